//! Finite sliding, small strain: the node-to-segment or segment-to-segment pairs are formed
//! again on the current configuration inside every load step, until they describe the step's
//! answer, so that contact follows bodies that slide along each other by many segments in a step
//! of any length.
//!
//! ```text
//! step i (u_{i−1}: the last converged step; u_0 = 0), iterate r = 0, 1, …  with u^(0) = u_{i−1}:
//!     x_a = X_a + u^(r)_a                             (node positions of the iterate)
//!     pair every master node m with its closest point y = Σ_j N_j(ξ*) x_j of the slave curve
//!     on x (crate::pairing, unchanged): n, t, N_j of that geometry
//!     g_k   = (x_m − y) · n                           (geometric gap at u^(r))
//!     g0_k  = g_k − n · (u^(r)_m − Σ_j N_j u^(r)_j)   (offset: the linear gap g0_k + (B_N u)_k
//!                                                       equals g_k at u^(r))
//!     s0_k  = t · (u_{i−1,m} − Σ_j N_j u_{i−1,j})     (start slip on these pairs at the step's
//!                                                       start, so that the step's slip increment
//!                                                       Δs_k = t · (Δu_m − Σ_j N_j Δu_j),
//!                                                       Δu = u − u_{i−1}, is measured on them)
//!     τ0_k  = τ_k of step i−1                          (the friction history of node m carries)
//!     free  : a projection past an end of an open slave curve, by more than 1e−9 of the curve's
//!             length along its end tangent — no normal and no tangential unknown (no force)
//!     solve step i on these pairs from (s0, τ0) with the chosen algorithm → u^(r+1)
//!     pair again on X + u^(r+1); stop when the pairing is stable: for every pair that carries
//!     a force or is not open by more than the tolerance on both pairings,
//!         the same slave nodes (segment) and the same side of the curve's ends, and
//!         | g0_k + (B_N u^(r+1))_k  −  g_k(u^(r+1)) | ≤ 1e−6 h      (REPAIRING_TOLERANCE;
//!                                      h the shortest edge of the interface's slave curve)
//!     (u^(r+1) is then the step's answer, on the pairs it was solved on); at most 25
//!     re-pairings (MAX_REPAIRINGS), after which the step ends with status max_iterations and
//!     a message (SolvedStep::unstable_pairing)
//!
//! segment to segment (crate::segment_to_segment, formed on x): the same with the pair's rows
//!     g0_k  = g̃_k − (B_N u^(r))_k,   s0_k = (B_T u_{i−1})_k   (g̃_k the weighted gap on x; the
//!                                                       rows Σ_a c_a · u_a integrated on x)
//! ```
//!
//! Δs_k is the motion of the master node relative to the material point of the slave curve it
//! projects on at the step's end, along the current tangent: a rigid translation of both bodies
//! gives Δs = 0 (objective in translation; rotations enter only through `t`, small in small
//! strain). Coulomb's law is applied to Δs by the algorithms as in every history step. The pairs
//! keep their index (one per master node), so the slip, force and pair-state histories carry from
//! step to step.
//!
//! Why re-pair inside the step: pairs formed once at a step's start and kept through it
//! extrapolate the start's segments and normals over the whole step's travel: a press fit pushed
//! 6 in one step gave twice the insertion force of 96 steps, and a slider driven seven cells per
//! step counted pairs past their segments in contact. With the pairs of the step's own answer a
//! step of any length ends in the state of many short ones, to the discretisation (the step's
//! path is not followed: what depends on it — the dissipation's trapezoid rule — stays of first
//! order in the step).
//!
//! Cost: every solve of a step builds the pair rows afresh and, up to
//! [`crate::SPARSE_FROM_PAIRS`] pairs, factors `K` bordered by them and condenses the interface
//! again (small sliding does both once per schedule); a step whose pairs hold at once costs one
//! pairing more than one solve (measured: one re-pairing per step for half-cell steps, two for a
//! press fit pushed 24 cells in one step).
//!
//! The active set, the augmented Lagrangian and Clarabel are accepted (each solve is an ordinary
//! step on the problem of its pairs): the Boussinesq algorithm grows one zone along a fixed
//! order of the pairs, and the penalty path is not verified with pairs that change between
//! solves.

use contact2d_mesh::Contour;

use crate::builder::{BuiltProblem, InterfaceInfo, Pairing};
use crate::error::ContactError;
use crate::history::Retention;
use crate::loading::LoadSchedule;
use crate::pairing::{ContactPair, pair_contours};
use crate::problem::ContactProblem;
use crate::segment_to_segment::pair_segments;
use crate::solution::{ContactSolution, ContactStatus, PairState, StepStart};
use crate::solve::{ContactAlgorithm, History, SolvedStep, SolverSettings, solve_step_from};

/// The most re-pairings inside one step: after the first solve of a step, the pairs are formed
/// again on its answer and the step solved again at most this many times; a pairing still
/// changing then ends the step with [`ContactStatus::MaxIterations`] and
/// [`SolvedStep::unstable_pairing`] saying so. (Measured: the bundled scenes need at most
/// a few.)
pub const MAX_REPAIRINGS: usize = 25;

/// The stopping rule's tolerance on the gap, relative to the mesh size `h` (the shortest edge
/// of the interface's slave curve): the pairing is stable when the linearised gap of the pairs
/// a step was solved on equals the geometric gap at its answer to `1e−6 h` for every pair, and
/// every pair reaches the same slave segment.
pub const REPAIRING_TOLERANCE: f64 = 1e-6;

/// The largest difference between the linearised and the geometric gaps, relative to the mesh
/// size, that ends a step whose pairing cycles (alternates between the same two pairings for
/// two periods, the pairs' slave segments compared): a node
/// over the kink between two slave segments (the deformed surface's normal jumps there by
/// θ = O(load/E)) paired with either segment overshoots their shared node a little, and its gap
/// on the other one is θ times the overshoot; the linearisations of the two segments differ by
/// that much, the discretisation's own error of the surface at the kink (measured: 4.9e-4 of
/// the mesh size at a kink of 1e−2 in the sliding patch test). Above it, the step ends with
/// [`ContactStatus::MaxIterations`] and a message.
pub const KINK_TOLERANCE: f64 = 1e-3;

/// Solves `schedule` on `built` with finite sliding (see the module docs) on the interfaces
/// where `finite[i]` is true: each step on pairs formed on its own answer (re-paired until they
/// hold, [`MAX_REPAIRINGS`] at most; [`SolvedStep::repairings`] counts them); the other
/// interfaces keep the pairs of `built` (small sliding). `on_step(i, step, current)` is told each
/// solved step with the problem it was solved on (its pairs are that step's). The history stops after the first step that does not converge; [`History::scaled`]
/// is false. Returns the history and the problem of the last step solved.
///
/// # Errors
/// [`ContactError::InvalidInput`] when `finite` does not hold one flag per interface;
/// [`ContactError::NotApplicable`] for an algorithm other than the active set, the augmented
/// Lagrangian and Clarabel; [`ContactError::FiniteSliding`] for an interface that is neither node to segment
/// nor segment to segment, or has a given gap; a schedule naming a pattern the problem does not have; every error of the
/// pairing, factorisation and step solve.
pub fn solve_finite_sliding(
    built: &BuiltProblem,
    finite: &[bool],
    settings: &SolverSettings,
    schedule: &LoadSchedule,
    retention: Retention,
    on_step: &mut dyn FnMut(usize, &SolvedStep, &BuiltProblem),
) -> Result<(History, BuiltProblem), ContactError> {
    check_applies(built, finite, settings.algorithm())?;
    let base = &built.problem;
    let names: Vec<&str> = base.patterns().iter().map(|p| p.name.as_str()).collect();
    let factors: Vec<Vec<f64>> =
        (0..schedule.steps().len()).map(|i| schedule.factors_for(i, &names)).collect::<Result<_, _>>()?;
    let zeros = vec![0.0; names.len()];
    let sizes = segment_sizes(built);
    let mut u = vec![0.0; 2 * base.model.mesh.num_nodes()];
    let mut previous_end = StepStart::initial(base.num_pairs());
    let mut guess: Option<Vec<PairState>> = None;
    let (mut alpha, mut dissipated, mut steps) = (vec![], 0.0, vec![]);
    let mut current = BuiltProblem { problem: base.clone(), interfaces: built.interfaces.clone() };
    for (i, target) in factors.iter().enumerate() {
        let previous = if i == 0 { &zeros } else { &factors[i - 1] };
        let mut formed = form_pairs(built, finite, &u)?;
        let mut step_guess = guess.clone();
        let mut repairings = 0;
        let (mut iterations, mut time) = (0, std::time::Duration::ZERO);
        // The pairings solved on in this step, and the last solve (for a cycle between two).
        let mut visited = vec![signature(built, finite, &formed)];
        let mut last: Option<(f64, Attempt)> = None;
        let mut not_held;
        let (problem, mut solution, floating_iterations, floating_residual, unstable) = loop {
            let problem = problem_on(built, &formed)?;
            let start =
                StepStart { slip: start_slip(built, finite, &problem, &u, &previous_end), ..previous_end.clone() };
            let outcome = solve_step_from(
                &problem,
                settings,
                target,
                previous,
                &start,
                step_guess.as_deref(),
                i + 1,
                &mut alpha,
            )?;
            // A step that ends `not_held` ends here (it is not solved): its report is this solve's.
            not_held = outcome.not_held;
            let (mut solution, floating_iterations, floating_residual) =
                (outcome.solution, outcome.iterations, outcome.residual);
            iterations += solution.iterations;
            time += solution.time;
            for k in formed.free.iter().enumerate().filter(|(_, f)| **f).map(|(k, _)| k) {
                solution.state[k] = PairState::Free;
            }
            if !solution.status.is_solved() {
                break (problem, solution, floating_iterations, floating_residual, None);
            }
            let next = form_pairs(built, finite, &solution.displacement)?;
            let change =
                pairing_change(built, finite, &sizes, &formed, &next, &solution.displacement, &solution.normal_force);
            let Some(mismatch) = change else {
                break (problem, solution, floating_iterations, floating_residual, None);
            };
            let gap = gap_mismatch(built, finite, &sizes, &formed, &next, &solution.displacement);
            let attempt = Attempt { problem, solution, floating_iterations, floating_residual };
            let signature = signature(built, finite, &next);
            let n = visited.len();
            if n >= 3 && signature == visited[n - 2] && visited[n - 1] == visited[n - 3] {
                // A cycle: the pairing has alternated between the same two for two periods. The
                // solve whose gaps differ least from the geometric ones is the step's answer if
                // within KINK_TOLERANCE of the mesh size.
                let (gap, mut best) = match last.take() {
                    Some((g, a)) if g < gap => (g, a),
                    _ => (gap, attempt),
                };
                let why = (gap > KINK_TOLERANCE).then(|| {
                    best.solution.status = ContactStatus::MaxIterations;
                    format!(
                        "finite sliding: the pairing cycles between segments; the best of the cycle's solves \
                         has linearised gaps {gap:.3e} of the mesh size from the geometric ones ({mismatch})"
                    )
                });
                break (best.problem, best.solution, best.floating_iterations, best.floating_residual, why);
            }
            visited.push(signature);
            let Attempt { problem, mut solution, floating_iterations, floating_residual } = attempt;
            if repairings == MAX_REPAIRINGS {
                solution.status = ContactStatus::MaxIterations;
                let why = format!(
                    "finite sliding: the pairs formed on the step's answer still differ from those it was solved on \
                     after {MAX_REPAIRINGS} re-pairings ({mismatch})"
                );
                break (problem, solution, floating_iterations, floating_residual, Some(why));
            }
            repairings += 1;
            step_guess = Some(solution.state.clone());
            formed = next;
            last = Some((gap, Attempt { problem, solution, floating_iterations, floating_residual }));
        };
        // The step's work is every solve of it.
        (solution.iterations, solution.time) = (iterations, time);
        dissipated += solution.dissipation;
        let converged = solution.status.is_solved();
        let step = SolvedStep {
            factors: target.clone(),
            solution,
            dissipated,
            floating_iterations,
            floating_residual,
            repairings,
            unstable_pairing: unstable,
            not_held,
        };
        current.problem = problem;
        on_step(i, &step, &current);
        u.clone_from(&step.solution.displacement);
        previous_end = StepStart::after(&step.solution);
        guess = Some(step.solution.state.clone());
        if retention == Retention::Last {
            steps.clear();
        }
        steps.push(step);
        if !converged {
            break;
        }
    }
    Ok((History { steps, scaled: false, condense_time: std::time::Duration::ZERO }, current))
}

/// Refuses, before solving, what finite sliding does not handle.
fn check_applies(built: &BuiltProblem, finite: &[bool], algorithm: ContactAlgorithm) -> Result<(), ContactError> {
    if finite.len() != built.interfaces.len() {
        return Err(ContactError::InvalidInput(format!(
            "{} sliding flags given for {} interfaces",
            finite.len(),
            built.interfaces.len()
        )));
    }
    if !matches!(
        algorithm,
        ContactAlgorithm::ActiveSet | ContactAlgorithm::AugmentedLagrangian | ContactAlgorithm::Clarabel
    ) {
        return Err(ContactError::NotApplicable {
            algorithm: algorithm.key(),
            reason: "finite sliding forms the pairs again inside every step; it is implemented and verified with \
                     the active set, the augmented Lagrangian and Clarabel only (use algorithm = \"active_set\")"
                .into(),
        });
    }
    for info in finite_interfaces(built, finite) {
        let refuse = |reason: &str| ContactError::FiniteSliding { contact: info.name.clone(), reason: reason.into() };
        if !matches!(info.pairing, Pairing::NodeToSegment | Pairing::SegmentToSegment) {
            return Err(refuse(
                "only node-to-segment and segment-to-segment pairing are formed again on the current \
                 configuration; set pairing = \"segment_to_segment\" or sliding = \"small\"",
            ));
        }
        let given = info.pairs.clone().any(|k| built.problem.gap[k] != built.problem.pairs[k].gap);
        if given {
            return Err(refuse(
                "a given gap replaces the geometric one, which finite sliding measures on the current \
                 configuration; leave the gap geometric or set sliding = \"small\"",
            ));
        }
    }
    Ok(())
}

/// The displacement of node `n` (zero for a node without DOFs: a rigid obstacle's).
fn node_displacement(u: &[f64], n: usize) -> [f64; 2] {
    [u.get(2 * n).copied().unwrap_or(0.0), u.get(2 * n + 1).copied().unwrap_or(0.0)]
}

/// `u_m − Σ_j N_j u_j` of a pair.
fn relative_displacement(pair: &ContactPair, u: &[f64]) -> [f64; 2] {
    let mut d = node_displacement(u, pair.master.0);
    for (node, w) in &pair.slave {
        let us = node_displacement(u, node.0);
        d = [d[0] - w * us[0], d[1] - w * us[1]];
    }
    d
}

/// `[(B_N u)_k, (B_T u)_k]` of a pair at `u`: `n · d`, `t · d` with `d = u_m − Σ_j N_j u_j`
/// (node to segment), or the integrated rows `Σ_a c_a · u_a` over the master and slave nodes
/// (segment to segment, [`crate::segment_to_segment`]; the slave coefficients carry their sign).
fn row_values(pair: &ContactPair, u: &[f64]) -> [f64; 2] {
    match &pair.integrated {
        None => {
            let d = relative_displacement(pair, u);
            [pair.normal[0] * d[0] + pair.normal[1] * d[1], pair.tangent[0] * d[0] + pair.tangent[1] * d[1]]
        }
        Some(rows) => rows.master.iter().chain(&rows.slave).fold([0.0; 2], |acc, c| {
            let ua = node_displacement(u, c.node.0);
            [acc[0] + c.normal[0] * ua[0] + c.normal[1] * ua[1], acc[1] + c.tangent[0] * ua[0] + c.tangent[1] * ua[1]]
        }),
    }
}

/// The start slips of a step: `s0_k = (B_T u)_k` (`t_k · (u_m − Σ_j N_j u_j)` node to
/// segment) on the new pairs of the finite
/// interfaces, the slip the previous step ended with on the others (their pairs are unchanged).
fn start_slip(
    built: &BuiltProblem,
    finite: &[bool],
    problem: &ContactProblem,
    u: &[f64],
    previous: &StepStart,
) -> Vec<f64> {
    let mut slip = previous.slip.clone();
    for info in finite_interfaces(built, finite) {
        for k in info.pairs.clone() {
            slip[k] = row_values(&problem.pairs[k], u)[1];
        }
    }
    slip
}

/// Pairs formed on a configuration `X + u`: every pair of the problem (those of the small-sliding
/// interfaces as built), the finite interfaces' with the offsets `g0_k` as their gaps, and
/// which pairs project past a slave curve's end (no unknowns).
#[derive(Debug, Clone)]
struct FormedPairs {
    pairs: Vec<ContactPair>,
    gaps: Vec<f64>,
    free: Vec<bool>,
}

/// The pairs formed on the configuration `X + u` (see [`FormedPairs`]).
fn form_pairs(built: &BuiltProblem, finite: &[bool], u: &[f64]) -> Result<FormedPairs, ContactError> {
    let mut moved = built.problem.model.clone();
    for (n, x) in moved.mesh.points.iter_mut().enumerate() {
        let d = node_displacement(u, n);
        *x = [x[0] + d[0], x[1] + d[1]];
    }
    let mut pairs = built.problem.pairs.clone();
    let mut gaps = built.problem.gap.clone();
    let mut free = vec![false; built.problem.num_pairs()];
    for info in finite_interfaces(built, finite) {
        let (master, slave) = current_contours(&moved, info)?;
        let formed = if info.pairing == Pairing::SegmentToSegment {
            pair_segments(&moved, &master, &slave, &info.slave_region)?
        } else {
            pair_contours(&moved, &master, &slave, &info.slave_region)?
        };
        if formed.len() != info.pairs.len() {
            return Err(ContactError::FiniteSliding {
                contact: info.name.clone(),
                reason: format!("{} pairs formed again for {}", formed.len(), info.pairs.len()),
            });
        }
        for (k, mut pair) in info.pairs.clone().zip(formed) {
            debug_assert_eq!(pair.master, built.problem.pairs[k].master, "pairs keep their master node");
            free[k] = past_end(&slave, &pair, moved.mesh.points[pair.master.0]);
            pair.gap -= row_values(&pair, u)[0];
            gaps[k] = pair.gap;
            pairs[k] = pair;
        }
    }
    Ok(FormedPairs { pairs, gaps, free })
}

/// The problem on `formed`: its pairs, their offsets `g0_k` as the gaps (the small-sliding
/// interfaces keep the gaps of `built`), and no unknowns on the pairs past an end.
fn problem_on(built: &BuiltProblem, formed: &FormedPairs) -> Result<ContactProblem, ContactError> {
    let mut problem = built.problem.with_pairs(formed.pairs.clone())?;
    problem.set_gaps(formed.gaps.clone())?;
    for (k, _) in formed.free.iter().enumerate().filter(|(_, f)| **f) {
        problem.normal[k] = false;
        problem.tangential[k] = false;
    }
    Ok(problem)
}

/// Each pair's mesh size `h_k`: the shortest edge of its interface's slave curve (1 for the
/// pairs of no interface, which never change).
fn segment_sizes(built: &BuiltProblem) -> Vec<f64> {
    let mut sizes = vec![1.0; built.problem.num_pairs()];
    for info in &built.interfaces {
        let contour = &info.slave_contour;
        let h = contour.edges.iter().map(|e| contour.edge_length(e, 1.0)).fold(f64::INFINITY, f64::min);
        for k in info.pairs.clone() {
            sizes[k] = if h.is_finite() && h > 0.0 { h } else { 1.0 };
        }
    }
    sizes
}

/// The slave nodes a pair's rows reach: the projection's segment (node to segment), or every
/// slave segment the master node's segments overlap (segment to segment).
fn slave_nodes(pair: &ContactPair) -> Vec<usize> {
    let mut nodes: Vec<usize> = match &pair.integrated {
        None => pair.slave.iter().map(|(n, _)| n.0).collect(),
        Some(rows) => rows.slave.iter().map(|c| c.node.0).collect(),
    };
    nodes.sort_unstable();
    nodes
}

/// One solve of a step on one pairing.
struct Attempt {
    problem: ContactProblem,
    solution: ContactSolution,
    floating_iterations: usize,
    floating_residual: f64,
}

/// The interfaces slid finitely (`finite[i]` true).
fn finite_interfaces<'a>(built: &'a BuiltProblem, finite: &'a [bool]) -> impl Iterator<Item = &'a InterfaceInfo> {
    built.interfaces.iter().zip(finite).filter(|(_, f)| **f).map(|(info, _)| info)
}

/// The pairs of the interfaces slid finitely, interface by interface.
fn finite_pairs<'a>(built: &'a BuiltProblem, finite: &'a [bool]) -> impl Iterator<Item = usize> + 'a {
    finite_interfaces(built, finite).flat_map(|info| info.pairs.clone())
}

/// Which slave nodes, or which end, every pair of the finite interfaces reaches.
fn signature(built: &BuiltProblem, finite: &[bool], formed: &FormedPairs) -> Vec<(bool, Vec<usize>)> {
    finite_pairs(built, finite).map(|k| (formed.free[k], slave_nodes(&formed.pairs[k]))).collect()
}

/// The largest difference, relative to the mesh size `h_k`, between the linearised gap of the
/// pairs `used` and the geometric gap of the pairs `next` formed at `u`, over the finite
/// interfaces' pairs that have unknowns in both.
fn gap_mismatch(
    built: &BuiltProblem,
    finite: &[bool],
    sizes: &[f64],
    used: &FormedPairs,
    next: &FormedPairs,
    u: &[f64],
) -> f64 {
    finite_pairs(built, finite)
        .filter(|&k| !used.free[k] && !next.free[k])
        .map(|k| {
            let (a, b) = (&used.pairs[k], &next.pairs[k]);
            ((a.gap + row_values(a, u)[0]) - (b.gap + row_values(b, u)[0])).abs() / sizes[k]
        })
        .fold(0.0, f64::max)
}

/// The paired point of `pair` on the slave curve at the configuration `X + u`:
/// `Σ_j N_j(ξ*) (X_j + u_j)` with the projection's weights (node to segment), or those of the
/// master node's own closest point (segment to segment).
fn paired_point(pair: &ContactPair, points: &[[f64; 2]], u: &[f64]) -> [f64; 2] {
    let weights = pair.integrated.as_ref().map_or(&pair.slave, |rows| &rows.point_slave);
    weights.iter().fold([0.0; 2], |y, (node, w)| {
        let d = node_displacement(u, node.0);
        let x = points[node.0];
        [y[0] + w * (x[0] + d[0]), y[1] + w * (x[1] + d[1])]
    })
}

/// Whether the pairing a step was solved on (`used`) still describes its answer (`u`, normal
/// forces `lambda`): `None` when, on every finite interface, each pair that carries a force or
/// whose gap is not open by more than the tolerance (a pair open on both pairings carries no
/// force either way, whatever its segment) reaches the same slave nodes in the pairs formed on
/// `X + u` (`next`) — or has the same paired point there to the tolerance (a node over the kink
/// between two segments, paired to their shared node from either side) —, is past an end in
/// both or neither, and has its linearised gap equal to the geometric gap at `u` to
/// [`REPAIRING_TOLERANCE`] of the mesh size `h_k`,
///
/// ```text
/// | g0_k + (B_N u)_k  (used)  −  g0_k + (B_N u)_k  (next) | ≤ REPAIRING_TOLERANCE · h_k
///   (the second is the geometric gap at u: next is formed on X + u)
/// ```
///
/// else what differs (for the status message).
fn pairing_change(
    built: &BuiltProblem,
    finite: &[bool],
    sizes: &[f64],
    used: &FormedPairs,
    next: &FormedPairs,
    u: &[f64],
    lambda: &[f64],
) -> Option<String> {
    let points = &built.problem.model.mesh.points;
    let mut worst: Option<(f64, usize, f64)> = None;
    for info in finite_interfaces(built, finite) {
        for k in info.pairs.clone() {
            let (a, b) = (&used.pairs[k], &next.pairs[k]);
            let tolerance = REPAIRING_TOLERANCE * sizes[k];
            let linear = a.gap + row_values(a, u)[0];
            let geometric = b.gap + row_values(b, u)[0];
            let open = |gap: f64, free: bool| free || gap > tolerance;
            if lambda[k] == 0.0 && open(linear, used.free[k]) && open(geometric, next.free[k]) {
                continue;
            }
            // A pair that changed segment still describes the answer when its paired point is the
            // new one (to the tolerance): a node over the kink between two slave segments,
            // whose closest point is their shared node from either side (the pairing would
            // otherwise flip between them from solve to solve).
            let moved = slave_nodes(a) != slave_nodes(b) && {
                let (y, z) = (paired_point(a, points, u), paired_point(b, points, u));
                (y[0] - z[0]).hypot(y[1] - z[1]) > tolerance
            };
            if used.free[k] != next.free[k] || moved {
                return Some(format!(
                    "contact \"{}\": pair {} (master node {}) moved to another slave segment",
                    info.name,
                    k - info.pairs.start,
                    a.master.0
                ));
            }
            let ratio = (linear - geometric).abs() / sizes[k];
            if ratio > REPAIRING_TOLERANCE && worst.is_none_or(|w| ratio > w.0) {
                worst = Some((ratio, k - info.pairs.start, linear - geometric));
            }
        }
    }
    worst.map(|(ratio, k, d)| format!("pair {k}: linearised minus geometric gap {d:.3e}, {ratio:.3e} of the mesh size"))
}

/// The interface's master and slave curves on the moved model.
fn current_contours(moved: &contact2d_fem::Model, info: &InterfaceInfo) -> Result<(Contour, Contour), ContactError> {
    Ok((Contour::from_group(&moved.mesh, &info.master)?, Contour::from_group(&moved.mesh, &info.slave)?))
}

/// Whether the master node at `x` projects past an end of the open curve `slave`: its paired
/// point is the end and `x` lies beyond it along the end tangent by more than 1e−9 of the
/// curve's length (round-off of a node exactly at the end is not past it).
fn past_end(slave: &Contour, pair: &ContactPair, x: [f64; 2]) -> bool {
    let (Some(&total), Some(first), Some(last)) =
        (slave.arc_length.last(), slave.tangents.first(), slave.tangents.last())
    else {
        return false;
    };
    if slave.closed {
        return false;
    }
    let tol = 1e-9 * total;
    let d = [x[0] - pair.slave_point[0], x[1] - pair.slave_point[1]];
    let beyond_start = pair.slave_arc_length <= tol && -(d[0] * first[0] + d[1] * first[1]) > tol;
    let beyond_end = pair.slave_arc_length >= total - tol && d[0] * last[0] + d[1] * last[1] > tol;
    beyond_start || beyond_end
}

//! Finite sliding, small strain: the node-to-segment or segment-to-segment pairs are formed
//! again on the current configuration before every load step, so that contact follows bodies
//! that slide along each other by many segments.
//!
//! ```text
//! before step i, with u = u_{i−1} (the last converged step; u_0 = 0):
//!     x_a = X_a + u_a                                (current node positions)
//!     pair every master node m with its closest point y = Σ_j N_j(ξ*) x_j of the slave curve
//!     on x (crate::pairing, unchanged): n, t, N_j of the current geometry
//!     g_k   = (x_m − y) · n                           (current gap, geometric)
//!     g0_k  = g_k − n · (u_m − Σ_j N_j u_j)           (offset: the step's linear gap
//!                                                       g0_k + (B_N u)_k equals g_k at u_{i−1})
//!     s0_k  = t · (u_m − Σ_j N_j u_j)                 (start slip on the new pair, so that the
//!                                                       step's slip increment is
//!                                                       Δs_k = t · (Δu_m − Σ_j N_j Δu_j))
//!     τ0_k  = τ_k of step i−1                          (the friction history of node m carries)
//!     free  : a projection past an end of an open slave curve, by more than 1e−9 of the curve's
//!             length along its end tangent — no normal and no tangential unknown (no force)
//! solve step i on these pairs from (s0, τ0) with the chosen algorithm
//!
//! segment to segment (crate::segment_to_segment, formed on x): the same with the pair's rows
//!     g0_k  = g̃_k − (B_N u)_k,   s0_k = (B_T u)_k       (g̃_k the weighted gap on x; the rows
//!                                                       Σ_a c_a · u_a integrated on x)
//! ```
//!
//! Δs_k is the motion of the master node relative to the material point of the slave curve it
//! projects on, along the current tangent: a rigid translation of both bodies gives Δs = 0
//! (objective in translation; rotations enter only through `t`, small in small strain). Coulomb's
//! law is applied to Δs by the algorithms as in every history step. The pairs keep their index
//! (one per master node), so the slip, force and pair-state histories carry from step to step.
//!
//! Cost: every step builds the pair rows afresh and, up to [`crate::SPARSE_FROM_PAIRS`] pairs,
//! factors `K` bordered by them and condenses the interface again (small sliding does both once
//! per schedule). Within a step the pairs are fixed: a node that crosses a segment end during
//! the step is re-paired at the next one (steps shorter than a segment keep the error of the
//! linearised gap to the segment's curvature).
//!
//! Only the active set and the augmented Lagrangian are accepted: the Boussinesq algorithm grows
//! one zone along a fixed order of the pairs, and the Clarabel and penalty paths are not
//! verified with pairs that change between steps.

use contact2d_mesh::Contour;

use crate::builder::{BuiltProblem, InterfaceInfo, Pairing};
use crate::error::ContactError;
use crate::history::Retention;
use crate::loading::LoadSchedule;
use crate::pairing::{ContactPair, pair_contours};
use crate::problem::ContactProblem;
use crate::segment_to_segment::pair_segments;
use crate::solution::{PairState, StepStart};
use crate::solve::{ContactAlgorithm, History, SolvedStep, SolverSettings, solve_step_from};

/// Solves `schedule` on `built` with finite sliding (see the module docs) on the interfaces
/// where `finite[i]` is true: each step on pairs formed on the configuration the previous step
/// ended in; the other interfaces keep the pairs of `built` (small sliding). `on_step(i, step,
/// current)` is told each solved step with the problem it was solved on (its pairs are that
/// step's). The history stops after the first step that does not converge; [`History::scaled`]
/// is false. Returns the history and the problem of the last step solved.
///
/// # Errors
/// [`ContactError::InvalidInput`] when `finite` does not hold one flag per interface;
/// [`ContactError::NotApplicable`] for an algorithm other than the active set and the augmented
/// Lagrangian; [`ContactError::FiniteSliding`] for an interface that is neither node to segment
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
    let mut u = vec![0.0; 2 * base.model.mesh.num_nodes()];
    let mut previous_end = StepStart::initial(base.num_pairs());
    let mut guess: Option<Vec<PairState>> = None;
    let (mut alpha, mut dissipated, mut steps) = (vec![], 0.0, vec![]);
    let mut current = BuiltProblem { problem: base.clone(), interfaces: built.interfaces.clone() };
    for (i, target) in factors.iter().enumerate() {
        let (problem, free) = pair_current(built, finite, &u)?;
        let start = StepStart { slip: start_slip(built, finite, &problem, &u, &previous_end), ..previous_end };
        let previous = if i == 0 { &zeros } else { &factors[i - 1] };
        let outcome =
            solve_step_from(&problem, settings, target, previous, &start, guess.as_deref(), i + 1, &mut alpha)?;
        let mut solution = outcome.solution;
        for k in free.iter().enumerate().filter(|(_, f)| **f).map(|(k, _)| k) {
            solution.state[k] = PairState::Free;
        }
        dissipated += solution.dissipation;
        let converged = solution.status.is_solved();
        let step = SolvedStep {
            factors: target.clone(),
            solution,
            dissipated,
            floating_iterations: outcome.iterations,
            floating_residual: outcome.residual,
            not_held: outcome.not_held,
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
    if !matches!(algorithm, ContactAlgorithm::ActiveSet | ContactAlgorithm::AugmentedLagrangian) {
        return Err(ContactError::NotApplicable {
            algorithm: algorithm.key(),
            reason: "finite sliding forms the pairs again before every step; it is implemented and verified with \
                     the active set and the augmented Lagrangian only (use algorithm = \"active_set\")"
                .into(),
        });
    }
    for info in built.interfaces.iter().zip(finite).filter(|(_, f)| **f).map(|(info, _)| info) {
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
    for info in built.interfaces.iter().zip(finite).filter(|(_, f)| **f).map(|(info, _)| info) {
        for k in info.pairs.clone() {
            slip[k] = row_values(&problem.pairs[k], u)[1];
        }
    }
    slip
}

/// The problem on pairs formed on the configuration `X + u`, with the offsets `g0_k` as gaps
/// and the pairs past a slave curve's end without unknowns; and which pairs those are.
fn pair_current(built: &BuiltProblem, finite: &[bool], u: &[f64]) -> Result<(ContactProblem, Vec<bool>), ContactError> {
    let mut moved = built.problem.model.clone();
    for (n, x) in moved.mesh.points.iter_mut().enumerate() {
        let d = node_displacement(u, n);
        *x = [x[0] + d[0], x[1] + d[1]];
    }
    let mut pairs = built.problem.pairs.clone();
    let mut gaps = built.problem.gap.clone();
    let mut free = vec![false; built.problem.num_pairs()];
    for info in built.interfaces.iter().zip(finite).filter(|(_, f)| **f).map(|(info, _)| info) {
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
    let mut problem = built.problem.with_pairs(pairs)?;
    problem.set_gaps(gaps)?;
    for (k, _) in free.iter().enumerate().filter(|(_, f)| **f) {
        problem.normal[k] = false;
        problem.tangential[k] = false;
    }
    Ok((problem, free))
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

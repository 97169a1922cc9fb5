//! The paired-node Boussinesq algorithm of Solodovnikov (1998), section 6, on the condensed
//! interface.
//!
//! ```text
//! pairs ordered by η from the bearing point; zones: stick [0, b), slip [b, l], free beyond l
//! problem A (6.1) for given zones:
//!   stick:  gap = 0,  Δs = 0  (v − vh = v_s_τ)          slip: gap = 0,  τ = σ μ λ  (f = 0)
//!   free:   λ = τ = 0
//! A = w A1 + A2: A1 carries the load (w = 1, no gap, no history), A2 the gaps and the history
//! (w = 0); both share one matrix (nonsymmetric through the slip rows), factored once per zone
//! configuration (dense LU of the condensed equations: the bodies' Cholesky factors did the
//! sparse work) and solved with two right-hand sides.
//! Boussinesq condition: λ = 0 at the last contact pair l*  ⇒  w = −λ2(l*)/λ1(l*)   (with gap);
//! without gap w is given and l* is the last pair that keeps λ ≥ 0.
//! b iteration: start with everything stuck; the first stuck pair outside the cone starts the
//! slip zone, with σ from the sign of its excess; repeat until b repeats.
//! Finally every inequality of (5.1) is checked: λ > 0 inside the contact zone, |τ| ≤ μλ on
//! stick, −τΔs ≥ 0 on slip, gap ≥ 0 on the free zone; violations are reported, never hidden.
//! ```
//!
//! Zone ends fall on pairs (nodes): the mesh resolves l and b to its node spacing unless the
//! nodes are placed at l* and b* (mesh morphing); see docs/algorithms.md.
//!
//! # References
//! V. N. Solodovnikov (1998), Solution of a contact problem for a plate with a deformable insert,
//! section 6 (problems A, A1, A2 and the Boussinesq principle).

use web_time::Instant;

use crate::algorithms::state_equations::{combine, solve_state_equations};
use crate::error::ContactError;
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_forces};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart, Violation};

/// How a Boussinesq step is loaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoussinesqLoading {
    /// The contact zone ends at the pair `order[index]` (the paper's steps in l); w follows from
    /// the Boussinesq condition. Needs a gap or a history (else w is undetermined).
    ContactEnd(usize),
    /// The load w is given and l* is searched (the no-gap case).
    Load(f64),
    /// Both given: the contact zone ends at `order[contact_end]` and the load is `load`; the
    /// force left at l* measures how far the Boussinesq condition is from holding (used to
    /// place a node at l* by root finding).
    Fixed {
        /// Position of l* in `order`.
        contact_end: usize,
        /// The load w.
        load: f64,
    },
}

/// The zones found by the algorithm, as positions in `order`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Zones {
    /// Number of stuck pairs: `order[..stick]`.
    pub stick: usize,
    /// Position of the last contact pair l*.
    pub contact_end: usize,
    /// The slip state of the slip zone (if any).
    pub slip: Option<PairState>,
}

/// The outcome of a Boussinesq step.
#[derive(Debug, Clone, PartialEq)]
pub struct BoussinesqStep {
    /// The solution (status [`ContactStatus::Inadmissible`] if any inequality fails).
    pub solution: ContactSolution,
    /// The zones.
    pub zones: Zones,
    /// Violated inequalities (empty when admissible).
    pub violations: Vec<Violation>,
}

/// One Boussinesq step from `start` with the pairs in `order` (by η from the bearing point).
pub fn solve_boussinesq_step(
    problem: &ContactProblem,
    interface: &Interface,
    order: &[usize],
    loading: BoussinesqLoading,
    start: &StepStart,
    max_iterations: usize,
) -> BoussinesqStep {
    // The sparse path's interface holds no compliances: condense here (this algorithm works on them).
    let condensed = interface.condensed(problem);
    let interface = &*condensed;
    let clock = Instant::now();
    let m = problem.num_pairs();
    let frictional = interface.c_tt.nrows() == m && problem.is_frictional();
    let mut zones = match loading {
        BoussinesqLoading::ContactEnd(i) | BoussinesqLoading::Fixed { contact_end: i, .. } => {
            Zones { stick: i + 1, contact_end: i, slip: None }
        }
        BoussinesqLoading::Load(_) => Zones { stick: m, contact_end: m.saturating_sub(1), slip: None },
    };
    let mut iterations = 0;
    let mut answer = None;
    let mut trace = Vec::new();
    for it in 1..=max_iterations.max(1) {
        iterations = it;
        let Some((w, lambda, tau)) = solve_zones(problem, interface, order, zones, loading, start, frictional) else {
            break;
        };
        // Without gap: shorten the contact zone while its last pair pulls (λ < 0).
        if let BoussinesqLoading::Load(_) = loading {
            let last = order[zones.contact_end];
            if lambda[last] < 0.0 && zones.contact_end > 0 {
                trace.push(IterationRecord {
                    iteration: it,
                    changed: 1,
                    in_contact: zones.contact_end + 1,
                    slipping: (zones.contact_end + 1).saturating_sub(zones.stick),
                    residual: 0.0,
                });
                zones.contact_end -= 1;
                zones.stick = zones.stick.min(zones.contact_end + 1);
                continue;
            }
        }
        let next = next_stick_end(problem, order, zones, &lambda, &tau, frictional);
        trace.push(IterationRecord {
            iteration: it,
            changed: next.map_or(0, |z| z.stick.abs_diff(zones.stick)),
            in_contact: zones.contact_end + 1,
            slipping: (zones.contact_end + 1).saturating_sub(zones.stick),
            residual: 0.0,
        });
        answer = Some((w, lambda, tau));
        match next {
            Some(z) if z != zones => zones = z,
            _ => break,
        }
    }
    let elapsed = clock.elapsed();
    let Some((w, lambda, tau)) = answer else {
        let forces = ZoneForces { load: 0.0, normal_force: vec![0.0; m], tangential_force: vec![0.0; m] };
        let raw = raw_solution(forces, ContactStatus::Numerical, iterations, elapsed);
        return BoussinesqStep {
            solution: finish_from_forces(problem, interface, raw, start),
            zones,
            violations: vec![],
        };
    };
    let forces = ZoneForces { load: w, normal_force: lambda, tangential_force: tau };
    let by_condition = matches!(loading, BoussinesqLoading::ContactEnd(_));
    let mut step =
        finish_zones(problem, interface, order, zones, forces, by_condition, start, (iterations, elapsed), 0.0);
    step.solution.trace = trace;
    step
}

/// Load and pair forces of problem A for given zones.
#[derive(Debug, Clone, PartialEq)]
pub struct ZoneForces {
    /// The load w (given, or from the Boussinesq condition).
    pub load: f64,
    /// λ per pair.
    pub normal_force: Vec<f64>,
    /// τ per pair.
    pub tangential_force: Vec<f64>,
}

/// Problem A (6.1) for zones given in full — stick `order[..zones.stick]`, slip with
/// `zones.slip` up to `order[zones.contact_end]`, free beyond — without the b iteration: the
/// building block of zone ends placed by root finding (the paper's nodes at b* and l*).
///
/// `load`: `Some(w)` solves at that load (the force left at l* then measures the Boussinesq
/// condition); `None` takes w from the Boussinesq condition λ(l*) = 0 (needs a gap or a history).
/// Returns `None` when the zone equations are singular or give no finite answer.
pub fn solve_given_zones(
    problem: &ContactProblem,
    interface: &Interface,
    order: &[usize],
    zones: Zones,
    load: Option<f64>,
    start: &StepStart,
) -> Option<ZoneForces> {
    // The sparse path's interface holds no compliances: condense here (this algorithm works on them).
    let condensed = interface.condensed(problem);
    let interface = &*condensed;
    let frictional = interface.c_tt.nrows() == problem.num_pairs() && problem.is_frictional();
    let loading = match load {
        Some(w) => BoussinesqLoading::Fixed { contact_end: zones.contact_end, load: w },
        None => BoussinesqLoading::ContactEnd(zones.contact_end),
    };
    let (w, lambda, tau) = solve_zones(problem, interface, order, zones, loading, start, frictional)?;
    Some(ZoneForces { load: w, normal_force: lambda, tangential_force: tau })
}

/// Evaluates zone forces into a [`BoussinesqStep`]: the displacement field is recovered once,
/// and every inequality of (5.1) is checked.
///
/// `by_condition`: the load came from the Boussinesq condition, so the force at l* is exactly
/// zero (set so, removing round-off). `(iterations, time)` are reported with the solution.
/// `end_slack`: the cone condition at the last stick pair and the sign condition at the last
/// contact pair are allowed this much (relative to the largest λ): the residual of a root
/// finder that placed a node at b* or l*, where these conditions hold with equality.
#[allow(clippy::too_many_arguments)]
pub fn finish_zones(
    problem: &ContactProblem,
    interface: &Interface,
    order: &[usize],
    zones: Zones,
    forces: ZoneForces,
    by_condition: bool,
    start: &StepStart,
    (iterations, time): (usize, std::time::Duration),
    end_slack: f64,
) -> BoussinesqStep {
    let mut forces = forces;
    if by_condition && let Some(&last) = order.get(zones.contact_end) {
        // The Boussinesq condition: the last contact pair carries exactly no force.
        (forces.normal_force[last], forces.tangential_force[last]) = (0.0, 0.0);
    }
    let raw = raw_solution(forces, ContactStatus::Converged, iterations, time);
    let mut solution = finish_from_forces(problem, interface, raw, start);
    let violations = check_inequalities(problem, order, zones, &solution, end_slack);
    if !violations.is_empty() {
        solution.status = ContactStatus::Inadmissible;
    }
    solution.violations.clone_from(&violations);
    BoussinesqStep { solution, zones, violations }
}

fn raw_solution(
    forces: ZoneForces,
    status: ContactStatus,
    iterations: usize,
    time: std::time::Duration,
) -> RawSolution {
    RawSolution {
        load_factor: forces.load,
        normal_force: forces.normal_force,
        tangential_force: forces.tangential_force,
        status,
        iterations,
        time,
    }
}

/// Solves problem A for given zones: `(w, λ, τ)`.
fn solve_zones(
    problem: &ContactProblem,
    interface: &Interface,
    order: &[usize],
    zones: Zones,
    loading: BoussinesqLoading,
    start: &StepStart,
    frictional: bool,
) -> Option<(f64, Vec<f64>, Vec<f64>)> {
    let m = problem.num_pairs();
    let mut role = vec![PairState::Free; m];
    for (pos, &k) in order.iter().enumerate().take(zones.contact_end + 1) {
        role[k] = if pos < zones.stick { PairState::Stick } else { zones.slip.unwrap_or(PairState::Stick) };
    }
    let x = solve_state_equations(problem, interface, start, &role, frictional)?;
    let w = match loading {
        BoussinesqLoading::Load(w) | BoussinesqLoading::Fixed { load: w, .. } => w,
        BoussinesqLoading::ContactEnd(_) => {
            let last = order[zones.contact_end];
            let (l1, l2) = (x[(last, 0)], x[(last, 1)]);
            if l1.abs() <= f64::EPSILON * l2.abs().max(1e-300) {
                return None;
            }
            -l2 / l1
        }
    };
    let (lambda, tau) = combine(&x, w);
    Some((w, lambda, tau))
}

/// The b iteration: the first stuck pair outside the cone starts the slip zone.
fn next_stick_end(
    problem: &ContactProblem,
    order: &[usize],
    zones: Zones,
    lambda: &[f64],
    tau: &[f64],
    frictional: bool,
) -> Option<Zones> {
    if !frictional {
        return None;
    }
    for (pos, &k) in order.iter().enumerate().take(zones.stick.min(zones.contact_end + 1)) {
        let mu = problem.friction[k];
        if problem.tangential[k] && tau[k].abs() > mu * lambda[k].max(0.0) * (1.0 + 1e-12) {
            // τ > μλ: the force needed to stick exceeds the cone; slip with τ = +μλ (Δs < 0).
            let slip = if tau[k] > 0.0 { PairState::SlipNegative } else { PairState::SlipPositive };
            return Some(Zones { stick: pos, contact_end: zones.contact_end, slip: Some(slip) });
        }
    }
    None
}

/// The inequalities of (5.1) on the zones found.
fn check_inequalities(
    problem: &ContactProblem,
    order: &[usize],
    zones: Zones,
    s: &ContactSolution,
    end_slack: f64,
) -> Vec<Violation> {
    let lambda_scale = s.normal_force.iter().fold(0.0f64, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
    let gap_scale = s.displacement.iter().fold(0.0f64, |a, u| a.max(u.abs())).max(f64::MIN_POSITIVE);
    let tol = 1e-9;
    let mut v = vec![];
    for (pos, &k) in order.iter().enumerate() {
        let (l, t) = (s.normal_force[k], s.tangential_force[k]);
        let cone_tol = if pos + 1 == zones.stick { tol + end_slack } else { tol };
        if pos == zones.contact_end && l < -(tol + end_slack) * lambda_scale {
            v.push(Violation { pair: k, condition: "p <= 0 at the contact end" });
        }
        if pos < zones.contact_end {
            if l <= -tol * lambda_scale {
                v.push(Violation { pair: k, condition: "p < 0 in the contact zone" });
            }
            if pos < zones.stick && t.abs() > problem.friction[k] * l + cone_tol * lambda_scale && problem.tangential[k]
            {
                v.push(Violation { pair: k, condition: "|q| <= mu|p| on the stick zone" });
            }
            if pos >= zones.stick && -t * s.slip_increment[k] < -tol * lambda_scale * gap_scale {
                v.push(Violation { pair: k, condition: "Q >= 0 on the slip zone" });
            }
        } else if pos > zones.contact_end && s.gap[k] < -tol * gap_scale {
            v.push(Violation { pair: k, condition: "no penetration on the free zone" });
        }
    }
    v
}

/// A loading history solved by Boussinesq steps, each from the state the previous one ended in
/// (the first from the virgin state: v_s = 0). Stops after the first step that is not converged
/// (inadmissible or numerical), which is returned last.
///
/// # Errors
/// The algorithm assumes a growing contact zone (spec §6): a decreasing load or contact end
/// (unloading) is refused with [`ContactError::InvalidInput`]; unload with the active set or
/// Clarabel (`solve_history`).
pub fn solve_boussinesq_history(
    problem: &ContactProblem,
    interface: &Interface,
    order: &[usize],
    loadings: &[BoussinesqLoading],
    max_iterations: usize,
) -> Result<Vec<crate::history::HistoryStep>, ContactError> {
    for pair in loadings.windows(2) {
        let decreasing = match (pair[0], pair[1]) {
            (BoussinesqLoading::Load(a), BoussinesqLoading::Load(b)) => b < a,
            (BoussinesqLoading::ContactEnd(a), BoussinesqLoading::ContactEnd(b)) => b < a,
            _ => false,
        };
        if decreasing {
            return Err(ContactError::InvalidInput(format!(
                "the Boussinesq algorithm assumes a growing contact zone and cannot unload ({:?} after {:?}); \
                 use the active set or Clarabel",
                pair[1], pair[0]
            )));
        }
    }
    // The zones are assumed from the pair order, not guessed from the previous states.
    crate::history::march(
        loadings,
        problem.num_pairs(),
        |&loading, start, _| {
            Ok(solve_boussinesq_step(problem, interface, order, loading, start, max_iterations).solution)
        },
        &mut |_| {},
    )
}

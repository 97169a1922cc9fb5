//! Turning an algorithm's answer into a full [`ContactSolution`]: displacements, gaps, slips,
//! states, dissipation and KKT residuals — the same evaluation for every algorithm.
//!
//! ```text
//! gap = g0 + B_N u,  s = B_T u,  Δs = s − s_start,  dissipation = Σ_slipping −½(τ_start + τ) Δs
//! contact  ⇔ λ/F > max(gap, 0)/U      slip ⇔ |Δs|/U > (μλ − |τ|)/F      (in contact)
//! ```
//! `F` and `U` are the problem's force and displacement scales (largest contact, load or
//! stiffness-times-displacement force; largest gap or displacement): each complementary pair is decided by its larger normalised member,
//! which is exact for active-set answers and robust for interior-point ones.
//!
//! A `Converged` answer that fails [`crate::certify::certify`] (KKT residuals, finiteness) is
//! reported as [`ContactStatus::Numerical`]: every algorithm ends here, so none can claim more
//! than its answer shows.

use std::time::Duration;

use contact2d_fem::Solution;

use crate::certify::{certify, force_scale};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, ContactStatus, KktResiduals, PairState, StepStart};

/// What an algorithm found, before evaluation.
#[derive(Debug, Clone, PartialEq)]
pub struct RawSolution {
    /// Load factor w.
    pub load_factor: f64,
    /// λ per pair.
    pub normal_force: Vec<f64>,
    /// τ per pair.
    pub tangential_force: Vec<f64>,
    /// Outcome.
    pub status: ContactStatus,
    /// Iterations.
    pub iterations: usize,
    /// Wall time.
    pub time: Duration,
}

/// Recovers the displacements once from `λ, τ` through the condensed interface and evaluates.
pub fn finish_from_forces(
    problem: &ContactProblem,
    interface: &Interface,
    raw: RawSolution,
    start: &StepStart,
) -> ContactSolution {
    let u_free = interface.free_displacement(raw.load_factor, &raw.normal_force, &raw.tangential_force);
    finish_from_displacement(problem, &u_free, raw, start)
}

/// Evaluates an answer given as free displacements (algorithms that solve for `u`).
pub fn finish_from_displacement(
    problem: &ContactProblem,
    u_free: &[f64],
    raw: RawSolution,
    start: &StepStart,
) -> ContactSolution {
    let w = raw.load_factor;
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let displacement = problem.system.dofs.expand(u_free, &prescribed);
    let gap: Vec<f64> =
        problem.normal_rows.iter().zip(&problem.gap).map(|(row, g0)| g0 + row.dot(u_free, &prescribed)).collect();
    let slip: Vec<f64> = problem.tangent_rows.iter().map(|row| row.dot(u_free, &prescribed)).collect();
    let slip_increment: Vec<f64> = slip.iter().zip(&start.slip).map(|(s, s0)| s - s0).collect();
    let (lambda, tau) = (&raw.normal_force, &raw.tangential_force);
    let length_scale = gap.iter().chain(&displacement).fold(0.0f64, |a, g| a.max(g.abs())).max(f64::MIN_POSITIVE);
    let force_scale = force_scale(problem, w, lambda, tau, length_scale);
    // Friction is judged against the contact forces themselves (the force scale F includes the
    // stiffer body's k̄U, which dwarfs the contact forces of a soft insert).
    let contact_scale = lambda.iter().fold(0.0f64, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
    let mut state = Vec::with_capacity(gap.len());
    let mut kkt = KktResiduals { min_dissipation: f64::INFINITY, ..KktResiduals::default() };
    let mut dissipation = 0.0;
    for k in 0..gap.len() {
        let mu = problem.friction[k];
        let in_contact = lambda[k] > 0.0 && lambda[k] / force_scale > gap[k].max(0.0) / length_scale;
        let slack = mu * lambda[k] - tau[k].abs();
        // A slip at round-off level (1e-12 of the length scale) is none.
        let normalised_slip = slip_increment[k].abs() / length_scale;
        let slipping =
            problem.tangential[k] && mu > 0.0 && normalised_slip > 1e-12 && normalised_slip > slack / force_scale;
        state.push(match (in_contact, slipping) {
            (false, _) => PairState::Free,
            (true, false) => PairState::Stick,
            (true, true) if slip_increment[k] > 0.0 => PairState::SlipPositive,
            (true, true) => PairState::SlipNegative,
        });
        // Friction works only where the pair slips at the end of the step (a pair that opened
        // moves tangentially without force; a stuck pair does not move).
        if slipping && in_contact {
            dissipation += -0.5 * (start.tangential_force[k] + tau[k]) * slip_increment[k];
        }
        if !problem.normal[k] {
            // Held along its normal by fixes: its gap is theirs, no contact condition (noted by
            // the run).
            continue;
        }
        kkt.max_penetration = kkt.max_penetration.max(-gap[k]);
        kkt.max_complementarity = kkt.max_complementarity.max((lambda[k] * gap[k]).abs());
        kkt.max_tension = kkt.max_tension.max(-lambda[k]);
        if in_contact && problem.tangential[k] && mu > 0.0 {
            let inside = slack.max(0.0) / contact_scale * slip_increment[k].abs() / length_scale;
            kkt.max_slip_inside_cone = kkt.max_slip_inside_cone.max(inside);
        }
        kkt.max_cone_violation = kkt.max_cone_violation.max(-slack);
        if slipping {
            kkt.min_dissipation = kkt.min_dissipation.min(-tau[k] * slip_increment[k]);
        }
    }
    if !kkt.min_dissipation.is_finite() {
        kkt.min_dissipation = 0.0;
    }
    let mut solution = ContactSolution {
        status: raw.status,
        load_factor: w,
        displacement,
        normal_force: raw.normal_force,
        tangential_force: raw.tangential_force,
        gap,
        state,
        slip,
        slip_increment,
        dissipation,
        kkt,
        iterations: raw.iterations,
        time: raw.time,
        trace: vec![],
        violations: vec![],
    };
    // `Converged` is the algorithm's claim; it stands only if the answer passes the checks.
    if solution.status == ContactStatus::Converged && certify(problem, &solution).is_err() {
        solution.status = ContactStatus::Numerical;
    }
    solution
}

/// Reactions of a contact solution: `K u − f − B_Nᵀ λ − B_Tᵀ τ` at constrained DOFs (the contact
/// forces a support carries included, as in [`ContactProblem::reactions`]), as a fem
/// [`Solution`].
pub fn fem_solution(problem: &ContactProblem, solution: &ContactSolution) -> Solution {
    let dofs = &problem.system.dofs;
    let u_free = dofs.restrict_free(&solution.displacement);
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| solution.load_factor * v).collect();
    let mut out = Solution::from_free(&problem.system, &u_free, &prescribed);
    let normal = solution.normal_force.iter().zip(&problem.normal_rows);
    for (force, row) in normal.chain(solution.tangential_force.iter().zip(&problem.tangent_rows)) {
        for (j, c) in &row.constrained {
            out.reactions[dofs.constrained_dofs()[*j].0] -= c * force;
        }
    }
    out
}

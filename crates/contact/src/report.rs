//! Turning interface forces into a full [`ContactSolution`]: displacements, gaps, states, KKT.

use std::time::Duration;

use contact2d_fem::Solution;

use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, ContactStatus, KktResiduals, PairState};

/// Recovers the displacements once from `λ, τ` and evaluates gaps, states and KKT residuals.
#[allow(clippy::too_many_arguments)]
pub fn finish_solution(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    normal_force: Vec<f64>,
    tangential_force: Vec<f64>,
    status: ContactStatus,
    iterations: usize,
    time: Duration,
) -> ContactSolution {
    let u_free = interface.free_displacement(w, &normal_force, &tangential_force);
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let displacement = problem.system.dofs.expand(&u_free, &prescribed);
    from_displacement(problem, w, &u_free, displacement, normal_force, tangential_force, status, iterations, time)
}

/// Builds the solution from known free displacements (used by algorithms that solve for `u`).
#[allow(clippy::too_many_arguments)]
pub fn from_displacement(
    problem: &ContactProblem,
    w: f64,
    u_free: &[f64],
    displacement: Vec<f64>,
    normal_force: Vec<f64>,
    tangential_force: Vec<f64>,
    status: ContactStatus,
    iterations: usize,
    time: Duration,
) -> ContactSolution {
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let gap: Vec<f64> =
        problem.normal_rows.iter().zip(&problem.gap).map(|(row, g0)| g0 + row.dot(u_free, &prescribed)).collect();
    // In contact where the normalised force exceeds the normalised gap: exact for an active-set
    // answer (λ = 0 or gap = 0) and robust for an interior-point one (both small but unequal).
    // Forces against the larger of the contact forces and the load's nodal forces (so that
    // round-off forces of an all-free solution are not mistaken for contact).
    let load_force = problem.pattern_rhs.iter().fold(0.0f64, |a, r| a.max((w * r).abs()));
    let force_scale = normal_force.iter().fold(load_force, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
    // Gaps are measured against the problem's displacement scale (not the largest gap, which is
    // itself round-off when every pair is closed).
    let gap_scale = gap.iter().chain(&displacement).fold(0.0f64, |a, g| a.max(g.abs())).max(f64::MIN_POSITIVE);
    let state: Vec<PairState> = normal_force
        .iter()
        .zip(&gap)
        .zip(&tangential_force)
        .zip(&problem.friction)
        .map(|(((l, g), t), mu)| {
            if *l / force_scale <= g.max(0.0) / gap_scale || *l <= 0.0 {
                PairState::Free
            } else if *mu > 0.0 && t.abs() >= mu * l * (1.0 - 1e-9) {
                if *t > 0.0 { PairState::SlipPositive } else { PairState::SlipNegative }
            } else {
                PairState::Stick
            }
        })
        .collect();
    let mut kkt = KktResiduals::default();
    for k in 0..gap.len() {
        kkt.max_penetration = kkt.max_penetration.max(-gap[k]);
        kkt.max_complementarity = kkt.max_complementarity.max((normal_force[k] * gap[k]).abs());
        kkt.max_tension = kkt.max_tension.max(-normal_force[k]);
        kkt.max_cone_violation =
            kkt.max_cone_violation.max(tangential_force[k].abs() - problem.friction[k] * normal_force[k].max(0.0));
    }
    ContactSolution {
        status,
        load_factor: w,
        displacement,
        normal_force,
        tangential_force,
        gap,
        state,
        kkt,
        iterations,
        time,
    }
}

/// Reactions of a contact solution: `K u − f` at constrained DOFs, as a fem [`Solution`].
pub fn fem_solution(problem: &ContactProblem, solution: &ContactSolution) -> Solution {
    let u_free = problem.system.dofs.restrict_free(&solution.displacement);
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| solution.load_factor * v).collect();
    Solution::from_free(&problem.system, &u_free, &prescribed)
}

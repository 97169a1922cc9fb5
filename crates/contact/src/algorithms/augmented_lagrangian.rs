//! Contact with Coulomb friction by the augmented Lagrangian of Alart & Curnier, solved by a
//! semi-smooth Newton method on the full (not condensed) system, as GetFEM and Kratos do.
//!
//! ```text
//! unknowns x = (u_f, λ, τ)                          (n + 2m; forces on the master node)
//! F_u = K u − w r − B_Nᵀ λ − B_Tᵀ τ          = 0      (equilibrium, free DOFs)
//! F_N = λ − max(0, σ),          σ = λ − c gap          (gap = ĝ + B_N u)
//! F_T = τ − proj_[−μσ⁺, μσ⁺](θ), θ = τ − c Δs          (Δs = ŝ + B_T u − s_start; F_T = τ without
//!                                                     a tangential unknown or μ = 0)
//! state of pair k:  σ ≤ 0: free;  |θ| ≤ μσ: stick;  θ > 0: slip− (τ = +μσ);  θ < 0: slip+
//! generalized Jacobian rows (the Newton system of the state, one sparse LU):
//!   free   λ_k = 0                           τ_k = 0
//!   active c b_k·u = −c ĝ_k                   stick: c t_k·u = c (s_start,k − ŝ_k)
//!                                            slip±: τ_k ∓ μ(λ_k − c b_k·u) = ∓ μ c ĝ_k
//! ```
//!
//! `c = k_c`, the contact stiffness scale ([`crate::algorithms::full_system::contact_stiffness`]),
//! puts every residual in force units. `F` is piecewise linear, so the Newton step from `x` with
//! the Jacobian of `x`'s state lands on the solution `x̂` of that state's linear system. The step
//! is safeguarded by a backtracking line search on `Φ(x) = ½‖F(x)‖²`: `x + α(x̂ − x)` with
//! `α = 1, ½, …, 1/16`, the first that decreases Φ by the Armijo factor `1 − 10⁻⁴α`; when none
//! does (the semi-smooth Newton method is not globally convergent), the full step is taken (a
//! non-monotone step that lets the active set move on). The iteration stops when a full step
//! leaves the state unchanged: `x̂` then satisfies its state's equations and the state is the
//! one `x̂` implies, so `F(x̂) = 0` to round-off. It also stops when a full step lands where
//! `‖F(x̂)‖ / F_scale ≤` [`ROUND_OFF_RESIDUAL`] although the implied state differs: a pair on the
//! boundary of two states (σ = 0, or |θ| = μσ, to round-off — e.g. a pair at a symmetry corner)
//! satisfies both states' equations there, and its state may flip on round-off at every
//! iteration without `x̂` moving, which the repeated-state test alone would follow to the
//! iteration limit (issue 41 item 5: 100 iterations whose last iterate passes the KKT checks).
//! The converged state is what the solution reports.
//!
//! The matrix has the sparsity of `K` plus the pair rows: it costs a sparse factorisation per
//! iteration instead of the condensed interface's dense `m × m` work, so it wins for long
//! interfaces (docs/benchmarks.md, "Augmented Lagrangian against the condensed active set").
//!
//! # References
//! Alart & Curnier (1991), Comput. Methods Appl. Mech. Engrg. 92: a mixed formulation for
//! frictional contact problems prone to Newton-like solution methods. Renard (2013), Comput.
//! Methods Appl. Mech. Engrg. 256: generalized Newton's methods for the approximation and
//! resolution of frictional contact problems in elasticity.

use std::time::Instant;

use crate::algorithms::full_system::{
    FixedPatternLu, backtrack, contact_stiffness, dot_free, row_offsets, stiffness_entries, stiffness_times,
};
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_displacement};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// The relative residual `‖F(x)‖ / F_scale` (`F_scale` the largest load or contact force) below
/// which a full Newton step's answer is taken as `F = 0` to round-off (see the module docs).
/// Measured: 7e-15 to 8.9e-13 at the converging iteration (two_blocks_press_slide,
/// cattaneo_mindlin, pin_lug, long_interface with 193 pairs), and at least 2.5e-4 at every
/// iteration before it on long_interface; 1e-10 lies over two orders above the round-off and
/// six below [`crate::certify::RESIDUAL_TOLERANCE`] (whose checks and the energy balance still
/// judge the answer, as for any converged run).
pub const ROUND_OFF_RESIDUAL: f64 = 1e-10;

/// Whether the iteration stops with `Converged` after a step of length `alpha` whose answer
/// implies the same state as the one it solved (`state_repeats`) or has the relative residual
/// `residual`: a full step (`alpha = 1`) that repeats the state or ends at a round-off residual.
fn settled(alpha: f64, state_repeats: bool, residual: f64) -> bool {
    alpha == 1.0 && (state_repeats || residual <= ROUND_OFF_RESIDUAL)
}

/// Solves one step to load factor `w` from the history `start`, starting from the state guess
/// `guess` (e.g. the previous step's states; `None`: the pairs that the load alone closes, from
/// one solve with the problem's Cholesky factor, in contact and sticking, the others free), with
/// at most `max_iterations` Newton iterations.
pub fn solve_augmented_lagrangian(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_iterations: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let equations = Equations::new(problem, w, start);
    let (n, m) = (equations.n, problem.num_pairs());
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => {
            let rhs: Vec<f64> = problem.pattern_rhs.iter().map(|r| w * r).collect();
            let u0 = problem.stiffness_factor().solve_or_nan(&rhs);
            (0..m)
                .map(|k| {
                    if equations.gap_offset[k] + dot_free(&problem.normal_rows[k], &u0) < 0.0 {
                        PairState::Stick
                    } else {
                        PairState::Free
                    }
                })
                .collect()
        }
    };
    let mut x = vec![0.0; n + 2 * m];
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let Some(mut lu) = FixedPatternLu::new(n + 2 * m, &equations.pattern) else {
        return finish(problem, w, start, &x, ContactStatus::Numerical, 0, clock, trace);
    };
    let mut merit = equations.merit(&x);
    for it in 1..=max_iterations {
        iterations = it;
        let (values, rhs) = equations.newton_system(&state);
        let Some(target) = lu.factor(&values).then(|| lu.solve(&rhs)).flatten() else {
            status = ContactStatus::Numerical;
            break;
        };
        let full_merit = equations.merit(&target);
        let (alpha, next_x, next_merit) = backtrack(&x, target, merit, full_merit, |t| equations.merit(t));
        (x, merit) = (next_x, next_merit);
        let next = equations.state_of(&x);
        let residual = (2.0 * merit).sqrt() / equations.force_scale(&x);
        trace.push(IterationRecord {
            iteration: it,
            changed: next.iter().zip(&state).filter(|(a, b)| a != b).count(),
            in_contact: state.iter().filter(|s| **s != PairState::Free).count(),
            slipping: state.iter().filter(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative)).count(),
            residual,
        });
        if settled(alpha, next == state, residual) {
            status = ContactStatus::Converged;
            break;
        }
        state = next;
    }
    finish(problem, w, start, &x, status, iterations, clock, trace)
}

#[allow(clippy::too_many_arguments)]
fn finish(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    x: &[f64],
    status: ContactStatus,
    iterations: usize,
    clock: Instant,
    trace: Vec<IterationRecord>,
) -> ContactSolution {
    let (n, m) = (problem.system.dofs.num_free(), problem.num_pairs());
    let raw = RawSolution {
        load_factor: w,
        normal_force: x[n..n + m].to_vec(),
        tangential_force: x[n + m..].to_vec(),
        status,
        iterations,
        time: clock.elapsed(),
    };
    let mut solution = finish_from_displacement(problem, &x[..n], raw, start);
    solution.trace = trace;
    solution
}

/// The Alart–Curnier equations of one step and the fixed pattern of their Jacobian.
struct Equations<'a> {
    problem: &'a ContactProblem,
    n: usize,
    w: f64,
    start: &'a StepStart,
    c: f64,
    gap_offset: Vec<f64>,
    slip_offset: Vec<f64>,
    /// Whether pair k has a tangential unknown with friction.
    frictional: Vec<bool>,
    /// `K_ff` entries (both triangles) first, then the pair blocks; see `newton_system`.
    pattern: Vec<(usize, usize)>,
    stiffness: Vec<f64>,
}

impl<'a> Equations<'a> {
    fn new(problem: &'a ContactProblem, w: f64, start: &'a StepStart) -> Equations<'a> {
        let (n, m) = (problem.system.dofs.num_free(), problem.num_pairs());
        let (gap_offset, slip_offset) = row_offsets(problem, w);
        let frictional: Vec<bool> = (0..m).map(|k| problem.tangential[k] && problem.friction[k] > 0.0).collect();
        let entries = stiffness_entries(problem);
        let mut pattern: Vec<(usize, usize)> = entries.iter().map(|&(i, j, _)| (i, j)).collect();
        for (k, &with_friction) in frictional.iter().enumerate() {
            let (normal, tangent) = (&problem.normal_rows[k], &problem.tangent_rows[k]);
            let (rn, rt) = (n + k, n + m + k);
            pattern.extend(normal.free.iter().map(|&(i, _)| (i, rn)));
            pattern.extend(normal.free.iter().map(|&(i, _)| (rn, i)));
            pattern.push((rn, rn));
            if with_friction {
                pattern.extend(tangent.free.iter().map(|&(i, _)| (i, rt)));
                pattern.extend(tangent.free.iter().map(|&(i, _)| (rt, i)));
                pattern.extend(normal.free.iter().map(|&(i, _)| (rt, i)));
                pattern.push((rt, rn));
            }
            pattern.push((rt, rt));
        }
        Equations {
            problem,
            n,
            w,
            start,
            c: contact_stiffness(problem),
            gap_offset,
            slip_offset,
            frictional,
            pattern,
            stiffness: entries.into_iter().map(|(_, _, v)| v).collect(),
        }
    }

    /// The values (in pattern order) and right-hand side of the Newton system of `state`.
    fn newton_system(&self, state: &[PairState]) -> (Vec<f64>, Vec<f64>) {
        let (p, n, c) = (self.problem, self.n, self.c);
        let m = p.num_pairs();
        let mut values = self.stiffness.clone();
        values.reserve(self.pattern.len() - values.len());
        let mut rhs = vec![0.0; n + 2 * m];
        rhs[..n].iter_mut().zip(&p.pattern_rhs).for_each(|(b, r)| *b = self.w * r);
        for k in 0..m {
            let (normal, tangent) = (&p.normal_rows[k], &p.tangent_rows[k]);
            let active = state[k] != PairState::Free;
            values.extend(normal.free.iter().map(|(_, v)| -v));
            values.extend(normal.free.iter().map(|(_, v)| if active { c * v } else { 0.0 }));
            values.push(if active { 0.0 } else { 1.0 });
            if active {
                rhs[n + k] = -c * self.gap_offset[k];
            }
            // slip−: τ = +μσ (sign +1); slip+: τ = −μσ (sign −1).
            let slip_sign = match state[k] {
                PairState::SlipNegative => 1.0,
                PairState::SlipPositive => -1.0,
                _ => 0.0,
            };
            let stick = state[k] == PairState::Stick;
            if self.frictional[k] {
                let mu = p.friction[k];
                values.extend(tangent.free.iter().map(|(_, v)| -v));
                values.extend(tangent.free.iter().map(|(_, v)| if stick { c * v } else { 0.0 }));
                values.extend(normal.free.iter().map(|(_, v)| slip_sign * mu * c * v));
                values.push(-slip_sign * mu);
                values.push(if stick { 0.0 } else { 1.0 });
                if stick {
                    rhs[n + m + k] = c * (self.start.slip[k] - self.slip_offset[k]);
                } else {
                    rhs[n + m + k] = -slip_sign * mu * c * self.gap_offset[k];
                }
            } else {
                values.push(1.0);
            }
        }
        (values, rhs)
    }

    /// `(σ, θ)` of pair k at `x` (θ = 0 without friction).
    fn multipliers(&self, x: &[f64], k: usize) -> (f64, f64) {
        let (p, n, m) = (self.problem, self.n, self.problem.num_pairs());
        let u = &x[..n];
        let gap = self.gap_offset[k] + dot_free(&p.normal_rows[k], u);
        let sigma = x[n + k] - self.c * gap;
        if !self.frictional[k] {
            return (sigma, 0.0);
        }
        let ds = self.slip_offset[k] + dot_free(&p.tangent_rows[k], u) - self.start.slip[k];
        (sigma, x[n + m + k] - self.c * ds)
    }

    /// The state each pair's complementarity functions select at `x`.
    fn state_of(&self, x: &[f64]) -> Vec<PairState> {
        (0..self.problem.num_pairs())
            .map(|k| {
                let (sigma, theta) = self.multipliers(x, k);
                PairState::from_trial(sigma, theta, self.problem.friction[k], self.frictional[k])
            })
            .collect()
    }

    /// `Φ(x) = ½ ‖F(x)‖²` of the module docs.
    fn merit(&self, x: &[f64]) -> f64 {
        let (p, n, m) = (self.problem, self.n, self.problem.num_pairs());
        let mut f = stiffness_times(p, &x[..n]);
        f.iter_mut().zip(&p.pattern_rhs).for_each(|(v, r)| *v -= self.w * r);
        for k in 0..m {
            for &(i, v) in &p.normal_rows[k].free {
                f[i] -= v * x[n + k];
            }
            if self.frictional[k] {
                for &(i, v) in &p.tangent_rows[k].free {
                    f[i] -= v * x[n + m + k];
                }
            }
        }
        let mut sum: f64 = f.iter().map(|v| v * v).sum();
        for k in 0..m {
            let (sigma, theta) = self.multipliers(x, k);
            let normal = x[n + k] - sigma.max(0.0);
            let bound = p.friction[k] * sigma.max(0.0);
            let tangential = if self.frictional[k] { x[n + m + k] - theta.clamp(-bound, bound) } else { x[n + m + k] };
            sum += normal * normal + tangential * tangential;
        }
        0.5 * sum
    }

    /// The largest load or contact force at `x` (the residual's scale in the trace).
    fn force_scale(&self, x: &[f64]) -> f64 {
        let load = self.problem.pattern_rhs.iter().fold(0.0f64, |a, r| a.max((self.w * r).abs()));
        x[self.n..].iter().fold(load, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stopping rule: a full step stops on a repeated state (whatever its residual) or on a
    /// round-off residual (whatever the implied state); a damped step never stops, since its
    /// point solves no state's equations; a full step that changes the state at a residual above
    /// round-off (2.5e-4: the last iteration but one on long_interface) goes on.
    #[test]
    fn a_full_step_stops_on_a_repeated_state_or_a_round_off_residual() {
        assert!(settled(1.0, true, 1e-3));
        assert!(settled(1.0, false, 8.9e-13));
        assert!(!settled(0.5, true, 1e-16));
        assert!(!settled(1.0, false, 2.5e-4));
        assert!(!settled(1.0, false, 2.0 * ROUND_OFF_RESIDUAL));
    }
}

//! Contact by the penalty method: a normal penalty and a regularised (elastic-slip) Coulomb law,
//! on the full displacement system.
//!
//! ```text
//! ε_N = κ_N k_c,  ε_T = κ_T k_c            (κ: the user's relative penalties; k_c: the contact
//!                                          stiffness scale of crate::algorithms::full_system)
//! λ_k = ε_N (−gap_k)⁺                      (gap_k = ĝ_k + b_k·u: the penetration is part of the law)
//! θ_k = τ_start,k − ε_T Δs_k               (elastic predictor, Δs_k = ŝ_k + t_k·u − s_start,k)
//! τ_k = θ_k if |θ_k| ≤ μλ_k (stick), else μλ_k sign θ_k (slip; sign θ > 0: slip−, < 0: slip+)
//! K u = w r + B_Nᵀ λ(u) + B_Tᵀ τ(u)         (piecewise linear in u)
//! state equations (one sparse LU per iteration):
//!   (K + Σ_active ε_N b bᵀ + Σ_stick ε_T t tᵀ + Σ_slip sign·μ ε_N t bᵀ) u
//!     = w r − Σ_active ε_N b ĝ + Σ_stick t (τ_start − ε_T (ŝ − s_start)) − Σ_slip sign·μ ε_N t ĝ
//! ```
//!
//! The states are iterated to a fixed point: solve the equations of the current state, take the
//! state the answer implies, until it repeats (Newton's method on the piecewise-linear system).
//! The step is safeguarded like the augmented Lagrangian's: backtracking on `½‖R(u)‖²`,
//! `R(u) = K u − w r − B_Nᵀλ(u) − B_Tᵀτ(u)`, the full step when no damped one decreases it (stick
//! and slip states otherwise cycle on a sliding step).
//! The answer then satisfies the penalised law exactly; the method's own residual, the
//! equilibrium `‖K u − w r − B_Nᵀλ − B_Tᵀτ‖∞ / F` (F: the largest load or contact force), is
//! checked at the certificate's 1e-4 ([`crate::certify::RESIDUAL_TOLERANCE`]). It is round-off
//! times `κ`: the LU solves the penalised system to its backward error, `ε_N` times the
//! round-off of the gap, and `λ = −ε_N gap` multiplies the gap's round-off by `ε_N`. Measured on
//! the two-block problem: the force error is `2.6/κ` down to 6e-8 at κ = 1e8, then grows as
//! round-off, 1.4e-5 at 1e10 and 1.1e-3 at 1e12, where this check reports
//! [`ContactStatus::Numerical`].
//!
//! Its error is the method's: a pair in contact penetrates by `λ/ε_N`, and a stuck pair slips
//! elastically by `|τ − τ_start|/ε_T`. The status says so: [`ContactStatus::Penalised`] when the
//! exact contact conditions fail [`crate::certify::certify`] (the penetration is reported in
//! `kkt.max_penetration`), [`ContactStatus::Converged`] only when they hold too (a penalty large
//! enough that the penetration is below the certificate's 1e-4 of the displacement scale).
//! Its cost is conditioning: `ε_N` adds stiffness `κ_N` times that of the contact DOFs, and the
//! condition number of the penalised matrix grows linearly with `κ_N` once it dominates
//! (docs/algorithms.md, "Penalty").
//!
//! # References
//! Wriggers (2006), Computational Contact Mechanics, 2nd ed., §6.3 (penalty method) and §5.2
//! (regularised Coulomb law).

use std::time::Instant;

use crate::algorithms::full_system::{
    FixedPatternLu, backtrack, contact_stiffness, dot_free, row_offsets, stiffness_entries, stiffness_times,
};
use crate::certify::{RESIDUAL_TOLERANCE, certify};
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_displacement};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// The relative penalties `κ_N`, `κ_T` (dimensionless; the penalties are `κ k_c`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PenaltyParameters {
    /// `κ_N`: the normal penalty relative to the contact stiffness scale.
    pub normal: f64,
    /// `κ_T`: the tangential (stick) penalty relative to the contact stiffness scale.
    pub tangential: f64,
}

impl Default for PenaltyParameters {
    /// `κ_N = κ_T = 1e3`: penetrations of about 1e-3 of the pair's own compliance times its force.
    fn default() -> PenaltyParameters {
        PenaltyParameters { normal: 1e3, tangential: 1e3 }
    }
}

/// Largest equilibrium residual (relative to the force scale) of an answer the method accepts.
const EQUILIBRIUM_TOLERANCE: f64 = RESIDUAL_TOLERANCE;

/// Solves one step to load factor `w` from `start` by the penalty method with `parameters`,
/// starting from the state guess `guess` (`None`: the pairs that the load alone closes, from one
/// solve with the problem's Cholesky factor, in contact and sticking).
pub fn solve_penalty(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    parameters: PenaltyParameters,
    max_iterations: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let law = PenaltyLaw::new(problem, w, start, parameters);
    let (n, m) = (problem.system.dofs.num_free(), problem.num_pairs());
    let rhs: Vec<f64> = problem.pattern_rhs.iter().map(|r| w * r).collect();
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => {
            let u0 = problem.stiffness_factor().solve_or_nan(&rhs);
            law.state_of(&u0).into_iter().map(|s| if s == PairState::Free { s } else { PairState::Stick }).collect()
        }
    };
    let mut u = vec![0.0; n];
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let mut merit = law.merit(&u);
    match FixedPatternLu::new(n, &law.pattern) {
        None => status = ContactStatus::Numerical,
        Some(mut lu) => {
            for it in 1..=max_iterations {
                iterations = it;
                let (values, b) = law.state_system(&state, &rhs);
                let Some(next_u) = lu.factor(&values).then(|| lu.solve(&b)).flatten() else {
                    status = ContactStatus::Numerical;
                    break;
                };
                // Safeguard (as the augmented Lagrangian's): backtrack on Φ(u) = ½‖R(u)‖² from
                // the full step u → û, α = 1, ½, …, 1/16; the full step when none decreases Φ.
                let full = law.merit(&next_u);
                let (alpha, next, next_merit) = backtrack(&u, next_u, merit, full, |t| law.merit(t));
                (u, merit) = (next, next_merit);
                // A slip whose direction reverses crosses the stick cone on the way: try stick
                // (without this, a pair with a tiny λ flips slip+ ↔ slip− forever).
                let next: Vec<PairState> = law
                    .state_of(&u)
                    .into_iter()
                    .zip(&state)
                    .map(|(n, s)| if slip_sign(n) * slip_sign(*s) < 0.0 { PairState::Stick } else { n })
                    .collect();
                trace.push(IterationRecord {
                    iteration: it,
                    changed: next.iter().zip(&state).filter(|(a, b)| a != b).count(),
                    in_contact: state.iter().filter(|s| **s != PairState::Free).count(),
                    slipping: state
                        .iter()
                        .filter(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative))
                        .count(),
                    residual: 0.0,
                });
                if alpha == 1.0 && next == state {
                    status = ContactStatus::Converged;
                    break;
                }
                state = next;
            }
        }
    }
    let (lambda, tau) = law.forces(&u, &state);
    if status == ContactStatus::Converged && law.equilibrium_residual(&u, &lambda, &tau) > EQUILIBRIUM_TOLERANCE {
        status = ContactStatus::Numerical;
    }
    let converged = status == ContactStatus::Converged;
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: tau,
        status: if converged { ContactStatus::Penalised } else { status },
        iterations,
        time: clock.elapsed(),
    };
    let mut solution = finish_from_displacement(problem, &u, raw, start);
    solution.trace = trace;
    if converged && certify(problem, &solution).is_ok() {
        solution.status = ContactStatus::Converged;
    }
    solution
}

/// The penalised law of one step and the fixed pattern of its state matrices.
struct PenaltyLaw<'a> {
    problem: &'a ContactProblem,
    w: f64,
    start: &'a StepStart,
    normal_penalty: f64,
    tangential_penalty: f64,
    gap_offset: Vec<f64>,
    slip_offset: Vec<f64>,
    frictional: Vec<bool>,
    /// `K_ff` entries (both triangles), then per pair `b⊗b`, and with friction `t⊗t`, `t⊗b`.
    pattern: Vec<(usize, usize)>,
    stiffness: Vec<f64>,
}

impl<'a> PenaltyLaw<'a> {
    fn new(problem: &'a ContactProblem, w: f64, start: &'a StepStart, parameters: PenaltyParameters) -> PenaltyLaw<'a> {
        let k_c = contact_stiffness(problem);
        let (gap_offset, slip_offset) = row_offsets(problem, w);
        let m = problem.num_pairs();
        let frictional: Vec<bool> = (0..m).map(|k| problem.tangential[k] && problem.friction[k] > 0.0).collect();
        let entries = stiffness_entries(problem);
        let mut pattern: Vec<(usize, usize)> = entries.iter().map(|&(i, j, _)| (i, j)).collect();
        let outer = |pattern: &mut Vec<(usize, usize)>, a: &[(usize, f64)], b: &[(usize, f64)]| {
            for &(i, _) in a {
                pattern.extend(b.iter().map(|&(j, _)| (i, j)));
            }
        };
        for (k, &with_friction) in frictional.iter().enumerate() {
            let (normal, tangent) = (&problem.normal_rows[k].free, &problem.tangent_rows[k].free);
            outer(&mut pattern, normal, normal);
            if with_friction {
                outer(&mut pattern, tangent, tangent);
                outer(&mut pattern, tangent, normal);
            }
        }
        PenaltyLaw {
            problem,
            w,
            start,
            normal_penalty: parameters.normal * k_c,
            tangential_penalty: parameters.tangential * k_c,
            gap_offset,
            slip_offset,
            frictional,
            pattern,
            stiffness: entries.into_iter().map(|(_, _, v)| v).collect(),
        }
    }

    /// The matrix values (pattern order) and right-hand side of the equations of `state`.
    fn state_system(&self, state: &[PairState], load: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let p = self.problem;
        let (e_n, e_t) = (self.normal_penalty, self.tangential_penalty);
        let mut values = self.stiffness.clone();
        let mut rhs = load.to_vec();
        let outer = |values: &mut Vec<f64>, a: &[(usize, f64)], b: &[(usize, f64)], scale: f64| {
            for &(_, x) in a {
                values.extend(b.iter().map(|&(_, y)| scale * x * y));
            }
        };
        for (k, s) in state.iter().enumerate() {
            let (normal, tangent) = (&p.normal_rows[k].free, &p.tangent_rows[k].free);
            let active = *s != PairState::Free;
            outer(&mut values, normal, normal, if active { e_n } else { 0.0 });
            if active {
                normal.iter().for_each(|&(i, v)| rhs[i] -= e_n * v * self.gap_offset[k]);
            }
            if !self.frictional[k] {
                continue;
            }
            let stick = *s == PairState::Stick;
            let sign = slip_sign(*s);
            let mu = p.friction[k];
            outer(&mut values, tangent, tangent, if stick { e_t } else { 0.0 });
            outer(&mut values, tangent, normal, sign * mu * e_n);
            let force = if stick {
                self.start.tangential_force[k] - e_t * (self.slip_offset[k] - self.start.slip[k])
            } else {
                -sign * mu * e_n * self.gap_offset[k]
            };
            tangent.iter().for_each(|&(i, v)| rhs[i] += v * force);
        }
        (values, rhs)
    }

    /// `(λ_k, θ_k)` at `u`.
    fn trial(&self, u: &[f64], k: usize) -> (f64, f64) {
        let p = self.problem;
        let gap = self.gap_offset[k] + dot_free(&p.normal_rows[k], u);
        let lambda = self.normal_penalty * (-gap).max(0.0);
        if !self.frictional[k] {
            return (lambda, 0.0);
        }
        let ds = self.slip_offset[k] + dot_free(&p.tangent_rows[k], u) - self.start.slip[k];
        (lambda, self.start.tangential_force[k] - self.tangential_penalty * ds)
    }

    /// The state the law selects at `u`.
    fn state_of(&self, u: &[f64]) -> Vec<PairState> {
        (0..self.problem.num_pairs())
            .map(|k| {
                let (lambda, theta) = self.trial(u, k);
                PairState::from_trial(lambda, theta, self.problem.friction[k], self.frictional[k])
            })
            .collect()
    }

    /// `(λ, τ)` of `u` in `state` (the state's linear law, which the fixed point makes the
    /// law's own).
    fn forces(&self, u: &[f64], state: &[PairState]) -> (Vec<f64>, Vec<f64>) {
        let m = self.problem.num_pairs();
        let (mut lambda, mut tau) = (vec![0.0; m], vec![0.0; m]);
        for k in 0..m {
            if state[k] == PairState::Free {
                continue;
            }
            let gap = self.gap_offset[k] + dot_free(&self.problem.normal_rows[k], u);
            lambda[k] = -self.normal_penalty * gap;
            let (_, theta) = self.trial(u, k);
            tau[k] = match state[k] {
                _ if !self.frictional[k] => 0.0,
                PairState::Stick => theta,
                s => slip_sign(s) * self.problem.friction[k] * lambda[k],
            };
        }
        (lambda, tau)
    }

    /// `R(u) = K u − w r − B_Nᵀλ(u) − B_Tᵀτ(u)` with the forces of the law's state at `u`.
    fn residual(&self, u: &[f64], lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let p = self.problem;
        let mut f = stiffness_times(p, u);
        f.iter_mut().zip(&p.pattern_rhs).for_each(|(v, r)| *v -= self.w * r);
        for k in 0..p.num_pairs() {
            p.normal_rows[k].free.iter().for_each(|&(i, v)| f[i] -= v * lambda[k]);
            p.tangent_rows[k].free.iter().for_each(|&(i, v)| f[i] -= v * tau[k]);
        }
        f
    }

    /// `Φ(u) = ½ ‖R(u)‖²` (the merit of the line search).
    fn merit(&self, u: &[f64]) -> f64 {
        let (lambda, tau) = self.forces(u, &self.state_of(u));
        0.5 * self.residual(u, &lambda, &tau).iter().map(|v| v * v).sum::<f64>()
    }

    /// `‖K u − w r − B_Nᵀλ − B_Tᵀτ‖∞ / F`, with `F` the largest load or contact force.
    fn equilibrium_residual(&self, u: &[f64], lambda: &[f64], tau: &[f64]) -> f64 {
        let p = self.problem;
        let f = self.residual(u, lambda, tau);
        let scale = p
            .pattern_rhs
            .iter()
            .map(|r| (self.w * r).abs())
            .chain(lambda.iter().chain(tau).map(|v| v.abs()))
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        f.iter().fold(0.0f64, |a, v| a.max(v.abs())) / scale
    }
}

/// `τ = sign · μλ` of a slip state: slip− (θ > 0) +1, slip+ −1, otherwise 0.
fn slip_sign(state: PairState) -> f64 {
    match state {
        PairState::SlipNegative => 1.0,
        PairState::SlipPositive => -1.0,
        _ => 0.0,
    }
}

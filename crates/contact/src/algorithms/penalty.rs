//! Contact by the penalty method: a normal penalty and a regularised (elastic-slip) Coulomb law,
//! each state's equations condensed onto the pairs' rows (the condensed interface) or on the full
//! displacement system (the sparse path).
//!
//! ```text
//! ε_N = κ_N k_c,  ε_T = κ_T k_c            (κ: the user's relative penalties; k_c: the contact
//!                                          stiffness scale of crate::algorithms::full_system)
//! λ_k = ε_N (−gap_k)⁺                      (gap_k = ĝ_k + b_k·u: the penetration is part of the law)
//! θ_k = τ_start,k − ε_T Δs_k               (elastic predictor, Δs_k = ŝ_k + t_k·u − s_start,k)
//! τ_k = θ_k if |θ_k| ≤ μλ_k (stick), else μλ_k sign θ_k (slip; sign θ > 0: slip−, < 0: slip+)
//! K u = w r + B_Nᵀ λ(u) + B_Tᵀ τ(u)         (piecewise linear in u)
//! state equations, full system (the sparse path, `solver.linear = "sparse"`; one sparse LU per
//! iteration):
//!   (K + Σ_active ε_N b bᵀ + Σ_stick ε_T t tᵀ + Σ_slip sign·μ ε_N t bᵀ) u
//!     = w r − Σ_active ε_N b ĝ + Σ_stick t (τ_start − ε_T (ŝ − s_start)) − Σ_slip sign·μ ε_N t ĝ
//! the same equations condensed (the condensed interface; a dense LU of the loaded forces per
//! iteration, `Condensed` below and crate::algorithms::pair_space):
//!   u = K⁻¹(w r + Bᵀ f),  (C f)_N,k + λ_k/ε_N = −(ĝ_k + w y0_N,k),
//!   (C f)_T,k + τ_k/ε_T = −(ŝ_k − s_start,k − τ_start,k/ε_T + w y0_T,k) (stick),  τ_k = sign·μλ_k (slip)
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
//! the two-block problem (full system): the force error is `2.6/κ` down to 6e-8 at κ = 1e8, then
//! grows as round-off, 1.4e-5 at 1e10 and 1.1e-3 at 1e12, where this check reports
//! [`ContactStatus::Numerical`]. Condensed, the residual is `Bᵀ(f − λ(u))`: the solved forces `f`
//! against the law's at the recovered rows, the same `ε_N` times a gap's round-off.
//!
//! Its error is the method's: a pair in contact penetrates by `λ/ε_N`, and a stuck pair slips
//! elastically by `|τ − τ_start|/ε_T`. The status says so: [`ContactStatus::Penalised`] when the
//! exact contact conditions fail [`crate::certify::certify`] (the penetration is reported in
//! `kkt.max_penetration`), [`ContactStatus::Converged`] only when they hold too (a penalty large
//! enough that the penetration is below the certificate's 1e-4 of the displacement scale).
//! Its cost is conditioning: `ε_N` adds stiffness `κ_N` times that of the contact DOFs, and the
//! condition number of the penalised matrix grows linearly with `κ_N` once it dominates
//! (docs/algorithms.md, "Penalty"); the condensed equations, in the forces, add `1/ε` to the
//! diagonal of the compliances instead and keep the active set's conditioning. Both paths take
//! the same iterates (to round-off), so the same iteration counts; the condensed one costs the
//! active set's dense work of the interface's size per iteration instead of a sparse LU of the
//! whole system (docs/benchmarks.md, "Penalty and augmented Lagrangian condensed").
//!
//! # References
//! Wriggers (2006), Computational Contact Mechanics, 2nd ed., §6.3 (penalty method) and §5.2
//! (regularised Coulomb law).

use std::time::Instant;

use crate::algorithms::full_system::{
    FixedPatternLu, backtrack, contact_stiffness, dot_free, row_offsets, stiffness_entries, stiffness_times,
};
use crate::algorithms::pair_space::{PairSpace, dense_solve, slip_sign};
use crate::certify::{RESIDUAL_TOLERANCE, certify};
use crate::interface::Interface;
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
/// solve with the problem's Cholesky factor, in contact and sticking), each iteration's
/// equations on the full system (one sparse LU).
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
    let n = problem.system.dofs.num_free();
    let (pattern, stiffness) = full_pattern(&law);
    match FixedPatternLu::new(n, &pattern) {
        Some(lu) => {
            let rhs: Vec<f64> = problem.pattern_rhs.iter().map(|r| w * r).collect();
            iterate(&law, &mut FullSystem { law: &law, lu, stiffness, rhs }, guess, max_iterations, clock)
        }
        None => {
            let raw = RawSolution {
                load_factor: w,
                normal_force: vec![0.0; problem.num_pairs()],
                tangential_force: vec![0.0; problem.num_pairs()],
                status: ContactStatus::Numerical,
                iterations: 0,
                time: clock.elapsed(),
            };
            finish_from_displacement(problem, &vec![0.0; n], raw, start)
        }
    }
}

/// [`solve_penalty`] with each iteration's equations condensed onto the pairs' rows of
/// `interface` (the problem's condensed interface at its current load;
/// `algorithms/pair_space.rs`): the same iterates to round-off, a dense LU of the loaded
/// rows per iteration instead of a sparse LU of the whole system.
pub fn solve_penalty_condensed(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    parameters: PenaltyParameters,
    max_iterations: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let law = PenaltyLaw::new(problem, w, start, parameters);
    let mut system = Condensed { law: &law, space: PairSpace::new(problem, interface) };
    iterate(&law, &mut system, guess, max_iterations, clock)
}

/// A way to solve the state equations of the penalised law: an iterate `x`, its pair rows
/// `y = (B_N u, B_T u)` (free parts, `2m`), its residual and displacement.
trait StateSolver {
    /// The iterate `u = 0`.
    fn origin(&self) -> Vec<f64>;
    /// The pair rows of `u = K⁻¹ w r` (the load without contact forces).
    fn load_rows(&self) -> Vec<f64>;
    /// The solution of the equations of `state` (`None`: singular).
    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>>;
    /// The pair rows `y` of the iterate `x`.
    fn rows(&self, x: &[f64]) -> Vec<f64>;
    /// `R = K u − w r − B_Nᵀλ − B_Tᵀτ` at `x`.
    fn residual(&self, x: &[f64], lambda: &[f64], tau: &[f64]) -> Vec<f64>;
    /// The free displacements of `x`.
    fn displacement(&self, x: &[f64]) -> Vec<f64>;
    /// The forces `x` carries itself, if it does and is in equilibrium with them (else the
    /// law's at its rows are reported).
    fn own_forces(&self, _x: &[f64]) -> Option<(Vec<f64>, Vec<f64>)> {
        None
    }
}

/// The full system: `x = u`, each state's equations one numeric sparse LU.
struct FullSystem<'a> {
    law: &'a PenaltyLaw<'a>,
    lu: FixedPatternLu,
    stiffness: Vec<f64>,
    rhs: Vec<f64>,
}

impl StateSolver for FullSystem<'_> {
    fn origin(&self) -> Vec<f64> {
        vec![0.0; self.rhs.len()]
    }

    fn load_rows(&self) -> Vec<f64> {
        self.rows(&self.law.problem.stiffness_factor().solve_or_nan(&self.rhs))
    }

    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>> {
        let (values, b) = self.law.state_system(&self.stiffness, state, &self.rhs);
        self.lu.factor(&values).then(|| self.lu.solve(&b)).flatten()
    }

    fn rows(&self, u: &[f64]) -> Vec<f64> {
        let p = self.law.problem;
        p.normal_rows.iter().chain(&p.tangent_rows).map(|r| dot_free(r, u)).collect()
    }

    fn residual(&self, u: &[f64], lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let p = self.law.problem;
        let mut f = stiffness_times(p, u);
        f.iter_mut().zip(&p.pattern_rhs).for_each(|(v, r)| *v -= self.law.w * r);
        for k in 0..p.num_pairs() {
            p.normal_rows[k].free.iter().for_each(|&(i, v)| f[i] -= v * lambda[k]);
            p.tangent_rows[k].free.iter().for_each(|&(i, v)| f[i] -= v * tau[k]);
        }
        f
    }

    fn displacement(&self, u: &[f64]) -> Vec<f64> {
        u.to_vec()
    }
}

/// The condensed system (`algorithms/pair_space.rs`): `x = (a, g)`,
/// `u = K⁻¹(a w r + Bᵀ g)`, each state's equations solved for the forces it loads (the law
/// `f = −ε (row + offset)` of each loaded row, with `y = w y0 + C f`; the compliance form keeps
/// the active set's conditioning, `1/ε` on the diagonal, instead of multiplying `C` by `ε`):
///
/// ```text
/// in contact:  (C f)_N,k + λ_k/ε_N = −(ĝ_k + w y0_N,k)
/// stick:       (C f)_T,k + τ_k/ε_T = −(ŝ_k − s_start,k − τ_start,k/ε_T + w y0_T,k)
/// slip±:       τ_k ∓ μ λ_k = 0
/// free:        λ_k = τ_k = 0;  no friction: τ_k = 0
/// ```
///
/// (the first two rows scaled by `k_c`), a dense LU of the unknown forces; the target is
/// `a = 1, g = f`.
struct Condensed<'a> {
    law: &'a PenaltyLaw<'a>,
    space: PairSpace<'a>,
}

impl StateSolver for Condensed<'_> {
    fn origin(&self) -> Vec<f64> {
        vec![0.0; 1 + 2 * self.law.problem.num_pairs()]
    }

    fn load_rows(&self) -> Vec<f64> {
        self.space.rows(self.law.w, &[])
    }

    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>> {
        let law = self.law;
        let (m, scale) = (law.problem.num_pairs(), law.contact_stiffness);
        let mut system = self.space.loaded_forces(state, &law.frictional, &law.problem.friction, scale)?;
        let load = self.space.rows(law.w, &[]);
        let mut rhs = vec![0.0; system.unknowns.len()];
        for (a, &i) in system.unknowns.iter().enumerate() {
            if system.is_slip_row(a, state) {
                continue;
            }
            let k = i % m;
            let (penalty, offset) = if i < m {
                (law.normal_penalty, law.gap_offset[k])
            } else {
                let e_t = law.tangential_penalty;
                (e_t, law.slip_offset[k] - law.start.slip[k] - law.start.tangential_force[k] / e_t)
            };
            system.matrix[(a, a)] += scale / penalty;
            rhs[a] = -scale * (offset + load[i]);
        }
        let forces = dense_solve(std::mem::take(&mut system.matrix), rhs)?;
        Some(system.target(m, forces))
    }

    fn rows(&self, x: &[f64]) -> Vec<f64> {
        self.space.rows(x[0] * self.law.w, &x[1..])
    }

    fn residual(&self, x: &[f64], lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let m = lambda.len();
        let d: Vec<f64> = x[1..].iter().zip(lambda.iter().chain(tau)).map(|(g, f)| g - f).collect();
        debug_assert_eq!(d.len(), 2 * m);
        self.space.equilibrium(x[0], self.law.w, &d)
    }

    fn displacement(&self, x: &[f64]) -> Vec<f64> {
        self.space.displacement(x[0] * self.law.w, &x[1..])
    }

    /// `g` when `a = 1`: `u = K⁻¹(w r + Bᵀ g)` is then in equilibrium with `g` exactly, and `g`
    /// satisfies the law to the round-off of the well-conditioned solve, while the law's forces
    /// at the rows, `−ε (ĝ + w y0 + C g)`, carry `ε` times the round-off of `C g` (a
    /// cancellation: the gap is a small difference of `ĝ` and the rows).
    fn own_forces(&self, x: &[f64]) -> Option<(Vec<f64>, Vec<f64>)> {
        let m = self.law.problem.num_pairs();
        (x[0] == 1.0).then(|| (x[1..1 + m].to_vec(), x[1 + m..].to_vec()))
    }
}

/// The fixed-point iteration of the module docs with the state equations of `solver`.
fn iterate(
    law: &PenaltyLaw,
    solver: &mut impl StateSolver,
    guess: Option<&[PairState]>,
    max_iterations: usize,
    clock: Instant,
) -> ContactSolution {
    let (problem, w, start) = (law.problem, law.w, law.start);
    let m = problem.num_pairs();
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => law
            .state_of(&solver.load_rows())
            .into_iter()
            .map(|s| if s == PairState::Free { s } else { PairState::Stick })
            .collect(),
    };
    let mut x = solver.origin();
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let mut value = merit(law, solver, &x);
    for it in 1..=max_iterations {
        iterations = it;
        let Some(target) = solver.target(&state) else {
            status = ContactStatus::Numerical;
            break;
        };
        // Safeguard (as the augmented Lagrangian's): backtrack on Φ(u) = ½‖R(u)‖² from
        // the full step u → û, α = 1, ½, …, 1/16; the full step when none decreases Φ.
        let full = merit(law, solver, &target);
        let (alpha, next_x, next_value) = backtrack(&x, target, value, full, |t| merit(law, solver, t));
        (x, value) = (next_x, next_value);
        // A slip whose direction reverses crosses the stick cone on the way: try stick
        // (without this, a pair with a tiny λ flips slip+ ↔ slip− forever).
        let next: Vec<PairState> = law
            .state_of(&solver.rows(&x))
            .into_iter()
            .zip(&state)
            .map(|(n, s)| if slip_sign(n) * slip_sign(*s) < 0.0 { PairState::Stick } else { n })
            .collect();
        trace.push(IterationRecord::of_states(it, &state, &next, 0.0));
        if alpha == 1.0 && next == state {
            status = ContactStatus::Converged;
            break;
        }
        state = next;
    }
    let (lambda, tau) = law.forces(&solver.rows(&x), &state);
    if status == ContactStatus::Converged
        && law.equilibrium_residual(&solver.residual(&x, &lambda, &tau), &lambda, &tau) > EQUILIBRIUM_TOLERANCE
    {
        status = ContactStatus::Numerical;
    }
    let converged = status == ContactStatus::Converged;
    let (lambda, tau) = solver.own_forces(&x).unwrap_or((lambda, tau));
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: tau,
        status: if converged { ContactStatus::Penalised } else { status },
        iterations,
        time: clock.elapsed(),
    };
    let mut solution = finish_from_displacement(problem, &solver.displacement(&x), raw, start);
    solution.trace = trace;
    if converged && certify(problem, &solution).is_ok() {
        solution.status = ContactStatus::Converged;
    }
    solution
}

/// `Φ(x) = ½ ‖R(x)‖²` (the merit of the line search), with the forces of the law's state at `x`.
fn merit(law: &PenaltyLaw, solver: &impl StateSolver, x: &[f64]) -> f64 {
    let y = solver.rows(x);
    let (lambda, tau) = law.forces(&y, &law.state_of(&y));
    0.5 * solver.residual(x, &lambda, &tau).iter().map(|v| v * v).sum::<f64>()
}

/// The penalised law of one step.
struct PenaltyLaw<'a> {
    problem: &'a ContactProblem,
    w: f64,
    start: &'a StepStart,
    normal_penalty: f64,
    tangential_penalty: f64,
    /// `k_c` (the condensed rows' scale).
    contact_stiffness: f64,
    gap_offset: Vec<f64>,
    slip_offset: Vec<f64>,
    frictional: Vec<bool>,
}

/// The fixed pattern of the full system's state matrices and the `K_ff` values at its start:
/// `K_ff` entries (both triangles), then per pair `b⊗b`, and with friction `t⊗t`, `t⊗b`.
fn full_pattern(law: &PenaltyLaw) -> (Vec<(usize, usize)>, Vec<f64>) {
    let problem = law.problem;
    let entries = stiffness_entries(problem);
    let mut pattern: Vec<(usize, usize)> = entries.iter().map(|&(i, j, _)| (i, j)).collect();
    let outer = |pattern: &mut Vec<(usize, usize)>, a: &[(usize, f64)], b: &[(usize, f64)]| {
        for &(i, _) in a {
            pattern.extend(b.iter().map(|&(j, _)| (i, j)));
        }
    };
    for (k, &with_friction) in law.frictional.iter().enumerate() {
        let (normal, tangent) = (&problem.normal_rows[k].free, &problem.tangent_rows[k].free);
        outer(&mut pattern, normal, normal);
        if with_friction {
            outer(&mut pattern, tangent, tangent);
            outer(&mut pattern, tangent, normal);
        }
    }
    (pattern, entries.into_iter().map(|(_, _, v)| v).collect())
}

impl<'a> PenaltyLaw<'a> {
    fn new(problem: &'a ContactProblem, w: f64, start: &'a StepStart, parameters: PenaltyParameters) -> PenaltyLaw<'a> {
        let k_c = contact_stiffness(problem);
        let (gap_offset, slip_offset) = row_offsets(problem, w);
        let m = problem.num_pairs();
        let frictional: Vec<bool> = (0..m).map(|k| problem.tangential[k] && problem.friction[k] > 0.0).collect();
        PenaltyLaw {
            problem,
            w,
            start,
            normal_penalty: parameters.normal * k_c,
            tangential_penalty: parameters.tangential * k_c,
            contact_stiffness: k_c,
            gap_offset,
            slip_offset,
            frictional,
        }
    }

    /// The full system's matrix values (pattern order of [`full_pattern`], starting from the
    /// `K_ff` values `stiffness`) and right-hand side of the equations of `state`.
    fn state_system(&self, stiffness: &[f64], state: &[PairState], load: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let p = self.problem;
        let (e_n, e_t) = (self.normal_penalty, self.tangential_penalty);
        let mut values = stiffness.to_vec();
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

    /// `(λ_k, θ_k)` at the pair rows `y` (`2m`: `B_N u`, then `B_T u`).
    fn trial(&self, y: &[f64], k: usize) -> (f64, f64) {
        let m = self.problem.num_pairs();
        let gap = self.gap_offset[k] + y[k];
        let lambda = self.normal_penalty * (-gap).max(0.0);
        if !self.frictional[k] {
            return (lambda, 0.0);
        }
        let ds = self.slip_offset[k] + y[m + k] - self.start.slip[k];
        (lambda, self.start.tangential_force[k] - self.tangential_penalty * ds)
    }

    /// The state the law selects at the pair rows `y`.
    fn state_of(&self, y: &[f64]) -> Vec<PairState> {
        (0..self.problem.num_pairs())
            .map(|k| {
                let (lambda, theta) = self.trial(y, k);
                PairState::from_trial(lambda, theta, self.problem.friction[k], self.frictional[k])
            })
            .collect()
    }

    /// `(λ, τ)` at the pair rows `y` in `state` (the state's linear law, which the fixed point
    /// makes the law's own).
    fn forces(&self, y: &[f64], state: &[PairState]) -> (Vec<f64>, Vec<f64>) {
        let m = self.problem.num_pairs();
        let (mut lambda, mut tau) = (vec![0.0; m], vec![0.0; m]);
        for k in 0..m {
            if state[k] == PairState::Free {
                continue;
            }
            let gap = self.gap_offset[k] + y[k];
            lambda[k] = -self.normal_penalty * gap;
            let (_, theta) = self.trial(y, k);
            tau[k] = match state[k] {
                _ if !self.frictional[k] => 0.0,
                PairState::Stick => theta,
                s => slip_sign(s) * self.problem.friction[k] * lambda[k],
            };
        }
        (lambda, tau)
    }

    /// `‖R‖∞ / F` of the residual `R = K u − w r − B_Nᵀλ − B_Tᵀτ`, with `F` the largest load or
    /// contact force.
    fn equilibrium_residual(&self, residual: &[f64], lambda: &[f64], tau: &[f64]) -> f64 {
        let p = self.problem;
        let scale = p
            .pattern_rhs
            .iter()
            .map(|r| (self.w * r).abs())
            .chain(lambda.iter().chain(tau).map(|v| v.abs()))
            .fold(0.0f64, f64::max)
            .max(f64::MIN_POSITIVE);
        residual.iter().fold(0.0f64, |a, v| a.max(v.abs())) / scale
    }
}

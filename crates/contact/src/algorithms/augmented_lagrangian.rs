//! Contact with Coulomb friction by the augmented Lagrangian of Alart & Curnier, solved by a
//! semi-smooth Newton method: on the full (not condensed) system as GetFEM and Kratos do (the
//! sparse path), or with `u` eliminated exactly by the condensed interface (`Condensed` below,
//! crate::algorithms::pair_space): the same iterates to round-off.
//!
//! ```text
//! unknowns x = (u_f, λ, τ)                          (n + 2m; forces on the master node)
//! F_u = K u − w r − B_Nᵀ λ − B_Tᵀ τ          = 0      (equilibrium, free DOFs)
//! F_N = λ − max(0, σ),          σ = λ − c gap          (gap = ĝ + B_N u)
//! F_T = τ − proj_[−μσ⁺, μσ⁺](θ), θ = τ − c Δs          (Δs = ŝ + B_T u − s_start; F_T = τ without
//!                                                     a tangential unknown or μ = 0)
//! state of pair k:  σ ≤ 0: free;  |θ| ≤ μσ: stick;  θ > 0: slip− (τ = +μσ);  θ < 0: slip+
//! generalized Jacobian rows (the Newton system of the state; full system: one sparse LU):
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
//! On the full system the matrix has the sparsity of `K` plus the pair rows: it costs a sparse
//! factorisation per iteration instead of the condensed interface's dense `m × m` work, so it
//! wins for long interfaces (docs/benchmarks.md, "Augmented Lagrangian against the condensed
//! active set"), and the sparse path (`solver.linear = "sparse"`, or `"auto"` from 2,000 pairs)
//! takes it. On the condensed interface every iterate is `u = K⁻¹(a w r + B_Nᵀλ + B_Tᵀτ)`, so
//! `F_u = (a − 1) w r` and the Newton system is the loaded forces' rows of the compliances (a
//! dense LU; docs/benchmarks.md, "Penalty and augmented Lagrangian condensed").
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
use crate::algorithms::pair_space::{PairSpace, dense_solve, slip_sign};
use crate::interface::Interface;
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
/// at most `max_iterations` Newton iterations, each on the full system (one sparse LU).
pub fn solve_augmented_lagrangian(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_iterations: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let equations = Equations::new(problem, w, start);
    let (n, m) = (problem.system.dofs.num_free(), problem.num_pairs());
    let (pattern, stiffness) = full_pattern(&equations);
    let Some(lu) = FixedPatternLu::new(n + 2 * m, &pattern) else {
        let x = vec![0.0; n + 2 * m];
        let solution = finish(problem, w, start, &x[..n], &x[n..], ContactStatus::Numerical, 0, clock);
        return solution;
    };
    let mut system = FullSystem { equations: &equations, lu, stiffness };
    iterate(&equations, &mut system, guess, max_iterations, clock)
}

/// [`solve_augmented_lagrangian`] with each Newton system condensed onto the pairs' rows of
/// `interface` (the problem's condensed interface at its current load;
/// `algorithms/pair_space.rs`): the same iterates to round-off, a dense LU of the
/// loaded rows per iteration instead of a sparse LU of the whole system.
pub fn solve_augmented_lagrangian_condensed(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_iterations: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let equations = Equations::new(problem, w, start);
    let mut system = Condensed { equations: &equations, space: PairSpace::new(problem, interface) };
    iterate(&equations, &mut system, guess, max_iterations, clock)
}

/// A way to solve the Newton systems: an iterate `x = (head, λ, τ)` (the head fixes `u`), its
/// pair rows `y = (B_N u, B_T u)` (free parts, `2m`), its equilibrium residual and displacement.
trait NewtonSolver {
    /// The length of the head of `x` (before `λ`).
    fn head(&self) -> usize;
    /// The pair rows of `u = K⁻¹ w r` (the load without contact forces).
    fn load_rows(&self) -> Vec<f64>;
    /// The Newton point `x̂` of `state` (`None`: singular).
    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>>;
    /// The pair rows `y` of `x`.
    fn rows(&self, x: &[f64]) -> Vec<f64>;
    /// `‖F_u(x)‖²`, `F_u = K u − w r − B_Nᵀ λ − B_Tᵀ τ`.
    fn equilibrium_squared(&self, x: &[f64]) -> f64;
    /// The free displacements of `x`.
    fn displacement(&self, x: &[f64]) -> Vec<f64>;
}

/// The full system: `x = (u, λ, τ)`, each Newton system one numeric sparse LU.
struct FullSystem<'a> {
    equations: &'a Equations<'a>,
    lu: FixedPatternLu,
    stiffness: Vec<f64>,
}

impl NewtonSolver for FullSystem<'_> {
    fn head(&self) -> usize {
        self.equations.n
    }

    fn load_rows(&self) -> Vec<f64> {
        let p = self.equations.problem;
        let rhs: Vec<f64> = p.pattern_rhs.iter().map(|r| self.equations.w * r).collect();
        self.rows(&p.stiffness_factor().solve_or_nan(&rhs))
    }

    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>> {
        let (values, rhs) = self.equations.newton_system(&self.stiffness, state);
        self.lu.factor(&values).then(|| self.lu.solve(&rhs)).flatten()
    }

    fn rows(&self, x: &[f64]) -> Vec<f64> {
        let p = self.equations.problem;
        let u = &x[..self.equations.n];
        p.normal_rows.iter().chain(&p.tangent_rows).map(|r| dot_free(r, u)).collect()
    }

    fn equilibrium_squared(&self, x: &[f64]) -> f64 {
        let (e, n) = (self.equations, self.equations.n);
        let (p, m) = (e.problem, e.problem.num_pairs());
        let mut f = stiffness_times(p, &x[..n]);
        f.iter_mut().zip(&p.pattern_rhs).for_each(|(v, r)| *v -= e.w * r);
        for k in 0..m {
            for &(i, v) in &p.normal_rows[k].free {
                f[i] -= v * x[n + k];
            }
            if e.frictional[k] {
                for &(i, v) in &p.tangent_rows[k].free {
                    f[i] -= v * x[n + m + k];
                }
            }
        }
        f.iter().map(|v| v * v).sum()
    }

    fn displacement(&self, x: &[f64]) -> Vec<f64> {
        x[..self.equations.n].to_vec()
    }
}

/// The condensed system (`algorithms/pair_space.rs`): `x = (a, λ, τ)`,
/// `u = K⁻¹(a w r + B_Nᵀ λ + B_Tᵀ τ)` (the full system's iterates have this form: its Newton
/// point solves `K û = w r + Bᵀ(λ̂, τ̂)`, and the convex combinations keep it), so
/// `F_u = (a − 1) w r` and the Newton system is the pairs' rows of the state:
///
/// ```text
/// in contact:  c (C (λ, τ))_N,k = −c (ĝ_k + w y0_N,k)                  (gap = 0)
/// stick:       c (C (λ, τ))_T,k =  c (s_start,k − ŝ_k − w y0_T,k)       (Δs = 0)
/// slip±:       τ_k ∓ μ λ_k = 0                                          (with gap = 0)
/// free:        λ_k = τ_k = 0;  no friction: τ_k = 0
/// ```
///
/// a dense LU of the unknown forces (`a = 1` at the Newton point).
struct Condensed<'a> {
    equations: &'a Equations<'a>,
    space: PairSpace<'a>,
}

impl NewtonSolver for Condensed<'_> {
    fn head(&self) -> usize {
        1
    }

    fn load_rows(&self) -> Vec<f64> {
        self.space.rows(self.equations.w, &[])
    }

    fn target(&mut self, state: &[PairState]) -> Option<Vec<f64>> {
        let e = self.equations;
        let (m, c) = (e.problem.num_pairs(), e.c);
        let mut system = self.space.loaded_forces(state, &e.frictional, &e.problem.friction, c)?;
        let load = self.space.rows(e.w, &[]);
        let mut rhs = vec![0.0; system.unknowns.len()];
        for (a, &i) in system.unknowns.iter().enumerate() {
            if system.is_slip_row(a, state) {
                continue;
            }
            let k = i % m;
            rhs[a] = if i < m {
                -c * (e.gap_offset[k] + load[i])
            } else {
                c * (e.start.slip[k] - e.slip_offset[k] - load[i])
            };
        }
        let forces = dense_solve(std::mem::take(&mut system.matrix), rhs)?;
        Some(system.target(m, forces))
    }

    fn rows(&self, x: &[f64]) -> Vec<f64> {
        self.space.rows(x[0] * self.equations.w, &x[1..])
    }

    fn equilibrium_squared(&self, x: &[f64]) -> f64 {
        let scale = (x[0] - 1.0) * self.equations.w;
        self.equations.problem.pattern_rhs.iter().map(|r| (scale * r) * (scale * r)).sum()
    }

    fn displacement(&self, x: &[f64]) -> Vec<f64> {
        self.space.displacement(x[0] * self.equations.w, &x[1..])
    }
}

/// The semi-smooth Newton iteration of the module docs with the Newton systems of `solver`.
fn iterate(
    equations: &Equations,
    solver: &mut impl NewtonSolver,
    guess: Option<&[PairState]>,
    max_iterations: usize,
    clock: Instant,
) -> ContactSolution {
    let (problem, w, start) = (equations.problem, equations.w, equations.start);
    let (head, m) = (solver.head(), problem.num_pairs());
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => {
            let y = solver.load_rows();
            (0..m)
                .map(|k| if equations.gap_offset[k] + y[k] < 0.0 { PairState::Stick } else { PairState::Free })
                .collect()
        }
    };
    let mut x = vec![0.0; head + 2 * m];
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let mut merit = equations.merit(solver, &x);
    for it in 1..=max_iterations {
        iterations = it;
        let Some(target) = solver.target(&state) else {
            status = ContactStatus::Numerical;
            break;
        };
        let full_merit = equations.merit(solver, &target);
        let (alpha, next_x, next_merit) = backtrack(&x, target, merit, full_merit, |t| equations.merit(solver, t));
        (x, merit) = (next_x, next_merit);
        let next = equations.state_of(&solver.rows(&x), &x[head..]);
        let residual = (2.0 * merit).sqrt() / equations.force_scale(&x[head..]);
        trace.push(IterationRecord::of_states(it, &state, &next, residual));
        if settled(alpha, next == state, residual) {
            status = ContactStatus::Converged;
            break;
        }
        state = next;
    }
    let mut solution = finish(problem, w, start, &solver.displacement(&x), &x[head..], status, iterations, clock);
    solution.trace = trace;
    solution
}

/// The solution of the free displacements `u` and the forces `(λ, τ)` (`2m`).
#[allow(clippy::too_many_arguments)]
fn finish(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    u: &[f64],
    forces: &[f64],
    status: ContactStatus,
    iterations: usize,
    clock: Instant,
) -> ContactSolution {
    let m = problem.num_pairs();
    let raw = RawSolution {
        load_factor: w,
        normal_force: forces[..m].to_vec(),
        tangential_force: forces[m..].to_vec(),
        status,
        iterations,
        time: clock.elapsed(),
    };
    finish_from_displacement(problem, u, raw, start)
}

/// The fixed pattern of the full system's Jacobian and the `K_ff` values at its start: `K_ff`
/// entries (both triangles) first, then the pair blocks; see `newton_system`.
fn full_pattern(equations: &Equations) -> (Vec<(usize, usize)>, Vec<f64>) {
    let (problem, n) = (equations.problem, equations.n);
    let m = problem.num_pairs();
    let entries = stiffness_entries(problem);
    let mut pattern: Vec<(usize, usize)> = entries.iter().map(|&(i, j, _)| (i, j)).collect();
    for (k, &with_friction) in equations.frictional.iter().enumerate() {
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
    (pattern, entries.into_iter().map(|(_, _, v)| v).collect())
}

/// The Alart–Curnier equations of one step.
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
}

impl<'a> Equations<'a> {
    fn new(problem: &'a ContactProblem, w: f64, start: &'a StepStart) -> Equations<'a> {
        let (n, m) = (problem.system.dofs.num_free(), problem.num_pairs());
        let (gap_offset, slip_offset) = row_offsets(problem, w);
        let frictional: Vec<bool> = (0..m).map(|k| problem.tangential[k] && problem.friction[k] > 0.0).collect();
        Equations { problem, n, w, start, c: contact_stiffness(problem), gap_offset, slip_offset, frictional }
    }

    /// The values (in the pattern order of [`full_pattern`], starting from the `K_ff` values
    /// `stiffness`) and right-hand side of the full system's Newton system of `state`.
    fn newton_system(&self, stiffness: &[f64], state: &[PairState]) -> (Vec<f64>, Vec<f64>) {
        let (p, n, c) = (self.problem, self.n, self.c);
        let m = p.num_pairs();
        let mut values = stiffness.to_vec();
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
            let slip_sign = slip_sign(state[k]);
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

    /// `(σ, θ)` of pair k at the pair rows `y` and forces `forces = (λ, τ)` (θ = 0 without
    /// friction).
    fn multipliers(&self, y: &[f64], forces: &[f64], k: usize) -> (f64, f64) {
        let m = self.problem.num_pairs();
        let gap = self.gap_offset[k] + y[k];
        let sigma = forces[k] - self.c * gap;
        if !self.frictional[k] {
            return (sigma, 0.0);
        }
        let ds = self.slip_offset[k] + y[m + k] - self.start.slip[k];
        (sigma, forces[m + k] - self.c * ds)
    }

    /// The state each pair's complementarity functions select at the pair rows `y` and forces
    /// `forces`.
    fn state_of(&self, y: &[f64], forces: &[f64]) -> Vec<PairState> {
        (0..self.problem.num_pairs())
            .map(|k| {
                let (sigma, theta) = self.multipliers(y, forces, k);
                PairState::from_trial(sigma, theta, self.problem.friction[k], self.frictional[k])
            })
            .collect()
    }

    /// `Φ(x) = ½ ‖F(x)‖²` of the module docs.
    fn merit(&self, solver: &impl NewtonSolver, x: &[f64]) -> f64 {
        let (p, m) = (self.problem, self.problem.num_pairs());
        let (y, forces) = (solver.rows(x), &x[solver.head()..]);
        let mut sum = solver.equilibrium_squared(x);
        for k in 0..m {
            let (sigma, theta) = self.multipliers(&y, forces, k);
            let normal = forces[k] - sigma.max(0.0);
            let bound = p.friction[k] * sigma.max(0.0);
            let tangential =
                if self.frictional[k] { forces[m + k] - theta.clamp(-bound, bound) } else { forces[m + k] };
            sum += normal * normal + tangential * tangential;
        }
        0.5 * sum
    }

    /// The largest load or contact force (`forces = (λ, τ)`; the residual's scale in the trace).
    fn force_scale(&self, forces: &[f64]) -> f64 {
        let load = self.problem.pattern_rhs.iter().fold(0.0f64, |a, r| a.max((self.w * r).abs()));
        forces.iter().fold(load, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE)
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

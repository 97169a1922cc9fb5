//! Bodies held only by contact: their rigid motions as unknowns of each step.
//!
//! Assembly pins every floating piece at as many DOFs as it has free rigid modes (springs `D`
//! of the stiffness of its mean diagonal, [`contact2d_fem::LinearSystem::stabilisation`]). With
//! the pins anchored at a rigid motion `R α` of the pieces, a step is an ordinary contact solve
//!
//! ```text
//! (K + D) u = f + Bᵀλ + D R α        (K R = 0, so u − R α is the pinned piece's deformation)
//! ```
//!
//! and the pins' forces `s(α) = D (u − R α)` (at the pinned DOFs) measure how far the answer is
//! from equilibrium: `K u = f + Bᵀλ − s`, so `Rᵀ(f + Bᵀλ) = Rᵀ s` is the load the contact does
//! not balance. The step is solved when `s(α) = 0` (Farhat and Roux's floating subdomains, the
//! rigid modes as unknowns). `s` is piecewise linear in `α`, so a Newton iteration on `α` with
//! a finite-difference Jacobian `J = ∂s/∂α` ends in a few steps:
//!
//! ```text
//! range of J:      α ← α − J⁺ s                      (backtracked on ‖s‖₁; where no halving
//!                  lowers it, again from J with each column the stiffer of its two one-sided
//!                  differences: the engaged piece at a pair that has just landed)
//! null space of J: the pieces move freely there (no contact engages): the unbalanced modal
//!                  force F = Rᵀ s, projected on the null space, gives the direction d of travel,
//!                  and the landing α ← α + t d with t = min_i gap_i / (−B_N R d)_i over the
//!                  open pairs (λ_i = 0) closes the first of them exactly; no pair ahead → the
//!                  body is not held (an error)
//! ```
//!
//! Any load lands in one step, however small, whatever the mesh; at zero load a body stays
//! where it was (`α` carries over from the previous step), never an error.
//!
//! Landing is not slip: a pair that is open at the step's start has no stick anchor, so its
//! reference for the slip increment is where the rigid travel brings it,
//! `s_ref = s_start + B_T R (α_landing − α_start)`: the travel across a clearance does no friction
//! work and the friction law does not see it.
//!
//! # References
//! C. Farhat, F.-X. Roux (1991), A method of finite element tearing and interconnecting and its
//! parallel solution algorithm, IJNME 32, 1205–1227 (the generalised inverse of a floating
//! subdomain and its rigid modes); Z. Dostál et al. (2006), Total FETI, Comm. Numer. Meth. Eng.
//! 22, 1155–1162.

use nalgebra::{DMatrix, DVector};

use crate::error::ContactError;
use crate::holding::{PairColumns, friction_demand};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, ContactStatus, PairState, StepStart};

/// The free rigid modes of the floating pieces and their pins.
#[derive(Debug, Clone)]
pub(crate) struct RigidModes {
    /// One free-DOF vector per mode, in the order of the pieces and their modes.
    columns: Vec<Vec<f64>>,
    /// `(piece, mode)` of each column.
    owners: Vec<(usize, usize)>,
    /// `(free index, k)` of the pins (as many as modes).
    pins: Vec<(usize, f64)>,
}

impl RigidModes {
    /// The modes of `problem`'s floating pieces, as free-DOF vectors.
    pub(crate) fn of(problem: &ContactProblem) -> RigidModes {
        let dofs = &problem.system.dofs;
        let n = dofs.num_free();
        let mut columns = vec![];
        let mut owners = vec![];
        for (p, piece) in problem.system.floating.iter().enumerate() {
            for m in 0..piece.free_modes.len() {
                let mut column = vec![0.0; n];
                for &node in &piece.nodes {
                    let r = piece.mode_displacement(m, problem.model.mesh.points[node]);
                    let r = dofs.frame(node).map_or(r, |f| f.to_local(r));
                    for (c, value) in r.into_iter().enumerate() {
                        if let contact2d_fem::DofKind::Free(i) = dofs.kind(contact2d_fem::Dof(2 * node + c)) {
                            column[i] = value;
                        }
                    }
                }
                columns.push(column);
                owners.push((p, m));
            }
        }
        RigidModes { columns, owners, pins: problem.system.stabilisation.clone() }
    }

    /// Number of modes (the unknowns `α`).
    pub(crate) fn len(&self) -> usize {
        self.columns.len()
    }

    /// Whether the problem has no floating piece.
    pub(crate) fn is_empty(&self) -> bool {
        self.columns.is_empty() || self.pins.len() != self.columns.len()
    }

    /// `R α` over the free DOFs.
    pub(crate) fn displacement(&self, alpha: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.columns.first().map_or(0, Vec::len)];
        for (column, a) in self.columns.iter().zip(alpha) {
            if *a != 0.0 {
                out.iter_mut().zip(column).for_each(|(o, c)| *o += a * c);
            }
        }
        out
    }

    /// The pins' anchor load `D R α` (free DOFs).
    fn anchor_load(&self, alpha: &[f64]) -> Vec<f64> {
        let rigid = self.displacement(alpha);
        let mut out = vec![0.0; rigid.len()];
        for &(i, k) in &self.pins {
            out[i] = k * rigid[i];
        }
        out
    }

    /// The pins' forces `s = D (u − R α)` at the pinned DOFs.
    fn pin_forces(&self, u_free: &[f64], alpha: &[f64]) -> Vec<f64> {
        self.pins
            .iter()
            .map(|&(i, k)| {
                let rigid: f64 = self.columns.iter().zip(alpha).map(|(c, a)| a * c[i]).sum();
                k * (u_free[i] - rigid)
            })
            .collect()
    }

    /// The modal load `Rᵀ f` of a free-DOF load `f`.
    pub(crate) fn modal_load(&self, load: &[f64]) -> Vec<f64> {
        self.columns.iter().map(|c| c.iter().zip(load).map(|(a, b)| a * b).sum()).collect()
    }

    /// The modal force `Rᵀ s` of the pins' forces.
    fn modal_force(&self, s: &[f64]) -> Vec<f64> {
        self.columns.iter().map(|c| self.pins.iter().zip(s).map(|(&(i, _), f)| c[i] * f).sum()).collect()
    }

    /// The largest pin stiffness (the scale of `J`).
    fn stiffness(&self) -> f64 {
        self.pins.iter().fold(0.0f64, |a, p| a.max(p.1))
    }
}

/// What one step of a floating problem needs besides the problem: the step's load factors, its
/// start, the previous step's pair states, and the step number (for errors).
pub(crate) struct FloatingStep<'a> {
    /// Pattern factors of the step.
    pub factors: &'a [f64],
    /// Pattern factors of the previous step (zeros before the first).
    pub previous_factors: &'a [f64],
    /// The state the step starts from.
    pub start: &'a StepStart,
    /// The previous step's pair states (`None` before the first step).
    pub guess: Option<&'a [PairState]>,
    /// The step number, from 1.
    pub step: usize,
    /// Newton iterations allowed.
    pub max_iterations: usize,
    /// Relative tolerance on the pins' forces.
    pub tolerance: f64,
    /// Whether the warm starts for long interfaces are on (`stick_continuation.rs`): the final
    /// leg's `α` predicted from the landing leg's, and the inner solves after a Newton step or a
    /// landing started with the stick continuation from their guess.
    pub predict: bool,
}

/// A step whose load a body held only by contact cannot take ([`ContactStatus::NotHeld`]): the
/// pairs' forces cannot balance the load in the pieces' rigid modes at any state of the contact
/// (the statics of `holding.rs`), so the load friction has to carry exceeds what it can:
///
/// ```text
/// ratio     = k_min: the least k with λ ≥ 0, |τ_i| ≤ k μ_i λ_i, Rᵀ(f + B_Nᵀλ + B_Tᵀτ) = 0
/// available = Σ_i μ_i λ_i at that distribution of the normal forces
/// demanded  = ratio · available
/// ```
///
/// For a block pressed by N on a flat base and pushed sideways by F: `ratio = F / (μ N)`,
/// `available = μ N`, `demanded = F`. Where the programme does not decide but the iteration
/// found a free rigid motion `d` that the closed pairs only slide along, the estimate of that
/// state is kept: `demanded = |dᵀRᵀ(f + B_Nᵀλ)|`, `available = Σ μ_i λ_i |(B_T R d)_i|` (the
/// pins still hold part of the load there: a few per cent off).
#[derive(Debug, Clone, PartialEq)]
pub struct NotHeld {
    /// The body that slides away.
    pub body: String,
    /// The load step (from 1).
    pub step: usize,
    /// The closed pairs (λ > 0) that the motion slides along: they name the contact.
    pub pairs: Vec<usize>,
    /// The tangential load demanded along the motion.
    pub demanded: f64,
    /// The friction force available along the motion.
    pub available: f64,
}

impl NotHeld {
    /// `demanded / available` (infinite where no friction is available).
    pub fn ratio(&self) -> f64 {
        if self.available > 0.0 { self.demanded / self.available } else { f64::INFINITY }
    }
}

/// The answer of a floating step: the solution, the Newton iterations, the pins' force left.
pub(crate) struct FloatingAnswer {
    pub solution: ContactSolution,
    pub iterations: usize,
    pub residual: f64,
    /// `α` after the last rigid travel of the leg (its start without one): from there on the
    /// pieces moved with the contact's deformation only.
    pub engaged_from: Vec<f64>,
    /// Set when the step's load is not held ([`ContactStatus::NotHeld`]).
    pub not_held: Option<NotHeld>,
}

/// The contact solve of one step at given `α`, `start` and warm-start `guess`; the flag says
/// whether the guess may be far from the answer (the pins moved by a Newton step or a landing
/// since the guess was solved; `StartingStates::Far` of `stick_continuation.rs`).
pub(crate) type StepSolver<'s> =
    dyn Fn(&ContactProblem, &Interface, &StepStart, Option<&[PairState]>, bool) -> ContactSolution + 's;

/// Solves one step with the floating pieces' rigid motions `α` as unknowns (module docs);
/// `alpha` enters as the previous step's and leaves as this step's.
///
/// A piece that is free during the step lands first. Along the step the load is
/// `f(θ) = f_start + θ (f_end − f_start)`; where the pieces' modal load `Rᵀ f(θ)` vanishes inside
/// the step (a load that reverses), the step is solved to that `θ*` first, and a step that
/// starts with no pair in contact starts free (`θ* = 0`). From `θ*` a sub-step at
/// `LANDING_FRACTION` of the rest of the increment carries the pieces across their clearances (in
/// a quasi-static model any load, however small, does), and the step ends from where they
/// landed. The step's dissipation is the sum over these legs.
///
/// # Errors
/// A piece that no contact holds along the direction its load pushes it
/// ([`ContactError::BodyNotHeld`]), or load factors the problem rejects.
pub(crate) fn solve_floating_step(
    loaded: &mut ContactProblem,
    interface: &mut Interface,
    modes: &RigidModes,
    step: &FloatingStep,
    alpha: &mut Vec<f64>,
    solve: &StepSolver,
) -> Result<FloatingAnswer, ContactError> {
    let clock = web_time::Instant::now();
    let along = |theta: f64| -> Vec<f64> {
        step.previous_factors.iter().zip(step.factors).map(|(f0, f1)| f0 + theta * (f1 - f0)).collect()
    };
    let free_at_start = step.guess.is_none_or(|states| states.iter().all(|s| *s == PairState::Free));
    let moves = step.factors.iter().zip(step.previous_factors).any(|(a, b)| a != b);
    let release = match release_fraction(loaded, modes, step)? {
        Some(theta) => Some(theta),
        None if free_at_start && moves => Some(0.0),
        None => None,
    };
    // (θ, factors) of the legs.
    let mut legs = vec![];
    if let Some(theta) = release {
        if theta > 0.0 {
            legs.push((theta, along(theta)));
        }
        let landing = theta + LANDING_FRACTION * (1.0 - theta);
        legs.push((landing, along(landing)));
    }
    legs.push((1.0, step.factors.to_vec()));
    let (mut start, mut guess) = (step.start.clone(), step.guess.map(<[PairState]>::to_vec));
    let (mut dissipation, mut inner, mut outer) = (0.0, 0, 0);
    let mut trace = vec![];
    let mut friction_slip = vec![0.0; step.start.slip.len()];
    let mut last = None;
    for (i, (theta, leg)) in legs.iter().enumerate() {
        let answer = balance_pins(loaded, interface, modes, step, leg, &start, guess.as_deref(), alpha, solve)?;
        // After the landing leg (from `θ*` to `θ_L`), the final leg's `α` is predicted by
        // proportion: α ← α + (α − α_engaged)(1 − θ_L) / (θ_L − θ*), the motion the contact's
        // deformation gave the pieces over the landing leg, extended to the step's end (exact
        // where the answer is proportional to the load, as a press from closed gaps is). The
        // Newton iteration corrects the rest.
        if step.predict
            && let Some(released) = release
            && i + 2 == legs.len()
            && *theta > released
        {
            let scale = (1.0 - theta) / (theta - released);
            alpha.iter_mut().zip(&answer.engaged_from).for_each(|(a, e)| *a += (*a - e) * scale);
        }
        dissipation += answer.solution.dissipation;
        friction_slip.iter_mut().zip(&answer.solution.slip_increment).for_each(|(a, d)| *a += d);
        let done = inner;
        trace.extend(
            answer.solution.trace.iter().map(|r| crate::IterationRecord { iteration: done + r.iteration, ..*r }),
        );
        inner += answer.solution.iterations;
        outer += answer.iterations;
        let solved = answer.solution.status.is_solved();
        start = StepStart::after(&answer.solution);
        guess = Some(answer.solution.state.clone());
        last = Some(answer);
        if !solved {
            break;
        }
    }
    let Some(mut answer) = last else {
        return Err(ContactError::InvalidInput("a floating step without a leg".into()));
    };
    // A step that did not end on a load no state of the contact holds ends `not_held`, by the
    // statics of the pieces (`holding.rs`): near the threshold the free motion may not show
    // before the iteration limit. Where the iteration found the free motion itself, the statics
    // give the exact demand (its own is measured in a state the pins still hold).
    if matches!(answer.solution.status, ContactStatus::MaxIterations | ContactStatus::NotHeld)
        && let Some(report) = not_held_by_statics(loaded, modes, step, alpha)?
    {
        answer.solution.status = ContactStatus::NotHeld;
        answer.not_held = Some(report);
    }
    answer.solution.dissipation = dissipation;
    // The step's slip increment is the friction slip of its legs (landing travel excluded).
    answer.solution.slip_increment = friction_slip;
    answer.solution.iterations = inner;
    answer.solution.trace = trace;
    answer.iterations = outer;
    answer.solution.time = clock.elapsed();
    Ok(answer)
}

/// The `θ*` strictly inside the step where the floating pieces' modal load `Rᵀ f(θ)` vanishes
/// (to 1e-12 of its larger end value), if any: `Rᵀ f(θ)` is linear in `θ`, so `θ*` minimises
/// `‖a + θ b‖` with `a = Rᵀ f_start`, `b = Rᵀ (f_end − f_start)`.
fn release_fraction(
    loaded: &mut ContactProblem,
    modes: &RigidModes,
    step: &FloatingStep,
) -> Result<Option<f64>, ContactError> {
    loaded.apply_load(step.previous_factors, None)?;
    let a = modes.modal_load(&loaded.pattern_rhs);
    loaded.apply_load(step.factors, None)?;
    let c = modes.modal_load(&loaded.pattern_rhs);
    let b: Vec<f64> = c.iter().zip(&a).map(|(c, a)| c - a).collect();
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
    let bb = dot(&b, &b);
    if bb == 0.0 {
        return Ok(None);
    }
    let theta = -dot(&a, &b) / bb;
    if !(theta > 0.0 && theta < 1.0) {
        return Ok(None);
    }
    let at: Vec<f64> = a.iter().zip(&b).map(|(a, b)| a + theta * b).collect();
    let scale = dot(&a, &a).sqrt().max(dot(&c, &c).sqrt());
    Ok((dot(&at, &at).sqrt() <= 1e-12 * scale).then_some(theta))
}

/// The pins' force, relative to the step's force scale, above which a Newton step on `α` is
/// taken to move the stick–slip fronts far (`balance_pins`). Measured on the floating pad
/// (docs/benchmarks.md, "Floating bodies on long interfaces"): the Newton steps start at
/// 0.15–0.18 and end at 1e-5–1e-4.
const FAR_IMBALANCE: f64 = 1e-3;

/// The fraction of a step's load increment at which a piece free at the step's start lands.
const LANDING_FRACTION: f64 = 1e-3;

/// Halvings of the Newton step on the engaged piece's Jacobian (`balance_pins`), down to
/// 2⁻²⁰ ≈ 1e-6 of the step.
const ENGAGED_HALVINGS: usize = 20;

/// The Newton iteration of the module docs at pattern factors `factors`: `α` such that the pins
/// carry no force, from `start`. The pairs open at `start` measure their slip from where the
/// rigid travel of each landing brings them: `s_ref = s_start + B_T R (α_landing − α_start)`.
#[allow(clippy::too_many_arguments)]
fn balance_pins(
    loaded: &mut ContactProblem,
    interface: &mut Interface,
    modes: &RigidModes,
    step: &FloatingStep,
    factors: &[f64],
    step_start: &StepStart,
    step_guess: Option<&[PairState]>,
    alpha: &mut Vec<f64>,
    solve: &StepSolver,
) -> Result<FloatingAnswer, ContactError> {
    loaded.apply_load(factors, None)?;
    let load_scale = loaded.pattern_rhs.iter().fold(0.0f64, |a, r| a.max(r.abs()));
    let alpha_start = alpha.clone();
    let open_at_start: Vec<bool> = match step_guess {
        Some(states) => states.iter().map(|s| *s == PairState::Free).collect(),
        None => vec![true; loaded.num_pairs()],
    };
    let mut start = step_start.clone();
    let inner_iterations = std::cell::Cell::new(0);
    // Every inner solve's iterations, numbered on: the step's log is all of them.
    let trace = std::cell::RefCell::new(Vec::<crate::IterationRecord>::new());
    let evaluate = |loaded: &mut ContactProblem,
                    interface: &mut Interface,
                    alpha: &[f64],
                    start: &StepStart,
                    guess: Option<&[PairState]>,
                    far: bool|
     -> Result<(ContactSolution, Vec<f64>), ContactError> {
        loaded.apply_load(factors, Some(&modes.anchor_load(alpha)))?;
        interface.update_load(loaded);
        let solution = solve(loaded, interface, start, guess, far && step.predict);
        let done = inner_iterations.get();
        trace
            .borrow_mut()
            .extend(solution.trace.iter().map(|r| crate::IterationRecord { iteration: done + r.iteration, ..*r }));
        inner_iterations.set(done + solution.iterations);
        let u_free = loaded.system.dofs.restrict_free(&solution.displacement);
        let s = modes.pin_forces(&u_free, alpha);
        Ok((solution, s))
    };
    let (mut solution, mut s) = evaluate(loaded, interface, alpha, &start, step_guess, false)?;
    let mut iterations = 0;
    let size = length_scale(loaded);
    let mut engaged_from = alpha.clone();
    let finish = |mut solution: ContactSolution, iterations: usize, s: &[f64], engaged_from: Vec<f64>| {
        solution.iterations = inner_iterations.get();
        solution.trace = trace.take();
        FloatingAnswer { solution, iterations, residual: norm1(s), engaged_from, not_held: None }
    };
    loop {
        let scale = force_scale(load_scale, &solution);
        let residual = norm1(&s);
        // The pins' force of a displacement of 1e-16 of the model's size is round-off: the floor
        // of the tolerance where the load and the contact forces vanish (an unloaded step).
        let allowed = (step.tolerance * scale).max(1e-16 * modes.stiffness() * size);
        if !residual.is_finite() || !solution.status.is_solved() || residual <= allowed {
            return Ok(finish(solution, iterations, &s, engaged_from));
        }
        if iterations >= step.max_iterations {
            solution.status = ContactStatus::MaxIterations;
            return Ok(finish(solution, iterations, &s, engaged_from));
        }
        iterations += 1;
        let guess = solution.state.clone();
        // J = ∂s/∂α by forward differences (s is piecewise linear: exact away from a kink). The
        // step moves the pins' forces by 1e-6 of the force scale: small against the answer's
        // kinks (pairs changing state), large against the solve's round-off.
        let h = (1e-6 * scale / modes.stiffness().max(f64::MIN_POSITIVE)).max(1e-12 * size);
        // Each difference is taken the way the unbalanced modal force pushes the pieces: the
        // one-sided derivative that matters at a pair that has just landed (gap 0, no force).
        let force = modes.modal_force(&s);
        let mut jacobian = DMatrix::<f64>::zeros(s.len(), modes.len());
        let mut sides = vec![];
        for j in 0..modes.len() {
            let hj = if force[j] < 0.0 { -h } else { h };
            let mut shifted = alpha.clone();
            shifted[j] += hj;
            let (_, sj) = evaluate(loaded, interface, &shifted, &start, Some(&guess), false)?;
            for (i, (a, b)) in sj.iter().zip(&s).enumerate() {
                jacobian[(i, j)] = (a - b) / hj;
            }
            sides.push(hj);
        }
        let svd = jacobian.clone().svd(true, true);
        let (Some(u), Some(v_t)) = (svd.u.as_ref(), svd.v_t.as_ref()) else {
            solution.status = ContactStatus::Numerical;
            return Ok(finish(solution, iterations, &s, engaged_from));
        };
        let engaged = |sigma: f64| sigma > 1e-8 * modes.stiffness();
        // The modal force in the null space of J: where the pieces move freely.
        let force = DVector::from_vec(force);
        let mut travel = DVector::<f64>::zeros(modes.len());
        for (k, sigma) in svd.singular_values.iter().enumerate() {
            if !engaged(*sigma) {
                let v = v_t.row(k).transpose();
                travel += &v * v.dot(&force);
            }
        }
        let direction = travel.normalize();
        let landing =
            (travel.norm() > allowed).then(|| landing_distance(loaded, modes, &solution, direction.as_slice()));
        // An open pair touching ahead (t = 0) is no travel: J did not see it closing (its
        // one-sided differences went the other way), and Newton's engaged Jacobian below does.
        if travel.norm() > allowed && landing != Some(Some(0.0)) {
            if let Some(Some(t)) = landing {
                let t = t * (1.0 + 1e-6);
                alpha.iter_mut().zip(direction.iter()).for_each(|(a, d)| *a += t * d);
                anchor_open_pairs(loaded, modes, &open_at_start, step_start, &alpha_start, alpha, &mut start);
                engaged_from.clone_from(alpha);
                (solution, s) = evaluate(loaded, interface, alpha, &start, Some(&guess), true)?;
                continue;
            }
            // No pair lies ahead: a body that no closed pair touches flies away (an error: the
            // model lacks a support); one pressed on its contact slides away (a status).
            let report = sliding_away(loaded, modes, &solution, direction.as_slice(), alpha, step.step)
                .ok_or_else(|| not_held(loaded, modes, direction.as_slice(), step.step))?;
            solution.status = ContactStatus::NotHeld;
            let mut answer = finish(solution, iterations, &s, engaged_from);
            answer.not_held = Some(report);
            return Ok(answer);
        }
        // Newton on the engaged modes, backtracked on ‖s‖₁. Pins that carry more than
        // `FAR_IMBALANCE` of the force scale hold the pieces far from where the contact would:
        // the states of the step's end may differ from the guess's along whole stick–slip
        // fronts, and the inner solve starts with the stick continuation.
        let far = residual > FAR_IMBALANCE * scale;
        let mut delta = DVector::<f64>::zeros(modes.len());
        let s_vec = DVector::from_column_slice(&s);
        for (k, sigma) in svd.singular_values.iter().enumerate() {
            if engaged(*sigma) {
                delta -= v_t.row(k).transpose() * (u.column(k).dot(&s_vec) / sigma);
            }
        }
        let mut fraction = 1.0;
        let mut best: Option<(Vec<f64>, ContactSolution, Vec<f64>)> = None;
        let mut improved = false;
        for _ in 0..8 {
            let trial: Vec<f64> = alpha.iter().zip(delta.iter()).map(|(a, d)| a + fraction * d).collect();
            let (trial_solution, trial_s) = evaluate(loaded, interface, &trial, &start, Some(&guess), far)?;
            improved = norm1(&trial_s) < residual;
            if best.is_none() || improved {
                best = Some((trial, trial_solution, trial_s));
            }
            if improved {
                break;
            }
            fraction *= 0.5;
        }
        // A Newton direction that no step along lowers ‖s‖₁ was taken on a Jacobian whose
        // one-sided differences straddle a kink: a pair that has just landed (gap 0, no force)
        // seen closed in one column and open in another, so that J mixes two linear pieces of
        // `s` and is near singular along the landing (measured: a block on its corner pair after
        // landing on the next one, a Newton step of 2.4 of the model's size along the landing
        // direction, every backtracked step worse). The engaged piece's Jacobian instead: each
        // column the stiffer of the two one-sided differences (a pair closing on one side adds
        // its stiffness there), and Newton again from it, backtracked further.
        if !improved && residual > 1e-8 * scale {
            let mut stiffer = jacobian.clone();
            for (j, hj) in sides.iter().enumerate() {
                let mut shifted = alpha.clone();
                shifted[j] -= hj;
                let (_, sj) = evaluate(loaded, interface, &shifted, &start, Some(&guess), false)?;
                let other: Vec<f64> = sj.iter().zip(&s).map(|(a, b)| (a - b) / -hj).collect();
                let norm = |c: &[f64]| c.iter().map(|v| v * v).sum::<f64>();
                let current: Vec<f64> = stiffer.column(j).iter().copied().collect();
                if norm(&other) > norm(&current) {
                    other.iter().enumerate().for_each(|(i, v)| stiffer[(i, j)] = *v);
                }
            }
            let svd = stiffer.svd(true, true);
            if let (Some(u), Some(v_t)) = (svd.u.as_ref(), svd.v_t.as_ref()) {
                let mut delta = DVector::<f64>::zeros(modes.len());
                for (k, sigma) in svd.singular_values.iter().enumerate() {
                    if engaged(*sigma) {
                        delta -= v_t.row(k).transpose() * (u.column(k).dot(&s_vec) / sigma);
                    }
                }
                let mut fraction = 1.0;
                for _ in 0..ENGAGED_HALVINGS {
                    let trial: Vec<f64> = alpha.iter().zip(delta.iter()).map(|(a, d)| a + fraction * d).collect();
                    let (trial_solution, trial_s) = evaluate(loaded, interface, &trial, &start, Some(&guess), far)?;
                    if norm1(&trial_s) < residual {
                        improved = true;
                        best = Some((trial, trial_solution, trial_s));
                        break;
                    }
                    fraction *= 0.5;
                }
            }
        }
        // No step of Newton's direction lowers a residual already at 1e-8 of the force scale:
        // it is the solve's round-off (a condensed solve is accurate to about 1e-12 of the
        // displacements, and the pins' forces are k times them), and the answer stands.
        if !improved && residual <= 1e-8 * scale {
            return Ok(finish(solution, iterations, &s, engaged_from));
        }
        if let Some((next_alpha, next_solution, next_s)) = best {
            *alpha = next_alpha;
            (solution, s) = (next_solution, next_s);
        }
    }
}

fn norm1(s: &[f64]) -> f64 {
    s.iter().map(|v| v.abs()).sum()
}

/// The force scale of a step: the largest of the load's nodal forces and the contact forces.
fn force_scale(load_scale: f64, solution: &ContactSolution) -> f64 {
    solution
        .normal_force
        .iter()
        .chain(&solution.tangential_force)
        .fold(load_scale, |a, l| a.max(l.abs()))
        .max(f64::MIN_POSITIVE)
}

/// The size of the model (the largest coordinate extent), the unit of `α`'s differences.
fn length_scale(problem: &ContactProblem) -> f64 {
    let points = &problem.model.mesh.points;
    let extent = |c: usize| {
        let (lo, hi) =
            points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p[c]), hi.max(p[c])));
        (hi - lo).max(0.0)
    };
    extent(0).max(extent(1)).max(f64::MIN_POSITIVE)
}

/// How far the pieces travel rigidly along `direction` (in `α`) until the first open pair
/// closes: `min gap_i / c_i` over the open pairs (no normal force) that close,
/// `c_i = −B_N,i R d`; `None` when no pair lies ahead. A closed pair is not ahead: `d` lies in
/// the null space of `J`, which its stiffness is in, so its closing rate is round-off (measured
/// 7e-9 on a gap of −3e-17 for a block turning about its corner pair), and taking it would end
/// the travel at `t = 0` over and over.
fn landing_distance(
    problem: &ContactProblem,
    modes: &RigidModes,
    solution: &ContactSolution,
    direction: &[f64],
) -> Option<f64> {
    let rigid = modes.displacement(direction);
    let zeros = vec![0.0; problem.system.dofs.num_constrained()];
    let scale = rigid.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let mut best: Option<f64> = None;
    for ((row, gap), lambda) in problem.normal_rows.iter().zip(&solution.gap).zip(&solution.normal_force) {
        let closing = -row.dot(&rigid, &zeros);
        // A row that does not see the travel (to round-off of the unit motion) cannot stop it.
        if *lambda == 0.0 && closing > 1e-9 * scale {
            let t = gap.max(0.0) / closing;
            best = Some(best.map_or(t, |b: f64| b.min(t)));
        }
    }
    best
}

/// The slip references of the pairs open at the step's start moved along with the rigid travel
/// from `alpha_start` to `alpha` (landing is not slip).
fn anchor_open_pairs(
    problem: &ContactProblem,
    modes: &RigidModes,
    open_at_start: &[bool],
    original: &StepStart,
    alpha_start: &[f64],
    alpha: &[f64],
    start: &mut StepStart,
) {
    let travel: Vec<f64> = alpha.iter().zip(alpha_start).map(|(a, b)| a - b).collect();
    let rigid = modes.displacement(&travel);
    let zeros = vec![0.0; problem.system.dofs.num_constrained()];
    for (k, row) in problem.tangent_rows.iter().enumerate() {
        if open_at_start.get(k).copied().unwrap_or(false) {
            start.slip[k] = original.slip[k] + row.dot(&rigid, &zeros);
        }
    }
}

/// The [`NotHeld`] report of pieces that travel freely along `direction` (unit, in `α`) while
/// pressed on closed pairs the travel slides along; `None` where no closed pair sees the
/// travel (nothing holds the pieces at all), or where an initial gap exceeds the model's size.
fn sliding_away(
    problem: &ContactProblem,
    modes: &RigidModes,
    solution: &ContactSolution,
    direction: &[f64],
    alpha: &[f64],
    step: usize,
) -> Option<NotHeld> {
    // An initial gap or interference beyond the model's size is no load that friction fails to
    // hold: small-strain contact cannot land across it, and the error says so.
    let largest_gap = problem.gap.iter().fold(0.0f64, |a, g| a.max(g.abs()));
    if largest_gap > length_scale(problem) {
        return None;
    }
    let rigid = modes.displacement(direction);
    let zeros = vec![0.0; problem.system.dofs.num_constrained()];
    let scale = rigid.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    // The load without the pins' anchor: `r − D R α`.
    let anchor = modes.anchor_load(alpha);
    let load: Vec<f64> = problem.pattern_rhs.iter().zip(&anchor).map(|(r, a)| r - a).collect();
    let mut demanded: f64 = modes.modal_load(&load).iter().zip(direction).map(|(m, d)| m * d).sum();
    let (mut available, mut pairs) = (0.0, vec![]);
    for (k, (normal, tangent)) in problem.normal_rows.iter().zip(&problem.tangent_rows).enumerate() {
        let lambda = solution.normal_force.get(k).copied().unwrap_or(0.0);
        if lambda <= 0.0 {
            continue;
        }
        demanded += lambda * normal.dot(&rigid, &zeros);
        // A row that does not see the travel (to round-off of the unit motion) is not slid along.
        let along = tangent.dot(&rigid, &zeros);
        if problem.tangential.get(k).copied().unwrap_or(false) && along.abs() > 1e-9 * scale {
            available += problem.friction.get(k).copied().unwrap_or(0.0) * lambda * along.abs();
            pairs.push(k);
        }
    }
    if pairs.is_empty() {
        return None;
    }
    let body = moving_body(problem, modes, direction)?;
    Some(NotHeld { body, step, pairs, demanded: demanded.abs(), available })
}

/// The [`NotHeld`] report of a step whose load the pairs cannot balance in the pieces' rigid
/// modes at any state of the contact ([`crate::holding::friction_demand`]), `None` where they can.
/// Leaves `loaded` with the step's load and the pins' anchor at `alpha`, as the iteration does.
fn not_held_by_statics(
    loaded: &mut ContactProblem,
    modes: &RigidModes,
    step: &FloatingStep,
    alpha: &[f64],
) -> Result<Option<NotHeld>, ContactError> {
    loaded.apply_load(step.factors, None)?;
    let load = modes.modal_load(&loaded.pattern_rhs);
    loaded.apply_load(step.factors, Some(&modes.anchor_load(alpha)))?;
    let zeros = vec![0.0; loaded.system.dofs.num_constrained()];
    let unit =
        |j: usize| modes.displacement(&(0..modes.len()).map(|i| f64::from(u8::from(i == j))).collect::<Vec<_>>());
    let columns: Vec<Vec<f64>> = (0..modes.len()).map(unit).collect();
    let pairs: Vec<PairColumns> = (loaded.normal_rows.iter().zip(&loaded.tangent_rows).enumerate())
        .map(|(k, (normal, tangent))| {
            let frictional = loaded.tangential.get(k).copied().unwrap_or(false);
            PairColumns {
                normal: columns.iter().map(|c| normal.dot(c, &zeros)).collect(),
                tangent: columns.iter().map(|c| if frictional { tangent.dot(c, &zeros) } else { 0.0 }).collect(),
                friction: if frictional { loaded.friction.get(k).copied().unwrap_or(0.0) } else { 0.0 },
            }
        })
        .collect();
    let Some(demand) = friction_demand(&load, &pairs) else {
        return Ok(None);
    };
    let Some(body) = moving_body(loaded, modes, &demand.direction) else {
        return Ok(None);
    };
    let demanded = demand.ratio * demand.available;
    Ok(Some(NotHeld { body, step: step.step, pairs: demand.pairs, demanded, available: demand.available }))
}

/// The name of the body that moves most along `direction`.
fn moving_body(problem: &ContactProblem, modes: &RigidModes, direction: &[f64]) -> Option<String> {
    let (worst, _) = direction.iter().enumerate().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()).then(b.0.cmp(&a.0)))?;
    let piece = problem.system.floating.get(modes.owners.get(worst)?.0)?;
    Some(piece.body.clone())
}

/// The error for the piece that moves most along `direction`, naming its modes that move.
fn not_held(problem: &ContactProblem, modes: &RigidModes, direction: &[f64], step: usize) -> ContactError {
    let largest = direction.iter().fold(0.0f64, |a, d| a.max(d.abs()));
    let Some((worst, _)) =
        direction.iter().enumerate().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()).then(b.0.cmp(&a.0)))
    else {
        return ContactError::InvalidInput("a floating step without a floating body".into());
    };
    let piece_index = modes.owners[worst].0;
    let piece = &problem.system.floating[piece_index];
    let names = piece.mode_names();
    let moving: Vec<String> = modes
        .owners
        .iter()
        .zip(direction)
        .filter(|((p, _), d)| *p == piece_index && d.abs() >= 1e-3 * largest)
        .map(|((_, m), _)| names[*m].clone())
        .collect();
    let largest_gap = problem.gap.iter().copied().fold(0.0f64, |a, g| if g.abs() > a.abs() { g } else { a });
    ContactError::BodyNotHeld {
        body: piece.body.clone(),
        modes: moving,
        step,
        largest_gap,
        model_size: length_scale(problem),
    }
}

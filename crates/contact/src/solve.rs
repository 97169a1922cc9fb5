//! One entry point for solving: `solve(&problem, &settings, &schedule) -> History`.
//!
//! ```text
//! for each step i of the schedule (factors F_i of the load patterns):
//!     load_i = Σ_p F_i[p] pattern_p
//!     solve the step from StepStart(s_{i−1}, τ_{i−1}) with the chosen algorithm
//!     Φ_f += dissipation_i
//! ```
//!
//! Shortcut: without any initial gap and with proportional loading that only grows
//! (`F_i = t_i d`, `0 < t_1 < t_2 < ...`), the solution is linear in `t` (the zones form at the
//! first instant and never change: spec §5.2, for friction too), so it is solved once at `d` and
//! scaled: `u_i = t_i u(d)`, `Φ_f,i = t_i² Φ_f(d)`. This is exact, not an approximation.
//!
//! Floating bodies (held only by contact): assembly pins each floating piece at as many DOFs as
//! it has free rigid modes, and each step finds the pieces' rigid motions `α` that leave the
//! pins without force (`crates/contact/src/floating.rs`): exact equilibrium `K u = f + Bᵀλ`, any load lands
//! in one step, zero load leaves a body where it was, and a body that no contact holds along the
//! direction its load pushes it ends the run: with status [`ContactStatus::NotHeld`] where it is
//! pressed on closed pairs that all slip along the motion (friction cannot carry the load:
//! [`crate::NotHeld`] gives the demanded and available friction forces), and with the error
//! [`ContactError::BodyNotHeld`] naming the body and its free rigid motions where no closed pair
//! touches it at all (a support is missing from the model: nothing can be solved).

use crate::algorithms::augmented_lagrangian::{solve_augmented_lagrangian, solve_augmented_lagrangian_condensed};
use crate::algorithms::boussinesq::{BoussinesqLoading, solve_boussinesq_step};
use crate::algorithms::clarabel_tresca::solve_frictional_qp_from;
use crate::algorithms::frictional_active_set::solve_frictional_active_set_from;
use crate::algorithms::penalty::{PenaltyParameters, solve_penalty, solve_penalty_condensed};
use crate::algorithms::stick_continuation::{StartingStates, StickContinuation, applies};
use crate::error::ContactError;
use crate::floating::{FloatingStep, NotHeld, RigidModes, solve_floating_step as solve_floating_step_with};
use crate::history::{HistoryStep, Retention, march_keeping};
use crate::interface::Interface;
use crate::linear::LinearSolver;
use crate::loading::LoadSchedule;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_displacement};
use crate::solution::{ContactSolution, ContactStatus, PairState, StepStart};

pub use crate::algorithm::ContactAlgorithm;

/// The largest iteration limit per step: every iteration of the condensed algorithms factors a
/// dense matrix of the pairs, so the bound keeps a run's time finite and known up front.
pub const MAX_ITERATIONS: usize = 10_000;

/// Validated solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    algorithm: ContactAlgorithm,
    max_iterations: usize,
    floating_tolerance: f64,
    max_floating_iterations: usize,
    penalty: PenaltyParameters,
    deadline: Option<web_time::Instant>,
    linear: LinearSolver,
    stick_continuation: StickContinuation,
}

impl SolverSettings {
    /// The defaults for `algorithm`: 100 iterations, floating tolerance 1e-10, 60 proximal
    /// iterations.
    pub fn new(algorithm: ContactAlgorithm) -> SolverSettings {
        SolverSettings {
            algorithm,
            max_iterations: 100,
            floating_tolerance: 1e-10,
            max_floating_iterations: 60,
            penalty: PenaltyParameters::default(),
            deadline: None,
            linear: LinearSolver::Auto,
            stick_continuation: StickContinuation::Auto,
        }
    }

    /// Sets how the contact states' linear equations are solved ([`LinearSolver`]; default
    /// [`LinearSolver::Auto`]).
    ///
    /// # Errors
    /// [`LinearSolver::Sparse`] with an algorithm that works on the compliances (Clarabel, the
    /// Boussinesq algorithm).
    pub fn with_linear(mut self, linear: LinearSolver) -> Result<SolverSettings, ContactError> {
        linear.resolve(self.algorithm, 0)?;
        self.linear = linear;
        Ok(self)
    }

    /// How the contact states' linear equations are solved.
    pub fn linear(&self) -> LinearSolver {
        self.linear
    }

    /// Sets whether the frictional active set follows a regularised stick law to the exact one
    /// ([`StickContinuation`]; default [`StickContinuation::Auto`]). The other algorithms
    /// ignore it: it changes where the active set starts, not the law it solves.
    pub fn with_stick_continuation(mut self, continuation: StickContinuation) -> SolverSettings {
        self.stick_continuation = continuation;
        self
    }

    /// The active set's [`StickContinuation`].
    pub fn stick_continuation(&self) -> StickContinuation {
        self.stick_continuation
    }

    /// Sets a wall-clock deadline: [`solve_with`] checks it before each load step and stops with
    /// [`ContactError::DeadlineExceeded`] once it has passed (a step under way is not
    /// interrupted). No deadline by default.
    pub fn with_deadline(mut self, deadline: web_time::Instant) -> SolverSettings {
        self.deadline = Some(deadline);
        self
    }

    /// The deadline of [`SolverSettings::with_deadline`], if any.
    pub fn deadline(&self) -> Option<web_time::Instant> {
        self.deadline
    }

    /// Sets the iteration limit of the algorithm per step.
    ///
    /// # Errors
    /// Zero, or more than [`MAX_ITERATIONS`].
    pub fn with_max_iterations(mut self, max_iterations: usize) -> Result<SolverSettings, ContactError> {
        if !(1..=MAX_ITERATIONS).contains(&max_iterations) {
            return Err(ContactError::InvalidInput(format!(
                "max_iterations = {max_iterations} must lie in 1 ..= {MAX_ITERATIONS}"
            )));
        }
        self.max_iterations = max_iterations;
        Ok(self)
    }

    /// Sets the relative equilibrium tolerance of floating bodies' proximal iteration.
    ///
    /// # Errors
    /// Outside `[1e-15, 1e-3]`.
    pub fn with_floating_tolerance(mut self, tolerance: f64) -> Result<SolverSettings, ContactError> {
        if !(1e-15..=1e-3).contains(&tolerance) {
            return Err(ContactError::InvalidInput(format!(
                "floating tolerance {tolerance} must lie in [1e-15, 1e-3]"
            )));
        }
        self.floating_tolerance = tolerance;
        Ok(self)
    }

    /// Sets the relative penalties `κ_N`, `κ_T` of [`ContactAlgorithm::Penalty`] (the penalties
    /// are `κ k_c`, [`crate::algorithms::full_system::contact_stiffness`]).
    ///
    /// # Errors
    /// A relative penalty outside `[1e-3, 1e15]` (or not finite).
    pub fn with_penalty(mut self, normal: f64, tangential: f64) -> Result<SolverSettings, ContactError> {
        for (name, value) in [("normal", normal), ("tangential", tangential)] {
            if !(1e-3..=1e15).contains(&value) {
                return Err(ContactError::InvalidInput(format!(
                    "{name} relative penalty {value} must lie in [1e-3, 1e15]"
                )));
            }
        }
        self.penalty = PenaltyParameters { normal, tangential };
        Ok(self)
    }

    /// The relative penalties of [`ContactAlgorithm::Penalty`].
    pub fn penalty(&self) -> PenaltyParameters {
        self.penalty
    }

    /// The algorithm.
    pub fn algorithm(&self) -> ContactAlgorithm {
        self.algorithm
    }

    /// The iteration limit per step.
    pub fn max_iterations(&self) -> usize {
        self.max_iterations
    }

    /// The floating bodies' proximal iteration limit per step.
    pub fn max_floating_iterations(&self) -> usize {
        self.max_floating_iterations
    }

    /// The floating bodies' relative equilibrium tolerance.
    pub fn floating_tolerance(&self) -> f64 {
        self.floating_tolerance
    }
}

/// One solved step of a schedule.
#[derive(Debug, Clone, PartialEq)]
pub struct SolvedStep {
    /// The factors of the problem's load patterns (in [`ContactProblem::patterns`] order).
    pub factors: Vec<f64>,
    /// The solution (its `load_factor` is 1: the load is the factors' combination; with floating
    /// bodies its iterations and time are summed over the proximal iterations).
    pub solution: ContactSolution,
    /// Φ_f accumulated up to and including this step.
    pub dissipated: f64,
    /// Proximal iterations of floating bodies (0 without floating bodies).
    pub floating_iterations: usize,
    /// The force the stabilising springs still carry, `‖D (u_{j+1} − u_j)‖₁` (0 without floating
    /// bodies): the equilibrium error of the answer.
    pub floating_residual: f64,
    /// Finite sliding: how many times the pairs were formed again on the step's answer and the
    /// step solved again ([`crate::finite_sliding`]; 0 for a step whose first pairing was
    /// stable, and for every step of small sliding).
    pub repairings: usize,
    /// Finite sliding: why the step ended at [`crate::finite_sliding::MAX_REPAIRINGS`] with a
    /// pairing still changing (its status is then [`ContactStatus::MaxIterations`]); `None`
    /// otherwise.
    pub unstable_pairing: Option<String>,
    /// What a step with status [`ContactStatus::NotHeld`] could not hold (`None` otherwise).
    pub not_held: Option<NotHeld>,
}

/// One step's answer: the solution, the floating bodies' iterations, the force their pins still
/// carry, and the load not held.
pub(crate) struct StepOutcome {
    pub solution: ContactSolution,
    pub iterations: usize,
    pub residual: f64,
    pub not_held: Option<NotHeld>,
}

/// A solved schedule.
#[derive(Debug, Clone, PartialEq)]
pub struct History {
    /// The steps in order; the history stops after the first step that does not converge. Only
    /// the last one after [`solve_keeping`] with [`Retention::Last`].
    pub steps: Vec<SolvedStep>,
    /// Whether the schedule was solved once and scaled (no gap, proportional growing loads).
    pub scaled: bool,
    /// Wall time of the condensation onto the interface.
    pub condense_time: std::time::Duration,
}

/// The floating bodies' proximal iteration of one step: iterations, residual, the load not held.
type FloatingRecord = (usize, f64, Option<Box<NotHeld>>);

/// Solves `schedule` on `problem` with `settings` (see the module docs).
///
/// # Errors
/// A schedule naming a pattern the problem does not have, unloading with the Boussinesq
/// algorithm, or a floating body that its contact does not hold.
pub fn solve(
    problem: &ContactProblem,
    settings: &SolverSettings,
    schedule: &LoadSchedule,
) -> Result<History, ContactError> {
    solve_with(problem, settings, schedule, &mut |_, _| {})
}

/// [`solve`], calling `on_step(i, step)` after each solved step (progress reporting).
///
/// # Errors
/// As [`solve`], and [`ContactError::DeadlineExceeded`] when the settings' deadline passes.
pub fn solve_with(
    problem: &ContactProblem,
    settings: &SolverSettings,
    schedule: &LoadSchedule,
    on_step: &mut dyn FnMut(usize, &SolvedStep),
) -> Result<History, ContactError> {
    solve_keeping(problem, settings, schedule, Retention::All, on_step)
}

/// [`solve_with`], the history keeping the steps `retention` asks for: with
/// [`Retention::Last`] every step is given to `on_step` as it is solved and only the last stays
/// in [`History::steps`], so that memory stays flat in the number of steps (a caller that
/// streams each step's results).
///
/// # Errors
/// As [`solve_with`].
pub fn solve_keeping(
    problem: &ContactProblem,
    settings: &SolverSettings,
    schedule: &LoadSchedule,
    retention: Retention,
    on_step: &mut dyn FnMut(usize, &SolvedStep),
) -> Result<History, ContactError> {
    let names: Vec<&str> = problem.patterns().iter().map(|p| p.name.as_str()).collect();
    // The steps' factors in the problem's pattern order: the schedule's own where it names the
    // patterns in that order, else one copy (issue 44 item 7: each copy is a vector a step, kept
    // for the whole run).
    let reordered: LoadSchedule;
    let steady = if schedule.patterns().iter().map(String::as_str).eq(names.iter().copied()) {
        schedule
    } else {
        let factors: Vec<Vec<f64>> =
            (0..schedule.steps().len()).map(|i| schedule.factors_for(i, &names)).collect::<Result<_, _>>()?;
        reordered = LoadSchedule::new(names.iter().map(|n| n.to_string()).collect(), factors)?;
        &reordered
    };
    if settings.algorithm == ContactAlgorithm::Boussinesq && steady.proportional().is_none() {
        return Err(not_boussinesq(
            "it needs proportional loads that only grow (its contact zone grows from one point); use the active \
             set or Clarabel for other schedules"
                .into(),
        ));
    }
    let mut loaded = problem.clone();
    let scaled = problem.is_gapless().then(|| steady.proportional()).flatten();
    let scaled_target: Vec<Vec<f64>>;
    let targets: &[Vec<f64>] = match &scaled {
        Some((direction, _)) => {
            scaled_target = vec![direction.clone()];
            &scaled_target
        }
        None => steady.steps(),
    };
    loaded.apply_load(&targets[0], None)?;
    let clock = web_time::Instant::now();
    let mut interface = match settings.linear.resolve(settings.algorithm, problem.num_pairs())? {
        LinearSolver::Sparse => Interface::sparse(&loaded),
        _ => Interface::new(&loaded),
    };
    let condense_time = clock.elapsed();
    let modes = RigidModes::of(problem);
    // Only the Boussinesq algorithm grows its zone along an order of the pairs.
    let order = if settings.algorithm == ContactAlgorithm::Boussinesq {
        let open: Vec<f64> = (0..loaded.num_pairs()).map(|k| loaded.gap[k] + interface.h_normal[k]).collect();
        let order = boussinesq_order(&loaded, &open);
        boussinesq_applies(&order, &open, &modes)?;
        order
    } else {
        vec![]
    };
    let mut alpha = vec![0.0; modes.len()];
    let zeros = vec![0.0; problem.patterns().len()];
    // (iterations, residual, load not held) of the floating bodies' proximal iteration, per step
    // (the rare load not held boxed: the record is kept for every step).
    let floating = std::cell::RefCell::new(Vec::with_capacity(targets.len()));
    let step_of = |i: usize, h: &HistoryStep| SolvedStep {
        factors: targets[i].clone(),
        solution: h.solution.clone(),
        dissipated: h.dissipated,
        floating_iterations: floating.borrow().get(i).map_or(0, |f: &FloatingRecord| f.0),
        floating_residual: floating.borrow().get(i).map_or(0.0, |f: &FloatingRecord| f.1),
        not_held: floating.borrow().get(i).and_then(|f: &FloatingRecord| f.2.as_deref().cloned()),
        repairings: 0,
        unstable_pairing: None,
    };
    let history = march_keeping(
        targets,
        problem.num_pairs(),
        retention,
        |target, start, guess| {
            let step = floating.borrow().len() + 1;
            if settings.deadline.is_some_and(|d| web_time::Instant::now() >= d) {
                return Err(ContactError::DeadlineExceeded { step, steps: targets.len() });
            }
            let context = StepContext { order: &order, start, guess, far_guess: false, step };
            let previous = if step >= 2 { &targets[step - 2] } else { &zeros };
            let factors = StepFactors { target, previous };
            let outcome =
                solve_floating_step(&mut loaded, &mut interface, settings, &factors, &context, &modes, &mut alpha)?;
            floating.borrow_mut().push((outcome.iterations, outcome.residual, outcome.not_held.map(Box::new)));
            Ok::<_, ContactError>(outcome.solution)
        },
        &mut |h| {
            if scaled.is_none() {
                let i = floating.borrow().len() - 1;
                on_step(i, &step_of(i, h));
            }
        },
    )?;
    // The index of the first step kept (all but the last dropped under `Retention::Last`).
    let first = floating.borrow().len() - history.len();
    let solved: Vec<SolvedStep> = history.iter().enumerate().map(|(i, h)| step_of(first + i, h)).collect();
    let is_scaled = scaled.is_some();
    let steps = match scaled {
        Some((_, multipliers)) => scale_steps(&solved, &multipliers, retention, on_step),
        None => solved,
    };
    Ok(History { steps, scaled: is_scaled, condense_time })
}

/// The one solution at the direction, scaled to every multiplier (each given to `on_step`, the
/// ones `retention` asks for kept).
fn scale_steps(
    solved: &[SolvedStep],
    multipliers: &[f64],
    retention: Retention,
    on_step: &mut dyn FnMut(usize, &SolvedStep),
) -> Vec<SolvedStep> {
    let Some(unit) = solved.first() else { return vec![] };
    let mut kept = vec![];
    for (i, &t) in multipliers.iter().enumerate() {
        let mut solution = unit.solution.clone();
        let before = if i == 0 { 0.0 } else { multipliers[i - 1] };
        scale_solution(&mut solution, t, before);
        // One solve did the work of every step: the counters report it once.
        if i > 0 {
            solution.iterations = 0;
            solution.time = std::time::Duration::ZERO;
            solution.trace.clear();
        }
        let step = SolvedStep {
            factors: unit.factors.iter().map(|f| f * t).collect(),
            dissipated: unit.dissipated * t * t,
            solution,
            floating_iterations: if i == 0 { unit.floating_iterations } else { 0 },
            floating_residual: unit.floating_residual * t,
            repairings: 0,
            unstable_pairing: None,
            not_held: unit.not_held.clone(),
        };
        on_step(i, &step);
        if retention == Retention::Last {
            kept.clear();
        }
        kept.push(step);
    }
    kept
}

/// Scales a solution of a problem that is linear in the load (no gap, proportional loading) to
/// `t`, the step having started at `t_before`: forces, displacements, gaps and slips linearly;
/// the slip increment as `(t − t_before)/t` of the slip; the step's dissipation as
/// `t² − t_before²` (the trapezoid rule of a linear path); the load factor stays 1 (the factors
/// carry the load).
pub fn scale_solution(s: &mut ContactSolution, t: f64, t_before: f64) {
    for v in s
        .displacement
        .iter_mut()
        .chain(&mut s.normal_force)
        .chain(&mut s.tangential_force)
        .chain(&mut s.gap)
        .chain(&mut s.slip)
    {
        *v *= t;
    }
    for (d, total) in s.slip_increment.iter_mut().zip(&s.slip) {
        *d = if t != 0.0 { total * (t - t_before) / t } else { 0.0 };
    }
    s.dissipation *= t * t - t_before * t_before;
    s.kkt.max_penetration *= t;
    s.kkt.max_complementarity *= t * t;
    s.kkt.max_tension *= t;
    s.kkt.max_cone_violation *= t;
    s.kkt.min_dissipation *= t * (t - t_before);
}

/// The pattern factors of a step and of the step before it.
struct StepFactors<'a> {
    target: &'a [f64],
    previous: &'a [f64],
}

/// What a step needs besides the load.
struct StepContext<'a> {
    order: &'a [usize],
    start: &'a StepStart,
    guess: Option<&'a [PairState]>,
    /// Whether `guess` may be far from the answer (a floating body's Newton step,
    /// `floating.rs`): the active set's stick continuation then runs from it.
    far_guess: bool,
    step: usize,
}

/// One step at `factors`; with floating bodies their rigid motions `alpha` are unknowns
/// (`floating.rs`). Returns the solution, the Newton iterations on `α`, the force the pins
/// still carry and the load not held.
fn solve_floating_step(
    loaded: &mut ContactProblem,
    interface: &mut Interface,
    settings: &SolverSettings,
    factors: &StepFactors,
    context: &StepContext,
    modes: &RigidModes,
    alpha: &mut Vec<f64>,
) -> Result<StepOutcome, ContactError> {
    if modes.is_empty() {
        loaded.apply_load(factors.target, None)?;
        interface.update_load_factors(loaded, factors.target);
        let solution = solve_step(loaded, interface, settings, context);
        return Ok(StepOutcome { solution, iterations: 0, residual: 0.0, not_held: None });
    }
    let step = FloatingStep {
        factors: factors.target,
        previous_factors: factors.previous,
        start: context.start,
        guess: context.guess,
        step: context.step,
        max_iterations: settings.max_floating_iterations,
        tolerance: settings.floating_tolerance,
        predict: settings.algorithm == ContactAlgorithm::ActiveSet && applies(loaded, settings.stick_continuation),
    };
    let solve = |problem: &ContactProblem,
                 interface: &Interface,
                 start: &StepStart,
                 guess: Option<&[PairState]>,
                 far_guess: bool| {
        let inner = StepContext { order: context.order, start, guess, far_guess, step: context.step };
        solve_step(problem, interface, settings, &inner)
    };
    let answer = solve_floating_step_with(loaded, interface, modes, &step, alpha, &solve)?;
    Ok(StepOutcome {
        solution: answer.solution,
        iterations: answer.iterations,
        residual: answer.residual,
        not_held: answer.not_held,
    })
}

/// One step of the chosen algorithm at the problem's current load (`w` = 1).
fn solve_step(
    problem: &ContactProblem,
    interface: &Interface,
    settings: &SolverSettings,
    context: &StepContext,
) -> ContactSolution {
    if problem.num_pairs() == 0 {
        // No contact pair: the bodies' linear problem, one solve with the factorisation.
        let clock = web_time::Instant::now();
        let u_free = interface.free_displacement(1.0, &[], &[]);
        let raw = RawSolution {
            load_factor: 1.0,
            normal_force: vec![],
            tangential_force: vec![],
            status: ContactStatus::Converged,
            iterations: 0,
            time: clock.elapsed(),
        };
        return finish_from_displacement(problem, &u_free, raw, context.start);
    }
    let max = settings.max_iterations;
    match settings.algorithm {
        ContactAlgorithm::ActiveSet => {
            let continuation = settings.stick_continuation;
            let starting = StartingStates::of(context.guess.is_some(), context.far_guess);
            let (start, guess) = (context.start, context.guess);
            solve_frictional_active_set_from(problem, interface, 1.0, start, guess, starting, max, continuation)
        }
        ContactAlgorithm::Clarabel => {
            solve_frictional_qp_from(problem, interface, 1.0, context.start, context.guess, max)
        }
        ContactAlgorithm::Boussinesq => {
            // The contact-end search moves one pair per iteration.
            let max = max.max(2 * context.order.len());
            solve_boussinesq_step(problem, interface, context.order, BoussinesqLoading::Load(1.0), context.start, max)
                .solution
        }
        // The sparse path's interface holds no compliances: each iteration on the full system.
        ContactAlgorithm::Penalty if interface.is_condensed() => {
            solve_penalty_condensed(problem, interface, 1.0, context.start, context.guess, settings.penalty, max)
        }
        ContactAlgorithm::Penalty => solve_penalty(problem, 1.0, context.start, context.guess, settings.penalty, max),
        ContactAlgorithm::AugmentedLagrangian if interface.is_condensed() => {
            solve_augmented_lagrangian_condensed(problem, interface, 1.0, context.start, context.guess, max)
        }
        ContactAlgorithm::AugmentedLagrangian => {
            solve_augmented_lagrangian(problem, 1.0, context.start, context.guess, max)
        }
    }
}

/// One step of `problem` (not yet loaded) at the pattern factors `target` (those of the step
/// before: `previous`) from `start` and the pair states `guess`: the step of [`solve_keeping`]
/// without its shortcut or history (finite sliding, [`crate::finite_sliding`], solves each step
/// on pairs of its own). `alpha` carries the floating bodies' rigid motions from step to step.
/// Returns the solution, the floating bodies' iterations, their residual force and the load
/// not held.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_step_from(
    problem: &ContactProblem,
    settings: &SolverSettings,
    target: &[f64],
    previous: &[f64],
    start: &StepStart,
    guess: Option<&[PairState]>,
    step: usize,
    alpha: &mut Vec<f64>,
) -> Result<StepOutcome, ContactError> {
    let mut loaded = problem.clone();
    loaded.apply_load(target, None)?;
    let mut interface = match settings.linear.resolve(settings.algorithm, problem.num_pairs())? {
        LinearSolver::Sparse => Interface::sparse(&loaded),
        _ => Interface::new(&loaded),
    };
    let modes = RigidModes::of(problem);
    alpha.resize(modes.len(), 0.0);
    let context = StepContext { order: &[], start, guess, far_guess: false, step };
    let factors = StepFactors { target, previous };
    solve_floating_step(&mut loaded, &mut interface, settings, &factors, &context, &modes, alpha)
}

/// Where a run of steps starts: the pattern factors, friction state and pair states the step
/// before ended with, the floating bodies' rigid motions, and the step's number in the whole
/// history (from 1).
pub(crate) struct RunStart<'a> {
    pub previous: &'a [f64],
    pub start: &'a StepStart,
    pub guess: Option<&'a [PairState]>,
    pub first_step: usize,
    pub total_steps: usize,
}

/// The steps to pattern factors `targets` on `problem`, each from the state the one before
/// ended in, the first from `run` (a stage of staged supports, [`crate::stages`]): the loop of
/// [`solve_keeping`] without its shortcut, `K` condensed once for the run. `on_step` is told
/// each solution with its floating bodies' iterations and residual; the run stops after the
/// first step that does not converge. Returns how many steps were solved.
///
/// # Errors
/// The Boussinesq algorithm (its zone grows from one point over a proportional schedule), a
/// passed deadline, and every error of a step.
pub(crate) fn solve_run_from(
    problem: &ContactProblem,
    settings: &SolverSettings,
    targets: &[Vec<f64>],
    run: &RunStart,
    on_step: &mut dyn FnMut(StepOutcome),
) -> Result<usize, ContactError> {
    if settings.algorithm == ContactAlgorithm::Boussinesq {
        return Err(not_boussinesq(
            "staged supports (from_step, until_step) change the problem between steps, and its zone grows from \
             one point over a proportional schedule; use the active set"
                .into(),
        ));
    }
    let Some(first) = targets.first() else { return Ok(0) };
    let mut loaded = problem.clone();
    loaded.apply_load(first, None)?;
    let mut interface = match settings.linear.resolve(settings.algorithm, problem.num_pairs())? {
        LinearSolver::Sparse => Interface::sparse(&loaded),
        _ => Interface::new(&loaded),
    };
    let modes = RigidModes::of(problem);
    let mut alpha = vec![0.0; modes.len()];
    let (mut previous, mut start, mut guess) = (run.previous.to_vec(), run.start.clone(), run.guess.map(<[_]>::to_vec));
    for (i, target) in targets.iter().enumerate() {
        let step = run.first_step + i;
        if settings.deadline.is_some_and(|d| web_time::Instant::now() >= d) {
            return Err(ContactError::DeadlineExceeded { step, steps: run.total_steps });
        }
        let context = StepContext { order: &[], start: &start, guess: guess.as_deref(), far_guess: false, step };
        let factors = StepFactors { target, previous: &previous };
        let outcome =
            solve_floating_step(&mut loaded, &mut interface, settings, &factors, &context, &modes, &mut alpha)?;
        let converged = outcome.solution.status.is_solved();
        start = StepStart::after(&outcome.solution);
        guess = Some(outcome.solution.state.clone());
        previous.clone_from(target);
        on_step(outcome);
        if !converged {
            return Ok(i + 1);
        }
    }
    Ok(targets.len())
}

/// The refusal of the Boussinesq algorithm for `reason`.
fn not_boussinesq(reason: String) -> ContactError {
    ContactError::NotApplicable { algorithm: ContactAlgorithm::Boussinesq.key(), reason }
}

/// Refuses, before solving, the problems the Boussinesq algorithm's one zone growing from an
/// end of the master curve cannot describe: a body held only by contact (it crosses its
/// clearance as a rigid body before any zone forms), and bodies that meet first inside the
/// master curve (a Hertz contact: the zone grows both ways from the middle). The meeting point
/// is where the gap under the first load without contact forces, `g + B_N u₀`, is least; an
/// interior least value below the starting end's by more than 1e-9 of the gaps' spread (round-off)
/// is inside.
/// `open` holds each pair's gap under the first load without contact forces.
fn boussinesq_applies(order: &[usize], open: &[f64], modes: &RigidModes) -> Result<(), ContactError> {
    if !modes.is_empty() {
        return Err(not_boussinesq(
            "a body is held only by contact, so it moves as a rigid body until its contact closes; use the \
             active set"
                .into(),
        ));
    }
    let loaded: Vec<f64> = order.iter().map(|&k| open[k]).collect();
    let (Some(&start), Some(&last)) = (loaded.first(), loaded.last()) else { return Ok(()) };
    let spread = loaded.iter().fold(0.0f64, |m, g| m.max((g - start).abs()));
    let (inside, least) = loaded.iter().enumerate().fold((0, start), |a, (i, &g)| if g < a.1 { (i, g) } else { a });
    if inside > 0 && inside + 1 < loaded.len() && least < start.min(last) - 1e-9 * spread {
        return Err(not_boussinesq(format!(
            "the bodies meet first inside the master curve (pair {} of {} along it), not at an end, so the \
             contact zone grows both ways; use the active set",
            inside + 1,
            loaded.len()
        )));
    }
    Ok(())
}

/// The pairs in the order the Boussinesq algorithm grows its zone on `problem` at its current
/// load (see `boussinesq_order` in the source: by arc length along the master curve, from the end
/// whose gap under the load without contact forces, `g + B_N u₀`, is smaller), for a caller
/// that solves the algorithm's steps itself (the placed zone ends of the facade).
///
/// # Errors
/// [`ContactError::NotApplicable`] where the algorithm does not apply, as [`solve_with`] refuses
/// it: a body held only by contact, or bodies that meet first inside the master curve.
pub fn boussinesq_zone_order(problem: &ContactProblem, interface: &Interface) -> Result<Vec<usize>, ContactError> {
    let open: Vec<f64> = (0..problem.num_pairs()).map(|k| problem.gap[k] + interface.h_normal[k]).collect();
    let order = boussinesq_order(problem, &open);
    boussinesq_applies(&order, &open, &RigidModes::of(problem))?;
    Ok(order)
}

/// The pairs in the order the Boussinesq algorithm grows its zone: by arc length along the
/// master curve, from the end where the bodies meet first — the end whose gap under the first
/// step's load without contact forces, `g + B_N u₀`, is smaller. (The initial gaps alone cannot
/// tell the ends of a neat fit apart: they are all zero, and only the load says which end
/// closes.) `open` holds each pair's `g + B_N u₀`.
fn boussinesq_order(problem: &ContactProblem, open: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..problem.num_pairs()).collect();
    order.sort_by(|a, b| {
        problem.pairs[*a].master_arc_length.total_cmp(&problem.pairs[*b].master_arc_length).then(a.cmp(b))
    });
    if let (Some(&first), Some(&last)) = (order.first(), order.last())
        && open[last] < open[first]
    {
        order.reverse();
    }
    order
}

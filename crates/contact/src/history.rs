//! Quasi-static loading histories: a sequence of load factors solved step by step, each step
//! starting from the slips and tangential forces the previous one ended with.
//!
//! ```text
//! for w_1, w_2, ...:  solve the step to w_i from StepStart(s_{i-1}, τ_{i-1});  Φ_f += dissipation_i
//! ```
//!
//! Decreasing loads (unloading) are allowed: the algorithms here do not assume a growing
//! contact zone.

use crate::algorithms::clarabel_tresca::solve_frictional_qp_on;
use crate::algorithms::frictional_active_set::solve_frictional_active_set;
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, PairState, StepStart};

/// An algorithm that solves one step of a history.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StepAlgorithm {
    /// The primal-dual active set on the condensed interface (frictional or not).
    ActiveSet,
    /// Clarabel: frictionless QP, or Tresca QPs to the Coulomb fixed point.
    Clarabel,
}

/// One solved step with the dissipation accumulated up to it.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryStep {
    /// The step's solution.
    pub solution: ContactSolution,
    /// Φ_f accumulated over the history up to and including this step.
    pub dissipated: f64,
}

/// Solves the loads in order from the virgin state. Stops early at the first step that does
/// not converge (its solution is the last entry, with its status).
pub fn solve_history(
    problem: &ContactProblem,
    interface: &Interface,
    algorithm: StepAlgorithm,
    loads: &[f64],
    max_iterations: usize,
) -> Vec<HistoryStep> {
    solve_history_with(problem, interface, algorithm, loads, max_iterations, &mut |_| {})
}

/// [`solve_history`], calling `on_step` after each solved step (progress reporting).
pub fn solve_history_with(
    problem: &ContactProblem,
    interface: &Interface,
    algorithm: StepAlgorithm,
    loads: &[f64],
    max_iterations: usize,
    on_step: &mut dyn FnMut(&HistoryStep),
) -> Vec<HistoryStep> {
    let solved = march::<f64, std::convert::Infallible>(
        loads,
        problem.num_pairs(),
        |&w, start, guess| {
            Ok(match algorithm {
                StepAlgorithm::ActiveSet => {
                    solve_frictional_active_set(problem, interface, w, start, guess, max_iterations)
                }
                StepAlgorithm::Clarabel => solve_frictional_qp_on(problem, interface, w, start, max_iterations),
            })
        },
        on_step,
    );
    match solved {
        Ok(steps) => steps,
        Err(never) => match never {},
    }
}

/// The loop every loading history shares (the active set's and Clarabel's here, the Boussinesq
/// algorithm's, and [`crate::solve()`]'s): each step solved by `solve_step(loading, start,
/// guess)` from the state the previous one ended in (`StepStart`: slips and tangential forces;
/// `guess`: its pair states), Φ_f accumulated, `on_step` told, and the loop stopped after the
/// first step that does not converge (which is returned last, with its status).
///
/// # Errors
/// The first error of `solve_step`.
pub fn march<L, E>(
    loadings: &[L],
    pairs: usize,
    solve_step: impl FnMut(&L, &StepStart, Option<&[PairState]>) -> Result<ContactSolution, E>,
    on_step: &mut dyn FnMut(&HistoryStep),
) -> Result<Vec<HistoryStep>, E> {
    march_keeping(loadings, pairs, Retention::All, solve_step, on_step)
}

/// Which solved steps a history keeps once `on_step` has seen them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Retention {
    /// Every step (memory grows with the number of steps).
    #[default]
    All,
    /// Only the last step: the others are seen by `on_step` alone, so that memory stays flat in
    /// the number of steps (a caller that streams each step's results as it is solved).
    Last,
}

/// [`march`], keeping the steps `retention` asks for (each one is given to `on_step` either
/// way; [`Retention::Last`] returns one step, the last solved, or none).
///
/// # Errors
/// The first error of `solve_step`.
pub fn march_keeping<L, E>(
    loadings: &[L],
    pairs: usize,
    retention: Retention,
    mut solve_step: impl FnMut(&L, &StepStart, Option<&[PairState]>) -> Result<ContactSolution, E>,
    on_step: &mut dyn FnMut(&HistoryStep),
) -> Result<Vec<HistoryStep>, E> {
    let mut start = StepStart::initial(pairs);
    let mut guess: Option<Vec<PairState>> = None;
    let mut dissipated = 0.0;
    let mut steps = Vec::with_capacity(match retention {
        Retention::All => loadings.len(),
        Retention::Last => 1,
    });
    for loading in loadings {
        let solution = solve_step(loading, &start, guess.as_deref())?;
        dissipated += solution.dissipation;
        start = StepStart::after(&solution);
        guess = Some(solution.state.clone());
        let converged = solution.status.is_solved();
        let step = HistoryStep { solution, dissipated };
        on_step(&step);
        if retention == Retention::Last {
            steps.clear();
        }
        steps.push(step);
        if !converged {
            break;
        }
    }
    Ok(steps)
}

/// `steps` equal increments from 0 to `w`.
pub fn equal_steps(w: f64, steps: usize) -> Vec<f64> {
    (1..=steps).map(|i| w * i as f64 / steps as f64).collect()
}

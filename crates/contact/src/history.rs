//! Quasi-static loading histories: a sequence of load factors solved step by step, each step
//! starting from the slips and tangential forces the previous one ended with.
//!
//! ```text
//! for w_1, w_2, ...:  solve the step to w_i from StepStart(s_{i-1}, τ_{i-1});  Φ_f += dissipation_i
//! ```
//!
//! Decreasing loads (unloading) are allowed: the algorithms here do not assume a growing
//! contact zone.

use crate::solution::{ContactSolution, PairState, StepStart};

/// One solved step with the dissipation accumulated up to it.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryStep {
    /// The step's solution.
    pub solution: ContactSolution,
    /// Φ_f accumulated over the history up to and including this step.
    pub dissipated: f64,
}

/// The loop every loading history shares (the Boussinesq algorithm's stepping in the contact
/// end, and [`crate::solve()`]'s for every algorithm): each step solved by `solve_step(loading,
/// start, guess)` from the state the previous one ended in (`StepStart`: slips and tangential
/// forces; `guess`: its pair states), Φ_f accumulated, `on_step` told, and the loop stopped after the
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

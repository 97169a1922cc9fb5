//! The state update and the round-off admissibility test both active-set paths share (the
//! condensed `frictional_active_set.rs` and the sparse `sparse_active_set.rs`): given one state's
//! forces, gaps and slips, which state comes next, and whether this one already holds.
//!
//! ```text
//! contact ⇔ λ − c_N gap > 0;   in contact, with θ = τ − c_T Δs,  Δs = s − s_start:
//!         stick ⇔ |θ| ≤ μ(λ − c_N gap);  else slip with τ = μλ sign θ
//! cycle:  a pair the update slips back the way it slipped two iterations before, after the
//!         last iteration reversed it (slip+ → slip− → slip+, or the other way), sticks instead
//! ```
//!
//! A slip reversal passes through stick. States where many pairs slip one way can flip all
//! together to the other way and back forever: the slip-driven update `θ = τ − c_T Δs`
//! overshoots where a whole interface slips, since `c_T` is scaled by one pair's compliance and
//! the interface moves as a whole (measured on a coarse level of `coarse_start.rs`: 922 of 1,001
//! pairs flipping at each of 38 iterations, pressed and slid with μ = 0.3; on a block held only
//! by contact, 996 of 1,001 pairs flipping while a few others changed, so that the whole state
//! never repeated). Only a pair's own cycle is broken so: applied at every reversal, the rule
//! itself cycled the plain iteration on the floating pad of `tests/stick_continuation.rs`. A
//! state that settles satisfies the same conditions either way.

use crate::problem::ContactProblem;
use crate::solution::{PairState, StepStart};

/// One state's solution on the interface: forces `λ`, `τ`, gaps and accumulated slips per pair.
pub(crate) struct Iterate<'a> {
    /// Normal forces `λ_k`.
    pub normal_force: &'a [f64],
    /// Tangential forces `τ_k`.
    pub tangential_force: &'a [f64],
    /// Gaps `gap_k` (with the initial gap).
    pub gap: &'a [f64],
    /// Accumulated tangential slips `s_k` (zero without friction).
    pub slip: &'a [f64],
}

/// The state the semi-smooth update picks from `iterate` (module docs), with the
/// complementarity constants `(c_N, c_T)`.
pub(crate) fn next_state(
    problem: &ContactProblem,
    iterate: &Iterate,
    start: &StepStart,
    (c_n, c_t): (f64, f64),
    frictional: bool,
) -> Vec<PairState> {
    let (lambda, tau) = (iterate.normal_force, iterate.tangential_force);
    (0..lambda.len())
        .map(|k| {
            let normal = lambda[k] - c_n * iterate.gap[k];
            if normal <= 0.0 || !problem.normal[k] {
                return PairState::Free;
            }
            let mu = problem.friction[k];
            if !frictional || !problem.tangential[k] || mu == 0.0 {
                return PairState::Stick;
            }
            let theta = tau[k] - c_t * (iterate.slip[k] - start.slip[k]);
            PairState::from_trial(normal, theta, mu, true)
        })
        .collect()
}

/// Breaks the pairs' two-iteration cycles (module docs): every pair that `next` slips back the
/// way it slipped in `before` (the state before `state`), `state` having reversed it, sticks in
/// `next` instead.
pub(crate) fn stick_reversals(before: &[PairState], state: &[PairState], next: &mut [PairState]) {
    for ((b, s), n) in before.iter().zip(state).zip(next.iter_mut()) {
        if *n == *b
            && matches!(
                (s, *n),
                (PairState::SlipPositive, PairState::SlipNegative) | (PairState::SlipNegative, PairState::SlipPositive)
            )
        {
            *n = PairState::Stick;
        }
    }
}

/// Whether `iterate`, the solution of `state`, satisfies all contact and friction conditions to
/// round-off (1e-10 of the force and length scales): a degenerate pair — λ = gap = 0 or
/// |τ| = μλ with Δs = 0 — may otherwise flip between two states forever on round-off.
pub(crate) fn admissible(problem: &ContactProblem, state: &[PairState], iterate: &Iterate, start: &StepStart) -> bool {
    let (lambda, tau, gap) = (iterate.normal_force, iterate.tangential_force, iterate.gap);
    let force = lambda.iter().chain(tau).fold(0.0f64, |a, v| a.max(v.abs())).max(f64::MIN_POSITIVE);
    // The length scale is the motion (gap − g0), not the gaps: a clearance of 1e12 must not make
    // a penetration of 0.4 look like round-off.
    let length = gap.iter().zip(&problem.gap).fold(0.0f64, |a, (v, g0)| a.max((v - g0).abs())).max(f64::MIN_POSITIVE);
    let (tf, tg) = (1e-10 * force, 1e-10 * length);
    // A pair without a normal unknown takes no part in the conditions (its gap is the fixes'
    // or, on a coarse level, `coarse_start.rs`, left free).
    (0..lambda.len()).filter(|&k| problem.normal[k]).all(|k| {
        let ds = iterate.slip[k] - start.slip[k];
        let mu_lambda = problem.friction[k] * lambda[k];
        match state[k] {
            PairState::Free => gap[k] >= -tg,
            PairState::Stick => lambda[k] >= -tf && tau[k].abs() <= mu_lambda + tf,
            PairState::SlipPositive => lambda[k] >= -tf && ds >= -tg,
            PairState::SlipNegative => lambda[k] >= -tf && ds <= tg,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_pair_slipped_back_after_a_reversal_sticks() {
        use PairState::{Free, SlipNegative, SlipPositive, Stick};
        // Pair 0 cycles (+, −, +): it sticks. Pair 1 reverses once (−, +, still +): it slips.
        // Pair 2 was stuck before the reversal (stick, +, −): it slips. Pair 3 opens.
        let before = [SlipPositive, SlipNegative, Stick, SlipPositive];
        let state = [SlipNegative, SlipPositive, SlipPositive, SlipNegative];
        let mut next = [SlipPositive, SlipPositive, SlipNegative, Free];
        stick_reversals(&before, &state, &mut next);
        assert_eq!(next, [Stick, SlipPositive, SlipNegative, Free]);
    }
}

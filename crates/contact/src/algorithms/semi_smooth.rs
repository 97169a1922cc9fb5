//! The state update and the round-off admissibility test both active-set paths share (the
//! condensed `frictional_active_set.rs` and the sparse `sparse_active_set.rs`): given one state's
//! forces, gaps and slips, which state comes next, and whether this one already holds.
//!
//! ```text
//! contact ⇔ λ − c_N gap > 0;   in contact, with θ = τ − c_T Δs,  Δs = s − s_start:
//!         stick ⇔ |θ| ≤ μ(λ − c_N gap);  else slip with τ = μλ sign θ
//! cycle:  a pair the update slips back the way it slipped two iterations before, after the
//!         last iteration reversed it (slip+ → slip− → slip+, or the other way), sticks instead
//! longer: the exact law's update back to any state visited before changes only the
//!         lowest-numbered changing pair whose change leads to a state not yet visited
//! ```
//!
//! A slip reversal passes through stick. States where many pairs slip one way can flip all
//! together to the other way and back forever: the slip-driven update `θ = τ − c_T Δs`
//! overshoots where a whole interface slips, since `c_T` is scaled by one pair's compliance and
//! the interface moves as a whole (measured on a coarse level of `coarse_start.rs`: 922 of 1,001
//! pairs flipping at each of 38 iterations, pressed and slid with μ = 0.3; on a block held only
//! by contact, 996 of 1,001 pairs flipping while a few others changed, so that the whole state
//! never repeated). Only a pair's own cycle is broken so: applied at every reversal, the rule
//! itself cycled the plain iteration on the floating pad of `tests/behaviour/stick_continuation.rs`. A
//! state that settles satisfies the same conditions either way.
//!
//! Longer cycles pass through stick without reversing: on a block held only by contact at 1,001
//! pairs (`tests/integration/sparse_path.rs`), eleven pairs slipping the wrong way stuck, six of them slipped
//! again, and the state came back every seven iterations until the limit. An update back to a
//! visited state then changes one pair only, the lowest-numbered whose change leads somewhere
//! new; the next update is a whole one again. It borrows the idea of Murty's least-index method
//! (one change at a time, the lowest index first, which for a linear complementarity problem
//! with a P-matrix visits no state twice); applied only at a revisit it is a safeguard, not a
//! proof of termination, and the iteration limit still bounds the solve. Only the
//! exact law's states solved to round-off are recorded (a regularised stage's law differs, and a
//! trial solution's cycle goes to round-off first, `sparse_active_set.rs`).

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
/// complementarity constants `(c_N, c_T)` and a regularised stage's stick compliances
/// `e_k` (`stick_continuation.rs`; empty for the exact law). In a stage the slips are the
/// layer's far side's, `Δs_k + e_k τ_k`, and the tangential constant is the pair's and the
/// layer's stiffness in series, `c_k = c_T / (1 + c_T e_k)`:
///
/// ```text
/// θ_k = τ_k − c_k (Δs_k + e_k τ_k) = (τ_k − c_T Δs_k) / (1 + c_T e_k)
/// ```
///
/// With `c_T` itself, `θ_k = (1 − c_T e_k) τ_k − c_T Δs_k` reverses every slipping pair of
/// small slip once `c_T e_k > 1` (the first stage from 1,000 pairs), and the stage cycled with
/// the whole interface flipping its slip direction at each iteration. The fixed points are the
/// same for any `c_k > 0`.
pub(crate) fn next_state(
    problem: &ContactProblem,
    iterate: &Iterate,
    start: &StepStart,
    (c_n, c_t): (f64, f64),
    compliances: &[f64],
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
            let c = compliances.get(k).map_or(c_t, |e| c_t / (1.0 + c_t * e));
            let theta = tau[k] - c * (iterate.slip[k] - start.slip[k]);
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

/// The states the exact law's iteration has visited in one solve: a cycle longer than two
/// iterations (module docs) is broken by changing one pair at a time.
#[derive(Debug, Default)]
pub(crate) struct VisitedStates(std::collections::HashSet<Vec<PairState>>);

impl VisitedStates {
    /// Records `state`; when `next` (not `state` itself) was visited before, the iteration is on
    /// a cycle, and `next` becomes `state` with only the change of the lowest-numbered pair that
    /// leads to a state not yet visited (module docs: after Murty's least-index method); `next`
    /// is left as it is when every single change leads back to a visited state.
    pub(crate) fn break_cycle(&mut self, state: &[PairState], next: &mut [PairState]) {
        self.0.insert(state.to_vec());
        if next == state || !self.0.contains(&*next) {
            return;
        }
        let mut candidate = state.to_vec();
        for k in (0..state.len()).filter(|&k| next[k] != state[k]) {
            candidate[k] = next[k];
            if !self.0.contains(&candidate) {
                next.copy_from_slice(&candidate);
                return;
            }
            candidate[k] = state[k];
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
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
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

    #[test]
    fn an_update_back_to_a_visited_state_changes_one_pair() {
        use PairState::{SlipPositive as P, Stick as S};
        let mut visited = VisitedStates::default();
        // A whole update to a new state is left as it is.
        let (a, b, c) = ([S, S, P], [P, P, S], [P, S, S]);
        let mut next = b;
        visited.break_cycle(&a, &mut next);
        assert_eq!(next, b);
        visited.break_cycle(&b, &mut c.clone());
        // From c, back to a (visited): only the lowest-numbered change that leads somewhere new.
        // Pair 0 (P → S) gives [S, S, S], not visited.
        let mut next = a;
        visited.break_cycle(&c, &mut next);
        assert_eq!(next, [S, S, S]);
        // From [S, S, S] back to b: pair 0 alone gives [P, S, S] = c (visited), pair 1 alone
        // [S, P, S] (new).
        let mut next = b;
        visited.break_cycle(&[S, S, S], &mut next);
        assert_eq!(next, [S, P, S]);
        // Settled (next = state): untouched.
        let mut next = [S, P, S];
        visited.break_cycle(&[S, P, S], &mut next);
        assert_eq!(next, [S, P, S]);
    }

    #[test]
    fn a_regularised_stage_reads_the_pair_and_the_layer_in_series() {
        use contact2d_mesh::CellKind;
        let mut problem = crate::test_fixtures::two_blocks(CellKind::Quad4, 0.0, 0.0, 1.0, 0.05, 2, 2);
        problem.set_friction(0.5).unwrap();
        let m = problem.num_pairs();
        let start = StepStart::initial(m);
        // Every pair slips + (τ = −μλ); the layer's compliance e with c_T e = 4. With c_k in
        // series, θ = (τ − c_T Δs) / (1 + c_T e): a pair that has not slipped itself (Δs = 0,
        // the layer's slip e τ the wrong way) sticks, θ = τ / 5; a pair slipped beyond the
        // layer's share (Δs > e μλ, the regularised law's slip) slips on. With c_T alone,
        // θ = (1 − c_T e) τ − c_T Δs = 3 μλ at Δs = 0: the first pair would reverse.
        let (c_t, e, mu_lambda) = (10.0, 0.4, 0.5);
        let normal_force = vec![1.0; m];
        let tangential_force = vec![-mu_lambda; m];
        let gap = vec![0.0; m];
        let layer_slip = |ds: f64| vec![ds - e * mu_lambda; m];
        let state = |slip: &[f64], compliances: &[f64]| {
            let iterate = Iterate { normal_force: &normal_force, tangential_force: &tangential_force, gap: &gap, slip };
            let next = next_state(&problem, &iterate, &start, (1.0, c_t), compliances, true);
            let contact: Vec<PairState> = (0..m).filter(|&k| problem.normal[k]).map(|k| next[k]).collect();
            assert!(!contact.is_empty() && contact.iter().all(|s| *s == contact[0]), "{next:?}");
            contact[0]
        };
        assert_eq!(state(&layer_slip(0.0), &vec![e; m]), PairState::Stick);
        assert_eq!(state(&layer_slip(0.25), &vec![e; m]), PairState::SlipPositive);
        // The exact law's update (no layer) reads c_T itself.
        assert_eq!(state(&vec![-0.02; m], &[]), PairState::Stick);
        assert_eq!(state(&vec![0.01; m], &[]), PairState::SlipPositive);
    }
}

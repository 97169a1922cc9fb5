//! Starting states for a long interface from coarser sets of its pairs, so that the active set's
//! iterations grow like the logarithm of the pair count rather than like the count itself.
//!
//! From every pair in contact and sticking, the active set moves a contact zone's edge by about
//! one pair per iteration where the zone must open far: the tension of the bonded start
//! concentrates at the edge of the bonded part, so each solve opens the next pair only. A
//! frictionless press through a tilted gap (Q4 blocks, `tests/integration/sparse_path.rs`) took 11, 21, 39
//! and 75 iterations at 126, 251, 501 and 1,001 pairs, and stopped at the limit of 100 at 2,001
//! pairs, a refined mesh failing where a coarse one converges. The same walk moves stick–slip
//! fronts: pressed and slid by 0.2 of the press with μ = 0.3, the same blocks took 20, 40, 61
//! and 93 iterations (condensed path) and the sparse path stopped at the limit from 501 pairs.
//! It moves them from a guess as well: a block held only by contact (`tests/integration/sparse_path.rs`),
//! slid after its press, starts each step from the last one's states, and each Newton step on
//! its rigid motion (`floating.rs`) starts the next solve from the states before it; at 1,001
//! pairs a slide step walked its stick–slip fronts by a pair every other iteration and stopped at
//! the limit.
//!
//! ```text
//! plain:              the active set from its start (every pair in contact and sticking, or a
//!                     guess of the states), at most PLAIN_ITERATIONS iterations; settled:
//!                     that is the answer
//! level ℓ = L, …, 1:  the pairs k ≡ 0 (mod 2^ℓ) keep their contact conditions, the others are
//!                     left free (no normal or tangential unknown, as a pair held by fixes);
//!                     solved from the states of level ℓ + 1 (level L: where the plain
//!                     iteration stopped) spread to the kept pairs
//! then all pairs, from the states of level 1 spread to every pair
//! spread: each pair takes the state of the nearer kept pair (the one before it on a tie)
//! 2^L: the largest power of two leaving at least COARSEST_PAIRS kept pairs
//! ```
//!
//! On level L a front moves by one kept pair, 2^L pairs, per iteration. Each level places the
//! zone edges and stick–slip fronts to within about one of its kept pairs, so the next level,
//! with twice as many, moves each front by a pair or two of its own: a few iterations per
//! level and about `log₂(m / COARSEST_PAIRS)` levels. A solve that settles within the plain
//! iterations (short walks, as the long-interface presses and most steps from a guess) is
//! unchanged. Each level, and the last solve, is solved from its spread states as from a close
//! guess: to round-off from its first iteration on the sparse path (a trial solution's error
//! flipped slipping pairs near the fronts to stick, which the exact law then walked back a pair
//! per iteration). The coarse levels
//! are the same active set on the same interface (only the pairs' unknowns are switched off),
//! and only their states are kept: the answer is the last solve's, on every pair, from its
//! own fixed point. Pairs follow the order of the problem's list (along each master curve,
//! interface by interface), so a level's kept pairs are spread along every curve.

use crate::algorithms::stick_continuation::{IterationLimit, StickContinuation};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState};

/// Pairs from which a solve that has not settled goes on from coarser levels.
pub(crate) const COARSE_FROM: usize = 128;

/// Iterations the plain active set takes before the coarse levels (a step that settles within
/// them is as without coarse levels: the long-interface presses settle in 13–21 iterations at
/// 761–5,001 pairs).
pub(crate) const PLAIN_ITERATIONS: usize = 24;

/// The fewest pairs the coarsest level keeps.
const COARSEST_PAIRS: usize = 32;

/// What the coarse levels found: the states of every pair, and the iterations they took.
pub(crate) struct CoarseStart {
    /// Every pair's state, spread from the finest coarse level.
    pub(crate) states: Vec<PairState>,
    /// Iterations of all levels, in order (numbered on from one).
    pub(crate) trace: Vec<IterationRecord>,
}

/// Whether a solve on `problem` may go on from coarse levels: at least
/// [`COARSE_FROM`] pairs, and the warm starts for long interfaces on.
pub(crate) fn applies(problem: &ContactProblem, continuation: StickContinuation) -> bool {
    continuation == StickContinuation::Auto && problem.num_pairs() >= COARSE_FROM
}

/// The coarse levels of the module docs for one step from the states `seed` (where the plain
/// iteration stopped), each solved by `solve` (the step's active set without coarse levels from
/// states spread from the level before, given the level's problem, its guess and its iteration
/// limit) with at most `budget` iterations in all; `None` if a level's equations fail or no
/// level ran.
pub(crate) fn coarse_start(
    problem: &ContactProblem,
    interface: &Interface,
    seed: &[PairState],
    budget: usize,
    solve: impl Fn(&ContactProblem, &Interface, Option<&[PairState]>, IterationLimit) -> ContactSolution,
) -> Option<CoarseStart> {
    let m = problem.num_pairs();
    let mut stride = 1;
    while m / (2 * stride) >= COARSEST_PAIRS {
        stride *= 2;
    }
    let mut guess = seed.to_vec();
    let mut solved_any = false;
    let mut trace: Vec<IterationRecord> = Vec::new();
    let mut level = problem.clone();
    while stride > 1 {
        let left = budget.saturating_sub(trace.len());
        if left == 0 {
            break;
        }
        for k in 0..m {
            let kept = k % stride == 0;
            level.normal[k] = problem.normal[k] && kept;
            level.tangential[k] = problem.tangential[k] && kept;
        }
        let limit = IterationLimit { stop: left, of_step: left };
        let solved = solve(&level, interface, Some(&guess), limit);
        if solved.status == ContactStatus::Numerical {
            return None;
        }
        let offset = trace.len();
        trace.extend(solved.trace.iter().map(|r| IterationRecord { iteration: offset + r.iteration, ..*r }));
        guess = spread(&solved.state, stride);
        solved_any = true;
        stride /= 2;
    }
    solved_any.then_some(CoarseStart { states: guess, trace })
}

/// Every pair's state from those of the kept pairs `k ≡ 0 (mod stride)`: the nearer kept pair's
/// (the one before on a tie, or the last kept pair past it).
fn spread(states: &[PairState], stride: usize) -> Vec<PairState> {
    let m = states.len();
    (0..m)
        .map(|k| {
            let below = k / stride * stride;
            let above = below + stride;
            if above < m && above - k < k - below { states[above] } else { states[below] }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use super::*;

    #[test]
    fn each_pair_takes_the_nearer_kept_pairs_state() {
        use PairState::{Free, SlipPositive, Stick};
        let states = [Stick, Free, Free, Free, Free, Free, Free, Free, SlipPositive, Free];
        // Kept pairs 0, 4, 8 (stride 4): 0–2 take pair 0's (2 is a tie), 3–6 pair 4's, 7–9 pair 8's.
        let spread = spread(&states, 4);
        assert_eq!(spread, [Stick, Stick, Stick, Free, Free, Free, Free, SlipPositive, SlipPositive, SlipPositive]);
    }
}

//! Path-following on a regularised stick law: the warm start that keeps the primal-dual active
//! set's iteration count from growing with the number of pairs on long frictional interfaces.
//!
//! ```text
//! why:    the exact stick rows (Δs_k = 0) put a shear concentration on the last sticking pair
//!         before a slip zone, so each iteration moves a stick–slip front by about one pair:
//!         iterations ∝ slip-zone length / h
//! stage j (regularised):  stick rows  Δs_k + e_k τ_k = 0   (an elastic tangential layer)
//!         e_k = ρ_j / c_T · w̄ / w_k      (w_k the pair's tributary length, w̄ their mean:
//!                                          a layer of stiffness per unit length c_T / (ρ_j w̄))
//!         ρ_0 = FIRST_LEVEL_PER_PAIR · m  (stages only if ρ_0 ≥ MIN_FIRST_LEVEL),
//!         ρ_{j+1} = ρ_j / STAGE_FACTOR,  while ρ_j ≥ LAST_LEVEL
//!         the update reads the slip of the layer's far side:  Δs ← Δs + e_k τ_k
//! last stage: e = 0, the exact law: the answer, from the regularised stages' last state
//! ```
//!
//! The layer spreads the shear concentration over a length that does not shrink with the mesh
//! (its stiffness per unit length is fixed by ρ and the interface, not by h), so a front moves
//! by many pairs per iteration; each stage starts from the previous stage's state. Only the
//! exact stage's fixed point is returned: the stages change where the iteration starts, not
//! what it converges to. Below `MIN_FIRST_LEVEL / FIRST_LEVEL_PER_PAIR` = 300 pairs there is no
//! regularised stage at all (the iteration is the plain one, bit for bit).
//!
//! # References
//! Hintermüller & Kunisch (2006), SIAM J. Optim. 17(1): path-following methods for a class of
//! constrained minimization problems in function space (a Moreau–Yosida regularisation
//! followed to its limit, with mesh-independent semi-smooth Newton steps per stage);
//! Stadler (2004), Comput. Optim. Appl. 27: semismooth Newton and augmented Lagrangian methods
//! for a simplified friction problem (the regularised friction law).

use crate::problem::ContactProblem;

/// The first stage's level per pair: `ρ_0 = 1e-3 m` (a layer as stiff as the pairs' own
/// tangential stiffness `c_T` at `m` = 1,000 pairs). Measured on the pad layout
/// (docs/benchmarks.md, "Iterations against pairs"): 1e-2 and 1e-3 both cut the count at 751 and
/// 1,501 pairs, 1e-3 the more.
const FIRST_LEVEL_PER_PAIR: f64 = 1e-3;

/// The smallest first level: below it (fewer than 300 pairs) the plain iteration is used, the
/// fronts being only a few pairs from where the all-stick state puts them.
const MIN_FIRST_LEVEL: f64 = 0.3;

/// The smallest level of a regularised stage (`e_k c_T ≥ 0.03` for the mean pair): the last
/// stage's states are then close enough to the exact law's that few pairs change after it.
/// Measured (docs/benchmarks.md, "Iterations against pairs"): stopping at 0.3 cost the
/// long-interface press 20 and 28 iterations at 761 and 1,521 pairs (14 and 18 plain: the exact
/// law's first state then switched ~50 slipping pairs back to stick); 0.03 gives 13 and 16,
/// 0.01 and 0.003 no fewer.
const LAST_LEVEL: f64 = 0.03;

/// The ratio of consecutive stages' levels.
const STAGE_FACTOR: f64 = 10.0;

/// Whether the frictional active set follows the regularised stick law to the exact one
/// (module docs) before solving the exact law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum StickContinuation {
    /// Regularised stages from 300 pairs on, when a step starts without a guess of the states
    /// (the first step of a history, or a one-step solve); none below 300 pairs or with a guess.
    /// From 128 pairs, a solve (with a guess or without) that has not settled after 24
    /// iterations goes on from coarser sets of its pairs (`coarse_start.rs`).
    #[default]
    Auto,
    /// The exact law from the first iteration (the plain primal-dual active set), without
    /// coarse levels.
    Off,
}

impl StickContinuation {
    /// Every choice, in declaration order.
    pub const ALL: [StickContinuation; 2] = [StickContinuation::Auto, StickContinuation::Off];

    /// The name scene files use (`solver.stick_continuation`).
    pub fn key(self) -> &'static str {
        match self {
            StickContinuation::Auto => "auto",
            StickContinuation::Off => "off",
        }
    }
}

/// Where a step's iteration starts, as the stages see it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum StartingStates {
    /// No guess: every pair in contact and sticking (stages from 300 pairs).
    AllStick,
    /// A guess close to the answer (the previous step's states, a floating body's Jacobian
    /// probe, or states spread from a coarser set of the pairs, `coarse_start.rs`): the plain
    /// iteration from it.
    Close,
    /// A guess that may be far from the answer (a floating body's Newton step moved its pins,
    /// `floating.rs`): stages from the guess's states, as from the all-stick start.
    Far,
}

impl StartingStates {
    /// `AllStick` without a guess, `Close` or `Far` (as `far`) with one.
    pub(crate) fn of(guessed: bool, far: bool) -> StartingStates {
        match (guessed, far) {
            (false, _) => StartingStates::AllStick,
            (true, false) => StartingStates::Close,
            (true, true) => StartingStates::Far,
        }
    }
}

/// Whether the warm starts for long interfaces are on: `continuation` is
/// [`StickContinuation::Auto`] and the problem has at least
/// `MIN_FIRST_LEVEL / FIRST_LEVEL_PER_PAIR` = 300 pairs. They are the stages of this module and,
/// for floating bodies, the prediction of the final leg's rigid motion (`floating.rs`).
pub(crate) fn applies(problem: &ContactProblem, continuation: StickContinuation) -> bool {
    continuation == StickContinuation::Auto && FIRST_LEVEL_PER_PAIR * problem.num_pairs() as f64 >= MIN_FIRST_LEVEL
}

/// One regularised stage: the level `ρ` of the module docs and what turns it into compliances.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StickStage {
    /// `ρ_j`.
    level: f64,
    /// The active set's tangential complementarity constant `c_T`.
    c_t: f64,
    /// The mean tributary length `w̄` of the pairs.
    mean_weight: f64,
}

impl StickStage {
    /// The first regularised stage of a step, or `None` when the step solves the exact law from
    /// the start (continuation off, no friction, a close guess of the states, fewer than 300
    /// pairs, or no usable `c_T`).
    pub(crate) fn first(
        problem: &ContactProblem,
        continuation: StickContinuation,
        c_t: f64,
        frictional: bool,
        starting: StartingStates,
    ) -> Option<StickStage> {
        let m = problem.num_pairs();
        let level = FIRST_LEVEL_PER_PAIR * m as f64;
        let mean_weight = problem.pairs.iter().map(|p| p.weight).sum::<f64>() / m.max(1) as f64;
        let usable = c_t.is_finite() && c_t > 0.0 && mean_weight.is_finite() && mean_weight > 0.0;
        let wanted = frictional
            && matches!(starting, StartingStates::AllStick | StartingStates::Far)
            && applies(problem, continuation);
        (wanted && usable).then_some(StickStage { level, c_t, mean_weight })
    }

    /// The next stage, or `None` when the next one is the exact law.
    pub(crate) fn next(self) -> Option<StickStage> {
        let level = self.level / STAGE_FACTOR;
        (level >= LAST_LEVEL).then_some(StickStage { level, ..self })
    }

    /// The stick rows' compliances `e_k = ρ / c_T · w̄ / w_k` (zero for a pair of no length).
    pub(crate) fn compliances(&self, problem: &ContactProblem) -> Vec<f64> {
        let scale = self.level / self.c_t * self.mean_weight;
        problem.pairs.iter().map(|p| if p.weight > 0.0 { scale / p.weight } else { 0.0 }).collect()
    }
}

/// The slips the update reads in a regularised stage: `Δs_k + e_k τ_k`, the slip of the
/// layer's far side (on a sticking pair this is zero by its row).
pub(crate) fn add_layer_slip(slip: &mut [f64], compliances: &[f64], tau: &[f64]) {
    for ((s, e), t) in slip.iter_mut().zip(compliances).zip(tau) {
        *s += e * t;
    }
}

/// How many iterations one active-set solve may take: it stops after `stop`; its regularised
/// stages' shares are taken of the step's whole limit `of_step` (a solve that is one part of a
/// step, `coarse_start.rs`, stops earlier without changing its stages).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct IterationLimit {
    /// The iterations this solve may take.
    pub(crate) stop: usize,
    /// The step's limit (`solver.max_iterations`).
    pub(crate) of_step: usize,
}

impl IterationLimit {
    /// The whole step's limit for one solve.
    pub(crate) fn whole(max_iterations: usize) -> IterationLimit {
        IterationLimit { stop: max_iterations, of_step: max_iterations }
    }
}

/// Iterations allowed to one regularised stage: a quarter of the step's limit (at least one),
/// so that a stage that does not settle still leaves most of it to the exact law.
pub(crate) fn stage_limit(max_iterations: usize) -> usize {
    (max_iterations / 4).max(1)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
    use contact2d_mesh::CellKind;

    use super::*;

    #[test]
    fn stages_are_skipped_below_300_pairs_whatever_the_start() {
        let problem = crate::test_fixtures::two_blocks(CellKind::Quad9, 0.0, 0.004, 2.0, 0.05, 5, 3);
        assert!(problem.num_pairs() < 300);
        for starting in [StartingStates::AllStick, StartingStates::Close, StartingStates::Far] {
            assert_eq!(StickStage::first(&problem, StickContinuation::Auto, 1.0, true, starting), None);
        }
    }

    #[test]
    fn from_300_pairs_stages_start_without_a_guess_or_from_a_far_one() {
        let problem = crate::test_fixtures::two_blocks(CellKind::Quad4, 0.0, 0.0, 1.0, 0.05, 300, 300);
        assert!(problem.num_pairs() >= 300, "{}", problem.num_pairs());
        let first = |continuation, starting| StickStage::first(&problem, continuation, 1.0, true, starting);
        assert!(first(StickContinuation::Auto, StartingStates::AllStick).is_some());
        assert!(first(StickContinuation::Auto, StartingStates::Far).is_some());
        assert_eq!(first(StickContinuation::Auto, StartingStates::Close), None);
        assert_eq!(first(StickContinuation::Off, StartingStates::Far), None);
        assert_eq!(StickStage::first(&problem, StickContinuation::Auto, 1.0, false, StartingStates::Far), None);
        assert!(applies(&problem, StickContinuation::Auto) && !applies(&problem, StickContinuation::Off));
        assert_eq!(StartingStates::of(false, true), StartingStates::AllStick);
        assert_eq!(StartingStates::of(true, true), StartingStates::Far);
    }

    #[test]
    fn levels_fall_by_the_stage_factor_to_the_exact_law() {
        let stage = StickStage { level: 3.0, c_t: 2.0, mean_weight: 1.0 };
        let second = stage.next().unwrap();
        assert!((second.level - 0.3).abs() < 1e-15);
        assert!((second.next().unwrap().level - 0.03).abs() < 1e-15);
        assert_eq!(second.next().unwrap().next(), None);
        // e_k = ρ / c_T · w̄ / w_k.
        assert!((stage.level / stage.c_t * stage.mean_weight - 1.5).abs() < 1e-15);
    }

    #[test]
    fn keys_are_distinct() {
        assert_eq!(StickContinuation::ALL.map(StickContinuation::key), ["auto", "off"]);
    }

    #[test]
    fn the_layer_slip_adds_e_tau() {
        let mut slip = vec![1.0, 2.0];
        add_layer_slip(&mut slip, &[0.5, 0.0], &[2.0, 7.0]);
        assert_eq!(slip, vec![2.0, 2.0]);
    }
}

//! The factor an interface keeps of the last reduced system of the state equations
//! (`algorithms/state_equations.rs`): the active set solves the equations of nearly the same
//! states iteration after iteration, and a state set seen before needs no new LU. It lives here,
//! not with the algorithm, so that the interface (a shared type) imports no algorithm.

use faer::Mat;

use crate::solution::PairState;

/// The last factored reduced system of an interface, keyed by what its matrix depends on
/// besides the compliances: the states, the friction coefficients and the tangential flags.
#[derive(Debug, Default)]
pub(crate) struct StateFactorCache(pub(crate) std::sync::Mutex<Option<StateFactor>>);

impl Clone for StateFactorCache {
    /// A clone starts empty (the factor is a cache, not part of the value).
    fn clone(&self) -> StateFactorCache {
        StateFactorCache::default()
    }
}

/// What a reduced system's matrix depends on besides the compliances: the states, the friction
/// coefficients, the tangential flags, whether friction is on, and the bits of the stick rows'
/// regularising compliances (empty: exact).
pub(crate) type StateKey = (Vec<PairState>, Vec<f64>, Vec<bool>, bool, Vec<u64>);

/// One factored reduced system: its key, its LU and the permutations of its rows, and what
/// the low-rank updates from it have computed (`algorithms/state_update.rs`).
#[derive(Debug)]
pub(crate) struct StateFactor {
    /// The state the LU is of.
    pub(crate) key: StateKey,
    /// The LU factors.
    pub(crate) lu: Mat<f64>,
    /// Row permutation.
    pub(crate) forward: Vec<usize>,
    /// Its inverse.
    pub(crate) inverse: Vec<usize>,
    /// `F⁻¹ e_i` of the full system of the factored state, per full row `i` an update has
    /// changed (kept while this factor lives).
    pub(crate) update_columns: Vec<(usize, Vec<f64>)>,
    /// `‖F‖∞` bound of the full systems on this interface, once an update has needed it.
    pub(crate) row_norm: Option<f64>,
    /// The states last solved by an update of this factor.
    pub(crate) last_updated: Option<Vec<PairState>>,
}

impl StateFactor {
    /// A fresh factor of the state `key`, no update computed yet.
    pub(crate) fn new(key: StateKey, lu: Mat<f64>, forward: Vec<usize>, inverse: Vec<usize>) -> StateFactor {
        StateFactor { key, lu, forward, inverse, update_columns: Vec::new(), row_norm: None, last_updated: None }
    }
}

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

/// One factored reduced system: its key, its LU and the permutations of its rows.
#[derive(Debug)]
pub(crate) struct StateFactor {
    /// States, friction coefficients, tangential flags, whether friction is on, and the bits
    /// of the stick rows' regularising compliances (empty: exact).
    pub(crate) key: (Vec<PairState>, Vec<f64>, Vec<bool>, bool, Vec<u64>),
    /// The LU factors.
    pub(crate) lu: Mat<f64>,
    /// Row permutation.
    pub(crate) forward: Vec<usize>,
    /// Its inverse.
    pub(crate) inverse: Vec<usize>,
}

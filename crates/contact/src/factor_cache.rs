//! The factor an interface keeps of the last reduced system of the state equations
//! (`algorithms/state_equations.rs`): the active set solves the equations of nearly the same
//! states iteration after iteration, and a state set seen before needs no new LU. It lives here,
//! not with the algorithm, so that the interface (a shared type) imports no algorithm.

use contact2d_fem::parallelism;
use faer::Mat;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};

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

/// A dense LU with partial pivoting (faer's, with the fixed [`contact2d_fem::parallelism`]).
#[derive(Debug)]
pub(crate) struct DenseLu {
    /// The LU factors.
    lu: Mat<f64>,
    /// Row permutation.
    forward: Vec<usize>,
    /// Its inverse.
    inverse: Vec<usize>,
}

impl DenseLu {
    /// Factors `a` (square) in place; a singular `a` is factored too ([`DenseLu::is_regular`]).
    pub(crate) fn factor(mut a: Mat<f64>) -> DenseLu {
        let (n, par) = (a.nrows(), parallelism());
        let mut memory = MemBuffer::new(factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default()));
        let (mut forward, mut inverse) = (vec![0usize; n], vec![0usize; n]);
        factor::lu_in_place(
            a.as_mut(),
            &mut forward,
            &mut inverse,
            par,
            MemStack::new(&mut memory),
            Default::default(),
        );
        DenseLu { lu: a, forward, inverse }
    }

    /// The order.
    pub(crate) fn size(&self) -> usize {
        self.lu.nrows()
    }

    /// Pivot `i` (the diagonal of `U`).
    pub(crate) fn pivot(&self, i: usize) -> f64 {
        self.lu[(i, i)]
    }

    /// Whether every pivot is finite and nonzero.
    pub(crate) fn is_regular(&self) -> bool {
        (0..self.size()).all(|i| self.pivot(i) != 0.0 && self.pivot(i).is_finite())
    }

    /// `b ← A⁻¹ b`.
    pub(crate) fn solve_in_place(&self, b: &mut Mat<f64>) {
        let (n, par) = (self.size(), parallelism());
        let mut memory = MemBuffer::new(solve::solve_in_place_scratch::<usize, f64>(n, b.ncols(), par));
        // The arrays are the permutation and its inverse written by `lu_in_place`.
        let perm = faer::perm::PermRef::new_checked(&self.forward, &self.inverse, n);
        solve::solve_in_place(self.lu.as_ref(), self.lu.as_ref(), perm, b.as_mut(), par, MemStack::new(&mut memory));
    }
}

/// One factored reduced system: its key and LU, and what the low-rank updates from it have
/// computed (`algorithms/state_update.rs`).
#[derive(Debug)]
pub(crate) struct StateFactor {
    /// The state the LU is of.
    pub(crate) key: StateKey,
    /// The reduced system's LU.
    pub(crate) lu: DenseLu,
    /// `F⁻¹ e_i` of the full system of the factored state, per full row `i` an update has
    /// changed (kept while this factor lives).
    pub(crate) update_columns: Vec<(usize, Vec<f64>)>,
    /// The largest absolute row sums of the compliance rows `[C_NN]`, `[C_NN C_NT]`,
    /// `[C_TN C_TT]` (the interface's, so handed on from factor to factor), once an update has
    /// needed them.
    pub(crate) compliance_row_norm: Option<[f64; 3]>,
    /// The states last solved by an update of this factor.
    pub(crate) last_updated: Option<Vec<PairState>>,
}

impl StateFactor {
    /// A fresh factor of the state `key`, no update computed yet; `compliance_row_norm` as the
    /// interface's previous factor knew it.
    pub(crate) fn new(key: StateKey, lu: DenseLu, compliance_row_norm: Option<[f64; 3]>) -> StateFactor {
        StateFactor { key, lu, update_columns: Vec::new(), compliance_row_norm, last_updated: None }
    }
}

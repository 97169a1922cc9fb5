//! Sparse Cholesky solves through faer, with the symbolic factorisation kept for reuse.
//!
//! ```text
//! P K_ff Pᵀ = L Lᵀ :  symbolic analysis (ordering P, elimination tree, supernodes) once per
//!                     sparsity pattern; numeric factorisation whenever the values change.
//! P from faer's AMD, or any permutation given (e.g. crate::ordering's nested dissection).
//! With the last t DOFs of P chosen (contact DOFs), L = [L_aa 0; L_ba L_bb] and
//! L_bb L_bbᵀ = K_bb − K_ba K_aa⁻¹ K_ab: the Schur complement on them (`trailing_block`).
//! Bordered by constraint rows B (crate::constrained): P [K Bᵀ; B 0] Pᵀ = L D Lᵀ, the rows
//! last; `solve` then uses the K block only and `condensed` gives C = B K⁻¹ Bᵀ.
//! ```
//!
//! The symbolic factorisation and the values of `L` are shared (reference counted): cloning a
//! solver is cheap, and a clone keeps solving with the factor it was cloned from.

use std::fmt;
use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, LltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
    factorize_symbolic_cholesky,
};
use faer::{Conj, Mat, Par, Side};

use crate::assembly::{Csc, LinearSystem};
use crate::error::FemError;
use crate::model::Model;
use crate::ordering::{COMPRESS_FROM, Ordering, fill_reducing_permutation, is_permutation, twin_compressed_amd};

/// A Cholesky factorisation of a symmetric positive definite matrix stored as its lower triangle.
#[derive(Clone)]
pub struct CholeskySolver {
    pub(crate) symbolic: Arc<SymbolicCholesky<usize>>,
    pub(crate) values: Arc<Vec<f64>>,
    /// Order of `K` (the factored matrix is `K` bordered by `constraints` rows, if any).
    pub(crate) dim: usize,
    /// Number of constraint rows factored with `K` (crate::constrained), 0 for `K` alone.
    pub(crate) constraints: usize,
    pub(crate) pattern: PatternFingerprint,
}

/// The shape, number of entries and a hash of the sparsity pattern a factorisation was made for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct PatternFingerprint {
    nnz: usize,
    hash: u64,
}

impl PatternFingerprint {
    pub(crate) fn of(k: &Csc) -> PatternFingerprint {
        let k = k.as_ref();
        // FNV-1a over the column pointers and row indices.
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        let mut eat = |v: usize| {
            hash ^= v as u64;
            hash = hash.wrapping_mul(0x0100_0000_01b3);
        };
        for j in 0..k.ncols() {
            eat(usize::MAX);
            k.row_idx_of_col(j).for_each(&mut eat);
        }
        PatternFingerprint { nnz: k.compute_nnz(), hash }
    }
}

impl fmt::Debug for CholeskySolver {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CholeskySolver")
            .field("dim", &self.dim)
            .field("constraints", &self.constraints)
            .field("factor_nnz", &self.factor_nnz())
            .field("supernodal", &matches!(self.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_)))
            .finish()
    }
}

/// The parallelism of every faer kernel contact2d calls (factorisation, solves, dense
/// products): sequential, never read from the thread pool, so that the numbers are the same bit
/// for bit whatever `RAYON_NUM_THREADS` is and however rayon schedules. faer's parallel kernels
/// split their work by the thread count, which changes the rounding (measured: the N = 128
/// flagship differed in the 14th digit between 1 and 2 threads). On the flagship scenes the
/// sequential kernels cost nothing (N = 64 no-gap scene, median of 5 on two cores: 0.157 s
/// against 0.231 s with the thread pool's parallelism); assembly, ordering and stress
/// recovery stay parallel (their results do not depend on the split).
pub fn parallelism() -> Par {
    Par::Seq
}

fn numeric(symbolic: &SymbolicCholesky<usize>, k: &Csc) -> Result<Vec<f64>, FemError> {
    let par = parallelism();
    let mut values = vec![0.0; symbolic.len_val()];
    let mut mem = MemBuffer::try_new(symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()))
        .map_err(|e| FemError::Factorization(format!("workspace: {e:?}")))?;
    symbolic
        .factorize_numeric_llt(
            &mut values,
            k.as_ref(),
            Side::Lower,
            Default::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .map_err(|e| {
            FemError::Factorization(format!(
                "stiffness matrix is not positive definite ({e:?}): a body may be unconstrained or an element degenerate"
            ))
        })?;
    Ok(values)
}

/// The symbolic analysis of `k` (lower triangle) with faer's AMD, from [`COMPRESS_FROM`]
/// unknowns on the pattern with twin columns merged ([`twin_compressed_amd`]).
fn amd_symbolic(k: &Csc, params: CholeskySymbolicParams<'_>) -> Result<SymbolicCholesky<usize>, FemError> {
    let analysis = |ordering| {
        factorize_symbolic_cholesky(k.symbolic(), Side::Lower, ordering, params)
            .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))
    };
    if k.nrows() < COMPRESS_FROM {
        return analysis(SymmetricOrdering::Amd);
    }
    let forward = twin_compressed_amd(k)?;
    let mut inverse = vec![0; forward.len()];
    for (new, &old) in forward.iter().enumerate() {
        inverse[old] = new;
    }
    analysis(SymmetricOrdering::Custom(PermRef::new_checked(&forward, &inverse, forward.len())))
}

pub(crate) fn check_square(k: &Csc) -> Result<(), FemError> {
    if k.nrows() != k.ncols() {
        return Err(FemError::Factorization(format!("matrix is {}×{}, not square", k.nrows(), k.ncols())));
    }
    Ok(())
}

impl CholeskySolver {
    /// Analyses and factors `k` (lower triangle) with faer's AMD ordering.
    ///
    /// # Errors
    /// [`FemError::Factorization`] if `k` is not square or not positive definite.
    pub fn factor(k: &Csc) -> Result<CholeskySolver, FemError> {
        check_square(k)?;
        let symbolic = amd_symbolic(k, Default::default())?;
        CholeskySolver::finish(symbolic, k)
    }

    /// Like [`CholeskySolver::factor`], the factor always supernodal: faer's automatic choice
    /// takes the simplicial factor for the thin, long meshes of long contact interfaces, whose
    /// numeric factorisation is then 1.7 times slower (0.44 s against 0.27 s at 145k DOFs, the
    /// solves 2 times faster; docs/benchmarks.md, "Sparse contact solves").
    ///
    /// # Errors
    /// As [`CholeskySolver::factor`].
    pub fn factor_supernodal(k: &Csc) -> Result<CholeskySolver, FemError> {
        check_square(k)?;
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic = amd_symbolic(k, params)?;
        CholeskySolver::finish(symbolic, k)
    }

    /// Analyses and factors the stiffness of `system` (assembled from `model`) with `ordering`.
    ///
    /// # Errors
    /// As [`CholeskySolver::factor`].
    pub fn factor_with_ordering(
        model: &Model,
        system: &LinearSystem,
        ordering: Ordering,
    ) -> Result<CholeskySolver, FemError> {
        match ordering {
            Ordering::Amd => CholeskySolver::factor(&system.stiffness),
            Ordering::NestedDissection | Ordering::NodeAmd => {
                let forward = fill_reducing_permutation(model, &system.dofs, &system.stiffness, ordering, &[])?;
                CholeskySolver::factor_with_permutation(&system.stiffness, &forward)
            }
        }
    }

    /// Analyses and factors `k` (lower triangle) with the fill-reducing permutation `forward`
    /// (`forward[new] = old`), e.g. from [`crate::fill_reducing_permutation`].
    ///
    /// # Errors
    /// [`FemError::Factorization`] if `k` is not square or not positive definite, or `forward`
    /// is not a permutation of `0..k.nrows()`.
    pub fn factor_with_permutation(k: &Csc, forward: &[usize]) -> Result<CholeskySolver, FemError> {
        check_square(k)?;
        let n = k.nrows();
        if !is_permutation(forward, n) {
            return Err(FemError::Factorization(format!("the ordering is not a permutation of 0..{n}")));
        }
        let mut inverse = vec![0; n];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        let perm = PermRef::new_checked(forward, &inverse, n);
        let symbolic =
            factorize_symbolic_cholesky(k.symbolic(), Side::Lower, SymmetricOrdering::Custom(perm), Default::default())
                .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))?;
        CholeskySolver::finish(symbolic, k)
    }

    fn finish(symbolic: SymbolicCholesky<usize>, k: &Csc) -> Result<CholeskySolver, FemError> {
        let values = numeric(&symbolic, k)?;
        Ok(CholeskySolver::from_parts(symbolic, values, k.nrows(), 0, PatternFingerprint::of(k)))
    }

    pub(crate) fn from_parts(
        symbolic: SymbolicCholesky<usize>,
        values: Vec<f64>,
        dim: usize,
        constraints: usize,
        pattern: PatternFingerprint,
    ) -> CholeskySolver {
        CholeskySolver { symbolic: Arc::new(symbolic), values: Arc::new(values), dim, constraints, pattern }
    }

    /// Refactors with new values on the same sparsity pattern, reusing the symbolic analysis.
    ///
    /// # Errors
    /// [`FemError::Factorization`] if the pattern differs from the analysed one, the matrix is
    /// not positive definite, or the factor is bordered by constraint rows (use
    /// [`CholeskySolver::refactor_with_constraints`]).
    pub fn refactor(&mut self, k: &Csc) -> Result<(), FemError> {
        if self.constraints > 0 {
            return Err(FemError::Factorization(
                "refactor: the factor has constraint rows (refactor_with_constraints)".into(),
            ));
        }
        if !self.same_pattern(k) {
            return Err(FemError::Factorization("refactor: the sparsity pattern changed".into()));
        }
        self.values = Arc::new(numeric(&self.symbolic, k)?);
        Ok(())
    }

    /// Whether `k` has the sparsity pattern this factorisation was analysed for.
    pub fn same_pattern(&self, k: &Csc) -> bool {
        self.constraints == 0
            && k.nrows() == self.dim
            && k.ncols() == self.dim
            && PatternFingerprint::of(k) == self.pattern
    }

    /// Dimension of the system.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The fill-reducing permutation (`forward[new] = old`), if any; with constraint rows, of
    /// `K` and the rows (indices `dim()..`) together.
    pub fn permutation(&self) -> Option<&[usize]> {
        self.symbolic.perm().map(|p| p.arrays().0)
    }

    /// Number of entries of `L` (lower triangle, diagonal included; with constraint rows, of
    /// the whole bordered factor).
    pub fn factor_nnz(&self) -> usize {
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => s.len_val(),
            SymbolicCholeskyRaw::Supernodal(s) => (0..s.n_supernodes())
                .map(|j| {
                    let c = s.supernode_end()[j] - s.supernode_begin()[j];
                    c * (c + 1) / 2 + c * s.supernode(j).pattern().len()
                })
                .sum(),
        }
    }

    /// Solves `K x = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let mut x = Mat::from_fn(b.len(), 1, |i, _| b[i]);
        self.solve_in_place(&mut x);
        x.col(0).iter().copied().collect()
    }

    /// Solves `K X = B` for several right-hand sides at once.
    pub fn solve_many(&self, b: &Mat<f64>) -> Mat<f64> {
        let mut x = b.clone();
        self.solve_in_place(&mut x);
        x
    }

    fn solve_in_place(&self, x: &mut Mat<f64>) {
        if self.constraints > 0 && self.solve_k_block_in_place(x) {
            return;
        }
        let par = parallelism();
        let req = self.symbolic.solve_in_place_scratch::<f64>(x.ncols(), par);
        // The workspace is of the size of the right-hand side; failing to allocate it is an
        // out-of-memory condition, which Rust's allocator treats as fatal anyway.
        let mut mem = MemBuffer::new(req);
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            x.as_mut(),
            par,
            MemStack::new(&mut mem),
        );
    }

    /// The trailing `t × t` block `L_bb` of the factor (dense, lower triangular), in the order of
    /// the last `t` DOFs of [`CholeskySolver::permutation`]: `L_bb L_bbᵀ` is the Schur
    /// complement of `K` on those DOFs. `None` if `t` exceeds the dimension or the factor is
    /// bordered by constraint rows ([`CholeskySolver::condensed`] gives their complement).
    pub fn trailing_block(&self, t: usize) -> Option<Mat<f64>> {
        if self.constraints > 0 {
            return None; // an LDLᵀ factor: see `condensed` for the rows' Schur complement
        }
        let n = self.dim;
        let first = n.checked_sub(t)?;
        let mut l = Mat::zeros(t, t);
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => {
                let (ptr, rows) = (s.col_ptr(), s.row_idx());
                for j in first..n {
                    for p in ptr[j]..ptr[j + 1] {
                        l[(rows[p] - first, j - first)] = self.values[p];
                    }
                }
            }
            SymbolicCholeskyRaw::Supernodal(s) => {
                for sn in 0..s.n_supernodes() {
                    let (begin, end) = (s.supernode_begin()[sn], s.supernode_end()[sn]);
                    if end <= first {
                        continue;
                    }
                    let c = end - begin;
                    let pattern = s.supernode(sn).pattern();
                    let vals = &self.values[s.col_ptr_for_val()[sn]..s.col_ptr_for_val()[sn + 1]];
                    let rows = c + pattern.len();
                    for jj in (first.max(begin) - begin)..c {
                        let col = &vals[jj * rows..(jj + 1) * rows];
                        for (ii, v) in col.iter().enumerate().take(c).skip(jj) {
                            l[(begin + ii - first, begin + jj - first)] = *v;
                        }
                        for (r, v) in pattern.iter().zip(&col[c..]) {
                            l[(r - first, begin + jj - first)] = *v;
                        }
                    }
                }
            }
        }
        Some(l)
    }
}

//! `K` factored together with constraint rows `B`: solves with `K` and the Schur complement
//! `C = B K⁻¹ Bᵀ` (the compliance of the bodies at the rows) from one sparse factorisation.
//!
//! ```text
//! A = [K  Bᵀ]      quasi-definite; ordered by AMD on A's pattern, the rows then moved last:
//!     [B  0 ]      P A Pᵀ = L D Lᵀ  (faer's supernodal LDLᵀ, no pivoting), L unit lower,
//!
//! L = [L_kk 0; L_bk L_bb],  D = diag(D_k, D_b):   L_kk D_k L_kkᵀ = P_K K P_Kᵀ  (D_k > 0 ⇔ K SPD)
//!                                                  L_bb D_b L_bbᵀ = −B K⁻¹ Bᵀ = −C  (D_b < 0)
//! C = W Wᵀ,  W = L_bb |D_b|^½        (lower triangular, r × r: r³/3 flops)
//! K⁻¹ x:  forward and backward solves with L_kk and D_k only (the rows' part of L skipped)
//! ```
//!
//! Why: ordering the DOFs the rows touch last (so that the trailing block of K's own Cholesky
//! factor is their Schur complement) makes a dense block of the size of those DOFs — about four per
//! contact pair with a segment-to-segment slave side — and its `t³/3` flops dominate long
//! interfaces (docs/benchmarks.md). Here the dense block has the size of the rows (two per pair)
//! and `K`'s own DOFs are not constrained in the ordering. The `K` block is eliminated first, so
//! its pivots are those of `K`'s Cholesky factorisation (no instability from the indefinite whole);
//! the rows' block is then the negative definite `−C` whenever `B` has full row rank. Rows that are
//! (numerically) dependent give a pivot of the wrong sign or a huge multiplier: the factorisation
//! is then redone without rows (see [`CholeskySolver::factor_with_constraints`]).

use std::sync::Arc;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::ldlt::factor::LdltRegularization;
use faer::linalg::matmul::matmul;
use faer::linalg::matmul::triangular::{self, BlockStructure};
use faer::linalg::triangular_solve::{solve_unit_lower_triangular_in_place, solve_unit_upper_triangular_in_place};
use faer::perm::PermRef;
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Accum, Mat, MatMut, MatRef, Side};

use crate::error::FemError;
use crate::ordering::fill_reducing_permutation_of_pattern;
use crate::solve::{CholeskySolver, PatternFingerprint, parallelism};
use crate::sparse::Csc;

/// A multiplier of `L_bb` larger than this marks rows that are dependent up to round-off (the
/// pivot of a dependent row is a rounding residue, and dividing by it amplifies noise).
const MAX_MULTIPLIER: f64 = 1e8;

/// The lower triangle of `A = [K Bᵀ; B 0]` (rows of `B` given as `(column, value)` lists over
/// `K`'s indices; repeated columns add), with an explicit zero diagonal in the rows' block.
fn augmented_lower(k: &Csc, rows: &[&[(usize, f64)]]) -> Result<Csc, FemError> {
    let (n, r) = (k.nrows(), rows.len());
    // Bᵀ by columns of K: per K column, the (row, value) entries below K, in row order.
    let mut count = vec![0usize; n + 1];
    for row in rows {
        for &(j, _) in *row {
            if j >= n {
                return Err(FemError::InvalidInput(format!("constraint row: column {j} out of range ({n} DOFs)")));
            }
            count[j + 1] += 1;
        }
    }
    for j in 0..n {
        count[j + 1] += count[j];
    }
    let mut next = count.clone();
    let mut entries = vec![(0usize, 0.0f64); count[n]];
    for (q, row) in rows.iter().enumerate() {
        for &(j, v) in *row {
            entries[next[j]] = (n + q, v);
            next[j] += 1;
        }
    }
    let kr = k.as_ref();
    let mut col_ptr = Vec::with_capacity(n + r + 1);
    let mut row_idx = Vec::with_capacity(kr.compute_nnz() + entries.len() + r);
    let mut values = Vec::with_capacity(row_idx.capacity());
    col_ptr.push(0);
    for j in 0..n {
        for (i, v) in kr.row_idx_of_col(j).zip(kr.val_of_col(j)) {
            if i >= j {
                row_idx.push(i);
                values.push(*v);
            }
        }
        for &(i, v) in &entries[count[j]..count[j + 1]] {
            // Entries of one row in one column are adjacent (rows are visited in order): add.
            match values.last_mut() {
                Some(last) if row_idx.last() == Some(&i) && row_idx.len() > col_ptr[j] => *last += v,
                _ => {
                    row_idx.push(i);
                    values.push(v);
                }
            }
        }
        col_ptr.push(row_idx.len());
    }
    for q in 0..r {
        row_idx.push(n + q);
        values.push(0.0);
        col_ptr.push(row_idx.len());
    }
    let symbolic = SymbolicSparseColMat::new_checked(n + r, n + r, col_ptr, None, row_idx);
    Ok(SparseColMat::new(symbolic, values))
}

/// The `(start, columns, rows)` of supernode `s`'s block in the factor values, with its pattern.
struct Block<'a> {
    start: usize,
    columns: usize,
    values: MatRef<'a, f64>,
    pattern: &'a [usize],
}

/// The supernodes of a supernodal factor (`None` for a simplicial one).
fn blocks<'a>(symbolic: &'a SymbolicCholesky<usize>, values: &'a [f64]) -> Option<Vec<Block<'a>>> {
    let SymbolicCholeskyRaw::Supernodal(s) = symbolic.raw() else { return None };
    Some(
        (0..s.n_supernodes())
            .map(|sn| {
                let (start, end) = (s.supernode_begin()[sn], s.supernode_end()[sn]);
                let pattern = s.supernode(sn).pattern();
                let columns = end - start;
                let vals = &values[s.col_ptr_for_val()[sn]..s.col_ptr_for_val()[sn + 1]];
                Block {
                    start,
                    columns,
                    values: MatRef::from_column_major_slice(vals, columns + pattern.len(), columns),
                    pattern,
                }
            })
            .collect(),
    )
}

/// `(D_k, D_b)`, the pivots of the `K` block (`n` first) and of the rows' block.
fn pivots(blocks: &[Block<'_>], n: usize, total: usize) -> (Vec<f64>, Vec<f64>) {
    let mut d = vec![0.0; total];
    for b in blocks {
        for c in 0..b.columns {
            d[b.start + c] = b.values[(c, c)];
        }
    }
    let rows = d.split_off(n);
    (d, rows)
}

/// The trailing `r × r` block of the unit lower factor (diagonal set to one).
fn trailing_unit_block(blocks: &[Block<'_>], n: usize, r: usize) -> Mat<f64> {
    let mut l = Mat::zeros(r, r);
    for b in blocks.iter().filter(|b| b.start + b.columns > n) {
        for jj in n.max(b.start) - b.start..b.columns {
            let j = b.start + jj - n;
            l[(j, j)] = 1.0;
            for ii in jj + 1..b.columns {
                l[(b.start + ii - n, j)] = b.values[(ii, jj)];
            }
            for (p, &i) in b.pattern.iter().enumerate() {
                l[(i - n, j)] = b.values[(b.columns + p, jj)];
            }
        }
    }
    l
}

impl CholeskySolver {
    /// Factors `K` (lower triangle) together with the constraint rows `rows` (free index,
    /// coefficient): afterwards [`CholeskySolver::solve`] still solves with `K`, and
    /// [`CholeskySolver::condensed`] gives `C = B K⁻¹ Bᵀ`. If the rows are dependent (up to
    /// round-off), `K` is factored alone (AMD, no rows) and `condensed` is `None`.
    ///
    /// # Errors
    /// [`FemError::Factorization`] if `K` is not square or not positive definite;
    /// [`FemError::InvalidInput`] for a row entry outside `K`.
    pub fn factor_with_constraints(k: &Csc, rows: &[&[(usize, f64)]]) -> Result<CholeskySolver, FemError> {
        crate::solve::check_square(k)?;
        let (n, r) = (k.nrows(), rows.len());
        if r == 0 {
            return CholeskySolver::factor(k);
        }
        let a = augmented_lower(k, rows)?;
        // AMD on the whole bordered pattern, the rows then moved last: the order of K's DOFs
        // knows that each row joins the DOFs of a pair. (AMD on K alone eliminates the contact
        // DOFs early, on the boundary, and every row's part of L then spans a long path of the
        // elimination tree: factorisation 1.15 s against 0.57 s at 1 522 rows, 6.1 s against
        // 2.0 s at 3 042, 4 % more on the flagship meshes; docs/benchmarks.md.)
        let mut forward: Vec<usize> =
            fill_reducing_permutation_of_pattern(&a)?.into_iter().filter(|&i| i < n).collect();
        forward.extend(n..n + r);
        let mut inverse = vec![0; n + r];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        let perm = PermRef::new_checked(&forward, &inverse, n + r);
        // Supernodal always: the rows' block and the K-block solves read the supernodes.
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_cholesky(a.symbolic(), Side::Lower, SymmetricOrdering::Custom(perm), params)
            .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))?;
        match numeric_ldlt(&symbolic, &a, n)? {
            Some(values) => Ok(CholeskySolver::from_parts(symbolic, values, n, r, PatternFingerprint::of(&a))),
            None => CholeskySolver::factor(k),
        }
    }

    /// Refactors with new values of `K` and the rows on the same sparsity pattern (e.g. a
    /// morphed mesh), reusing the symbolic analysis; falls back to
    /// [`CholeskySolver::factor_with_constraints`] when the pattern changed or this factor has
    /// no rows.
    ///
    /// # Errors
    /// As [`CholeskySolver::factor_with_constraints`].
    pub fn refactor_with_constraints(&mut self, k: &Csc, rows: &[&[(usize, f64)]]) -> Result<(), FemError> {
        if self.constraints == 0 || rows.len() != self.constraints || k.nrows() != self.dim {
            *self = CholeskySolver::factor_with_constraints(k, rows)?;
            return Ok(());
        }
        let a = augmented_lower(k, rows)?;
        if PatternFingerprint::of(&a) != self.pattern {
            *self = CholeskySolver::factor_with_constraints(k, rows)?;
            return Ok(());
        }
        match numeric_ldlt(&self.symbolic, &a, k.nrows())? {
            Some(values) => self.values = Arc::new(values),
            None => *self = CholeskySolver::factor(k)?,
        }
        Ok(())
    }

    /// Number of constraint rows factored with `K` (0 for a plain Cholesky factor).
    pub fn constraint_count(&self) -> usize {
        self.constraints
    }

    /// `C = B K⁻¹ Bᵀ` for the rows given to [`CholeskySolver::factor_with_constraints`], in their
    /// order (symmetric positive definite), or `None` without rows.
    pub fn condensed(&self) -> Option<Mat<f64>> {
        let r = self.constraints;
        if r == 0 {
            return None;
        }
        let blocks = blocks(&self.symbolic, &self.values)?;
        let (_, d_rows) = pivots(&blocks, self.dim, self.dim + r);
        let mut w = trailing_unit_block(&blocks, self.dim, r);
        for (j, d) in d_rows.iter().enumerate() {
            let s = (-d).sqrt();
            w.col_mut(j).iter_mut().for_each(|v| *v *= s);
        }
        let mut c = Mat::zeros(r, r);
        let par = parallelism();
        triangular::matmul(
            c.as_mut(),
            BlockStructure::TriangularLower,
            Accum::Replace,
            w.as_ref(),
            BlockStructure::TriangularLower,
            w.transpose(),
            BlockStructure::TriangularUpper,
            1.0,
            par,
        );
        for j in 0..r {
            for i in 0..j {
                c[(i, j)] = c[(j, i)];
            }
        }
        Some(c)
    }

    /// `K⁻¹ X` in place with the `K` block of an augmented factor: the rows' part of `L` is
    /// skipped (row indices `≥ n` come last in every supernode's pattern and diagonal block).
    ///
    /// Returns false (and leaves `x` alone) if the factor is not a supernodal, permuted one — never
    /// for a factor made by [`CholeskySolver::factor_with_constraints`] (it forces both).
    pub(crate) fn solve_k_block_in_place(&self, x: &mut Mat<f64>) -> bool {
        let n = self.dim;
        let (Some(blocks), Some(perm)) = (blocks(&self.symbolic, &self.values), self.symbolic.perm()) else {
            return false;
        };
        let (forward, _) = perm.arrays();
        let k = x.ncols();
        let mut y = Mat::from_fn(n, k, |i, j| x[(forward[i], j)]);
        let par = parallelism();
        let k_part = |b: &Block<'_>| {
            let columns = b.columns.min(n.saturating_sub(b.start));
            let below = b.pattern.partition_point(|&i| i < n);
            (columns, below)
        };
        // One workspace for every supernode's rows below its diagonal block.
        let widest = blocks.iter().map(|b| b.pattern.len()).max().unwrap_or(0);
        let mut work = vec![0.0; widest * k];
        for b in blocks.iter().filter(|b| b.start < n) {
            let (c, below) = k_part(b);
            let mut top = y.as_mut().subrows_mut(b.start, c);
            solve_unit_lower_triangular_in_place(b.values.submatrix(0, 0, c, c), top.as_mut(), par);
            let mut tmp = MatMut::from_column_major_slice_mut(&mut work[..below * k], below, k);
            matmul(tmp.as_mut(), Accum::Replace, b.values.submatrix(b.columns, 0, below, c), top.as_ref(), 1.0, par);
            for j in 0..k {
                for (p, &i) in b.pattern[..below].iter().enumerate() {
                    y[(i, j)] -= tmp[(p, j)];
                }
            }
        }
        let mut inverse_pivots = vec![0.0; n];
        for b in blocks.iter().filter(|b| b.start < n) {
            let (c, _) = k_part(b);
            for i in 0..c {
                inverse_pivots[b.start + i] = b.values[(i, i)].recip();
            }
        }
        for j in 0..k {
            y.col_mut(j).iter_mut().zip(&inverse_pivots).for_each(|(v, d)| *v *= d);
        }
        for b in blocks.iter().rev().filter(|b| b.start < n) {
            let (c, below) = k_part(b);
            let mut gathered = MatMut::from_column_major_slice_mut(&mut work[..below * k], below, k);
            for j in 0..k {
                for (p, &i) in b.pattern[..below].iter().enumerate() {
                    gathered[(p, j)] = y[(i, j)];
                }
            }
            let mut top = y.as_mut().subrows_mut(b.start, c);
            matmul(
                top.as_mut(),
                Accum::Add,
                b.values.submatrix(b.columns, 0, below, c).transpose(),
                gathered.as_ref(),
                -1.0,
                par,
            );
            solve_unit_upper_triangular_in_place(b.values.submatrix(0, 0, c, c).transpose(), top.as_mut(), par);
        }
        for i in 0..n {
            for j in 0..x.ncols() {
                x[(forward[i], j)] = y[(i, j)];
            }
        }
        true
    }
}

/// The numeric LDLᵀ of the augmented matrix `a` (`K` of order `n` first): `Ok(None)` if the rows'
/// block is not negative definite with moderate multipliers (dependent rows).
///
/// # Errors
/// [`FemError::Factorization`] if the `K` block is not positive definite.
fn numeric_ldlt(symbolic: &SymbolicCholesky<usize>, a: &Csc, n: usize) -> Result<Option<Vec<f64>>, FemError> {
    let par = parallelism();
    let mut values = vec![0.0; symbolic.len_val()];
    let mut mem = MemBuffer::try_new(symbolic.factorize_numeric_ldlt_scratch::<f64>(par, Default::default()))
        .map_err(|e| FemError::Factorization(format!("workspace: {e:?}")))?;
    let not_spd = || {
        FemError::Factorization(
            "stiffness matrix is not positive definite: a body may be unconstrained or an element degenerate".into(),
        )
    };
    let regularization = LdltRegularization::default();
    if let Err(faer::linalg::cholesky::ldlt::factor::LdltError::ZeroPivot { index }) = symbolic.factorize_numeric_ldlt(
        &mut values,
        a.as_ref(),
        Side::Lower,
        regularization,
        par,
        MemStack::new(&mut mem),
        Default::default(),
    ) {
        return if index < n { Err(not_spd()) } else { Ok(None) };
    }
    let Some(blocks) = blocks(symbolic, &values) else { return Ok(None) };
    let (d_k, d_rows) = pivots(&blocks, n, a.nrows());
    if d_k.iter().any(|d| !(d.is_finite() && *d > 0.0)) {
        return Err(not_spd());
    }
    let rows_ok = d_rows.iter().all(|d| d.is_finite() && *d < 0.0)
        && trailing_unit_block(&blocks, n, a.nrows() - n)
            .col_iter()
            .all(|c| c.iter().all(|v| v.abs() <= MAX_MULTIPLIER));
    Ok(rows_ok.then_some(values))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use super::*;
    use crate::test_matrices::grid_laplacian;

    /// Rows like contact pairs: a node against a weighted pair of neighbours, along the edge.
    fn edge_rows(m: usize) -> Vec<Vec<(usize, f64)>> {
        (1..m - 1).map(|j| vec![(j, 1.0), (m + j - 1, -0.25), (m + j + 1, -0.75), (m + j, 0.3)]).collect()
    }

    #[test]
    fn solves_and_condensation_match_the_plain_factor() {
        let (m, k) = (12, grid_laplacian(12, 0.01));
        let rows = edge_rows(m);
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let bordered = CholeskySolver::factor_with_constraints(&k, &refs).expect("SPD with independent rows");
        assert_eq!(bordered.constraint_count(), rows.len());
        let plain = CholeskySolver::factor(&k).expect("SPD");
        let b: Vec<f64> = (0..m * m).map(|i| ((i * 7919) % 13) as f64 - 6.0).collect();
        let (x1, x2) = (bordered.solve(&b), plain.solve(&b));
        // Two backward-stable factorisations of a matrix with condition number ~1e3: the
        // solutions agree to round-off times the condition number.
        let scale = x2.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        assert!(x1.iter().zip(&x2).all(|(a, b)| (a - b).abs() <= 1e-11 * scale));
        let c = bordered.condensed().expect("rows were factored");
        for (p, row_p) in rows.iter().enumerate() {
            let mut e = vec![0.0; m * m];
            row_p.iter().for_each(|&(i, v)| e[i] += v);
            let z = plain.solve(&e);
            for (q, row_q) in rows.iter().enumerate() {
                let exact: f64 = row_q.iter().map(|&(i, v)| v * z[i]).sum();
                // C = B K⁻¹ Bᵀ by two routes; entries are O(0.1–1): 1e-12 absolute is round-off.
                assert!((c[(p, q)] - exact).abs() <= 1e-12, "C[{p},{q}] {} vs {exact}", c[(p, q)]);
            }
        }
    }

    #[test]
    fn many_rows_condense_exactly() {
        let (m, k) = (50, grid_laplacian(50, 0.01));
        // 1 100 rows, independent (each has a DOF of its own): a large dense last block.
        let rows: Vec<Vec<(usize, f64)>> = (0..1100).map(|q| vec![(q, 1.0), (m * m - 1 - q, -0.5)]).collect();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let bordered = CholeskySolver::factor_with_constraints(&k, &refs).expect("SPD with independent rows");
        assert_eq!(bordered.constraint_count(), rows.len());
        let c = bordered.condensed().expect("rows were factored");
        let plain = CholeskySolver::factor(&k).expect("SPD");
        for p in [0, 7, 500, rows.len() - 1] {
            let mut e = vec![0.0; m * m];
            rows[p].iter().for_each(|&(i, v)| e[i] += v);
            let z = plain.solve(&e);
            for q in [0, 3, 499, 1000, rows.len() - 2] {
                let exact: f64 = rows[q].iter().map(|&(i, v)| v * z[i]).sum();
                // As above: two routes to B K⁻¹ Bᵀ, entries O(0.01–1), condition ~1e4.
                assert!((c[(p, q)] - exact).abs() <= 1e-11, "C[{p},{q}] {} vs {exact}", c[(p, q)]);
            }
        }
    }

    #[test]
    fn dependent_rows_fall_back_to_the_plain_factor() {
        let k = grid_laplacian(6, 0.1);
        let rows = [vec![(3usize, 1.0), (4, 2.0)], vec![(3, -2.0), (4, -4.0)]];
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let solver = CholeskySolver::factor_with_constraints(&k, &refs).expect("K is SPD");
        assert_eq!(solver.constraint_count(), 0);
        assert!(solver.condensed().is_none());
    }

    #[test]
    fn an_indefinite_k_is_an_error_not_a_fallback() {
        let k = grid_laplacian(5, -4.5);
        let rows = [vec![(0usize, 1.0)]];
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        assert!(matches!(CholeskySolver::factor_with_constraints(&k, &refs), Err(FemError::Factorization(_))));
    }

    #[test]
    fn refactoring_with_new_values_matches_a_fresh_factor() {
        let (m, k) = (8, grid_laplacian(8, 0.01));
        let rows = edge_rows(m);
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let mut solver = CholeskySolver::factor_with_constraints(&k, &refs).expect("SPD");
        let k2 = grid_laplacian(8, 0.5);
        let scaled: Vec<Vec<(usize, f64)>> =
            rows.iter().map(|r| r.iter().map(|&(i, v)| (i, 2.0 * v)).collect()).collect();
        let refs2: Vec<&[(usize, f64)]> = scaled.iter().map(Vec::as_slice).collect();
        solver.refactor_with_constraints(&k2, &refs2).expect("SPD");
        let fresh = CholeskySolver::factor_with_constraints(&k2, &refs2).expect("SPD");
        // Same symbolic analysis and values: the same bits.
        assert_eq!(solver.condensed(), fresh.condensed());
    }
}

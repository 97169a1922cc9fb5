//! `K` and constraint rows `B` factored together as one sparse symmetric saddle-point system,
//! each row switched on or off per factorisation: the symbolic analysis is done once for every
//! row, the numeric factorisation per choice of rows.
//!
//! ```text
//! A(on) = [K     B_onᵀ]      rows q switched off:  B_q → 0,  A_qq = 1   (so x_q = rhs_q)
//!         [B_on  0    ]      (the pattern keeps every row; only values change)
//! P A Pᵀ = L D Lᵀ            (faer's supernodal LDLᵀ, no pivoting)
//! P:  AMD on the pattern of A with every row, then each row moved to just after the last
//!     DOF of its support (its free columns), the relative order otherwise kept
//! ```
//!
//! `P A Pᵀ` is stored permuted once at the analysis, so each numeric factorisation reads it
//! as it is (faer permutes an unpermuted matrix on every factorisation: 0.065 s of each 0.35 s
//! one at 579k DOFs), and each solve permutes its right-hand side.
//!
//! Why no pivoting is safe: with each row after its support, a leading principal block of
//! `P A Pᵀ` holds some DOFs `E` of `K` and rows whose support lies in `E`:
//! `[K_EE B_Eᵀ; B_E 0]`, non-singular whenever `K` is positive definite and the rows switched
//! on are independent (its Schur complement `−B_E K_EE⁻¹ B_Eᵀ` is then negative definite). So
//! every pivot exists: positive for `K`'s DOFs, negative for the rows (a row's pivot is minus
//! its compliance against what is eliminated before it). faer's elimination tree post-order
//! keeps the property: a row is an ancestor of every DOF of its support.
//!
//! Unlike the bordered factor ([`crate::CholeskySolver::factor_with_constraints`]), whose rows
//! are last and whose last block is dense (`r³/3` flops, `r` rows), the rows here take part in
//! the fill-reducing order: the factor stays sparse, and its cost grows like `K`'s own
//! factorisation.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::ldlt::factor::LdltRegularization;
use faer::reborrow::{Reborrow, ReborrowMut};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::linalg::cholesky::{
    CholeskySymbolicParams, LdltRef, SymbolicCholesky, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Side};

use crate::error::FemError;
use crate::ordering::fill_reducing_permutation_of_pattern;
use crate::solve::parallelism;
use crate::sparse::Csc;

/// `[K Bᵀ; B 0]` with rows switched on and off, analysed once and factored per choice (module
/// docs). The factor's values and the workspaces are allocated once and reused.
pub struct SaddlePointSolver {
    /// Order of `K`.
    n: usize,
    /// The lower triangle of `P A Pᵀ` with every row on.
    matrix: Csc,
    /// `P`: position `p` of `P A Pᵀ` is unknown `forward[p]` of `A`.
    forward: Vec<usize>,
    /// A right-hand side permuted (a solve's workspace).
    permuted: Vec<f64>,
    /// The rows' values as analysed, and where each sits in `matrix`'s values.
    row_entries: Vec<Vec<(usize, f64)>>,
    /// Where each row's diagonal sits in `matrix`'s values.
    row_diagonal: Vec<usize>,
    symbolic: SymbolicCholesky<usize>,
    /// The numeric factor of the last [`SaddlePointSolver::factor`].
    values: Vec<f64>,
    /// Whether `values` holds a successful factorisation.
    factored: bool,
    /// The factorisation's and one solve's workspace.
    memory: MemBuffer,
}

impl std::fmt::Debug for SaddlePointSolver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SaddlePointSolver")
            .field("dim", &self.n)
            .field("rows", &self.row_entries.len())
            .field("factor_nnz", &self.symbolic.len_val())
            .field("factored", &self.factored)
            .finish()
    }
}

impl SaddlePointSolver {
    /// Analyses `[K Bᵀ; B 0]` for `K` (lower triangle, positive definite) and every row that
    /// will ever be switched on (`(free column, coefficient)`; repeated columns add).
    ///
    /// # Errors
    /// [`FemError::Factorization`] if `K` is not square or the analysis fails (out of memory);
    /// [`FemError::InvalidInput`] for a row entry outside `K`.
    pub fn analyse(k: &Csc, rows: &[&[(usize, f64)]]) -> Result<SaddlePointSolver, FemError> {
        crate::solve::check_square(k)?;
        let (n, r) = (k.nrows(), rows.len());
        let (lower, row_entries, row_diagonal) = saddle_lower(k, rows)?;
        // AMD on the whole pattern: it knows that each row joins the DOFs of a pair (AMD on K
        // alone, the rows then inserted, gave 5 times the fill on the long-interface meshes).
        let amd = fill_reducing_permutation_of_pattern(&lower)?;
        // Each row just after the last DOF of its support (a row with no support first).
        let mut position = vec![0usize; n + r];
        for (p, &i) in amd.iter().enumerate() {
            position[i] = p;
        }
        let mut key: Vec<(usize, usize, usize)> = (0..n).map(|i| (position[i], 0, i)).collect();
        for (q, row) in rows.iter().enumerate() {
            let last = row.iter().map(|&(j, _)| position[j]).max();
            key.push(last.map_or((0, 0, n + q), |p| (p, 1 + position[n + q], n + q)));
        }
        key.sort_unstable();
        let forward: Vec<usize> = key.iter().map(|&(_, _, i)| i).collect();
        let mut inverse = vec![0; n + r];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        let (matrix, moved) = permute_lower(&lower, &inverse);
        drop(lower);
        let row_entries =
            row_entries.into_iter().map(|row| row.into_iter().map(|(p, v)| (moved[p], v)).collect()).collect();
        let row_diagonal = row_diagonal.into_iter().map(|p| moved[p]).collect();
        let params =
            CholeskySymbolicParams { supernodal_flop_ratio_threshold: SupernodalThreshold::AUTO, ..Default::default() };
        // faer's analysis without an ordering reads the upper triangle whatever side it is told.
        let upper = matrix
            .symbolic()
            .transpose()
            .to_col_major()
            .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))?;
        let symbolic = factorize_symbolic_cholesky(upper.as_ref(), Side::Upper, SymmetricOrdering::Identity, params)
            .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))?;
        drop(upper);
        let par = parallelism();
        let scratch = symbolic
            .factorize_numeric_ldlt_scratch::<f64>(par, Default::default())
            .or(symbolic.solve_in_place_scratch::<f64>(1, par));
        let memory = MemBuffer::try_new(scratch).map_err(|e| FemError::Factorization(format!("workspace: {e:?}")))?;
        Ok(SaddlePointSolver {
            n,
            matrix,
            permuted: vec![0.0; n + r],
            forward,
            row_entries,
            row_diagonal,
            values: vec![0.0; symbolic.len_val()],
            symbolic,
            factored: false,
            memory,
        })
    }

    /// Order of `K`.
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Number of rows analysed.
    pub fn row_count(&self) -> usize {
        self.row_entries.len()
    }

    /// Number of entries of the factor `L` (lower triangle).
    pub fn factor_nnz(&self) -> usize {
        self.symbolic.len_val()
    }

    /// Factors `A(on)` of the module docs: row `q` as analysed where `on[q]`, else zero with a
    /// unit diagonal.
    ///
    /// # Errors
    /// [`FemError::InvalidInput`] if `on` has the wrong length; [`FemError::Factorization`] on a
    /// zero or non-finite pivot (`K` not positive definite, or dependent rows switched on).
    pub fn factor(&mut self, on: &[bool]) -> Result<(), FemError> {
        self.factor_with_compliance(on, &[])
    }

    /// Factors `A(on)` with `−c_q` on the diagonal of each row `q` switched on (`c` empty: zero):
    ///
    /// ```text
    /// [K     B_onᵀ ]
    /// [B_on  −C_on ]      C = diag(c) ≥ 0  (a compliance in series with the row's constraint)
    /// ```
    ///
    /// The matrix stays quasi-definite (its Schur complement `−(B K⁻¹ Bᵀ + C)` is negative
    /// definite), so the unpivoted LDLᵀ of the module docs still exists.
    ///
    /// # Errors
    /// As [`SaddlePointSolver::factor`]; [`FemError::InvalidInput`] if `compliance` is neither
    /// empty nor one entry per row, or has a negative or non-finite entry.
    pub fn factor_with_compliance(&mut self, on: &[bool], compliance: &[f64]) -> Result<(), FemError> {
        self.factored = false;
        if on.len() != self.row_entries.len() {
            return Err(FemError::InvalidInput(format!(
                "{} row switches for {} rows",
                on.len(),
                self.row_entries.len()
            )));
        }
        if !compliance.is_empty() && compliance.len() != on.len() {
            return Err(FemError::InvalidInput(format!("{} compliances for {} rows", compliance.len(), on.len())));
        }
        if let Some(c) = compliance.iter().find(|c| !c.is_finite() || **c < 0.0) {
            return Err(FemError::InvalidInput(format!("row compliance {c} is negative or not finite")));
        }
        for (q, entries) in self.row_entries.iter().enumerate() {
            let values = self.matrix.val_mut();
            for &(position, value) in entries {
                values[position] = if on[q] { value } else { 0.0 };
            }
            let c = compliance.get(q).copied().unwrap_or(0.0);
            values[self.row_diagonal[q]] = if on[q] { -c } else { 1.0 };
        }
        let par = parallelism();
        // faer zeroes the factor's values itself before its scatter.
        self.symbolic
            .factorize_numeric_ldlt(
                &mut self.values,
                self.matrix.as_ref(),
                Side::Lower,
                LdltRegularization::default(),
                par,
                MemStack::new(&mut self.memory),
                Default::default(),
            )
            .map_err(|e| FemError::Factorization(format!("saddle-point LDLᵀ: {e:?}")))?;
        if self.values.iter().any(|v| !v.is_finite()) {
            return Err(FemError::Factorization("saddle-point LDLᵀ: a pivot is not finite".into()));
        }
        self.factored = true;
        Ok(())
    }

    /// Solves `A(on) x = b` with the last factorisation (`b` of length `dim + row_count`), in
    /// place; `false` (and `b` untouched) if there is none.
    pub fn solve_in_place(&mut self, b: &mut [f64]) -> bool {
        if !self.factored || b.len() != self.n + self.row_entries.len() {
            return false;
        }
        let rows = b.len();
        for (x, &i) in self.permuted.iter_mut().zip(&self.forward) {
            *x = b[i];
        }
        let x = MatMut::from_column_major_slice_mut(&mut self.permuted, rows, 1);
        LdltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            x,
            parallelism(),
            MemStack::new(&mut self.memory),
        );
        for (x, &i) in self.permuted.iter().zip(&self.forward) {
            b[i] = *x;
        }
        true
    }
}

impl SaddlePointSolver {
    /// Solves `A(on) X = B` for the columns of `b` (each of length `dim + row_count`) with the
    /// last factorisation, in place and in one pass over the factor; `false` (and `b`
    /// untouched) if there is none or `b` has the wrong number of rows.
    ///
    /// With every row switched off, `A = [K 0; 0 I]`: the first `dim` entries of each column
    /// are then `K⁻¹ b`, from the factor of the saddle-point system alone.
    pub fn solve_many_in_place(&mut self, mut b: MatMut<'_, f64>) -> bool {
        let rows = self.n + self.row_entries.len();
        if !self.factored || b.nrows() != rows {
            return false;
        }
        let par = parallelism();
        let Ok(mut memory) = MemBuffer::try_new(self.symbolic.solve_in_place_scratch::<f64>(b.ncols(), par)) else {
            return false;
        };
        // Each column permuted through the one-column workspace: no second copy of `b`.
        for c in 0..b.ncols() {
            for (x, &i) in self.permuted.iter_mut().zip(&self.forward) {
                *x = b[(i, c)];
            }
            b.rb_mut().col_mut(c).iter_mut().zip(&self.permuted).for_each(|(b, x)| *b = *x);
        }
        LdltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            b.rb_mut(),
            par,
            MemStack::new(&mut memory),
        );
        for c in 0..b.ncols() {
            self.permuted.iter_mut().zip(b.rb().col(c).iter()).for_each(|(x, b)| *x = *b);
            for (x, &i) in self.permuted.iter().zip(&self.forward) {
                b[(i, c)] = *x;
            }
        }
        true
    }
}

/// Where row `q`'s entries sit in the values of the saddle matrix, with their values.
type RowEntries = Vec<Vec<(usize, f64)>>;

/// The lower triangle of `[K Bᵀ; B 0]` with an explicit diagonal in the rows' block, each row's
/// entries (duplicate columns summed) and the positions of its entries and diagonal.
fn saddle_lower(k: &Csc, rows: &[&[(usize, f64)]]) -> Result<(Csc, RowEntries, Vec<usize>), FemError> {
    let (n, r) = (k.nrows(), rows.len());
    // The rows by column of K: (row, value), in row order, duplicates summed.
    let mut by_column: Vec<Vec<(usize, f64)>> = vec![vec![]; n];
    for (q, row) in rows.iter().enumerate() {
        for &(j, v) in *row {
            if j >= n {
                return Err(FemError::InvalidInput(format!("constraint row: column {j} out of range ({n} DOFs)")));
            }
            match by_column[j].last_mut() {
                Some(last) if last.0 == n + q => last.1 += v,
                _ => by_column[j].push((n + q, v)),
            }
        }
    }
    let kr = k.as_ref();
    let mut col_ptr = Vec::with_capacity(n + r + 1);
    let mut row_idx = Vec::with_capacity(kr.compute_nnz() + rows.iter().map(|r| r.len()).sum::<usize>() + r);
    let mut values = Vec::with_capacity(row_idx.capacity());
    let mut entries: RowEntries = vec![vec![]; r];
    col_ptr.push(0);
    for (j, column) in by_column.iter().enumerate() {
        for (i, v) in kr.row_idx_of_col(j).zip(kr.val_of_col(j)) {
            if i >= j {
                row_idx.push(i);
                values.push(*v);
            }
        }
        for &(i, v) in column {
            entries[i - n].push((values.len(), v));
            row_idx.push(i);
            values.push(v);
        }
        col_ptr.push(row_idx.len());
    }
    let mut diagonal = Vec::with_capacity(r);
    for q in 0..r {
        diagonal.push(values.len());
        row_idx.push(n + q);
        values.push(0.0);
        col_ptr.push(row_idx.len());
    }
    let symbolic = SymbolicSparseColMat::new_checked(n + r, n + r, col_ptr, None, row_idx);
    Ok((SparseColMat::new(symbolic, values), entries, diagonal))
}

/// The lower triangle of `P A Pᵀ` from the lower triangle `a` of `A` (`inverse[i]`: the
/// position of unknown `i` in `P A Pᵀ`), columns sorted, and where each of `a`'s values went.
fn permute_lower(a: &Csc, inverse: &[usize]) -> (Csc, Vec<usize>) {
    let (n, a) = (a.nrows(), a.as_ref());
    // Each entry's new (row, column), lower: counted per new column, then placed by column
    // and sorted within it.
    let new_place = |i: usize, j: usize| {
        let (p, q) = (inverse[i], inverse[j]);
        if p >= q { (p, q) } else { (q, p) }
    };
    let mut col_ptr = vec![0usize; n + 1];
    for j in 0..n {
        for i in a.row_idx_of_col(j) {
            col_ptr[new_place(i, j).1 + 1] += 1;
        }
    }
    for j in 0..n {
        col_ptr[j + 1] += col_ptr[j];
    }
    let mut next = col_ptr.clone();
    let mut placed = vec![(0usize, 0usize); col_ptr[n]];
    let mut old = 0;
    for j in 0..n {
        for i in a.row_idx_of_col(j) {
            let (row, column) = new_place(i, j);
            placed[next[column]] = (row, old);
            next[column] += 1;
            old += 1;
        }
    }
    for j in 0..n {
        placed[col_ptr[j]..col_ptr[j + 1]].sort_unstable();
    }
    let old_values = a.val();
    let mut moved = vec![0; placed.len()];
    let mut row_idx = Vec::with_capacity(placed.len());
    let mut values = Vec::with_capacity(placed.len());
    for (new, &(row, old)) in placed.iter().enumerate() {
        moved[old] = new;
        row_idx.push(row);
        values.push(old_values[old]);
    }
    let symbolic = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
    (SparseColMat::new(symbolic, values), moved)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use super::*;
    use crate::CholeskySolver;
    use crate::test_matrices::grid_laplacian;

    /// The saddle-point solution against the bordered factor's condensation (a second
    /// elimination): `u = K⁻¹(f − Bᵀy)`, `C y = B K⁻¹ f − g` on the rows switched on.
    #[test]
    fn matches_the_condensed_solution_for_any_rows_switched_on() {
        let (m, k) = (10, grid_laplacian(10, 0.01));
        let rows: Vec<Vec<(usize, f64)>> =
            (1..m - 1).map(|j| vec![(j, 1.0), (m + j - 1, -0.25), (m + j + 1, -0.75), (m + j, 0.3)]).collect();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let mut saddle = SaddlePointSolver::analyse(&k, &refs).unwrap();
        let n = m * m;
        let f: Vec<f64> = (0..n).map(|i| ((i * 7) % 11) as f64 - 5.0).collect();
        let g: Vec<f64> = (0..rows.len()).map(|q| 0.1 * q as f64 - 0.3).collect();
        for pattern in [0usize, 0b1011_0110, 0xff] {
            let on: Vec<bool> = (0..rows.len()).map(|q| pattern >> q & 1 == 1).collect();
            saddle.factor(&on).unwrap();
            let mut x: Vec<f64> = f.iter().copied().chain(g.iter().copied()).collect();
            assert!(saddle.solve_in_place(&mut x));
            // Reference: the rows switched on, condensed through the bordered factor.
            let active: Vec<usize> = (0..rows.len()).filter(|&q| on[q]).collect();
            let sub: Vec<&[(usize, f64)]> = active.iter().map(|&q| refs[q]).collect();
            let bordered = CholeskySolver::factor_with_constraints(&k, &sub).unwrap();
            let u0 = bordered.solve(&f);
            let dot = |row: &[(usize, f64)], u: &[f64]| row.iter().map(|&(j, v)| v * u[j]).sum::<f64>();
            let mut y = vec![0.0; active.len()];
            if let Some(c) = bordered.condensed() {
                let rhs: Vec<f64> = active.iter().map(|&q| dot(refs[q], &u0) - g[q]).collect();
                let c = nalgebra::DMatrix::from_fn(c.nrows(), c.ncols(), |i, j| c[(i, j)]);
                let sol = c.lu().solve(&nalgebra::DVector::from_vec(rhs)).unwrap();
                y = sol.iter().copied().collect();
            }
            let mut load = f.clone();
            for (a, &q) in active.iter().enumerate() {
                refs[q].iter().for_each(|&(j, v)| load[j] -= v * y[a]);
            }
            let u = bordered.solve(&load);
            // Two backward-stable eliminations of a system with condition number < 1e4: they
            // agree to ~1e4 ε; 1e-11 of the largest value leaves a margin.
            let scale = x.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            for i in 0..n {
                assert!((x[i] - u[i]).abs() <= 1e-11 * scale, "u[{i}]: {} against {}", x[i], u[i]);
            }
            for (q, &on_q) in on.iter().enumerate() {
                let expected = if on_q { y[active.iter().position(|&a| a == q).unwrap()] } else { g[q] };
                assert!((x[n + q] - expected).abs() <= 1e-11 * scale, "row {q}: {} against {expected}", x[n + q]);
            }
        }
    }

    /// With every row off the saddle-point factor solves with `K` alone: several right-hand
    /// sides at once give `K⁻¹ b` of each (against `K`'s own Cholesky factor) and what a
    /// column-by-column solve gives.
    #[test]
    fn many_right_hand_sides_with_every_row_off_solve_with_k() {
        let (m, k) = (10, grid_laplacian(10, 0.01));
        let rows: Vec<Vec<(usize, f64)>> = (1..m - 1).map(|j| vec![(j, 1.0), (m + j, -0.5)]).collect();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let mut saddle = SaddlePointSolver::analyse(&k, &refs).unwrap();
        let (n, r) = (m * m, rows.len());
        saddle.factor(&vec![false; r]).unwrap();
        let columns = 3;
        let b = faer::Mat::<f64>::from_fn(
            n + r,
            columns,
            |i, c| if i < n { ((i * (c + 3)) % 13) as f64 - 6.0 } else { 0.0 },
        );
        let mut x = b.clone();
        assert!(saddle.solve_many_in_place(x.as_mut()));
        let cholesky = CholeskySolver::factor(&k).unwrap();
        for c in 0..columns {
            let f: Vec<f64> = (0..n).map(|i| b[(i, c)]).collect();
            let u = cholesky.solve(&f);
            let mut one: Vec<f64> = (0..n + r).map(|i| b[(i, c)]).collect();
            assert!(saddle.solve_in_place(&mut one));
            // Two backward-stable factorisations of a matrix with condition number < 1e4 agree
            // to ~1e4 ε; 1e-11 of the largest value leaves a margin. The same factor applied
            // column by column agrees to round-off of the solve itself.
            let scale = u.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            for i in 0..n {
                assert!(
                    (x[(i, c)] - u[i]).abs() <= 1e-11 * scale,
                    "column {c}, u[{i}]: {} against {}",
                    x[(i, c)],
                    u[i]
                );
                assert!((x[(i, c)] - one[i]).abs() <= 1e-13 * scale, "column {c}, u[{i}] against one column");
            }
            for q in 0..r {
                assert_eq!(x[(n + q, c)], 0.0, "a row switched off keeps its right-hand side");
            }
        }
        let mut wrong = faer::Mat::<f64>::zeros(n, 1);
        assert!(!saddle.solve_many_in_place(wrong.as_mut()), "a column of the wrong length is refused");
    }

    /// With compliances on the rows the solution satisfies `K u + Bᵀ y = f` and
    /// `B u − C y = g` (residuals computed from the matrices themselves, not from a second
    /// factorisation): the unpivoted LDLᵀ of the quasi-definite matrix is backward stable.
    #[test]
    fn row_compliances_give_the_regularised_equations() {
        let (m, k) = (8, grid_laplacian(8, 0.01));
        let rows: Vec<Vec<(usize, f64)>> = (1..m - 1).map(|j| vec![(j, 1.0), (m + j, -0.5)]).collect();
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let mut saddle = SaddlePointSolver::analyse(&k, &refs).unwrap();
        let (n, r) = (m * m, rows.len());
        let f: Vec<f64> = (0..n).map(|i| ((i * 5) % 7) as f64 - 3.0).collect();
        let g: Vec<f64> = (0..r).map(|q| 0.2 * q as f64 - 0.5).collect();
        let on = vec![true; r];
        let c: Vec<f64> = (0..r).map(|q| 0.1 * (q % 3) as f64).collect();
        saddle.factor_with_compliance(&on, &c).unwrap();
        let mut x: Vec<f64> = f.iter().chain(&g).copied().collect();
        assert!(saddle.solve_in_place(&mut x));
        let (u, y) = x.split_at(n);
        // K u (lower triangle stored) + Bᵀ y − f.
        let mut residual: Vec<f64> = f.iter().map(|v| -v).collect();
        for j in 0..n {
            for (i, v) in k.as_ref().row_idx_of_col(j).zip(k.as_ref().val_of_col(j)) {
                residual[i] += v * u[j];
                if i != j {
                    residual[j] += v * u[i];
                }
            }
        }
        for (q, row) in rows.iter().enumerate() {
            row.iter().for_each(|&(j, v)| residual[j] += v * y[q]);
            let b_u: f64 = row.iter().map(|&(j, v)| v * u[j]).sum();
            // Condition number < 1e4 on this 8 × 8 grid: residuals ~1e4 ε of the values.
            assert!((b_u - c[q] * y[q] - g[q]).abs() <= 1e-10, "row {q}");
        }
        assert!(residual.iter().all(|v| v.abs() <= 1e-10), "{residual:?}");
        assert!(matches!(saddle.factor_with_compliance(&on, &[1.0]), Err(FemError::InvalidInput(_))));
        let negative = vec![-1.0; r];
        assert!(matches!(saddle.factor_with_compliance(&on, &negative), Err(FemError::InvalidInput(_))));
    }

    /// Every entry of the permuted lower triangle is `A[forward[p], forward[q]]`, each of `A`'s
    /// entries lands once, and the columns come sorted (exact: values are only moved).
    #[test]
    fn permuted_lower_triangle_holds_the_permuted_entries() {
        let k = grid_laplacian(6, 0.3);
        let n = k.nrows();
        let forward: Vec<usize> = (0..n).map(|i| (i * 7 + 3) % n).collect();
        let mut inverse = vec![0; n];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        let (permuted, moved) = permute_lower(&k, &inverse);
        let (a, b) = (k.as_ref(), permuted.as_ref());
        let mut old = 0;
        for j in 0..n {
            for (i, &v) in a.row_idx_of_col(j).zip(a.val_of_col(j)) {
                assert_eq!(b.val()[moved[old]], v);
                old += 1;
                // A is symmetric, stored lower: (i, j) sits at (max, min) of the new indices.
                let (p, q) = (inverse[i].max(inverse[j]), inverse[i].min(inverse[j]));
                let rows: Vec<usize> = b.row_idx_of_col(q).collect();
                assert!(rows.windows(2).all(|w| w[0] < w[1]), "column {q} unsorted");
                assert_eq!(b.val_of_col(q)[rows.iter().position(|&r| r == p).unwrap()], v);
            }
        }
        assert_eq!(b.compute_nnz(), a.compute_nnz());
    }

    #[test]
    fn rejects_rows_out_of_range_and_wrong_switches() {
        let k = grid_laplacian(3, 0.0);
        let bad: &[(usize, f64)] = &[(9, 1.0)];
        assert!(matches!(SaddlePointSolver::analyse(&k, &[bad]), Err(FemError::InvalidInput(_))));
        let good: &[(usize, f64)] = &[(0, 1.0)];
        let mut s = SaddlePointSolver::analyse(&k, &[good]).unwrap();
        assert!(matches!(s.factor(&[]), Err(FemError::InvalidInput(_))));
        let mut b = vec![0.0; 10];
        assert!(!s.solve_in_place(&mut b));
    }
}

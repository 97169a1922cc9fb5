//! What the full-space (not condensed) contact algorithms share: the contact stiffness scale,
//! the offsets of the pair rows, products with `K_ff`, and a sparse LU whose sparsity pattern is
//! fixed for the whole solve.
//!
//! ```text
//! k_c  = mean over pairs k of  Σ_i b_ki² K_ii / Σ_i b_ki²     (b_k: the free part of B_N row k)
//! gap_k(u) = ĝ_k + b_k · u_f,   ĝ_k = g0_k + w (B_N,c u_c)_k
//! s_k(u)   = ŝ_k + t_k · u_f,   ŝ_k = w (B_T,c u_c)_k
//! ```
//!
//! `k_c` is the stiffness of the contact DOFs along the normals: the force per unit gap a pair's
//! own nodes resist with when all other DOFs are held. It is a local, mesh-level quantity (no
//! condensation needed) with units of force per length, so a penalty `ε = κ k_c` with a
//! dimensionless `κ` makes the penetration `λ/ε` a fraction `1/κ` of the displacement a force
//! `λ` produces on the pair's own nodes. It is the `c` of the augmented Lagrangian's
//! complementarity functions for the same reason.
//!
//! The LU keeps one symbolic factorisation (column ordering, supernodes) for a pattern given up
//! front: the algorithms list every entry any state could use (explicit zeros where the current
//! state does not), so each Newton iteration is one numeric factorisation.

use contact2d_fem::parallelism;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::lu::{LuRef, NumericLu, SymbolicLu, factorize_symbolic_lu};
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};
use faer::{Conj, Mat};

use crate::problem::{ContactProblem, PairRow};

/// The contact stiffness scale `k_c` of the module docs (force per length). Falls back to the
/// problem's [`ContactProblem::stiffness_scale`] when no normal row has a free DOF.
pub fn contact_stiffness(problem: &ContactProblem) -> f64 {
    let k = problem.system.stiffness.as_ref();
    let diagonal =
        |i: usize| k.row_idx_of_col(i).zip(k.val_of_col(i)).find(|(r, _)| *r == i).map_or(0.0, |(_, v)| v.abs());
    let (mut sum, mut count) = (0.0, 0usize);
    for row in &problem.normal_rows {
        let norm: f64 = row.free.iter().map(|(_, v)| v * v).sum();
        if norm > 0.0 {
            sum += row.free.iter().map(|(i, v)| v * v * diagonal(*i)).sum::<f64>() / norm;
            count += 1;
        }
    }
    if count > 0 && sum > 0.0 { sum / count as f64 } else { problem.stiffness_scale.max(f64::MIN_POSITIVE) }
}

/// The constrained parts of the pair rows at load `w`: `(ĝ, ŝ)` of the module docs.
pub(crate) fn row_offsets(problem: &ContactProblem, w: f64) -> (Vec<f64>, Vec<f64>) {
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let part = |row: &PairRow| row.constrained.iter().map(|(j, v)| v * prescribed[*j]).sum::<f64>();
    let normal = problem.normal_rows.iter().zip(&problem.gap).map(|(r, g0)| g0 + part(r)).collect();
    let tangent = problem.tangent_rows.iter().map(part).collect();
    (normal, tangent)
}

/// `row · u_f` (free part only).
pub(crate) fn dot_free(row: &PairRow, u_free: &[f64]) -> f64 {
    row.free.iter().map(|(i, v)| v * u_free[*i]).sum()
}

/// Every entry `(i, j, K_ij)` of `K_ff`, both triangles (the stiffness stores its lower one).
pub(crate) fn stiffness_entries(problem: &ContactProblem) -> Vec<(usize, usize, f64)> {
    let k = problem.system.stiffness.as_ref();
    let mut out = Vec::with_capacity(2 * k.compute_nnz());
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            out.push((i, j, *v));
            if i != j {
                out.push((j, i, *v));
            }
        }
    }
    out
}

/// `K_ff u` from the stored lower triangle.
pub(crate) fn stiffness_times(problem: &ContactProblem, u: &[f64]) -> Vec<f64> {
    let k = problem.system.stiffness.as_ref();
    let mut out = vec![0.0; u.len()];
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            out[i] += v * u[j];
            if i != j {
                out[j] += v * u[i];
            }
        }
    }
    out
}

/// A square sparse matrix of fixed pattern (entries listed once, duplicates summed) and its LU
/// factorisation with partial pivoting: symbolic once, numeric per [`FixedPatternLu::factor`].
/// The safeguard of the semi-smooth Newton methods: from `x` towards the Newton target `x̂`
/// (merit `Φ(x̂)` = `target_merit`), the first step `α = 1, ½, …, 1/16` with the Armijo decrease
/// `Φ(x + α (x̂ − x)) ≤ (1 − 1e-4 α) Φ(x)`, or the full step when none decreases Φ (non-monotone).
/// Returns `(α, x_next, Φ(x_next))`.
pub(crate) fn backtrack(
    x: &[f64],
    target: Vec<f64>,
    merit: f64,
    target_merit: f64,
    merit_of: impl Fn(&[f64]) -> f64,
) -> (f64, Vec<f64>, f64) {
    let armijo = |alpha: f64, value: f64| value <= (1.0 - 1e-4 * alpha) * merit;
    if armijo(1.0, target_merit) {
        return (1.0, target, target_merit);
    }
    let mut alpha = 1.0;
    while alpha > 1.0 / 16.0 {
        alpha *= 0.5;
        let trial: Vec<f64> = x.iter().zip(&target).map(|(a, b)| a + alpha * (b - a)).collect();
        let value = merit_of(&trial);
        if armijo(alpha, value) {
            return (alpha, trial, value);
        }
    }
    (1.0, target, target_merit)
}

pub(crate) struct FixedPatternLu {
    dim: usize,
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    lu_symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    factored: bool,
}

impl FixedPatternLu {
    /// Analyses the pattern of the `dim × dim` matrix with entries at `(row, col)` of `pattern`
    /// (in the order the values will be given). `None` if faer rejects it (index out of range,
    /// out of memory).
    pub(crate) fn new(dim: usize, pattern: &[(usize, usize)]) -> Option<FixedPatternLu> {
        let pairs: Vec<Pair<usize, usize>> = pattern.iter().map(|&(row, col)| Pair { row, col }).collect();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(dim, dim, &pairs).ok()?;
        let lu_symbolic = factorize_symbolic_lu(symbolic.as_ref(), Default::default()).ok()?;
        Some(FixedPatternLu { dim, symbolic, argsort, lu_symbolic, numeric: NumericLu::new(), factored: false })
    }

    /// Numeric factorisation of the matrix with `values` (one per pattern entry). `false` on
    /// failure (the matrix is then unusable until the next successful call).
    pub(crate) fn factor(&mut self, values: &[f64]) -> bool {
        self.factored = false;
        let Ok(matrix) = SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, values) else {
            return false;
        };
        let par = parallelism();
        let Ok(mut memory) =
            MemBuffer::try_new(self.lu_symbolic.factorize_numeric_lu_scratch::<f64>(par, Default::default()))
        else {
            return false;
        };
        let done = self.lu_symbolic.factorize_numeric_lu(
            &mut self.numeric,
            matrix.as_ref(),
            par,
            MemStack::new(&mut memory),
            Default::default(),
        );
        self.factored = done.is_ok();
        self.factored
    }

    /// `A⁻¹ b` with the last factorisation; `None` if there is none or the answer is not finite
    /// (a singular matrix).
    pub(crate) fn solve(&self, rhs: &[f64]) -> Option<Vec<f64>> {
        if !self.factored || rhs.len() != self.dim {
            return None;
        }
        let par = parallelism();
        let mut x = Mat::<f64>::from_fn(self.dim, 1, |i, _| rhs[i]);
        let mut memory = MemBuffer::try_new(self.lu_symbolic.solve_in_place_scratch::<f64>(1, par)).ok()?;
        LuRef::new_unchecked(&self.lu_symbolic, &self.numeric).solve_in_place_with_conj(
            Conj::No,
            x.as_mut(),
            par,
            MemStack::new(&mut memory),
        );
        let out: Vec<f64> = (0..self.dim).map(|i| x[(i, 0)]).collect();
        out.iter().all(|v| v.is_finite()).then_some(out)
    }
}

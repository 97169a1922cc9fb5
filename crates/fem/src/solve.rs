//! Sparse Cholesky solves through faer, with the symbolic factorisation kept for reuse.
//!
//! ```text
//! K_ff = P Lᵀ... : symbolic analysis (AMD ordering, elimination tree, supernodes) once per
//! sparsity pattern; numeric factorisation K_ff = L Lᵀ whenever the values change.
//! ```

use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::{Mat, Side};

use crate::assembly::Csc;
use crate::error::FemError;

/// A Cholesky factorisation of a symmetric positive definite matrix stored as its lower triangle.
#[derive(Debug, Clone)]
pub struct CholeskySolver {
    symbolic: SymbolicLlt<usize>,
    factor: Llt<usize, f64>,
    dim: usize,
}

fn numeric(symbolic: &SymbolicLlt<usize>, k: &Csc) -> Result<Llt<usize, f64>, FemError> {
    Llt::try_new_with_symbolic(symbolic.clone(), k.as_ref(), Side::Lower).map_err(|e| {
        FemError::Factorization(format!(
            "stiffness matrix is not positive definite ({e:?}): a body may be unconstrained or an element degenerate"
        ))
    })
}

impl CholeskySolver {
    /// Analyses and factors `k` (lower triangle).
    ///
    /// # Errors
    /// [`FemError::Factorization`] if `k` is not square or not positive definite.
    pub fn factor(k: &Csc) -> Result<CholeskySolver, FemError> {
        if k.nrows() != k.ncols() {
            return Err(FemError::Factorization(format!("matrix is {}×{}, not square", k.nrows(), k.ncols())));
        }
        let symbolic = SymbolicLlt::try_new(k.symbolic(), Side::Lower)
            .map_err(|e| FemError::Factorization(format!("symbolic analysis: {e:?}")))?;
        let factor = numeric(&symbolic, k)?;
        Ok(CholeskySolver { symbolic, factor, dim: k.nrows() })
    }

    /// Refactors with new values on the same sparsity pattern, reusing the symbolic analysis.
    ///
    /// # Errors
    /// [`FemError::Factorization`] if the pattern's size differs or the matrix is not positive definite.
    pub fn refactor(&mut self, k: &Csc) -> Result<(), FemError> {
        if k.nrows() != self.dim || k.ncols() != self.dim {
            return Err(FemError::Factorization("refactor: matrix size changed".into()));
        }
        self.factor = numeric(&self.symbolic, k)?;
        Ok(())
    }

    /// Dimension of the system.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Solves `K x = b`.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let rhs = Mat::from_fn(b.len(), 1, |i, _| b[i]);
        let x = self.factor.solve(&rhs);
        (0..b.len()).map(|i| x[(i, 0)]).collect()
    }

    /// Solves `K X = B` for several right-hand sides at once.
    pub fn solve_many(&self, b: &Mat<f64>) -> Mat<f64> {
        self.factor.solve(b)
    }
}

//! `K_ff`'s factorisation, shared by the copies of a problem and, on the sparse path, made only
//! when something first asks for it.
//!
//! ```text
//! K_ff = L Lᵀ  (bordered by the pair rows below SPARSE_FROM_PAIRS: crate::problem)
//! ```
//!
//! Below [`crate::SPARSE_FROM_PAIRS`] pairs the problem factors `K_ff` bordered by its pair rows
//! as it is built: the condensed path's compliances come from that factor. Beyond, the sparse
//! path's active set solves every contact state on the saddle-point system (`crate::kkt`),
//! whose factor with every row switched off is `K_ff`'s own, and never reads a Cholesky factor
//! of `K_ff`: at 5,001 pairs on the long-interface benchmark that factor holds 48.2 M entries
//! (0.39 GB) and takes 1.3 s. It is then made at the first solve that needs it: floating
//! bodies' rigid-motion iteration, the augmented Lagrangian's and the penalty method's first
//! guess, and the condensed path asked for where bordering `K` by the pair rows fails
//! (dependent rows; it borders `K` itself otherwise).

use std::sync::{Arc, OnceLock};

use contact2d_fem::{CholeskySolver, FemError, LinearSystem};
use faer::Mat;

use crate::error::ContactError;

/// `K_ff`'s factor (or the factor bordered by the pair rows), made now or at the first solve.
#[derive(Debug, Clone)]
pub(crate) struct StiffnessFactor {
    system: Arc<LinearSystem>,
    /// The factor, or why `K_ff` could not be factored; shared by every clone.
    factor: Arc<OnceLock<Result<CholeskySolver, String>>>,
}

impl StiffnessFactor {
    /// A factor already made (of `system`'s `K_ff`, bordered or not).
    pub(crate) fn made(system: Arc<LinearSystem>, solver: CholeskySolver) -> StiffnessFactor {
        StiffnessFactor { system, factor: Arc::new(OnceLock::from(Ok(solver))) }
    }

    /// `K_ff` of `system`, factored at the first call of [`StiffnessFactor::get`].
    pub(crate) fn deferred(system: Arc<LinearSystem>) -> StiffnessFactor {
        StiffnessFactor { system, factor: Arc::new(OnceLock::new()) }
    }

    /// Order of `K_ff` (free DOFs).
    pub(crate) fn dim(&self) -> usize {
        self.system.dofs.num_free()
    }

    /// The factor, made now if it was deferred (a supernodal Cholesky factorisation of `K_ff`).
    ///
    /// # Errors
    /// [`ContactError::Fem`] if `K_ff` is not positive definite (the same error each call).
    pub(crate) fn get(&self) -> Result<&CholeskySolver, ContactError> {
        let made = self
            .factor
            .get_or_init(|| CholeskySolver::factor_supernodal(&self.system.stiffness).map_err(|e| e.to_string()));
        made.as_ref().map_err(|e| ContactError::Fem(FemError::Factorization(e.clone())))
    }

    /// The factor if it has been made.
    pub(crate) fn if_made(&self) -> Option<&CholeskySolver> {
        self.factor.get().and_then(|f| f.as_ref().ok())
    }

    /// `K_ff⁻¹ b`, or NaN in every entry if `K_ff` cannot be factored. Only a deferred factor
    /// can fail here (a factor made with the problem was checked as it was built), and a NaN
    /// answer is reported as a numerical failure by the statuses' finiteness check.
    pub(crate) fn solve_or_nan(&self, b: &[f64]) -> Vec<f64> {
        self.get().map_or_else(|_| vec![f64::NAN; b.len()], |s| s.solve(b))
    }

    /// `K_ff⁻¹ B` column by column, with the failure of [`StiffnessFactor::solve_or_nan`].
    pub(crate) fn solve_many_or_nan(&self, b: &Mat<f64>) -> Mat<f64> {
        self.get().map_or_else(|_| Mat::from_fn(b.nrows(), b.ncols(), |_, _| f64::NAN), |s| s.solve_many(b))
    }
}

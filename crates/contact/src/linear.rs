//! Which linear algebra solves the contact states: the condensed interface or the sparse full
//! system, chosen by a measured rule or forced by the user (`solver.linear` in scene files).
//!
//! ```text
//! condensed  C = B K⁻¹ Bᵀ dense (2 pairs × 2 pairs), each state's reduced system a dense LU:
//!            (2m)³ flops and (2m)² memory — fastest up to a few thousand pairs
//! sparse     each state's [K Bᵀ; B 0] factored sparse (crate::kkt): the cost of K's sparse
//!            factorisation per change of state, no dense block — fastest above
//! auto       sparse for the active set from SPARSE_FROM_PAIRS pairs on, condensed below and
//!            for the algorithms that need the compliances (Clarabel, Boussinesq)
//! ```
//!
//! The threshold is measured on the long-interface benchmark (docs/benchmarks.md, "Sparse
//! contact solves"): a one-step press is faster condensed at 761 pairs (2.1 against 4.5 s CPU)
//! and sparse from 1,521 (11.7 against 13.3 s; 3.4 times at 3,041); a 40-step history, whose
//! condensed path reuses the LU of repeated states, is faster condensed at every size measured
//! (up to 1,521 pairs). 2,000 lies between the two crossovers.

use crate::algorithm::ContactAlgorithm;
use crate::error::ContactError;

/// The pair count from which [`LinearSolver::Auto`] takes the sparse path for the active set
/// (and from which a problem factors `K` without the pair rows,
/// [`crate::ContactProblem::is_bordered`]).
pub const SPARSE_FROM_PAIRS: usize = 2_000;

/// How the contact states' linear equations are solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum LinearSolver {
    /// [`LinearSolver::Sparse`] for the active set, the augmented Lagrangian and the penalty
    /// method from [`SPARSE_FROM_PAIRS`] pairs on, else [`LinearSolver::Condensed`].
    #[default]
    Auto,
    /// The interface condensed onto the pairs ([`crate::Interface::new`]).
    Condensed,
    /// The full system, sparse ([`crate::Interface::sparse`]); not for Clarabel and the
    /// Boussinesq algorithm, which work on the compliances.
    Sparse,
}

impl LinearSolver {
    /// Every choice, in declaration order.
    pub const ALL: [LinearSolver; 3] = [LinearSolver::Auto, LinearSolver::Condensed, LinearSolver::Sparse];

    /// The name scene files use (`solver.linear`).
    pub fn key(self) -> &'static str {
        match self {
            LinearSolver::Auto => "auto",
            LinearSolver::Condensed => "condensed",
            LinearSolver::Sparse => "sparse",
        }
    }

    /// Whether `algorithm` can run on the sparse path (it needs no compliances).
    pub fn sparse_supports(algorithm: ContactAlgorithm) -> bool {
        matches!(
            algorithm,
            ContactAlgorithm::ActiveSet | ContactAlgorithm::AugmentedLagrangian | ContactAlgorithm::Penalty
        )
    }

    /// The path taken for `algorithm` on `pairs` pairs: [`LinearSolver::Condensed`] or
    /// [`LinearSolver::Sparse`].
    ///
    /// # Errors
    /// [`ContactError::NotApplicable`] for [`LinearSolver::Sparse`] with an algorithm that needs
    /// the compliances.
    pub fn resolve(self, algorithm: ContactAlgorithm, pairs: usize) -> Result<LinearSolver, ContactError> {
        match self {
            LinearSolver::Auto if LinearSolver::sparse_supports(algorithm) && pairs >= SPARSE_FROM_PAIRS => {
                Ok(LinearSolver::Sparse)
            }
            LinearSolver::Auto | LinearSolver::Condensed => Ok(LinearSolver::Condensed),
            LinearSolver::Sparse if LinearSolver::sparse_supports(algorithm) => Ok(LinearSolver::Sparse),
            LinearSolver::Sparse => Err(ContactError::NotApplicable {
                algorithm: algorithm.key(),
                reason: "it works on the condensed compliances; use solver.linear = \"condensed\" or \"auto\"".into(),
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn auto_takes_the_sparse_path_from_the_threshold_for_the_algorithms_that_support_it() {
        let auto = LinearSolver::Auto;
        assert_eq!(auto.resolve(ContactAlgorithm::ActiveSet, SPARSE_FROM_PAIRS - 1).unwrap(), LinearSolver::Condensed);
        assert_eq!(auto.resolve(ContactAlgorithm::ActiveSet, SPARSE_FROM_PAIRS).unwrap(), LinearSolver::Sparse);
        assert_eq!(auto.resolve(ContactAlgorithm::Clarabel, 10 * SPARSE_FROM_PAIRS).unwrap(), LinearSolver::Condensed);
        assert_eq!(
            LinearSolver::Condensed.resolve(ContactAlgorithm::ActiveSet, 1 << 20).unwrap(),
            LinearSolver::Condensed
        );
        assert_eq!(LinearSolver::Sparse.resolve(ContactAlgorithm::ActiveSet, 1).unwrap(), LinearSolver::Sparse);
        for algorithm in [ContactAlgorithm::Clarabel, ContactAlgorithm::Boussinesq] {
            assert!(matches!(LinearSolver::Sparse.resolve(algorithm, 1), Err(ContactError::NotApplicable { .. })));
        }
        let keys: Vec<&str> = LinearSolver::ALL.iter().map(|l| l.key()).collect();
        assert_eq!(keys, ["auto", "condensed", "sparse"]);
    }
}

//! The algorithms a contact problem can be solved with, by name: one variant per algorithm of
//! `algorithms/`, dispatched by [`crate::solve()`]. A module of its own so that what only names an
//! algorithm (the settings, the choice of linear solver) imports no solver.

/// Which algorithm solves each step. Adding an algorithm is one file plus one variant here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ContactAlgorithm {
    /// Primal-dual active set on the condensed interface (frictional or not).
    ActiveSet,
    /// Clarabel: frictionless QP, or Tresca QPs to the Coulomb fixed point (the independent
    /// check).
    Clarabel,
    /// The paper's paired-node Boussinesq algorithm: one contact zone growing from the end of
    /// the master curve where the initial gap is smallest, stick inside slip. Loads must grow.
    Boussinesq,
    /// The penalty method with a regularised Coulomb law on the full system (penalties from
    /// [`SolverSettings::penalty`](crate::SolverSettings::penalty)); status [`ContactStatus::Penalised`](crate::ContactStatus::Penalised) where its penetration
    /// fails the exact certificate.
    Penalty,
    /// The augmented Lagrangian of Alart and Curnier by a semi-smooth Newton method on the full
    /// (not condensed) system: one sparse LU per iteration.
    AugmentedLagrangian,
}

impl ContactAlgorithm {
    /// Every algorithm, in declaration order (for comparisons that run them all).
    pub const ALL: [ContactAlgorithm; 5] = [
        ContactAlgorithm::ActiveSet,
        ContactAlgorithm::Clarabel,
        ContactAlgorithm::Boussinesq,
        ContactAlgorithm::Penalty,
        ContactAlgorithm::AugmentedLagrangian,
    ];

    /// The name scene files use (`solver.algorithm`).
    pub fn key(self) -> &'static str {
        match self {
            ContactAlgorithm::ActiveSet => "active_set",
            ContactAlgorithm::Clarabel => "clarabel",
            ContactAlgorithm::Boussinesq => "boussinesq",
            ContactAlgorithm::Penalty => "penalty",
            ContactAlgorithm::AugmentedLagrangian => "augmented_lagrangian",
        }
    }
}

//! The contact algorithms, each one file, all taking the same [`crate::ContactProblem`] (and the
//! condensed [`crate::Interface`] where they work on it) and returning the same
//! [`crate::ContactSolution`]; [`crate::solve()`] dispatches to them by [`crate::ContactAlgorithm`].
//!
//! ```text
//! frictionless_active_set   primal-dual active set on the condensed interface, μ = 0
//! frictional_active_set     the same with Coulomb friction (stick / slip± states)
//! boussinesq                the paper's paired-node algorithm: zones assumed, (5.1) checked
//! clarabel_qp               the frictionless QP in the contact forces (dual, condensed; Clarabel)
//! clarabel_tresca           Tresca QPs to the Coulomb fixed point (Clarabel)
//! penalty                   normal penalty and regularised Coulomb law (condensed or full system)
//! augmented_lagrangian      Alart–Curnier semi-smooth Newton (condensed, or full system: sparse LU)
//! full_system               contact stiffness scale and fixed-pattern sparse LU (shared)
//! pair_space                penalty / augmented Lagrangian iterations condensed onto the pair rows
//! state_equations           the linear system of a given zone configuration (shared)
//! state_layout              which unknowns a zone configuration leaves open (shared)
//! state_update              a state's system as a low-rank update of the last factored one
//! sparse_active_set         the active set on the sparse full system (crate::kkt), no condensation
//! semi_smooth               the state update and admissibility test of both active-set paths (shared)
//! stick_continuation        regularised stick stages before the exact law (both active-set paths)
//! coarse_start              a long interface's starting states from coarser sets of its pairs
//! ```

pub mod augmented_lagrangian;
pub mod boussinesq;
pub mod clarabel_qp;
pub mod clarabel_tresca;
pub(crate) mod coarse_start;
pub mod frictional_active_set;
pub mod frictionless_active_set;
pub mod full_system;
pub(crate) mod pair_space;
pub mod penalty;
pub(crate) mod semi_smooth;
pub(crate) mod sparse_active_set;
pub(crate) mod state_equations;
pub(crate) mod state_layout;
pub(crate) mod state_update;
pub mod stick_continuation;

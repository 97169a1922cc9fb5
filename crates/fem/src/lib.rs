//! The finite-element layer of contact2d: mesh → model → assembly → solve → solution.
//!
//! ```text
//! Model::new(mesh) + add_body(region, material) + fix(group, component, value) + add_edge_load
//!   → assemble (parallel, Dirichlet eliminated, K_ff lower triangle in faer CSC)
//!   → fill_reducing_permutation (AMD or nested dissection, chosen DOFs last; optional)
//!   → CholeskySolver::factor / factor_with_permutation (symbolic analysis kept for refactoring)
//!     or factor_with_constraints (K bordered by rows B: solves with K and C = B K⁻¹ Bᵀ)
//!   → ElementMatrices::assemble_moved (a morphed copy: the unmoved cells' matrices reused)
//!   → Solution (displacements, reactions) → strain_energy, nodal_stresses, stresses_along_curve
//! ```
//!
//! # Examples
//! A unit square of Quad4 pulled by a prescribed displacement: see `tests/` and the README.

pub mod assembly;
mod cell_matrix;
mod constrained;
pub mod dof;
pub mod error;
pub mod model;
mod model_dofs;
pub mod ordering;
mod pattern;
pub mod reassembly;
pub mod recovery;
pub mod rigid;
pub mod saddle;
pub mod solution;
pub mod solve;
mod sparse;
#[cfg(test)]
mod test_matrices;

pub use assembly::{Csc, FLOATING_PIN_STIFFNESS, LinearSystem, assemble, assemble_body_forces, assemble_edge_loads};
pub use dof::{Component, Dof, DofKind, DofMap};
pub use error::FemError;
pub use model::{Body, BodyId, Dirichlet, EdgeLoad, Model, element_type};
pub use ordering::{COMPRESS_FROM, Ordering, fill_reducing_permutation, twin_compressed_amd};
pub use reassembly::ElementMatrices;
pub use recovery::{CurveSample, StressRecovery, nodal_stress_states, nodal_stresses, stresses_along_curve};
pub use rigid::{FloatingPiece, check_rigid_modes, floating_pieces};
pub use saddle::SaddlePointSolver;
pub use solution::{Solution, solve_linear, strain_energy};
pub use solve::{CholeskySolver, parallelism};

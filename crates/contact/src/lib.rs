//! Contact between elastic bodies: pairing, one contact problem, several algorithms.
//!
//! ```text
//! contours (mesh) → pair_contours → ContactProblem (K factored once, B_N, B_T, gaps, μ)
//!   → Interface (condensed compliances) → algorithms → ContactSolution (status, u, λ, τ, KKT)
//! placement: the Boussinesq algorithm's zone ends placed on nodes moved along a morphable master
//!   curve (any geometry that implements placement::PlaceableContact)
//! ```
//!
//! Sign conventions: `n` points out of the slave body towards the master; `λ ≥ 0` is the
//! compressive normal force on the master node; the paper's pressure is `p = −λ / w` with `w` the
//! master node's tributary length, so `p < 0` in contact.

// The shared test fixtures name the crate by its external name.
#[cfg(test)]
extern crate self as contact2d_contact;

/// The contact crate's test problems, shared by its unit tests and its integration tests.
#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, dead_code)]
#[path = "../tests/fixtures/two_blocks.rs"]
mod test_fixtures;

pub mod algorithm;
pub mod algorithms;
pub mod builder;
pub mod certify;
pub mod description;
pub mod error;
mod factor_cache;
pub mod finite_sliding;
mod floating;
mod force_span;
pub mod history;
mod holding;
pub mod interface;
mod kkt;
pub mod linear;
pub mod loading;
mod pair_rows;
pub mod pairing;
pub mod placement;
pub mod post;
pub mod problem;
pub mod reactions;
pub mod report;
pub mod segment_to_segment;
mod side;
pub mod solution;
pub mod solve;
pub mod stages;
mod stiffness_factor;

pub use algorithms::augmented_lagrangian::{solve_augmented_lagrangian, solve_augmented_lagrangian_condensed};
pub use algorithms::full_system::contact_stiffness;
pub use algorithms::penalty::{PenaltyParameters, solve_penalty, solve_penalty_condensed};
pub use algorithms::stick_continuation::StickContinuation;
pub use algorithms::{boussinesq, clarabel_qp, clarabel_tresca, frictional_active_set, frictionless_active_set};
pub use boussinesq::{
    BoussinesqLoading, BoussinesqStep, ZoneForces, Zones, finish_zones, solve_boussinesq_history,
    solve_boussinesq_step, solve_given_zones,
};
pub use builder::{
    BodyDescription, BuiltProblem, ContactDescription, EdgeLoadKind, FixDescription, GapDescription, InterfaceInfo,
    LoadDescription, NodeFixDescription, NodeLoadDescription, Pairing, ProblemDescription,
};
pub use certify::{Check, EnergyAllowance, FailedCheck, certify, check_energy_balance, energy_scale, status_reason};
pub use clarabel_qp::{solve_frictionless_qp, solve_frictionless_qp_on};
pub use clarabel_tresca::{solve_frictional_qp, solve_frictional_qp_from, solve_frictional_qp_on};
pub use error::ContactError;
pub use finite_sliding::solve_finite_sliding;
pub use floating::NotHeld;
pub use frictional_active_set::{solve_frictional_active_set, solve_frictional_active_set_with};
pub use frictionless_active_set::solve_frictionless_active_set;
pub use history::{HistoryStep, Retention, equal_steps};
pub use interface::Interface;
pub use linear::{LinearSolver, SPARSE_FROM_PAIRS};
pub use loading::LoadSchedule;
pub use pairing::{
    ContactPair, IntegratedRows, RowCoefficient, node_to_node_targets, nodes_face_each_other, pair_contours,
    tributary_weights, tributary_weights_in,
};
pub use post::{contact_end, contact_end_from_pressure, pair_tractions, stick_end};
pub use problem::{BuildTimes, ContactProblem, LoadPattern, PairRow, SparseRow, condensed_rows};
pub use report::{RawSolution, fem_solution, finish_from_displacement, finish_from_forces};
pub use segment_to_segment::pair_segments;
pub use solution::{ContactSolution, ContactStatus, IterationRecord, KktResiduals, PairState, StepStart, Violation};
pub use solve::{ContactAlgorithm, History, SolvedStep, SolverSettings, solve, solve_keeping, solve_with};
pub use stages::{Stage, StageActivity, solve_stages};

//! Errors of the fem crate.

use contact2d_element::ElementError;
use contact2d_mesh::MeshError;
use thiserror::Error;

/// Everything that can go wrong building or solving a finite-element model.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum FemError {
    /// A mesh query failed (unknown physical group, bad contour, ...).
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// An element of a body is inverted (det J changes sign inside it) or degenerate. Cells whose
    /// nodes merely run clockwise are renumbered by [`crate::Model::add_body`], never reported.
    #[error(
        "body \"{body}\": element {cell} is inverted or degenerate (det J = {det_j:.3e} changes sign or vanishes \
         inside it; a node is on the wrong side of the element)"
    )]
    InvertedElement {
        /// Body name.
        body: String,
        /// The mesh's element tag.
        cell: u64,
        /// The determinant found.
        det_j: f64,
    },
    /// Another element-level failure, with the cell it happened in.
    #[error("body \"{body}\", element {cell}: {source}")]
    Element {
        /// Body name.
        body: String,
        /// The mesh's element tag.
        cell: u64,
        /// The element error.
        source: ElementError,
    },
    /// A region holds cells the model cannot use as 2D elements.
    #[error("physical group \"{group}\": {reason}")]
    InvalidRegion {
        /// Group name.
        group: String,
        /// What is wrong.
        reason: String,
    },
    /// A parameter outside its admissible range.
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// Two Dirichlet conditions prescribe different values for the same DOF.
    #[error("conflicting Dirichlet conditions at node tag {node_tag}, {component}: {first} vs {second}")]
    ConflictingDirichlet {
        /// The file's node tag.
        node_tag: u64,
        /// "u1" or "u2".
        component: &'static str,
        /// Value prescribed first.
        first: f64,
        /// Value prescribed second.
        second: f64,
    },
    /// Local directions (`un`, `ut`) that cannot hold: a node also held in `u1` / `u2`, or on two
    /// curves with different normals.
    #[error("local directions (un, ut) on \"{group}\" at node tag {node_tag}: {reason}")]
    LocalDirections {
        /// The group of the `un` / `ut` fix.
        group: String,
        /// The file's node tag.
        node_tag: u64,
        /// What conflicts.
        reason: String,
    },
    /// A body (or a disconnected piece of one) is not held against rigid motion.
    #[error(
        "body \"{body}\" is not constrained against rigid motion: {free_modes} rigid mode(s) free (piece containing node tag {node_tag})"
    )]
    UnconstrainedBody {
        /// Body name.
        body: String,
        /// Number of rigid modes (of 3) left free.
        free_modes: usize,
        /// A node of the unconstrained piece.
        node_tag: u64,
    },
    /// The sparse factorisation failed.
    #[error("factorisation failed: {0}")]
    Factorization(String),
}

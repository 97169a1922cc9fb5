//! Errors of the element crate.

use thiserror::Error;

/// Everything that can go wrong in element-level computations.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ElementError {
    /// The isoparametric map is inverted or degenerate at a point (det J ≤ 0).
    #[error("non-positive Jacobian determinant {det_j:.3e} at reference point ({:.3}, {:.3})", xi[0], xi[1])]
    NonPositiveJacobian {
        /// The determinant found.
        det_j: f64,
        /// The reference point where it was evaluated.
        xi: [f64; 2],
    },
    /// A degenerate edge (zero length element).
    #[error("degenerate edge: zero arc-length derivative at ξ = {xi:.3}")]
    DegenerateEdge {
        /// The reference point.
        xi: f64,
    },
    /// Material parameters outside their admissible range.
    #[error("invalid material: {reason}")]
    InvalidMaterial {
        /// What is wrong.
        reason: String,
    },
    /// The number of coordinates does not match the element's node count.
    #[error("{element} needs {expected} nodes, got {got}")]
    WrongNodeCount {
        /// Element type name.
        element: &'static str,
        /// Nodes the element has.
        expected: usize,
        /// Coordinates supplied.
        got: usize,
    },
    /// A quadrature rule that is not tabulated.
    #[error("unsupported quadrature rule: {what}")]
    UnsupportedRule {
        /// Which rule was asked for.
        what: String,
    },
    /// An out-of-plane thickness that is not positive and finite.
    #[error("thickness must be positive and finite, got {thickness}")]
    InvalidThickness {
        /// The thickness given.
        thickness: f64,
    },
    /// A formulation the element kind does not support (B-bar on Tri3).
    #[error("formulation {formulation} is not available for {element}")]
    UnsupportedFormulation {
        /// Element kind.
        element: String,
        /// The formulation asked for.
        formulation: String,
    },
}

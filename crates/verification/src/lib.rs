//! Verification of the plane-elasticity layer against closed forms and published values.
//!
//! The functions here build a model, solve it and measure it; they return numbers and never
//! assert or print. The verification tests (`tests/verification/verify_*.rs`) assert on them and
//! `examples/verification_tables.rs` turns the same numbers into the tables of
//! `docs/verification.md`, so what the documentation shows is what the tests check.
//!
//! ```text
//! analytic   closed forms: Lamé cylinder, Kirsch field, Howland / Heywood SCF, affine fields
//! norms      L2 and energy error norms by Gauss quadrature against a closed form; rates
//! patch      patch tests on distorted meshes (Dirichlet and traction variants)
//! lame       thick-walled cylinder under internal pressure: h-convergence studies
//! kirsch     plate with a circular hole under tension: O-grid mesh, SCF studies
//! balance    global equilibrium of reactions and applied loads (forces and moment)
//! report     markdown tables of the studies
//! ```

pub mod analytic;
pub mod balance;
pub mod kirsch;
pub mod lame;
pub mod norms;
pub mod patch;
pub mod report;
pub mod revolution;

use contact2d_element::ElementError;
use contact2d_fem::FemError;
use thiserror::Error;

/// Everything that can go wrong while running a verification problem.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum VerifyError {
    /// Building or solving the finite-element model failed.
    #[error(transparent)]
    Fem(#[from] FemError),
    /// An element-level evaluation failed.
    #[error(transparent)]
    Element(#[from] ElementError),
    /// A problem parameter is outside its admissible range.
    #[error("invalid verification parameter: {0}")]
    InvalidParameter(String),
    /// A node the measurement needs is not in the mesh.
    #[error("no mesh node at ({x}, {y}) within {tolerance:e}")]
    MissingNode {
        /// x of the point looked for.
        x: f64,
        /// y of the point looked for.
        y: f64,
        /// The distance accepted.
        tolerance: f64,
    },
}

/// The mesh node closest to `point`, if it lies within `tolerance` of it.
///
/// # Errors
/// [`VerifyError::MissingNode`] if no node is that close.
pub fn node_at(mesh: &contact2d_mesh::Mesh, point: [f64; 2], tolerance: f64) -> Result<usize, VerifyError> {
    let distance = |p: &[f64; 2]| (p[0] - point[0]).hypot(p[1] - point[1]);
    mesh.points
        .iter()
        .enumerate()
        .map(|(i, p)| (i, distance(p)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .filter(|(_, d)| *d <= tolerance)
        .map(|(i, _)| i)
        .ok_or(VerifyError::MissingNode { x: point[0], y: point[1], tolerance })
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn node_at_finds_the_closest_node_or_reports_the_point() {
        let mesh = contact2d_mesh::generate::rectangle(contact2d_mesh::CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
        let n = node_at(&mesh, [0.5, 0.5 + 1e-13], 1e-12).unwrap();
        assert_eq!(mesh.points[n], [0.5, 0.5]);
        assert!(matches!(node_at(&mesh, [0.25, 0.25], 0.1), Err(VerifyError::MissingNode { .. })));
    }
}

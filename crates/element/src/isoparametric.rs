//! The isoparametric map `x(ξ) = Σ_a N_a(ξ) x_a`, its Jacobian, and physical gradients.
//!
//! ```text
//! J = ∂x/∂ξ = Σ_a x_a ⊗ ∇_ξ N_a        J_ij = Σ_a x_a,i ∂N_a/∂ξ_j
//! ∇_x N_a = J⁻ᵀ ∇_ξ N_a                det J > 0 required (positively oriented cell)
//! ```

use nalgebra::Matrix2;

use crate::error::ElementError;
use crate::shape::{EdgeType, ElementType, MAX_NODES};

/// The map at one reference point: position, Jacobian determinant, physical shape gradients.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MappedPoint {
    /// Physical position `x(ξ)`.
    pub x: [f64; 2],
    /// `det J`.
    pub det_j: f64,
    /// Shape function values `N_a`.
    pub n: [f64; MAX_NODES],
    /// Physical gradients `[∂N_a/∂x, ∂N_a/∂y]`.
    pub dn_dx: [[f64; 2]; MAX_NODES],
    /// Number of nodes.
    pub len: usize,
}

/// Checks that `coords` has the element's node count.
///
/// # Errors
/// [`ElementError::WrongNodeCount`] otherwise.
pub fn check_node_count(element: ElementType, coords: &[[f64; 2]]) -> Result<(), ElementError> {
    if coords.len() == element.num_nodes() {
        Ok(())
    } else {
        Err(ElementError::WrongNodeCount {
            element: element_name(element),
            expected: element.num_nodes(),
            got: coords.len(),
        })
    }
}

fn element_name(element: ElementType) -> &'static str {
    match element {
        ElementType::Tri3 => "Tri3",
        ElementType::Tri6 => "Tri6",
        ElementType::Quad4 => "Quad4",
        ElementType::Quad8 => "Quad8",
        ElementType::Quad9 => "Quad9",
    }
}

/// The Jacobian determinant `det J(ξ)` of the element with nodal `coords`, of any sign
/// (for mesh-quality reports; [`map_point`] rejects non-positive values).
///
/// # Errors
/// [`ElementError::WrongNodeCount`] for a wrong number of coordinates.
pub fn jacobian_determinant(element: ElementType, coords: &[[f64; 2]], xi: [f64; 2]) -> Result<f64, ElementError> {
    check_node_count(element, coords)?;
    let shape = element.eval(xi);
    // J_ij = Σ_a x_a,i ∂N_a/∂ξ_j
    let (mut j00, mut j01, mut j10, mut j11) = (0.0, 0.0, 0.0, 0.0);
    for (c, dn) in coords.iter().zip(shape.gradients()) {
        j00 += c[0] * dn[0];
        j01 += c[0] * dn[1];
        j10 += c[1] * dn[0];
        j11 += c[1] * dn[1];
    }
    Ok(j00 * j11 - j01 * j10)
}

/// Evaluates the isoparametric map of the element with nodal `coords` at reference point `xi`.
///
/// # Errors
/// [`ElementError::WrongNodeCount`] for a wrong number of coordinates,
/// [`ElementError::NonPositiveJacobian`] where the map is inverted or degenerate.
pub fn map_point(element: ElementType, coords: &[[f64; 2]], xi: [f64; 2]) -> Result<MappedPoint, ElementError> {
    check_node_count(element, coords)?;
    let shape = element.eval(xi);
    let mut jac: Matrix2<f64> = Matrix2::zeros();
    let mut x = [0.0; 2];
    for (a, c) in coords.iter().enumerate() {
        for i in 0..2 {
            x[i] += shape.n[a] * c[i];
            for j in 0..2 {
                jac[(i, j)] += c[i] * shape.dn[a][j];
            }
        }
    }
    let det_j = jac.determinant();
    // Relative threshold: det J scales like the square of the element size.
    let scale = jac.norm_squared();
    if !det_j.is_finite() || det_j <= 1e-12 * scale {
        return Err(ElementError::NonPositiveJacobian { det_j, xi });
    }
    // J⁻ᵀ ∇_ξ N: with J = [[a, b], [c, d]], J⁻¹ = [[d, -b], [-c, a]] / det.
    let (a, b, c, d) = (jac[(0, 0)], jac[(0, 1)], jac[(1, 0)], jac[(1, 1)]);
    let mut dn_dx = [[0.0; 2]; MAX_NODES];
    for (k, g) in shape.gradients().iter().enumerate() {
        dn_dx[k] = [(d * g[0] - c * g[1]) / det_j, (-b * g[0] + a * g[1]) / det_j];
    }
    Ok(MappedPoint { x, det_j, n: shape.n, dn_dx, len: shape.len })
}

/// The map of an edge element at `xi`: position, tangent `dx/dξ` and its length `ds/dξ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgePoint {
    /// Position on the edge.
    pub x: [f64; 2],
    /// Unit tangent in the direction of increasing ξ.
    pub tangent: [f64; 2],
    /// Unit normal: the tangent turned clockwise, `[t_y, -t_x]` (outward for a counter-clockwise boundary).
    pub normal: [f64; 2],
    /// Arc-length derivative `ds/dξ = |dx/dξ|`.
    pub ds_dxi: f64,
    /// Shape function values (first `num_nodes` entries).
    pub n: [f64; 3],
}

/// Evaluates an edge element's geometry at `xi ∈ [-1, 1]`.
///
/// # Errors
/// [`ElementError::WrongNodeCount`], or [`ElementError::DegenerateEdge`] where `ds/dξ = 0`.
pub fn map_edge_point(edge: EdgeType, coords: &[[f64; 2]], xi: f64) -> Result<EdgePoint, ElementError> {
    if coords.len() != edge.num_nodes() {
        return Err(ElementError::WrongNodeCount {
            element: if edge == EdgeType::Line2 { "Line2" } else { "Line3" },
            expected: edge.num_nodes(),
            got: coords.len(),
        });
    }
    let (n, dn) = edge.eval(xi);
    let mut x = [0.0; 2];
    let mut dx = [0.0; 2];
    for (a, c) in coords.iter().enumerate() {
        for i in 0..2 {
            x[i] += n[a] * c[i];
            dx[i] += dn[a] * c[i];
        }
    }
    let ds_dxi = dx[0].hypot(dx[1]);
    if !ds_dxi.is_finite() || ds_dxi <= 0.0 {
        return Err(ElementError::DegenerateEdge { xi });
    }
    let tangent = [dx[0] / ds_dxi, dx[1] / ds_dxi];
    Ok(EdgePoint { x, tangent, normal: [tangent[1], -tangent[0]], ds_dxi, n })
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn affine_map_has_constant_jacobian() {
        // Quad4 on the parallelogram (0,0) (2,0) (3,1) (1,1): area 2, det J = area / 4.
        let c = [[0.0, 0.0], [2.0, 0.0], [3.0, 1.0], [1.0, 1.0]];
        let p = map_point(ElementType::Quad4, &c, [0.3, -0.2]).unwrap();
        assert!((p.det_j - 0.5).abs() < 1e-15);
    }

    #[test]
    fn inverted_element_is_an_error() {
        let c = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]; // clockwise
        assert!(matches!(map_point(ElementType::Quad4, &c, [0.0, 0.0]), Err(ElementError::NonPositiveJacobian { .. })));
        let collapsed = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert!(map_point(ElementType::Tri3, &collapsed, [0.2, 0.2]).is_err());
    }

    #[test]
    fn wrong_node_count_is_an_error() {
        let c = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(matches!(
            map_point(ElementType::Quad4, &c, [0.0, 0.0]),
            Err(ElementError::WrongNodeCount { expected: 4, got: 3, .. })
        ));
        assert!(map_edge_point(EdgeType::Line3, &c[..2], 0.0).is_err());
    }

    #[test]
    fn quadratic_edge_on_a_circle() {
        // Three points on the unit circle; at the mid node the tangent is exact by symmetry.
        let (a, b) = (0.0f64, std::f64::consts::FRAC_PI_2);
        let m = 0.5 * (a + b);
        let c = [[a.cos(), a.sin()], [b.cos(), b.sin()], [m.cos(), m.sin()]];
        let p = map_edge_point(EdgeType::Line3, &c, 0.0).unwrap();
        assert!((p.tangent[0] + m.sin()).abs() < 1e-14 && (p.tangent[1] - m.cos()).abs() < 1e-14);
        assert!(map_edge_point(EdgeType::Line2, &[[1.0, 1.0], [1.0, 1.0]], 0.0).is_err());
    }
}

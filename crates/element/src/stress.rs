//! Strain and stress at any reference point, and extrapolation from Gauss points to nodes.
//!
//! ```text
//! ε(ξ) = Σ_a B_a(ξ) u_a,   σ(ξ) = D ε(ξ)        (Voigt: [ε11, ε22, γ12], [σ11, σ22, σ12])
//! ```
//!
//! With the B-bar [`Formulation`] the strain is `ε̄ = B̄ u` and `σ = D ε̄` ([`stress_at_with`]),
//! the same treatment as the stiffness.
//!
//! Extrapolation: the Gauss-point values are interpolated by the polynomial space that is
//! unisolvent on the points (constant for 1 point, linear for 3 triangle points, the tensor
//! Lagrange space of degree n-1 for an n×n rule) and that polynomial is evaluated at the nodes:
//! `σ_nodes = E σ_gauss` with `E = M V⁻¹`, `V` the basis at the Gauss points and `M` at the nodes.
//! For Quad9 with 3×3 points this is exact for biquadratic stress fields.

use nalgebra::DMatrix;

use crate::error::ElementError;
use crate::formulation::{DilatationProjection, Formulation, deviatoric_split, volumetric_split};
use crate::isoparametric::map_point;
use crate::kinematics::Kinematics;
use crate::material::{Material, PlaneCondition};
use crate::quadrature::GaussRule;
use crate::shape::ElementType;

/// The strain `[ε11, ε22, γ12]` at reference point `xi` for element displacements
/// `u = [u_0x, u_0y, u_1x, ...]`.
///
/// # Errors
/// As [`map_point`].
pub fn strain_at(element: ElementType, coords: &[[f64; 2]], u: &[f64], xi: [f64; 2]) -> Result<[f64; 3], ElementError> {
    let p = map_point(element, coords, xi)?;
    if u.len() != 2 * p.len {
        return Err(ElementError::WrongNodeCount {
            element: "displacement vector",
            expected: 2 * p.len,
            got: u.len() / 2,
        });
    }
    let mut e = [0.0; 3];
    for a in 0..p.len {
        let [gx, gy] = p.dn_dx[a];
        let (ux, uy) = (u[2 * a], u[2 * a + 1]);
        e[0] += gx * ux;
        e[1] += gy * uy;
        e[2] += gy * ux + gx * uy;
    }
    Ok(e)
}

/// The stress `[σ11, σ22, σ12]` at reference point `xi` of a body in the plane reduction `plane`.
///
/// # Errors
/// As [`strain_at`].
pub fn stress_at(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    plane: PlaneCondition,
    u: &[f64],
    xi: [f64; 2],
) -> Result<[f64; 3], ElementError> {
    let e = strain_at(element, coords, u, xi)?;
    let s = plane.elasticity_matrix(material) * nalgebra::Vector3::new(e[0], e[1], e[2]);
    Ok([s[0], s[1], s[2]])
}

/// The strain of the given [`Formulation`] at reference point `xi`:
///
/// ```text
/// Standard:  ε = B(ξ) u
/// BBar:      ε̄ = B̄(ξ) u = ε + ½ (θ̄ − θ) [1, 1, 0],   θ = ε11 + ε22,  θ̄ = q(x)ᵀ M⁻¹ G u
/// ```
///
/// The projection `M⁻¹ G` is integrated with [`GaussRule::stiffness_rule`], the rule the
/// assembly uses, so that `ε̄` is the strain of the assembled stiffness.
///
/// # Errors
/// As [`strain_at`], and [`ElementError::UnsupportedFormulation`] for B-bar on Tri3.
pub fn strain_at_with(
    element: ElementType,
    coords: &[[f64; 2]],
    u: &[f64],
    xi: [f64; 2],
    formulation: Formulation,
) -> Result<[f64; 3], ElementError> {
    let e = strain_at(element, coords, u, xi)?;
    match formulation {
        Formulation::Standard => Ok(e),
        Formulation::BBar => {
            let theta_bar = projected_dilatation(element, coords, u, xi)?;
            let shift = 0.5 * (theta_bar - e[0] - e[1]);
            Ok([e[0] + shift, e[1] + shift, e[2]])
        }
    }
}

/// `θ̄` at reference point `xi` (the B-bar projection with the stiffness rule).
fn projected_dilatation(
    element: ElementType,
    coords: &[[f64; 2]],
    u: &[f64],
    xi: [f64; 2],
) -> Result<f64, ElementError> {
    let projection = DilatationProjection::new(element, coords, &GaussRule::stiffness_rule(element))?;
    let x = map_point(element, coords, xi)?.x;
    Ok(projection.dilatation(x, u))
}

/// The stress of the given [`Formulation`] at reference point `xi`:
///
/// ```text
/// Standard:  σ = D B u
/// BBar:      σ = D ε̄ = D_d ε + κ θ̄ [1, 1, 0]     (D = D_d + κ m mᵀ, crate::formulation)
/// ```
///
/// The B-bar form is evaluated on the right, so that the large `κ` multiplies only the
/// projected dilatation `θ̄` (which converges), never the pointwise `θ`.
///
/// # Errors
/// As [`strain_at_with`].
///
/// # Examples
/// ```
/// use contact2d_element::{stress_at, stress_at_with, ElementType, Formulation, Material, PlaneCondition};
/// // An affine field: B-bar and standard stresses agree (θ̄ = θ).
/// let (m, strain) = (Material::new(1.0, 0.4999).unwrap(), PlaneCondition::Strain);
/// let q4 = ElementType::Quad4;
/// let x = q4.reference_nodes();
/// let u: Vec<f64> = x.iter().flat_map(|p| [1e-3 * p[0], -0.5e-3 * p[1] + 2e-4 * p[0]]).collect();
/// let (s, sb) = (stress_at(q4, x, &m, strain, &u, [0.3, 0.1]).unwrap(), stress_at_with(q4, x, &m, strain, &u, [0.3, 0.1], Formulation::BBar).unwrap());
/// assert!((0..3).all(|k| (s[k] - sb[k]).abs() < 1e-9 * s[0].abs()));
/// ```
pub fn stress_at_with(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    plane: PlaneCondition,
    u: &[f64],
    xi: [f64; 2],
    formulation: Formulation,
) -> Result<[f64; 3], ElementError> {
    match formulation {
        Formulation::Standard => stress_at(element, coords, material, plane, u, xi),
        Formulation::BBar => {
            let e = strain_at(element, coords, u, xi)?;
            let theta_bar = projected_dilatation(element, coords, u, xi)?;
            let (d_dev, kappa) = deviatoric_split(material, plane);
            let s = d_dev * nalgebra::Vector3::new(e[0], e[1], e[2]);
            Ok([s[0] + kappa * theta_bar, s[1] + kappa * theta_bar, s[2]])
        }
    }
}

/// The hoop strain `ε_θθ = u_r / r` of a body of revolution at reference point `xi`; on the axis
/// (`r = 0`, where `u_r = 0`) its limit `∂u_r/∂r`.
///
/// # Errors
/// As [`strain_at`].
pub fn hoop_strain_at(element: ElementType, coords: &[[f64; 2]], u: &[f64], xi: [f64; 2]) -> Result<f64, ElementError> {
    let p = map_point(element, coords, xi)?;
    if u.len() != 2 * p.len {
        return Err(ElementError::WrongNodeCount {
            element: "displacement vector",
            expected: 2 * p.len,
            got: u.len() / 2,
        });
    }
    let radial: f64 = (0..p.len).map(|a| p.n[a] * u[2 * a]).sum();
    // "On the axis" relative to the cell's size, so the limit is taken only where r/h is round-off.
    let size = p.det_j.sqrt();
    if p.x[0].abs() <= 1e-12 * size {
        Ok((0..p.len).map(|a| p.dn_dx[a][0] * u[2 * a]).sum())
    } else {
        Ok(radial / p.x[0])
    }
}

/// The whole stress of a body of the given [`Kinematics`] at reference point `xi`:
/// `[σ11, σ22, σ12, σ_out]`, `σ_out` the out-of-plane stress (σ33 in the plane, σθθ for a body
/// of revolution).
///
/// ```text
/// plane:         [σ11, σ22, σ12] = stress_at_with(…),  σ33 = Kinematics::out_of_plane_stress
/// axisymmetric:  [σ_rr, σ_zz, σ_rz] = D_pp ε + λ ε_θθ [1, 1, 0],  σθθ = λ (ε_rr + ε_zz) + (λ + 2μ) ε_θθ
///   B-bar:       σ = D_d ε + K θ̄ [1, 1, 0, 1]   (D_d, K, θ̄ with the hoop term: crate::formulation)
/// ```
///
/// # Errors
/// As [`stress_at_with`].
pub fn stress_state_at(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    kinematics: &Kinematics,
    u: &[f64],
    xi: [f64; 2],
    formulation: Formulation,
) -> Result<[f64; 4], ElementError> {
    if let Some(plane) = kinematics.plane_condition() {
        let s = stress_at_with(element, coords, material, plane, u, xi, formulation)?;
        return Ok([s[0], s[1], s[2], plane.out_of_plane_stress(material, &s)]);
    }
    let e = strain_at(element, coords, u, xi)?;
    let hoop = hoop_strain_at(element, coords, u, xi)?;
    let (d, (lambda, diagonal), theta_bar) = match formulation {
        Formulation::Standard => {
            let coupling = kinematics.hoop_elasticity(material).unwrap_or_default();
            (kinematics.in_plane_elasticity(material), coupling, None)
        }
        Formulation::BBar => {
            let split = volumetric_split(material, kinematics);
            let projection =
                DilatationProjection::new_in(element, coords, &kinematics.stiffness_rule(element), kinematics)?;
            let x = map_point(element, coords, xi)?.x;
            (split.deviatoric, split.hoop.unwrap_or_default(), Some(split.bulk * projection.dilatation(x, u)))
        }
    };
    let s = d * nalgebra::Vector3::new(e[0], e[1], e[2]);
    let state = [s[0] + lambda * hoop, s[1] + lambda * hoop, s[2], lambda * (e[0] + e[1]) + diagonal * hoop];
    Ok(match theta_bar {
        None => state,
        Some(p) => [state[0] + p, state[1] + p, state[2], state[3] + p],
    })
}

/// The von Mises equivalent stress of a whole stress state `[σ11, σ22, σ12, σ_out]` (σ_out the
/// out-of-plane normal stress, σ33 or σθθ, a principal stress):
/// `√(½ [(σ11 − σ22)² + (σ22 − σ_out)² + (σ_out − σ11)²] + 3 σ12²)`.
pub fn von_mises(state: &[f64; 4]) -> f64 {
    let [s11, s22, s12, s33] = *state;
    (0.5 * ((s11 - s22).powi(2) + (s22 - s33).powi(2) + (s33 - s11).powi(2)) + 3.0 * s12 * s12).sqrt()
}

/// Monomial exponents of the extrapolation space for a rule of `len` points on `element`'s cell.
fn extrapolation_basis(element: ElementType, len: usize) -> Result<Vec<(i32, i32)>, ElementError> {
    let unsupported =
        || ElementError::UnsupportedRule { what: format!("extrapolation from {len} points on {element:?}") };
    if element.is_triangle() {
        match len {
            1 => Ok(vec![(0, 0)]),
            3 => Ok(vec![(0, 0), (1, 0), (0, 1)]),
            6 => Ok(vec![(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]),
            _ => Err(unsupported()),
        }
    } else {
        let n = (len as f64).sqrt().round() as i32;
        if (n * n) as usize != len || n == 0 {
            return Err(unsupported());
        }
        Ok((0..n).flat_map(|j| (0..n).map(move |i| (i, j))).collect())
    }
}

/// The extrapolation matrix `E` (`nodes × points`) from the points of `rule` to the element's nodes.
///
/// # Errors
/// [`ElementError::UnsupportedRule`] when no unisolvent space is tabulated for the rule.
pub fn gauss_to_node_extrapolation(element: ElementType, rule: &GaussRule) -> Result<DMatrix<f64>, ElementError> {
    let basis = extrapolation_basis(element, rule.len())?;
    let eval = |p: &[f64; 2]| basis.iter().map(|&(i, j)| p[0].powi(i) * p[1].powi(j)).collect::<Vec<_>>();
    let v = DMatrix::from_row_iterator(rule.len(), basis.len(), rule.points.iter().flat_map(eval));
    let nodes = element.reference_nodes();
    let m = DMatrix::from_row_iterator(nodes.len(), basis.len(), nodes.iter().flat_map(eval));
    let v_inv = v.try_inverse().ok_or_else(|| ElementError::UnsupportedRule {
        what: format!("extrapolation from {} points on {element:?}: points not unisolvent", rule.len()),
    })?;
    Ok(m * v_inv)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::material::PlaneCondition;

    #[test]
    fn affine_displacement_gives_its_constant_strain_on_every_element() {
        for t in ElementType::ALL {
            let coords: Vec<[f64; 2]> = t
                .reference_nodes()
                .iter()
                .map(|&[x, y]| [1.2 * x + 0.3 * y + 0.05 * x * y, 0.1 * x + 0.8 * y])
                .collect();
            let u: Vec<f64> = coords.iter().flat_map(|&[x, y]| [0.01 * x + 0.02 * y, -0.005 * x + 0.03 * y]).collect();
            let e = strain_at(t, &coords, &u, [0.2, 0.1]).unwrap();
            assert!((e[0] - 0.01).abs() < 1e-14 && (e[1] - 0.03).abs() < 1e-14 && (e[2] - 0.015).abs() < 1e-14);
            let m = Material::new(2.0, 0.3).unwrap();
            let s = stress_at(t, &coords, &m, PlaneCondition::Stress, &u, [0.0, 0.1]).unwrap();
            assert!((s[2] - 2.0 / 2.6 * 0.015).abs() < 1e-14);
        }
    }

    #[test]
    fn extrapolation_reproduces_fields_of_the_space() {
        // Quad9 3×3: biquadratic fields exactly; Tri6 3-point: linear fields exactly.
        let q9 = gauss_to_node_extrapolation(ElementType::Quad9, &GaussRule::quad(3).unwrap()).unwrap();
        let rule = GaussRule::quad(3).unwrap();
        let f = |p: &[f64; 2]| 1.0 + p[0] - 2.0 * p[1] * p[1] + p[0] * p[0] * p[1] * p[1];
        let g = DMatrix::from_iterator(9, 1, rule.points.iter().map(f));
        let nodal = &q9 * g;
        for (a, x) in ElementType::Quad9.reference_nodes().iter().enumerate() {
            assert!((nodal[a] - f(x)).abs() < 1e-12);
        }
        let t6 = gauss_to_node_extrapolation(ElementType::Tri6, &GaussRule::triangle(2).unwrap()).unwrap();
        let rule = GaussRule::triangle(2).unwrap();
        let f = |p: &[f64; 2]| 2.0 - p[0] + 3.0 * p[1];
        let nodal = &t6 * DMatrix::from_iterator(3, 1, rule.points.iter().map(f));
        for (a, x) in ElementType::Tri6.reference_nodes().iter().enumerate() {
            assert!((nodal[a] - f(x)).abs() < 1e-12);
        }
        assert!(gauss_to_node_extrapolation(ElementType::Quad4, &GaussRule::triangle(4).unwrap()).is_err());
    }

    #[test]
    fn wrong_displacement_length_is_an_error() {
        let c = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(strain_at(ElementType::Tri3, &c, &[0.0; 4], [0.1, 0.1]).is_err());
    }
}

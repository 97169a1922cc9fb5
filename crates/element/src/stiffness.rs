//! Element stiffness of plane elasticity.
//!
//! ```text
//! K_e = ∫_Ωe Bᵀ D B t dΩ = Σ_g B(ξ_g)ᵀ D B(ξ_g) t det J(ξ_g) w_g
//!
//! B_a = [ ∂N_a/∂x   0       ]      element DOFs interleaved: [u_0x, u_0y, u_1x, u_1y, ...]
//!       [ 0         ∂N_a/∂y ]
//!       [ ∂N_a/∂y   ∂N_a/∂x ]
//! ```
//!
//! `t` is the thickness (1 in the paper).

use nalgebra::DMatrix;

use crate::error::ElementError;
use crate::isoparametric::map_point;
use crate::material::Material;
use crate::quadrature::GaussRule;
use crate::shape::ElementType;

/// The element stiffness matrix `K_e` (size `2n × 2n`), integrated with `rule`.
///
/// # Errors
/// [`ElementError::WrongNodeCount`] or [`ElementError::NonPositiveJacobian`] from the map.
///
/// # Examples
/// ```
/// use contact2d_element::{element_stiffness, ElementType, GaussRule, Material, PlaneCondition};
/// let m = Material::new(1.0, 0.3, PlaneCondition::Stress).unwrap();
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let k = element_stiffness(ElementType::Quad4, &square, &m, 1.0, &GaussRule::quad(2).unwrap()).unwrap();
/// assert_eq!(k.nrows(), 8);
/// assert!((k.clone() - k.transpose()).abs().max() < 1e-14);
/// ```
pub fn element_stiffness(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    thickness: f64,
    rule: &GaussRule,
) -> Result<DMatrix<f64>, ElementError> {
    let n = element.num_nodes();
    let d = material.elasticity_matrix();
    let mut k = DMatrix::zeros(2 * n, 2 * n);
    for (xi, w) in rule.points.iter().zip(&rule.weights) {
        let p = map_point(element, coords, *xi)?;
        let f = w * p.det_j * thickness;
        for a in 0..n {
            let [ax, ay] = p.dn_dx[a];
            // D B_a: the 3×2 block, columns for u_ax and u_ay.
            let db_ax =
                [d[(0, 0)] * ax + d[(0, 2)] * ay, d[(1, 0)] * ax + d[(1, 2)] * ay, d[(2, 0)] * ax + d[(2, 2)] * ay];
            let db_ay =
                [d[(0, 1)] * ay + d[(0, 2)] * ax, d[(1, 1)] * ay + d[(1, 2)] * ax, d[(2, 1)] * ay + d[(2, 2)] * ax];
            for b in a..n {
                let [bx, by] = p.dn_dx[b];
                // B_bᵀ (D B_a): rows u_bx = [bx, 0, by], u_by = [0, by, bx].
                let kxx = bx * db_ax[0] + by * db_ax[2];
                let kxy = bx * db_ay[0] + by * db_ay[2];
                let kyx = by * db_ax[1] + bx * db_ax[2];
                let kyy = by * db_ay[1] + bx * db_ay[2];
                k[(2 * b, 2 * a)] += f * kxx;
                k[(2 * b, 2 * a + 1)] += f * kxy;
                k[(2 * b + 1, 2 * a)] += f * kyx;
                k[(2 * b + 1, 2 * a + 1)] += f * kyy;
            }
        }
    }
    // Only the lower blocks (b ≥ a) were integrated; mirror them.
    for a in 0..2 * n {
        for b in 0..a {
            k[(b, a)] = k[(a, b)];
        }
    }
    Ok(k)
}

/// The element's area `∫ dΩ` with `rule`.
///
/// # Errors
/// As [`element_stiffness`].
pub fn element_area(element: ElementType, coords: &[[f64; 2]], rule: &GaussRule) -> Result<f64, ElementError> {
    let mut area = 0.0;
    for (xi, w) in rule.points.iter().zip(&rule.weights) {
        area += w * map_point(element, coords, *xi)?.det_j;
    }
    Ok(area)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::material::PlaneCondition;
    use proptest::prelude::*;

    /// A randomly distorted element: reference nodes scaled, sheared, rotated, and jittered.
    pub(crate) fn distorted(element: ElementType, jitter: &[f64]) -> Vec<[f64; 2]> {
        element
            .reference_nodes()
            .iter()
            .enumerate()
            .map(|(i, &[x, y])| {
                let (jx, jy) = (jitter[2 * i % jitter.len()], jitter[(2 * i + 1) % jitter.len()]);
                [1.3 * x + 0.2 * y + 0.08 * jx + 2.0, -0.1 * x + 0.9 * y + 0.08 * jy - 1.0]
            })
            .collect()
    }

    fn symmetric_eigenvalues(k: &DMatrix<f64>) -> Vec<f64> {
        let mut ev: Vec<f64> = k.clone().symmetric_eigen().eigenvalues.iter().copied().collect();
        ev.sort_by(f64::total_cmp);
        ev
    }

    proptest! {
        /// K is symmetric, positive semi-definite, and has exactly three zero modes (rigid motions).
        #[test]
        fn stiffness_has_three_rigid_modes(ti in 0usize..5, jitter in proptest::collection::vec(-1.0..1.0f64, 18)) {
            let t = ElementType::ALL[ti];
            let coords = distorted(t, &jitter);
            let m = Material::new(1.0, 0.3, PlaneCondition::Stress).unwrap();
            let k = element_stiffness(t, &coords, &m, 1.0, &GaussRule::stiffness_rule(t)).unwrap();
            prop_assert!((k.clone() - k.transpose()).abs().max() < 1e-13);
            let ev = symmetric_eigenvalues(&k);
            let largest = ev[ev.len() - 1];
            prop_assert!(ev[..3].iter().all(|e| e.abs() < 1e-10 * largest), "{:?}", ev);
            prop_assert!(ev[3] > 1e-6 * largest, "spurious zero mode: {:?}", ev);
        }

        /// A rigid motion produces no force: K (a + θ × x) = 0.
        #[test]
        fn rigid_motion_produces_no_force(ti in 0usize..5, jitter in proptest::collection::vec(-1.0..1.0f64, 18)) {
            let t = ElementType::ALL[ti];
            let coords = distorted(t, &jitter);
            let m = Material::new(5.0, 0.2, PlaneCondition::Strain).unwrap();
            let k = element_stiffness(t, &coords, &m, 1.0, &GaussRule::stiffness_rule(t)).unwrap();
            let u = DMatrix::from_iterator(2 * coords.len(), 1, coords.iter().flat_map(|x| [0.3 - 0.1 * x[1], -0.2 + 0.1 * x[0]]));
            prop_assert!((&k * u).abs().max() < 1e-12 * k.abs().max());
        }
    }

    #[test]
    fn area_of_unit_square_and_triangle() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert!((element_area(ElementType::Quad4, &sq, &GaussRule::quad(2).unwrap()).unwrap() - 1.0).abs() < 1e-15);
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!((element_area(ElementType::Tri3, &tri, &GaussRule::triangle(1).unwrap()).unwrap() - 0.5).abs() < 1e-15);
    }
}

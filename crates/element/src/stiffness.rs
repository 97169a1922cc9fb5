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
//! `t det J` is the volume weight of the body's [`Kinematics`] (`t` the thickness, 1 in the paper).

use nalgebra::{DMatrix, Matrix3};

use crate::error::ElementError;
use crate::formulation::{DilatationProjection, Formulation, deviatoric_split};
use crate::isoparametric::map_point;
use crate::kinematics::Kinematics;
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
/// use contact2d_element::{element_stiffness, ElementType, GaussRule, Kinematics, Material, PlaneCondition};
/// let m = Material::new(1.0, 0.3, PlaneCondition::Stress).unwrap();
/// let plate = Kinematics::plane(PlaneCondition::Stress, 1.0).unwrap();
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let k = element_stiffness(ElementType::Quad4, &square, &m, &plate, &GaussRule::quad(2).unwrap()).unwrap();
/// assert_eq!(k.nrows(), 8);
/// assert!((k.clone() - k.transpose()).abs().max() < 1e-14);
/// ```
pub fn element_stiffness(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    kinematics: &Kinematics,
    rule: &GaussRule,
) -> Result<DMatrix<f64>, ElementError> {
    element_stiffness_with(element, coords, material, kinematics, rule, Formulation::Standard)
}

/// The element stiffness matrix in the given [`Formulation`]:
///
/// ```text
/// Standard:  K_e = Σ_g B_gᵀ D B_g t det J_g w_g
/// BBar:      K_e = Σ_g B_gᵀ D_d B_g t det J_g w_g + κ t Gᵀ M⁻¹ G     (= ∫ B̄ᵀ D B̄ t dΩ)
/// ```
///
/// with `D_d`, `κ`, `G`, `M` as in [`crate::formulation`]; `rule` integrates both parts.
///
/// # Errors
/// As [`element_stiffness`], and [`ElementError::UnsupportedFormulation`] for B-bar on Tri3.
///
/// # Examples
/// ```
/// use contact2d_element::{element_stiffness_with, ElementType, Formulation, GaussRule, Kinematics, Material, PlaneCondition};
/// let rubber = Material::new(1.0, 0.4999, PlaneCondition::Strain).unwrap();
/// let long = Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap();
/// let q9 = ElementType::Quad9;
/// let k = element_stiffness_with(q9, q9.reference_nodes(), &rubber, &long, &GaussRule::stiffness_rule(q9), Formulation::BBar).unwrap();
/// assert!((k.clone() - k.transpose()).abs().max() < 1e-9 * k.abs().max());
/// ```
pub fn element_stiffness_with(
    element: ElementType,
    coords: &[[f64; 2]],
    material: &Material,
    kinematics: &Kinematics,
    rule: &GaussRule,
    formulation: Formulation,
) -> Result<DMatrix<f64>, ElementError> {
    match formulation {
        Formulation::Standard => integrate_btdb(element, coords, &material.elasticity_matrix(), kinematics, rule),
        Formulation::BBar => {
            let projection = DilatationProjection::new(element, coords, rule)?;
            let (d_dev, kappa) = deviatoric_split(material);
            let mut k = integrate_btdb(element, coords, &d_dev, kinematics, rule)?;
            k += projection.volumetric_stiffness(kappa, kinematics.uniform_weight());
            // Gᵀ M⁻¹ G is symmetric up to round-off; make K_e exactly symmetric.
            let n = k.nrows();
            for a in 0..n {
                for b in 0..a {
                    let v = 0.5 * (k[(a, b)] + k[(b, a)]);
                    k[(a, b)] = v;
                    k[(b, a)] = v;
                }
            }
            Ok(k)
        }
    }
}

/// `Σ_g B_gᵀ d B_g t det J_g w_g` for any symmetric 3×3 `d` (`t` the kinematics' volume weight).
fn integrate_btdb(
    element: ElementType,
    coords: &[[f64; 2]],
    d: &Matrix3<f64>,
    kinematics: &Kinematics,
    rule: &GaussRule,
) -> Result<DMatrix<f64>, ElementError> {
    let n = element.num_nodes();
    let mut k = DMatrix::zeros(2 * n, 2 * n);
    for (xi, w) in rule.points.iter().zip(&rule.weights) {
        let p = map_point(element, coords, *xi)?;
        let f = w * p.det_j * kinematics.volume_weight(p.x);
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
            let k = element_stiffness(t, &coords, &m, &Kinematics::plane(m.plane(), 1.0).unwrap(), &GaussRule::stiffness_rule(t)).unwrap();
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
            let k = element_stiffness(t, &coords, &m, &Kinematics::plane(m.plane(), 1.0).unwrap(), &GaussRule::stiffness_rule(t)).unwrap();
            let u = DMatrix::from_iterator(2 * coords.len(), 1, coords.iter().flat_map(|x| [0.3 - 0.1 * x[1], -0.2 + 0.1 * x[0]]));
            prop_assert!((&k * u).abs().max() < 1e-12 * k.abs().max());
        }
    }

    proptest! {
        /// B-bar: symmetric, positive semi-definite, no force under a rigid motion, and exactly
        /// three zero modes for Quad4, Quad8, Quad9 (Tri6: five, module docs of `formulation`),
        /// also at ν = 0.4999 in plane strain.
        #[test]
        fn bbar_stiffness_has_the_rigid_modes_only(
            ti in 1usize..5,
            nu in prop_oneof![Just(0.3f64), Just(0.4999f64)],
            jitter in proptest::collection::vec(-1.0..1.0f64, 18),
        ) {
            let t = ElementType::ALL[ti];
            prop_assume!(t != ElementType::Tri3);
            let coords = distorted(t, &jitter);
            let m = Material::new(1.0, nu, PlaneCondition::Strain).unwrap();
            let k = element_stiffness_with(t, &coords, &m, &Kinematics::plane(m.plane(), 1.0).unwrap(), &GaussRule::stiffness_rule(t), Formulation::BBar).unwrap();
            prop_assert!((k.clone() - k.transpose()).abs().max() == 0.0);
            let u = DMatrix::from_iterator(2 * coords.len(), 1, coords.iter().flat_map(|x| [0.3 - 0.1 * x[1], -0.2 + 0.1 * x[0]]));
            prop_assert!((&k * u).abs().max() < 1e-12 * k.abs().max());
            // Zero modes against the deviatoric scale μ (the volumetric eigenvalues are ~κ ≫ μ).
            let ev = symmetric_eigenvalues(&k);
            let mu = 1.0 / (2.0 * (1.0 + nu));
            let zero_modes = if t == ElementType::Tri6 { 5 } else { 3 };
            prop_assert!(ev[..zero_modes].iter().all(|e| e.abs() < 1e-8 * mu), "{:?}", ev);
            prop_assert!(ev[zero_modes] > 1e-4 * mu, "spurious zero mode: {:?}", ev);
        }
    }

    /// `∫ Bᵀ D_d B + κ Gᵀ M⁻¹ G` (the implementation) equals `∫ B̄ᵀ D B̄` formed point by point
    /// from the definition B̄ = B + ½ m (b̄ − b)ᵀ: a second algorithm for the same matrix.
    #[test]
    fn bbar_equals_the_b_bar_product_formed_pointwise() {
        for t in [ElementType::Quad4, ElementType::Quad8, ElementType::Quad9, ElementType::Tri6] {
            let coords = distorted(t, &[0.3, -0.7, 0.5, 0.1, -0.2, 0.9, -0.4]);
            let m = Material::new(2.0, 0.45, PlaneCondition::Strain).unwrap();
            let rule = GaussRule::stiffness_rule(t);
            let k = element_stiffness_with(
                t,
                &coords,
                &m,
                &Kinematics::plane(m.plane(), 0.7).unwrap(),
                &rule,
                Formulation::BBar,
            )
            .unwrap();
            let proj = crate::formulation::DilatationProjection::new(t, &coords, &rule).unwrap();
            let n = t.num_nodes();
            let mut reference = DMatrix::zeros(2 * n, 2 * n);
            for (xi, w) in rule.points.iter().zip(&rule.weights) {
                let p = map_point(t, &coords, *xi).unwrap();
                let b_bar_row = proj.projected_divergence(p.x);
                let mut bb = DMatrix::zeros(3, 2 * n);
                for a in 0..n {
                    let [gx, gy] = p.dn_dx[a];
                    bb[(0, 2 * a)] = gx;
                    bb[(1, 2 * a + 1)] = gy;
                    bb[(2, 2 * a)] = gy;
                    bb[(2, 2 * a + 1)] = gx;
                    for (c, g) in [(2 * a, gx), (2 * a + 1, gy)] {
                        let shift = 0.5 * (b_bar_row[c] - g);
                        bb[(0, c)] += shift;
                        bb[(1, c)] += shift;
                    }
                }
                let d = DMatrix::from_iterator(3, 3, m.elasticity_matrix().iter().copied());
                reference += bb.transpose() * d * &bb * (w * p.det_j * 0.7);
            }
            assert!((&k - &reference).abs().max() < 1e-12 * k.abs().max(), "{t:?}");
        }
    }

    /// Tri3 has no B-bar variant; the standard call is the `Standard` formulation.
    #[test]
    fn bbar_tri3_is_refused_and_standard_delegates() {
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let m = Material::new(1.0, 0.3, PlaneCondition::Strain).unwrap();
        let rule = GaussRule::triangle(1).unwrap();
        assert!(matches!(
            element_stiffness_with(
                ElementType::Tri3,
                &tri,
                &m,
                &Kinematics::plane(m.plane(), 1.0).unwrap(),
                &rule,
                Formulation::BBar
            ),
            Err(ElementError::UnsupportedFormulation { .. })
        ));
        let a =
            element_stiffness(ElementType::Tri3, &tri, &m, &Kinematics::plane(m.plane(), 1.0).unwrap(), &rule).unwrap();
        let b = element_stiffness_with(
            ElementType::Tri3,
            &tri,
            &m,
            &Kinematics::plane(m.plane(), 1.0).unwrap(),
            &rule,
            Formulation::Standard,
        )
        .unwrap();
        assert_eq!(a, b);
    }

    #[test]
    fn area_of_unit_square_and_triangle() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        assert!((element_area(ElementType::Quad4, &sq, &GaussRule::quad(2).unwrap()).unwrap() - 1.0).abs() < 1e-15);
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!((element_area(ElementType::Tri3, &tri, &GaussRule::triangle(1).unwrap()).unwrap() - 0.5).abs() < 1e-15);
    }
}

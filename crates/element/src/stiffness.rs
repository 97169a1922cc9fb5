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
//!
//! A body of revolution adds the hoop row `B_θ,a = [N_a / r, 0]` (`ε_θθ = u_r / r`) and weighs
//! every point by `2πr`:
//!
//! ```text
//! K_e = Σ_g [ B_pᵀ D_pp B_p + B_pᵀ d λ B_θ + B_θᵀ λ dᵀ B_p + B_θᵀ (λ + 2μ) B_θ ] 2πr det J w_g,
//!       d = [1, 1, 0]ᵀ,  D_pp the plane-strain matrix ([`Kinematics::in_plane_elasticity`])
//! ```

use nalgebra::{DMatrix, Matrix3};

use crate::error::ElementError;
use crate::formulation::{DilatationProjection, Formulation, volumetric_split};
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
/// let m = Material::new(1.0, 0.3).unwrap();
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
/// A body of revolution weighs by `2πr` (t = 1), adds the hoop row to `B` (with `D_d`'s hoop
/// coupling under B-bar) and the hoop term to the projected dilatation ([`crate::formulation`]).
///
/// with `D_d`, `κ`, `G`, `M` as in [`crate::formulation`]; `rule` integrates both parts.
///
/// # Errors
/// As [`element_stiffness`], and [`ElementError::UnsupportedFormulation`] for B-bar on Tri3.
///
/// # Examples
/// ```
/// use contact2d_element::{element_stiffness_with, ElementType, Formulation, GaussRule, Kinematics, Material, PlaneCondition};
/// let rubber = Material::new(1.0, 0.4999).unwrap();
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
        Formulation::Standard => {
            let mut k = integrate_btdb(element, coords, &kinematics.in_plane_elasticity(material), kinematics, rule)?;
            if let Some(hoop) = kinematics.hoop_elasticity(material) {
                add_hoop_stiffness(&mut k, element, coords, hoop, kinematics, rule)?;
            }
            Ok(k)
        }
        Formulation::BBar => {
            let projection = DilatationProjection::new_in(element, coords, rule, kinematics)?;
            let split = volumetric_split(material, kinematics);
            let mut k = integrate_btdb(element, coords, &split.deviatoric, kinematics, rule)?;
            if let Some(hoop) = split.hoop {
                add_hoop_stiffness(&mut k, element, coords, hoop, kinematics, rule)?;
            }
            k += projection.volumetric_stiffness(split.bulk, kinematics.uniform_factor());
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

/// Adds the hoop terms of a body of revolution (module docs) to the in-plane `k`: `(λ, λ + 2μ)`
/// from [`Kinematics::hoop_elasticity`] (or B-bar's deviatoric `(−2μ/3, 4μ/3)`), every point
/// weighed by `2πr det J w`.
fn add_hoop_stiffness(
    k: &mut DMatrix<f64>,
    element: ElementType,
    coords: &[[f64; 2]],
    (lambda, diagonal): (f64, f64),
    kinematics: &Kinematics,
    rule: &GaussRule,
) -> Result<(), ElementError> {
    let n = element.num_nodes();
    for (xi, w) in rule.points.iter().zip(&rule.weights) {
        let p = map_point(element, coords, *xi)?;
        // Gauss points lie inside the cell, so r > 0 for a mesh with r ≥ 0.
        let r = p.x[0];
        let f = w * p.det_j * kinematics.volume_weight(p.x);
        for a in 0..n {
            let [ax, ay] = p.dn_dx[a];
            let hoop_a = p.n[a] / r;
            for b in 0..n {
                let bx = p.dn_dx[b][0];
                let hoop_b = p.n[b] / r;
                // Written so that (a, b) and (b, a) round alike: K_e stays exactly symmetric.
                k[(2 * a, 2 * b)] += f * (lambda * (ax * hoop_b + hoop_a * bx) + diagonal * (hoop_a * hoop_b));
                let coupling = f * lambda * (ay * hoop_b);
                k[(2 * a + 1, 2 * b)] += coupling;
                k[(2 * b, 2 * a + 1)] += coupling;
            }
        }
    }
    Ok(())
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

    /// The 4×4 isotropic matrix on `[ε_rr, ε_zz, γ_rz, ε_θθ]`: `λ m mᵀ + μ diag(2, 2, 1, 2)`,
    /// `m = [1, 1, 0, 1]` (written from λ and μ, independently of the kinematics' blocks).
    fn isotropic_4x4(e: f64, nu: f64) -> nalgebra::Matrix4<f64> {
        let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let mu = e / (2.0 * (1.0 + nu));
        let m = nalgebra::Vector4::new(1.0, 1.0, 0.0, 1.0);
        m * m.transpose() * lambda + nalgebra::Matrix4::from_diagonal(&nalgebra::Vector4::new(2.0, 2.0, 1.0, 2.0)) * mu
    }

    /// A distorted cell off the axis, and the reference cell moved onto the axis (its leftmost
    /// nodes at r = 0: an edge of a quadrilateral, an edge of a triangle) and sheared in z.
    fn revolution_cells(t: ElementType, jitter: &[f64]) -> Vec<Vec<[f64; 2]>> {
        let reference = t.reference_nodes();
        let x_min = reference.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        let on_axis = reference.iter().map(|&[x, y]| [x - x_min, y + 0.3 * (x - x_min)]).collect();
        vec![distorted(t, jitter), on_axis]
    }

    proptest! {
        /// A body of revolution: K is symmetric, positive semi-definite, with exactly one zero
        /// mode (the axial translation; a radial translation strains the hoops), and the energy of
        /// a uniform state `u_r = a r, u_z = c z + d r` is `½ εᵀ D ε V` with the isotropic 4×4 `D`
        /// and Pappus' volume `V = 2π ∫ r dA`, to round-off (the integrand is `r` times a
        /// polynomial the stiffness rule integrates exactly).
        #[test]
        fn axisymmetric_stiffness_has_one_rigid_mode_and_the_uniform_energy(
            ti in 0usize..5,
            jitter in proptest::collection::vec(-1.0..1.0f64, 18),
            (a, c, d) in (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64),
        ) {
            let t = ElementType::ALL[ti];
            let m = Material::new(3.0, 0.3).unwrap();
            for coords in revolution_cells(t, &jitter) {
                let rule = Kinematics::Axisymmetric.stiffness_rule(t);
                let k = element_stiffness(t, &coords, &m, &Kinematics::Axisymmetric, &rule).unwrap();
                prop_assert!((k.clone() - k.transpose()).abs().max() == 0.0);
                let ev = symmetric_eigenvalues(&k);
                let scale = ev.last().copied().unwrap();
                prop_assert!(ev[0].abs() < 1e-10 * scale, "{ev:?}");
                prop_assert!(ev[1] > 1e-6 * scale, "{ev:?}");
                let axial: Vec<f64> = coords.iter().flat_map(|_| [0.0, 1.0]).collect();
                let ku = &k * nalgebra::DVector::from_vec(axial);
                prop_assert!(ku.abs().max() < 1e-12 * scale);

                let u: Vec<f64> = coords.iter().flat_map(|p| [a * p[0], c * p[1] + d * p[0]]).collect();
                let u = nalgebra::DVector::from_vec(u);
                let energy = 0.5 * u.dot(&(&k * &u));
                let eps = nalgebra::Vector4::new(a, c, d, a);
                let mut volume = 0.0;
                for (xi, w) in rule.points.iter().zip(&rule.weights) {
                    let p = map_point(t, &coords, *xi).unwrap();
                    volume += 2.0 * std::f64::consts::PI * p.x[0] * p.det_j * w;
                }
                let exact = 0.5 * eps.dot(&(isotropic_4x4(3.0, 0.3) * eps)) * volume;
                prop_assert!((energy - exact).abs() < 1e-12 * exact.abs().max(scale), "{energy} vs {exact}");
            }
        }
    }

    proptest! {
        /// K is symmetric, positive semi-definite, and has exactly three zero modes (rigid motions).
        #[test]
        fn stiffness_has_three_rigid_modes(ti in 0usize..5, jitter in proptest::collection::vec(-1.0..1.0f64, 18)) {
            let t = ElementType::ALL[ti];
            let coords = distorted(t, &jitter);
            let m = Material::new(1.0, 0.3).unwrap();
            let k = element_stiffness(t, &coords, &m, &Kinematics::plane(PlaneCondition::Stress, 1.0).unwrap(), &GaussRule::stiffness_rule(t)).unwrap();
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
            let m = Material::new(5.0, 0.2).unwrap();
            let k = element_stiffness(t, &coords, &m, &Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap(), &GaussRule::stiffness_rule(t)).unwrap();
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
            let m = Material::new(1.0, nu).unwrap();
            let k = element_stiffness_with(t, &coords, &m, &Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap(), &GaussRule::stiffness_rule(t), Formulation::BBar).unwrap();
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
            let m = Material::new(2.0, 0.45).unwrap();
            let rule = GaussRule::stiffness_rule(t);
            let k = element_stiffness_with(
                t,
                &coords,
                &m,
                &Kinematics::plane(PlaneCondition::Strain, 0.7).unwrap(),
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
                let d = DMatrix::from_iterator(3, 3, PlaneCondition::Strain.elasticity_matrix(&m).iter().copied());
                reference += bb.transpose() * d * &bb * (w * p.det_j * 0.7);
            }
            assert!((&k - &reference).abs().max() < 1e-12 * k.abs().max(), "{t:?}");
        }
    }

    /// A body of revolution under B-bar: `∫ Bᵀ D_d B 2πr + K Gᵀ M⁻¹ G` (the implementation, with
    /// the in-plane block and the hoop coupling of `D_d`) equals `∫ B̄ᵀ D B̄ 2πr` formed point by
    /// point from the 4-row definition `B̄ = B + ⅓ m (b̄ − b)ᵀ`, `m = [1, 1, 0, 1]`, `D` the 4×4
    /// isotropic matrix: a second algorithm for the same matrix. An axial translation produces
    /// no force, and a field of constant dilatation (`u = (c r, d z)`, θ̄ = θ) the same forces as
    /// the standard element's. Tolerance 1e-12 relative: round-off of sums of O(10²) terms.
    #[test]
    fn axisymmetric_bbar_equals_the_b_bar_product_formed_pointwise() {
        for t in [ElementType::Quad4, ElementType::Quad8, ElementType::Quad9, ElementType::Tri6] {
            let coords: Vec<[f64; 2]> =
                distorted(t, &[0.3, -0.7, 0.5, 0.1, -0.2, 0.9, -0.4]).iter().map(|x| [x[0] + 1.8, x[1]]).collect();
            let m = Material::new(2.0, 0.45).unwrap();
            let kin = Kinematics::Axisymmetric;
            let rule = kin.stiffness_rule(t);
            let k = element_stiffness_with(t, &coords, &m, &kin, &rule, Formulation::BBar).unwrap();
            let proj = crate::formulation::DilatationProjection::new_in(t, &coords, &rule, &kin).unwrap();
            let (e, nu) = (m.youngs_modulus(), m.poissons_ratio());
            let (lambda, mu) = (e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), e / (2.0 * (1.0 + nu)));
            let mut d = DMatrix::zeros(4, 4);
            for (i, j) in [(0, 0), (0, 1), (0, 3), (1, 0), (1, 1), (1, 3), (3, 0), (3, 1), (3, 3)] {
                d[(i, j)] = lambda + if i == j { 2.0 * mu } else { 0.0 };
            }
            d[(2, 2)] = mu;
            let n = t.num_nodes();
            let mut reference = DMatrix::zeros(2 * n, 2 * n);
            for (xi, w) in rule.points.iter().zip(&rule.weights) {
                let p = map_point(t, &coords, *xi).unwrap();
                let b_bar_row = proj.projected_divergence(p.x);
                let r = p.x[0];
                let mut bb = DMatrix::zeros(4, 2 * n);
                for a in 0..n {
                    let [gx, gy] = p.dn_dx[a];
                    bb[(0, 2 * a)] = gx;
                    bb[(1, 2 * a + 1)] = gy;
                    bb[(2, 2 * a)] = gy;
                    bb[(2, 2 * a + 1)] = gx;
                    bb[(3, 2 * a)] = p.n[a] / r;
                    for (c, g) in [(2 * a, gx + p.n[a] / r), (2 * a + 1, gy)] {
                        let shift = (b_bar_row[c] - g) / 3.0;
                        for row in [0, 1, 3] {
                            bb[(row, c)] += shift;
                        }
                    }
                }
                reference += bb.transpose() * &d * &bb * (w * p.det_j * 2.0 * std::f64::consts::PI * r);
            }
            let scale = k.abs().max();
            assert!((&k - &reference).abs().max() < 1e-12 * scale, "{t:?}");
            let axial = DMatrix::from_iterator(2 * n, 1, coords.iter().flat_map(|_| [0.0, 1.0]));
            assert!((&k * axial).abs().max() < 1e-12 * scale, "{t:?}: an axial translation is force-free");
            let standard = element_stiffness(t, &coords, &m, &kin, &rule).unwrap();
            let dilatation = DMatrix::from_iterator(2 * n, 1, coords.iter().flat_map(|x| [0.3 * x[0], -0.2 * x[1]]));
            assert!((&k * &dilatation - &standard * &dilatation).abs().max() < 1e-12 * scale, "{t:?}");
        }
    }

    /// Tri3 has no B-bar variant; the standard call is the `Standard` formulation.
    #[test]
    fn bbar_tri3_is_refused_and_standard_delegates() {
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let m = Material::new(1.0, 0.3).unwrap();
        let rule = GaussRule::triangle(1).unwrap();
        assert!(matches!(
            element_stiffness_with(
                ElementType::Tri3,
                &tri,
                &m,
                &Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap(),
                &rule,
                Formulation::BBar
            ),
            Err(ElementError::UnsupportedFormulation { .. })
        ));
        let a = element_stiffness(
            ElementType::Tri3,
            &tri,
            &m,
            &Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap(),
            &rule,
        )
        .unwrap();
        let b = element_stiffness_with(
            ElementType::Tri3,
            &tri,
            &m,
            &Kinematics::plane(PlaneCondition::Strain, 1.0).unwrap(),
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

//! Volumetric treatment of the displacement elements: the standard formulation or B̄ (B-bar),
//! which removes volumetric locking of nearly incompressible materials.
//!
//! Standard displacement elements enforce `div u ≈ 0` at every stiffness Gauss point when
//! `λ → ∞` (ν → ½ in plane strain); the discrete space cannot satisfy that many constraints and
//! the solution "locks" (displacements far too small, stresses polluted by `λ div u_h`). B̄
//! (Hughes 1980) replaces the dilatation `θ = ε11 + ε22 = b · u` by its L2 projection `θ̄` onto
//! a small, element-wise (discontinuous) pressure space `P_e`:
//!
//! ```text
//! in-plane split of D (both plane conditions, m = [1, 1, 0]):
//!   D = D_d + κ m mᵀ,   D_d = μ [ 1 -1  0 ]   (D_d m = 0)
//!                               [-1  1  0 ]
//!                               [ 0  0  1 ]
//!   μ = E / (2(1 + ν)),  κ = λ̂ + μ,  λ̂ = Eν/((1 + ν)(1 - 2ν)) (strain), Eν/(1 - ν²) (stress)
//!
//! pressure basis q(x) of P_e, in physical coordinates about the corner centroid x_c, scaled by h:
//!   Quad4, Tri6:    q = [1]                                  (constant dilatation)
//!   Quad8, Quad9:   q = [1, (x1 - x_c1)/h, (x2 - x_c2)/h]     (linear, discontinuous: Q2/P1)
//!
//! M = ∫_Ωe q qᵀ dΩ   (m × m),   G = ∫_Ωe q bᵀ dΩ   (m × 2n),  b_a = [∂N_a/∂x1, ∂N_a/∂x2]
//! θ̄(x) = q(x)ᵀ M⁻¹ G u_e                                        (the L2 projection of θ on P_e)
//! B̄ = B + ½ m (b̄ - b)ᵀ,   b̄ᵀ(x) = q(x)ᵀ M⁻¹ G                   (ε̄ = B̄ u_e: θ replaced by θ̄)
//!
//! K_e = ∫ B̄ᵀ D B̄ t dΩ = ∫ Bᵀ D_d B t dΩ + κ t Gᵀ M⁻¹ G          (D_d B̄ = D_d B, mᵀ B̄ = b̄ᵀ)
//! σ   = D ε̄ = D_d ε + κ θ̄ m
//! ```
//!
//! A body of revolution ([`Kinematics::Axisymmetric`]) splits the whole 3D dilatation, hoop
//! strain included, with every integral weighed by `2πr` (Hughes 1980, §4; Simo, Taylor &
//! Pister 1985 for the axisymmetric mean dilatation):
//!
//! ```text
//! ε = [ε_rr, ε_zz, γ_rz, ε_θθ],  m = [1, 1, 0, 1],  θ = ε_rr + ε_zz + ε_θθ = b · u,
//! b_a = [∂N_a/∂r + N_a/r, ∂N_a/∂z]
//! D = D_d + K m mᵀ,  K = λ + 2μ/3 (the bulk modulus),
//! D_d = μ [ 4/3 -2/3  0 -2/3 ]   (D_d m = 0)
//!         [-2/3  4/3  0 -2/3 ]
//!         [ 0    0    1  0   ]
//!         [-2/3 -2/3  0  4/3 ]
//! M = ∫ q qᵀ 2πr dA,  G = ∫ q bᵀ 2πr dA,  B̄ = B + ⅓ m (b̄ - b)ᵀ
//! K_e = ∫ Bᵀ D_d B 2πr dA + K Gᵀ M⁻¹ G,   σ = D_d ε + K θ̄ m
//! ```
//!
//! (`mᵀ m = 3` makes `mᵀ B̄ = b̄ᵀ`.) The in-plane block of `D_d` and its hoop coupling
//! `(−2μ/3, 4μ/3)` enter the stiffness exactly as `D_pp` and `(λ, λ + 2μ)` do in the
//! standard formulation ([`VolumetricSplit`]).
//!
//! This is the mixed u–p formulation with the discontinuous pressure `p = κ θ̄ ∈ P_e` condensed at
//! element level (Malkus & Hughes 1978): `∫ ε(v)ᵀ D_d ε(u) + ∫ p div v = f(v)`,
//! `∫ q (div u − p/κ) = 0 ∀ q ∈ P_e`. Its pairs are the inf-sup stable Q2/P1 (Quad9), P2/P0
//! (Tri6) and the classical mean-dilatation Q1/P0 (Quad4, stable up to a checkerboard pressure
//! mode that does not affect displacements); Q8/P1 is used in practice in the same way. Tri3 has
//! constant strain already, so projecting its dilatation changes nothing and it still locks:
//! B̄ is refused for Tri3 ([`ElementError::UnsupportedFormulation`]). Since the constants are
//! in every `P_e`, an affine displacement has `θ̄ = θ`: B̄ passes the patch test.
//!
//! A single Tri6 element under B̄ has two zero-energy modes besides the rigid motions (the
//! quadratic conformal fields `u1 + i u2 = c z²`, whose dilatation has zero element mean); they
//! are not compatible with the neighbours' constant pressures, so an assembled mesh has none.
//!
//! # References
//! T. J. R. Hughes (1980), Generalization of selective integration procedures to anisotropic and
//! nonlinear media, IJNME 15, 1413–1418, eq. (14)–(20). D. S. Malkus, T. J. R. Hughes (1978),
//! Mixed finite element methods — reduced and selective integration techniques: a unification of
//! concepts, CMAME 15, 63–81. D. Boffi, F. Brezzi, M. Fortin (2013), Mixed Finite Element Methods
//! and Applications, §8.6–8.7 (Q2/P1, P2/P0). J. C. Simo, R. L. Taylor, K. S. Pister (1985),
//! Variational and projection methods for the volume constraint in finite deformation
//! elasto-plasticity, CMAME 51, 177–208 (the axisymmetric mean dilatation).

use nalgebra::{DMatrix, Matrix3};

use crate::error::ElementError;
use crate::isoparametric::{check_node_count, map_point};
use crate::kinematics::Kinematics;
use crate::material::{Material, PlaneCondition};
use crate::quadrature::GaussRule;
use crate::shape::ElementType;

/// How the volumetric part of the strain is discretised.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Formulation {
    /// `ε = B u` at every Gauss point (locks in plane strain as ν → ½).
    #[default]
    Standard,
    /// B̄: the dilatation projected onto the element pressure space (module docs); locking-free
    /// for Quad4, Quad8, Quad9 and Tri6.
    BBar,
}

impl Formulation {
    /// Whether `element` supports this formulation (B̄: every kind but Tri3).
    pub fn supports(self, element: ElementType) -> bool {
        match self {
            Formulation::Standard => true,
            Formulation::BBar => pressure_space_dim(element).is_some(),
        }
    }

    /// Checks [`Formulation::supports`].
    ///
    /// # Errors
    /// [`ElementError::UnsupportedFormulation`] otherwise.
    pub fn check(self, element: ElementType) -> Result<(), ElementError> {
        if self.supports(element) {
            Ok(())
        } else {
            Err(ElementError::UnsupportedFormulation {
                element: format!("{element:?}"),
                formulation: format!("{self:?}"),
            })
        }
    }
}

/// Dimension of the B̄ pressure space of `element` (module docs); `None` for Tri3.
pub fn pressure_space_dim(element: ElementType) -> Option<usize> {
    match element {
        ElementType::Tri3 => None,
        ElementType::Quad4 | ElementType::Tri6 => Some(1),
        ElementType::Quad8 | ElementType::Quad9 => Some(3),
    }
}

/// Poisson's ratio above which standard elements in plane strain get a [`locking_warning`].
///
/// Measured (`docs/verification.md`, "Nearly incompressible materials"): the locking part of
/// the standard elements' stress error grows like `1/(1 − 2ν)`. On the Lamé cylinder (finest
/// meshes) the standard L2 stress error is 3× (quadratic kinds) to 2× (Quad4) the B-bar error at
/// ν = 0.3, 8× (Quad4) to 12× (Quad8, Quad9) at ν = 0.45, 40–58× at 0.49; the flagship's stress
/// concentration K (N = 32, plane strain, μ = 0 and 0.3) exceeds the B-bar value by 3–5 % at
/// ν = 0.3 (the plain discretisation difference), 9–12 % at 0.45, 27–29 % at 0.49 and 120–150 %
/// at 0.499. Past 0.45 the standard error is an order of magnitude above the locking-free one.
pub const LOCKING_POISSON_THRESHOLD: f64 = 0.45;

/// A warning when standard displacement elements in plane strain are used past
/// [`LOCKING_POISSON_THRESHOLD`]; `None` in plane stress (λ̂ = Eν/(1 − ν²) stays bounded), for
/// B̄, or below the threshold.
///
/// # Examples
/// ```
/// use contact2d_element::{Formulation, PlaneCondition, locking_warning};
/// assert!(locking_warning(PlaneCondition::Strain, 0.4999, Formulation::Standard).is_some());
/// assert!(locking_warning(PlaneCondition::Strain, 0.4999, Formulation::BBar).is_none());
/// assert!(locking_warning(PlaneCondition::Stress, 0.4999, Formulation::Standard).is_none());
/// assert!(locking_warning(PlaneCondition::Strain, 0.3, Formulation::Standard).is_none());
/// ```
pub fn locking_warning(plane: PlaneCondition, poissons_ratio: f64, formulation: Formulation) -> Option<String> {
    let kinematics = match plane {
        PlaneCondition::Stress => Kinematics::PlaneStress { thickness: 1.0 },
        PlaneCondition::Strain => Kinematics::PlaneStrain { thickness: 1.0 },
    };
    locking_warning_in(&kinematics, poissons_ratio, formulation)
}

/// [`locking_warning`] for a body of any [`Kinematics`]: plane strain and bodies of revolution
/// lock (λ = Eν/((1 + ν)(1 − 2ν)) grows without bound as ν → ½), plane stress does not.
pub fn locking_warning_in(kinematics: &Kinematics, poissons_ratio: f64, formulation: Formulation) -> Option<String> {
    (!matches!(kinematics, Kinematics::PlaneStress { .. })
        && formulation == Formulation::Standard
        && poissons_ratio > LOCKING_POISSON_THRESHOLD)
        .then(|| {
            format!(
                "{} with ν = {poissons_ratio} > {LOCKING_POISSON_THRESHOLD}: standard displacement \
                 elements lock volumetrically (displacements too small, stresses polluted); use the B-bar \
                 formulation (scene key plate_insert.formulation = \"bbar\")",
                kinematics.name()
            )
        })
}

/// `(λ̂, μ)`: the in-plane Lamé parameters with `D = λ̂ m mᵀ + μ diag(2, 2, 1)` (module docs).
pub fn lame_parameters(material: &Material, plane: PlaneCondition) -> (f64, f64) {
    let (e, nu) = (material.youngs_modulus(), material.poissons_ratio());
    let mu = e / (2.0 * (1.0 + nu));
    let lambda = match plane {
        PlaneCondition::Strain => e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
        PlaneCondition::Stress => e * nu / (1.0 - nu * nu),
    };
    (lambda, mu)
}

/// `(D_d, κ)` of the split `D = D_d + κ m mᵀ` (module docs), `D_d` built from μ alone so that
/// it carries no cancellation error when `κ ≫ μ`.
pub fn deviatoric_split(material: &Material, plane: PlaneCondition) -> (Matrix3<f64>, f64) {
    let (lambda, mu) = lame_parameters(material, plane);
    (Matrix3::new(mu, -mu, 0.0, -mu, mu, 0.0, 0.0, 0.0, mu), lambda + mu)
}

/// The split `D = D_d + κ m mᵀ` of a body's [`Kinematics`] (module docs): the in-plane block
/// of `D_d`, its hoop coupling for a body of revolution, and `κ`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolumetricSplit {
    /// The `[ε11, ε22, γ12]` block of `D_d`.
    pub deviatoric: Matrix3<f64>,
    /// `(D_d[rr, θθ], D_d[θθ, θθ]) = (−2μ/3, 4μ/3)` for a body of revolution; `None` in the
    /// plane.
    pub hoop: Option<(f64, f64)>,
    /// `κ`: `λ̂ + μ` in the plane (`m = [1, 1, 0]`), the bulk modulus `λ + 2μ/3` for a body of
    /// revolution (`m = [1, 1, 0, 1]`).
    pub bulk: f64,
}

/// The [`VolumetricSplit`] of `material` in `kinematics`: [`deviatoric_split`] in the plane;
/// for a body of revolution the 3D split with `λ = Eν/((1 + ν)(1 − 2ν))`.
pub fn volumetric_split(material: &Material, kinematics: &Kinematics) -> VolumetricSplit {
    if let Some(plane) = kinematics.plane_condition() {
        let (deviatoric, bulk) = deviatoric_split(material, plane);
        return VolumetricSplit { deviatoric, hoop: None, bulk };
    }
    let (e, nu) = (material.youngs_modulus(), material.poissons_ratio());
    let mu = e / (2.0 * (1.0 + nu));
    let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    let (diagonal, off) = (4.0 * mu / 3.0, -2.0 * mu / 3.0);
    VolumetricSplit {
        deviatoric: Matrix3::new(diagonal, off, 0.0, off, diagonal, 0.0, 0.0, 0.0, mu),
        hoop: Some((off, diagonal)),
        bulk: lambda + 2.0 * mu / 3.0,
    }
}

/// The L2 projection of the dilatation onto an element's pressure space: `θ̄(x) = q(x)ᵀ P u_e`
/// with `P = M⁻¹ G` (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct DilatationProjection {
    centre: [f64; 2],
    scale: f64,
    /// `G = ∫ q bᵀ dΩ` (m × 2n).
    pub g: DMatrix<f64>,
    /// `M⁻¹ G` (m × 2n).
    pub p: DMatrix<f64>,
}

impl DilatationProjection {
    /// The projection of the element with nodal `coords`, integrated with `rule`.
    ///
    /// # Errors
    /// [`ElementError::UnsupportedFormulation`] for Tri3, the map's errors, or
    /// [`ElementError::UnsupportedRule`] when `rule` is too small to make `M` invertible.
    pub fn new(element: ElementType, coords: &[[f64; 2]], rule: &GaussRule) -> Result<Self, ElementError> {
        Self::new_in(element, coords, rule, &Kinematics::PlaneStrain { thickness: 1.0 })
    }

    /// The projection in a body of the given [`Kinematics`]: in the plane as [`Self::new`] (the
    /// weight `t` is applied by [`Self::volumetric_stiffness`]); for a body of revolution `M`
    /// and `G` weighed by `2πr` and the divergence row with the hoop term `N_a / r` (module
    /// docs).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn new_in(
        element: ElementType,
        coords: &[[f64; 2]],
        rule: &GaussRule,
        kinematics: &Kinematics,
    ) -> Result<Self, ElementError> {
        Formulation::BBar.check(element)?;
        check_node_count(element, coords)?;
        let m_dim = pressure_space_dim(element).unwrap_or(1);
        let corners = if element.is_triangle() { 3 } else { 4 };
        let k = corners as f64;
        let centre = [
            coords[..corners].iter().map(|c| c[0]).sum::<f64>() / k,
            coords[..corners].iter().map(|c| c[1]).sum::<f64>() / k,
        ];
        let scale = coords[..corners]
            .iter()
            .map(|c| (c[0] - centre[0]).hypot(c[1] - centre[1]))
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        let mut proj =
            DilatationProjection { centre, scale, g: DMatrix::zeros(m_dim, 2 * coords.len()), p: DMatrix::zeros(0, 0) };
        let mut m = DMatrix::zeros(m_dim, m_dim);
        for (xi, w) in rule.points.iter().zip(&rule.weights) {
            let pt = map_point(element, coords, *xi)?;
            // × 1.0 exactly in the plane; Gauss points lie inside the cell, so r > 0.
            let f = w * pt.det_j * kinematics.varying_weight(pt.x);
            let hoop = kinematics.has_hoop_strain().then_some(pt.x[0]);
            let q = proj.basis(pt.x);
            for i in 0..m_dim {
                for j in 0..m_dim {
                    m[(i, j)] += f * q[i] * q[j];
                }
                for a in 0..pt.len {
                    let radial = match hoop {
                        None => pt.dn_dx[a][0],
                        Some(r) => pt.dn_dx[a][0] + pt.n[a] / r,
                    };
                    proj.g[(i, 2 * a)] += f * q[i] * radial;
                    proj.g[(i, 2 * a + 1)] += f * q[i] * pt.dn_dx[a][1];
                }
            }
        }
        let chol = m.cholesky().ok_or_else(|| ElementError::UnsupportedRule {
            what: format!("{}-point rule: the B-bar pressure Gram matrix of {element:?} is singular", rule.len()),
        })?;
        proj.p = chol.solve(&proj.g);
        Ok(proj)
    }

    /// The pressure basis `q(x)` (first `m` entries meaningful).
    fn basis(&self, x: [f64; 2]) -> [f64; 3] {
        [1.0, (x[0] - self.centre[0]) / self.scale, (x[1] - self.centre[1]) / self.scale]
    }

    /// `b̄ᵀ(x) = q(x)ᵀ M⁻¹ G`: the row that maps element displacements to `θ̄(x)`.
    pub fn projected_divergence(&self, x: [f64; 2]) -> Vec<f64> {
        let q = self.basis(x);
        (0..self.p.ncols()).map(|c| (0..self.p.nrows()).map(|i| q[i] * self.p[(i, c)]).sum()).collect()
    }

    /// `θ̄(x)` for element displacements `u = [u_0x, u_0y, ...]`.
    pub fn dilatation(&self, x: [f64; 2], u: &[f64]) -> f64 {
        self.projected_divergence(x).iter().zip(u).map(|(b, u)| b * u).sum()
    }

    /// The volumetric stiffness `κ t Gᵀ M⁻¹ G = κ t Gᵀ P` (2n × 2n); `t` is 1 for a body of
    /// revolution, whose `G` carries the `2πr` ([`Kinematics::uniform_factor`]).
    pub fn volumetric_stiffness(&self, kappa: f64, thickness: f64) -> DMatrix<f64> {
        (self.g.transpose() * &self.p) * (kappa * thickness)
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn split_reproduces_the_elasticity_matrix() {
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            let m = Material::new(3.0, 0.35).unwrap();
            let (dd, kappa) = deviatoric_split(&m, plane);
            let mm = nalgebra::Vector3::new(1.0, 1.0, 0.0);
            let d = dd + mm * mm.transpose() * kappa;
            assert!((d - plane.elasticity_matrix(&m)).abs().max() < 1e-14, "{plane:?}");
            assert!((dd * mm).abs().max() == 0.0);
        }
    }

    #[test]
    fn projection_reproduces_a_dilatation_in_the_space() {
        // Quad9 on a distorted cell: u = (x1² / 2, x1 x2 / 2) has θ = 1.5 x1, linear, so θ̄ = θ.
        let coords: Vec<[f64; 2]> = ElementType::Quad9
            .reference_nodes()
            .iter()
            .map(|&[x, y]| [1.1 * x + 0.2 * y + 3.0, -0.1 * x + 0.9 * y])
            .collect();
        let u: Vec<f64> = coords.iter().flat_map(|&[x, y]| [0.5 * x * x, 0.5 * x * y]).collect();
        let proj = DilatationProjection::new(ElementType::Quad9, &coords, &GaussRule::quad(3).unwrap()).unwrap();
        for x in [[3.0, 0.0], [3.5, 0.4], [2.2, -0.7]] {
            assert!((proj.dilatation(x, &u) - 1.5 * x[0]).abs() < 1e-12);
        }
        // Quad4 takes the mean: u = (x1², 0) on the unit square gives θ̄ = mean(2 x1) = 1.
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let u: Vec<f64> = sq.iter().flat_map(|&[x, _]| [x * x, 0.0]).collect();
        let proj = DilatationProjection::new(ElementType::Quad4, &sq, &GaussRule::quad(2).unwrap()).unwrap();
        assert!((proj.dilatation([0.1, 0.9], &u) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn tri3_and_a_too_small_rule_are_errors() {
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let e = DilatationProjection::new(ElementType::Tri3, &tri, &GaussRule::triangle(1).unwrap());
        assert!(matches!(e, Err(ElementError::UnsupportedFormulation { .. })));
        let q9 = ElementType::Quad9.reference_nodes();
        assert!(matches!(
            DilatationProjection::new(ElementType::Quad9, q9, &GaussRule::quad(1).unwrap()),
            Err(ElementError::UnsupportedRule { .. })
        ));
        assert!(Formulation::Standard.supports(ElementType::Tri3));
        assert!(!Formulation::BBar.supports(ElementType::Tri3));
    }
}

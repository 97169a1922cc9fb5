//! Linear isotropic elasticity: the material (E, ν), and the plane reductions of its 3D law.
//!
//! Voigt notation with engineering shear strain, `ε = [ε11, ε22, γ12]`, `γ12 = 2 ε12`,
//! `σ = [σ11, σ22, σ12]`, `σ = D ε`:
//!
//! ```text
//! plane stress:  D = E/(1-ν²)        [ 1   ν   0       ]
//!                                    [ ν   1   0       ]
//!                                    [ 0   0   (1-ν)/2 ]
//!
//! plane strain:  D = E/((1+ν)(1-2ν)) [ 1-ν  ν    0        ]
//!                                    [ ν    1-ν  0        ]
//!                                    [ 0    0    (1-2ν)/2 ]
//! ```
//!
//! The strain energy density is `½ εᵀ D ε`; for plane stress this is the paper's (1.1):
//! `E/(2(1-ν²)) [e11² + 2ν e11 e22 + e22² + 2(1-ν) e12²]`.
//!
//! A [`Material`] is E and ν alone: which reduction applies (plane stress, plane strain, or a body
//! of revolution) is the body's [`crate::Kinematics`], chosen per model.

use nalgebra::Matrix3;

use crate::error::ElementError;

/// Which plane reduction of 3D elasticity (of a plane [`crate::Kinematics`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlaneCondition {
    /// σ33 = 0 (thin plates; the paper's case).
    Stress,
    /// ε33 = 0 (long bodies).
    Strain,
}

impl PlaneCondition {
    /// The elasticity matrix `D` of `material` in this reduction (see the module docs).
    pub fn elasticity_matrix(self, material: &Material) -> Matrix3<f64> {
        let (e, nu) = (material.youngs_modulus, material.poissons_ratio);
        match self {
            PlaneCondition::Stress => {
                let c = e / (1.0 - nu * nu);
                Matrix3::new(c, c * nu, 0.0, c * nu, c, 0.0, 0.0, 0.0, c * 0.5 * (1.0 - nu))
            }
            PlaneCondition::Strain => {
                let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
                Matrix3::new(
                    c * (1.0 - nu),
                    c * nu,
                    0.0,
                    c * nu,
                    c * (1.0 - nu),
                    0.0,
                    0.0,
                    0.0,
                    c * 0.5 * (1.0 - 2.0 * nu),
                )
            }
        }
    }

    /// The out-of-plane stress σ33 of an in-plane stress state: zero in plane stress,
    /// `ν (σ11 + σ22)` in plane strain.
    pub fn out_of_plane_stress(self, material: &Material, stress: &[f64; 3]) -> f64 {
        match self {
            PlaneCondition::Stress => 0.0,
            PlaneCondition::Strain => material.poissons_ratio * (stress[0] + stress[1]),
        }
    }
}

/// An isotropic linear elastic material: Young's modulus and Poisson's ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    youngs_modulus: f64,
    poissons_ratio: f64,
}

impl Material {
    /// A material with Young's modulus `E > 0` and Poisson's ratio `-1 < ν < 0.5`.
    ///
    /// # Errors
    /// [`ElementError::InvalidMaterial`] for a non-finite or out-of-range parameter.
    pub fn new(youngs_modulus: f64, poissons_ratio: f64) -> Result<Self, ElementError> {
        if !(youngs_modulus.is_finite() && youngs_modulus > 0.0) {
            return Err(ElementError::InvalidMaterial {
                reason: format!("Young's modulus must be positive and finite, got {youngs_modulus}"),
            });
        }
        if !(poissons_ratio.is_finite() && poissons_ratio > -1.0 && poissons_ratio < 0.5) {
            return Err(ElementError::InvalidMaterial {
                reason: format!("Poisson's ratio must lie in (-1, 0.5), got {poissons_ratio}"),
            });
        }
        Ok(Material { youngs_modulus, poissons_ratio })
    }

    /// Young's modulus E.
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson's ratio ν.
    pub fn poissons_ratio(&self) -> f64 {
        self.poissons_ratio
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn rejects_out_of_range_parameters() {
        for (e, nu) in [(0.0, 0.3), (-1.0, 0.3), (f64::NAN, 0.3), (1.0, 0.5), (1.0, -1.0), (1.0, f64::INFINITY)] {
            assert!(matches!(Material::new(e, nu), Err(ElementError::InvalidMaterial { .. })));
        }
    }

    #[test]
    fn plane_stress_energy_matches_paper_form() {
        // (1.1): W = E/(2(1-ν²)) [e11² + 2ν e11 e22 + e22² + 2(1-ν) e12²], with γ = 2 e12.
        let m = Material::new(2.0, 0.3).unwrap();
        let (e11, e22, e12) = (0.1, -0.03, 0.02);
        let eps = nalgebra::Vector3::new(e11, e22, 2.0 * e12);
        let w = 0.5 * eps.dot(&(PlaneCondition::Stress.elasticity_matrix(&m) * eps));
        let paper = 2.0 / (2.0 * (1.0 - 0.09)) * (e11 * e11 + 0.6 * e11 * e22 + e22 * e22 + 1.4 * e12 * e12);
        assert!((w - paper).abs() < 1e-15);
    }

    #[test]
    fn plane_strain_has_zero_out_of_plane_strain() {
        // ε33 = (σ33 - ν(σ11 + σ22))/E must vanish.
        let m = Material::new(3.0, 0.25).unwrap();
        let s = PlaneCondition::Strain.elasticity_matrix(&m) * nalgebra::Vector3::new(0.01, 0.02, 0.003);
        let s = [s[0], s[1], s[2]];
        let s33 = PlaneCondition::Strain.out_of_plane_stress(&m, &s);
        assert!((s33 - 0.25 * (s[0] + s[1])).abs() < 1e-15);
    }
}

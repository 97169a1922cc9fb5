//! The 2D kinematics of a body: which reduction of 3D elasticity the plane model stands for, and
//! the measures that depend on it.
//!
//! ```text
//! plane stress  (σ33 = 0):  dV = t dA,   dΓ = t ds,   σ33 = 0
//! plane strain  (ε33 = 0):  dV = t dA,   dΓ = t ds,   σ33 = ν (σ11 + σ22)
//! ```
//!
//! `t` is the out-of-plane thickness (1 in the paper). Every integral of the element layer
//! (stiffness, body force, edge traction) takes its weight from [`Kinematics::volume_weight`] or
//! [`Kinematics::boundary_weight`], which receive the point `x` so that a body of revolution
//! (weight `2πr`, a later variant) is one more arm here and not a search through the callers.

use crate::error::ElementError;
use crate::material::PlaneCondition;

/// The kinematics of a 2D body: plane stress or plane strain, each with its thickness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kinematics {
    /// σ33 = 0 (thin plates; the paper's case), thickness `t`.
    PlaneStress {
        /// Out-of-plane thickness `t > 0`.
        thickness: f64,
    },
    /// ε33 = 0 (long bodies), thickness `t` (the length the forces are per).
    PlaneStrain {
        /// Out-of-plane thickness `t > 0`.
        thickness: f64,
    },
}

impl Kinematics {
    /// The plane kinematics of `plane` with `thickness`.
    ///
    /// # Errors
    /// [`ElementError::InvalidThickness`] when the thickness is not positive and finite.
    ///
    /// # Examples
    /// ```
    /// use contact2d_element::{Kinematics, PlaneCondition};
    /// let k = Kinematics::plane(PlaneCondition::Stress, 2.0).unwrap();
    /// assert_eq!(k, Kinematics::PlaneStress { thickness: 2.0 });
    /// assert_eq!(k.volume_weight([0.3, 0.1]), 2.0);
    /// assert!(Kinematics::plane(PlaneCondition::Strain, 0.0).is_err());
    /// ```
    pub fn plane(plane: PlaneCondition, thickness: f64) -> Result<Self, ElementError> {
        if !(thickness.is_finite() && thickness > 0.0) {
            return Err(ElementError::InvalidThickness { thickness });
        }
        Ok(match plane {
            PlaneCondition::Stress => Kinematics::PlaneStress { thickness },
            PlaneCondition::Strain => Kinematics::PlaneStrain { thickness },
        })
    }

    /// The plane condition (stress or strain) of this kinematics.
    pub fn plane_condition(&self) -> PlaneCondition {
        match self {
            Kinematics::PlaneStress { .. } => PlaneCondition::Stress,
            Kinematics::PlaneStrain { .. } => PlaneCondition::Strain,
        }
    }

    /// The out-of-plane thickness `t`.
    pub fn thickness(&self) -> f64 {
        match *self {
            Kinematics::PlaneStress { thickness } | Kinematics::PlaneStrain { thickness } => thickness,
        }
    }

    /// The volume weight at the point `x`: `dV = volume_weight(x) dA` (`t` in the plane).
    pub fn volume_weight(&self, _x: [f64; 2]) -> f64 {
        self.thickness()
    }

    /// The boundary weight at the point `x`: `dΓ = boundary_weight(x) ds` (`t` in the plane).
    pub fn boundary_weight(&self, _x: [f64; 2]) -> f64 {
        self.thickness()
    }

    /// The weight of an integral whose integrand does not vary across the element, such as the
    /// B-bar volumetric term `κ t Gᵀ M⁻¹ G` (`t` in the plane).
    pub fn uniform_weight(&self) -> f64 {
        self.thickness()
    }

    /// The out-of-plane stress σ33 of the in-plane stress `[σ11, σ22, σ12]` of a material of
    /// Poisson's ratio `ν`: zero in plane stress, `ν (σ11 + σ22)` in plane strain.
    pub fn out_of_plane_stress(&self, poissons_ratio: f64, stress: &[f64; 3]) -> f64 {
        match self {
            Kinematics::PlaneStress { .. } => 0.0,
            Kinematics::PlaneStrain { .. } => poissons_ratio * (stress[0] + stress[1]),
        }
    }

    /// The number of rigid-body modes of a free body: three in the plane (two translations, one
    /// rotation).
    pub fn rigid_modes(&self) -> usize {
        3
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::material::Material;

    #[test]
    fn plane_round_trips_and_refuses_bad_thickness() {
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            let k = Kinematics::plane(plane, 0.7).unwrap();
            assert_eq!(k.plane_condition(), plane);
            assert_eq!(k.thickness(), 0.7);
            assert_eq!(k.boundary_weight([1.0, 2.0]), 0.7);
        }
        for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(Kinematics::plane(PlaneCondition::Stress, t), Err(ElementError::InvalidThickness { .. })));
        }
    }

    #[test]
    fn out_of_plane_stress_matches_the_material() {
        // The same formula written twice (Material keeps its own for now): they must agree exactly.
        let s = [3.0, -1.25, 0.5];
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            let m = Material::new(2.0, 0.3, plane).unwrap();
            let k = Kinematics::plane(plane, 1.0).unwrap();
            assert_eq!(k.out_of_plane_stress(m.poissons_ratio(), &s), m.out_of_plane_stress(&s));
        }
    }
}

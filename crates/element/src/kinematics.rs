//! The 2D kinematics of a body: which reduction of 3D elasticity the plane model stands for, and
//! the measures that depend on it.
//!
//! ```text
//! plane stress  (σ33 = 0):  dV = t dA,   dΓ = t ds,   σ33 = 0
//! plane strain  (ε33 = 0):  dV = t dA,   dΓ = t ds,   σ33 = ν (σ11 + σ22)
//! axisymmetric  (x = r ≥ 0, y = z, no twist):
//!                ε = [ε_rr, ε_zz, γ_rz, ε_θθ],  ε_θθ = u_r / r,
//!                dV = 2πr dA,  dΓ = 2πr ds,  σθθ = λ (ε_rr + ε_zz) + (λ + 2μ) ε_θθ
//! ```
//!
//! `t` is the out-of-plane thickness (1 in the paper). Every integral of the element layer
//! (stiffness, body force, edge traction) takes its weight from [`Kinematics::volume_weight`] or
//! [`Kinematics::boundary_weight`], which receive the point `x`: a body of revolution is one
//! more arm here, and its forces are totals over the circumference (as Abaqus' CAX elements
//! report them).

use std::f64::consts::PI;

use nalgebra::Matrix3;

use crate::error::ElementError;
use crate::material::{Material, PlaneCondition};
use crate::quadrature::GaussRule;
use crate::shape::ElementType;

/// The kinematics of a 2D body: plane stress or plane strain, each with its thickness, or a body
/// of revolution.
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
    /// A body of revolution about the `y` axis (`x = r ≥ 0`, `y = z`), loaded without twist:
    /// the hoop strain `u_r / r` is a fourth strain component and every measure carries `2πr`.
    Axisymmetric,
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
    /// assert_eq!(Kinematics::Axisymmetric.volume_weight([0.5, 0.1]), std::f64::consts::PI);
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

    /// The plane condition (stress or strain) of a plane kinematics; `None` for a body of
    /// revolution.
    pub fn plane_condition(&self) -> Option<PlaneCondition> {
        match self {
            Kinematics::PlaneStress { .. } => Some(PlaneCondition::Stress),
            Kinematics::PlaneStrain { .. } => Some(PlaneCondition::Strain),
            Kinematics::Axisymmetric => None,
        }
    }

    /// The out-of-plane thickness `t` of a plane kinematics; `None` for a body of revolution,
    /// whose forces are totals over the circumference.
    pub fn thickness(&self) -> Option<f64> {
        match *self {
            Kinematics::PlaneStress { thickness } | Kinematics::PlaneStrain { thickness } => Some(thickness),
            Kinematics::Axisymmetric => None,
        }
    }

    /// The volume weight at the point `x`: `dV = volume_weight(x) dA` (`t` in the plane, `2πr`
    /// for a body of revolution).
    pub fn volume_weight(&self, x: [f64; 2]) -> f64 {
        match *self {
            Kinematics::PlaneStress { thickness } | Kinematics::PlaneStrain { thickness } => thickness,
            Kinematics::Axisymmetric => 2.0 * PI * x[0],
        }
    }

    /// The boundary weight at the point `x`: `dΓ = boundary_weight(x) ds` (`t` in the plane,
    /// `2πr` for a body of revolution).
    pub fn boundary_weight(&self, x: [f64; 2]) -> f64 {
        self.volume_weight(x)
    }

    /// The part of the volume weight that varies over a cell: `1` in the plane, `2πr` for a body
    /// of revolution, so that `volume_weight(x) = uniform_factor() · varying_weight(x)`. The
    /// B-bar projection's `M` and `G` are integrated with it ([`crate::DilatationProjection`]).
    pub fn varying_weight(&self, x: [f64; 2]) -> f64 {
        match self {
            Kinematics::PlaneStress { .. } | Kinematics::PlaneStrain { .. } => 1.0,
            Kinematics::Axisymmetric => 2.0 * PI * x[0],
        }
    }

    /// The part of the volume weight that is the same everywhere: the thickness `t` in the
    /// plane, `1` for a body of revolution.
    pub fn uniform_factor(&self) -> f64 {
        self.thickness().unwrap_or(1.0)
    }

    /// The measure of the contact pairs' boundary integrals (tributary lengths, segment-to-segment
    /// weights) at `x`: `1` in the plane, where a pair's weight is per unit thickness and
    /// [`Kinematics::pair_area_factor`] (`t`) turns it into an area; `2πr` for a body of
    /// revolution, whose pair weight is the area of the node's ring itself
    /// ([`Kinematics::varying_weight`]).
    pub fn pairing_measure(&self, x: [f64; 2]) -> f64 {
        self.varying_weight(x)
    }

    /// What turns a contact pair's weight into its contact area (pressure `p = λ / (w f)`): the
    /// thickness `t` in the plane, `1` for a body of revolution ([`Kinematics::uniform_factor`]).
    pub fn pair_area_factor(&self) -> f64 {
        self.uniform_factor()
    }

    /// Whether the strain has the hoop row `ε_θθ = u_r / r` (a body of revolution).
    pub fn has_hoop_strain(&self) -> bool {
        matches!(self, Kinematics::Axisymmetric)
    }

    /// The in-plane block of the constitutive matrix, acting on `[ε11, ε22, γ12]`: the plane
    /// stress or plane strain matrix ([`PlaneCondition::elasticity_matrix`]) in the plane, the
    /// plane-strain matrix (the `rr, zz, rz` block of the 4×4 isotropic matrix) for a body of
    /// revolution.
    pub fn in_plane_elasticity(&self, material: &Material) -> Matrix3<f64> {
        match self {
            Kinematics::PlaneStress { .. } => PlaneCondition::Stress.elasticity_matrix(material),
            Kinematics::PlaneStrain { .. } => PlaneCondition::Strain.elasticity_matrix(material),
            Kinematics::Axisymmetric => {
                let (e, nu) = (material.youngs_modulus(), material.poissons_ratio());
                let c = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
                let (a, b, g) = (c * (1.0 - nu), c * nu, c * 0.5 * (1.0 - 2.0 * nu));
                Matrix3::new(a, b, 0.0, b, a, 0.0, 0.0, 0.0, g)
            }
        }
    }

    /// The hoop coupling of a body of revolution, `(λ, λ + 2μ)`: the constitutive rows
    /// `σ11 += λ ε_θθ`, `σ22 += λ ε_θθ`, `σθθ = λ (ε11 + ε22) + (λ + 2μ) ε_θθ`; `None` in the
    /// plane.
    pub fn hoop_elasticity(&self, material: &Material) -> Option<(f64, f64)> {
        self.has_hoop_strain().then(|| {
            let (e, nu) = (material.youngs_modulus(), material.poissons_ratio());
            let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
            let mu = e / (2.0 * (1.0 + nu));
            (lambda, lambda + 2.0 * mu)
        })
    }

    /// The out-of-plane stress where it follows from the in-plane stress `[σ11, σ22, σ12]` of a
    /// material: zero in plane stress, `ν (σ11 + σ22)` in plane strain; `None` for a body of
    /// revolution, whose σθθ needs the hoop strain ([`crate::stress_state_at`]).
    pub fn out_of_plane_stress(&self, material: &Material, stress: &[f64; 3]) -> Option<f64> {
        match self {
            Kinematics::PlaneStress { .. } => Some(PlaneCondition::Stress.out_of_plane_stress(material, stress)),
            Kinematics::PlaneStrain { .. } => Some(PlaneCondition::Strain.out_of_plane_stress(material, stress)),
            Kinematics::Axisymmetric => None,
        }
    }

    /// The rigid motions of a free body, as `(a, b, θ)` vectors of `u(x) = (a − θ x2, b + θ x1)`:
    /// all three in the plane; the axial translation `(0, 1, 0)` alone for a body of revolution
    /// (a radial translation or an in-plane rotation would strain the hoops).
    pub fn rigid_motions(&self) -> Vec<[f64; 3]> {
        match self {
            Kinematics::PlaneStress { .. } | Kinematics::PlaneStrain { .. } => {
                vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
            }
            Kinematics::Axisymmetric => vec![[0.0, 1.0, 0.0]],
        }
    }

    /// The number of rigid-body modes of a free body: three in the plane, one for a body of
    /// revolution.
    pub fn rigid_modes(&self) -> usize {
        self.rigid_motions().len()
    }

    /// The Gauss rule of the element stiffness (and of the stress recovery's Gauss points):
    /// [`GaussRule::stiffness_rule`] in the plane. A body of revolution takes one degree more
    /// on triangles — 3 points on Tri3 (one point would leave the 4-row strain operator rank 4, a
    /// spurious zero-energy mode besides the axial translation) and 6 on Tri6 (`r` times the
    /// plane integrand is one degree higher); the quadrilaterals' product rules already integrate
    /// that extra degree.
    pub fn stiffness_rule(&self, element: ElementType) -> GaussRule {
        let triangle = match (self, element) {
            (Kinematics::Axisymmetric, ElementType::Tri3) => GaussRule::triangle(2),
            (Kinematics::Axisymmetric, ElementType::Tri6) => GaussRule::triangle(4),
            _ => return GaussRule::stiffness_rule(element),
        };
        // Degrees 2 and 4 are tabulated, so the fallback is unreachable.
        triangle.unwrap_or_else(|_| GaussRule::stiffness_rule(element))
    }

    /// A short name for people: "plane stress", "plane strain" or "axisymmetric".
    pub fn name(&self) -> &'static str {
        match self {
            Kinematics::PlaneStress { .. } => "plane stress",
            Kinematics::PlaneStrain { .. } => "plane strain",
            Kinematics::Axisymmetric => "axisymmetric",
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn plane_round_trips_and_refuses_bad_thickness() {
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            let k = Kinematics::plane(plane, 0.7).unwrap();
            assert_eq!(k.plane_condition(), Some(plane));
            assert_eq!(k.thickness(), Some(0.7));
            assert_eq!(k.boundary_weight([1.0, 2.0]), 0.7);
        }
        for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(Kinematics::plane(PlaneCondition::Stress, t), Err(ElementError::InvalidThickness { .. })));
        }
    }
}

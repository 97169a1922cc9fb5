//! Error norms of a finite-element solution against a closed form, and convergence rates.
//!
//! ```text
//! ‖e‖_L2 = ( ∫_Ωh |u_h - u|² t dΩ )^½                    e = u_h - u
//! ‖e‖_E  = ( ∫_Ωh (ε_h - ε)ᵀ D (ε_h - ε) t dΩ )^½         (= √(2 × strain energy of e))
//! relative errors: ‖e‖ / ‖u‖ with ‖u‖ the same norm of the closed form
//!
//! rate between meshes 1 (coarse) and 2 (fine):  q = ln(e1/e2) / ln(h1/h2)
//! ```
//!
//! The integrals run over the discrete domain `Ωh` (the union of the mapped cells) with a rule
//! well above the stiffness rule — 5×5 Gauss points on quadrilaterals, the degree-5 rule on
//! triangles — so that the quadrature error is far below the discretisation error and cannot
//! produce spurious superconvergence at the stiffness Gauss points.

use contact2d_element::{ElementType, GaussRule, map_point};
use contact2d_fem::{BodyId, Model};

use crate::VerifyError;
use crate::analytic::ElasticField;

/// Absolute and reference norms of one solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorNorms {
    /// `‖u_h - u‖_L2`.
    pub l2_error: f64,
    /// `‖u‖_L2`.
    pub l2_norm: f64,
    /// `‖u_h - u‖_E`.
    pub energy_error: f64,
    /// `‖u‖_E`.
    pub energy_norm: f64,
}

impl ErrorNorms {
    /// `‖u_h - u‖_L2 / ‖u‖_L2`.
    pub fn relative_l2(&self) -> f64 {
        self.l2_error / self.l2_norm
    }

    /// `‖u_h - u‖_E / ‖u‖_E`.
    pub fn relative_energy(&self) -> f64 {
        self.energy_error / self.energy_norm
    }
}

/// The error-norm quadrature rule of an element (see the module docs).
///
/// # Errors
/// None in practice: the rules requested are tabulated.
pub fn error_rule(element: ElementType) -> Result<GaussRule, VerifyError> {
    Ok(if element.is_triangle() { GaussRule::triangle(5)? } else { GaussRule::quad(5)? })
}

/// The L2 and energy error norms of the displacement `u` (global DOF order) of one body.
///
/// # Errors
/// Element failures (not expected once the body was validated) or a wrong vector length.
pub fn error_norms(
    model: &Model,
    body: BodyId,
    u: &[f64],
    exact: &impl ElasticField,
) -> Result<ErrorNorms, VerifyError> {
    let b = model.bodies.get(body.0).ok_or_else(|| VerifyError::InvalidParameter(format!("no body {}", body.0)))?;
    if u.len() != 2 * model.mesh.num_nodes() {
        return Err(VerifyError::InvalidParameter(format!(
            "displacement has {} entries, the mesh needs {}",
            u.len(),
            2 * model.mesh.num_nodes()
        )));
    }
    let d = b.kinematics.in_plane_elasticity(&b.material);
    let energy = |e: [f64; 3]| {
        let de = d * nalgebra::Vector3::new(e[0], e[1], e[2]);
        e[0] * de[0] + e[1] * de[1] + e[2] * de[2]
    };
    let mut sums = [0.0; 4];
    for i in 0..b.num_cells() {
        let element = b.elements[i];
        let coords = b.cell_coords(&model.mesh, i);
        let ue: Vec<f64> = b.cell_dofs(i).map(|dof| u[dof.0]).collect();
        let rule = error_rule(element)?;
        for (xi, w) in rule.points.iter().zip(&rule.weights) {
            let p = map_point(element, &coords, *xi)?;
            let mut uh = [0.0; 2];
            let mut eh = [0.0; 3];
            for a in 0..p.len {
                let [gx, gy] = p.dn_dx[a];
                let (ux, uy) = (ue[2 * a], ue[2 * a + 1]);
                uh[0] += p.n[a] * ux;
                uh[1] += p.n[a] * uy;
                eh[0] += gx * ux;
                eh[1] += gy * uy;
                eh[2] += gy * ux + gx * uy;
            }
            let (ux, ex) = (exact.displacement(p.x), exact.strain(p.x));
            let f = w * p.det_j * b.kinematics.volume_weight(p.x);
            sums[0] += f * ((uh[0] - ux[0]).powi(2) + (uh[1] - ux[1]).powi(2));
            sums[1] += f * (ux[0] * ux[0] + ux[1] * ux[1]);
            sums[2] += f * energy([eh[0] - ex[0], eh[1] - ex[1], eh[2] - ex[2]]);
            sums[3] += f * energy(ex);
        }
    }
    Ok(ErrorNorms {
        l2_error: sums[0].sqrt(),
        l2_norm: sums[1].sqrt(),
        energy_error: sums[2].max(0.0).sqrt(),
        energy_norm: sums[3].sqrt(),
    })
}

/// The observed convergence rate `ln(e_coarse/e_fine) / ln(h_coarse/h_fine)`.
///
/// # Examples
/// ```
/// use contact2d_verification::norms::convergence_rate;
/// // Halving h divides the error by 8: third order.
/// assert!((convergence_rate(0.2, 8e-3, 0.1, 1e-3) - 3.0).abs() < 1e-12);
/// ```
pub fn convergence_rate(h_coarse: f64, error_coarse: f64, h_fine: f64, error_fine: f64) -> f64 {
    (error_coarse / error_fine).ln() / (h_coarse / h_fine).ln()
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::analytic::AffineField;
    use contact2d_element::{Kinematics, Material};
    use contact2d_mesh::{CellKind, generate::rectangle};

    #[test]
    fn interpolated_affine_field_has_zero_error_and_exact_norms() {
        // u = (0.1 x, 0): ‖u‖²_L2 = ∫∫ 0.01 x² = 0.01 · 8/3 · 1 on [0,2]×[0,1];
        // ‖u‖²_E = ∫ D11 ε11² = E/(1-ν²) · 0.01 · 2 in plane stress.
        let mut model = Model::new(rectangle(CellKind::Quad9, [0.0, 2.0], [0.0, 1.0], 3, 2));
        let body = model
            .add_body("domain", Material::new(1.0, 0.25).unwrap(), Kinematics::PlaneStress { thickness: 1.0 })
            .unwrap();
        let field = AffineField { offset: [0.0, 0.0], gradient: [[0.1, 0.0], [0.0, 0.0]] };
        let u: Vec<f64> = model.mesh.points.iter().flat_map(|&x| field.displacement(x)).collect();
        let norms = error_norms(&model, body, &u, &field).unwrap();
        assert!(norms.l2_error < 1e-15 && norms.energy_error < 1e-15);
        assert!((norms.l2_norm.powi(2) - 0.01 * 8.0 / 3.0).abs() < 1e-14);
        assert!((norms.energy_norm.powi(2) - 0.02 / (1.0 - 0.0625)).abs() < 1e-14);
        assert!(error_norms(&model, body, &u[1..], &field).is_err());
    }

    #[test]
    fn rate_of_a_power_law_is_its_exponent() {
        assert!((convergence_rate(0.2, 3.0 * 0.2f64.powi(3), 0.1, 3.0 * 0.1f64.powi(3)) - 3.0).abs() < 1e-12);
    }
}

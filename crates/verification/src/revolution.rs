//! Bodies of revolution against closed forms: the thick-walled cylinder under internal pressure
//! with closed and with open ends, and a solid cylinder's uniform state (the patch test with
//! nodes on the axis).
//!
//! ```text
//!   z
//!   ^   top: u_z = 0 (closed ends) or free (open ends)
//! L +---------+            the meridian section a ≤ r ≤ b, 0 ≤ z ≤ L of a tube, x = r, y = z,
//!   |         |            nr cells radially and nz = nr L/(b − a) axially (rectangle cells)
//! p |->       |  outer     internal pressure p on r = a
//!   |         |  free
//! 0 +---------+--> r
//!   a  bottom: u_z = 0    b
//!
//! closed ends (ε_zz = 0):  u_r = the plane-strain Lamé displacement,  u_z = 0
//! open ends   (σ_zz = 0):  u_r = the plane-stress Lamé displacement,
//!                          u_z = ε_zz z,  ε_zz = −ν (σ_rr + σ_θθ)/E = −2ν p a² / (E (b² − a²))
//! both:                    σ_rr, σ_θθ = Lamé's (independent of the ends), σ_rz = 0
//! ```
//!
//! Both are exact 3D elasticity solutions of a finite tube with those ends (the stresses do not
//! depend on z, and σ_zz = 0 is consistent with free ends), so the whole tube converges to them,
//! with no end effect to exclude. The measured errors: the relative L2 error of the displacement
//! weighed by `2πr` (expected `O(h^{k+1})` for elements of degree `k`), and the recovered
//! stresses at the inner wall (`σ_rr → −p`, `σ_θθ →` Lamé's).
//!
//! The patch test: a solid cylinder `0 ≤ r ≤ b` (nodes on the axis) under an external pressure
//! `p` with both ends held axially is in the uniform state `σ_rr = σ_θθ = −p`, `u_r = c r`,
//! `c = −p / (2 (λ + μ))`; every element reproduces it to round-off.

use contact2d_element::{Kinematics, Material, PlaneCondition, map_point};
use contact2d_fem::{BodyId, Component, EdgeLoad, Model, Solution, StressRecovery, nodal_stress_states, solve_linear};
use contact2d_mesh::CellKind;
use contact2d_mesh::generate::rectangle;

use crate::VerifyError;
use crate::lame::LameSetup;
use crate::norms::error_rule;

/// How the tube's ends are held.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TubeEnds {
    /// `u_z = 0` at both ends: plane strain along the axis.
    Closed,
    /// `u_z = 0` at `z = 0`, the end `z = L` free: `σ_zz = 0`.
    Open,
}

/// One mesh of the tube.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TubeLevel {
    /// Cells radially.
    pub n_radial: usize,
    /// Mesh size `(b − a)/n_radial`.
    pub h: f64,
    /// `‖u_h − u‖ / ‖u‖` in L2 weighed by `2πr`.
    pub relative_l2: f64,
    /// `max |σ_rr + p| / p` over the inner-wall nodes (recovered nodal stresses).
    pub inner_radial_stress_error: f64,
    /// `max |σ_θθ − σ_θθ(a)| / σ_θθ(a)` over the inner-wall nodes.
    pub inner_hoop_stress_error: f64,
}

/// The tube of the module docs, of length `b − a`, as a model.
///
/// # Errors
/// A zero cell count or model failures.
pub fn tube_model(
    kind: CellKind,
    ends: TubeEnds,
    n_radial: usize,
    setup: &LameSetup,
) -> Result<(Model, BodyId), VerifyError> {
    if n_radial == 0 {
        return Err(VerifyError::InvalidParameter("the tube needs at least one cell radially".into()));
    }
    let (a, b) = (setup.inner_radius, setup.outer_radius);
    let mesh = rectangle(kind, [a, b], [0.0, b - a], n_radial, n_radial);
    let mut model = Model::new(mesh);
    let material = Material::new(setup.youngs_modulus, setup.poissons_ratio)?;
    let body = model.add_body_in("domain", material, Kinematics::Axisymmetric, setup.formulation)?;
    model.fix("bottom", Component::Y, 0.0)?;
    if ends == TubeEnds::Closed {
        model.fix("top", Component::Y, 0.0)?;
    }
    model.add_edge_load(EdgeLoad::Pressure { group: "left".into(), pressure: setup.pressure })?;
    Ok((model, body))
}

/// The exact displacement `[u_r, u_z]` at `x = [r, z]` (module docs).
///
/// # Errors
/// As [`LameSetup::exact`].
pub fn tube_displacement(ends: TubeEnds, setup: &LameSetup) -> Result<impl Fn([f64; 2]) -> [f64; 2], VerifyError> {
    let plane = match ends {
        TubeEnds::Closed => PlaneCondition::Strain,
        TubeEnds::Open => PlaneCondition::Stress,
    };
    let lame = setup.exact(plane)?;
    let (a, b) = (setup.inner_radius, setup.outer_radius);
    let axial_strain = match ends {
        TubeEnds::Closed => 0.0,
        TubeEnds::Open => {
            -2.0 * setup.poissons_ratio * setup.pressure * a * a / (setup.youngs_modulus * (b * b - a * a))
        }
    };
    Ok(move |x: [f64; 2]| [lame.radial_displacement(x[0]), axial_strain * x[1]])
}

/// Solves one mesh of the tube and measures it.
///
/// # Errors
/// Model, solver or element failures.
pub fn solve_tube(
    kind: CellKind,
    ends: TubeEnds,
    n_radial: usize,
    setup: &LameSetup,
) -> Result<(TubeLevel, Model, Solution), VerifyError> {
    let exact = tube_displacement(ends, setup)?;
    let lame = setup.exact(PlaneCondition::Strain)?;
    let (model, body) = tube_model(kind, ends, n_radial, setup)?;
    let (_, _, solution) = solve_linear(&model)?;
    let relative_l2 = weighted_l2_error(&model, body, &solution.displacement, &exact)?;
    let states = nodal_stress_states(&model, body, &solution.displacement, StressRecovery::Extrapolated)?;
    let p = setup.pressure;
    let hoop = lame.hoop_stress(setup.inner_radius);
    let (mut radial_error, mut hoop_error) = (0.0f64, 0.0f64);
    for n in model.mesh.group_nodes("left").map_err(contact2d_fem::FemError::from)? {
        if let Some([s_rr, _, _, s_tt]) = states[n.0] {
            radial_error = radial_error.max((s_rr + p).abs() / p.abs());
            hoop_error = hoop_error.max((s_tt - hoop).abs() / hoop.abs());
        }
    }
    let level = TubeLevel {
        n_radial,
        h: (setup.outer_radius - setup.inner_radius) / n_radial as f64,
        relative_l2,
        inner_radial_stress_error: radial_error,
        inner_hoop_stress_error: hoop_error,
    };
    Ok((level, model, solution))
}

/// `(∫ |u_h − u|² 2πr dA / ∫ |u|² 2πr dA)^½` with the error rule of [`crate::norms::error_rule`].
fn weighted_l2_error(
    model: &Model,
    body: BodyId,
    u: &[f64],
    exact: &impl Fn([f64; 2]) -> [f64; 2],
) -> Result<f64, VerifyError> {
    let b = &model.bodies[body.0];
    let (mut err, mut norm) = (0.0, 0.0);
    for i in 0..b.num_cells() {
        let element = b.elements[i];
        let coords = b.cell_coords(&model.mesh, i);
        let ue: Vec<f64> = b.cell_dofs(i).map(|d| u[d.0]).collect();
        let rule = error_rule(element)?;
        for (xi, w) in rule.points.iter().zip(&rule.weights) {
            let p = map_point(element, &coords, *xi)?;
            let uh = (0..p.len).fold([0.0; 2], |s, a| [s[0] + p.n[a] * ue[2 * a], s[1] + p.n[a] * ue[2 * a + 1]]);
            let ue_exact = exact(p.x);
            let f = w * p.det_j * b.kinematics.volume_weight(p.x);
            err += f * ((uh[0] - ue_exact[0]).powi(2) + (uh[1] - ue_exact[1]).powi(2));
            norm += f * (ue_exact[0].powi(2) + ue_exact[1].powi(2));
        }
    }
    Ok((err / norm).sqrt())
}

/// The patch test of the module docs on a solid cylinder `0 ≤ r ≤ b`, length `b`, on an
/// `n × n` mesh: `(displacement, stress)` errors, the largest deviation of the nodal `u_r` from
/// `c r` and of `u_z` from 0 (relative to `|c| b`), and of the recovered `σ_rr`, `σ_θθ` from `−p`,
/// `σ_zz` from `2 λ c` and `σ_rz` from 0 (relative to `p`).
///
/// # Errors
/// Model, solver or element failures.
pub fn solid_cylinder_patch(kind: CellKind, n: usize, setup: &LameSetup) -> Result<(f64, f64), VerifyError> {
    let radius = setup.outer_radius;
    let mesh = rectangle(kind, [0.0, radius], [0.0, radius], n, n);
    let mut model = Model::new(mesh);
    let material = Material::new(setup.youngs_modulus, setup.poissons_ratio)?;
    let body = model.add_body_in("domain", material, Kinematics::Axisymmetric, setup.formulation)?;
    model.fix_axis_nodes();
    model.fix("bottom", Component::Y, 0.0)?;
    model.fix("top", Component::Y, 0.0)?;
    model.add_edge_load(EdgeLoad::Pressure { group: "right".into(), pressure: setup.pressure })?;
    let (_, _, solution) = solve_linear(&model)?;
    let (e, nu, p) = (setup.youngs_modulus, setup.poissons_ratio, setup.pressure);
    let lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    let mu = e / (2.0 * (1.0 + nu));
    let c = -p / (2.0 * (lambda + mu));
    let u = &solution.displacement;
    let mut displacement_error = 0.0f64;
    // The body's nodes (a Quad8 grid leaves its cells' centres in the mesh, in no cell).
    for n in model.bodies[body.0].nodes.iter().map(|n| n.0) {
        let x = model.mesh.points[n];
        let ur = u[2 * n] - c * x[0];
        displacement_error = displacement_error.max(ur.abs().max(u[2 * n + 1].abs()) / (c.abs() * radius));
    }
    let states = nodal_stress_states(&model, body, u, StressRecovery::Extrapolated)?;
    let mut stress_error = 0.0f64;
    for [s_rr, s_zz, s_rz, s_tt] in states.into_iter().flatten() {
        let deviation = [s_rr + p, s_zz - 2.0 * lambda * c, s_rz, s_tt + p];
        stress_error = deviation.iter().fold(stress_error, |m, d| m.max(d.abs() / p.abs()));
    }
    Ok((displacement_error, stress_error))
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use contact2d_element::Formulation;

    #[test]
    fn a_tube_with_a_node_off_the_half_plane_is_refused() {
        let mut model = Model::new(rectangle(CellKind::Quad4, [-0.1, 1.0], [0.0, 1.0], 2, 2));
        let m = Material::new(1.0, 0.3).unwrap();
        let err = model.add_body_in("domain", m, Kinematics::Axisymmetric, Default::default()).unwrap_err();
        assert!(err.to_string().contains("r = x = -0.1 < 0"), "{err}");
        // A node at the round-off of the coordinates left of the axis is on the axis.
        let mut mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
        mesh.points.iter_mut().filter(|p| p[0] == 0.0).for_each(|p| p[0] = -1e-17);
        let mut model = Model::new(mesh);
        model.add_body_in("domain", m, Kinematics::Axisymmetric, Default::default()).unwrap();
        assert_eq!(model.fix_axis_nodes(), 3);
    }

    #[test]
    fn every_element_passes_the_solid_cylinder_patch_test() {
        // A uniform state is in every element's space (u_r = c r is interpolated exactly and
        // u_r / r = c at every Gauss point), so only round-off separates it from the closed form:
        // 1e-9 allows the conditioning of a 2×2 to 4×4 mesh's stiffness (about 1e3) times ε
        // accumulated over the assembly, with a wide margin.
        let setup = LameSetup::default();
        for kind in [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
            for n in [2, 4] {
                let (du, ds) = solid_cylinder_patch(kind, n, &setup).unwrap();
                assert!(du < 1e-9 && ds < 1e-9, "{kind:?} n = {n}: displacement {du:e}, stress {ds:e}");
            }
        }
        // B-bar: the uniform state's dilatation 2c is constant, so θ̄ = θ and the state is still
        // exact, nodes on the axis included; ν = 0.4999 multiplies the conditioning by
        // κ/μ ≈ 3 300, still far inside 1e-9 relative.
        for nu in [0.3, 0.4999] {
            let bbar = LameSetup { poissons_ratio: nu, formulation: Formulation::BBar, ..LameSetup::default() };
            for kind in [CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
                for n in [2, 4] {
                    let (du, ds) = solid_cylinder_patch(kind, n, &bbar).unwrap();
                    assert!(du < 1e-9 && ds < 1e-9, "B-bar {kind:?} ν = {nu} n = {n}: {du:e}, {ds:e}");
                }
            }
        }
    }
}

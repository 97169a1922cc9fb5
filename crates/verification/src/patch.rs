//! Patch tests on distorted meshes: every element must reproduce a constant-strain state exactly.
//!
//! ```text
//!  y=1.5  +-----+----+-----+---+-----+     rectangle [1, 3] x [-0.5, 1.5], 5 x 4 cells of one kind;
//!         |     |     \    |    \    |     interior vertices moved by up to ±0.2 h per coordinate;
//!         +-----+--+---+---+-----+---+     mid-side nodes of interior edges set to the midpoints and
//!         |    /   |    \  |     |   |     then moved by up to ±0.05 h (curved edges); Quad9 centres
//!         +---+----+-----+-+-----+---+     at the mean of the corners plus the same jitter; boundary
//!         |   |      |     |     |   |     nodes stay where the generator put them
//!  y=-0.5 +---+------+-----+-----+---+
//!        x=1                        x=3
//!
//! Dirichlet variant: u = u0 + G x prescribed at every node of all four sides (G with stretch,
//!                    shear and rotation)
//! Traction variant:  u1 = 0 on the left side, u2 = 0 on the bottom (rollers), constant traction
//!                    σ·n on the right and top sides for the biaxial state σ = (σ11, σ22, 0)
//! ```
//!
//! Both variants must give the affine displacement at every node and the constant stress
//! `σ = D ε` at every point of every cell, for every node placement that keeps the cells valid:
//! the isoparametric map reproduces `x`, so `u0 + G x` lies in the element space, and the
//! stiffness rules integrate `∫ ∇N_a · σ dΩ` exactly for a constant `σ` (the integrand
//! `cof(J) ∇_ξ N_a` is a polynomial of low degree), so the discrete equations are satisfied.
//!
//! # References
//! B. M. Irons, A. Razzaque (1972), Experience with the patch test for convergence of finite
//! elements, in: The Mathematical Foundations of the Finite Element Method (A. K. Aziz, ed.),
//! Academic Press, 557–587. R. L. Taylor, O. C. Zienkiewicz, J. C. Simo, A. H. C. Chan (1986),
//! The patch test — a condition for assessing FEM convergence, Int. J. Numer. Meth. Eng. 22, 39–62.

use std::collections::BTreeSet;

use contact2d_element::{Formulation, Kinematics, Material, PlaneCondition, stress_state_at};
use contact2d_fem::{
    CholeskySolver, Component, EdgeLoad, Model, Solution, StressRecovery, assemble, element_type, nodal_stresses,
    solve_linear,
};
use contact2d_mesh::generate::rectangle;
use contact2d_mesh::{CellKind, Mesh};

use crate::VerifyError;
use crate::analytic::{AffineField, ElasticField};
use crate::norms::error_rule;

/// Which boundary conditions drive the patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PatchVariant {
    /// The exact affine displacement prescribed on the whole boundary (general `G`, with shear
    /// and rotation).
    Dirichlet,
    /// Rollers on the left and bottom sides, the exact constant traction on the right and top
    /// (a biaxial state): exercises the load assembly and the Dirichlet elimination as well.
    Traction,
}

/// The distorted patch and its material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSetup {
    /// `[x0, x1]` of the rectangle.
    pub x: [f64; 2],
    /// `[y0, y1]` of the rectangle.
    pub y: [f64; 2],
    /// Cells along x.
    pub nx: usize,
    /// Cells along y.
    pub ny: usize,
    /// Largest move of a vertex per coordinate, as a fraction of the cell size `h`.
    pub vertex_jitter: f64,
    /// Largest move of a mid-side or centre node off its straight-edge position, per coordinate, in `h`.
    pub midside_jitter: f64,
    /// Seed of the node moves.
    pub seed: u64,
    /// Young's modulus.
    pub youngs_modulus: f64,
    /// Poisson's ratio.
    pub poissons_ratio: f64,
}

impl Default for PatchSetup {
    fn default() -> Self {
        PatchSetup {
            x: [1.0, 3.0],
            y: [-0.5, 1.5],
            nx: 5,
            ny: 4,
            vertex_jitter: 0.2,
            midside_jitter: 0.05,
            seed: 0x5EED_2D00,
            youngs_modulus: 200.0,
            poissons_ratio: 0.3,
        }
    }
}

/// What a patch test measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchResult {
    /// Cell kind.
    pub kind: CellKind,
    /// Plane condition.
    pub plane: PlaneCondition,
    /// Boundary conditions.
    pub variant: PatchVariant,
    /// Number of cells.
    pub cells: usize,
    /// Number of nodes not on the boundary.
    pub interior_nodes: usize,
    /// Largest vertex move actually applied, in `h`.
    pub max_vertex_move: f64,
    /// `max_n |u_h(x_n) - u(x_n)| / max_n |u(x_n)|` over all active nodes.
    pub displacement_error: f64,
    /// `max |σ_h - σ| / max |σ|` (component-wise) over the stiffness and error-rule points of every
    /// cell and both nodal recoveries.
    pub stress_error: f64,
}

/// SplitMix64: a tiny, well-mixed, reproducible generator (no dependency, no global state).
struct SplitMix64(u64);

impl SplitMix64 {
    /// Uniform in `[-1, 1)`.
    fn symmetric(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        2.0 * ((z >> 11) as f64 / (1u64 << 53) as f64) - 1.0
    }
}

const SIDES: [&str; 4] = ["bottom", "right", "top", "left"];

/// The rectangle of `setup` in cells of `kind`, with its interior nodes moved as the module docs
/// describe. Returns the mesh and the largest vertex move in units of `h`.
///
/// # Errors
/// [`VerifyError::InvalidParameter`] for a non-2D kind or empty grid.
pub fn distorted_rectangle(kind: CellKind, setup: &PatchSetup) -> Result<(Mesh, f64), VerifyError> {
    let element = element_type(kind)
        .filter(|_| setup.nx > 0 && setup.ny > 0)
        .ok_or_else(|| VerifyError::InvalidParameter(format!("patch of {} cells of {kind:?}", setup.nx * setup.ny)))?;
    let mut mesh = rectangle(kind, setup.x, setup.y, setup.nx, setup.ny);
    let h = ((setup.x[1] - setup.x[0]) / setup.nx as f64).min((setup.y[1] - setup.y[0]) / setup.ny as f64);
    let mut boundary = BTreeSet::new();
    for side in SIDES {
        boundary.extend(mesh.group_nodes(side).map_err(contact2d_fem::FemError::from)?.into_iter().map(|n| n.0));
    }
    let cells: Vec<Vec<usize>> = mesh
        .blocks
        .iter()
        .filter(|b| b.kind == kind)
        .flat_map(|b| b.cells().map(|c| c.iter().map(|n| n.0).collect()))
        .collect();
    let vertices_per_cell = if element.is_triangle() { 3 } else { 4 };
    let vertices: BTreeSet<usize> = cells.iter().flat_map(|c| c[..vertices_per_cell].iter().copied()).collect();
    let others: BTreeSet<usize> = cells.iter().flat_map(|c| c[vertices_per_cell..].iter().copied()).collect();
    let mut rng = SplitMix64(setup.seed);
    let mut max_move: f64 = 0.0;
    for &n in vertices.difference(&boundary) {
        let d = [setup.vertex_jitter * h * rng.symmetric(), setup.vertex_jitter * h * rng.symmetric()];
        max_move = max_move.max(d[0].abs().max(d[1].abs()) / h);
        mesh.points[n] = [mesh.points[n][0] + d[0], mesh.points[n][1] + d[1]];
    }
    if element.degree() == 2 {
        // Straight edges first: mid-side nodes at the midpoints, the Quad9 centre at the mean of the corners.
        for cell in &cells {
            for &[s, e, m] in element.edges() {
                let (ps, pe) = (mesh.points[cell[s]], mesh.points[cell[e]]);
                mesh.points[cell[m]] = [0.5 * (ps[0] + pe[0]), 0.5 * (ps[1] + pe[1])];
            }
            if cell.len() == 9 {
                let c = (0..4).fold([0.0; 2], |acc, a| {
                    [acc[0] + 0.25 * mesh.points[cell[a]][0], acc[1] + 0.25 * mesh.points[cell[a]][1]]
                });
                mesh.points[cell[8]] = c;
            }
        }
        // Then curve the interior edges (shared nodes move once, so neighbours stay conforming).
        for &n in others.difference(&boundary) {
            let d = [setup.midside_jitter * h * rng.symmetric(), setup.midside_jitter * h * rng.symmetric()];
            mesh.points[n] = [mesh.points[n][0] + d[0], mesh.points[n][1] + d[1]];
        }
    }
    Ok((mesh, max_move))
}

/// The affine field of the Dirichlet variant: general gradient (stretch, shear and rotation).
pub fn dirichlet_field() -> AffineField {
    AffineField { offset: [0.01, -0.02], gradient: [[0.02, -0.015], [0.005, 0.03]] }
}

/// The stresses `[σ11, σ22]` of the traction variant's biaxial state.
pub const TRACTION_STRESS: [f64; 2] = [3.0, -1.25];

/// Runs one patch test.
///
/// # Errors
/// Mesh, model or solver failures (an inverted cell would surface here).
pub fn run_patch_test(
    kind: CellKind,
    plane: PlaneCondition,
    variant: PatchVariant,
    setup: &PatchSetup,
) -> Result<PatchResult, VerifyError> {
    run_patch_test_with(kind, plane, variant, setup, Formulation::Standard)
}

/// As [`run_patch_test`] with the body's [`Formulation`] (B-bar passes too: the dilatation of an
/// affine field is constant, so its projection is itself).
///
/// # Errors
/// As [`run_patch_test`], and an unsupported formulation (B-bar on Tri3).
pub fn run_patch_test_with(
    kind: CellKind,
    plane: PlaneCondition,
    variant: PatchVariant,
    setup: &PatchSetup,
    formulation: Formulation,
) -> Result<PatchResult, VerifyError> {
    let (mesh, max_vertex_move) = distorted_rectangle(kind, setup)?;
    let material = Material::new(setup.youngs_modulus, setup.poissons_ratio)?;
    let mut model = Model::new(mesh);
    let body = model.add_body_in("domain", material, Kinematics::plane(plane, 1.0)?, formulation)?;
    let (field, solution) = match variant {
        PatchVariant::Dirichlet => {
            let field = dirichlet_field();
            for side in SIDES {
                model.fix(side, Component::X, 0.0)?;
                model.fix(side, Component::Y, 0.0)?;
            }
            let system = assemble(&model)?;
            let solver = CholeskySolver::factor(&system.stiffness)?;
            let prescribed: Vec<f64> = system
                .dofs
                .constrained_dofs()
                .iter()
                .map(|d| field.displacement(model.mesh.points[d.node()])[d.0 % 2])
                .collect();
            let u_free = solver.solve(&system.rhs(&prescribed));
            (field, Solution::from_free(&system, &u_free, &prescribed))
        }
        PatchVariant::Traction => {
            // ε = D⁻¹ σ; the field vanishes on x = x0 (u1) and y = y0 (u2), where the rollers are.
            let d_inv = plane.elasticity_matrix(&material).try_inverse().ok_or_else(|| {
                VerifyError::InvalidParameter("singular elasticity matrix in the traction patch test".into())
            })?;
            let eps = d_inv * nalgebra::Vector3::new(TRACTION_STRESS[0], TRACTION_STRESS[1], 0.0);
            let field = AffineField {
                offset: [-eps[0] * setup.x[0], -eps[1] * setup.y[0]],
                gradient: [[eps[0], 0.0], [0.0, eps[1]]],
            };
            model.fix("left", Component::X, 0.0)?;
            model.fix("bottom", Component::Y, 0.0)?;
            model.add_edge_load(EdgeLoad::Traction { group: "right".into(), traction: [TRACTION_STRESS[0], 0.0] })?;
            model.add_edge_load(EdgeLoad::Traction { group: "top".into(), traction: [0.0, TRACTION_STRESS[1]] })?;
            let (_, _, solution) = solve_linear(&model)?;
            (field, solution)
        }
    };
    let active = model.active_nodes();
    let mut boundary = BTreeSet::new();
    for side in SIDES {
        boundary.extend(model.mesh.group_nodes(side).map_err(contact2d_fem::FemError::from)?.into_iter().map(|n| n.0));
    }
    let (mut du, mut u_max) = (0.0f64, 0.0f64);
    for (n, &x) in model.mesh.points.iter().enumerate().filter(|(n, _)| active[*n]) {
        let (uh, ue) = (solution.node_displacement(n), field.displacement(x));
        du = du.max((uh[0] - ue[0]).abs().max((uh[1] - ue[1]).abs()));
        u_max = u_max.max(ue[0].abs().max(ue[1].abs()));
    }
    let e = field.strain([0.0, 0.0]);
    let s = plane.elasticity_matrix(&material) * nalgebra::Vector3::new(e[0], e[1], e[2]);
    let exact = [s[0], s[1], s[2]];
    let s_max = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut ds = 0.0f64;
    let mut compare = |sh: [f64; 3]| {
        for k in 0..3 {
            ds = ds.max((sh[k] - exact[k]).abs());
        }
    };
    let b = &model.bodies[body.0];
    for i in 0..b.num_cells() {
        let element = b.elements[i];
        let coords = b.cell_coords(&model.mesh, i);
        let ue: Vec<f64> = b.cell_dofs(i).map(|d| solution.displacement[d.0]).collect();
        let stiffness_rule = contact2d_element::GaussRule::stiffness_rule(element);
        let error_rule = error_rule(element)?;
        for xi in stiffness_rule.points.iter().chain(&error_rule.points) {
            let [s11, s22, s12, _] =
                stress_state_at(element, &coords, &b.material, &b.kinematics, &ue, *xi, b.formulation)?;
            compare([s11, s22, s12]);
        }
    }
    for recovery in [StressRecovery::Extrapolated, StressRecovery::Direct] {
        for s in nodal_stresses(&model, body, &solution.displacement, recovery)?.into_iter().flatten() {
            compare(s);
        }
    }
    Ok(PatchResult {
        kind,
        plane,
        variant,
        cells: b.num_cells(),
        interior_nodes: (0..model.mesh.num_nodes()).filter(|n| active[*n] && !boundary.contains(n)).count(),
        max_vertex_move,
        displacement_error: du / u_max,
        stress_error: ds / s_max,
    })
}

/// Every kind of [`crate::balance::KINDS`] in both plane conditions and both variants on
/// the default setup.
///
/// # Errors
/// As [`run_patch_test`].
pub fn all_patch_tests() -> Result<Vec<PatchResult>, VerifyError> {
    let setup = PatchSetup::default();
    let mut out = vec![];
    for kind in crate::balance::KINDS {
        for plane in crate::balance::PLANES {
            for variant in [PatchVariant::Dirichlet, PatchVariant::Traction] {
                out.push(run_patch_test(kind, plane, variant, &setup)?);
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn distortion_keeps_the_boundary_and_moves_the_interior() {
        let setup = PatchSetup::default();
        let (plain, _) = distorted_rectangle(CellKind::Quad9, &PatchSetup { vertex_jitter: 0.0, ..setup }).unwrap();
        let (moved, max_move) = distorted_rectangle(CellKind::Quad9, &setup).unwrap();
        assert!(max_move > 0.1 && max_move <= setup.vertex_jitter);
        for side in SIDES {
            for n in moved.group_nodes(side).unwrap() {
                assert_eq!(moved.points[n.0], plain.points[n.0]);
            }
        }
        let changed = moved.points.iter().zip(&plain.points).filter(|(a, b)| a != b).count();
        assert!(changed > 0);
        assert!(distorted_rectangle(CellKind::Line2, &setup).is_err());
    }

    #[test]
    fn generator_is_reproducible_and_symmetric() {
        let (mut a, mut b) = (SplitMix64(7), SplitMix64(7));
        let xs: Vec<f64> = (0..1000).map(|_| a.symmetric()).collect();
        assert!(xs.iter().zip((0..1000).map(|_| b.symmetric())).all(|(x, y)| *x == y));
        assert!(xs.iter().all(|x| (-1.0..1.0).contains(x)));
        assert!(xs.iter().sum::<f64>().abs() < 100.0);
    }
}

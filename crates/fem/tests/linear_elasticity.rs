//! End-to-end checks of the fem pipeline on generated meshes: closed-form uniaxial tension,
//! reaction balance, symbolic reuse, and the error paths for bad models.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_element::{Kinematics, Material};
use contact2d_fem::{
    CholeskySolver, Component, FemError, Model, StressRecovery, nodal_stresses, solve_linear, strain_energy,
};
use contact2d_mesh::{CellKind, generate::rectangle};

/// A 2 × 1 bar, left edge on rollers (u1 = 0) with one u2 fixed via the bottom, right edge pulled by δ.
/// Closed form (plane stress): σ11 = E δ / L, σ22 = σ12 = 0, reaction E δ H / L, energy ½ E (δ/L)² L H.
fn uniaxial(kind: CellKind) -> (Model, f64) {
    let mesh = rectangle(kind, [0.0, 2.0], [0.0, 1.0], 4, 3);
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(200.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap();
    model.fix("bottom", Component::Y, 0.0).unwrap();
    let delta = 0.01;
    model.fix("right", Component::X, delta).unwrap();
    (model, delta)
}

#[test]
fn uniaxial_tension_is_exact_for_every_element_kind() {
    for kind in [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
        let (model, delta) = uniaxial(kind);
        let (_, _, sol) = solve_linear(&model).unwrap();
        let (e, l, h) = (200.0, 2.0, 1.0);
        // Tolerance: the discrete solution is exact (affine field in the element space); 1e-10 covers round-off.
        let r = sol.reaction_resultant(&model, "right").unwrap();
        assert!((r[0] - e * delta / l * h).abs() < 1e-10, "{kind:?}: {r:?}");
        let l_react = sol.reaction_resultant(&model, "left").unwrap();
        assert!((r[0] + l_react[0]).abs() < 1e-10, "reactions balance");
        let energy = strain_energy(&model, contact2d_fem::BodyId(0), &sol.displacement).unwrap();
        assert!((energy - 0.5 * e * (delta / l).powi(2) * l * h).abs() < 1e-12);
        for s in nodal_stresses(&model, contact2d_fem::BodyId(0), &sol.displacement, StressRecovery::Extrapolated)
            .unwrap()
            .into_iter()
            .flatten()
        {
            assert!((s[0] - e * delta / l).abs() < 1e-9 && s[1].abs() < 1e-9 && s[2].abs() < 1e-9);
        }
    }
}

#[test]
fn refactor_reuses_the_symbolic_analysis() {
    let (model, _) = uniaxial(CellKind::Quad9);
    let (system, mut solver, sol) = solve_linear(&model).unwrap();
    // Doubling every stiffness value halves the displacements for the same loads.
    let mut doubled = system.stiffness.clone();
    doubled.val_mut().iter_mut().for_each(|v| *v *= 2.0);
    solver.refactor(&doubled).unwrap();
    let rhs = system.rhs(system.dofs.prescribed_values());
    let u = solver.solve(&rhs);
    let u0 = system.dofs.restrict_free(&sol.displacement);
    assert!(u.iter().zip(&u0).all(|(a, b)| (2.0 * a - b).abs() < 1e-14));
    let _ = CholeskySolver::factor(&system.stiffness).unwrap();
}

#[test]
fn unconstrained_body_is_a_typed_error() {
    let mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap(); // u2 and rotation... rotation held, u2 free
    match solve_linear(&model) {
        Err(FemError::UnconstrainedBody { free_modes: 1, .. }) => {}
        other => panic!("expected UnconstrainedBody, got {other:?}"),
    }
}

#[test]
fn conflicting_dirichlet_and_bad_groups_are_typed_errors() {
    let mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
    let mut model = Model::new(mesh);
    let m = Material::new(1.0, 0.3).unwrap();
    assert!(matches!(model.add_body("nope", m, Kinematics::PlaneStress { thickness: 1.0 }), Err(FemError::Mesh(_))));
    assert!(matches!(
        model.add_body("left", m, Kinematics::PlaneStress { thickness: 1.0 }),
        Err(FemError::InvalidRegion { .. })
    ));
    assert!(matches!(
        model.add_body("domain", m, Kinematics::PlaneStress { thickness: 0.0 }),
        Err(FemError::InvalidInput(_))
    ));
    model.add_body("domain", m, Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap();
    model.fix("bottom", Component::X, 1.0).unwrap();
    assert!(matches!(model.dof_map(), Err(FemError::ConflictingDirichlet { .. })));
    assert!(model.fix("left", Component::Y, f64::NAN).is_err());
}

#[test]
fn inverted_element_is_named() {
    let mut mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
    // Drag the first cell's corner at (0.5, 0.5) across its diagonal: det J changes sign inside
    // the cell. (A cell merely numbered clockwise is renumbered, see tests/orientation.rs.)
    let centre = mesh.points.iter().position(|p| *p == [0.5, 0.5]).unwrap();
    mesh.points[centre] = [0.1, 0.1];
    let mut model = Model::new(mesh);
    match model.add_body("domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }) {
        Err(FemError::InvertedElement { cell: 1, .. }) => {}
        other => panic!("expected InvertedElement for cell 1, got {other:?}"),
    }
}

/// A traction is per unit length and thickness: a body of thickness 2 under σ = 1 strains like
/// one of thickness 1 (closed form: u1 = σ L / E at the loaded edge, with ν = 0).
#[test]
fn edge_traction_scales_with_the_body_thickness() {
    for thickness in [1.0, 2.0, 0.25] {
        let mut m = Model::new(rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 1, 1));
        m.add_body("domain", Material::new(1.0, 0.0).unwrap(), Kinematics::PlaneStress { thickness }).unwrap();
        m.fix("left", Component::X, 0.0).unwrap();
        m.fix("bottom", Component::Y, 0.0).unwrap();
        m.add_edge_load(contact2d_fem::EdgeLoad::Traction { group: "right".into(), traction: [1.0, 0.0] }).unwrap();
        let (_, _, sol) = solve_linear(&m).unwrap();
        // Node 3 is (1, 1) in the generated 2 × 2 lattice.
        assert!((sol.node_displacement(3)[0] - 1.0).abs() < 1e-12, "thickness {thickness}");
    }
}

/// A body made of two disconnected pieces, only one of them supported: the other piece is
/// reported (union-find over the cells finds the pieces).
#[test]
fn an_unsupported_piece_of_a_body_is_reported() {
    let mut mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
    let other = rectangle(CellKind::Quad4, [3.0, 4.0], [0.0, 1.0], 2, 2);
    contact2d_mesh::generate::append_prefixed(&mut mesh, &other, "b_");
    // Put the second piece's cells into the first region.
    let domain_tag = mesh.groups.iter().find(|g| g.name == "domain").unwrap().tag;
    for b in mesh.blocks.iter_mut().filter(|b| b.kind == CellKind::Quad4) {
        b.physical_tags = vec![domain_tag];
    }
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap();
    model.fix("left", Component::Y, 0.0).unwrap();
    match solve_linear(&model) {
        Err(FemError::UnconstrainedBody { free_modes: 3, .. }) => {}
        other => panic!("expected the free piece to be reported, got {other:?}"),
    }
}

/// A body force sums to `b t_h |Ω|` on every element type (the shape functions are a partition
/// of unity and the rule integrates them exactly on straight cells), to round-off; a region that
/// is no body is an error.
#[test]
fn body_forces_sum_to_the_weight() {
    use contact2d_fem::assemble_body_forces;
    for kind in [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
        let mut model = Model::new(rectangle(kind, [0.0, 2.0], [0.0, 1.5], 3, 2));
        model
            .add_body("domain", Material::new(200.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 0.5 })
            .unwrap();
        let f = assemble_body_forces(&model, &[("domain".into(), [0.25, -2.0])]).unwrap();
        let (fx, fy) = f.chunks(2).fold((0.0, 0.0), |(x, y), c| (x + c[0], y + c[1]));
        let volume = 2.0 * 1.5 * 0.5;
        assert!((fx - 0.25 * volume).abs() < 1e-13 && (fy + 2.0 * volume).abs() < 1e-13, "{kind:?}: ({fx}, {fy})");
        assert!(assemble_body_forces(&model, &[("nowhere".into(), [0.0, 1.0])]).is_err());
        assert!(assemble_body_forces(&model, &[("domain".into(), [f64::NAN, 1.0])]).is_err());
    }
}

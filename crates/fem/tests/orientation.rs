//! Meshes as users draw them (issue 10, item 12): cells whose nodes run clockwise give the same
//! answer as the counter-clockwise mesh; only a truly inverted cell is an error.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_element::{Kinematics, Material};
use contact2d_fem::{BodyId, Component, EdgeLoad, FemError, Model, solve_linear};
use contact2d_mesh::generate::{MappedGrid, Side, mapped_grid, rectangle, side_name};
use contact2d_mesh::{CellKind, Mesh, cell_orientation, read_msh, signed_area};

const KINDS: [CellKind; 5] = [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9];

/// A clockwise renumbering of a cell, written out here independently of the library's
/// reversal: the mirror ξ → −ξ (quadrangles, nodes 0 ↔ 1, 2 ↔ 3, mid nodes 5 ↔ 7) and the swap of
/// corners 0 ↔ 1 (triangles, mid nodes 4 ↔ 5). New node k is old node `perm[k]`.
fn mirror(kind: CellKind) -> &'static [usize] {
    match kind {
        CellKind::Tri3 => &[1, 0, 2],
        CellKind::Tri6 => &[1, 0, 2, 3, 5, 4],
        CellKind::Quad4 => &[1, 0, 3, 2],
        CellKind::Quad8 => &[1, 0, 3, 2, 4, 7, 6, 5],
        CellKind::Quad9 => &[1, 0, 3, 2, 4, 7, 6, 5, 8],
        _ => unreachable!(),
    }
}

/// The same mesh with every 2D cell numbered clockwise.
fn clockwise_twin(mesh: &Mesh) -> Mesh {
    let mut twin = mesh.clone();
    for block in twin.blocks.iter_mut().filter(|b| b.kind.dim() == 2) {
        let perm = mirror(block.kind);
        for cell in block.nodes.chunks_exact_mut(perm.len()) {
            let old = cell.to_vec();
            for (k, &p) in perm.iter().enumerate() {
                cell[k] = old[p];
            }
        }
    }
    twin
}

/// A curved, non-affine 2 × 1 domain (every cell distorted, quadratic edges curved).
fn distorted(kind: CellKind) -> Mesh {
    let grid = MappedGrid { kind, nx: 4, ny: 3, region: "domain" };
    let name = |side: Side, _| Some(side_name(side).to_string());
    mapped_grid(&grid, |u, v| [2.0 * u + 0.3 * u * v, v + 0.15 * (std::f64::consts::PI * u).sin()], name)
}

/// Clamped left edge, shear traction on the right edge: a solution that uses every DOF.
fn cantilever(mesh: Mesh) -> Model {
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(200.0, 0.3).unwrap(), Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap();
    model.fix("left", Component::Y, 0.0).unwrap();
    model.add_edge_load(EdgeLoad::Traction { group: "right".into(), traction: [0.2, -1.0] }).unwrap();
    model
}

#[test]
fn a_clockwise_twin_gives_the_same_displacements() {
    for kind in KINDS {
        let mesh = distorted(kind);
        let twin = clockwise_twin(&mesh);
        let block = twin.blocks.iter().find(|b| b.kind == kind).unwrap();
        let n = kind.nodes_per_cell();
        for cell in block.cells() {
            let coords: Vec<_> = cell.iter().map(|v| twin.points[v.0]).collect();
            assert!(signed_area(kind, &coords).unwrap() < 0.0, "{kind:?}: the twin must be clockwise");
        }
        let (_, _, u) = solve_linear(&cantilever(mesh)).unwrap();
        let model = cantilever(twin);
        // The model renumbered every cell: all counter-clockwise now.
        for cell in model.mesh.blocks.iter().find(|b| b.kind == kind).unwrap().nodes.chunks_exact(n) {
            let coords: Vec<_> = cell.iter().map(|v| model.mesh.points[v.0]).collect();
            assert_eq!(cell_orientation(kind, &coords), Some(contact2d_mesh::Orientation::CounterClockwise));
        }
        let (_, _, v) = solve_linear(&model).unwrap();
        // Same elements (the Gauss rules are symmetric under the renumbering, so the quadrature
        // points are the same physical points), assembled in another order: the difference is
        // round-off amplified by the condition number (~1e4 here), far below 1e-10 of |u|max.
        let scale = u.displacement.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let diff = u.displacement.iter().zip(&v.displacement).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        assert!(scale > 0.0 && diff <= 1e-10 * scale, "{kind:?}: {diff:e} vs {scale:e}");
    }
}

/// Closed form for the uniaxial tension patch test on the twin: reaction E δ H / L on the pulled
/// edge (plane stress, the affine field lies in every element space, so exact to round-off).
#[test]
fn a_clockwise_twin_passes_the_patch_test() {
    for kind in KINDS {
        let twin = clockwise_twin(&rectangle(kind, [0.0, 2.0], [0.0, 1.0], 4, 3));
        let mut model = Model::new(twin);
        model
            .add_body("domain", Material::new(200.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 })
            .unwrap();
        model.fix("left", Component::X, 0.0).unwrap();
        model.fix("bottom", Component::Y, 0.0).unwrap();
        model.fix("right", Component::X, 0.01).unwrap();
        let (_, _, sol) = solve_linear(&model).unwrap();
        let r = sol.reaction_resultant(&model, "right").unwrap();
        // Tolerance: exact discrete solution; 1e-10 covers round-off.
        assert!((r[0] - 200.0 * 0.01 / 2.0).abs() < 1e-10, "{kind:?}: {r:?}");
    }
}

/// The committed Gmsh fixture: a square from a counter-clockwise curve loop and one from a
/// clockwise loop (Gmsh numbers the latter's cells clockwise); both pass the patch test.
#[test]
fn a_gmsh_surface_from_a_clockwise_curve_loop_is_accepted() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../meshes/fixtures");
    for file in ["clockwise_square_v41_ascii.msh", "clockwise_square_v22_bin.msh"] {
        let mesh = read_msh(dir.join(file)).unwrap();
        for (region, sign) in [("ccw", 1.0), ("cw", -1.0)] {
            // The reader is faithful: the clockwise cells arrive clockwise.
            for block in mesh.blocks_in_group(region).unwrap() {
                for cell in block.cells() {
                    let coords: Vec<_> = cell.iter().map(|v| mesh.points[v.0]).collect();
                    assert!(sign * signed_area(block.kind, &coords).unwrap() > 0.0, "{file} {region}");
                }
            }
            let mut model = Model::new(mesh.clone());
            let body =
                model.add_body(region, Material::new(100.0, 0.25).unwrap(), Kinematics::PlaneStress { thickness: 1.0 });
            assert_eq!(body.unwrap(), BodyId(0), "{file} {region}");
            model.fix(&format!("{region}_left"), Component::X, 0.0).unwrap();
            model.fix(&format!("{region}_bottom"), Component::Y, 0.0).unwrap();
            model.fix(&format!("{region}_right"), Component::X, 0.02).unwrap();
            let (_, _, sol) = solve_linear(&model).unwrap();
            let r = sol.reaction_resultant(&model, &format!("{region}_right")).unwrap();
            // Closed form E δ H / L = 100 · 0.02 · 1 / 1; Gmsh's transfinite nodes sit within
            // ~1e-12 of the grid points, so 1e-9 covers them.
            assert!((r[0] - 2.0).abs() < 1e-9, "{file} {region}: {r:?}");
        }
    }
}

#[test]
fn a_truly_inverted_cell_is_still_named() {
    for kind in [CellKind::Quad4, CellKind::Quad9] {
        let mut mesh = rectangle(kind, [0.0, 1.0], [0.0, 1.0], 2, 2);
        // Drag the centre corner of the first cell (0.5, 0.5) across its diagonal to (0.1, 0.1):
        // a reflex corner, det J changes sign inside the cell. Its clockwise twin is inverted too.
        let centre = mesh.points.iter().position(|p| *p == [0.5, 0.5]).unwrap();
        mesh.points[centre] = [0.1, 0.1];
        for mesh in [mesh.clone(), clockwise_twin(&mesh)] {
            let mut model = Model::new(mesh);
            match model.add_body("domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 })
            {
                Err(e @ FemError::InvertedElement { cell: 1, .. }) => {
                    assert!(e.to_string().contains("element 1 is inverted"), "{e}");
                }
                other => panic!("{kind:?}: expected InvertedElement for cell 1, got {other:?}"),
            }
        }
    }
}

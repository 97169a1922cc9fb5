//! Issue 23 (equilibrium on curved interfaces and corners): two contacts that share a node. A
//! square block pressed into an L-shaped seat — a floor and a wall, two separate bodies — so
//! that the block's corner node (0, 0) is a slave node of both interfaces. Meshes are generated
//! in the test (no file, no gmsh).
//!
//! ```text
//!        wall_left fixed
//!        ┌──┐ y = 10
//!        │W │      block_top: u2 = −0.01
//!        │a │   ┌────────┐ y = 5
//!        │l │   │ block  │ ← block_right: u1 = −0.01
//!        │l │   │  5×5   │
//!        └──┘ ▶ └────────┘ y = 0   the corner (0, 0): slave of "floor" (block_bottom on
//!   x = −2..0   ┌─────────────────┐  floor_top) and of "wall" (block_left on wall_right)
//!               │ floor 10 × 2    │
//!               └─────────────────┘ y = −2, floor_bottom fixed
//! ```
//!
//! Independent truths: (1) the block's corner node — and no other — enters pairs of both
//! contacts (with either side as master), and their normals (0, 1) and (1, 0) are independent,
//! so the system is regular: the status is `converged`; (2) global equilibrium, the
//! reactions of every fix sum to zero; (3) statics of each body, frictionless: the floor is held
//! only by its bottom and the block, so its bottom's reaction is the block's push on it, and by
//! Newton's third law the floor's push on the block, which is all that balances the block's top
//! along y (the frictionless wall pushes along x only): R(floor_bottom)₂ = −R(block_top)₂ = the
//! floor contact's normal force; likewise along x with the wall; (4) symmetry about y = x (the
//! geometry, meshes and loads are mirror images): the two contacts carry the same normal force,
//! and with friction the same tangential force.
//!
//! Tolerances: 1e-9 of the load for the balances (a direct solve's round-off, as in
//! `tests/behaviour/corners_and_quadratic_edges.rs`); 1e-8 relative for the symmetry (the mirrored
//! meshes number their nodes differently, so round-off differs between the two sides).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic_on_mesh};
use contact2d_mesh::generate::{MappedGrid, Side, append_prefixed, mapped_grid, side_name};
use contact2d_mesh::{CellKind, Mesh};

/// The block [0, 5]², the floor [0, 10] × [−2, 0] and the wall [−2, 0] × [0, 10] (the floor's
/// mirror image about y = x), n cells per 5 mm along the interfaces.
fn seat_mesh(kind: CellKind, n: usize) -> Mesh {
    let named = |side: Side, _| Some(side_name(side).to_string());
    let grid = |nx, ny| MappedGrid { kind, nx, ny, region: "domain" };
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &mapped_grid(&grid(n, n), |u, v| [5.0 * u, 5.0 * v], named), "block_");
    append_prefixed(&mut mesh, &mapped_grid(&grid(2 * n, 2), |u, v| [10.0 * u, -2.0 + 2.0 * v], named), "floor_");
    append_prefixed(&mut mesh, &mapped_grid(&grid(2, 2 * n), |u, v| [-2.0 + 2.0 * u, 10.0 * v], named), "wall_");
    mesh
}

/// The block driven 0.01 down at its top and 0.01 left at its right side, the seat held; with
/// `block_master` the block's edges are the contacts' master curves (the pairs sit at its nodes,
/// so the corner node carries one pair of each contact), else the seat's.
fn seat_scene(pairing: &str, mu: f64, block_master: bool) -> String {
    let body =
        |region: &str| format!("[[body]]\nregion = \"{region}\"\nyoungs_modulus = 1000.0\npoissons_ratio = 0.3\n");
    let contact = |name: &str, seat: &str, block: &str| {
        let (master, slave) = if block_master { (block, seat) } else { (seat, block) };
        format!(
            "[[contact]]\nname = \"{name}\"\nmaster = \"{master}\"\nslave = \"{slave}\"\nfriction = {mu:?}\npairing = \"{pairing}\"\n"
        )
    };
    format!(
        r#"
name = "block_in_a_seat"
mesh = "generated.msh"
plane = "strain"
{}{}{}
[[fix]]
group = "floor_bottom"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "wall_left"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "block_top"
u2 = -0.01
[[fix]]
group = "block_right"
u1 = -0.01
{}{}
[loading]
steps = 2
"#,
        body("block_domain"),
        body("floor_domain"),
        body("wall_domain"),
        contact("floor", "floor_top", "block_bottom"),
        contact("wall", "wall_right", "block_left"),
    )
}

fn run(text: &str, mesh: Mesh) -> GenericOutcome {
    let scene = GenericScene::from_toml_str(text, Path::new("tests/generated.toml"), &[]).unwrap();
    solve_generic_on_mesh(&scene, mesh, &mut |_, _| {}).unwrap()
}

/// The nodes that enter a pair of both contacts (as the pair's node or in its interpolation).
fn shared_nodes(out: &GenericOutcome) -> Vec<usize> {
    let problem = &out.built.problem;
    let nodes = |i: usize| -> std::collections::BTreeSet<usize> {
        problem.pairs[out.built.interfaces[i].pairs.clone()]
            .iter()
            .flat_map(|p| {
                std::iter::once(p.master.0).chain(p.slave.iter().filter(|(_, w)| *w != 0.0).map(|(n, _)| n.0))
            })
            .collect()
    };
    nodes(0).intersection(&nodes(1)).copied().collect()
}

/// The last step's reaction of `group` along `k`.
fn reaction(out: &GenericOutcome, group: &str, k: usize) -> f64 {
    out.report.steps.last().unwrap().reactions[group][k].unwrap()
}

#[test]
fn a_node_shared_by_two_contacts_solves_and_every_body_balances() {
    for kind in [CellKind::Quad9, CellKind::Quad4] {
        for pairing in ["node_to_segment", "segment_to_segment"] {
            for (mu, block_master) in [(0.0, false), (0.3, false), (0.0, true), (0.3, true)] {
                let case = format!("{kind:?}, {pairing}, μ = {mu}, block master {block_master}");
                let out = run(&seat_scene(pairing, mu, block_master), seat_mesh(kind, 4));
                let r = &out.report;
                // (1) The block's corner (0, 0), and only it, enters both contacts.
                let shared = shared_nodes(&out);
                let points = &out.built.problem.model.mesh.points;
                assert_eq!(shared.len(), 1, "{case}: shared nodes {shared:?}");
                assert!(points[shared[0]][0].abs() < 1e-12 && points[shared[0]][1].abs() < 1e-12, "{case}");
                assert_eq!(r.status, "converged", "{case}: {:?}", r.failed_check);
                // The pushes the block's driven faces take (their reactions point out of the seat).
                let (top, right) = (-reaction(&out, "block_top", 1), -reaction(&out, "block_right", 0));
                let scale = top.abs().max(right.abs());
                assert!(top > 0.0 && right > 0.0, "{case}: the block is pushed into the seat ({top}, {right})");
                // (2) global equilibrium.
                let [rx, ry] = r.steps.last().unwrap().reactions_total;
                assert!(rx.abs() < 1e-9 * scale && ry.abs() < 1e-9 * scale, "{case}: imbalance {rx}, {ry}");
                let (floor, wall) = (&r.contacts["floor"], &r.contacts["wall"]);
                // (4) symmetry about y = x.
                let same = |a: f64, b: f64| (a - b).abs() <= 1e-8 * scale;
                assert!(
                    same(floor.normal_force, wall.normal_force),
                    "{case}: {} against {}",
                    floor.normal_force,
                    wall.normal_force
                );
                assert!(same(top, right), "{case}: top {top} against right {right}");
                assert!(
                    same(floor.tangential_force.abs(), wall.tangential_force.abs()),
                    "{case}: shear {} against {}",
                    floor.tangential_force,
                    wall.tangential_force
                );
                if mu == 0.0 {
                    // (3) statics of each body and Newton's third law across each interface.
                    let tight = |a: f64, b: f64| (a - b).abs() <= 1e-9 * scale;
                    assert!(tight(reaction(&out, "floor_bottom", 1), top), "{case}: floor against block");
                    assert!(tight(reaction(&out, "wall_left", 0), right), "{case}: wall against block");
                    assert!(tight(floor.normal_force, top), "{case}: floor contact {}", floor.normal_force);
                    assert!(tight(wall.normal_force, right), "{case}: wall contact {}", wall.normal_force);
                    assert!(reaction(&out, "floor_bottom", 0).abs() < 1e-9 * scale, "{case}: no shear on the floor");
                }
            }
        }
    }
}

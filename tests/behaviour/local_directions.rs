//! Issue 40, item 4: local directions on a curve, `[[fix]] group = …, un = …, ut = …` (normal and
//! tangential to the curve node by node: `u = T u'`, `K' = Tᵀ K T`), on meshes generated here.
//!
//! ```text
//!  Lamé cylinder, p on the inner arc              block on a slope (α = 30°)
//!   (a) quarter annulus: un = 0 on the cut         left face u1 = u2 = 0 ▶ ╱▔▔▔▔╱ ◀ top: traction
//!       edges  ≡  u2 = 0 / u1 = 0                                         ╱____╱    along the slope
//!   (b) 30° sector θ ∈ [20°, 50°]: un = 0 on                         slope: un = 0 (a roller)
//!       both cut edges (neither axis-aligned)
//! ```
//!
//! Independent truths: the same problem posed in u1 / u2 (the cut edges of a quarter annulus are
//! the axes); the discrete symmetry of the annulus (a sector between two of its mesh's symmetry
//! lines is the quarter's solution there); Lamé's closed form to the discretisation error;
//! rotation invariance (the block on the slope against the same block on level ground, turned).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic_on_mesh};
use contact2d_element::PlaneCondition;
use contact2d_mesh::generate::{MappedGrid, Side, annulus_sector, mapped_grid, side_name};
use contact2d_mesh::{CellBlock, CellKind, Mesh, NodeId, PhysicalGroup};
use contact2d_verification::analytic::LameCylinder;

const E: f64 = 200e3;
const NU: f64 = 0.3;
const P: f64 = 100.0;

fn scene(fixes: &str, loads: &str) -> GenericScene {
    let text = format!(
        r#"
name = "local_directions"
mesh = "generated.msh"
plane = "strain"
[[body]]
region = "domain"
youngs_modulus = {E}
poissons_ratio = {NU}
{fixes}
{loads}
[loading]
steps = 1
path_error = false
"#
    );
    GenericScene::from_toml_str(&text, Path::new("tests/generated.toml"), &[]).unwrap()
}

fn run(fixes: &str, loads: &str, mesh: Mesh) -> GenericOutcome {
    solve_generic_on_mesh(&scene(fixes, loads), mesh, &mut |_, _| {}).unwrap()
}

fn displacement(out: &GenericOutcome) -> Vec<f64> {
    out.history.steps.last().unwrap().solution.displacement.clone()
}

const PRESSURE: &str = "[[load]]\ngroup = \"inner\"\npressure = 100.0";

fn fix(group: &str, values: &str) -> String {
    format!("[[fix]]\ngroup = \"{group}\"\n{values}\n")
}

#[test]
fn un_on_the_axes_of_a_quarter_annulus_is_u2_and_u1_there() {
    // θ = 0: n = (0, −1), un = −u2; θ = 90°: n = (−1, ~6e-17), un = −u1 (the mesh's nodes there
    // are at x = r cos(π/2) ≈ 6e-17 r). Same problem: equal to round-off, 1e-12 of max |u|.
    for kind in [CellKind::Quad8, CellKind::Tri3] {
        let mesh = || annulus_sector(kind, [1.0, 2.0], [0.0, std::f64::consts::FRAC_PI_2], 3, 6);
        let global = run(&(fix("start", "u2 = 0.0") + &fix("end", "u1 = 0.0")), PRESSURE, mesh());
        let local = run(&(fix("start", "un = 0.0") + &fix("end", "un = 0.0")), PRESSURE, mesh());
        let (a, b) = (displacement(&global), displacement(&local));
        let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let diff = a.iter().zip(&b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        assert!(diff < 1e-12 * scale, "{kind:?}: max |Δu| = {diff:e} of {scale:e}");
        // The reactions: the cut edges carry the hoop force, along their normals (R2 on θ = 0,
        // R1 on θ = 90°), the same in both posings.
        let (rg, rl) = (&global.report.reactions, &local.report.reactions);
        let hoop = (rg["start"][1].unwrap(), rg["end"][0].unwrap());
        let local_start = rl["start"].map(Option::unwrap);
        let local_end = rl["end"].map(Option::unwrap);
        assert!((local_start[1] - hoop.0).abs() < 1e-10 * hoop.0.abs(), "{local_start:?} vs {hoop:?}");
        assert!((local_end[0] - hoop.1).abs() < 1e-10 * hoop.1.abs(), "{local_end:?} vs {hoop:?}");
        assert!(local_start[0].abs() < 1e-10 * hoop.0.abs() && local_end[1].abs() < 1e-10 * hoop.1.abs());
    }
}

#[test]
fn un_on_the_cut_edges_of_a_tilted_sector_gives_lames_radial_displacement() {
    // The sector θ ∈ [20°, 50°] (3 cells of 10° around) against the quarter annulus (9 cells of
    // 10°, u2 = 0 / u1 = 0, no local direction): both meshes are pieces of the full annulus mesh
    // of 36 cells, which is symmetric about every line θ = k · 10°; the discrete solution is
    // then symmetric about 20° and 50° too: no normal displacement there, the tangential
    // equations split half and half. So the sector with rollers (un = 0) on its cut edges is the
    // quarter's solution restricted to it: equal at every node to round-off (1e-10 of max |u|;
    // the nodes agree to ~1e-16 as the two mappings round cos / sin differently).
    let deg = std::f64::consts::PI / 180.0;
    let (nr, kind) = (4, CellKind::Quad8);
    let sector = run(
        &(fix("start", "un = 0.0") + &fix("end", "un = 0.0")),
        PRESSURE,
        annulus_sector(kind, [1.0, 2.0], [20.0 * deg, 50.0 * deg], nr, 3),
    );
    let quarter_mesh = annulus_sector(kind, [1.0, 2.0], [0.0, 90.0 * deg], nr, 9);
    let quarter = run(&(fix("start", "u2 = 0.0") + &fix("end", "u1 = 0.0")), PRESSURE, quarter_mesh.clone());
    let (us, uq) = (displacement(&sector), displacement(&quarter));
    let points = &sector.built.problem.model.mesh.points;
    let scale = uq.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let lame = LameCylinder::new(1.0, 2.0, P, E, NU, PlaneCondition::Strain).unwrap();
    let (mut worst_symmetry, mut worst_lame) = (0.0f64, 0.0f64);
    let active = sector.built.problem.model.active_nodes();
    for (n, x) in points.iter().enumerate().filter(|(n, _)| active[*n]) {
        let twin = quarter_mesh
            .points
            .iter()
            .position(|q| (q[0] - x[0]).hypot(q[1] - x[1]) < 1e-12)
            .expect("every node of the sector is a node of the quarter");
        let (a, b) = ([us[2 * n], us[2 * n + 1]], [uq[2 * twin], uq[2 * twin + 1]]);
        worst_symmetry = worst_symmetry.max((a[0] - b[0]).abs()).max((a[1] - b[1]).abs());
        let r = x[0].hypot(x[1]);
        let (ur, ut) = ((a[0] * x[0] + a[1] * x[1]) / r, (a[1] * x[0] - a[0] * x[1]) / r);
        let exact = lame.radial_displacement(r);
        worst_lame = worst_lame.max((ur - exact).abs() / exact.abs()).max(ut.abs() / exact.abs());
    }
    assert!(worst_symmetry < 1e-10 * scale, "sector vs quarter: {worst_symmetry:e} of {scale:e}");
    // Lamé's closed form, to the discretisation error of Q8 at h = 0.25 and 10° cells (measured
    // 7.1e-5 relative, in u_r and u_θ alike; the bound is 1e-3). The symmetry measured 3.4e-17 of
    // max |u| = 9.5e-4.
    assert!(worst_lame < 1e-3, "u_r against Lamé: {worst_lame:e}");
}

/// A block L × H on a slope at `alpha` (its bottom), the bottom's first cell edge at the left
/// corner named `corner` (so that the slope group `bottom` does not reach the left face's
/// corner node, held in u1 / u2).
fn block(alpha: f64) -> Mesh {
    let (c, s) = (alpha.cos(), alpha.sin());
    let grid = MappedGrid { kind: CellKind::Quad9, nx: 6, ny: 3, region: "domain" };
    mapped_grid(
        &grid,
        |u, v| {
            let (x, y) = (3.0 * u, 1.0 * v);
            [c * x - s * y, s * x + c * y]
        },
        |side, t| {
            let name = if side == Side::Bottom && t < 1.0 / 6.0 { "corner" } else { side_name(side) };
            Some(name.to_string())
        },
    )
}

#[test]
fn a_roller_on_a_slope_reacts_normal_to_the_slope_and_turns_with_it() {
    // The block held by u1 = u2 = 0 on its left face and by un = 0 on the slope, a traction τ
    // along the slope on its top. Truths: (1) the roller's reaction has no component along the
    // slope, to 1e-10 of the load (round-off); (2) equilibrium: loads + reactions = 0 to 1e-10;
    // (3) rotation invariance: the same block on level ground (α = 0, u2 = 0 on the bottom,
    // τ along x1) gives the reactions turned by α, to 1e-10 of the load.
    let alpha = 30f64.to_radians();
    let (c, s) = (alpha.cos(), alpha.sin());
    let tau = 10.0;
    let load = |t: [f64; 2]| format!("[[load]]\ngroup = \"top\"\ntraction = [{:?}, {:?}]", t[0], t[1]);
    let left = fix("left", "u1 = 0.0\nu2 = 0.0");
    let slope = run(&(left.clone() + &fix("bottom", "un = 0.0")), &load([tau * c, tau * s]), block(alpha));
    let level = run(&(left + &fix("bottom", "u2 = 0.0")), &load([tau, 0.0]), block(0.0));
    let force = tau * 3.0;
    let r = &slope.report.reactions;
    let roller = r["bottom"].map(Option::unwrap);
    let along = roller[0] * c + roller[1] * s;
    assert!(along.abs() < 1e-10 * force, "roller reaction {roller:?}: {along:e} along the slope");
    let wall = r["left"].map(Option::unwrap);
    let total = [roller[0] + wall[0] + force * c, roller[1] + wall[1] + force * s];
    assert!(total[0].abs() < 1e-10 * force && total[1].abs() < 1e-10 * force, "imbalance {total:?}");
    let turn = |v: [f64; 2]| [c * v[0] - s * v[1], s * v[0] + c * v[1]];
    let level_roller =
        turn([level.report.reactions["bottom"][0].unwrap_or(0.0), level.report.reactions["bottom"][1].unwrap()]);
    let level_wall = turn(level.report.reactions["left"].map(Option::unwrap));
    for (a, b) in [(roller, level_roller), (wall, level_wall)] {
        assert!((a[0] - b[0]).abs() < 1e-10 * force && (a[1] - b[1]).abs() < 1e-10 * force, "{a:?} vs {b:?}");
    }
}

fn error(fixes: &str, mesh: Mesh) -> String {
    let scene = GenericScene::from_toml_str(
        &format!(
            "name = \"bad\"\nmesh = \"generated.msh\"\nplane = \"strain\"\n[[body]]\nregion = \"domain\"\n\
             youngs_modulus = 1.0\npoissons_ratio = 0.3\n{fixes}\n[[load]]\ngroup = \"top\"\ntraction = [0.0, 1.0]\n"
        ),
        Path::new("tests/generated.toml"),
        &[],
    );
    match scene {
        Err(e) => e.to_string(),
        Ok(scene) => match solve_generic_on_mesh(&scene, mesh, &mut |_, _| {}) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("{fixes}: solved"),
        },
    }
}

fn square() -> Mesh {
    contact2d_mesh::generate::rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2)
}

#[test]
fn un_on_a_group_that_is_not_a_curve_is_an_error_naming_the_key() {
    let e = error(&fix("domain", "un = 0.0"), square());
    assert!(e.contains("fix.0.un") && e.contains("\"domain\"") && e.contains("need a curve"), "{e}");
}

#[test]
fn un_with_u1_in_one_fix_is_an_error_naming_the_key() {
    let e = error(&fix("bottom", "un = 0.0\nu1 = 0.0"), square());
    assert!(e.contains("fix.0.un") && e.contains("u1"), "{e}");
}

#[test]
fn un_and_u1_on_one_node_from_two_fixes_is_an_error_naming_both() {
    // The corner (0, 0) is on "bottom" (un = 0.1) and on "left" (u1 = 0): conditions in two
    // frames with a value that is not a zero support.
    let e = error(&(fix("bottom", "un = 0.1") + &fix("left", "u1 = 0.0")), square());
    assert!(e.contains("un, ut") && e.contains("\"bottom\"") && e.contains("u1") && e.contains("\"left\""), "{e}");
    // Two rollers along one direction at a node (un on "bottom", u2 on "left": both vertical at
    // the corner) do not hold it in x1: an error as well.
    let e = error(&(fix("bottom", "un = 0.0") + &fix("left", "u2 = 0.0")), square());
    assert!(e.contains("un, ut") && e.contains("u2 by \"left\""), "{e}");
}

#[test]
fn zero_supports_in_two_frames_hold_their_corner_fully() {
    // un = 0 on the bottom and u1 = 0 on the left of a square pulled up by a traction on its top:
    // the corner (0, 0) is held in both directions (a pin), as u1 = 0 / u2 = 0 there would; the
    // same problem posed with u2 = 0 on the bottom (n = (0, −1): un = −u2) gives the same
    // displacements to round-off (1e-12 of max |u|).
    let local = run(
        &(fix("bottom", "un = 0.0") + &fix("left", "u1 = 0.0")),
        "[[load]]\ngroup = \"top\"\ntraction = [0.0, 1.0]",
        square(),
    );
    let global = run(
        &(fix("bottom", "u2 = 0.0") + &fix("left", "u1 = 0.0")),
        "[[load]]\ngroup = \"top\"\ntraction = [0.0, 1.0]",
        square(),
    );
    let (a, b) = (displacement(&local), displacement(&global));
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12 * scale), "{a:?} vs {b:?}");
}

#[test]
fn un_at_a_cusp_is_an_error_naming_the_node() {
    // A curve that runs (0, 0) → (1, 0) and back to (0.5, 0): no normal at (1, 0).
    let mut mesh = square();
    let at = |p: [f64; 2]| NodeId(mesh.points.iter().position(|q| *q == p).unwrap());
    let nodes = vec![at([0.0, 0.0]), at([1.0, 0.0]), at([1.0, 0.0]), at([0.5, 0.0])];
    mesh.groups.push(PhysicalGroup { name: "fold".into(), dim: 1, tag: 77 });
    mesh.blocks.push(CellBlock {
        kind: CellKind::Line2,
        entity_dim: 1,
        entity_tag: 77,
        physical_tags: vec![77],
        nodes,
        element_tags: vec![1001, 1002],
    });
    let e = error(&(fix("fold", "un = 0.0") + &fix("left", "u1 = 0.0")), mesh);
    assert!(e.contains("fix.0.un") && e.contains("cusp"), "{e}");
}

#[test]
fn prescribed_un_on_two_tilted_edges_translate_the_sector_rigidly() {
    // un = c · n on the two straight cut edges of the tilted sector (n: each edge's outward
    // normal, c = (3, −2)·1e-3), no load: the rigid translation u = c meets both conditions and
    // equilibrium, and the two normals hold every rigid mode, so it is the solution, exactly:
    // every node's u = c to round-off (1e-12 of |c|); the reactions vanish (1e-9 of E |c|).
    let deg = std::f64::consts::PI / 180.0;
    let c = [3e-3, -2e-3];
    let normal = |theta: f64, sign: f64| [-sign * theta.sin(), sign * theta.cos()];
    let (n_start, n_end) = (normal(20.0 * deg, -1.0), normal(50.0 * deg, 1.0));
    let value = |n: [f64; 2]| c[0] * n[0] + c[1] * n[1];
    let fixes = fix("start", &format!("un = {:?}", value(n_start))) + &fix("end", &format!("un = {:?}", value(n_end)));
    for kind in [CellKind::Quad8, CellKind::Tri3] {
        let out = run(&fixes, "", annulus_sector(kind, [1.0, 2.0], [20.0 * deg, 50.0 * deg], 3, 3));
        let u = displacement(&out);
        let active = out.built.problem.model.active_nodes();
        let size = c[0].hypot(c[1]);
        for n in (0..active.len()).filter(|n| active[*n]) {
            let d = [u[2 * n] - c[0], u[2 * n + 1] - c[1]];
            assert!(d[0].hypot(d[1]) < 1e-12 * size, "{kind:?} node {n}: u = ({}, {})", u[2 * n], u[2 * n + 1]);
        }
        for (group, r) in &out.report.reactions {
            let r = r.map(Option::unwrap);
            assert!(r[0].hypot(r[1]) < 1e-9 * E * size, "{kind:?} {group}: {r:?}");
        }
    }
}

#[test]
fn a_staged_un_holds_the_arc_where_the_step_before_left_it() {
    // The quarter annulus under p in two steps (p/2, p); the outer arc held radially (un = 0)
    // from step 2 on: its nodes' radial displacement stays where step 1 left it (to round-off,
    // 1e-12 of it), its reaction is null in step 1 and the radial hoop-free support in step 2.
    let fixes = fix("start", "un = 0.0") + &fix("end", "un = 0.0") + &fix("outer", "un = 0.0\nfrom_step = 2");
    let text = format!(
        "name = \"staged\"\nmesh = \"generated.msh\"\nplane = \"strain\"\n[[body]]\nregion = \"domain\"\n\
         youngs_modulus = {E}\npoissons_ratio = {NU}\n{fixes}\n{PRESSURE}\n[loading]\nsteps = 2\npath_error = false\n"
    );
    let scene = GenericScene::from_toml_str(&text, Path::new("tests/generated.toml"), &[]).unwrap();
    let mesh = annulus_sector(CellKind::Quad8, [1.0, 2.0], [0.0, std::f64::consts::FRAC_PI_2], 3, 6);
    let out = solve_generic_on_mesh(&scene, mesh, &mut |_, _| {}).unwrap();
    let model = &out.built.problem.model;
    let radial = |step: usize, n: usize| {
        let (u, x) = (&out.history.steps[step].solution.displacement, model.mesh.points[n]);
        (u[2 * n] * x[0] + u[2 * n + 1] * x[1]) / x[0].hypot(x[1])
    };
    let outer = model.mesh.group_nodes("outer").unwrap();
    for n in &outer {
        let (first, second) = (radial(0, n.0), radial(1, n.0));
        assert!(first > 0.0 && (second - first).abs() < 1e-12 * first, "node {}: {first:e} → {second:e}", n.0);
    }
    assert_eq!(out.report.steps.len(), 2);
    assert!(out.report.steps.to_vec()[0].reactions["outer"].iter().all(Option::is_none));
    assert!(out.report.steps.to_vec()[1].reactions["outer"].iter().all(Option::is_some));
}

#[test]
fn un_on_a_contact_node_is_the_same_support_as_u1_on_a_vertical_edge() {
    // The plate's left edge x = 0 on `un = 0` (its normal is ±x, so un = 0 is u1 = 0): its
    // corner (0, 0) is a node of the contact's master edge, whose pair rows are then written
    // in the corner's frame (B' = B T). Truth: the same problem with u1 = 0, to 1e-10 of the
    // largest displacement and of the press (two eliminations of one condition: round-off).
    // The plate and the ground turned by `angle` about the origin (the corner).
    let mesh = |angle: f64| {
        let (c, s) = (angle.cos(), angle.sin());
        let turn = move |x: [f64; 2]| [c * x[0] - s * x[1], s * x[0] + c * x[1]];
        let mut mesh = Mesh::default();
        let plate = mapped_grid(
            &MappedGrid { kind: CellKind::Quad4, nx: 4, ny: 2, region: "domain" },
            |u, v| turn([10.0 * u, 5.0 * v]),
            |side, _| Some(side_name(side).to_string()),
        );
        contact2d_mesh::generate::append_prefixed(&mut mesh, &plate, "plate_");
        let ground = mapped_grid(
            &MappedGrid { kind: CellKind::Quad4, nx: 6, ny: 2, region: "domain" },
            |u, v| turn([12.0 * u, -2.0 + 2.0 * v]),
            |side, _| Some(side_name(side).to_string()),
        );
        contact2d_mesh::generate::append_prefixed(&mut mesh, &ground, "ground_");
        mesh
    };
    let solve = |support: &str, mesh: Mesh| {
        let text = format!(
            "name = \"c\"\nmesh = \"generated.msh\"\nplane = \"strain\"\n[[body]]\nregion = \"plate_domain\"\n\
             youngs_modulus = 1000.0\npoissons_ratio = 0.3\n[[fix]]\ngroup = \"plate_left\"\n{support}\n\
             [[load]]\ngroup = \"plate_top\"\npressure = 1.0\n[[contact]]\nname = \"floor\"\nmaster = \"plate_bottom\"\n\
             slave = \"ground_top\"\nrigid = true\nfriction = 0.5\n[loading]\npath_error = false\n"
        );
        let scene = GenericScene::from_toml_str(&text, Path::new("tests/generated.toml"), &[]).unwrap();
        solve_generic_on_mesh(&scene, mesh, &mut |_, _| {}).unwrap()
    };
    let (local, global) = (solve("un = 0.0", mesh(0.0)), solve("u1 = 0.0", mesh(0.0)));
    for out in [&local, &global] {
        assert_eq!(out.report.status, "converged", "{:?}", out.report.failed_check);
    }
    let (a, b) = (&local.history.steps[0].solution.displacement, &global.history.steps[0].solution.displacement);
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(worst <= 1e-10 * scale, "displacements differ by {worst:e} of {scale:e}");
    let (ca, cb) = (&local.report.contacts["floor"], &global.report.contacts["floor"]);
    let press = 10.0;
    assert!(
        (ca.normal_force - cb.normal_force).abs() <= 1e-10 * press,
        "{} against {}",
        ca.normal_force,
        cb.normal_force
    );
    assert!((ca.tangential_force - cb.tangential_force).abs() <= 1e-10 * press);
    // The whole problem turned by 30°: the left edge is no longer along an axis, and `un = 0`
    // is the only way to pose its roller. Truth: rotation invariance — the contact's resultants
    // are those of the unturned problem and every displacement is the unturned one turned, to
    // 1e-9 (round-off of the turned coordinates).
    let angle = std::f64::consts::FRAC_PI_6;
    let turned = solve("un = 0.0", mesh(angle));
    assert_eq!(turned.report.status, "converged", "{:?}", turned.report.failed_check);
    let ct = &turned.report.contacts["floor"];
    assert!(
        (ct.normal_force - cb.normal_force).abs() <= 1e-9 * press,
        "{} against {}",
        ct.normal_force,
        cb.normal_force
    );
    assert!((ct.tangential_force.abs() - cb.tangential_force.abs()).abs() <= 1e-9 * press);
    let u = &turned.history.steps[0].solution.displacement;
    let (c, s) = (angle.cos(), angle.sin());
    for n in 0..b.len() / 2 {
        let expected = [c * b[2 * n] - s * b[2 * n + 1], s * b[2 * n] + c * b[2 * n + 1]];
        for k in 0..2 {
            assert!(
                (u[2 * n + k] - expected[k]).abs() <= 1e-9 * scale,
                "node {n}: {:?} against {expected:?}",
                &u[2 * n..2 * n + 2]
            );
        }
    }
}

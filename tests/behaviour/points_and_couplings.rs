//! Reference points and couplings (`[[point]]`), loads and fixes on points, and a group turned
//! rigidly (`[[fix]] rotation, about`), each against an independent truth:
//!
//! * a rigid rotation's displacement field `u = t + θ e3 × (x − c)` (exact: a rigid motion
//!   strains nothing, so the finite-element solution is that field up to round-off);
//! * equilibrium of forces and moments: the supports' reactions balance the point's force and
//!   moment (to 1e-8 of the load);
//! * Euler–Bernoulli's end rotation `θ = M L / (E I)` of a cantilever under an end moment (with
//!   ν = 0 the plane-stress solution `u1 = −M x y / (E I)`, `u2 = M x² / (2 E I)` is quadratic,
//!   so Quad9 elements hold it exactly and the clamp `u = 0` at x = 0 is exact too: the only error
//!   is round-off).
//!
//! Meshes are generated (`contact2d_mesh::generate::rectangle`, groups `domain`, `bottom`,
//! `right`, `top`, `left`) and scenes are TOML strings, solved on the mesh without files.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic_on_mesh};
use contact2d::mesh::generate::{append_prefixed, rectangle};
use contact2d::mesh::{CellKind, Mesh};
use contact2d::scene::SceneError;

fn scene(text: &str) -> Result<GenericScene, SceneError> {
    GenericScene::from_toml_str(text, Path::new("points.toml"), &[])
}

fn solve(text: &str, mesh: Mesh) -> GenericOutcome {
    let outcome = solve_generic_on_mesh(&scene(text).unwrap(), mesh, &mut |_, _| {}).unwrap();
    assert_eq!(outcome.report.status, "converged", "{:?}", outcome.report.failed_check);
    outcome
}

/// The key of a scene's value error, checked or solved.
fn error_key(text: &str, mesh: Mesh) -> String {
    let err = match scene(text) {
        Err(e) => e,
        Ok(s) => match solve_generic_on_mesh(&s, mesh, &mut |_, _| {}) {
            Err(contact2d::generic::GenericError::Scene(e)) => e,
            other => panic!("expected a scene error, got {:?}", other.map(|o| o.report.status)),
        },
    };
    match err {
        SceneError::Value { key, path, .. } => {
            assert_eq!(path, "points.toml");
            key
        }
        other => panic!("expected a value error, got {other:?}"),
    }
}

fn block() -> Mesh {
    rectangle(CellKind::Quad9, [0.0, 2.0], [0.0, 1.0], 4, 2)
}

const BODY: &str = r#"
name = "t"
mesh = "none.msh"
[[body]]
region = "domain"
youngs_modulus = 1000.0
poissons_ratio = 0.3
"#;

/// `θ e3 × (x − c)`.
fn turn(theta: f64, x: [f64; 2], c: [f64; 2]) -> [f64; 2] {
    [-theta * (x[1] - c[1]), theta * (x[0] - c[0])]
}

#[test]
fn a_block_turned_by_one_edge_moves_as_a_rigid_rotation() {
    // Only the left edge is held, turned by θ about c and translated by t: the whole block
    // follows rigidly. Tolerance 1e-10 of |θ| L: the solve of K_ff u_f = −K_fc u_c loses about
    // cond(K) ε ~ 1e4 × 1e-16 relative on this 8-cell block.
    let (theta, c, t) = (2e-3, [0.5, 0.25], [1e-4, -3e-4]);
    let text = format!(
        "{BODY}[[fix]]\ngroup = \"left\"\nrotation = {theta}\nabout = [{}, {}]\nu1 = {}\nu2 = {}\n",
        c[0], c[1], t[0], t[1]
    );
    let outcome = solve(&text, block());
    let u = &outcome.history.steps.last().unwrap().solution.displacement;
    let mesh = &outcome.built.problem.model.mesh;
    let mut worst = 0.0f64;
    for (n, x) in mesh.points.iter().enumerate() {
        let r = turn(theta, *x, c);
        worst = worst.max((u[2 * n] - t[0] - r[0]).abs()).max((u[2 * n + 1] - t[1] - r[1]).abs());
    }
    assert!(worst < 1e-10 * theta * 2.0, "largest departure from the rigid field {worst:e}");
    // A rigid motion stores nothing (up to the round-off of ½ uᵀ K u, ~ n ε E U², U = |θ| L)
    // and needs no force.
    let energy = outcome.report.energies["domain"];
    assert!(energy.abs() < 1e-10 * 1000.0 * (theta * 2.0) * (theta * 2.0), "{energy}");
    assert!(outcome.report.reactions["left"].iter().all(|r| r.unwrap().abs() < 1e-9));
}

#[test]
fn a_block_turned_above_an_open_contact_moves_rigidly_and_leaves_the_other_still() {
    // Block B above block A, a gap of 0.5 between them; B's top is turned by θ = 1e-3 about its
    // centre, which moves no point of B by more than 1.2e-3: the contact stays open, A (fixed at
    // its bottom) stays still and B moves rigidly. Tolerance as above.
    let mut mesh = rectangle(CellKind::Quad9, [0.0, 2.0], [0.0, 1.0], 4, 2);
    let mut a = mesh.clone();
    a.groups.iter_mut().for_each(|g| g.name = format!("a_{}", g.name));
    mesh = a;
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.0, 2.0], [1.5, 2.5], 4, 2), "b_");
    let (theta, c) = (1e-3, [1.0, 2.0]);
    let text = format!(
        r#"name = "t"
mesh = "none.msh"
[[body]]
region = "a_domain"
youngs_modulus = 1000.0
poissons_ratio = 0.3
[[body]]
region = "b_domain"
youngs_modulus = 1000.0
poissons_ratio = 0.3
[[fix]]
group = "a_bottom"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "b_top"
rotation = {theta}
about = [{}, {}]
[[contact]]
name = "between"
master = "b_bottom"
slave = "a_top"
"#,
        c[0], c[1]
    );
    let outcome = solve(&text, mesh);
    let u = &outcome.history.steps.last().unwrap().solution.displacement;
    let mesh = &outcome.built.problem.model.mesh;
    assert_eq!(outcome.report.contacts["between"].normal_force, 0.0);
    let mut worst = 0.0f64;
    for (n, x) in mesh.points.iter().enumerate() {
        let r = if x[1] > 1.25 { turn(theta, *x, c) } else { [0.0, 0.0] };
        worst = worst.max((u[2 * n] - r[0]).abs()).max((u[2 * n + 1] - r[1]).abs());
    }
    assert!(worst < 1e-10 * theta * 2.0, "largest departure {worst:e}");
}

#[test]
fn a_moment_through_a_distributing_point_is_balanced_by_the_supports() {
    // A plate [0, 4] × [0, 1] clamped on its left edge; a distributing point at p = (5, 0.5),
    // off the plate, coupled to the right edge, carries F = (10, −20) and M = 30. A second
    // distributing point `anchor` at a = (0, 0), coupled to the left edge and neither loaded nor
    // fixed, reports the left supports' resultant R and moment M_R about a. Equilibrium:
    //   R + F = 0,   M_R + M + (p − a) × F = 0,
    // to 1e-8 of the load (|F| |p| + |M| ~ 150): the reactions are K u − f at the supports,
    // exact up to round-off.
    let text = format!(
        r#"{BODY}
[[fix]]
group = "left"
u1 = 0.0
u2 = 0.0
[[point]]
name = "shaft_ref"
at = [5.0, 0.5]
group = "right"
coupling = "distributing"
[[point]]
name = "anchor"
at = [0.0, 0.0]
group = "left"
coupling = "distributing"
[[load]]
point = "shaft_ref"
force = [10.0, -20.0]
moment = 30.0
"#
    );
    let outcome = solve(&text, rectangle(CellKind::Quad9, [0.0, 4.0], [0.0, 1.0], 8, 2));
    let (f, m, p): ([f64; 2], f64, [f64; 2]) = ([10.0, -20.0], 30.0, [5.0, 0.5]);
    let scale = 1e-8 * (f[0].hypot(f[1]) * p[0].hypot(p[1]) + m);
    let anchor = outcome.report.points["anchor"];
    let [r1, r2] = anchor.reaction;
    assert!((r1 + f[0]).abs() < scale && (r2 + f[1]).abs() < scale, "R = {:?}", anchor.reaction);
    let moment = anchor.reaction_moment.unwrap() + m + (p[0] * f[1] - p[1] * f[0]);
    assert!(moment.abs() < scale, "moment balance off by {moment:e}");
    // The same from the reactions of every constrained DOF, summed here.
    let step = outcome.history.steps.last().unwrap();
    let problem = &outcome.built.problem;
    let r = problem.reactions(&step.solution, &step.factors).unwrap();
    let (mut total, mut about_a) = ([0.0; 2], 0.0);
    for (d, r) in problem.system.dofs.constrained_dofs().iter().zip(&r) {
        let x = problem.model.mesh.points[d.node()];
        total[d.0 % 2] += r;
        about_a += if d.0 % 2 == 0 { -x[1] * r } else { x[0] * r };
    }
    assert!((total[0] + f[0]).abs() < scale && (total[1] + f[1]).abs() < scale, "{total:?}");
    assert!((about_a + m + (p[0] * f[1] - p[1] * f[0])).abs() < scale, "{about_a}");
    // The loaded point is held by nothing: no reaction; the step rows carry the points too.
    assert_eq!(outcome.report.points["shaft_ref"].reaction, [0.0, 0.0]);
    assert_eq!(outcome.report.steps.to_vec()[0].points["anchor"], anchor);
}

#[test]
fn a_cantilever_under_an_end_moment_turns_by_m_l_over_e_i() {
    // Euler–Bernoulli: θ(L) = M L / (E I), I = h³ / 12 (unit thickness), u2(L) = M L² / (2 E I).
    // With ν = 0 the plane-stress solution is quadratic and the clamp exact (module docs), so
    // Quad9 elements reproduce it: the distributing coupling's nodal forces on the straight end
    // (w_i M y_i / Σ w y², tributary weights L/6, L/6, 2L/3 per Line3) are the consistent loads
    // of the linear bending stress. The tolerance is round-off, 1e-9 relative (cond(K) of a
    // 10 × 1 beam on 20 × 2 cells, ~1e7, times ε); a coarser mesh gives the same answer, which
    // is the refinement argument: there is no discretisation error to shrink.
    let (length, height, e, m) = (10.0, 1.0, 1000.0, 2.0);
    let inertia = height * height * height / 12.0;
    let text = format!(
        r#"name = "t"
mesh = "none.msh"
[[body]]
region = "domain"
youngs_modulus = {e}
poissons_ratio = 0.0
[[fix]]
group = "left"
u1 = 0.0
u2 = 0.0
[[point]]
name = "tip"
at = [{length}, 0.5]
group = "right"
coupling = "distributing"
[[load]]
point = "tip"
moment = {m}
"#
    );
    for nx in [5, 20] {
        let outcome = solve(&text, rectangle(CellKind::Quad9, [0.0, length], [0.0, height], nx, 2));
        let tip = outcome.report.points["tip"];
        let theta = m * length / (e * inertia);
        let deflection = m * length * length / (2.0 * e * inertia);
        let rotation = tip.rotation.unwrap();
        assert!((rotation - theta).abs() < 1e-9 * theta, "{nx} cells: θ = {rotation}, M L / (E I) = {theta}");
        assert!((tip.displacement[1] - deflection).abs() < 1e-9 * deflection, "{nx} cells: {:?}", tip.displacement);
        assert!(tip.displacement[0].abs() < 1e-9 * deflection, "{:?}", tip.displacement);
    }
}

#[test]
fn a_fixed_kinematic_point_moves_its_group_rigidly_and_its_reaction_balances_the_supports() {
    // A block clamped at the bottom; a kinematic point p = (1, 2) coupled to the top edge is
    // fixed at u_p = (1e-3, −2e-3), θ = 1e-3: every top node moves as u_p + θ e3 × (x − p)
    // (prescribed), the point reports its prescribed motion, and its reaction and moment
    // balance the bottom's (reported by a free distributing point coupled there): R_top + R_bottom
    // = 0, M_top + M_bottom + (b − p) × R_bottom = 0 about p, to 1e-8 of the reaction's scale.
    let (up, theta, p) = ([1e-3, -2e-3], 1e-3, [1.0, 2.0]);
    let text = format!(
        r#"{BODY}
[[fix]]
group = "bottom"
u1 = 0.0
u2 = 0.0
[[point]]
name = "cap"
at = [{}, {}]
group = "top"
coupling = "kinematic"
[[point]]
name = "base"
at = [1.0, 0.0]
group = "bottom"
coupling = "distributing"
[[fix]]
point = "cap"
u1 = {}
u2 = {}
rotation = {theta}
pattern = "turn"
"#,
        p[0], p[1], up[0], up[1]
    );
    let outcome = solve(&text, block());
    let u = &outcome.history.steps.last().unwrap().solution.displacement;
    let mesh = &outcome.built.problem.model.mesh;
    for n in mesh.group_nodes("top").unwrap() {
        let r = turn(theta, mesh.points[n.0], p);
        assert!((u[2 * n.0] - up[0] - r[0]).abs() < 1e-15 && (u[2 * n.0 + 1] - up[1] - r[1]).abs() < 1e-15);
    }
    let cap = outcome.report.points["cap"];
    assert!((cap.rotation.unwrap() - theta).abs() < 1e-12 * theta);
    assert!((cap.displacement[0] - up[0]).abs() < 1e-15 && (cap.displacement[1] - up[1]).abs() < 1e-15);
    let base = outcome.report.points["base"];
    let scale = 1e-8 * cap.reaction[0].hypot(cap.reaction[1]);
    assert!(scale > 0.0);
    assert!((cap.reaction[0] + base.reaction[0]).abs() < scale && (cap.reaction[1] + base.reaction[1]).abs() < scale);
    let b = [1.0, 0.0];
    let arm = [b[0] - p[0], b[1] - p[1]];
    let moment = cap.reaction_moment.unwrap()
        + base.reaction_moment.unwrap()
        + (arm[0] * base.reaction[1] - arm[1] * base.reaction[0]);
    assert!(moment.abs() < scale * 3.0, "moment balance off by {moment:e}");
    assert_eq!(outcome.report.steps.to_vec()[0].factors["turn"], 1.0);
}

#[test]
fn a_node_point_takes_a_force_and_a_fix() {
    // A point without coupling is the mesh node at `at`: a force there is a nodal force; the
    // balance R + F = 0 holds to 1e-8 of |F|.
    let text = format!(
        r#"{BODY}
[[fix]]
group = "left"
u1 = 0.0
u2 = 0.0
[[point]]
name = "corner"
at = [2.0, 1.0]
[[point]]
name = "foot"
at = [2.0, 0.0]
[[fix]]
point = "foot"
u2 = 0.0
[[load]]
point = "corner"
force = [0.0, -5.0]
"#
    );
    let outcome = solve(&text, block());
    let r = &outcome.report;
    assert!(r.points["corner"].rotation.is_none() && r.points["corner"].displacement[1] < 0.0);
    let total = r.reactions_total;
    assert!(total[0].abs() < 1e-8 * 5.0 && (total[1] - 5.0).abs() < 1e-8 * 5.0, "{total:?}");
    assert!(r.points["foot"].reaction[1] > 0.0);
    assert_eq!(r.points["foot"].displacement[1], 0.0);
}

#[test]
fn a_zero_fix_may_name_a_pattern_that_a_schedule_names() {
    let text = format!(
        r#"{BODY}
[[fix]]
group = "left"
u1 = 0.0
u2 = 0.0
pattern = "hold"
[[load]]
group = "right"
force = [1.0, 0.0]
pattern = "pull"
[loading]
schedule = [{{ hold = 1.0, pull = 0.5 }}, {{ hold = 1.0, pull = 1.0 }}]
"#
    );
    let outcome = solve(&text, block());
    assert_eq!(outcome.report.steps.len(), 2);
    assert!((outcome.report.reactions["left"][0].unwrap() + 1.0).abs() < 1e-10);
}

#[test]
fn bad_points_fixes_and_loads_are_refused_naming_the_key() {
    let coupled = |group: &str, coupling: &str| {
        format!("[[point]]\nname = \"p\"\nat = [2.0, 0.5]\ngroup = \"{group}\"\ncoupling = \"{coupling}\"\n")
    };
    let left = "[[fix]]\ngroup = \"left\"\nu1 = 0.0\nu2 = 0.0\n";
    let moment = "[[load]]\npoint = \"p\"\nmoment = 1.0\n";
    let mut empty = block();
    empty.groups.push(contact2d::mesh::PhysicalGroup { name: "nothing".into(), dim: 1, tag: 99 });
    let cases: Vec<(String, Mesh, &str)> = vec![
        // A point coupled to a missing group, or to an empty one.
        (format!("{BODY}{left}{}{moment}", coupled("nowhere", "distributing")), block(), "point.0.group"),
        (format!("{BODY}{left}{}{moment}", coupled("nothing", "distributing")), empty, "point.0.group"),
        // A moment on a point with no coupling.
        (format!("{BODY}{left}[[point]]\nname = \"p\"\nat = [2.0, 1.0]\n{moment}"), block(), "load.0.moment"),
        // A kinematic coupling on a group that is also fixed.
        (
            format!(
                "{BODY}{left}{}[[fix]]\npoint = \"p\"\nu1 = 0.0\nu2 = 0.0\nrotation = 0.0\n",
                coupled("left", "kinematic")
            ),
            block(),
            "point.0.group",
        ),
        // A loaded (not fixed) kinematic point: a multi-point constraint, not built.
        (format!("{BODY}{left}{}{moment}", coupled("right", "kinematic")), block(), "point.0.coupling"),
        // A fix on a distributing point.
        (
            format!("{BODY}{left}{}[[fix]]\npoint = \"p\"\nu1 = 0.0\n", coupled("right", "distributing")),
            block(),
            "fix.1.point",
        ),
        // A rotation of a group without its centre, and a centre without a rotation.
        (format!("{BODY}[[fix]]\ngroup = \"left\"\nrotation = 0.1\n"), block(), "fix.0.about"),
        (format!("{BODY}[[fix]]\ngroup = \"left\"\nu1 = 0.0\nabout = [0.0, 0.0]\n"), block(), "fix.0.about"),
        // A moment on a group, a load on an unknown point, a point off the mesh without coupling.
        (format!("{BODY}{left}[[load]]\ngroup = \"right\"\nmoment = 1.0\n"), block(), "load.0.moment"),
        (format!("{BODY}{left}[[load]]\npoint = \"q\"\nforce = [1.0, 0.0]\n"), block(), "load.0.point"),
        (
            format!(
                "{BODY}{left}[[point]]\nname = \"p\"\nat = [2.1, 0.5]\n[[load]]\npoint = \"p\"\nforce = [1.0, 0.0]\n"
            ),
            block(),
            "point.0.at",
        ),
        // A group without a coupling.
        (
            format!("{BODY}{left}[[point]]\nname = \"p\"\nat = [2.0, 0.5]\ngroup = \"right\"\n"),
            block(),
            "point.0.coupling",
        ),
    ];
    for (text, mesh, key) in cases {
        assert_eq!(error_key(&text, mesh), key, "{text}");
    }
}

#[test]
fn a_kinematic_point_fixed_as_a_group_fix_gives_the_same_problem_and_its_reaction() {
    // `pad_on_base.toml`'s pad_top fix (u1 = 0, u2 = −0.001) posed as a kinematic point fixed at
    // (0, −0.001), rotation 0: the same DOFs prescribed the same values, so the same solution.
    // The point's reaction is the group's (1e-10 of the force: the same sums in another order),
    // and a distributing point coupled to the clamped base_bottom reports its opposite.
    let path = Path::new("scenes/generic/pad_on_base.toml");
    let original = contact2d::generic::load_scene(path, &[]).unwrap();
    let original = contact2d::generic::solve_generic(&original, &mut |_, _| {}).unwrap().report;
    let text = std::fs::read_to_string(path).unwrap().replace(
        "[[fix]]\ngroup = \"pad_top\"\nu1 = 0.0\nu2 = -0.001\n",
        "[[point]]\nname = \"cap\"\nat = [2.5, 1.2]\ngroup = \"pad_top\"\ncoupling = \"kinematic\"\n\
         [[point]]\nname = \"anchor\"\nat = [2.5, 0.0]\ngroup = \"base_bottom\"\ncoupling = \"distributing\"\n\
         [[fix]]\npoint = \"cap\"\nu1 = 0.0\nu2 = -0.001\nrotation = 0.0\n",
    );
    assert!(text.contains("name = \"cap\""));
    let posed = GenericScene::from_toml_str(&text, path, &[]).unwrap();
    let posed = contact2d::generic::solve_generic(&posed, &mut |_, _| {}).unwrap().report;
    assert_eq!(posed.status, "converged");
    let expected = original.reactions["pad_top"];
    let force = expected[1].unwrap().abs();
    let (cap, anchor) = (posed.points["cap"], posed.points["anchor"]);
    for c in 0..2 {
        assert!((cap.reaction[c] - expected[c].unwrap()).abs() <= 1e-10 * force, "{:?} {expected:?}", cap.reaction);
        assert!((cap.reaction[c] + anchor.reaction[c]).abs() <= 1e-8 * force, "{:?}", anchor.reaction);
    }
    let n = original.contacts["joint"].normal_force;
    assert!((posed.contacts["joint"].normal_force - n).abs() <= 1e-10 * n.abs());
}

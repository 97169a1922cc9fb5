//! Issue 27, item 7: corners, quadratic edges and statuses, on scenes built here (meshes generated
//! in the test, no file or gmsh needed).
//!
//! ```text
//!  plate on a rigid plane (μ = 1)            half pin in a plate (non-matching, quadratic)
//!   symmetry u1 = 0 │ p = 100                      plate outer r = 40 fixed
//!                   ┌──────────────┐ y = 5          hole r = 10 (master) ╭───╮
//!                   │  plate 10×5  │                pin r = 10 (slave)  │pin│ ← u1 = −0.01 on r = 2
//!   corner (0, 0) ▶ └──────────────┘ y = 0          y = 0: u2 = 0 in both bodies (symmetry line)
//!   ══════════════ rigid ground ═══════ y = 0..−2
//! ```
//!
//! Independent truths: global equilibrium (the loads, `reactions_total` and the rigid obstacle's
//! resultant sum to zero), symmetry (no shear on a symmetry line), and a second pairing or a
//! second treatment of the same condition (NTS against STS; a node held by a fix against the
//! same problem without its pair).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic_on_mesh};
use contact2d_mesh::generate::{MappedGrid, Side, annulus_sector, append_prefixed, mapped_grid, side_name};
use contact2d_mesh::{CellKind, Mesh};

/// Plate [0, 10] × [0, 5] (2n × n cells) on a rigid ground [0, 12] × [−2, 0]. With `split`, the
/// plate's bottom edge at the corner (the first cell) is its own group `plate_corner`.
fn plate_mesh(kind: CellKind, n: usize, split: bool) -> Mesh {
    let grid = MappedGrid { kind, nx: 2 * n, ny: n, region: "domain" };
    let first = 0.5 / (2 * n) as f64;
    let plate = mapped_grid(
        &grid,
        |u, v| [10.0 * u, 5.0 * v],
        |side, t| Some(if split && side == Side::Bottom && t < first { "corner" } else { side_name(side) }.to_string()),
    );
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &plate, "plate_");
    let ground = mapped_grid(
        &MappedGrid { kind, nx: 3 * n, ny: n, region: "domain" },
        |u, v| [12.0 * u, -2.0 + 2.0 * v],
        |side, _| Some(side_name(side).to_string()),
    );
    append_prefixed(&mut mesh, &ground, "ground_");
    mesh
}

/// The plate pressed by p = 100 (1,000 N over its top), μ = 1, with `fixes` on its left edge.
fn plate_scene(pairing: &str, steps: usize, left: &str) -> String {
    format!(
        r#"
name = "plate_on_plane"
mesh = "generated.msh"
plane = "strain"
[[body]]
region = "plate_domain"
youngs_modulus = 1000.0
poissons_ratio = 0.3
[[fix]]
group = "plate_left"
{left}
[[load]]
group = "plate_top"
pressure = 100.0
[[contact]]
name = "floor"
master = "plate_bottom"
slave = "ground_top"
rigid = true
friction = 1.0
pairing = "{pairing}"
[loading]
steps = {steps}
"#
    )
}

/// The load's total force on the plate (p × top length).
const PRESS: f64 = 1000.0;

fn run(text: &str, mesh: Mesh) -> GenericOutcome {
    let scene = GenericScene::from_toml_str(text, Path::new("tests/generated.toml"), &[]).unwrap();
    solve_generic_on_mesh(&scene, mesh, &mut |_, _| {}).unwrap()
}

/// `[R1, R2]` of the loads + reactions + the obstacle: zero by global equilibrium.
fn imbalance(out: &GenericOutcome) -> [f64; 2] {
    let r = &out.report;
    let obstacle =
        r.contacts.values().filter_map(|c| c.rigid_resultant).fold([0.0, 0.0], |a, f| [a[0] + f[0], a[1] + f[1]]);
    [r.reactions_total[0] + obstacle[0], r.reactions_total[1] + obstacle[1] - PRESS]
}

#[test]
fn a_contact_node_a_fix_holds_along_the_normal_is_left_to_the_fix() {
    // The plate clamped along its left edge (u1 = u2 = 0): the corner (0, 0) is a contact node
    // held along the normal. Before: no contact at all, status `numerical` with no check named
    // (the pair's row had no free DOF and made the interface singular; penetration 13.8 under
    // the pressure, 0.12 under a prescribed 0.12). Truths: (1) global equilibrium, to 1e-9 of
    // the load (round-off of a direct solve); (2) on linear edges, where the corner is the only
    // node of its edge, the same problem with that edge left out of the contact (the pair not
    // formed) gives the same contact force to 1e-9 relative: the fix holds the node and a pair
    // there adds no condition.
    let left = "u1 = 0.0\nu2 = 0.0";
    for kind in [CellKind::Quad9, CellKind::Quad4, CellKind::Tri6] {
        for n in [2, 4] {
            let out = run(&plate_scene("node_to_segment", 1, left), plate_mesh(kind, n, false));
            let r = &out.report;
            assert_eq!(r.status, "converged", "{kind:?} n = {n}: {:?}", r.failed_check);
            assert!(r.notes.iter().any(|s| s.contains("held along the contact normal")), "{:?}", r.notes);
            let [fx, fy] = imbalance(&out);
            assert!(fx.abs() < 1e-9 * PRESS && fy.abs() < 1e-9 * PRESS, "{kind:?} n = {n}: imbalance {fx}, {fy}");
            assert!(r.kkt.max_penetration < 1e-12, "{kind:?} n = {n}: penetration {}", r.kkt.max_penetration);
            assert!(r.contacts["floor"].normal_force > 0.5 * PRESS, "{kind:?} n = {n}: the contact carries the press");
            if kind == CellKind::Quad4 {
                let truth = run(&plate_scene("node_to_segment", 1, left), plate_mesh(kind, n, true));
                let (a, b) = (r.contacts["floor"].normal_force, truth.report.contacts["floor"].normal_force);
                assert!((a - b).abs() <= 1e-9 * b.abs(), "n = {n}: {a} against {b} without the corner's pair");
            }
        }
    }
}

#[test]
fn a_prescribed_penetration_at_a_held_node_is_noted_and_the_rest_solves() {
    // The left edge pushed 0.12 into the plane (u2 = −0.12) and the top likewise: the corner's
    // penetration is the fixes', which no contact force can change; before, it stopped the whole
    // contact (status `numerical`, penetration 0.12 everywhere, no check named). Truth: global
    // equilibrium to 1e-9 of the largest reaction, and the note names the prescribed
    // penetration (0.12 to round-off).
    let left = "u1 = 0.0\nu2 = -0.12\n[[fix]]\ngroup = \"plate_top\"\nu2 = -0.12";
    let text = plate_scene("node_to_segment", 1, left).replace("pressure = 100.0", "pressure = 0.0");
    let out = run(&text, plate_mesh(CellKind::Quad9, 2, false));
    let r = &out.report;
    assert_eq!(r.status, "converged", "{:?}", r.failed_check);
    assert!(r.notes.iter().any(|s| s.contains("prescribe a penetration of 1.2000e-1")), "{:?}", r.notes);
    let obstacle = r.contacts["floor"].rigid_resultant.unwrap();
    let scale = r.reactions_total[1].abs();
    assert!((r.reactions_total[0] + obstacle[0]).abs() < 1e-9 * scale);
    assert!((r.reactions_total[1] + obstacle[1]).abs() < 1e-9 * scale);
}

#[test]
fn segment_to_segment_converges_at_a_symmetry_corner_and_agrees_with_node_to_segment() {
    // Symmetry line x = 0 (u1 = 0 only), μ = 1, the plate held only by the contact vertically.
    // Before: segment-to-segment stopped at max_iterations (100) at n = 2 and 4 (a cycle of three
    // states: the corner pair's tangential row reached free DOFs only through its neighbours'
    // shape functions, so its stick equation nearly repeated theirs and returned τ = −2.2 against
    // λ = 0.06). Truths: the normal force is the press (equilibrium, 1e-9), the friction
    // resultant is the symmetry line's reaction (equilibrium, 1e-9), and the two pairings are two
    // discretisations of one traction, so their friction resultants converge to each other: the
    // relative difference is below 2 % at n = 2, below 0.5 % at n = 4 and falls by at least 1.5
    // from n = 2 to 4 (measured on Quad4 1.1 % and 0.37 %, on Quad9 1.7e-4 and 1.2e-6).
    for kind in [CellKind::Quad9, CellKind::Quad8, CellKind::Quad4, CellKind::Tri6] {
        for steps in [1, 3] {
            let mut differences = vec![];
            for n in [2, 4] {
                let what = format!("{kind:?} n = {n}, {steps} steps");
                let sts = run(&plate_scene("segment_to_segment", steps, "u1 = 0.0"), plate_mesh(kind, n, false));
                let nts = run(&plate_scene("node_to_segment", steps, "u1 = 0.0"), plate_mesh(kind, n, false));
                for out in [&sts, &nts] {
                    let r = &out.report;
                    assert_eq!(r.status, "converged", "{what}: {:?}", r.failed_check);
                    assert!(r.steps.iter().all(|s| s.iterations < 100), "{what}");
                    let [fx, fy] = imbalance(out);
                    assert!(fx.abs() < 1e-9 * PRESS && fy.abs() < 1e-9 * PRESS, "{what}: imbalance {fx}, {fy}");
                    assert!((r.contacts["floor"].normal_force - PRESS).abs() < 1e-9 * PRESS, "{what}");
                }
                let (a, b) =
                    (sts.report.contacts["floor"].tangential_force, nts.report.contacts["floor"].tangential_force);
                differences.push((a - b).abs() / b.abs());
            }
            let [coarse, fine] = [differences[0], differences[1]];
            assert!(coarse < 2e-2 && fine < 5e-3, "{kind:?}, {steps} steps: {differences:?}");
            assert!(fine < coarse / 1.5 || fine < 1e-5, "{kind:?}, {steps} steps: {differences:?}");
        }
    }
}

/// Half pin in a plate: plate r ∈ [10, 40] (2n × 5n cells), pin r ∈ [2, 10] (n × 4n cells),
/// θ ∈ [0, π]: the interface r = 10 meshed with 5n and 4n quadratic edges (non-matching).
fn pin_mesh(kind: CellKind, n: usize) -> Mesh {
    let mut mesh = Mesh::default();
    let half = [0.0, std::f64::consts::PI];
    append_prefixed(&mut mesh, &annulus_sector(kind, [10.0, 40.0], half, 2 * n, 5 * n), "plate_");
    append_prefixed(&mut mesh, &annulus_sector(kind, [2.0, 10.0], half, n, 4 * n), "pin_");
    mesh
}

/// The pin's bore pushed 0.01 along −x, steel on steel, symmetry y = 0 in both bodies.
fn pin_scene(pairing: &str, steps: usize, mu: f64) -> String {
    let mut fixes = String::new();
    for group in ["plate_start", "plate_end", "pin_start", "pin_end"] {
        fixes += &format!("[[fix]]\ngroup = \"{group}\"\nu2 = 0.0\n");
    }
    format!(
        r#"
name = "pin_in_plate"
mesh = "generated.msh"
plane = "strain"
[[body]]
region = "plate_domain"
youngs_modulus = 200000.0
poissons_ratio = 0.3
[[body]]
region = "pin_domain"
youngs_modulus = 200000.0
poissons_ratio = 0.3
[[fix]]
group = "plate_outer"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "pin_inner"
u1 = -0.01
{fixes}
[[contact]]
name = "bore"
master = "plate_inner"
slave = "pin_outer"
friction = {mu:?}
pairing = "{pairing}"
[loading]
steps = {steps}
"#
    )
}

#[test]
fn no_shear_on_the_symmetry_line_with_segment_to_segment() {
    // The nodes of the hole at θ = 0 and π lie on the symmetry line y = 0, where both bodies
    // are held in u2, the tangent there. Symmetry requires zero shear. Before: with
    // segment-to-segment pairing the node at θ = π carried 22.0 MPa in 1 step and −22.8 MPa in 2
    // (n = 2; 24.7 MPa at n = 4), node-to-segment 0. Tolerance 1e-9 of the peak pressure:
    // round-off (the pair now has no tangential unknown, its shear is exactly 0).
    for pairing in ["segment_to_segment", "node_to_segment"] {
        for n in [2, 4] {
            for steps in [1, 2, 3] {
                let out = run(&pin_scene(pairing, steps, 0.3), pin_mesh(CellKind::Quad9, n));
                let r = &out.report;
                assert_eq!(r.status, "converged", "{pairing} n = {n}, {steps} steps: {:?}", r.failed_check);
                let profile = r.contacts["bore"].profile.as_ref().unwrap();
                let peak = profile.pressure.iter().fold(0.0f64, |a, p| a.max(*p));
                for (k, (y, shear)) in profile.y.iter().zip(&profile.shear).enumerate() {
                    if y.abs() < 1e-9 {
                        assert!(shear.abs() <= 1e-9 * peak, "{pairing} n = {n}, {steps} steps, node {k}: {shear}");
                    }
                }
            }
        }
    }
}

/// The largest departure of a pressure from the mean of its two neighbours, over the peak: the
/// corner/mid-side alternation (a smooth profile has it O(h²)).
fn alternation(pressure: &[f64]) -> f64 {
    let peak = pressure.iter().fold(0.0f64, |a, p| a.max(*p));
    pressure.windows(3).map(|w| (w[1] - 0.5 * (w[0] + w[2])).abs()).fold(0.0, f64::max) / peak
}

#[test]
fn node_to_segment_on_quadratic_non_matching_edges_warns_and_segment_to_segment_converges() {
    // Frictionless pin, levels n = 4 and 8. Measured (Quad9, n = 1, 2, 4, 8): node-to-segment's
    // alternation 0.64, 0.37, 0.23, 0.22 stalls (its peak 116, 104, 104, 105 MPa does not
    // settle), segment-to-segment's 0.91, 0.93, 0.18, 0.088 halves with h (peak 161, 152, 103,
    // 98). So node-to-segment on quadratic slave edges of non-matching meshes gets a note that
    // recommends segment-to-segment; the test asserts the note and segment-to-segment's
    // convergence: the alternation falls by at least 1/0.6 from n = 4 to n = 8 (measured 2.1 on
    // Quad9, 2.4 on Quad8, 2.2 on Tri6; an O(h) error would give 2).
    for kind in [CellKind::Quad9, CellKind::Quad8, CellKind::Tri6] {
        let nts = run(&pin_scene("node_to_segment", 1, 0.0), pin_mesh(kind, 4));
        assert!(
            nts.report.notes.iter().any(|s| s.contains("use pairing = \"segment_to_segment\"")),
            "{kind:?}: {:?}",
            nts.report.notes
        );
        let level = |n| {
            let out = run(&pin_scene("segment_to_segment", 1, 0.0), pin_mesh(kind, n));
            assert_eq!(out.report.status, "converged");
            assert!(!out.report.notes.iter().any(|s| s.contains("node-to-segment")), "{:?}", out.report.notes);
            alternation(&out.report.contacts["bore"].profile.as_ref().unwrap().pressure)
        };
        let (coarse, fine) = (level(4), level(8));
        assert!(fine < 0.6 * coarse, "{kind:?}: alternation {coarse} at n = 4, {fine} at n = 8");
    }
}

#[test]
fn every_status_that_is_not_converged_names_its_check() {
    // One iteration allowed: the active set stops at its limit. Before: `max_iterations` with
    // `failed_check` null. Truth: the status's own definition (certify's checks).
    let text = pin_scene("node_to_segment", 1, 0.3) + "[solver]\nmax_iterations = 1\n";
    let out = run(&text, pin_mesh(CellKind::Quad9, 2));
    let r = &out.report;
    assert_eq!(r.status, "max_iterations");
    let why = r.failed_check.as_deref().unwrap();
    assert!(why.starts_with("step 1: iteration limit: 1 iterations"), "{why}");
    assert!(r.steps.to_vec()[0].failed_check.is_some());
}

#[test]
fn the_augmented_lagrangian_converges_at_a_symmetry_corner_on_fine_meshes() {
    // Issue 41 item 5: the augmented Lagrangian (Alart–Curnier) on this scene with Quad9 and
    // segment-to-segment pairs was reported to stop at max_iterations (100, "without a repeated
    // state") on the finer meshes. n = 8 and 16 (plates of 16 × 8 and 32 × 16 cells; measured
    // also on 16 × 16 and 32 × 32: 2 iterations at μ = 1, 6 to 14 at μ = 0.02 to 0.2, all
    // converged). μ = 1 sticks everywhere; μ = 0.1 slips over part of the interface (friction
    // resultant 95 < μN = 100), so the iteration moves pairs between states before it settles
    // (AL 9 and 14 iterations, active set 10 and 11). Truths: the normal force is the press
    // (equilibrium, 1e-9 of it: round-off of a direct solve, measured ≤ 1.1e-14 of it at μ = 1); and
    // the active set (the default algorithm) on the same mesh is a second exact method: both
    // stop only at an exact solution of one state's linear equations (the AL when a full
    // Newton step leaves the state unchanged, so F(x̂) = 0 to round-off, module docs of
    // algorithms/augmented_lagrangian.rs; the active set at round-off, certify.rs), so their
    // friction resultants differ by round-off alone: 1e-9 of the press (measured 3.6e-15 at
    // μ = 1, 8.2e-16 at μ = 0.1).
    for n in [8usize, 16] {
        for mu in ["1.0", "0.1"] {
            let what = format!("Quad9 n = {n}, μ = {mu}");
            let text = plate_scene("segment_to_segment", 1, "u1 = 0.0")
                .replace("friction = 1.0", &format!("friction = {mu}"))
                .replace("[loading]", "[loading]\npath_error = false");
            let al_text = text.replace("[loading]", "[solver]\nalgorithm = \"augmented_lagrangian\"\n[loading]");
            let al = run(&al_text, plate_mesh(CellKind::Quad9, n, false));
            let active = run(&text, plate_mesh(CellKind::Quad9, n, false));
            for out in [&al, &active] {
                let r = &out.report;
                assert_eq!(r.status, "converged", "{what}: {:?}", r.failed_check);
                assert!(r.steps.iter().all(|s| s.iterations < 100), "{what}");
                let [fx, fy] = imbalance(out);
                assert!(fx.abs() < 1e-9 * PRESS && fy.abs() < 1e-9 * PRESS, "{what}: imbalance {fx}, {fy}");
                assert!((r.contacts["floor"].normal_force - PRESS).abs() < 1e-9 * PRESS, "{what}");
            }
            let (a, b) =
                (al.report.contacts["floor"].tangential_force, active.report.contacts["floor"].tangential_force);
            assert!((a - b).abs() < 1e-9 * PRESS, "{what}: friction resultant {a} (AL) against {b} (active set)");
        }
    }
}

//! The active set's stick continuation (crates/contact/src/algorithms/stick_continuation.rs) on
//! the pad layout of issue 22 (scenes/generic/pad_on_base.toml): the iteration count stops
//! growing with the pairs, and the answer is the plain active set's.
//!
//! ```text
//!            pad_top: u1 = 0, u2 = −0.001
//!              ┌────────── pad ──────────┐         polymer pad E = 7 GPa, ν = 0.45
//!   ───────────┴──── joint, μ = 0.2 ─────┴────────  steel base  E = 200 GPa, ν = 0.3
//!  │                   base                      │
//!  └──────────────── base_bottom: u = 0 ─────────┘  plane strain, one step
//! ```
//!
//! Two meshes of meshes/generic/pad_on_base.geo with 2 cells through the base and 1 through the
//! pad (small, for a short test): h = 0.032 (189 pairs, 3,772 DOFs) and h = 0.016 (377 pairs,
//! 7,516 DOFs).
//! Truths the tests assert against:
//! * the plain primal-dual active set (`solver.stick_continuation = "off"`, a second algorithm
//!   for the same discrete law): the same profiles to 1e-10 of their largest value — both end on
//!   the exact law's state, and one state's equations have one solution; what differs is the
//!   round-off of the LU of the same reduced system (~1e-13 here);
//! * equilibrium: the interface's normal force equals the reaction of the pad's top (a
//!   conservation law; 1e-9 relative, the round-off of summing ~400 pair forces);
//! * the iteration count: a semi-smooth Newton method on a regularised law converges in a
//!   number of iterations bounded independently of the mesh per stage (Hintermüller & Kunisch
//!   2006); the theory gives no number, so the bound is measured: on these meshes 18 and 13
//!   iterations at 189 and 377 pairs with the continuation, 18 and 28 without (on the
//!   benchmark's meshes 9, 10, 12, 15, 18 at 189 to 3,001 pairs against 9, 19, 35, 31, 98;
//!   docs/benchmarks.md, "Iterations against pairs"). The test asserts that doubling the pairs
//!   adds at most 2 iterations, and that the plain method, whose stick–slip fronts move about one
//!   pair per iteration, needs at least 5 more at 377 pairs (so the test sees the difference).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericReport, load_scene, solve_generic};

fn run(mesh: &str, continuation: &str) -> GenericReport {
    run_scene("scenes/generic/pad_on_base.toml", mesh, continuation, &[])
}

fn run_scene(path: &str, mesh: &str, continuation: &str, extra: &[&str]) -> GenericReport {
    let mut overrides =
        vec![format!("mesh=\"../../meshes/generic/{mesh}\""), format!("solver.stick_continuation=\"{continuation}\"")];
    overrides.extend(extra.iter().map(|s| s.to_string()));
    let scene = load_scene(Path::new(path), &overrides).unwrap();
    let report = solve_generic(&scene, &mut |_, _| {}).unwrap().report;
    assert_eq!(report.status, "converged", "{mesh}, continuation {continuation}");
    report
}

/// The largest difference of two profiles relative to the largest value of the first.
fn profile_gap(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

#[test]
fn iterations_do_not_grow_with_the_pairs_and_the_answer_is_the_plain_active_sets() {
    let coarse = run("pad_on_base_thin_032.msh", "auto");
    let fine = run("pad_on_base_thin_016.msh", "auto");
    let plain = run("pad_on_base_thin_016.msh", "off");
    assert_eq!((coarse.pairs, fine.pairs), (189, 377));
    println!(
        "iterations: {} (189 pairs), {} (377 pairs), plain {}",
        coarse.iterations, fine.iterations, plain.iterations
    );
    assert!(fine.iterations <= coarse.iterations + 2, "{} then {}", coarse.iterations, fine.iterations);
    assert!(plain.iterations >= fine.iterations + 5, "plain {} against {}", plain.iterations, fine.iterations);

    let (a, b) = (&fine.contacts["joint"], &plain.contacts["joint"]);
    let (pa, pb) = (a.profile.as_ref().unwrap(), b.profile.as_ref().unwrap());
    assert!(profile_gap(&pa.pressure, &pb.pressure) <= 1e-10);
    assert!(profile_gap(&pa.shear, &pb.shear) <= 1e-10);
    assert_eq!(pa.state, pb.state);
    assert!((a.normal_force - b.normal_force).abs() <= 1e-10 * b.normal_force);

    // Equilibrium: the pad is held by its top and the interface alone.
    let top = fine.reactions["pad_top"][1].unwrap();
    assert!((a.normal_force + top).abs() <= 1e-9 * a.normal_force, "{} against {top}", a.normal_force);
    // Stick–slip fronts inside the interface: both zones exist, as the layout intends.
    assert!(a.stick_length > 0.5 && a.stick_length < 0.95 * a.contact_length);
}

/// The pad with its top free sideways (scenes/generic/pad_on_base_floating.toml): the pad floats
/// horizontally and friction alone holds it, so each step is a Newton iteration on its rigid
/// motion around inner active-set solves (crates/contact/src/floating.rs). From 300 pairs the
/// inner solves after a Newton step that moves pins carrying more than 1e-3 of the force scale
/// run the stick continuation from their guess, and the final leg's rigid motion is predicted
/// from the landing leg's. Truths:
/// * the plain iteration (`"off"`): the same states, and the same pressure and shear profiles to
///   1e-10 of the largest pressure. Both end on the exact law's state; what differs is the pad's
///   rigid motion, balanced by the outer Newton iteration to its floor (both runs with
///   `solver.floating_tolerance = 1e-14`: the iteration stops where no step lowers the pins'
///   force, at 1e-8 of the force scale or below, floating.rs). With the default 1e-10 the
///   profiles differ by 3e-10 of the largest pressure, with 1e-14 by 6e-11 (pressure) and 2.9e-10
///   of the largest shear, which is μ = 0.2 times smaller: 6e-11 of the largest pressure. The
///   shear is therefore compared at the pressure's scale, the interface's traction scale;
/// * equilibrium of the pad, which nothing holds sideways but the interface: the interface's
///   tangential force vanishes, to 1e-9 of the normal force (round-off of ~400 pair forces and
///   the floating tolerance);
/// * the count: on these meshes 43 iterations with the warm starts against 266 plain at 377
///   pairs (144 for both at 189 pairs, where neither applies; on the benchmark's meshes 57, 43,
///   64, 56 at 189 to 1,501 pairs against 57, 85, 154, 270; docs/benchmarks.md, "Floating bodies
///   on long interfaces"). The test asserts the plain count is at least 4 times the other, so it
///   sees the difference.
#[test]
fn a_pad_held_sideways_by_friction_alone_gets_the_plain_answer_in_fewer_iterations() {
    const FLOATING: &str = "scenes/generic/pad_on_base_floating.toml";
    let tight = ["solver.floating_tolerance=1e-14"];
    let warm = run_scene(FLOATING, "pad_on_base_thin_016.msh", "auto", &tight);
    let plain = run_scene(FLOATING, "pad_on_base_thin_016.msh", "off", &tight);
    assert_eq!(warm.pairs, 377);
    println!("iterations at 377 pairs: {} warm, {} plain", warm.iterations, plain.iterations);
    assert!(plain.iterations >= 4 * warm.iterations, "plain {} against {}", plain.iterations, warm.iterations);

    let (a, b) = (&warm.contacts["joint"], &plain.contacts["joint"]);
    let (pa, pb) = (a.profile.as_ref().unwrap(), b.profile.as_ref().unwrap());
    let traction = pb.pressure.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let largest_gap = |x: &[f64], y: &[f64]| x.iter().zip(y).fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
    assert!(largest_gap(&pa.pressure, &pb.pressure) <= 1e-10 * traction);
    assert!(largest_gap(&pa.shear, &pb.shear) <= 1e-10 * traction);
    assert_eq!(pa.state, pb.state);
    assert!((a.normal_force - b.normal_force).abs() <= 1e-10 * b.normal_force);
    for report in [&warm, &plain] {
        let joint = &report.contacts["joint"];
        assert!(joint.tangential_force.abs() <= 1e-9 * joint.normal_force, "{}", joint.tangential_force);
        // Stick–slip fronts inside the interface, and the pad's top free sideways.
        assert!(joint.stick_length > 0.5 && joint.stick_length < 0.95 * joint.contact_length);
        assert!(report.reactions["pad_top"][0].is_none());
    }
}

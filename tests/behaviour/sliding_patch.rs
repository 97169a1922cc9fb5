//! The sliding patch test of finite sliding (issue 23 item 2): an elastic block pressed onto a
//! long rigid flat base, then its top driven 1.5 along the base (15 block cells, 30 steps of
//! half a cell), the pairs formed again on the current configuration inside every step until they hold.
//!
//! ```text
//!                 p = 10 (press), u1 = 1.5 (slide)
//!             8 ------ 7                     block [0, 1] × [0, 0.5], E = 1000, ν = 0
//!  -μp ↓  (8) |        | (6) ↑ +μp           side tractions of the uniform stress
//!             5 ------ 6                     block_bottom (paired nodes, 10 Quad9 cells)
//!   4 ---------------------------------- 3   base_top: rigid, [-0.5, 3.5]; 40 cells (matching)
//!   1 ---------------------------------- 2   or 29 (non-matching)
//! ```
//!
//! Truth (closed form): once the whole interface slips, the state is the uniform stress
//! σ = [[0, μp], [μp, −p]] — it meets the top's pressure, the sides' tractions (0, ±μp), Coulomb
//! on the bottom (|τ| = μ p) and, with ν = 0 (ε_xx = 0), the top's uniform prescribed u1. So:
//! pressure p at every paired node, tangential force μP = 0.3 · 10 · 1 = 3, stored energy
//! ½ (p²/E + (μp)²/G) · A = ½ (0.1 + 0.018) · 0.5 = 0.0295, and every step's external work
//! equals the step's dissipation (the energy balance W = E + D step by step). The
//! discretisation reproduces a uniform stress exactly (patch test), so the tolerances are
//! round-off: 1e-6 as the issue asks for force and pressure (1e-12 measured), 1e-9 relative for
//! the per-step energy balance (1e-10 measured: sums over ~400 DOFs of values of order one).
//! Against a rigid flat the block's rows do not depend on where its nodes land on the base's
//! segments, so the non-matching mesh gives the same numbers (measured: the same, no jump as
//! nodes cross segment ends); the elastic-base case is crates/contact/tests/integration/finite_sliding.rs.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, load_scene, solve_generic};

const P: f64 = 10.0;
const MU: f64 = 0.3;
/// The closed-form stored energy of the uniform sliding state (module docs).
const STORED: f64 = 0.0295;
/// The first step at which the whole interface slips from its start (steps 1–2 press, step 3
/// is the first push, at whose start the block still sticks).
const FIRST_STEADY: usize = 4;

fn solve(path: &str, overrides: &[String]) -> GenericOutcome {
    let mut scene = load_scene(Path::new(path), overrides).unwrap();
    scene.every_profile = true;
    solve_generic(&scene, &mut |_, _| {}).unwrap()
}

fn check_patch(path: &str, overrides: &[String]) {
    let out = solve(path, overrides);
    assert_eq!(out.report.status, "converged", "{path}");
    let steps = &out.report.steps.to_vec();
    assert_eq!(steps.len(), 32, "{path}");
    for (i, step) in steps.iter().enumerate().skip(FIRST_STEADY - 1) {
        let c = &step.contacts["slide"];
        let profile = c.profile.as_ref().unwrap();
        assert!(profile.state.iter().all(|s| s.starts_with("slip")), "{path} step {}: {:?}", i + 1, profile.state);
        assert!((c.normal_force - P).abs() <= 1e-6 * P, "{path} step {}: P = {}", i + 1, c.normal_force);
        let t = c.tangential_force.abs();
        assert!((t - MU * P).abs() <= 1e-6 * MU * P, "{path} step {}: T = {t}, μP = {}", i + 1, MU * P);
        for (k, p) in profile.pressure.iter().enumerate() {
            assert!((p - P).abs() <= 1e-6 * P, "{path} step {} pair {k}: p = {p}", i + 1);
        }
        assert!((c.contact_length - 1.0).abs() <= 1e-9, "{path} step {}: length {}", i + 1, c.contact_length);
        let stored: f64 = step.energies.values().sum();
        assert!((stored - STORED).abs() <= 1e-6 * STORED, "{path} step {}: E = {stored}", i + 1);
        let before = &steps[i - 1];
        let work = step.work - before.work;
        let dissipated = step.dissipated - before.dissipated;
        let stored_change = stored - before.energies.values().sum::<f64>();
        let balance = work - stored_change - dissipated;
        assert!(balance.abs() <= 1e-9 * work.abs(), "{path} step {}: ΔW − ΔE − ΔD = {balance} (ΔW = {work})", i + 1);
    }
    // The pairs follow the block: the last step's pairs were formed on its own answer (finite
    // sliding re-pairs inside the step until the pairs hold; a uniform patch's answer does not
    // change from one re-pairing to the next beyond round-off), each right under its node, all
    // on the final overlap [1.5, 2.5] less the shear γh = 2μp h / E = 0.003, none on the
    // initial one [0, 1].
    let last = &out.history.steps[out.history.steps.len() - 1];
    let u = &last.solution.displacement;
    for (k, pair) in out.built.problem.pairs.iter().enumerate() {
        let x = out.built.problem.model.mesh.points[pair.master.0][0] + u[2 * pair.master.0];
        assert!(
            (pair.slave_point[0] - x).abs() <= 1e-9,
            "{path} pair {k}: node at {x}, pair at {:?}",
            pair.slave_point
        );
        assert!((1.5 - 1e-2..=2.5).contains(&pair.slave_point[0]), "{path} pair {k}: {:?}", pair.slave_point);
    }
    assert!(!out.report.notes.iter().any(|n| n.contains("sliding beyond small sliding")), "{:?}", out.report.notes);
}

#[test]
fn sliding_patch_on_matching_meshes_keeps_mu_p_and_a_uniform_pressure() {
    check_patch("scenes/generic/sliding_patch_matching.toml", &[]);
}

#[test]
fn sliding_patch_with_the_augmented_lagrangian_keeps_mu_p_and_a_uniform_pressure() {
    check_patch("scenes/generic/sliding_patch_matching.toml", &["solver.algorithm=augmented_lagrangian".into()]);
}

#[test]
fn sliding_patch_on_non_matching_meshes_keeps_mu_p_and_a_uniform_pressure() {
    check_patch("scenes/generic/sliding_patch_nonmatching.toml", &[]);
}

#[test]
fn small_sliding_of_the_same_scene_leaves_its_pairs_behind_and_says_so() {
    let scene =
        load_scene(Path::new("scenes/generic/sliding_patch_matching.toml"), &["contact.0.sliding=small".into()]);
    let out = solve_generic(&scene.unwrap(), &mut |_, _| {}).unwrap();
    assert!(out.report.notes.iter().any(|n| n.contains("sliding beyond small sliding")), "{:?}", out.report.notes);
}

#[test]
fn sliding_patch_with_clarabel_keeps_mu_p_and_a_uniform_pressure() {
    // Clarabel, the independent check, runs finite sliding too (its QPs are built on each
    // solve's pairs).
    check_patch("scenes/generic/sliding_patch_matching.toml", &["solver.algorithm=clarabel".into()]);
}

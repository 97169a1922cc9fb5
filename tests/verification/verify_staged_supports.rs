//! Staged supports (`[[fix]] from_step`, `until_step`) on the Lamé interference fit
//! (`scenes/generic/interference_fit.toml`: a disk a = 500 mm shrunk into a ring b = 1000 mm,
//! E = 2e5 MPa, ν = 0.3, plane stress, radial interference δ = 0.6667 mm; quarter model).
//!
//! ```text
//!   y │‾‾‾‾╲  ring_outer (r = b): the rim clamp, u1 = u2 = 0
//!     │disk ╲  ╲
//!     │______|__|__ x        u1 = 0 on x = 0 (sym_x), u2 = 0 on y = 0 (sym_y)
//! ```
//!
//! Closed forms (thick-walled cylinders, plane stress, Timoshenko & Goodier §30):
//! * free rim (Lamé): `p = E δ (b² − a²) / (2 a b²)` = 100.0 MPa;
//! * rim clamped from the start (`u_r(b) = 0`; ring `u = A (r − b²/r)`, disk `u = −p a (1 − ν)/E`
//!   at its rim): `δ = p/E [(1 − ν²)(b² − a²) / (a ((1 + ν) + (1 − ν) b²/a²)) + a (1 − ν)]`,
//!   p = 195.3 MPa.
//!
//! Staging: the fit in step 1, the clamp from step 2 on at the position the rim reached. In
//! linear elasticity with the total formulation the clamp then carries no force and the fit
//! pressure stays Lamé's; clamped from step 1 it is the clamped closed form; released after step
//! 1 the answer is the free rim's, which a second, independent solve without the clamp gives.
//!
//! Tolerances: 0.5 % against the closed forms, as `verify_lame_interference_fit.rs` (Quad9 on
//! 12 radial cells resolves the ring's 1/r² field to ~1e-4; node-to-node pairs on coincident
//! arcs). Against another solve of the same linear system: 1e-9 relative (round-off of two
//! factorisations of different DOF maps, ~1e-12, with margin).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic};

const BASE: &str = "scenes/generic/interference_fit.toml";
const A: f64 = 500.0;
const B: f64 = 1000.0;
const E: f64 = 2e5;
const NU: f64 = 0.3;
const DELTA: f64 = 0.6667;

fn lame_pressure() -> f64 {
    E * DELTA * (B * B - A * A) / (2.0 * A * B * B)
}

fn clamped_rim_pressure() -> f64 {
    let ring = (1.0 - NU * NU) * (B * B - A * A) / (A * ((1.0 + NU) + (1.0 - NU) * B * B / (A * A)));
    E * DELTA / (ring + A * (1.0 - NU))
}

/// The interference fit with `extra` appended to its scene file.
fn scene_with(extra: &str) -> GenericScene {
    let text = std::fs::read_to_string(BASE).unwrap() + extra;
    GenericScene::from_toml_str(&text, Path::new(BASE), &[]).unwrap()
}

fn solve(scene: &GenericScene) -> GenericOutcome {
    let out = solve_generic(scene, &mut |_, _| {}).unwrap();
    assert_eq!(out.report.status, "converged", "{:?}", out.report.failed_check);
    out
}

/// The fit's pressure at every pair of step `i` (from 0), from its normal forces.
fn pressures(out: &GenericOutcome, i: usize) -> Vec<f64> {
    let s = &out.history.steps[i].solution;
    let problem = &out.built.problem;
    (0..problem.num_pairs()).map(|k| s.normal_force[k] / problem.pairs[k].weight).collect()
}

fn clamp(from_until: &str) -> String {
    format!("\n[[fix]]\ngroup = \"ring_outer\"\nu1 = 0.0\nu2 = 0.0\n{from_until}\n\n[loading]\nsteps = 2\n")
}

#[test]
fn a_clamp_added_after_the_fit_leaves_lames_pressure_and_carries_no_force() {
    let out = solve(&scene_with(&clamp("from_step = 2")));
    let p = lame_pressure();
    let (first, second) = (pressures(&out, 0), pressures(&out, 1));
    for (k, (p1, p2)) in first.iter().zip(&second).enumerate() {
        assert!((p1 / p - 1.0).abs() < 0.005, "step 1 pair {k}: {p1} against Lamé's {p}");
        assert!((p2 / p - 1.0).abs() < 0.005, "step 2 pair {k}: {p2} against Lamé's {p}");
        assert!((p2 - p1).abs() < 1e-9 * p, "pair {k}: the clamp changed the pressure {p1} → {p2}");
    }
    // The clamp's own reaction: on ring_outer's nodes that no symmetry line holds too (the two
    // end nodes share a component with sym_x / sym_y, whose reaction that part is).
    let step = &out.history.steps[1];
    let problem = &out.built.problem;
    let r = problem.reactions(&step.solution, &step.factors).unwrap();
    let mesh = &problem.model.mesh;
    let shared: Vec<usize> =
        ["sym_x", "sym_y"].iter().flat_map(|g| mesh.group_nodes(g).unwrap()).map(|n| n.0).collect();
    let mut clamp_force = [0.0f64; 2];
    for (j, d) in problem.system.dofs.constrained_dofs().iter().enumerate() {
        let node = d.0 / 2;
        if mesh.group_nodes("ring_outer").unwrap().iter().any(|n| n.0 == node) && !shared.contains(&node) {
            clamp_force[d.0 % 2] += r[j].abs();
        }
    }
    let fit_force = out.report.steps.to_vec()[1].contacts["fit"].normal_force;
    assert!(
        clamp_force[0] < 1e-9 * fit_force && clamp_force[1] < 1e-9 * fit_force,
        "the clamp carries {clamp_force:?} against the fit's {fit_force}"
    );
    // Before it holds, the clamp reports no reaction (null), after it a number.
    assert_eq!(out.report.steps.to_vec()[0].reactions["ring_outer"], [None, None]);
    assert!(out.report.steps.to_vec()[1].reactions["ring_outer"].iter().all(Option::is_some));
}

#[test]
fn a_clamp_from_the_start_changes_the_fit_pressure_to_the_clamped_closed_form() {
    let out = solve(&scene_with(&clamp("from_step = 1")));
    let (p, p_free) = (clamped_rim_pressure(), lame_pressure());
    for (k, pk) in pressures(&out, 1).iter().enumerate() {
        assert!((pk / p - 1.0).abs() < 0.005, "pair {k}: {pk} against the clamped rim's {p}");
    }
    // Staging matters: the clamp from the start raises the fit pressure by 95 %.
    assert!(p / p_free > 1.9, "{p} against {p_free}");
}

#[test]
fn a_support_released_after_step_one_gives_the_free_answer_of_a_second_solve() {
    let staged = solve(&scene_with(&clamp("until_step = 1")));
    let free = solve(&scene_with("\n[loading]\nsteps = 2\n"));
    let clamped = clamped_rim_pressure();
    for (k, pk) in pressures(&staged, 0).iter().enumerate() {
        assert!((pk / clamped - 1.0).abs() < 0.005, "step 1 pair {k}: {pk} against the clamped rim's {clamped}");
    }
    let (u, v) = (&staged.history.steps[1].solution.displacement, &free.history.steps[1].solution.displacement);
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let worst = u.iter().zip(v).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(worst < 1e-9 * scale, "released: |u − u_free| = {worst:e} of {scale:e}");
    let p = lame_pressure();
    for (k, pk) in pressures(&staged, 1).iter().enumerate() {
        assert!((pk / p - 1.0).abs() < 0.005, "step 2 pair {k}: {pk} against Lamé's {p}");
    }
    // Released, the group exerts no force of its own: null.
    assert_eq!(staged.report.steps.to_vec()[1].reactions["ring_outer"], [None, None]);
}

/// `scenes/generic/two_blocks_press_slide.toml` with the top driven sideways only from step 3
/// on: pressed in steps 1–2 with its u1 free (the upper block then floats sideways, held by
/// friction), then held where the press left it plus the slide's 0.01 × factor.
#[test]
fn a_staged_fix_adds_its_values_to_the_position_reached() {
    let path = Path::new("scenes/generic/two_blocks_press_slide.toml");
    let text =
        std::fs::read_to_string(path).unwrap().replace("pattern = \"slide\"", "pattern = \"slide\"\nfrom_step = 3");
    let scene = GenericScene::from_toml_str(&text, path, &[]).unwrap();
    let out = solve(&scene);
    let mesh = &out.built.problem.model.mesh;
    let top = mesh.group_nodes("upper_top").unwrap();
    let u = |i: usize| &out.history.steps[i].solution.displacement;
    let pressed = u(1);
    for (i, slide) in [(2, 0.25), (3, 0.5), (4, 0.75), (5, 1.0)] {
        for n in &top {
            let moved = u(i)[2 * n.0] - pressed[2 * n.0];
            // u_{K−1} + value: one rounding of the sum.
            assert!((moved - 0.01 * slide).abs() < 1e-15 + 1e-12 * pressed[2 * n.0].abs(), "step {}: {moved}", i + 1);
        }
    }
    // Equilibrium in every step: the press (−1000 along x2 at its factor) and the reactions
    // sum to zero, to 1e-9 of the press (round-off of the floating bodies' springs, which the
    // proximal iteration leaves at the floating tolerance 1e-10).
    for (i, step) in out.report.steps.iter().enumerate() {
        let press = -1000.0 * step.factors["press"];
        let [r1, r2] = step.reactions_total;
        assert!(r1.abs() < 1e-9 * 1000.0 && (r2 + press).abs() < 1e-9 * 1000.0, "step {}: {r1}, {r2}", i + 1);
    }
    assert_eq!(out.report.steps.to_vec()[1].reactions["upper_top"], [None, None]);
}

/// The streaming run (each step handed on as solved, only the last kept) reports the same as
/// the run that keeps every step, stage changes included.
#[test]
fn a_staged_run_streams_the_same_report() {
    let scene = scene_with(&clamp("until_step = 1"));
    let kept = solve(&scene);
    let mut seen = 0;
    let streamed =
        contact2d::generic::solve_generic_streaming(&scene, &mut |_, _| {}, &mut |_, _, _| seen += 1).unwrap();
    assert_eq!(seen, 2);
    assert_eq!(streamed.history.steps.len(), 1);
    let strip = |r: &contact2d::generic::GenericReport| {
        let mut v = serde_json::to_value(r).unwrap();
        v.as_object_mut().unwrap().remove("time_s");
        v
    };
    assert_eq!(strip(&streamed.report), strip(&kept.report));
}

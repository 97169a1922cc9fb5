//! Press-fit insertion with finite sliding (issue 23, "Contact that moves", item 2), through the
//! verification gallery's case (`contact2d::verify::press_fit`, `scenes/generic/press_fit.toml`,
//! `contact2d verify --cases press_fit`).
//!
//! ```text
//!            S ‿‿‿ lead-in (R = 25.01, ℓ = 1) ‿‿ M ════ rigid wall y = a − δ ════ E
//!  ┌────────────────────── plug a = 1 ──────────┐ → back face u1 = 6 in 48 steps
//!  └────────────── y = 0: symmetry ─────────────┘   E = 1000, ν = 0, μ = 0.2, δ = 0.01
//! ```
//!
//! Goal: the insertion force grows as μ p L, p = E δ / a = 10 (2 μ p L for the whole plug), once
//! the tip is L ≥ 2a past the lead-in's end (L counted in the plug's material: small strain's
//! tractions are per unit reference length). Truth (closed form, module docs of the case): with
//! ν = 0 the fully inserted part is in the state u_y = −δ y/a, σ_yy = −p, σ_xy = −μ p y/a,
//! σ_xx linear in x — compatible and quadratic, so Quad9 reproduces it exactly; what is left is
//! the ends' disturbance. Tolerances (justified in `src/verify/press_fit.rs`): the growth
//! (F − F_s)/(μ p (L − L_s)) over L − L_s ≥ a within 1 % (measured 0.11 % on L1 and L2) and the
//! pressure ≥ 1.5a from both ends within 1 % of p (measured 0.53 %, the same on L1 and L2: the
//! continuum's end effects, not the mesh's); equilibrium of the driven face against the wall to
//! 1e-9 (round-off); the energy balance per step within 1 % of the step's work, with 48 and 96
//! steps (the trapezoid rule where nodes slide over the curved lead-in: 8.0e-5 on L1 with the
//! pairs of each step's answer, 0.61 % when they were formed once at the step's start). The constant
//! entry offset F − μ p L (1.21–1.22, so F/(μ p L) = 1.12 at L = 5.22) is reported, not asserted.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{load_scene, solve_generic};
use contact2d::verify::{Level, press_fit};

#[test]
fn press_fit_case_passes_on_both_meshes() {
    let report = press_fit::run(Path::new("."), Level::Fast).unwrap();
    assert_eq!(report.checks.len(), 9);
    for check in &report.checks {
        println!("{} ({}): {:e} against {:e}", check.quantity, check.mesh, check.measured, check.reference);
    }
    for m in &report.measurements {
        println!("{} ({}): {:e}", m.quantity, m.mesh, m.value);
    }
    for check in &report.checks {
        assert!(check.passed(), "{} ({}): {} against {}", check.quantity, check.mesh, check.measured, check.reference);
    }
}

#[test]
fn the_plug_slides_over_at_least_ten_cells_and_every_paired_node_in_the_slot_slips() {
    let mut scene = load_scene(Path::new("scenes/generic/press_fit.toml"), &[]).unwrap();
    scene.every_profile = true;
    let out = solve_generic(&scene, &mut |_, _| {}).unwrap();
    assert_eq!(out.report.status, "converged");
    let run = press_fit::measure(&out).unwrap();
    let last = run.length.len() - 1;
    // L1 cells are 0.25 long: the checked range spans more than ten of them.
    assert!(run.length[last] - run.length[run.first] >= 10.0 * 0.25, "{:?}", run.length);
    // Gross sliding: once inside, every pair in contact slips forward (Coulomb's |τ| = μ p with
    // the slip's sign), which the closed form assumes.
    let row = out.report.steps.get(last).unwrap();
    let profile = row.contacts["bore"].profile.as_ref().unwrap();
    for ((p, tau), state) in profile.pressure.iter().zip(&profile.shear).zip(&profile.state) {
        if *p > 0.0 {
            assert_eq!(*state, "slip+");
            assert!((tau.abs() - 0.2 * p).abs() <= 1e-9 * p, "τ = {tau}, p = {p}");
        }
    }
    // The same force from the reaction and from the contact: F ≥ |T| (the lead-in's normal force
    // pushes back too), and the difference is of the order of the slender p ∫ i/δ |y′| dx = 0.05.
    let share = run.normal_share;
    assert!((0.0..0.2).contains(&share), "F − |T| = {share}");
}

/// The last step's insertion force (the driven face's reaction), the interface's normal force
/// Σλ and its dissipation, and each step's re-pairings.
fn forces(out: &contact2d::generic::GenericOutcome) -> ([f64; 3], Vec<usize>) {
    let last = out.report.steps.last().unwrap();
    let bore = &last.contacts["bore"];
    let repairings = out.report.steps.iter().map(|s| s.repairings.unwrap()).collect();
    ([last.reactions["plug_back"][0].unwrap(), bore.normal_force, last.dissipated], repairings)
}

#[test]
fn one_long_step_gives_the_insertion_force_of_ninety_six_and_of_the_closed_form() {
    // Goal: with the pairs formed again on each step's answer until they hold, the push of 6 in
    // one step ends in the state 96 steps of half a cell reach (finite sliding's pairs follow
    // the plug through 24 cells of travel within the step). Truths: the 96-step path (its
    // forces converge with the step: 48 steps differ from 96 by 1e-5), within 1 % as the issue
    // asks; and the closed form of the growth, μ p per unit inserted length (the case's own
    // 1 % tolerance, module docs of `press_fit`), measured between long steps.
    let solve = |set: &str| {
        let mut scene = load_scene(Path::new("scenes/generic/press_fit.toml"), &[set.to_string()]).unwrap();
        scene.every_profile = true;
        solve_generic(&scene, &mut |_, _| {}).unwrap()
    };
    let (one, one_repairings) = forces(&solve("loading.steps=1"));
    let (five, _) = forces(&solve("loading.steps=5"));
    let (many, many_repairings) = forces(&solve("loading.steps=96"));
    println!("1 step: F, Σλ, D = {one:?}, re-pairings {one_repairings:?}");
    println!("5 steps: F, Σλ, D = {five:?}");
    println!("96 steps: F, Σλ, D = {many:?}, re-pairings at most {:?}", many_repairings.iter().max());
    for (q, name) in [(0, "insertion force"), (1, "normal force")] {
        let error = one[q] / many[q] - 1.0;
        assert!(error.abs() <= 0.01, "{name}: 1 step {} against 96 steps {} ({error:+.2e})", one[q], many[q]);
    }
    // The dissipation is a path integral, Σ ∫ τ ds, which a step's trapezoid rule
    // Σ −½(τ_start + τ) Δs approximates to first order in the step; it cannot come from a step's
    // end states alone (the plug's nodes touch down on the lead-in within the step). Five steps
    // already give it within 1 % of 96.
    let error = five[2] / many[2] - 1.0;
    assert!(error.abs() <= 0.01, "dissipation: 5 steps {} against 96 steps {} ({error:+.2e})", five[2], many[2]);
    // The closed form's growth between two long steps: pushed to 4.5 (3.5 in one step), then to
    // 6 (1.5 in one step): (F − F_s)/(μ p (L − L_s)) = 1.
    let long = solve("loading.schedule=[{push = 0.16666666666666666}, {push = 0.75}, {push = 1.0}]");
    let run = press_fit::measure(&long).unwrap();
    println!("long steps: L = {:?}, F = {:?}, growth − 1 = {:+.3e}", run.length, run.force, run.growth);
    assert_eq!(run.first, 1, "the second step is the first with L ≥ 2a: {:?}", run.length);
    assert!(run.length[2] - run.length[1] >= 1.0, "the growth spans L − L_s ≥ a: {:?}", run.length);
    assert!(run.growth.abs() <= 0.01, "growth − 1 = {}", run.growth);
}

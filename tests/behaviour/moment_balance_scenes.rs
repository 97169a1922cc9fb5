//! Verification: the moments a generic run reports balance — about the origin and about any
//! other centre (`run --about x,y`), the loads' moment, the reactions' (`reaction_moment_total`)
//! and the rigid obstacles' (`contacts.<name>.rigid_moment`) sum to zero at every step.
//!
//! Citation: the equilibrium of the discrete system, T. J. R. Hughes (2000), The Finite Element
//! Method, Dover, §1.14: `K u = f + B_Nᵀ λ + B_Tᵀ τ + r`, and `K` annihilates each body's
//! infinitesimal rotation `(−(y − c_2), x − c_1)` as it does its translations, so the rotation's
//! work with both sides vanishes.
//!
//! Goal: issue "Pose the joint an engineer brings", item 5 (reaction moments, contact moments,
//! the moment centre).
//!
//! ```text
//!  about c = (0, 0) and c = (3.7 w, −2.1 h) (w, h: the mesh's extent), every step:
//!    M_loads = Σ_p factor_p Σ_a (x_a − c) × f_p,a          (from the patterns' nodal forces)
//!    M_loads + reaction_moment_total + Σ contacts.<name>.rigid_moment = 0
//!
//!  two_blocks_press_slide, each block on its own (about c = (5, −3)):
//!          P = 1000 ↓, u1 driven          upper: loads + reaction_moments.upper_top (u1 only)
//!    ┌──────────────────┐                        + the master side's (couple − moment) = 0
//!    └──────────────────┘   joint, μ = 0.3
//!    ┌──────────────────┐                 lower: contacts.joint.moment
//!    └──────────────────┘                        + reaction_moments.lower_bottom = 0
//!    ▲▲▲▲▲▲ lower_bottom fixed
//! ```
//!
//! The scenes (every step): a pin-loaded lug (a frictional pin in a bore, clearance closed), the same with a
//! rigid pin (its moment is the rigid obstacle's), two blocks pressed then slid, a cylinder on a
//! block, a block pushed up a rigid incline, a Lamé interference fit, a block sliding on a rigid
//! base. Interfaces between two bodies whose pairs join touching points carry no moment of
//! their own (a normal force acts along the line joining the pair's points; a tangential force
//! across an initial gap g would carry the couple g τ, absent here: these interfaces are
//! frictionless or touch).
//!
//! Tolerance: 1e-8 of the moment scale, the force scale (the loads' `Σ |f|` plus the contact
//! forces `Σ |λ| + |τ|`, which the reactions carry where no load is applied) times the mesh's
//! extent plus the centre's distance. The balance is exact for the discrete system up to the
//! solver's residual (a backward-stable Cholesky solve, ~1e-12 relative; the floating bodies'
//! proximal iteration stopped at 1e-10 of the load); a reaction moment at the wrong position or
//! a component counted twice is of order 1e-2 to 1 of the scale.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, load_scene, solve_generic};

fn solve(name: &str, centre: [f64; 2]) -> GenericOutcome {
    let path = format!("scenes/generic/{name}.toml");
    let mut scene = load_scene(Path::new(&path), &[]).unwrap();
    scene.moment_centre = centre;
    solve_generic(&scene, &mut |_, _| {}).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The step's loads' moment about `c`, `Σ_p factor_p Σ_a (x_a − c) × f_p,a`, and their `Σ |f|`.
fn load_moment(out: &GenericOutcome, factors: &[f64], c: [f64; 2]) -> (f64, f64) {
    let points = &out.built.problem.model.mesh.points;
    let (mut moment, mut size) = (0.0, 0.0);
    for (pattern, factor) in out.built.problem.patterns().iter().zip(factors) {
        for (d, v) in pattern.nodal.iter().enumerate() {
            let x = points[d / 2];
            let f = factor * v;
            moment += if d % 2 == 0 { -(x[1] - c[1]) * f } else { (x[0] - c[0]) * f };
            size += f.abs();
        }
    }
    (moment, size)
}

/// The mesh's extent `[w, h]`.
fn extent(out: &GenericOutcome) -> [f64; 2] {
    let [lo, hi] = out.built.problem.model.mesh.bounding_box().unwrap();
    [hi[0] - lo[0], hi[1] - lo[1]]
}

/// Checks the balance of every step of `name` about `centre` and returns the worst residual
/// relative to the moment scale.
fn check_balance(name: &str, centre: [f64; 2]) -> f64 {
    let out = solve(name, centre);
    let report = &out.report;
    assert_eq!(report.moment_centre, centre, "{name}");
    let [w, h] = extent(&out);
    let arm = w.hypot(h) + centre[0].hypot(centre[1]);
    let mut worst = 0.0f64;
    for (i, step) in report.steps.iter().enumerate() {
        let factors: Vec<f64> = out.built.problem.patterns().iter().map(|p| step.factors[&p.name]).collect();
        let (loads, load_size) = load_moment(&out, &factors, centre);
        let contact_size: f64 = step.contacts.values().map(|c| c.normal_force.abs() + c.tangential_force.abs()).sum();
        let rigid: f64 = step.contacts.values().filter_map(|c| c.rigid_moment).sum();
        let couples: f64 = step.contacts.values().filter_map(|c| c.couple).sum();
        let residual = loads + step.reaction_moment_total + rigid + couples;
        let scale = (load_size + contact_size) * arm;
        assert!(scale > 0.0, "{name} step {i}: nothing loaded");
        assert!(
            residual.abs() <= 1e-8 * scale,
            "{name} about {centre:?}, step {i}: loads {loads:e} + reactions {:e} + rigid {rigid:e} + couples \
             {couples:e} = {residual:e} (scale {scale:e})",
            step.reaction_moment_total
        );
        // The slave side's moment is the rigid obstacle's, reversed.
        for c in step.contacts.values() {
            if let Some(m) = c.rigid_moment {
                assert_eq!(c.moment, -m, "{name}");
            }
        }
        worst = worst.max(residual.abs() / scale);
    }
    worst
}

#[test]
fn the_moments_of_loads_reactions_and_rigid_obstacles_balance_about_any_centre() {
    for name in [
        "pin_lug",
        "pin_lug_rigid_pin",
        "two_blocks_press_slide",
        "cylinder_on_block",
        "incline_push",
        "interference_fit",
        "sliding_patch_matching",
    ] {
        let probe = solve(name, [0.0; 2]);
        let [w, h] = extent(&probe);
        for centre in [[0.0, 0.0], [3.7 * w, -2.1 * h]] {
            let worst = check_balance(name, centre);
            eprintln!("{name} about {centre:?}: worst residual {worst:.2e} of the scale");
        }
    }
}

/// Each block of the two blocks balances on its own: the lower one is held by `lower_bottom` and
/// receives the interface's slave-side force (`moment`); the upper one carries the press, the
/// driven top's horizontal reaction (the group prescribes u1 only: its moment is that of the u1
/// reactions) and the master side's force, whose moment is `couple − moment`. Same tolerance.
#[test]
fn each_of_two_blocks_balances_its_moments_with_the_contacts_and_its_groups() {
    let centre = [5.0, -3.0];
    let out = solve("two_blocks_press_slide", centre);
    let [w, h] = extent(&out);
    let arm = w.hypot(h) + centre[0].hypot(centre[1]);
    for (i, step) in out.report.steps.iter().enumerate() {
        let factors: Vec<f64> = out.built.problem.patterns().iter().map(|p| step.factors[&p.name]).collect();
        let (loads, load_size) = load_moment(&out, &factors, centre);
        let joint = &step.contacts["joint"];
        let scale = (load_size + joint.normal_force.abs() + joint.tangential_force.abs()) * arm;
        let lower = joint.moment + step.reaction_moments["lower_bottom"];
        assert!(lower.abs() <= 1e-8 * scale, "step {i}: lower block {lower:e} of {scale:e}");
        let master_side = joint.couple.unwrap() - joint.moment;
        let upper = loads + step.reaction_moments["upper_top"] + master_side;
        assert!(upper.abs() <= 1e-8 * scale, "step {i}: upper block {upper:e} of {scale:e}");
        // The driven top prescribes u1 only: its u2 reaction is none, its moment that of the u1
        // reactions, which is not zero once the top is driven sideways.
        assert!(step.reactions["upper_top"][1].is_none());
    }
    let last = out.report.steps.last().unwrap();
    assert!(last.reaction_moments["upper_top"].abs() > 1e-3 * last.contacts["joint"].normal_force.abs());
}

//! The step-size error of a frictional run (`path_error`) and adaptive load stepping
//! (`[loading] adaptive`), checked against the converged path: the pin in the lug
//! (`scenes/generic/pin_lug.toml`, elastic pin in a bore with 0.1 mm clearance, μ = 0.2, pushed
//! by 1,000 N) solved in 400 equal steps.
//!
//! ```text
//!        lug (fixed at its far end)
//!   ┌───────────────┐
//!   │   ╭───────╮   │      pin pushed by F = 1000 N along +y,
//!   │   │  pin  │   │      held only by the contact and the symmetry line
//!   │   ╰───────╯   │
//!   └───────────────┘
//! ```
//!
//! Coulomb friction is path-dependent and a step's answer first order in the step size, so the
//! truth for a given load is the limit of ever finer steps; 400 steps stand for it (from 40 to
//! 400 steps the tangential resultant moves by 0.8 N of 348 N, from 400 on by less, as the
//! first-order rate says: about a tenth of that).
//!
//! Checked:
//! * a frictionless run is path-independent: `path_error` is 0 without a second solve;
//! * the estimate of 4 fixed steps is the error they make against the converged path within a
//!   factor 3 either way (an estimate, by one halving, of a first-order error that is not yet
//!   clean: the stick/slip states change by whole pairs);
//! * adaptive stepping at tolerance 1e-3 from 1, 4 and 40 user steps: the user's steps are
//!   the output points, and the answer is the converged path's within the tolerance's
//!   promise — the stick length to one pair (same last sticking pair), the resultant within
//!   1e-3 of the largest contact force (1,058 N) plus the 400 steps' own error (≤ 0.1 N);
//! * a tolerance ≤ 0 is refused naming `loading.adaptive.tolerance`, and adaptive stepping with
//!   the Boussinesq algorithm's placed zone ends naming `loading.adaptive`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericReport, load_scene, solve_generic};

const PIN_LUG: &str = "scenes/generic/pin_lug.toml";

fn run(scene: &str, sets: &[&str]) -> GenericReport {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    solve_generic(&load_scene(Path::new(scene), &sets).unwrap(), &mut |_, _| {}).unwrap().report
}

/// The bore's resultant along the push and its stick length.
fn bore(report: &GenericReport) -> (f64, f64) {
    let c = report.contacts.values().next().unwrap();
    (c.resultant[1], c.stick_length)
}

#[test]
fn frictionless_runs_are_path_independent() {
    let r = run(PIN_LUG, &["contact.0.friction=0.0"]);
    assert_eq!(r.status, "converged");
    assert_eq!(r.path_error, Some(0.0));
    assert!(r.steps.iter().all(|s| s.path_error == Some(0.0)));
}

#[test]
fn the_estimate_and_adaptive_stepping_against_the_converged_path() {
    let converged = run(PIN_LUG, &["loading.steps=400", "loading.path_error=false"]);
    let (f_true, stick_true) = bore(&converged);
    let largest = converged.contacts.values().next().unwrap().resultant[0].hypot(f_true);

    // The estimate of the bundled 4 steps against their actual error.
    let four = run(PIN_LUG, &[]);
    let actual = (bore(&four).0 - f_true).abs() / largest;
    let estimate = four.path_error.unwrap();
    assert!(estimate > actual / 3.0 && estimate < 3.0 * actual, "estimate {estimate:e}, actual {actual:e}");
    assert_eq!(four.steps.len(), 4);

    // Adaptive from 1, 4 and 40 user steps.
    for user in ["1", "4", "40"] {
        let r = run(PIN_LUG, &[&format!("loading.steps={user}"), "loading.adaptive.tolerance=1e-3"]);
        assert_eq!(r.status, "converged");
        let n: usize = user.parse().unwrap();
        assert_eq!(r.steps.len(), n, "one row per user step");
        for (i, s) in r.steps.iter().enumerate() {
            let f = s.factors.values().next().unwrap();
            assert!((f - (i + 1) as f64 / n as f64).abs() < 1e-15, "output at the user's factor");
        }
        let taken: usize = r.steps.iter().map(|s| s.substeps.unwrap()).sum();
        assert_eq!(Some(taken), r.steps_taken);
        assert!(r.path_error.unwrap() <= 1e-3);
        let (f, stick) = bore(&r);
        assert!((f - f_true).abs() <= 1e-3 * largest + 0.1, "resultant {f} against {f_true}");
        // One pair of the bore's 81 on the half circle of radius 10: π·10/80 ≈ 0.39 mm.
        assert!((stick - stick_true).abs() < 0.39, "stick length {stick} against {stick_true}");
    }
}

#[test]
fn a_tolerance_that_is_not_positive_is_refused_by_its_key() {
    let e = load_scene(Path::new(PIN_LUG), &["loading.adaptive.tolerance=0.0".into()]).unwrap_err();
    assert!(e.to_string().contains("loading.adaptive.tolerance"), "{e}");
    // The Boussinesq algorithm's placed zone ends solve each step on its own mesh: refused.
    let placed = Path::new("scenes/generic/roller_on_block_placed.toml");
    let e = load_scene(placed, &["loading.adaptive.tolerance=1e-3".into()]).unwrap_err();
    assert!(e.to_string().contains("loading.adaptive"), "{e}");
}

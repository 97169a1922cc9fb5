//! Clarabel, the independent check, against the active set on every bundled generic scene
//! (`scenes/generic/*.toml`, issue 27 item 8).
//!
//! Goal: wherever the active set converges, Clarabel (`solver.algorithm = "clarabel"`: dual QPs
//! in the contact forces by an interior point, Tresca QPs to the Coulomb fixed point, the states
//! found polished exactly and certified) converges too, and every step's total normal force of
//! every contact agrees.
//!
//! Tolerance 1e-5 relative to the contact's largest total normal force over the steps. The
//! active set ends at round-off (its states' linear equations solved exactly). Clarabel's
//! interior point stops at 1e-10 on data scaled to O(1); its answer only decides the pair states,
//! and the polished answer is the exact solution of those states, certified against every
//! contact and friction condition at 1e-4 (crate contact, certify.rs). Same states give the same
//! forces to round-off (~1e-12); a wrong state that slipped through the certificate would move a
//! force by the size of its residual, up to 1e-4 — which 1e-5 catches. Floating bodies (their
//! rigid motion solved by Newton iterations to the relative floating tolerance 1e-10) add
//! differences of that order. The time of each algorithm is printed (`--nocapture`), not
//! asserted (CI machines are shared); docs/algorithms.md holds the measured table.
//!
//! Every bundled scene runs: the slowest, `long_interface` (40 steps, 193 pairs all in contact,
//! a dense QP of 386 unknowns per Tresca iteration), took 15.5 s with Clarabel and 0.6 s with the
//! active set on the development machine; the whole test about 30 s (release).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod common;

use contact2d::contact::ContactError;
use contact2d::generic::{GenericError, GenericReport, load_scene, solve_generic};

fn run(path: &std::path::Path, algorithm: &str) -> Result<(GenericReport, f64), GenericError> {
    let overrides = [format!("solver.algorithm={algorithm}")];
    let scene = load_scene(path, &overrides).unwrap();
    let clock = std::time::Instant::now();
    let outcome = solve_generic(&scene, &mut |_, _| {})?;
    Ok((outcome.report, clock.elapsed().as_secs_f64()))
}

/// Whether the scene has a contact with finite sliding, which Clarabel does not solve (its pairs
/// are formed again before every step; refused before solving, docs/user-guide.md `sliding`).
fn has_finite_sliding(path: &std::path::Path) -> bool {
    let scene = load_scene(path, &[]).unwrap();
    scene.contact.iter().any(|c| c.sliding == contact2d::generic::scene::SlidingKey::Finite)
}

#[test]
fn clarabel_converges_and_agrees_with_the_active_set_on_every_bundled_scene() {
    let scenes = common::bundled_scenes();
    assert!(scenes.len() >= 10, "the bundled generic scenes are missing");
    for path in &scenes {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let (active, t_active) = run(path, "active_set").unwrap();
        let (clarabel, t_clarabel) = match run(path, "clarabel") {
            Ok(run) => run,
            // The one refusal allowed: finite sliding, named before solving.
            Err(GenericError::Contact { source, .. })
                if has_finite_sliding(path) && matches!(*source, ContactError::NotApplicable { .. }) =>
            {
                println!("{name}: Clarabel refused before solving ({source})");
                continue;
            }
            Err(e) => panic!("{name}: Clarabel: {e}"),
        };
        println!("{name}: active set {t_active:.2} s, Clarabel {t_clarabel:.2} s");
        assert_eq!(active.status, "converged", "{name}: the active set");
        assert_eq!(clarabel.status, "converged", "{name}: Clarabel ({:?})", clarabel.failed_check);
        assert_eq!(active.steps.len(), clarabel.steps.len(), "{name}: steps");
        for contact in active.contacts.keys() {
            let scale = active.steps.iter().map(|s| s.contacts[contact].normal_force.abs()).fold(0.0f64, f64::max);
            assert!(scale > 0.0, "{name}/{contact}: no normal force in any step");
            for (i, (a, c)) in active.steps.iter().zip(&clarabel.steps).enumerate() {
                let (a, c) = (a.contacts[contact].normal_force, c.contacts[contact].normal_force);
                assert!(
                    (a - c).abs() <= 1e-5 * scale,
                    "{name}/{contact}, step {}: Clarabel {c} against the active set {a} (scale {scale})",
                    i + 1
                );
            }
        }
    }
}

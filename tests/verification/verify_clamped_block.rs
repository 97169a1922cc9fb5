//! A block clamped through a reference point, its side support released, pulled until it slips:
//! the verification gallery's case (`contact2d::verify::clamped_block`,
//! `scenes/generic/clamped_block.toml`; rigid-body statics with Coulomb's law, Meriam & Kraige,
//! *Engineering Mechanics: Statics*, §6/2).
//!
//! Goal: reference points (a distributing coupling over the block's top), a force and a moment
//! on a point, and a staged support (`until_step = 1`) give the statics of the block: every
//! converged step N = P, R1 = F + S1, the contact's moment about the point = M + m_p(S), and the
//! run ends `not_held` with the last held pull factor within one load step below μP/F(1).
//!
//! ```text
//!            M ↺  P ↓  F →     point "clamp" at (2, 2), distributing over block_top
//!   block_left ┌────●────┐     u1 = 0 in step 1 only (until_step = 1)
//!              └─────────┘     μ = 0.35
//!      ┌────────────────────┐  base, clamped below
//! ```
//!
//! Parameters: steel (E = 2e5 MPa, ν = 0.3), plane strain, P = 1000 N/mm, M = 100 N·mm/mm,
//! F = 1000 λ N/mm with λ = 0.1 … 0.5 in steps of 0.1 (λ* = 0.35), Quad4, matching 0.25 mm
//! cells along the interface.
//!
//! Tolerances (the case's module says why): forces 1e-8 relative, moments 1e-8 of P × width,
//! the last held factor the load step 0.1, the demanded friction force 1e-5 relative.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{load_scene, solve_generic};
use contact2d::verify::{Level, clamped_block};

#[test]
fn the_clamped_block_follows_statics_and_lets_go_at_mu_p() {
    let report = clamped_block::run(Path::new("."), Level::Fast).unwrap();
    // Three checks for each of the four converged steps, the last held factor, the demand.
    assert_eq!(report.checks.len(), 3 * 4 + 2, "{:?}", report.notes);
    for check in &report.checks {
        println!("{} ({}): {:e} against {:e}", check.quantity, check.mesh, check.measured, check.reference);
        assert!(check.passed(), "{} ({}): {} against {}", check.quantity, check.mesh, check.measured, check.reference);
    }
    assert!(report.notes.is_empty(), "{:?}", report.notes);
}

/// The staging is not idle: the side support carries a force while the block is clamped (the
/// moment and the base's Poisson contraction push the block sideways; the balance check of
/// step 1 includes it), reports `null` once released, and the run's last row is the step not
/// held, naming the contact and the block.
#[test]
fn the_side_support_holds_in_the_clamp_step_only() {
    let path = Path::new("scenes/generic/clamped_block.toml");
    let scene = load_scene(path, &["loading.path_error=false".into(), clamped_block::schedule_override()]).unwrap();
    let report = solve_generic(&scene, &mut |_, _| {}).unwrap().report;
    assert_eq!(report.status, "not_held", "{:?}", report.failed_check);
    let first = report.steps.to_vec()[0].reactions["block_left"][0].unwrap();
    assert!(first.abs() > 1.0, "the side support carries {first} N/mm in step 1");
    assert!(report.steps.to_vec()[1..].iter().all(|s| s.reactions["block_left"] == [None, None]));
    let not_held = report.not_held.as_ref().unwrap();
    assert_eq!((not_held.contact.as_str(), not_held.body.as_str(), not_held.step), ("joint", "block", 5));
    assert_eq!(report.steps.len(), 5);
    assert!(report.steps.to_vec()[..4].iter().all(|s| s.status == "converged"));
}

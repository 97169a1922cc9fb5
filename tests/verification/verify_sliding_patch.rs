//! The sliding patch test through the verification gallery's case
//! (`contact2d::verify::sliding_patch`, scenes `scenes/generic/sliding_patch_*.toml`): a block
//! pressed onto a long rigid flat and pushed 15 cells along it with finite sliding. Every check
//! of the case compares with the closed-form uniform sliding state (T = μP, p uniform, the
//! stored energy ½ (p²/E + (μp)²/G) A) or with the energy balance ΔW = ΔE + ΔD, to round-off
//! tolerances justified in the case's docs (1e-6; 1e-9 for the balance).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::verify::{Level, sliding_patch};

#[test]
fn sliding_patch_case_passes_on_both_meshes() {
    let report = sliding_patch::run(Path::new("."), Level::Fast).unwrap();
    assert_eq!(report.checks.len(), 8);
    for check in &report.checks {
        assert!(check.passed(), "{} ({}): {} against {}", check.quantity, check.mesh, check.measured, check.reference);
    }
    for m in &report.measurements {
        println!("{} ({}): {:e}", m.quantity, m.mesh, m.value);
    }
}

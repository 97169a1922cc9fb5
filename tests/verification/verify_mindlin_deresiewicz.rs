//! Mindlin–Deresiewicz fretting of a cylinder on a flat, through the verification gallery's
//! case (`contact2d::verify::mindlin_deresiewicz`, scene
//! `scenes/generic/cattaneo_mindlin_fretting.toml`).
//!
//! ```text
//!          cylinder_top: u2 = −0.0142 (press), u1 = ±0.0028 (shear, cycled twice)
//!              ___
//!            /     \      roller R = 50, steel          a = 0.5 ≪ R
//!   ========= ‾‾‾‾‾ =========  block_top (slave)
//!   |        block          |
//!   =========================  block_bottom fixed
//! ```
//!
//! Source: Mindlin & Deresiewicz (1953); Johnson, *Contact Mechanics* §7.1–7.2; the plane energy
//! per cycle derived in docs/theory.md. Tolerances (justified in the case's module docs): c'/a
//! within one pair spacing, the unloading shear's L2 error within 7 % of μ p0, the energy per
//! cycle within 2 % of the closed form, the largest slip amplitude within the slip's change over one
//! pair spacing at the edge, and the work of the driven top over the cycle equal to
//! the energy dissipated within 2 % (conservation, the trapezoid rule of the step rows).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::verify::{Level, mindlin_deresiewicz};

#[test]
fn reverse_slip_zones_traction_and_energy_per_cycle_follow_the_closed_form() {
    let report = mindlin_deresiewicz::run(Path::new("."), Level::Fast).unwrap();
    println!("{}", contact2d::verify::report::text_table(std::slice::from_ref(&report)));
    assert!(report.notes.is_empty(), "{:?}", report.notes);
    // 10 unloading steps × 2 checks, the energy per cycle, the work balance, the amplitude.
    assert_eq!(report.checks.len(), 23);
    for c in &report.checks {
        assert!(c.passed(), "{} at {}: {} against {}", c.quantity, c.mesh, c.measured, c.reference);
    }
}

//! Cattaneo–Mindlin partial slip through the verification gallery's case
//! (`contact2d::verify::cattaneo_mindlin`, scene `scenes/generic/cattaneo_mindlin.toml`): a steel
//! roller R = 50 mm pressed on a steel block, then sheared with the press held, μ = 0.3.
//!
//! ```text
//! c = a √(1 − Q/(μP)),   q(x) = μ p0 [√(1 − x²/a²) − (c/a) √(1 − x²/c²)]
//! ```
//! Source: Cattaneo (1938), Mindlin (1949); Johnson, *Contact Mechanics* §7.1. Tolerances (the
//! issue's targets, justified in the case's module): c/a within 2 % at Q/(μP) ≈ 0.25, 0.5, 0.75
//! and the shear profile's L2 error within 3 % of μ p0, on the finest mesh of the fast level (L2);
//! the load-step study (1, 2, 4 shear steps) must agree to 1e-3 in c/a: under monotone loading
//! the Cattaneo–Mindlin state does not depend on the path.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::verify::{Level, cattaneo_mindlin};

#[test]
fn stick_zone_and_shear_traction_match_cattaneo_mindlin() {
    let report = cattaneo_mindlin::run(Path::new("."), Level::Fast).unwrap();
    println!("{}", contact2d::verify::report::text_table(std::slice::from_ref(&report)));
    assert_eq!(report.checks.len(), 6, "three ratios, two checks each");
    for c in &report.checks {
        assert!(c.passed(), "{} on {}: {} against {}", c.quantity, c.mesh, c.measured, c.reference);
    }
    let study: Vec<f64> =
        report.measurements.iter().filter(|m| m.quantity == "step study: c/a").map(|m| m.value).collect();
    assert_eq!(study.len(), 3);
    assert!(study.iter().all(|c| (c - study[0]).abs() < 1e-3), "step study {study:?}");
}

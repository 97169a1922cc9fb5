//! The moving roller through the verification gallery's case (`contact2d::verify::moving_roller`,
//! `scenes/generic/moving_roller.toml`; Hertz, Johnson, *Contact Mechanics* (1985) §4.2).
//!
//! Goal: with `sliding = "finite"` the Hertz pressure travels with an elastic roller driven along
//! an elastic block by 16 block cells.
//!
//! ```text
//!            d (pattern "drive") →   ┌───────────┐ roller_top: u1 = d, u2 = −δ (pattern "press")
//!                                     \  roller   /  steel, R = 50 mm, lower half disc
//!                                       `-.___.-'
//!   ┌──────────────────────────────────────────────────────────┐ block_top: 96 cells h = a/32
//!   │                        block (aluminium)                  │ along the path, graded away
//!   └──────────────────────────────────────────────────────────┘ block_bottom clamped
//! ```
//!
//! Parameters: E = 210 000 / 70 000 MPa, ν = 0.3, plane strain, μ = 0, δ = 0.34 mm in four steps
//! (F ≈ 7 570 N/mm, a ≈ 3.0 mm, a/R = 0.06, p0 ≈ 1 600 MPa), then 32 moves of h/2, one step
//! each (the step's pairs are formed again on its answer until they hold; no settle step),
//! segment-to-segment pairs.
//!
//! Asserted at every step after the press, against the closed form at the step's measured force F: the
//! half-width a within 1 % and the pressure at the roller's lowest node within 1.5 % (the
//! gallery's Hertz tolerances, `src/verify/hertz.rs`, asserted there on a mesh of the same
//! resolution, 32 cells across a); the pressure centre within h/10 of the driven top's
//! displacement (no lag: each step's pairs are those of its answer); and at every step from the
//! end of the press the energy W = E + D (D = 0 frictionless) within 1 % of E (the trapezoid rule
//! of the displacement-driven press, 0.5 % of E; the case's docs give it).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::verify::{Level, moving_roller};

#[test]
fn the_hertz_pressure_travels_with_the_roller() {
    let report = moving_roller::run(Path::new("."), Level::Fast).unwrap();
    assert_eq!(report.checks.len(), 4);
    for m in &report.measurements {
        println!("{} ({}): {:e}", m.quantity, m.mesh, m.value);
    }
    for check in &report.checks {
        println!("{} ({}): {:e}", check.quantity, check.mesh, check.measured);
        assert!(check.passed(), "{} ({}): {} against {}", check.quantity, check.mesh, check.measured, check.reference);
    }
}

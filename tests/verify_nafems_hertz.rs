//! NAFEMS 2D Hertz contact benchmark (cylindrical roller on a block), as Code_Aster documents
//! it (SSNP154), through the generic scene `scenes/generic/cylinder_on_block.toml`.
//!
//! ```text
//!        F/2 = 17 500 N/mm on cylinder_top (half model, x ≥ 0)
//!      ┌────┐   roller R = 50 mm, E = 210 000 MPa, ν = 0.3 — held only by the contact and
//!      │    ╲   the symmetry line (u1 = 0 on "axis")
//!      ╰─────╯
//!   ────────────── block E = 70 000 MPa, ν = 0.3, W = H = 100 mm (half), bottom clamped
//! ```
//!
//! Closed form (plane strain, half-spaces): E* = [(1−ν1²)/E1 + (1−ν2²)/E2]⁻¹,
//! a = √(4FR/(πE*)) = 6.21 mm, p0 = 2F/(πa) = 3585 MPa, p(x) = p0 √(1 − x²/a²).
//!
//! Tolerances (the issue's targets at the finest bundled mesh, L3): a within 1 %, p0 (the
//! pressure at the centre x = 0) within 1.5 % (Code_Aster's published model is 1.2 % low). The block is finite, so the half-space
//! closed form holds only to the block's size effect: the block twice as large (L2 mesh of the
//! same contact refinement) must change a and p0 by less than 1 %. The pressure profile of the
//! node-to-segment pairing on quadratic edges oscillates between corner and mid nodes (with the
//! roller as master the largest nodal pressure on L3 is 24 % above p0); the profile's L2 error
//! and the largest nodal pressure are measured and printed here, not asserted (issue 11 item 4
//! brings the pairing whose profile converges).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{load_scene, solve_generic};

const F: f64 = 35_000.0;
const R: f64 = 50.0;

fn closed_form() -> (f64, f64) {
    let e_star = 1.0 / ((1.0 - 0.09) / 210_000.0 + (1.0 - 0.09) / 70_000.0);
    let a = (4.0 * F * R / (std::f64::consts::PI * e_star)).sqrt();
    (a, 2.0 * F / (std::f64::consts::PI * a))
}

/// (a, p0 = the pressure at the centre x = 0, L2 error of the profile relative to p0, the
/// largest nodal pressure) on `mesh`.
fn measure(mesh: &str) -> (f64, f64, f64, f64) {
    let scene = load_scene(
        Path::new("scenes/generic/cylinder_on_block.toml"),
        &[format!("mesh=\"../../meshes/generic/{mesh}\"")],
    )
    .unwrap();
    let out = solve_generic(&scene, &mut |_, _| {}).unwrap();
    assert_eq!(out.report.status, "converged", "{mesh}");
    let hertz = &out.report.contacts["hertz"];
    let (a, p0) = closed_form();
    let profile = hertz.profile.as_ref().unwrap();
    // L2 over [0, a] by the trapezoid rule on the master nodes' x.
    let (mut err, mut norm) = (0.0, 0.0);
    let pts: Vec<(f64, f64)> =
        profile.x.iter().zip(&profile.pressure).filter(|(x, _)| **x <= a).map(|(x, p)| (*x, *p)).collect();
    for w in pts.windows(2) {
        let exact = |x: f64| p0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt();
        let dx = w[1].0 - w[0].0;
        err += 0.5 * dx * ((w[0].1 - exact(w[0].0)).powi(2) + (w[1].1 - exact(w[1].0)).powi(2));
        norm += dx;
    }
    let centre = profile.x.iter().zip(&profile.pressure).min_by(|a, b| a.0.abs().total_cmp(&b.0.abs())).unwrap();
    (hertz.contact_length, *centre.1, (err / norm.max(f64::MIN_POSITIVE)).sqrt() / p0, hertz.max_pressure)
}

#[test]
fn nafems_hertz_half_width_and_peak_pressure() {
    let (a, p0) = closed_form();
    assert!((a - 6.21).abs() < 0.005 && (p0 - 3585.0).abs() < 2.0, "closed form a = {a}, p0 = {p0}");
    let mut finest = (0.0, 0.0);
    for level in ["L1", "L2", "L3"] {
        let (a_h, p_h, l2, p_max) = measure(&format!("cylinder_on_block_{level}.msh"));
        println!(
            "{level}: a = {a_h:.4} ({:+.2} %), p(0) = {p_h:.1} ({:+.2} %), profile L2 error {:.1} % of p0, \
             largest nodal pressure {p_max:.1} ({:+.2} %)",
            100.0 * (a_h / a - 1.0),
            100.0 * (p_h / p0 - 1.0),
            100.0 * l2,
            100.0 * (p_max / p0 - 1.0)
        );
        finest = (a_h, p_h);
    }
    assert!((finest.0 / a - 1.0).abs() < 0.01, "a at L3: {} against {a}", finest.0);
    assert!((finest.1 / p0 - 1.0).abs() < 0.015, "p0 at L3: {} against {p0}", finest.1);
    let (a2, p2, _, _) = measure("cylinder_on_block_L2.msh");
    let (a_big, p_big, _, _) = measure("cylinder_on_block_big_L2.msh");
    assert!(
        (a_big / a2 - 1.0).abs() < 0.01 && (p_big / p2 - 1.0).abs() < 0.01,
        "block size: a {a2} → {a_big}, p0 {p2} → {p_big}"
    );
}

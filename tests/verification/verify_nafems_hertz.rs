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
//! pressure at the centre x = 0) within 1.5 % (Code_Aster's published model is 1.2 % low), for
//! both pairings; the profile's L2 error ≤ 2 % of p0 for the segment-to-segment pairing. The
//! block is finite, so the half-space closed form holds only to the block's size effect: the
//! block twice as large (L2 mesh of the same contact refinement) must change a and p0 by less
//! than 1 %. The profile error is the L2 norm over the whole master curve of p_h − p, p_h the
//! piecewise-linear interpolant of the nodal pressures (the segment-to-segment pressure field on
//! Line3 edges), relative to p0 √a. The node-to-segment pressure on quadratic edges oscillates
//! between corner and mid nodes (with the roller as master the largest nodal pressure on L3 is
//! 24 % above p0, the profile error 9 %): measured and printed, not asserted. The rates between
//! levels are printed, not asserted: the segment-to-segment error is that of the cell holding
//! the contact edge, where p ~ √(a − x), O(h/a) in L2 with a constant that depends on where a
//! falls between nodes, and in the interior the block's size effect (0.09 %) dominates
//! (docs/verification.md).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::scene::PairingKey;
use contact2d::generic::{load_scene, solve_generic};

const F: f64 = 35_000.0;
const R: f64 = 50.0;

fn closed_form() -> (f64, f64) {
    let e_star = 1.0 / ((1.0 - 0.09) / 210_000.0 + (1.0 - 0.09) / 70_000.0);
    let a = (4.0 * F * R / (std::f64::consts::PI * e_star)).sqrt();
    (a, 2.0 * F / (std::f64::consts::PI * a))
}

/// What one solve measured.
struct Measured {
    /// Contact half-width.
    a: f64,
    /// The pressure at the centre x = 0.
    p0: f64,
    /// L2 error of the profile over the whole master curve, relative to p0 √a.
    l2: f64,
    /// The same over the interior x ≤ 0.8 a, relative to p0 √(0.8 a).
    l2_interior: f64,
    /// The largest nodal pressure.
    p_max: f64,
}

/// Solves the scene on `mesh` with `pairing` and measures it.
fn measure(mesh: &str, pairing: PairingKey) -> Measured {
    let mut scene = load_scene(
        Path::new("scenes/generic/cylinder_on_block.toml"),
        &[format!("mesh=\"../../meshes/generic/{mesh}\"")],
    )
    .unwrap();
    scene.contact[0].pairing = pairing;
    let out = solve_generic(&scene, &mut |_, _| {}).unwrap();
    assert_eq!(out.report.status, "converged", "{mesh}");
    let hertz = &out.report.contacts["hertz"];
    let (a, p0) = closed_form();
    let profile = hertz.profile.as_ref().unwrap();
    // L2 norm of p_h − p, p_h the piecewise-linear interpolant of the nodal pressures along x
    // (for segment-to-segment on these Line3 edges exactly its pressure field, see
    // contact2d_contact::segment_to_segment), by 64 midpoint samples per node interval.
    let exact = |x: f64| p0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt();
    let (mut err, mut interior) = (0.0, 0.0);
    for i in 0..profile.x.len().saturating_sub(1) {
        let (x0, x1) = (profile.x[i], profile.x[i + 1]);
        let (q0, q1) = (profile.pressure[i], profile.pressure[i + 1]);
        for j in 0..64 {
            let t = (j as f64 + 0.5) / 64.0;
            let x = x0 + t * (x1 - x0);
            let e = (x1 - x0).abs() / 64.0 * (q0 + t * (q1 - q0) - exact(x)).powi(2);
            err += e;
            if x <= 0.8 * a {
                interior += e;
            }
        }
    }
    let centre = profile.x.iter().zip(&profile.pressure).min_by(|a, b| a.0.abs().total_cmp(&b.0.abs())).unwrap();
    Measured {
        a: hertz.contact_length,
        p0: *centre.1,
        l2: (err / a).sqrt() / p0,
        l2_interior: (interior / (0.8 * a)).sqrt() / p0,
        p_max: hertz.max_pressure,
    }
}

#[test]
fn nafems_hertz_half_width_and_peak_pressure() {
    let (a, p0) = closed_form();
    assert!((a - 6.21).abs() < 0.005 && (p0 - 3585.0).abs() < 2.0, "closed form a = {a}, p0 = {p0}");
    let mut finest = vec![];
    for pairing in [PairingKey::NodeToSegment, PairingKey::SegmentToSegment] {
        let mut previous: Option<Measured> = None;
        for level in ["L1", "L2", "L3"] {
            let m = measure(&format!("cylinder_on_block_{level}.msh"), pairing);
            let rate = |e: f64, f: fn(&Measured) -> f64| {
                previous.as_ref().map(|p| format!(" (rate {:.2})", (f(p) / e).log2())).unwrap_or_default()
            };
            println!(
                "{pairing:?} {level}: a = {:.4} ({:+.2} %), p(0) = {:.1} ({:+.2} %), profile L2 error {:.2} % of p0{}, \
                 interior (x ≤ 0.8a) {:.3} %{}, largest nodal pressure {:.1} ({:+.2} %)",
                m.a,
                100.0 * (m.a / a - 1.0),
                m.p0,
                100.0 * (m.p0 / p0 - 1.0),
                100.0 * m.l2,
                rate(m.l2, |p| p.l2),
                100.0 * m.l2_interior,
                rate(m.l2_interior, |p| p.l2_interior),
                m.p_max,
                100.0 * (m.p_max / p0 - 1.0)
            );
            previous = Some(m);
        }
        finest.push((pairing, previous.unwrap()));
    }
    for (pairing, m) in &finest {
        assert!((m.a / a - 1.0).abs() < 0.01, "{pairing:?}: a at L3: {} against {a}", m.a);
        assert!((m.p0 / p0 - 1.0).abs() < 0.015, "{pairing:?}: p0 at L3: {} against {p0}", m.p0);
    }
    // The issue's profile target, met by the segment-to-segment pairing only.
    let (_, mortar) = &finest[1];
    assert!(mortar.l2 <= 0.02, "segment-to-segment profile L2 error at L3: {:.2} % of p0", 100.0 * mortar.l2);
    // The block size effect, with the scene's default (automatic: segment-to-segment here).
    let m2 = measure("cylinder_on_block_L2.msh", PairingKey::Automatic);
    let big = measure("cylinder_on_block_big_L2.msh", PairingKey::Automatic);
    println!(
        "block size (L2, automatic pairing): a {:.4} → {:.4} ({:+.2} %), p(0) {:.1} → {:.1} ({:+.2} %)",
        m2.a,
        big.a,
        100.0 * (big.a / m2.a - 1.0),
        m2.p0,
        big.p0,
        100.0 * (big.p0 / m2.p0 - 1.0)
    );
    assert!(
        (big.a / m2.a - 1.0).abs() < 0.01 && (big.p0 / m2.p0 - 1.0).abs() < 0.01,
        "block size: a {} → {}, p0 {} → {}",
        m2.a,
        big.a,
        m2.p0,
        big.p0
    );
}

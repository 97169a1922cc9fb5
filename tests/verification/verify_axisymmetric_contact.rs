//! Verification: the two contact closed forms of bodies of revolution (issue 43, item 4), each
//! on two mesh levels of every element type (T3 T6 Q4 Q8 Q9): Hertz's sphere on a flat
//! (`scenes/generic/hertz_sphere_axisymmetric.toml`) and Boussinesq's rigid flat punch on a
//! half-space (`scenes/generic/punch_axisymmetric.toml`).
//!
//! Citation: H. Hertz (1882), Über die Berührung fester elastischer Körper; J. Boussinesq (1885),
//! Application des potentiels; K. L. Johnson (1985), Contact Mechanics, §3.8 (the flat punch) and
//! §4.2 (the sphere); I. N. Sneddon (1946), Boussinesq's problem for a flat-ended cylinder.
//!
//! Set-up and closed forms (the `verify` cases `hertz_sphere_axisymmetric`, `punch_axisymmetric`,
//! src/verify/, whose checks these tests assert):
//!
//! ```text
//! sphere:  R = 10, P = 8000 (total), E1 = 210 000, E2 = 70 000, ν = 0.3, block 40 × 40 (≈ 40a)
//!          a = (3PR/(4E*))^⅓ = 1.0132,  p0 = 3P/(2πa²) = 3721.1,  p = p0 √(1 − r²/a²)
//! punch:   a = 1, δ = 0.001, E = 200 000, ν = 0.3, rigid punch, block 50a × 50a
//!          P = 2aEδ/(1 − ν²) = 439.56,  p = P/(2πa√(a² − r²))
//! ```
//!
//! Tolerances (justified in the two modules' docs):
//! * sphere: h/a on a, on p0 (the r-weighed least-squares amplitude over r < 0.8a) and on the
//!   profile's r-weighed RMS error over r < 0.8a relative to p0, h the master nodes' spacing at the
//!   contact (a/12 on L1, a/24 on L2): the discrete zone ends between two nodes; the finite block's
//!   first-order effect is a rigid shift (a 4× larger block: 0.02 % on a);
//! * punch: 1.09a/L + h/a on P and on the profile's RMS error over 0 < r ≤ 0.7a relative to
//!   p(0): Boussinesq's point-force bound on the compliance the held bottom removes (2.2 % at
//!   L = 50a; measured 1.3 %) plus the energy error O(h/a) of the edge's ρ^½ singularity, h the
//!   cell size at the edge.
//!
//! Measured (docs/verification.md): sphere a within 3.4 % (L1) and 1.6 % (L2), p0 within 0.6 % and
//! 0.11 %; punch P +0.1 … +3.4 % (L1), +1.4 … +2.0 % (L2).

use std::path::Path;

use contact2d::verify::{CaseReport, Level, hertz_sphere_axisymmetric, punch_axisymmetric};

fn assert_passes(report: &CaseReport) {
    for c in &report.checks {
        eprintln!(
            "{} {} {}: {} against {} (error {:.3e})",
            report.name,
            c.mesh,
            c.quantity,
            c.measured,
            c.reference,
            c.error()
        );
        assert!(
            c.passed(),
            "{} {}: {} = {} against {} ({:?})",
            report.name,
            c.mesh,
            c.quantity,
            c.measured,
            c.reference,
            c.tolerance
        );
    }
}

#[test]
fn hertzs_sphere_on_a_flat_gives_a_p0_and_the_profile_with_every_element_on_two_levels() {
    let report = hertz_sphere_axisymmetric::run(Path::new("."), Level::Fast).unwrap();
    // 5 element types × 2 levels × (a, p0, profile)
    assert_eq!(report.checks.len(), 30);
    assert_passes(&report);
}

#[test]
fn boussinesqs_flat_punch_gives_the_force_and_the_profile_with_every_element_on_two_levels() {
    let report = punch_axisymmetric::run(Path::new("."), Level::Fast).unwrap();
    // 5 element types × 2 levels × (P, profile)
    assert_eq!(report.checks.len(), 20);
    assert_passes(&report);
}

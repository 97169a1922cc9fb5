//! Verification: a plate with a circular hole under uniaxial tension — the stress concentration
//! factor against Kirsch (infinite plate) and Howland (strip of finite width).
//!
//! Citation: G. Kirsch (1898), Die Theorie der Elastizität und die Bedürfnisse der
//! Festigkeitslehre, Z. VDI 42, 797–807 (SCF = 3 for the infinite plate);
//! R. C. J. Howland (1930), On the stresses in the neighbourhood of a circular hole in a strip
//! under tension, Phil. Trans. R. Soc. Lond. A 229, 49–86, doi:10.1098/rsta.1930.0002
//! (Kt_gross for the infinitely long strip, λ = d/D = 0.1 … 0.5: 3.03, 3.14, 3.36, 3.74, 4.32,
//! as reproduced by W. D. Pilkey, D. F. Pilkey (2008), Peterson's Stress Concentration Factors,
//! 3rd ed., Wiley, §4.3.1 / Chart 4.1); R. B. Heywood (1952), Designing by Photoelasticity,
//! Chapman & Hall: Kt_net ≈ 2 + (1 − λ)³ (printed for comparison, not asserted).
//!
//! Goal: (1) in a long strip the hoop stress at the net-section edge of the hole reaches
//! Howland's values; (2) in a square plate the SCF tends to Kirsch's 3 as the hole shrinks, the
//! finite-size correction decaying like (a/W)², and so does σ_θθ(a, 0°) → −σ.
//!
//! ```text
//!  x2                                       quarter model; O-grid: n cells along each ray
//!   B +--------------- free ---------------+    from the hole (graded towards it), 2n rays;
//!     |sym_x                         . '   |    the ray to the corner (L, B) is a grid line
//!     |u1=0                    . '         |--> σ
//!     |                  . '    rays       |--> σ   loaded edge x1 = L: traction (σ, 0)
//!   a +-.          . '                     |--> σ   free: x2 = B and the hole
//!     |  \   . '                           |
//!     +---+----------- sym_y: u2 = 0 ------+--> x1
//!     0   a                                L
//!
//!  SCF = σ_θθ(a, 90°)/σ = σ11(0, a)/σ, σ = applied (gross) tension; λ = d/D = a/B
//! ```
//!
//! Parameters: Q9 cells, n = 16 and 32 (2n = 32 and 64 around); plane stress, E = 1, ν = 0.3
//! (the stresses of this traction problem do not depend on them); σ = 1.
//! (1) Howland: B = 1, L = 4B (a strip 8B long, so the disturbance of the hole — decaying
//! like exp(−π x/B) or faster along a strip — is negligible at the loaded end; checked below
//! against L = 8B), a = λ B for λ = 0.1, 0.2, 0.3, 0.4, 0.5.
//! (2) Kirsch: square plate L = B = W = 1, a/W = 0.2, 0.1, 0.05.
//!
//! Reference values: Howland's Kt_gross above; Kirsch's SCF = 3 and σ_θθ(a, 0°) = −σ.
//!
//! Tolerances:
//! * Discretisation: the SCF changes by < 0.5 % from n = 16 to n = 32 (so the finer value is
//!   converged to well within that, the quadratic cells converging at second order or better).
//! * Howland: |SCF − Kt_gross| < 1 % of Kt_gross. Howland's table has three significant figures
//!   (rounding alone is up to 0.17 %) and comes from a truncated series; 1 % covers that, the
//!   discretisation (< 0.5 %) and the finite length (< 0.05 %, asserted).
//! * Kirsch: for a finite plate the hole's field reaches the boundary with relative size (a/W)²,
//!   so SCF − 3 and σ_θθ(a, 0°)/σ + 1 are O((a/W)²): each halving of a/W must divide them by
//!   2^(2 − 0.15) or more (the same rate tolerance as the convergence studies), and at
//!   a/W = 0.05 the SCF is within 1 % of 3.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_verification::analytic::KirschPlate;
use contact2d_verification::kirsch::{
    PlateWithHole, STANDARD_KIND, STANDARD_LEVELS, howland_studies, kirsch_studies, solve_scf,
};

#[test]
fn strip_matches_howland() {
    let studies = howland_studies(STANDARD_KIND, &STANDARD_LEVELS).unwrap();
    assert_eq!(studies.len(), 5);
    for s in &studies {
        let lambda = s.plate.diameter_ratio();
        let howland = s.howland.unwrap();
        assert!(s.mesh_change() < 5e-3, "λ = {lambda}: SCF changed by {:.3} % on refinement", 100.0 * s.mesh_change());
        let diff = (s.scf() - howland) / howland;
        assert!(diff.abs() < 1e-2, "λ = {lambda}: SCF {:.4} vs Howland {howland} ({:+.2} %)", s.scf(), 100.0 * diff);
    }
}

#[test]
fn strip_is_long_enough() {
    // The widest hole disturbs the most: L = 4B and L = 8B must agree on the SCF.
    let short = PlateWithHole { half_length: 4.0, half_width: 1.0, radius: 0.5 };
    let long = PlateWithHole { half_length: 8.0, ..short };
    let n = STANDARD_LEVELS[0];
    let (s, l) = (solve_scf(STANDARD_KIND, &short, n).unwrap().scf, solve_scf(STANDARD_KIND, &long, n).unwrap().scf);
    assert!((s - l).abs() < 5e-4 * l, "SCF {s} (L = 4B) vs {l} (L = 8B)");
}

#[test]
fn square_plate_tends_to_kirsch() {
    let studies = kirsch_studies(STANDARD_KIND, &STANDARD_LEVELS).unwrap();
    assert!(studies.len() >= 2);
    for s in &studies {
        assert!(s.mesh_change() < 5e-3, "a/W = {}: SCF changed by {:.3} %", s.plate.radius, 100.0 * s.mesh_change());
    }
    let scf_gap = |s: &contact2d_verification::kirsch::ScfStudy| s.scf() - KirschPlate::SCF;
    let hoop_gap = |s: &contact2d_verification::kirsch::ScfStudy| s.levels.last().unwrap().hoop_at_zero + 1.0;
    for w in studies.windows(2) {
        let (big, small) = (&w[0], &w[1]);
        let ratio = big.plate.radius / small.plate.radius;
        for (what, gap) in [("SCF − 3", &scf_gap as &dyn Fn(_) -> f64), ("σ_θθ(a, 0°)/σ + 1", &hoop_gap)] {
            let (g_big, g_small) = (gap(big), gap(small));
            assert!(g_small.abs() < g_big.abs(), "{what}: {g_small} at a/W = {} not below {g_big}", small.plate.radius);
            let exponent = (g_big / g_small).ln() / ratio.ln();
            assert!(exponent >= 2.0 - 0.15, "{what}: decays like (a/W)^{exponent:.2}, expected (a/W)^2");
        }
    }
    let smallest = studies.last().unwrap();
    assert!(
        (smallest.scf() - KirschPlate::SCF).abs() < 0.01 * KirschPlate::SCF,
        "a/W = {}: SCF {}",
        smallest.plate.radius,
        smallest.scf()
    );
}

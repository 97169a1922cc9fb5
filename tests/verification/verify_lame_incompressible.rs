//! Verification: volumetric locking and its cure — Lamé's thick-walled cylinder in plane strain
//! at ν = 0.4999, standard displacement elements against B-bar (projected dilatation).
//!
//! Citation: G. Lamé (1852), Leçons sur la théorie mathématique de l'élasticité des corps
//! solides; closed form as in S. P. Timoshenko, J. N. Goodier (1970), Theory of Elasticity, §28.
//! Locking and B-bar: T. J. R. Hughes (1980), IJNME 15, 1413–1418; D. S. Malkus, T. J. R. Hughes
//! (1978), CMAME 15, 63–81; D. Boffi, F. Brezzi, M. Fortin (2013), Mixed Finite Element Methods
//! and Applications, §8.6–8.7 (Q2/P1, P2/P0 stable; error bounds independent of λ).
//!
//! Goal: (1) the standard Quad4, Quad8, Quad9 and Tri6 lock at ν = 0.4999 — their displacement
//! and stress errors are one to three orders of magnitude above the B-bar ones on the same mesh;
//! (2) B-bar converges at the optimal rates, L2 displacement h^(k+1), L2 stress h^k, inner-wall
//! σ_rr and σ_θθ h^k (k = 1 for Quad4, 2 for Quad8, Quad9, Tri6), with error constants that do
//! not grow as ν → ½ (the ν = 0.4999 errors within 1.5× of the ν = 0.3 ones); (3) B-bar passes
//! the patch test (affine fields exact) on the distorted patches, also at ν = 0.4999.
//!
//! ```text
//!   x2
//!    ^  end (θ = 90°): u1 = 0
//!  b +-- _
//!    |     ~ .                    quarter annulus a ≤ r ≤ b, mesh annulus_sector: nr cells
//!  a +- .      .                  radially, 2 nr around; nodes of quadratic cells on the arcs
//!    |    \      \
//!    |  p  |  --> |  outer free   internal pressure p on the inner arc
//!    +-----+------+--> x1
//!    0     a      b    start (θ = 0): u2 = 0
//!
//!   nr = 4, 8, 16, 32, 64 (Quad4);  nr = 2, 4, 8, 16, 32 (Quad8, Quad9, Tri6)
//! ```
//!
//! Parameters: a = 1, b = 2, p = 100, E = 200 000, ν = 0.4999 (λ/μ = 2ν/(1 − 2ν) ≈ 5000), plane
//! strain, thickness 1. Reference: u_r = C1 r + C2/r with C1 = A(1 + ν)(1 − 2ν)/E, C2 = A(1 + ν)
//! b²/E, A = p a²/(b² − a²); σ_rr = A(1 − b²/r²), σ_θθ = A(1 + b²/r²) — finite as ν → ½.
//! Caveat: the exact mean stress σ_rr + σ_θθ = 2A is constant, so every pressure space represents
//! it exactly; this problem tests locking, not the approximation power of the pressure space
//! (which is why Tri6/P0 reaches h³ here).
//!
//! Tolerances: rates on the finest pair ≥ theory − 0.15, as in `verify_lame_cylinder.rs` (the
//! next term of the error expansion; a consistency bug costs ≥ 0.5). Locking: the locking error
//! scales with λ/μ ≈ 5000 times the ordinary one, and the measured standard/B-bar error ratios at
//! the second-finest mesh are ≥ 75 (displacement) and ≥ 2600 (stress), while at ν = 0.3 the
//! same ratios are about 3 or less (B-bar is exact for this problem's constant pressure): requiring ≥ 10 and
//! ≥ 100 separates the two regimes with a wide margin both ways. ν-robustness: the B-bar error
//! constants at ν = 0.4999 are measured 1.0–1.25× those at ν = 0.3 (the displacement field itself
//! changes with ν); 1.5 leaves room for that, while locking multiplies them by 10²–10⁴. Patch test:
//! 1e-10 relative at ν = 0.3, as in `verify_patch_test.rs` (measured ≤ 3e-14); at ν = 0.4999 the
//! round-off of the solve is amplified by the condition number, which grows with κ/μ ≈ 5000
//! (measured ≤ 2.4e-11), hence 1e-9, while a formulation that missed affine fields errs by O(1e-2)
//! or more on these distorted cells.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::element::{Formulation, PlaneCondition};
use contact2d::mesh::CellKind;
use contact2d_verification::lame::{LameLevel, LameSetup, LameStudy, lame_study, standard_levels, theoretical_rates};
use contact2d_verification::patch::{PatchSetup, PatchVariant, run_patch_test_with};

const NU: f64 = 0.4999;
const RATE_TOLERANCE: f64 = 0.15;
const LOCKED_DISPLACEMENT_RATIO: f64 = 10.0;
const LOCKED_STRESS_RATIO: f64 = 100.0;
const ROBUSTNESS_FACTOR: f64 = 1.5;

fn study(kind: CellKind, nu: f64, formulation: Formulation) -> LameStudy {
    let setup = LameSetup { poissons_ratio: nu, formulation, ..LameSetup::default() };
    lame_study(kind, PlaneCondition::Strain, &standard_levels(kind), &setup).unwrap()
}

fn check(kind: CellKind) {
    let (l2_theory, gradient_theory) = theoretical_rates(kind);
    let standard = study(kind, NU, Formulation::Standard);
    let bbar = study(kind, NU, Formulation::BBar);
    let bbar_03 = study(kind, 0.3, Formulation::BBar);

    // (1) The standard elements lock: on the second-finest mesh, far larger errors than B-bar.
    let n = standard.levels.len() - 2;
    let (s, b) = (&standard.levels[n], &bbar.levels[n]);
    let ratio_u = s.norms.relative_l2() / b.norms.relative_l2();
    let ratio_s = s.relative_stress_l2 / b.relative_stress_l2;
    assert!(ratio_u >= LOCKED_DISPLACEMENT_RATIO, "{kind:?}: standard/B-bar displacement error only {ratio_u:.1}");
    assert!(ratio_s >= LOCKED_STRESS_RATIO, "{kind:?}: standard/B-bar stress error only {ratio_s:.1}");

    // (2) B-bar converges monotonically, at the optimal rates, ν-robustly.
    let errors = |l: &LameLevel| {
        [l.norms.relative_l2(), l.relative_stress_l2, l.inner_radial_stress_error, l.inner_hoop_stress_error]
    };
    for w in bbar.levels.windows(2) {
        let (c, f) = (errors(&w[0]), errors(&w[1]));
        assert!((0..4).all(|i| f[i] < c[i]), "{kind:?}: a B-bar error grew at nr = {}: {c:?} → {f:?}", w[1].n_radial);
    }
    let last = |rates: Vec<f64>| *rates.last().unwrap();
    let rates = [
        (last(bbar.l2_rates()), l2_theory, "L2 displacement"),
        (last(bbar.stress_l2_rates()), gradient_theory, "L2 stress"),
        (last(bbar.wall_stress_rates()), gradient_theory, "σ_rr(a)"),
        (last(bbar.rates_of(|l| l.inner_hoop_stress_error)), gradient_theory, "σ_θθ(a)"),
    ];
    for (rate, theory, what) in rates {
        assert!(rate >= theory - RATE_TOLERANCE, "{kind:?} B-bar {what}: rate {rate:.3}, theory {theory}");
    }
    let (fine, fine_03) = (errors(bbar.finest().unwrap()), errors(bbar_03.finest().unwrap()));
    for i in 0..4 {
        assert!(
            fine[i] <= ROBUSTNESS_FACTOR * fine_03[i],
            "{kind:?} B-bar: error {i} at ν = {NU} is {:.3e}, at ν = 0.3 {:.3e}",
            fine[i],
            fine_03[i]
        );
    }
}

#[test]
fn quad4_locks_and_bbar_converges() {
    check(CellKind::Quad4);
}

#[test]
fn quad8_locks_and_bbar_converges() {
    check(CellKind::Quad8);
}

#[test]
fn quad9_locks_and_bbar_converges() {
    check(CellKind::Quad9);
}

#[test]
fn tri6_locks_and_bbar_converges() {
    check(CellKind::Tri6);
}

/// (3) B-bar reproduces affine fields exactly on the distorted patches (every B-bar kind, both
/// plane conditions, both boundary-condition variants), also nearly incompressible.
#[test]
fn bbar_passes_the_patch_test() {
    for (nu, tolerance) in [(0.3, 1e-10), (NU, 1e-9)] {
        let setup = PatchSetup { poissons_ratio: nu, ..PatchSetup::default() };
        for kind in [CellKind::Quad4, CellKind::Quad8, CellKind::Quad9, CellKind::Tri6] {
            for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
                for variant in [PatchVariant::Dirichlet, PatchVariant::Traction] {
                    let r = run_patch_test_with(kind, plane, variant, &setup, Formulation::BBar).unwrap();
                    let what = format!("{kind:?} {plane:?} {variant:?} ν = {nu}");
                    assert!(r.displacement_error <= tolerance, "{what}: displacement error {:e}", r.displacement_error);
                    assert!(r.stress_error <= tolerance, "{what}: stress error {:e}", r.stress_error);
                }
            }
        }
    }
}

/// Tri3 has no B-bar variant: asking for it is an error, not a silently locking answer.
#[test]
fn tri3_bbar_is_refused() {
    let setup = LameSetup { poissons_ratio: NU, formulation: Formulation::BBar, ..LameSetup::default() };
    assert!(lame_study(CellKind::Tri3, PlaneCondition::Strain, &[4], &setup).is_err());
}

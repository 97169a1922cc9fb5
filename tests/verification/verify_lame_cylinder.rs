//! Verification: Lamé's thick-walled cylinder under internal pressure — convergence rates of
//! the displacement in the L2 and energy norms, and the radial stress at the inner wall.
//!
//! Citation: G. Lamé (1852), Leçons sur la théorie mathématique de l'élasticité des corps
//! solides, Bachelier, Paris; closed form as in S. P. Timoshenko, J. N. Goodier (1970), Theory
//! of Elasticity, 3rd ed., §28. Rates: P. G. Ciarlet, P.-A. Raviart (1972), The combined effect
//! of curved boundaries and numerical integration in isoparametric finite element methods, in
//! A. K. Aziz (ed.), The Mathematical Foundations of the FEM, 409–474; G. Strang, G. Fix (1973),
//! An Analysis of the Finite Element Method, ch. 3–4.
//!
//! Goal: for every element kind in plane stress and plane strain, the observed rates of the
//! relative errors between the two finest meshes reach the a priori rates — L2: h^(k+1),
//! energy: h^k for degree k (1 for T3/Q4, 2 for T6/Q8/Q9) — and σ_rr(a) → −p.
//!
//! ```text
//!   x2
//!    ^  end (θ = 90°): u1 = 0
//!  b +-- _
//!    |     ~ .                    quarter annulus a ≤ r ≤ b, 0 ≤ θ ≤ 90°, mesh annulus_sector:
//!  a +- .      .                  nr cells radially, 2 nr around; nodes of quadratic cells
//!    |    \      \                on the exact arcs
//!    |  p  |  --> |  outer free   internal pressure p on the inner arc
//!    +-----+------+--> x1
//!    0     a      b    start (θ = 0): u2 = 0
//!
//!   h = (b - a)/nr:  nr = 4, 8, 16, 32, 64 (T3, Q4);  nr = 2, 4, 8, 16, 32 (T6, Q8, Q9)
//! ```
//!
//! Parameters: a = 1, b = 2, p = 100, E = 200 000, ν = 0.3, thickness 1.
//!
//! Reference values (closed form, `crates/verification/src/analytic.rs`): with A = p a²/(b² − a²),
//! u_r = C1 r + C2/r, plane stress C1 = A(1 − ν)/E, plane strain C1 = A(1 + ν)(1 − 2ν)/E,
//! C2 = A(1 + ν) b²/E in both; σ_rr = A(1 − b²/r²), so σ_rr(a) = −p. Errors are relative,
//! ‖u_h − u‖/‖u‖, integrated with 5×5 Gauss points (quads) or the degree-5 rule (triangles) over
//! the discrete domain.
//!
//! Tolerance: observed rate on the finest pair ≥ theory − 0.15. The estimates are asymptotic:
//! on a finite sequence the observed rate differs from the limit by the relative size of the
//! next term of the error expansion, which halves (or better) with every refinement; 0.15 is a
//! bound for that on the finest pair, while a consistency bug (wrong Jacobian, quadrature, load
//! or norm) lowers a rate by 0.5 or more. Faster rates are not failures — the estimates are
//! upper bounds on the error (T6 shows a mildly superconvergent L2 rate on this structured
//! triangulation). The wall stress is a pointwise value of the recovered stress, which
//! converges like the gradient, O(h^k), and is checked with the same tolerance; every
//! refinement must also reduce every error.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::element::PlaneCondition;
use contact2d::mesh::CellKind;
use contact2d_verification::lame::{LameSetup, LameStudy, lame_study, standard_levels, theoretical_rates};

const RATE_TOLERANCE: f64 = 0.15;

fn study(kind: CellKind, plane: PlaneCondition) -> LameStudy {
    lame_study(kind, plane, &standard_levels(kind), &LameSetup::default()).unwrap()
}

fn check(kind: CellKind) {
    let (l2_theory, energy_theory) = theoretical_rates(kind);
    for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
        let s = study(kind, plane);
        let what = format!("{kind:?} plane {plane:?}");
        for w in s.levels.windows(2) {
            let (c, f) = (&w[0], &w[1]);
            assert!(f.norms.relative_l2() < c.norms.relative_l2(), "{what}: L2 error grew at nr = {}", f.n_radial);
            assert!(
                f.norms.relative_energy() < c.norms.relative_energy(),
                "{what}: energy error grew at nr = {}",
                f.n_radial
            );
            assert!(
                f.inner_radial_stress_error < c.inner_radial_stress_error,
                "{what}: σ_rr(a) error grew at nr = {}",
                f.n_radial
            );
        }
        let last = |rates: Vec<f64>| *rates.last().unwrap();
        let (l2, energy, wall) = (last(s.l2_rates()), last(s.energy_rates()), last(s.wall_stress_rates()));
        assert!(l2 >= l2_theory - RATE_TOLERANCE, "{what}: L2 rate {l2:.3}, theory {l2_theory}");
        assert!(energy >= energy_theory - RATE_TOLERANCE, "{what}: energy rate {energy:.3}, theory {energy_theory}");
        assert!(wall >= energy_theory - RATE_TOLERANCE, "{what}: σ_rr(a) rate {wall:.3}, theory {energy_theory}");
    }
}

#[test]
fn quad4_converges_at_the_optimal_rates() {
    check(CellKind::Quad4);
}

#[test]
fn quad8_converges_at_the_optimal_rates() {
    check(CellKind::Quad8);
}

#[test]
fn quad9_converges_at_the_optimal_rates() {
    check(CellKind::Quad9);
}

#[test]
fn tri6_converges_at_the_optimal_rates() {
    check(CellKind::Tri6);
}

#[test]
fn tri3_converges_at_the_optimal_rates() {
    check(CellKind::Tri3);
}

//! Verification: global equilibrium of reactions and applied loads (forces and moment).
//!
//! Citation: the equilibrium of the discrete system, e.g. T. J. R. Hughes (2000), The Finite
//! Element Method, Dover, §1.14 (reactions from the assembled residual); the pressure resultant
//! is Gauss's theorem on the arc (Timoshenko & Goodier 1970, §28 for the Lamé geometry).
//!
//! Goal: the reactions at the Dirichlet supports plus the consistent nodal loads sum to zero —
//! both force components and the moment — because `K` annihilates rigid motions:
//! `Σ (f + r) = 1ᵀ K u = (K 1)ᵀ u = 0`. A wrong reaction recovery, a load applied to a
//! constrained DOF and dropped, or a stiffness that is not rigid-motion free breaks it. The
//! applied loads are also checked against their closed-form resultants.
//!
//! ```text
//!  (a) Lamé quarter cylinder (4 x 8 cells)         (b) cantilever (10 x 2 cells)
//!   x2                                              x2
//!    ^ u1 = 0 on θ = 90°                             ^
//!  2 +.                                            1 +#---------------------+ |
//!    |  .                                            |#                     | | τ = 10
//!  1 +.   .     outer free                           |#  clamped: u = 0     | v (shear)
//!    | p \  \                                      0 +#---------------------+---> x1
//!    +----+--+--> x1    u2 = 0 on θ = 0              0                      5
//!    0    1  2
//!   F = p a (1, 1) = (100, 100), M_F(0) = 0         F = (0, -τ c) = (0, -10), M_F(0) = -τ c L = -50
//! ```
//!
//! Parameters: (a) a = 1, b = 2, p = 100, E = 200 000, ν = 0.3; (b) L = 5, c = 1, τ = 10,
//! E = 200 000, ν = 0.3; every element kind, plane stress and plane strain, thickness 1.
//!
//! Reference values: `F + R = 0`, `M_F + M_R = 0` (moments about the origin); the resultant of
//! the pressure is exactly `p a (1, 1)` and its moment exactly 0 for any chain of edges whose end
//! nodes lie on the arc (`∫ n ds` is the rotated chord, `∫ x·t ds = ½ Δ|x|²`), and the 3-point
//! edge rule integrates both exactly, as it does the uniform end shear.
//!
//! Tolerance: residuals ≤ 1e-10 relative to ‖F‖ (moments to ‖F‖ L). The sums vanish up to
//! the residual of the Cholesky solve (reactions are `K_cf u_f + K_cc u_c − f_c`), which a
//! backward-stable solve keeps of order ε ‖K‖ ‖u‖, i.e. at most about ε κ(K_ff) ‖F‖: tiny for the
//! pressure on the stiff cylinder, largest for the end shear that excites the soft bending mode
//! of the cantilever (a few 1e-12 on these ≤ 400-DOF meshes). 1e-10 keeps a margin above that,
//! while a real defect — a reaction lost at a node shared by two groups, a load on a constrained
//! DOF dropped — is of the order of the load itself. The loads against their closed forms:
//! ≤ 1e-12 (quadrature and summation round-off only).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_verification::balance::balance_cases;

#[test]
fn reactions_balance_the_applied_loads() {
    let cases = balance_cases().unwrap();
    assert_eq!(cases.len(), 20, "5 kinds × 2 plane conditions × 2 models");
    for c in &cases {
        let [r1, r2] = c.balance.relative_force_residual();
        let m = c.balance.relative_moment_residual(c.length);
        let what = format!("{} {:?} {:?}", c.model, c.kind, c.plane);
        assert!(r1 <= 1e-10 && r2 <= 1e-10, "{what}: force residual ({r1:e}, {r2:e})");
        assert!(m <= 1e-10, "{what}: moment residual {m:e}");
    }
}

#[test]
fn applied_loads_match_their_closed_form_resultants() {
    for c in &balance_cases().unwrap() {
        let scale = c.expected_load[0].hypot(c.expected_load[1]);
        let f = c.balance.load;
        let what = format!("{} {:?} {:?}", c.model, c.kind, c.plane);
        assert!(
            (f[0] - c.expected_load[0]).hypot(f[1] - c.expected_load[1]) <= 1e-12 * scale,
            "{what}: load resultant {f:?}, expected {:?}",
            c.expected_load
        );
        assert!(
            (c.balance.load_moment - c.expected_load_moment).abs() <= 1e-12 * scale * c.length,
            "{what}: load moment {}, expected {}",
            c.balance.load_moment,
            c.expected_load_moment
        );
    }
}

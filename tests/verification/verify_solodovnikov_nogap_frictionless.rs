//! Solodovnikov (1998), plate with a deformable insert, no gap and no friction (spec §5.3, §7).
//!
//! Goal: reproduce the published row "mu = 0" of the no-gap table with two independent
//! algorithms on the same discrete problem: the condensed primal-dual active set, and the full
//! QP (5.3) solved by Clarabel.
//!
//! ```text
//!   top: u2 = 0                                    right (x1 = 5): u1 = w = 1, u2 = 0
//!   ┌──────────────────────────────────────────────┐
//!   │ left free     plate E1 = 1, ν = 0.3          │
//!   │          ╭────╮                              │     Quad9, N = 32 and 64 elements along
//!   │         │insert│ E2 = E1, clamped at ρ = 0.25│     the half circle (meshes/plate_insert)
//!   └─────────╯      ╰─────────────────────────────┘
//!   bottom (x2 = 0 outside the hole): u2 = 0; insert symmetry: u2 = 0; variant 1 pairs, eps = 0
//! ```
//!
//! Published (spec §7): l = 0.4708, P = 0.184, Φ_E1 = 0.07322, Φ_E2 = 0.01874, σ* = 0.3282,
//! K = 4.460. Tolerances (issue 3): P, Φ_E1, Φ_E2 within 1% (they converge to 4-5 digits at
//! 32-64 elements, spec §8); l within 0.005 absolute (the 3/2-power interpolation of the gap
//! between the bracketing nodes, spec §8); σ*, K within 3% (σ* is a cusp at the contact end that converges
//! slowly from below and depends on the recovery, spec §8: reported here with Gauss-point
//! extrapolation). The two algorithms: displacements within 1e-8 relative (Clarabel at 1e-12
//! tolerances reaches ~1e-9), identical contact sets. Energy balance P w / 2 = Φ_E1 + Φ_E2 to
//! 1e-8 relative (Clapeyron, exact for the discrete problem up to solver accuracy).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::{ContactStatus, Interface, PairState, solve_frictionless_active_set, solve_frictionless_qp};
use contact2d::plate_insert::{PairDiscretisation, PlateInsert};

fn within(measured: f64, published: f64, rel: f64, what: &str) {
    let err = (measured - published).abs() / published.abs();
    assert!(err <= rel, "{what}: measured {measured:.5}, published {published}, relative error {err:.2e} > {rel}");
}

fn check_level(n: usize) {
    let case = PlateInsert {
        pairs: PairDiscretisation::NodeToSegment,
        ..PlateInsert::paper(format!("meshes/plate_insert/plate_insert_eps0_N{n}.msh"))
    }
    .build()
    .unwrap();
    let interface = Interface::new(&case.problem);
    let active_set = solve_frictionless_active_set(&case.problem, &interface, 1.0, 50);
    let qp = solve_frictionless_qp(&case.problem, 1.0);
    assert_eq!(active_set.status, ContactStatus::Converged);
    assert_eq!(qp.status, ContactStatus::Converged);

    // Same discrete solution from both algorithms.
    let umax = active_set.displacement.iter().fold(0.0f64, |a, u| a.max(u.abs()));
    let du = active_set.displacement.iter().zip(&qp.displacement).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(du <= 1e-8 * umax, "N={n}: active set vs Clarabel differ by {:.2e} relative", du / umax);
    assert_eq!(active_set.state, qp.state, "N={n}: contact sets differ");
    assert!(active_set.kkt.max_penetration < 1e-12 && active_set.kkt.max_tension == 0.0);

    for (name, s) in [("active set", &active_set), ("Clarabel", &qp)] {
        let q = case.results(s).unwrap();
        let energy = q.energy_plate + q.energy_insert;
        let balance = (0.5 * q.pull - energy).abs() / energy;
        assert!(balance < 1e-8, "{name} N={n}: energy balance off by {balance:.2e}");
        within(q.pull, 0.184, 0.01, &format!("{name} N={n} P"));
        within(q.energy_plate, 0.07322, 0.01, &format!("{name} N={n} Phi_E1"));
        within(q.energy_insert, 0.01874, 0.01, &format!("{name} N={n} Phi_E2"));
        let l = q.contact_end.unwrap();
        assert!((l - 0.4708).abs() <= 0.005, "{name} N={n}: l = {l:.4} vs 0.4708");
        within(q.sigma_star, 0.3282, 0.03, &format!("{name} N={n} sigma*"));
        within(q.stress_concentration, 4.460, 0.03, &format!("{name} N={n} K"));
        assert!(s.state.contains(&PairState::Stick));
    }
}

#[test]
fn no_gap_frictionless_n32_matches_the_paper_with_both_algorithms() {
    check_level(32);
}

#[test]
fn no_gap_frictionless_n64_matches_the_paper_with_both_algorithms() {
    check_level(64);
}

/// Without gap and friction the solution is linear in w: solved once at w = 1 and scaled, it
/// equals the direct solve at another w (to round-off, 1e-12 relative).
#[test]
fn no_gap_frictionless_solution_scales_linearly_with_the_load() {
    let case = PlateInsert {
        pairs: PairDiscretisation::NodeToSegment,
        ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0_N16.msh")
    }
    .build()
    .unwrap();
    assert!(case.problem.is_gapless());
    let interface = Interface::new(&case.problem);
    let unit = solve_frictionless_active_set(&case.problem, &interface, 1.0, 50);
    let w = 0.3838;
    let direct = solve_frictionless_active_set(&case.problem, &interface, w, 50);
    let umax = direct.displacement.iter().fold(0.0f64, |a, u| a.max(u.abs()));
    for (a, b) in unit.displacement.iter().zip(&direct.displacement) {
        assert!((w * a - b).abs() <= 1e-12 * umax);
    }
    assert_eq!(unit.state, direct.state);
}

//! Solodovnikov (1998), plate with a deformable insert and clearance, no friction: Table 2, U(3).
//!
//! Goal: reproduce the row U(3) (variant 2: pairs defined from the insert edge Γ_c, μ = 0)
//! with the condensed active set and with Clarabel's QP on the same discrete problem.
//!
//! ```text
//!   top: u2 = 0                                     right: u1 = w = 0.3838, u2 = 0
//!   ┌───────────────────────────────────────────────┐
//!   │           ╭─────╮  hole r = 1 (plate)          │   insert: outer radius 1 − ε, centred at
//!   │          │ ╭─╮  │  insert ρ = 1 − ε            │   (−ε, 0), clamped at ρ = 0.25
//!   └──────────╯ ╰─╯  ╰──────────────────────────────┘   ε = 0.05, c = 1 (ω = c/ε = 20)
//!   master: insert-edge nodes; slave: the closest hole point (node-to-segment on the Line3 edge)
//!   gap: the paper's u_rc = −c (1 + cos φ̂)  (gap = −u_rc, displacement units)
//! ```
//!
//! Published (spec §7, Table 2, U(3)): l = 0.1499 (on the hole-edge angle), P = 4.679e-2,
//! Φ_E1 = 6.427e-3, Φ_E2 = 1.874e-3, σ* = 0.0994, K = 5.313.
//! Tolerances (issue 3): P, Φ_E1, Φ_E2 within 1% (converged to 4-5 digits at 32-64 elements,
//! spec §8); l within 0.005 absolute (3/2-power gap interpolation inside the mesh bracket);
//! σ*, K within 3% (with clearance the peak sits inside the free zone and converges quickly,
//! spec §8). The two algorithms agree to 1e-8 relative in displacement (Clarabel at 1e-12).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::{ContactStatus, Interface, solve_frictionless_active_set, solve_frictionless_qp};
use contact2d::plate_insert::{PairingVariant, PlateInsert, PlateInsertProblem};

const W: f64 = 0.3838;

fn case(n: usize) -> PlateInsertProblem {
    PlateInsert {
        variant: PairingVariant::InsertMaster,
        eps: 0.05,
        clearance: 1.0,
        ..PlateInsert::paper(format!("meshes/plate_insert/plate_insert_eps0.05_N{n}.msh"))
    }
    .build()
    .unwrap()
}

fn within(measured: f64, published: f64, rel: f64, what: &str) {
    let err = (measured - published).abs() / published.abs();
    assert!(err <= rel, "{what}: measured {measured:.5}, published {published}, relative error {err:.2e} > {rel}");
}

fn assert_table2_u3(case: &PlateInsertProblem, s: &contact2d::contact::ContactSolution, what: &str) {
    let q = case.results(s).unwrap();
    within(q.pull, 4.679e-2, 0.01, &format!("{what} P"));
    within(q.energy_plate, 6.427e-3, 0.01, &format!("{what} Phi_E1"));
    within(q.energy_insert, 1.874e-3, 0.01, &format!("{what} Phi_E2"));
    let l = q.contact_end.unwrap();
    assert!((l - 0.1499).abs() <= 0.005, "{what}: l = {l:.4} vs 0.1499");
    within(q.sigma_star, 0.0994, 0.03, &format!("{what} sigma*"));
    within(q.stress_concentration, 5.313, 0.03, &format!("{what} K"));
    // Spec §7: on the master's own coordinate 1 − θ̂/π the end lies further out than on the hole angle.
    assert!(q.contact_end_master.unwrap() > l);
}

#[test]
fn table2_u3_n32_both_algorithms_agree_and_match_the_paper() {
    let case = case(32);
    let interface = Interface::new(&case.problem);
    let active_set = solve_frictionless_active_set(&case.problem, &interface, W, 50);
    let qp = solve_frictionless_qp(&case.problem, W);
    assert_eq!(active_set.status, ContactStatus::Converged);
    assert_eq!(qp.status, ContactStatus::Converged);
    let umax = active_set.displacement.iter().fold(0.0f64, |a, u| a.max(u.abs()));
    let du = active_set.displacement.iter().zip(&qp.displacement).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    assert!(du <= 1e-8 * umax, "active set vs Clarabel: {:.2e} relative", du / umax);
    assert_eq!(active_set.state, qp.state);
    assert!(active_set.kkt.max_penetration < 1e-12);
    assert_table2_u3(&case, &active_set, "active set N=32");
    assert_table2_u3(&case, &qp, "Clarabel N=32");
}

#[test]
fn table2_u3_n64_active_set_matches_the_paper() {
    let case = case(64);
    let interface = Interface::new(&case.problem);
    let s = solve_frictionless_active_set(&case.problem, &interface, W, 50);
    assert_eq!(s.status, ContactStatus::Converged);
    assert_table2_u3(&case, &s, "active set N=64");
}

/// With clearance the solution is not linear in w (the contact zone grows with the load):
/// doubling w must not double the displacements.
#[test]
fn with_clearance_the_response_is_not_linear_in_w() {
    let case = case(16);
    let interface = Interface::new(&case.problem);
    let a = solve_frictionless_active_set(&case.problem, &interface, W, 50);
    let b = solve_frictionless_active_set(&case.problem, &interface, 2.0 * W, 50);
    let pa = case.results(&a).unwrap().pull;
    let pb = case.results(&b).unwrap().pull;
    assert!((pb - 2.0 * pa).abs() > 1e-3 * pa, "P(2w) = {pb}, 2 P(w) = {}", 2.0 * pa);
}

//! Clarabel's Tresca fixed point warm-started from pair states (issue 44, item 10): a body held
//! only by contact solves the same step many times at nearby rigid motions, and a history
//! solves each step near the last one's states; `solve_frictional_qp_from` starts the fixed
//! point from the exact solution of the guessed states instead of the frictionless QP.
//!
//! Goal: the guess changes the work, never the answer. Truths: the active set (an independent
//! algorithm) and Clarabel without a guess, on the paper's plate with insert (N = 32, no gap,
//! μ = 0.3, w = 1). Tolerance 1e-10 of the largest displacement: every answer here is the exact
//! solution of its pair states (polished), so the same states give the same displacements to the
//! round-off of one factorisation (~1e-13); a different state moves them by far more than 1e-10.
//! The states themselves are compared one by one.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::{
    ContactSolution, ContactStatus, Interface, PairState, StepStart, solve_frictional_active_set,
    solve_frictional_qp_from,
};
use contact2d::plate_insert::PlateInsert;

fn assert_same(a: &ContactSolution, b: &ContactSolution, what: &str) {
    assert_eq!(b.status, ContactStatus::Converged, "{what}");
    assert_eq!(a.state, b.state, "{what}: states");
    let umax = a.displacement.iter().fold(0.0f64, |m, u| m.max(u.abs()));
    let du = a.displacement.iter().zip(&b.displacement).fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
    assert!(du <= 1e-10 * umax, "{what}: {:.2e} of the displacements", du / umax);
}

#[test]
fn a_guess_changes_the_work_of_clarabel_not_its_answer() {
    let case = PlateInsert { friction: 0.3, ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0_N32.msh") }
        .build()
        .unwrap();
    let problem = &case.problem;
    let interface = Interface::new(problem);
    let start = StepStart::initial(problem.num_pairs());
    let active = solve_frictional_active_set(problem, &interface, 1.0, &start, None, 100);
    assert_eq!(active.status, ContactStatus::Converged);
    assert!(active.state.iter().any(|s| matches!(s, PairState::Stick)), "the case has a stick zone");
    assert!(active.state.iter().any(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative)));
    let cold = solve_frictional_qp_from(problem, &interface, 1.0, &start, None, 100);
    assert_same(&active, &cold, "Clarabel without a guess");
    // The answer's own states: accepted after the one Tresca QP that checks them.
    let warm = solve_frictional_qp_from(problem, &interface, 1.0, &start, Some(&cold.state), 100);
    assert_same(&active, &warm, "Clarabel from its answer's states");
    assert_eq!(warm.iterations, 1, "one Tresca QP checks a right guess");
    // A wrong guess (every pair stuck: its exact solution breaks the cone) is only a start.
    let stuck = vec![PairState::Stick; problem.num_pairs()];
    let wrong = solve_frictional_qp_from(problem, &interface, 1.0, &start, Some(&stuck), 100);
    assert_same(&active, &wrong, "Clarabel from every pair stuck");
    // A guess of another length is ignored.
    let short = solve_frictional_qp_from(problem, &interface, 1.0, &start, Some(&stuck[1..]), 100);
    assert_same(&active, &short, "Clarabel from a guess of the wrong length");
}

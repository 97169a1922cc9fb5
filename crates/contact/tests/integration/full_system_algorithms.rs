//! The full-system algorithms (augmented Lagrangian, penalty) against the condensed active set on
//! the two-block problem (`fixtures/two_blocks.rs`):
//!
//! ```text
//!            ↓ push, → slide (prescribed on top)
//!   ┌────────────────┐  upper block "b_" (E = ratio), master b_bottom
//!   └────────────────┘  ← gap + tilt · (x − 1.5)
//!   ┌────────────────────────┐  lower block "a_" (E = 1), slave a_top
//!   └────────────────────────┘  bottom clamped
//! ```
//!
//! The augmented Lagrangian solves the same discrete problem as the active set exactly (both end
//! at a state whose linear equations they solve to round-off), so the forces must agree to 1e-8
//! of the largest force (sparse LU against dense Cholesky/LU round-off on systems of condition
//! ~1e6 leaves ~1e-10) and the states must be equal. The penalty method solves a different
//! (regularised) problem: its error must fall like 1/κ (first order), and its penetration must be
//! the law's λ/(κ k_c).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_contact::{
    ContactAlgorithm, ContactSolution, ContactStatus, LoadSchedule, PairState, PenaltyParameters, SolverSettings,
    StepStart, contact_stiffness, solve, solve_augmented_lagrangian, solve_penalty,
};
use contact2d_mesh::CellKind;

use crate::fixture;
use fixture::{two_blocks, two_blocks_sliding};

/// `max |a − b|` over the normal and tangential forces, relative to the largest force of `b`.
fn force_difference(a: &ContactSolution, b: &ContactSolution) -> f64 {
    let scale = b.normal_force.iter().chain(&b.tangential_force).fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = a
        .normal_force
        .iter()
        .zip(&b.normal_force)
        .chain(a.tangential_force.iter().zip(&b.tangential_force))
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    diff / scale
}

#[test]
fn augmented_lagrangian_agrees_with_the_active_set_without_friction() {
    for (kind, gap, tilt, ratio) in
        [(CellKind::Quad4, 0.01, 0.01, 2.0), (CellKind::Quad9, 0.0, 0.0, 0.1), (CellKind::Quad4, 0.005, -0.008, 10.0)]
    {
        let problem = two_blocks(kind, gap, tilt, ratio, gap + 0.02, 7, 5);
        let start = StepStart::initial(problem.num_pairs());
        let reference =
            solve(&problem, &SolverSettings::new(ContactAlgorithm::ActiveSet), &single_step()).unwrap().steps;
        let reference = &reference[0].solution;
        let al = solve_augmented_lagrangian(&problem, 1.0, &start, None, 100);
        assert_eq!(reference.status, ContactStatus::Converged);
        assert_eq!(al.status, ContactStatus::Converged, "{kind:?} gap {gap}");
        assert_eq!(al.state, reference.state);
        let d = force_difference(&al, reference);
        assert!(d <= 1e-8, "{kind:?} gap {gap}: relative force difference {d:.2e}");
    }
}

#[test]
fn augmented_lagrangian_agrees_with_the_active_set_pressing_and_sliding_with_friction() {
    // Four steps of a push 0.03 with a slide 0.01 through a tilted gap, μ = 0.3: stick, slip and
    // open pairs, and a history (slips and forces carried from step to step).
    let mut problem = two_blocks_sliding(CellKind::Quad4, 0.005, 0.004, 2.0, 0.03, 0.01, 8, 6);
    problem.set_friction(0.3).unwrap();
    let schedule = LoadSchedule::new(vec!["main".into()], vec![vec![0.25], vec![0.5], vec![0.75], vec![1.0]]).unwrap();
    let run = |algorithm| solve(&problem, &SolverSettings::new(algorithm), &schedule).unwrap();
    let (reference, al) = (run(ContactAlgorithm::ActiveSet), run(ContactAlgorithm::AugmentedLagrangian));
    assert_eq!(al.steps.len(), 4);
    let mut slipped = false;
    for (a, r) in al.steps.iter().zip(&reference.steps) {
        assert_eq!(r.solution.status, ContactStatus::Converged);
        assert_eq!(a.solution.status, ContactStatus::Converged);
        assert_eq!(a.solution.state, r.solution.state);
        let d = force_difference(&a.solution, &r.solution);
        assert!(d <= 1e-8, "relative force difference {d:.2e}");
        slipped |= a.solution.state.iter().any(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative));
    }
    assert!(slipped, "the slide must make some pair slip");
}

#[test]
fn penalty_error_falls_like_one_over_the_penalty_and_its_penetration_is_the_law() {
    let problem = two_blocks(CellKind::Quad4, 0.01, 0.01, 2.0, 0.03, 7, 5);
    let start = StepStart::initial(problem.num_pairs());
    let exact = solve_augmented_lagrangian(&problem, 1.0, &start, None, 100);
    assert_eq!(exact.status, ContactStatus::Converged);
    let k_c = contact_stiffness(&problem);
    let mut errors = vec![];
    for kappa in [1e2, 1e3, 1e4] {
        let p = PenaltyParameters { normal: kappa, tangential: kappa };
        let s = solve_penalty(&problem, 1.0, &start, None, p, 100);
        // κ ≤ 1e3 leaves a penetration above the certificate's 1e-4 of U: not `Converged`.
        if kappa <= 1e3 {
            assert_eq!(s.status, ContactStatus::Penalised, "κ = {kappa}");
        }
        assert!(s.status.is_solved(), "κ = {kappa}");
        let lambda_max = s.normal_force.iter().fold(0.0f64, |a, l| a.max(*l));
        // λ = ε (−gap)⁺ exactly at the fixed point (round-off of the LU: 1e-9 relative).
        let expected = lambda_max / (kappa * k_c);
        assert!((s.kkt.max_penetration - expected).abs() <= 1e-9 * expected, "κ = {kappa}");
        errors.push(force_difference(&s, &exact));
    }
    // First order: each decade of κ divides the error by ten (within a factor two: the contact
    // set of the penalised solution may still differ at the zone's end).
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((5.0..=20.0).contains(&ratio), "errors {errors:?}");
    }
    // A large enough penalty meets the exact certificate and is reported as converged.
    let penalised = |kappa| PenaltyParameters { normal: kappa, tangential: kappa };
    let stiff = solve_penalty(&problem, 1.0, &start, None, penalised(1e6), 100);
    assert_eq!(stiff.status, ContactStatus::Converged);
    // 2.6/κ = 2.6e-6 from the law, with a factor 2 for round-off.
    assert!(force_difference(&stiff, &exact) <= 5e-6);
    // Too large a penalty: λ = −ε gap multiplies the gap's round-off by ε; the equilibrium
    // residual measures it (1e-3 of the forces at κ = 1e12) and the status says so.
    let too_stiff = solve_penalty(&problem, 1.0, &start, None, penalised(1e12), 100);
    assert_eq!(too_stiff.status, ContactStatus::Numerical);
}

#[test]
fn penalty_with_friction_approaches_the_coulomb_solution() {
    let mut problem = two_blocks_sliding(CellKind::Quad4, 0.005, 0.004, 2.0, 0.03, 0.01, 8, 6);
    problem.set_friction(0.3).unwrap();
    let start = StepStart::initial(problem.num_pairs());
    let exact = solve_augmented_lagrangian(&problem, 1.0, &start, None, 100);
    assert_eq!(exact.status, ContactStatus::Converged);
    let errors: Vec<f64> = [1e2, 1e4]
        .iter()
        .map(|&kappa| {
            let s =
                solve_penalty(&problem, 1.0, &start, None, PenaltyParameters { normal: kappa, tangential: kappa }, 100);
            assert!(s.status.is_solved(), "κ = {kappa}: {:?}", s.status);
            force_difference(&s, &exact)
        })
        .collect();
    // Two decades of κ: at least one decade of error (first order would be two).
    assert!(errors[1] <= 0.1 * errors[0], "errors {errors:?}");
}

fn single_step() -> LoadSchedule {
    LoadSchedule::new(vec!["main".into()], vec![vec![1.0]]).unwrap()
}

/// The penalty and augmented Lagrangian methods condensed onto the pairs' rows (the default on
/// fewer than 2,000 pairs, `algorithms/pair_space.rs`) and on the full system (`solver.linear =
/// "sparse"`) take the same iterates: each iteration solves the same state's linear equations
/// exactly, by a dense LU of the compliances `C = B K⁻¹ Bᵀ` or by a sparse LU of the bordered
/// system. So every step must take the same number of iterations and end in the same states,
/// and the answers may differ by the round-off of the two factorisations only: cond · ε ≈ 1e-10
/// of the largest force on these systems (condition ~1e6) for the augmented Lagrangian, and for
/// the penalty that times κ = 1e3 (the penalised matrix `K + ε_N BᵀB` has condition ~κ · 1e6, and
/// `λ = −ε_N gap` multiplies a gap's round-off by the penalty): 1e-7 (measured 3e-9 for the
/// penalty, 5e-15 for the augmented Lagrangian; displacements 5e-13 and 8e-16).
#[test]
fn condensed_and_full_system_penalty_and_augmented_lagrangian_take_the_same_iterates() {
    use contact2d_contact::LinearSolver;
    let mut problem = two_blocks_sliding(CellKind::Quad4, 0.005, 0.004, 2.0, 0.03, 0.01, 8, 6);
    problem.set_friction(0.3).unwrap();
    let schedule = LoadSchedule::new(vec!["main".into()], vec![vec![0.25], vec![0.5], vec![0.75], vec![1.0]]).unwrap();
    for algorithm in [ContactAlgorithm::Penalty, ContactAlgorithm::AugmentedLagrangian] {
        let run = |linear| {
            let settings = SolverSettings::new(algorithm).with_linear(linear).unwrap();
            solve(&problem, &settings, &schedule).unwrap()
        };
        let (condensed, full) = (run(LinearSolver::Condensed), run(LinearSolver::Sparse));
        assert_eq!(condensed.steps.len(), 4, "{algorithm:?}");
        assert_eq!(full.steps.len(), 4, "{algorithm:?}");
        let mut slipped = false;
        for (c, f) in condensed.steps.iter().zip(&full.steps) {
            let (c, f) = (&c.solution, &f.solution);
            assert!(f.status.is_solved(), "{algorithm:?}: {:?}", f.status);
            assert_eq!(c.status, f.status, "{algorithm:?}");
            assert_eq!(c.iterations, f.iterations, "{algorithm:?}");
            assert_eq!(c.state, f.state, "{algorithm:?}");
            let tolerance = if algorithm == ContactAlgorithm::Penalty { 1e-7 } else { 1e-10 };
            let d = force_difference(c, f);
            assert!(d <= tolerance, "{algorithm:?}: relative force difference {d:.2e}");
            let u_scale = f.displacement.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let du = c.displacement.iter().zip(&f.displacement).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(du <= tolerance * u_scale, "{algorithm:?}: relative displacement difference {:.2e}", du / u_scale);
            slipped |= c.state.iter().any(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative));
        }
        assert!(slipped, "{algorithm:?}: the slide must make some pair slip");
    }
}

//! The sparse path (`solver.linear = "sparse"`: each contact state solved on the full system,
//! `crate::kkt`) against the condensed path (the interface condensed onto the pairs, each state's
//! reduced system a dense LU): a second algorithm for the same discrete problem, so the two
//! histories must agree to round-off in every force and displacement.
//!
//! ```text
//!   ┌──────────────┐  upper block: pushed (two_blocks) or pressed and slid (blocks below)
//!   └──────────────┘  master ── gap / tilt / touching ──
//!   ┌──────────────────────┐  lower block, slave; bottom clamped
//!   └──────────────────────┘
//! ```
//!
//! Cases: frictionless through a tilted gap; Coulomb press and slide through stick and slip;
//! a floating block (held only by contact) with every pairing (node-to-segment,
//! node-to-node, segment-to-segment on non-matching meshes).
//!
//! Tolerance 1e-10 of the largest value of each field: both paths end in the same contact
//! state and solve its linear equations backward-stably (LU of the condensed compliances;
//! LDLᵀ plus GMRES to a relative residual of 1e-14 on the full system); on these meshes the
//! systems' condition numbers are below ~1e5, so the answers differ by ~1e5 ε ≈ 2e-11.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_contact::{
    BodyDescription, ContactAlgorithm, ContactDescription, ContactProblem, ContactStatus, EdgeLoadKind, FixDescription,
    GapDescription, History, LinearSolver, LoadDescription, LoadSchedule, Pairing, ProblemDescription, SolverSettings,
    solve,
};
use contact2d_element::{Formulation, Kinematics};
use contact2d_fem::Component;
use contact2d_mesh::generate::{append_prefixed, rectangle};
use contact2d_mesh::{CellKind, Mesh};

use crate::fixture;
use fixture::{two_blocks, two_blocks_sliding};

/// Solves `schedule` on `problem` with the active set on both paths.
fn both_paths(problem: &ContactProblem, schedule: &LoadSchedule) -> (History, History) {
    let run = |linear| {
        // Floating bodies' proximal iteration to 1e-14 (default 1e-10): it stops at a spring
        // force of that fraction of the force scale, and the paths must agree beyond it.
        let settings = SolverSettings::new(ContactAlgorithm::ActiveSet)
            .with_linear(linear)
            .unwrap()
            .with_floating_tolerance(1e-14)
            .unwrap();
        solve(problem, &settings, schedule).unwrap()
    };
    (run(LinearSolver::Condensed), run(LinearSolver::Sparse))
}

/// Asserts that every step converged on both paths with the same states, and that forces,
/// displacements, gaps and dissipation agree to 1e-10 of each field's largest value.
fn assert_agree(condensed: &History, sparse: &History) {
    let statuses = |h: &History| h.steps.iter().map(|s| s.solution.status).collect::<Vec<_>>();
    assert_eq!(statuses(condensed), statuses(sparse));
    for (i, (a, b)) in condensed.steps.iter().zip(&sparse.steps).enumerate() {
        let (a, b) = (&a.solution, &b.solution);
        assert_eq!(a.status, ContactStatus::Converged, "step {i}: condensed {:?}", a.status);
        assert_eq!(b.status, ContactStatus::Converged, "step {i}: sparse {:?}", b.status);
        assert_eq!(a.state, b.state, "step {i}: states");
        let largest = |x: &[f64]| x.iter().fold(f64::MIN_POSITIVE, |m, v| m.max(v.abs()));
        // Gaps are judged on the displacements' scale (closed gaps are round-off themselves).
        let fields = [
            ("normal force", &a.normal_force, &b.normal_force, largest(&a.normal_force)),
            ("tangential force", &a.tangential_force, &b.tangential_force, largest(&a.normal_force)),
            ("displacement", &a.displacement, &b.displacement, largest(&a.displacement)),
            ("gap", &a.gap, &b.gap, largest(&a.displacement).max(largest(&a.gap))),
        ];
        for (name, x, y, scale) in fields {
            for (k, (p, q)) in x.iter().zip(y.iter()).enumerate() {
                assert!((p - q).abs() <= 1e-10 * scale, "step {i}, {name} [{k}]: condensed {p}, sparse {q}");
            }
        }
        // The dissipation Σ −½(τ_start + τ) Δs is judged on the scale its first-order error has
        // when forces and displacements agree to 1e-10 of their largest values:
        // Σ_k (|τ_k| · max|u| + max|λ| · |Δs_k|) (a slip is a difference of displacements, so
        // its error is on the displacements' scale however small the slip itself).
        let (u, lambda) = (largest(&a.displacement), largest(&a.normal_force));
        let d: f64 =
            a.tangential_force.iter().zip(&a.slip_increment).map(|(t, s)| t.abs() * u + lambda * s.abs()).sum();
        let d = d.max(a.dissipation.abs()).max(f64::MIN_POSITIVE);
        assert!(
            (a.dissipation - b.dissipation).abs() <= 1e-10 * d,
            "step {i}: dissipation {} against {}",
            a.dissipation,
            b.dissipation
        );
    }
}

#[test]
fn frictionless_contact_through_a_tilted_gap() {
    let problem = two_blocks(CellKind::Quad9, 0.01, 0.05, 3.0, 0.03, 7, 5);
    let schedule = LoadSchedule::ramp(vec!["main".into()], 3).unwrap();
    let (condensed, sparse) = both_paths(&problem, &schedule);
    assert!(condensed.steps.last().unwrap().solution.state.contains(&contact2d_contact::PairState::Free));
    assert_agree(&condensed, &sparse);
}

#[test]
fn coulomb_press_and_slide_through_stick_and_slip() {
    let mut problem = two_blocks_sliding(CellKind::Quad9, 0.0, 0.005, 2.0, 0.05, 0.02, 8, 6);
    problem.set_friction(0.3).unwrap();
    let schedule = LoadSchedule::ramp(vec!["main".into()], 4).unwrap();
    let (condensed, sparse) = both_paths(&problem, &schedule);
    let states = &condensed.steps.last().unwrap().solution.state;
    assert!(
        states.iter().any(|s| matches!(
            s,
            contact2d_contact::PairState::SlipPositive | contact2d_contact::PairState::SlipNegative
        ))
    );
    assert_agree(&condensed, &sparse);
}

/// Beyond [`contact2d_contact::SPARSE_FROM_PAIRS`] pairs the problem defers `K`'s own factor,
/// and the sparse path's active set never asks for it (its solves with `K` alone use the state
/// system with every row off); the condensed path, asked for, borders `K` itself. The two
/// paths still agree, and the deferred factor, made on demand, solves `K u = f`.
#[test]
fn a_long_interface_is_solved_without_a_factor_of_k_alone() {
    let problem = two_blocks(CellKind::Quad4, 0.0, 0.01, 2.0, 0.01, 2400, contact2d_contact::SPARSE_FROM_PAIRS);
    assert!(problem.num_pairs() > contact2d_contact::SPARSE_FROM_PAIRS);
    assert!(!problem.is_factored() && !problem.is_bordered());
    let schedule = LoadSchedule::ramp(vec!["main".into()], 1).unwrap();
    let (condensed, sparse) = both_paths(&problem, &schedule);
    assert!(condensed.steps.last().unwrap().solution.state.contains(&contact2d_contact::PairState::Free));
    assert_agree(&condensed, &sparse);
    assert!(!problem.is_factored(), "neither path made K's own factor");
    // Made now: K u = r to round-off (a backward-stable Cholesky solve: the residual is a few
    // ε ‖K‖ ‖u‖; 1e-10 of ‖r‖ leaves orders of margin on this well-conditioned mesh).
    let u = problem.solver().unwrap().solve(&problem.pattern_rhs);
    assert!(problem.is_factored());
    let k = problem.system.stiffness.as_ref();
    let mut ku = vec![0.0; u.len()];
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            ku[i] += v * u[j];
            if i != j {
                ku[j] += v * u[i];
            }
        }
    }
    let norm = |x: &[f64]| x.iter().map(|v| v * v).sum::<f64>().sqrt();
    let residual: Vec<f64> = ku.iter().zip(&problem.pattern_rhs).map(|(a, b)| a - b).collect();
    assert!(norm(&residual) <= 1e-10 * norm(&problem.pattern_rhs), "‖K u − r‖ = {:e}", norm(&residual));
}

/// Lower block `lower` × [−1, 0] (`na` cells along x), upper block [0.5, 2.5] × [0, 1] (`nb`),
/// Quad9; the upper block pressed by q = 10 and slid by its top (u1 only: it floats in y).
fn floating_description(lower: [f64; 2], na: usize, nb: usize, pairing: Pairing) -> ProblemDescription {
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, lower, [-1.0, 0.0], na, 3), "a_");
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.5, 2.5], [0.0, 1.0], nb, 3), "b_");
    let body = |region: &str, e: f64| BodyDescription {
        region: region.into(),
        youngs_modulus: e,
        poissons_ratio: 0.3,
        kinematics: Kinematics::PlaneStrain { thickness: 1.0 },
        formulation: Formulation::Standard,
    };
    let fix = |group: &str, component, value, pattern: &str| FixDescription {
        group: group.into(),
        component,
        value,
        pattern: pattern.into(),
    };
    ProblemDescription {
        mesh,
        bodies: vec![body("a_domain", 1000.0), body("b_domain", 2000.0)],
        fixes: vec![
            fix("a_bottom", Component::X, 0.0, "main"),
            fix("a_bottom", Component::Y, 0.0, "main"),
            fix("b_top", Component::X, 0.02, "slide"),
        ],
        loads: vec![LoadDescription {
            group: "b_top".into(),
            kind: EdgeLoadKind::Pressure(10.0),
            pattern: "press".into(),
        }],
        node_fixes: vec![],
        node_loads: vec![],
        contacts: vec![ContactDescription {
            name: "joint".into(),
            master: "b_bottom".into(),
            slave: "a_top".into(),
            rigid_slave: false,
            pairing,
            gap: GapDescription::Geometric,
            friction: 0.3,
            self_contact: false,
        }],
    }
}

/// The floating block's history: pressed, then slid by 0.3, 0.6 and 1 of the "slide" pattern.
fn press_and_slide() -> LoadSchedule {
    LoadSchedule::new(
        vec!["press".into(), "slide".into()],
        vec![vec![1.0, 0.0], vec![1.0, 0.3], vec![1.0, 0.6], vec![1.0, 1.0]],
    )
    .unwrap()
}

#[test]
fn a_floating_block_pressed_and_slid_with_every_pairing() {
    for &pairing in Pairing::ALL {
        // Node-to-node: a lower block as wide as the upper one, the meshes matching (one slave
        // node per pair); otherwise a wider lower block with non-matching cells (7 against 4).
        let (lower, na) = if pairing == Pairing::NodeToNode { ([0.5, 2.5], 4) } else { ([0.0, 3.0], 7) };
        let built = floating_description(lower, na, 4, pairing).build().unwrap();
        assert_eq!(built.problem.system.floating.len(), 1, "{pairing:?}");
        let schedule = press_and_slide();
        let (condensed, sparse) = both_paths(&built.problem, &schedule);
        assert_agree(&condensed, &sparse);
    }
}

#[test]
fn sparse_is_refused_for_the_algorithms_that_need_the_compliances() {
    for algorithm in [ContactAlgorithm::Clarabel, ContactAlgorithm::Boussinesq] {
        let refused = SolverSettings::new(algorithm).with_linear(LinearSolver::Sparse);
        assert!(matches!(refused, Err(contact2d_contact::ContactError::NotApplicable { .. })), "{algorithm:?}");
    }
}

#[test]
fn the_compliance_algorithms_condense_a_sparse_interface_themselves() {
    // Clarabel's entry point given the sparse path's interface (no compliances) condenses the
    // problem itself: the same answer as on the condensed interface, bit for bit (the same
    // computation).
    let problem = two_blocks(CellKind::Quad9, 0.01, 0.05, 3.0, 0.03, 7, 5);
    let on_condensed =
        contact2d_contact::solve_frictionless_qp_on(&problem, &contact2d_contact::Interface::new(&problem), 1.0);
    let on_sparse =
        contact2d_contact::solve_frictionless_qp_on(&problem, &contact2d_contact::Interface::sparse(&problem), 1.0);
    assert_eq!(on_condensed.status, on_sparse.status);
    assert_eq!(on_condensed.normal_force, on_sparse.normal_force);
}

#[test]
fn the_full_system_algorithms_give_the_same_answer_on_either_path() {
    // The augmented Lagrangian and the penalty method solve each Newton iteration condensed onto
    // the pairs' rows on the condensed path and by a sparse LU of the full system on the sparse
    // path (`algorithms/pair_space.rs`): the same iterates, so the same statuses, iteration
    // counts and states, and answers that differ by the two factorisations' round-off only:
    // cond · ε ≈ 1e-10 of the largest force (condition ~1e6), times κ = 1e3 for the penalty
    // (its matrix K + ε BᵀB and λ = −ε gap multiply the round-off by the penalty).
    let mut problem = two_blocks_sliding(CellKind::Quad9, 0.0, 0.005, 2.0, 0.05, 0.02, 6, 4);
    problem.set_friction(0.3).unwrap();
    let schedule = LoadSchedule::ramp(vec!["main".into()], 2).unwrap();
    for algorithm in [ContactAlgorithm::AugmentedLagrangian, ContactAlgorithm::Penalty] {
        let tolerance = if algorithm == ContactAlgorithm::Penalty { 1e-7 } else { 1e-10 };
        let run = |linear| {
            let settings = SolverSettings::new(algorithm).with_linear(linear).unwrap();
            solve(&problem, &settings, &schedule).unwrap()
        };
        let (condensed, sparse) = (run(LinearSolver::Condensed), run(LinearSolver::Sparse));
        assert_eq!(condensed.steps.len(), sparse.steps.len(), "{algorithm:?}");
        for (a, b) in condensed.steps.iter().zip(&sparse.steps) {
            let (a, b) = (&a.solution, &b.solution);
            assert_eq!(a.status, b.status, "{algorithm:?}");
            assert_eq!(a.iterations, b.iterations, "{algorithm:?}");
            assert_eq!(a.state, b.state, "{algorithm:?}");
            let largest = |v: &[f64]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let apart = |x: &[f64], y: &[f64]| x.iter().zip(y).fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
            let force = apart(&a.normal_force, &b.normal_force).max(apart(&a.tangential_force, &b.tangential_force));
            assert!(force <= tolerance * largest(&b.normal_force), "{algorithm:?}: forces {force:.2e} apart");
            let u = apart(&a.displacement, &b.displacement);
            assert!(u <= tolerance * largest(&b.displacement), "{algorithm:?}: displacements {u:.2e} apart");
        }
    }
}

/// The blocks of [`two_blocks_sliding`] in Q4 with `nb` cells along the upper block (`nb + 1`
/// pairs): pressed through a tilted gap (some pairs open) and, with `mu`, slid by 0.2 of the press.
fn tilted_press(nb: usize, mu: f64) -> ContactProblem {
    let slide = if mu > 0.0 { 0.002 } else { 0.0 };
    let mut problem = two_blocks_sliding(CellKind::Quad4, 0.0, 0.01, 2.0, 0.01, slide, nb * 6 / 5, nb);
    problem.set_friction(mu).unwrap();
    problem
}

/// One step of `problem` by the active set on `linear`: its solution.
fn one_step(problem: &ContactProblem, linear: LinearSolver) -> contact2d_contact::ContactSolution {
    let settings = SolverSettings::new(ContactAlgorithm::ActiveSet).with_linear(linear).unwrap();
    let schedule = LoadSchedule::ramp(vec!["main".into()], 1).unwrap();
    solve(problem, &settings, &schedule).unwrap().steps.remove(0).solution
}

/// Refining the tilted press: every mesh converges, and the iterations grow like the number of
/// coarse levels (`algorithms/coarse_start.rs`), not like the pair count. Before the coarse
/// levels the frictionless press took 39, 75 iterations at 501, 1,001 pairs and stopped at the
/// limit of 100 at 2,001; with μ = 0.3 the sparse path stopped at the limit from 501 pairs.
/// Measured now: 32, 35, 38, 40 (frictionless) and 39, 45, 50, 54 (μ = 0.3; condensed 43 and
/// 47 at 501 and 1,001) at 501 to 4,001 pairs, a few per doubling (one more level); the bound
/// of 8 per doubling would fail at the walk's rate (about a tenth of the pairs per doubling here).
#[test]
fn iterations_grow_like_the_levels_not_the_pairs() {
    for mu in [0.0, 0.3] {
        let mut counts = vec![];
        for nb in [500, 1000, 2000, 4000] {
            let problem = tilted_press(nb, mu);
            let sparse = one_step(&problem, LinearSolver::Sparse);
            assert_eq!(sparse.status, ContactStatus::Converged, "μ = {mu}, {} pairs: sparse", problem.num_pairs());
            assert!(sparse.state.contains(&contact2d_contact::PairState::Free), "some pairs open");
            if nb <= 1000 {
                // The condensed path as the second algorithm (its dense blocks grow like the
                // pairs cubed, so only the smaller meshes).
                let condensed = one_step(&problem, LinearSolver::Condensed);
                assert_eq!(condensed.status, ContactStatus::Converged, "μ = {mu}, {nb}: condensed");
                assert_eq!(condensed.state, sparse.state, "μ = {mu}, {nb}: the same states");
                // Both settle in the same state and solve its equations backward-stably (module
                // docs): 1e-10 of the largest force.
                let scale = condensed.normal_force.iter().fold(0.0f64, |a, v| a.max(v.abs()));
                for (a, b) in condensed.normal_force.iter().zip(&sparse.normal_force) {
                    assert!((a - b).abs() <= 1e-10 * scale, "μ = {mu}, {nb}: λ {a} against {b}");
                }
            }
            counts.push(sparse.iterations);
        }
        println!("μ = {mu}: iterations {counts:?} at 501, 1,001, 2,001, 4,001 pairs");
        for pair in counts.windows(2) {
            assert!(pair[1] <= pair[0] + 8, "μ = {mu}: iterations {counts:?} grow by more than 8 per doubling");
        }
    }
}

/// A block held vertically only by contact, beyond [`contact2d_contact::SPARSE_FROM_PAIRS`]
/// pairs: the sparse path's floating iteration solves with `K` alone, so it makes the deferred
/// factor at its first solve (`crate::stiffness_factor`), and the step balances. Truths: the
/// block is pressed by q = 10 over its width 2 and held along y by the interface alone, so the
/// pair forces sum to 20 (a conservation law; the floating iteration stops at 1e-10 of the force
/// scale, and summing 2,001 forces adds ~1e-13: 1e-8 of 20 is a margin); the same states and
/// forces whether the deferred factor was made before the solve or by it (one factor of `K`,
/// the same bits).
#[test]
fn a_floating_block_on_a_long_interface_makes_the_deferred_factor_when_it_needs_it() {
    let mut built = floating_description([0.0, 3.0], 1300, 1000, Pairing::NodeToSegment).build().unwrap();
    // Frictionless, to keep the test short: the pressed and slid block with μ = 0.3 is the
    // next test's (at 2,001 pairs it converges in 138 to 206 iterations a step on the sparse
    // path; docs/benchmarks.md).
    built.problem.set_friction(0.0).unwrap();
    let problem = &built.problem;
    assert!(problem.num_pairs() > contact2d_contact::SPARSE_FROM_PAIRS);
    assert_eq!(problem.system.floating.len(), 1);
    assert!(!problem.is_factored());
    let schedule = LoadSchedule::new(vec!["press".into(), "slide".into()], vec![vec![1.0, 0.0]]).unwrap();
    let settings = SolverSettings::new(ContactAlgorithm::ActiveSet).with_linear(LinearSolver::Sparse).unwrap();
    let deferred = solve(problem, &settings, &schedule).unwrap().steps.remove(0).solution;
    assert!(problem.is_factored(), "the floating iteration made K's factor");
    assert_eq!(deferred.status, ContactStatus::Converged);
    let total: f64 = deferred.normal_force.iter().sum();
    assert!((total - 20.0).abs() <= 1e-8 * 20.0, "Σλ = {total}");
    let again = solve(problem, &settings, &schedule).unwrap().steps.remove(0).solution;
    assert_eq!(again.state, deferred.state);
    assert_eq!(again.normal_force, deferred.normal_force);
}

/// A block held only by contact, pressed and then slid through three steps with μ = 0.3, on a
/// long interface (1,001 pairs). Before the coarse levels ran from any start and longer state
/// cycles were broken (`semi_smooth.rs`), the first slide step walked its stick–slip fronts a
/// pair every other iteration from the press's states and stopped at `max_iterations` on the
/// condensed path, and the sparse path stopped in its second slide step, while 501 pairs
/// converged: a refined mesh failing where a coarse one converges. Truths: both paths end every
/// step in the same states and forces to 1e-10 (`assert_agree`), and the pair forces sum to the
/// press q × width = 20 in every step (equilibrium of the block along y, which only the
/// interface holds; 1e-8 of 20 as in the test above).
#[test]
fn a_floating_block_pressed_and_slid_converges_on_a_long_interface() {
    let built = floating_description([0.0, 3.0], 650, 500, Pairing::NodeToSegment).build().unwrap();
    assert_eq!(built.problem.num_pairs(), 1001);
    assert_eq!(built.problem.system.floating.len(), 1);
    let schedule = press_and_slide();
    let (condensed, sparse) = both_paths(&built.problem, &schedule);
    assert_agree(&condensed, &sparse);
    for (i, step) in sparse.steps.iter().enumerate() {
        let total: f64 = step.solution.normal_force.iter().sum();
        assert!((total - 20.0).abs() <= 1e-8 * 20.0, "step {i}: Σλ = {total}");
        let slipping = step
            .solution
            .state
            .iter()
            .filter(|s| {
                matches!(s, contact2d_contact::PairState::SlipPositive | contact2d_contact::PairState::SlipNegative)
            })
            .count();
        println!(
            "step {i}: {} and {} iterations, {slipping} pairs slipping",
            condensed.steps[i].solution.iterations, step.solution.iterations
        );
    }
}

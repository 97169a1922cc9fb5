//! Bodies held only by contact, built with the problem builder and solved through the one entry
//! point, against equilibrium and Coulomb's law (closed forms, no stored output).
//!
//! ```text
//!        q (pressure, pattern "press")      and/or u1 = d on b_top (pattern "slide")
//!   ┌──────────────────┐  upper block "b_domain": no Dirichlet condition in y (floating)
//!   └──────────────────┘  master b_bottom ── touching, gap 0 ──
//!   ┌──────────────────────────┐  lower block "a_domain", slave a_top
//!   └──────────────────────────┘  a_bottom clamped
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_contact::{
    BodyDescription, ContactAlgorithm, ContactDescription, ContactError, ContactStatus, EdgeLoadKind, FixDescription,
    GapDescription, LoadDescription, LoadSchedule, Pairing, ProblemDescription, SolverSettings, solve,
};
use contact2d_element::{Formulation, Kinematics};
use contact2d_fem::Component;
use contact2d_mesh::generate::{append_prefixed, rectangle};
use contact2d_mesh::{CellKind, Mesh};

/// Lower block [0, 3] × [−1, 0] with `na` cells along x, upper block [x0, x1] × [0, 1] with `nb`.
fn blocks(na: usize, upper: [f64; 2], nb: usize) -> Mesh {
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.0, 3.0], [-1.0, 0.0], na, 3), "a_");
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, upper, [0.0, 1.0], nb, 3), "b_");
    mesh
}

fn body(region: &str, e: f64) -> BodyDescription {
    BodyDescription {
        region: region.into(),
        youngs_modulus: e,
        poissons_ratio: 0.3,
        kinematics: Kinematics::PlaneStrain { thickness: 1.0 },
        formulation: Formulation::Standard,
    }
}

fn fix(group: &str, component: Component, value: f64, pattern: &str) -> FixDescription {
    FixDescription { group: group.into(), component, value, pattern: pattern.into() }
}

fn description(mesh: Mesh, friction: f64, pressure: f64, slide: Option<f64>) -> ProblemDescription {
    let mut fixes = vec![fix("a_bottom", Component::X, 0.0, "main"), fix("a_bottom", Component::Y, 0.0, "main")];
    if let Some(d) = slide {
        fixes.push(fix("b_top", Component::X, d, "slide"));
    }
    ProblemDescription {
        mesh,
        bodies: vec![body("a_domain", 1000.0), body("b_domain", 2000.0)],
        fixes,
        loads: vec![LoadDescription {
            group: "b_top".into(),
            kind: EdgeLoadKind::Pressure(pressure),
            pattern: "press".into(),
        }],
        node_fixes: vec![],
        node_loads: vec![],
        contacts: vec![ContactDescription {
            name: "joint".into(),
            master: "b_bottom".into(),
            slave: "a_top".into(),
            rigid_slave: false,
            pairing: Pairing::NodeToSegment,
            gap: GapDescription::Geometric,
            friction,
            self_contact: false,
        }],
    }
}

#[test]
fn a_floating_block_pressed_by_a_force_carries_it_in_contact() {
    // Equal widths and matching meshes, the lower block on rollers (u2 = 0 at its bottom, u1 = 0
    // on its left side) and the upper block guided (u1 = 0 on its left side), frictionless:
    // both blocks are in uniform stress σ22 = −q, so the contact pressure is q everywhere.
    // Only u2 of the upper block is free: it is held by the contact alone. Tolerance 1e-8: the
    // proximal iteration stops at a spring force of 1e-10 of the force scale.
    let mut d = description(blocks(6, [0.0, 3.0], 6), 0.0, 10.0, None);
    d.fixes = vec![
        fix("a_bottom", Component::Y, 0.0, "main"),
        fix("a_left", Component::X, 0.0, "main"),
        fix("b_left", Component::X, 0.0, "main"),
    ];
    let built = d.build().unwrap();
    assert_eq!(built.problem.system.floating.len(), 1);
    assert_eq!(built.problem.system.floating[0].body, "b_domain");
    let settings = SolverSettings::new(ContactAlgorithm::ActiveSet);
    let schedule = LoadSchedule::ramp(vec!["press".into()], 1).unwrap();
    let history = solve(&built.problem, &settings, &schedule).unwrap();
    let step = &history.steps[0];
    assert_eq!(step.solution.status, ContactStatus::Converged);
    assert!(step.floating_iterations >= 1, "the proximal iteration ran");
    let total: f64 = step.solution.normal_force.iter().sum();
    assert!((total - 10.0 * 3.0).abs() < 1e-9 * 30.0, "normal force {total} against q·width = 30");
    for (pair, lambda) in built.problem.pairs.iter().zip(&step.solution.normal_force) {
        let p = lambda / pair.weight;
        assert!((p - 10.0).abs() < 1e-8 * 10.0, "pressure {p} at x = {:?}", pair.slave_point);
    }
    // Every algorithm takes the same floating problem: Clarabel agrees to its accuracy (1e-6).
    let qp = solve(&built.problem, &SolverSettings::new(ContactAlgorithm::Clarabel), &schedule).unwrap();
    let qp_total: f64 = qp.steps[0].solution.normal_force.iter().sum();
    assert!((qp_total - 30.0).abs() < 1e-6 * 30.0, "Clarabel: {qp_total}");
}

#[test]
fn press_then_slide_reaches_coulomb_gross_sliding() {
    // Pressed by q = 10 over width 2 (P = 20, force control, held constant), then the top is
    // slid far enough for the whole interface to slip: the tangential force is μ P exactly
    // (Coulomb), and the horizontal reaction on the slid top balances it.
    let mu = 0.3;
    let built = description(blocks(6, [0.5, 2.5], 4), mu, 10.0, Some(0.05)).build().unwrap();
    let names: Vec<&str> = built.problem.patterns().iter().map(|p| p.name.as_str()).collect();
    assert_eq!(names.len(), 2);
    assert!(names.contains(&"press") && names.contains(&"slide"));
    let schedule = LoadSchedule::new(
        vec!["press".into(), "slide".into()],
        vec![vec![1.0, 0.0], vec![1.0, 0.25], vec![1.0, 0.5], vec![1.0, 1.0]],
    )
    .unwrap();
    let history = solve(&built.problem, &SolverSettings::new(ContactAlgorithm::ActiveSet), &schedule).unwrap();
    assert!(!history.scaled);
    assert_eq!(history.steps.len(), 4);
    let last = history.steps.last().unwrap();
    assert_eq!(last.solution.status, ContactStatus::Converged);
    let normal: f64 = last.solution.normal_force.iter().sum();
    let tangential: f64 = last.solution.tangential_force.iter().sum();
    assert!((normal - 20.0).abs() < 1e-8 * 20.0, "normal {normal}");
    assert!((tangential.abs() - mu * 20.0).abs() < 1e-8 * 20.0, "tangential {tangential} against μP = {}", mu * 20.0);
    // Reactions: the slid top carries −τ in x (the block is in equilibrium).
    let reactions = built.problem.reactions(&last.solution, &last.factors).unwrap();
    let dofs = &built.problem.system.dofs;
    let top: f64 = dofs
        .constrained_dofs()
        .iter()
        .zip(&reactions)
        .filter(|(d, _)| d.0 % 2 == 0 && built.problem.model.mesh.points[d.node()][1] > 0.5)
        .map(|(_, r)| r)
        .sum();
    assert!((top.abs() - mu * 20.0).abs() < 1e-7 * 20.0, "top reaction {top}");
    assert!(last.dissipated > 0.0);
    // Every constrained DOF once: the clamped bottom and the slid top balance the press P = 20
    // (x2) and each other (x1); the pairs are internal (their resultants vanish).
    let mut total = [0.0; 2];
    for (d, r) in dofs.constrained_dofs().iter().zip(&reactions) {
        total[d.0 % 2] += r;
    }
    assert!(total[0].abs() < 1e-7 * 20.0 && (total[1] - 20.0).abs() < 1e-7 * 20.0, "total {total:?}");
    for k in 0..built.problem.num_pairs() {
        let (lambda, tau) = (last.solution.normal_force[k], last.solution.tangential_force[k]);
        let r = built.problem.pair_resultant(k, lambda, tau).unwrap();
        assert!(r[0].hypot(r[1]) <= 1e-12 * (lambda.abs() + tau.abs()).max(1.0), "pair {k}: {r:?}");
    }
    // Bad input is an error, not a panic.
    let mut short = last.solution.clone();
    short.normal_force.pop();
    assert!(matches!(built.problem.reactions(&short, &last.factors), Err(ContactError::InvalidInput(_))));
    assert!(matches!(built.problem.reactions(&last.solution, &[1.0]), Err(ContactError::InvalidInput(_))));
    assert!(matches!(built.problem.pair_resultant(usize::MAX, 1.0, 0.0), Err(ContactError::InvalidInput(_))));
}

#[test]
fn a_block_pulled_away_is_reported_not_held() {
    // A negative pressure pulls the floating block off: nothing holds it in y.
    let built = description(blocks(6, [0.5, 2.5], 4), 0.0, -10.0, None).build().unwrap();
    let schedule = LoadSchedule::ramp(vec!["press".into()], 1).unwrap();
    match solve(&built.problem, &SolverSettings::new(ContactAlgorithm::ActiveSet), &schedule) {
        Err(ContactError::BodyNotHeld { body, modes, step, .. }) => {
            assert_eq!(body, "b_domain");
            assert_eq!(step, 1);
            assert!(modes.iter().any(|m| m == "u2 translation"), "{modes:?}");
        }
        other => panic!("expected BodyNotHeld, got {other:?}"),
    }
}

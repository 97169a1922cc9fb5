//! The sliding patch test of finite sliding: a block pressed onto a long base and pushed along it
//! by ten base cells, the pairs formed again on the current configuration inside every step until
//! they hold, asserted against equilibrium and Coulomb's law (closed forms, no stored output).
//!
//! ```text
//!            q (pattern "press"), u1 = d on b_top (pattern "slide")
//!        ┌────┐ ──────────────────────→ ┌────┐   upper block "b_domain" [0.5, 1.5] × [0, 1]
//!   ┌────┴────┴─────────────────────────┴────┴────┐  base "a_domain" [0, 6] × [−1, 0], 24 cells
//!   └─────────────────────────────────────────────┘  a_bottom clamped
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_contact::finite_sliding::solve_finite_sliding;
use contact2d_contact::{
    BodyDescription, BuiltProblem, ContactAlgorithm, ContactDescription, ContactError, ContactStatus, EdgeLoadKind,
    FixDescription, GapDescription, LoadDescription, LoadSchedule, PairState, Pairing, ProblemDescription, Retention,
    SolverSettings,
};
use contact2d_element::{Formulation, Kinematics};
use contact2d_fem::Component;
use contact2d_mesh::CellKind;
use contact2d_mesh::Mesh;
use contact2d_mesh::generate::{append_prefixed, rectangle};

/// Base cells along x over [0, 6]: a cell of 0.25.
const BASE_CELLS: usize = 24;
const CELL: f64 = 6.0 / BASE_CELLS as f64;
/// The push: ten base cells.
const PUSH: f64 = 10.0 * CELL;
const MU: f64 = 0.3;
/// Pressure on the block's top, width 1: the press P = q · 1.
const Q: f64 = 10.0;

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

/// The base and a block of width 1 at [0.5, 1.5] with `block_cells` cells along x.
fn scene(block_cells: usize, pairing: Pairing) -> ProblemDescription {
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.0, 6.0], [-1.0, 0.0], BASE_CELLS, 3), "a_");
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.5, 1.5], [0.0, 1.0], block_cells, 3), "b_");
    ProblemDescription {
        mesh,
        bodies: vec![body("a_domain", 1000.0), body("b_domain", 2000.0)],
        fixes: vec![
            fix("a_bottom", Component::X, 0.0, "main"),
            fix("a_bottom", Component::Y, 0.0, "main"),
            fix("b_top", Component::X, PUSH, "slide"),
        ],
        loads: vec![LoadDescription {
            group: "b_top".into(),
            kind: EdgeLoadKind::Pressure(Q),
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
            friction: MU,
            self_contact: false,
        }],
    }
}

/// Press, then push in `steps` equal steps.
fn schedule(steps: usize) -> LoadSchedule {
    let mut factors = vec![vec![1.0, 0.0]];
    factors.extend((1..=steps).map(|j| vec![1.0, j as f64 / steps as f64]));
    LoadSchedule::new(vec!["press".into(), "slide".into()], factors).unwrap()
}

/// What one solved step left: its pairs' current geometry and its forces.
struct Seen {
    push: f64,
    normal: Vec<f64>,
    tangential: Vec<f64>,
    state: Vec<PairState>,
    /// Per pair: the y components of the force on the block per unit λ and τ.
    directions: Vec<[f64; 2]>,
    /// Per pair: the block node's x where the step ended (`X + u`) and the x of its projection
    /// on the base, on the pairs the step was solved on (formed again on its answer until they
    /// hold).
    follows: Vec<(f64, f64)>,
    /// The contact forces on the block, summed over its nodes at their reference positions:
    /// `[Σ f_x, Σ f_y, Σ (X − X_c) f_y − (Y − Y_top) f_x]`, the moment about the block's
    /// reference top centre `(X_c, Y_top) = (1, 1)`.
    resultant: [f64; 3],
}

fn run(built: &BuiltProblem, settings: &SolverSettings, steps: usize) -> Vec<Seen> {
    let mut seen = vec![];
    let slide = built.problem.patterns().iter().position(|p| p.name == "slide").unwrap();
    let mut on_step = |_: usize, step: &contact2d_contact::SolvedStep, current: &BuiltProblem| {
        let problem = &current.problem;
        let points = &problem.model.mesh.points;
        let u = &step.solution.displacement;
        let follows =
            problem.pairs.iter().map(|p| (points[p.master.0][0] + u[2 * p.master.0], p.slave_point[0])).collect();
        // The y components of the force per unit λ and τ on the block: n and t of a node-to-segment
        // pair; of a segment-to-segment pair the sums of its master coefficients,
        // (1/w) ∫ φ_k (n_y, t_y) ds (the mean of the normal along the segment, not normalised).
        let directions = problem
            .pairs
            .iter()
            .map(|p| match &p.integrated {
                None => [p.normal[1], p.tangent[1]],
                Some(rows) => rows.master.iter().fold([0.0, 0.0], |a, c| [a[0] + c.normal[1], a[1] + c.tangent[1]]),
            })
            .collect();
        // The force on the block per unit λ and τ at each of its nodes: n and t at a
        // node-to-segment pair's node; a segment-to-segment pair's master coefficients.
        let mut resultant = [0.0; 3];
        for (k, p) in problem.pairs.iter().enumerate() {
            let (l, t) = (step.solution.normal_force[k], step.solution.tangential_force[k]);
            let at = |node: usize, n: [f64; 2], tg: [f64; 2]| {
                let f = [l * n[0] + t * tg[0], l * n[1] + t * tg[1]];
                let x = points[node];
                [f[0], f[1], (x[0] - 1.0) * f[1] - (x[1] - 1.0) * f[0]]
            };
            let forces: Vec<[f64; 3]> = match &p.integrated {
                None => vec![at(p.master.0, p.normal, p.tangent)],
                Some(rows) => rows.master.iter().map(|c| at(c.node.0, c.normal, c.tangent)).collect(),
            };
            for f in forces {
                (0..3).for_each(|i| resultant[i] += f[i]);
            }
        }
        seen.push(Seen {
            resultant,
            push: step.factors[slide] * PUSH,
            normal: step.solution.normal_force.clone(),
            tangential: step.solution.tangential_force.clone(),
            state: step.solution.state.clone(),
            directions,
            follows,
        });
        assert_eq!(step.solution.status, ContactStatus::Converged, "step at push {}", step.factors[slide] * PUSH);
    };
    let (history, _) =
        solve_finite_sliding(built, &[true], settings, &schedule(steps), Retention::All, &mut on_step).unwrap();
    assert_eq!(history.steps.len(), steps + 1);
    seen
}

/// The checks every mesh passes: the press carried (equilibrium), Coulomb's law on every
/// slipping pair and μΣλ in gross sliding, and the pairs under the block.
fn check_equilibrium_and_coulomb(seen: &[Seen], label: &str) {
    let p = Q * 1.0;
    for s in seen {
        // Equilibrium of the block in y (held by the contact alone): the pairs' forces along
        // their current normals and tangents carry P. Not Σλ = P: the base's surface under the
        // block is tilted by O(q/E) = 1e-2, and μP of friction along it carries 3e-3 of P
        // (measured: Σλ from 1.003 P to 1.009 P on the matching mesh, to 1.021 P on the
        // non-matching one). Tolerance 1e-8 P: the floating iteration
        // stops at a spring force of 1e-10 of the force scale.
        let vertical: f64 =
            s.normal.iter().zip(&s.tangential).zip(&s.directions).map(|((l, t), [ny, ty])| l * ny + t * ty).sum();
        let normal: f64 = s.normal.iter().sum();
        let tangential: f64 = s.tangential.iter().sum();
        eprintln!("{label} push {:.4}: Σλ {normal:.9} Στ {tangential:.9} vertical {vertical:.9}", s.push);
        assert!((vertical.abs() - p).abs() <= 1e-8 * p, "{label} push {}: vertical {vertical}, P = {p}", s.push);
        // Coulomb on every slipping pair, |τ| = μλ, to 1e-6 P as the issue asks; in gross sliding
        // (every pair in contact slips) Σ|τ| = μΣλ.
        for (k, st) in s.state.iter().enumerate() {
            if matches!(st, PairState::SlipPositive | PairState::SlipNegative) {
                let (l, t) = (s.normal[k], s.tangential[k]);
                assert!((t.abs() - MU * l).abs() <= 1e-6 * p, "{label} push {} pair {k}: τ {t}, λ {l}", s.push);
            }
        }
        let gross = s.state.iter().all(|st| *st != PairState::Stick);
        if gross {
            assert!(
                (tangential.abs() - MU * normal).abs() <= 1e-6 * p,
                "{label} push {}: Στ = {tangential}, μΣλ = {}",
                s.push,
                MU * normal
            );
        }
    }
    // After the first push the whole interface slips (the block is pushed by ten cells against a
    // stiffer base: the slip front crosses it within the first step of half a cell).
    let slipping = seen.iter().skip(2).all(|s| s.state.iter().all(|st| *st != PairState::Stick));
    assert!(slipping, "{label}: a pair sticks after the second push step");
    // Pairs follow the block: every block node projects onto the base within 1e-2 of a cell of
    // its own x where the step ended (the pairs are formed again on the step's answer until
    // they hold; the last solve moves a node by far less than that bound). Why that bound: a node lifted off (the trailing edge
    // tips, Free) or just past a segment end sits O(q/E · 1) = 1e-2 from a surface sloped or
    // kinked by O(q/E) = 1e-2, so its closest point is O(1e-4) from vertical, 4e-4 of a cell
    // (measured: 8e-5 of a cell on the matching mesh, 1.3e-3 on the non-matching one, at a
    // segment end); the bound keeps a factor of ten over that. A pair kept from the undeformed
    // configuration would project up to ten cells behind.
    for s in seen {
        for (k, (x, y)) in s.follows.iter().enumerate() {
            assert!((x - y).abs() <= 1e-2 * CELL, "{label} push {} pair {k}: node at {x}, projection {y}", s.push);
        }
    }
}

#[test]
fn a_block_pushed_ten_cells_on_a_matching_mesh_carries_mu_p_and_keeps_its_pairs() {
    // Matching: block cells of 0.25 like the base's, pushed in 20 steps of half a cell.
    let built = scene(4, Pairing::NodeToSegment).build().unwrap();
    let seen = run(&built, &SolverSettings::new(ContactAlgorithm::ActiveSet), 20);
    check_equilibrium_and_coulomb(&seen, "matching");
    // Translation invariance: at every whole-cell push the block sits on the base exactly as
    // after the first whole-cell push, up to the base's ends (3 to 7.5 block widths away); the
    // pressure profile is the same there. Stated measured gap (printed), not asserted tighter.
    let reference = &seen[2].normal;
    let mut worst = 0.0f64;
    for s in seen.iter().skip(2).step_by(2) {
        for (a, b) in s.normal.iter().zip(reference) {
            worst = worst.max((a - b).abs() / (Q * CELL));
        }
    }
    eprintln!("matching: largest change of a pair force across whole-cell pushes = {worst:.3e} of q·cell");
}

#[test]
fn a_block_pushed_ten_cells_on_a_non_matching_mesh_carries_mu_p() {
    // Non-matching: block cells of 0.2 over base cells of 0.25, pushed in 19 steps (0.132, not
    // a multiple of either cell), so block nodes cross base segment ends between steps.
    let built = scene(5, Pairing::NodeToSegment).build().unwrap();
    let seen = run(&built, &SolverSettings::new(ContactAlgorithm::ActiveSet), 19);
    check_equilibrium_and_coulomb(&seen, "non-matching");
    // The oscillation as nodes cross segment ends: the largest step-to-step change of a pair's
    // normal force in gross sliding, over the mean pair force P / pairs (measured, printed).
    let mean = Q / seen[0].normal.len() as f64;
    let mut worst = 0.0f64;
    for w in seen[2..].windows(2) {
        for (a, b) in w[0].normal.iter().zip(&w[1].normal) {
            worst = worst.max((a - b).abs() / mean);
        }
    }
    eprintln!("non-matching: largest step-to-step change of a pair force = {worst:.3e} of the mean");
}

#[test]
fn a_block_pushed_ten_cells_with_frictionless_segment_to_segment_pairs_carries_p() {
    // The non-matching mesh above, frictionless, with segment-to-segment pairs formed again on the
    // current configuration before every step. Closed forms: the press is carried along the
    // pairs' current normals (1e-8 P, the floating iteration's tolerance as above), no tangential
    // force, and the pairs follow the block (1e-2 of a cell, as above). (With μ = 0.3 the
    // frictional push is the test below.)
    let mut description = scene(5, Pairing::SegmentToSegment);
    description.contacts[0].friction = 0.0;
    let built = description.build().unwrap();
    let seen = run(&built, &SolverSettings::new(ContactAlgorithm::ActiveSet), 19);
    for s in &seen {
        let vertical: f64 = s.normal.iter().zip(&s.directions).map(|(l, [ny, _])| l * ny).sum();
        assert!((vertical.abs() - Q).abs() <= 1e-8 * Q, "push {}: vertical {vertical}, P = {Q}", s.push);
        assert!(s.tangential.iter().all(|t| *t == 0.0), "push {}: a tangential force", s.push);
        for (k, (x, y)) in s.follows.iter().enumerate() {
            assert!((x - y).abs() <= 1e-2 * CELL, "push {} pair {k}: node at {x}, projection {y}", s.push);
        }
    }
}

#[test]
fn clarabel_and_the_augmented_lagrangian_push_the_block_as_the_active_set_does() {
    // A second and a third algorithm on the same finite-sliding history (the matching mesh,
    // node to segment, μ = 0.3, 20 push steps): every step's normal forces agree with the
    // active set's to 1e-5 of the largest (the issue's bound; each algorithm's own stopping
    // rule is far tighter).
    let built = scene(4, Pairing::NodeToSegment).build().unwrap();
    let reference = run(&built, &SolverSettings::new(ContactAlgorithm::ActiveSet), 20);
    for algorithm in [ContactAlgorithm::Clarabel, ContactAlgorithm::AugmentedLagrangian] {
        let seen = run(&built, &SolverSettings::new(algorithm), 20);
        for (a, b) in seen.iter().zip(&reference) {
            let scale = b.normal.iter().fold(0.0f64, |m, l| m.max(l.abs()));
            for (x, y) in a.normal.iter().zip(&b.normal) {
                assert!((x - y).abs() <= 1e-5 * scale, "{algorithm:?} push {}: λ {x} against {y}", a.push);
            }
        }
    }
}

#[test]
fn what_finite_sliding_does_not_handle_is_refused_before_solving() {
    let built = scene(4, Pairing::NodeToSegment).build().unwrap();
    let mut nothing = |_: usize, _: &contact2d_contact::SolvedStep, _: &BuiltProblem| panic!("solved a step");
    for algorithm in [ContactAlgorithm::Penalty, ContactAlgorithm::Boussinesq] {
        let settings = SolverSettings::new(algorithm);
        let e =
            solve_finite_sliding(&built, &[true], &settings, &schedule(2), Retention::All, &mut nothing).unwrap_err();
        assert!(matches!(e, ContactError::NotApplicable { .. }), "{algorithm:?}: {e}");
    }
}

#[test]
fn a_block_pushed_with_frictional_segment_to_segment_pairs_slides_on_mu_p_without_tipping() {
    // The non-matching mesh, μ = 0.3, segment-to-segment pairs formed again on the current
    // configuration until they hold, 19 push steps. (It stopped at max_iterations at push 0.39:
    // the floating block's Newton iteration stalled on its leading corner pair — see
    // `floating.rs`, `landing_distance` and the engaged Jacobian.) Closed forms:
    // * equilibrium, Coulomb's law (|τ| = μλ on every slipping pair, Στ = μΣλ in gross sliding,
    //   1e-6 P) and the pairs following the block, as on the node-to-segment meshes above;
    // * no tipping: the block is held at its top in x only, so it is free to rotate about any
    //   point of its top line, and the contact alone balances the moment of the friction μP at
    //   lever arm H = 1: the contact's moment about the reference top centre vanishes (the
    //   pressure's resultant passes through it, the top's x reactions have no arm; the rigid
    //   modes are those of the reference geometry, small strain), to 1e-8 P·H (the floating
    //   iteration's tolerance, as for the vertical equilibrium), and the centre of pressure
    //   sits at e = Στ·H/Σf_y = μH = 0.3 ahead of the centre, inside the half-width 0.5 (the
    //   trailing 40 % lifts off, and the block stands on its leading part, not on a corner).
    let mut description = scene(5, Pairing::SegmentToSegment);
    description.contacts[0].friction = MU;
    let built = description.build().unwrap();
    let settings = SolverSettings::new(ContactAlgorithm::ActiveSet);
    let seen = run(&built, &settings, 19);
    check_equilibrium_and_coulomb(&seen, "segment to segment");
    for s in seen.iter().skip(2) {
        let [fx, fy, m] = s.resultant;
        let e = (m - fx) / fy;
        eprintln!(
            "segment to segment push {:.4}: moment {m:.3e}, centre of pressure {e:.9}, Σf_x/Σf_y {:.9}",
            s.push,
            fx / fy
        );
        assert!(m.abs() <= 1e-8 * Q, "push {}: moment {m}", s.push);
        // e = μH up to the tilt θ = O(q/E) = 1e-2 of the base's surface under the block:
        // Σf_x = Σ(λ n_x + τ t_x) differs from −μΣλ by O(θ) Σλ, so e/H − μ by O(θ); bound 2θ
        // (measured below 3e-3). And e < 0.5: the resultant inside the block's base.
        assert!((e - MU * 1.0).abs() <= 2e-2, "push {}: centre of pressure {e}, μH = {MU}", s.push);
        assert!(e < 0.5, "push {}: the block tips (centre of pressure {e})", s.push);
    }
    // The converged path: in gross sliding the state at a push does not depend on the steps
    // taken to it (every pair slips one way from the second step on, so Coulomb's law fixes
    // τ = −μλ whatever the path, and the pairs are formed on the push's own configuration). The
    // same push in 38 steps must give, at the common pushes: every block node's x to 1e-2 of a
    // cell (the bound of the pairs following the block, above) and every pair's normal force to
    // 1e-2 P — the pairing is accepted where its linearised gaps are within KINK_TOLERANCE =
    // 1e-3 of the mesh size h = 0.25 of the geometric ones, and a gap error of 2.5e-4 moves a
    // pair force by at most E·2.5e-4 = 0.25 = 2.5e-2 P on the base of E = 1000 (its nodal
    // stiffness per unit thickness is O(E)); bound 1e-2 P, measured 1.9e-3 P and 5.6e-4 of a
    // cell, printed.
    let fine = run(&built, &settings, 38);
    let mut worst = [0.0f64; 3];
    for (j, s) in seen.iter().enumerate().skip(2) {
        let f = &fine[2 * j];
        assert!((f.push - s.push).abs() <= 1e-12, "the same push");
        for (a, b) in s.normal.iter().zip(&f.normal) {
            worst[0] = worst[0].max((a - b).abs() / Q);
        }
        worst[1] = worst[1].max((s.resultant[2] - f.resultant[2]).abs() / Q);
        let u = |x: &Seen| x.follows.iter().map(|(a, _)| *a).collect::<Vec<_>>();
        for (a, b) in u(s).iter().zip(&u(f)) {
            worst[2] = worst[2].max((a - b).abs() / CELL);
        }
    }
    eprintln!(
        "19 against 38 steps: pair force {:.3e} P, moment {:.3e} P, node x {:.3e} cell",
        worst[0], worst[1], worst[2]
    );
    assert!(worst[0] <= 1e-2, "19 and 38 steps: a pair force differs by {} P", worst[0]);
    assert!(worst[1] <= 2e-8, "19 and 38 steps: the moments differ by {} P", worst[1]);
    assert!(worst[2] <= 1e-2, "19 and 38 steps: a node's x differs by {} of a cell", worst[2]);
}

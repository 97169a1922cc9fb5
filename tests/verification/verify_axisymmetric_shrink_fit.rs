//! Verification: a shrink fit of a solid shaft in a hub as bodies of revolution
//! (`scenes/generic/shrink_fit_axisymmetric.toml`, `kinematics = "axisymmetric"`), through the
//! scene, the pairing and every contact algorithm that solves it exactly.
//!
//! Citation: S. P. Timoshenko, J. N. Goodier (1970), Theory of Elasticity, 3rd ed., §28–§30
//! (thick cylinders, shrink fits); the shaft under external pressure is in the uniform state
//! u_r = −p r (1 + ν)(1 − 2ν)/E (plane strain along the axis), the hub Lamé's.
//!
//! Set-up: shaft 0 ≤ r ≤ b = 10, hub b ≤ r ≤ c = 20, length L = 10, both ends of both bodies held
//! axially (u_z = 0), E = 200 000, ν = 0.3, radial interference δ = 0.01 (the contact's gap),
//! frictionless; Q9, 8 × 8 cells per body. With the ends held the fit is Lamé's along its whole
//! length (no end effect):
//!
//! ```text
//! p = E δ / (b (1 + ν) [((1 − 2ν) b² + c²)/(c² − b²) + (1 − 2ν)]) = 82.4176
//! normal force (a total over the circumference) N = p 2π b L = 51 784
//! ```
//!
//! Tolerance: 1e-4 relative on N, on every pair's pressure and on the mean pressure. The shaft's
//! exact field is in the Q9 space; the hub's u_r = A r + B/r is not, and its interpolation
//! error on 8 cells across the wall is O(h³) ≈ 1e-5 relative (measured 3e-6); a wrong measure
//! (a pair weight without 2πr, or a load or stiffness without it) is an O(1) error.

use std::path::Path;

use contact2d::generic::{GenericReport, load_scene, solve_generic};

const SCENE: &str = "scenes/generic/shrink_fit_axisymmetric.toml";

fn run(sets: &[&str]) -> GenericReport {
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    solve_generic(&load_scene(Path::new(SCENE), &sets).unwrap(), &mut |_, _| {}).unwrap().report
}

#[test]
fn the_shrink_fit_carries_lames_pressure_over_the_whole_circumference() {
    let (e, nu, delta, b, c, length) = (200_000.0, 0.3, 0.01, 10.0, 20.0, 10.0);
    let p = e * delta / (b * (1.0 + nu) * (((1.0 - 2.0 * nu) * b * b + c * c) / (c * c - b * b) + (1.0 - 2.0 * nu)));
    let force = p * 2.0 * std::f64::consts::PI * b * length;
    for algorithm in ["active_set", "clarabel", "augmented_lagrangian", "boussinesq", "penalty"] {
        // The penalty answer penetrates by about 1e-3 of its pairs' displacement (δ/2 here), so
        // its pressure may be low by up to ~1e-3: bound 2e-3 for it (measured 1.7e-5).
        let tolerance = if algorithm == "penalty" { 2e-3 } else { 1e-4 };
        for pairing in ["segment_to_segment", "node_to_segment"] {
            let r = run(&[&format!("solver.algorithm={algorithm}"), &format!("contact.0.pairing={pairing}")]);
            let tag = format!("{algorithm} × {pairing}");
            assert_eq!(r.status, "converged", "{tag}");
            assert_eq!(r.kinematics, "axisymmetric");
            let fit = &r.contacts["fit"];
            assert!(
                (fit.normal_force - force).abs() < tolerance * force,
                "{tag}: N {} against {force}",
                fit.normal_force
            );
            let mean = fit.mean_pressure.unwrap();
            assert!((mean - p).abs() < tolerance * p, "{tag}: mean pressure {mean} against {p}");
            let profile = fit.profile.as_ref().unwrap();
            for q in &profile.pressure {
                assert!((q - p).abs() < tolerance * p, "{tag}: a pair's pressure {q} against {p}");
            }
            assert!(r.notes.iter().any(|n| n.contains("17 nodes on the axis")), "{tag}: {:?}", r.notes);
        }
    }
}

/// `tests/scenes/shrink_fit_axisymmetric_pull.toml`: the shaft held only by the fit (μ = 0.3),
/// whose one free rigid motion as a body of revolution is the axial translation, pulled by a total
/// axial force F = 0, 5 000, 10 000, 15 000. Statics and Coulomb: the fit carries the pull exactly
/// (Σ τ = F to 1e-9 of the larger of F and μN, the contact's force scale: the floating body's
/// equilibrium is solved to round-off; the augmented Lagrangian leaves 1.6e-12 of N at F = 0) while F < μN,
/// and where F > μN the run ends `not_held` at that step, its available force being μN of that
/// state (1e-9) and its ratio F / (μN) (1e-6: the demanded force is the pull as the statics LP
/// returns it, to its tolerance). Active set, Clarabel, the augmented Lagrangian and the penalty
/// (its own N: the available force is μN of the state it solved) alike.
#[test]
fn a_shaft_held_only_by_the_fit_holds_below_mu_n_and_is_not_held_above() {
    // Every algorithm that solves friction on a body held only by contact: the same statics.
    for algorithm in ["active_set", "clarabel", "augmented_lagrangian", "penalty"] {
        pull_out(algorithm);
    }
}

fn pull_out(algorithm: &str) {
    let mu = 0.3;
    let sets = vec![format!("solver.algorithm={algorithm}")];
    let scene = load_scene(Path::new("tests/scenes/shrink_fit_axisymmetric_pull.toml"), &sets).unwrap();
    let r = solve_generic(&scene, &mut |_, _| {}).unwrap().report;
    assert_eq!(r.status, "not_held", "{algorithm}: {:?}", r.failed_check);
    let pulls = [0.0, 5000.0, 10000.0, 15000.0];
    for (row, pull) in r.steps.iter().zip(pulls) {
        let fit = &row.contacts["fit"];
        if pull < mu * fit.normal_force {
            assert_eq!(row.status, "converged", "{algorithm}: pull {pull}");
            assert!(
                (fit.tangential_force - pull).abs() <= 1e-9 * pull.max(mu * fit.normal_force),
                "{algorithm}: pull {pull}: Σ τ {}",
                fit.tangential_force
            );
        } else {
            assert_eq!(row.status, "not_held", "{algorithm}: pull {pull}");
        }
    }
    let not_held = r.not_held.as_ref().unwrap();
    assert_eq!(not_held.step, 4);
    let fit = &r.steps.to_vec()[3].contacts["fit"];
    assert!((not_held.available - mu * fit.normal_force).abs() <= 1e-9 * not_held.available, "{algorithm}");
    let ratio = pulls[3] / (mu * fit.normal_force);
    assert!(
        (not_held.ratio - ratio).abs() <= 1e-6 * ratio,
        "{algorithm}: ratio {} against F/(μN) {ratio}",
        not_held.ratio
    );
}

/// The fit above on two mesh levels of every element type
/// (`meshes/generic/shrink_fit_axisymmetric_kinds.geo`: n × n cells per body, n = 4, 8 for the
/// quadratic kinds and 8, 16 for the linear ones, so h = b/n), with both pairings. The hub's
/// Lamé field u_r = A r + B/r is not in any element's space; its interpolation error, relative,
/// is at most (h/b)^(k+1) (k the degree; the constant is below 1 for 1/r on r ≥ b): the bound on
/// N on each level. Between the levels N converges at least at the displacement's L2 rate
/// k + 1 − 0.15 (the tube study's bound; it is a resultant, measured 2.0 linear, 3.9 quadratic),
/// and every pair's pressure at the wall stress's rate k − 0.5 (the tube study's bound:
/// triangles' diagonals split the wall unevenly, so their pair pressures oscillate around p,
/// measured 3.7 % → 2.1 % on T3, 0.9 % → 0.3 % on T6 node to segment, 6.5 % → 3.8 % and
/// 1.6 % → 0.5 % segment to segment; quadrilaterals' equal p to N's error).
#[test]
fn every_element_type_carries_the_fit_on_two_levels() {
    let (e, nu, delta, b, c, length) = (200_000.0, 0.3, 0.01, 10.0, 20.0, 10.0);
    let p = e * delta / (b * (1.0 + nu) * (((1.0 - 2.0 * nu) * b * b + c * c) / (c * c - b * b) + (1.0 - 2.0 * nu)));
    let force = p * 2.0 * std::f64::consts::PI * b * length;
    for (kind, degree, cells) in [("T3", 1, 8.0), ("Q4", 1, 8.0), ("T6", 2, 4.0), ("Q8", 2, 4.0), ("Q9", 2, 4.0)] {
        for pairing in ["node_to_segment", "segment_to_segment"] {
            let errors: Vec<(f64, f64)> = [1, 2]
                .iter()
                .map(|level| {
                    let mesh = format!("mesh=\"../../meshes/generic/shrink_fit_axisymmetric_{kind}_L{level}.msh\"");
                    let r = run(&[&mesh, &format!("contact.0.pairing={pairing}")]);
                    let tag = format!("{kind} L{level} {pairing}");
                    assert_eq!(r.status, "converged", "{tag}");
                    let fit = &r.contacts["fit"];
                    let error = (fit.normal_force - force).abs() / force;
                    let h = b / (cells * f64::from(*level));
                    assert!(error <= (h / b).powi(degree + 1), "{tag}: N {} against {force}", fit.normal_force);
                    let pressure = fit.profile.as_ref().unwrap().pressure.iter().filter(|q| **q > 0.0);
                    let worst = pressure.fold(0.0f64, |m, q| m.max((q - p).abs() / p));
                    eprintln!("{tag}: N error {error:.2e}, worst pair pressure {worst:.2e}");
                    (error, worst)
                })
                .collect();
            let rate = |a: f64, b: f64| (a / b).log2();
            let k = f64::from(degree);
            assert!(rate(errors[0].0, errors[1].0) >= k + 1.0 - 0.15, "{kind} {pairing}: N rate {errors:?}");
            assert!(rate(errors[0].1, errors[1].1) >= k - 0.5, "{kind} {pairing}: pressure rate {errors:?}");
        }
    }
}

//! The paper's case solved by every algorithm of the library (issue 20 item 2), and its generic
//! twin by the paper's algorithm.
//!
//! ```text
//!   scenes/plate_insert_nogap_mu03.toml (N = 64, μ = 0.3, no gap) with each of the five
//!   algorithms: the same discrete problem, so each agrees with the active set (the second
//!   algorithm is the truth here) to the accuracy of its own method
//!   scenes/generic/plate_insert_nogap_mu03.toml with boussinesq: the same pairs, supports and
//!   load in the generic schema; P is the x reaction of "right", l the contact length on the
//!   unit hole over π — equal to the preset's unplaced Boussinesq run
//! ```
//!
//! Tolerances (relative):
//! * Clarabel 1e-6: its interior-point tolerance (1e-8 on its scaled residuals) bounds the
//!   force error far below that; the flagship's runs agree to 1e-7 (docs/verification.md).
//! * the augmented Lagrangian 1e-8: a semi-smooth Newton method ends on the exact active set
//!   and solves the same linear equations as the active set, to round-off of the full system's
//!   LU (condition number ~1e6 here: 1e-10) — 1e-8 leaves a margin of 100.
//! * the penalty method 1e-3: its normal penalty is 1e3 × the contact stiffness scale k_c, so
//!   the penetration it needs to carry λ is λ/(1e3 k_c), which moves the contact forces by
//!   about 1/1e3 of themselves at most.
//! * Boussinesq (unplaced) 1e-10: it solves the same linear equations once its zones equal the
//!   active set's, so only round-off differs.
//! * the twin 1e-6 (the issue's bound): the same mesh, pairs and loads in the other schema.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::contact::{ContactAlgorithm, ContactError};
use contact2d::generic::{GenericError, load_scene, solve_generic};
use contact2d::plate_insert::PlateInsertScene;
use contact2d::run::{RunOutcome, solve_scene};

const PRESET: &str = "scenes/plate_insert_nogap_mu03.toml";
const TWIN: &str = "scenes/generic/plate_insert_nogap_mu03.toml";

fn preset(overrides: &[&str]) -> RunOutcome {
    let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    solve_scene(&PlateInsertScene::load(Path::new(PRESET), &overrides).unwrap()).unwrap()
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn every_algorithm_solves_the_papers_case() {
    let truth = preset(&["solver.algorithm=active_set"]);
    assert_eq!(truth.report.status, "converged");
    let truth = truth.paper;
    let tolerance = |a: ContactAlgorithm| match a {
        ContactAlgorithm::Clarabel => 1e-6,
        ContactAlgorithm::AugmentedLagrangian => 1e-8,
        ContactAlgorithm::Penalty => 1e-3,
        _ => 1e-10,
    };
    for algorithm in ContactAlgorithm::ALL {
        let mut overrides = vec![format!("solver.algorithm={}", algorithm.key())];
        if algorithm == ContactAlgorithm::Boussinesq {
            overrides.push("solver.place_zone_ends=false".into());
        }
        let set: Vec<&str> = overrides.iter().map(String::as_str).collect();
        let RunOutcome { report, paper: r, .. } = preset(&set);
        assert_eq!(report.status, "converged", "{}: {:?}", algorithm.key(), report.failed_check);
        assert_eq!(report.algorithm, algorithm);
        let tol = tolerance(algorithm);
        for (what, got, want) in
            [("P", r.P, truth.P), ("Phi_E1", r.Phi_E1, truth.Phi_E1), ("Phi_E2", r.Phi_E2, truth.Phi_E2)]
        {
            let err = relative(got, want);
            assert!(
                err <= tol,
                "{}: {what} = {got} against the active set's {want}: {err:.1e} > {tol:.0e}",
                algorithm.key()
            );
        }
    }
}

#[test]
fn the_generic_twin_with_boussinesq_matches_the_preset() {
    let preset = preset(&["solver.algorithm=boussinesq", "solver.place_zone_ends=false"]).paper;
    let twin = load_scene(Path::new(TWIN), &["solver.algorithm=boussinesq".into()]).unwrap();
    let twin = solve_generic(&twin, &mut |_, _| {}).unwrap().report;
    assert_eq!(twin.status, "converged", "{:?}", twin.failed_check);
    let p = twin.reactions["right"][0].unwrap();
    let l = twin.contacts["hole"].contact_length / std::f64::consts::PI;
    assert!(relative(p, preset.P) <= 1e-6, "P: twin {p}, preset {}", preset.P);
    let preset_l = preset.l.unwrap();
    assert!(relative(l, preset_l) <= 1e-6, "l: twin {l}, preset {preset_l}");
}

/// Where the Boussinesq algorithm's assumptions fail it is refused before solving with a typed
/// error, never run to a silent `inadmissible`: a pin that crosses its clearance as a rigid body
/// (pin_lug) and a roller held only by contact (cylinder_on_block).
#[test]
fn boussinesq_is_refused_where_it_does_not_apply() {
    for scene in ["scenes/generic/pin_lug.toml", "scenes/generic/cylinder_on_block.toml"] {
        let s = load_scene(Path::new(scene), &["solver.algorithm=boussinesq".into()]).unwrap();
        match solve_generic(&s, &mut |_, _| {}) {
            Err(GenericError::Contact { source, .. }) => {
                assert!(
                    matches!(*source, ContactError::NotApplicable { algorithm: "boussinesq", .. }),
                    "{scene}: {source}"
                )
            }
            Err(other) => panic!("{scene}: another error: {other}"),
            Ok(out) => panic!("{scene}: solved with status {}", out.report.status),
        }
    }
}

/// `contact2d compare` on the paper's scene: every algorithm × the paper's two pairings on the
/// N = 16 and 32 meshes, each compared with the published value as well. The published P
/// (0.195, three digits) bounds every converged run's P to half a unit of its last digit
/// (2.6e-3 relative): the discretisation error of P is 5e-4 at N = 16 (the table in
/// docs/algorithms.md), well inside it.
#[test]
fn compare_runs_every_algorithm_on_the_papers_scene() {
    use contact2d::compare::{CompareArgs, compare};
    let mesh = |n: u32| format!("meshes/plate_insert/plate_insert_eps0_N{n}.msh").into();
    let args = CompareArgs {
        scene: PRESET.into(),
        meshes: vec![mesh(16), mesh(32)],
        repeat: 1,
        references: vec![],
        sets: vec![],
        out: std::env::temp_dir().join("contact2d-compare-paper-unused"),
        time_limit: 120.0,
    };
    let comparison = compare(&args, &mut |_, _, _| {}).unwrap();
    assert_eq!(comparison.rows.len(), ContactAlgorithm::ALL.len() * 2 * 2);
    assert_eq!(comparison.references["published:P"].kind, contact2d::compare::ReferenceKind::Published);
    // P's reference from the runs: two levels, so no extrapolation; the most accurate method on
    // the finer mesh (node to segment before node to node, the active set first), within the
    // published value's rounding (0.195 ± 0.0005).
    let p = &comparison.references["P"];
    assert_eq!(
        (p.kind, p.from.as_str()),
        (contact2d::compare::ReferenceKind::Finest, "active_set × node_to_segment on plate_insert_eps0_N32.msh")
    );
    assert!((p.value - 0.195).abs() <= 0.0005, "{p:?}");
    for row in &comparison.rows {
        assert_eq!(row.status, "converged", "{} × {} on {}: {:?}", row.algorithm, row.pairing, row.mesh, row.reason);
        let error = row.errors["published:P"];
        assert!(
            error <= 0.0005 / 0.195,
            "{} × {} on {}: P off the published 0.195 by {error:.1e}",
            row.algorithm,
            row.pairing,
            row.mesh
        );
    }
}

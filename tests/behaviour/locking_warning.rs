//! The flagship scene in plane strain as ν → ½: the standard elements warn (run notes) and lock,
//! `plate_insert.formulation = "bbar"` gives a stress concentration K that no longer depends on
//! ν; an unknown formulation is a scene error.
//!
//! Truth used: the plane-strain solution of the contact problem is continuous in ν up to and
//! including the incompressible limit (the Lamé constant λ enters through a well-posed mixed
//! problem), so K(0.49) and K(0.4999999) differ by a few per cent at most in the exact solution;
//! the measured B-bar change on the N = 16 mesh is 0.12 % (K = 4.089 → 4.084), and 2 % leaves
//! room for the physical dependence on ν, while the locking standard elements change K by a
//! factor ≥ 10 (measured 6.26 → 2801; K = 1825 in issue 15).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::element::LOCKING_POISSON_THRESHOLD;
use contact2d::plate_insert::PlateInsertScene;
use contact2d::run::{RunOutcome, solve_scene};

fn run(nu: f64, formulation: &str) -> RunOutcome {
    let scene = PlateInsertScene::load(
        std::path::Path::new("scenes/plate_insert_nogap_mu0.toml"),
        &[
            "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0_N16.msh\"".into(),
            "plate_insert.plane_condition=\"strain\"".into(),
            format!("plate_insert.poissons_ratio={nu}"),
            format!("plate_insert.formulation=\"{formulation}\""),
        ],
    )
    .unwrap();
    solve_scene(&scene).unwrap()
}

#[test]
fn standard_elements_warn_and_lock_bbar_does_not() {
    let warned = |r: &RunOutcome| r.report.notes.iter().any(|n| n.contains("lock"));
    let (std_low, std_high) = (run(0.49, "standard"), run(0.4999999, "standard"));
    let (bbar_low, bbar_high) = (run(0.49, "bbar"), run(0.4999999, "bbar"));
    assert!(warned(&std_low) && warned(&std_high), "{:?}", std_low.report.notes);
    assert!(!warned(&bbar_low) && !warned(&bbar_high), "{:?}", bbar_high.report.notes);
    assert!(!warned(&run(LOCKING_POISSON_THRESHOLD, "standard")));
    let k = |r: &RunOutcome| r.paper.K;
    assert!(k(&std_high) > 10.0 * k(&std_low), "standard K {} → {}", k(&std_low), k(&std_high));
    let change = (k(&bbar_high) - k(&bbar_low)).abs() / k(&bbar_low);
    assert!(change < 0.02, "B-bar K {} → {} ({:.2} %)", k(&bbar_low), k(&bbar_high), 100.0 * change);
    assert_eq!(bbar_high.report.status, "converged");
}

#[test]
fn unknown_formulation_is_a_scene_error() {
    let e = PlateInsertScene::load(
        std::path::Path::new("scenes/plate_insert_nogap_mu0.toml"),
        &["plate_insert.formulation=\"mixed\"".into()],
    );
    assert!(e.is_err());
    let s = PlateInsertScene::load(std::path::Path::new("scenes/plate_insert_nogap_mu0.toml"), &[]).unwrap();
    assert_eq!(s.plate_insert().formulation, contact2d::element::Formulation::Standard);
}

/// A nearly incompressible body of revolution locks as plane strain does (λ → ∞ in its 4×4 D):
/// the standard elements warn naming the kinematics, B-bar does not
/// (`scenes/generic/shrink_fit_axisymmetric.toml`; B-bar's accuracy there:
/// tests/verification/verify_axisymmetric_lame.rs, `bbar_tubes_of_revolution_do_not_lock`).
#[test]
fn a_body_of_revolution_warns_as_plane_strain_does() {
    let notes = |formulation: &str| {
        let sets = ["body.0.poissons_ratio=0.49".to_string(), format!("body.0.formulation=\"{formulation}\"")];
        let scene =
            contact2d::generic::load_scene(std::path::Path::new("scenes/generic/shrink_fit_axisymmetric.toml"), &sets)
                .unwrap();
        scene.element_warnings()
    };
    let standard = notes("standard");
    assert!(standard.iter().any(|n| n.contains("axisymmetric with ν = 0.49") && n.contains("lock")), "{standard:?}");
    assert!(notes("bbar").is_empty());
}

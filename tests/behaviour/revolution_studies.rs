//! `compare` and `sweep` on a body of revolution (issue 43 item 5: "everywhere a scene goes"),
//! against the closed form of `scenes/generic/shrink_fit_axisymmetric.toml`: a shaft b = 10
//! shrunk into a hub c = 20, length L = 10, both ends held axially, E = 2e5, ν = 0.3, radial
//! interference δ (Timoshenko & Goodier §30, tests/verification/verify_axisymmetric_shrink_fit.rs):
//!
//! ```text
//! p(δ) = E δ / (b (1 + ν) [((1 − 2ν) b² + c²)/(c² − b²) + (1 − 2ν)]),   N = p 2π b L
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

use contact2d::compare::{CompareArgs, compare};

const FIT: &str = "scenes/generic/shrink_fit_axisymmetric.toml";

/// The closed-form normal force (a total over the circumference) at radial interference `delta`.
fn normal_force(delta: f64) -> f64 {
    let (e, nu, b, c, length) = (200_000.0, 0.3, 10.0, 20.0, 10.0);
    let p = e * delta / (b * (1.0 + nu) * (((1.0 - 2.0 * nu) * b * b + c * c) / (c * c - b * b) + (1.0 - 2.0 * nu)));
    p * 2.0 * std::f64::consts::PI * b * length
}

#[test]
fn compare_runs_every_algorithm_and_pairing_on_a_body_of_revolution_to_the_closed_form() {
    let exact = normal_force(0.01);
    let args = CompareArgs {
        scene: FIT.into(),
        meshes: vec![],
        repeat: 1,
        references: vec![format!("contacts.fit.normal_force={exact}")],
        sets: vec![],
        out: std::env::temp_dir().join("contact2d-compare-revolution-unused"),
        time_limit: 60.0,
    };
    let comparison = compare(&args, &mut |_, _, _| {}).unwrap();
    assert_eq!(comparison.rows.len(), 15, "5 algorithms × 3 pairings");
    for row in &comparison.rows {
        let tag = format!("{} × {}", row.algorithm, row.pairing);
        assert_eq!(row.status, "converged", "{tag}: {:?}", row.reason);
        // The verification test's bounds: 1e-4 (the hub's O(h³) interpolation error, measured
        // 3.3e-6), 2e-3 for the penalty answer, which penetrates by about 1e-3 of its pairs'
        // displacement (measured 2e-5).
        let tolerance = if row.algorithm == "penalty" { 2e-3 } else { 1e-4 };
        let error = row.errors["contacts.fit.normal_force"];
        assert!(error.abs() <= tolerance, "{tag}: error {error} of N = {}", row.values["contacts.fit.normal_force"]);
    }
}

#[test]
fn a_sweep_over_the_interference_follows_the_closed_form() {
    let dir = std::env::temp_dir().join(format!("contact2d_sweep_revolution_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", FIT, "--vary", "contact.fit.gap=-0.005,-0.01,-0.02", "--quiet", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3);
    for row in &rows {
        assert_eq!(row[col("status")], "converged");
        let delta = -row[col("contact.fit.gap")].parse::<f64>().unwrap();
        let n = row[col("contacts.fit.normal_force")].parse::<f64>().unwrap();
        // The verification test's 1e-4 (above); N is linear in δ, so the bound holds at every δ.
        assert!((n - normal_force(delta)).abs() <= 1e-4 * normal_force(delta), "δ = {delta}: N = {n}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The mean pressure of a zone that reaches the axis: Hertz's sphere
/// (`scenes/generic/hertz_sphere_axisymmetric.toml`, its contact zone the disc r ≤ L) spreads its
/// normal force N over Pappus' area of the zone, π L², not over 2π r̄ L with r̄ the rings' area
/// centroid (2L/3, which made it 3/4 of that). The discrete centroid of the nodes in contact
/// stands for the zone's, whose end lies between two nodes: bound h/L, h = a/12 the mesh's
/// spacing at the contact (the verify case's tolerance; measured 0.49 %).
#[test]
fn a_zone_reaching_the_axis_spreads_its_force_over_its_disc() {
    let scene =
        contact2d::generic::load_scene(std::path::Path::new("scenes/generic/hertz_sphere_axisymmetric.toml"), &[])
            .unwrap();
    let report = contact2d::generic::solve_generic(&scene, &mut |_, _| {}).unwrap().report;
    let hertz = &report.contacts["hertz"];
    let disc = hertz.normal_force / (std::f64::consts::PI * hertz.contact_length.powi(2));
    let mean = hertz.mean_pressure.unwrap();
    assert!((mean - disc).abs() <= disc / 12.0, "mean pressure {mean} against N/(πL²) = {disc}");
}

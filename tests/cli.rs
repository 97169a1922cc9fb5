//! The command-line tool end to end: summaries, scene runs, and clean failures on bad input.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

fn contact2d(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(args).output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into(), String::from_utf8_lossy(&out.stderr).into())
}

#[test]
fn mesh_json_has_the_documented_keys() {
    let (ok, stdout, _) = contact2d(&["mesh", "meshes/plate_insert/plate_insert_eps0_N16.msh", "--json"]);
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["nodes"], 864);
    assert_eq!(v["elements"]["quad9"], 192);
    assert!(v["physical_groups"].as_array().unwrap().iter().any(|g| g["name"] == "hole_edge" && g["dim"] == 1));
    assert_eq!(v["bbox"][1][0], 5.0);
    assert!(v["min_det_j"].as_f64().unwrap() > 0.0);
}

#[test]
fn bad_mesh_fails_with_one_clear_line_and_no_panic() {
    for file in ["Cargo.toml", "does/not/exist.msh"] {
        let (ok, _, stderr) = contact2d(&["mesh", file]);
        assert!(!ok);
        assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
        assert!(stderr.contains(file) && !stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn run_scene_json_has_the_documented_keys() {
    let (ok, stdout, stderr) = contact2d(&[
        "run",
        "scenes/plate_insert_nogap_mu0.toml",
        "--set",
        "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0_N16.msh\"",
        "--json",
    ]);
    assert!(ok, "{stderr}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    for key in [
        "l",
        "b",
        "P",
        "Phi_E1",
        "Phi_E2",
        "Phi_f",
        "sigma_star",
        "K",
        "w",
        "dofs",
        "algorithm",
        "status",
        "kkt",
        "time_s",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    for key in ["max_penetration", "max_complementarity", "max_cone_violation", "min_dissipation"] {
        assert!(v["kkt"].get(key).is_some(), "missing kkt.{key}");
    }
    assert_eq!(v["status"], "converged");
}

#[test]
fn unknown_scene_keys_and_overrides_are_clear_errors() {
    let (ok, _, stderr) = contact2d(&["run", "scenes/plate_insert_nogap_mu0.toml", "--set", "plate_insert.youngs=2"]);
    assert!(!ok && stderr.contains("youngs") && !stderr.contains("panicked"), "{stderr}");
    let (ok, _, stderr) = contact2d(&["run", "scenes/plate_insert_nogap_mu0.toml", "--set", "solver.algorithm=magic"]);
    assert!(!ok && stderr.contains("magic"), "{stderr}");
}

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
    // The one contract: the generic summary, the paper's quantities under `paper`.
    for key in ["dofs", "pairs", "algorithm", "status", "steps", "contacts", "reactions", "energies", "kkt", "time_s"] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    for key in ["l", "b", "P", "Phi_E1", "Phi_E2", "Phi_f", "W", "sigma_star", "K", "w", "mu", "steps"] {
        assert!(v["paper"].get(key).is_some(), "missing paper.{key}");
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

#[test]
fn every_subcommand_has_help_with_examples() {
    for args in [&["--help"][..], &["mesh", "--help"], &["run", "--help"], &["help", "run"]] {
        let (ok, stdout, _) = contact2d(args);
        assert!(ok, "{args:?}");
        assert!(stdout.contains("Examples:") && stdout.contains("contact2d "), "{args:?}: {stdout}");
    }
    let (_, stdout, _) = contact2d(&["run", "--help"]);
    assert!(stdout.contains("--set") && stdout.contains("scenes/"), "{stdout}");
}

#[test]
fn a_malformed_command_line_exits_with_status_2() {
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["run"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["frobnicate"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn bad_override_values_name_the_key_and_the_override() {
    for (set, key) in [
        ("plate_insert.load=abc", "plate_insert.load"),
        ("plate_insert.poissons_ratio=0.5", "plate_insert.poissons_ratio"),
        ("plate_insert.friction=-1", "plate_insert.friction"),
        ("plate_insert.l_steps=[0.1]", "plate_insert.l_steps"),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(["run", "scenes/plate_insert_nogap_mu0.toml", "--set", set])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{set}");
        assert!(stderr.contains(key) && stderr.contains("plate_insert_nogap_mu0.toml"), "{set}: {stderr}");
        assert!(!stderr.contains("panicked") && stderr.trim().lines().count() == 1, "{stderr}");
    }
    // A rigid insert on a scene that states stiffness_ratio = 1.0 is not a contradiction.
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", "scenes/plate_insert_nogap_mu0.toml", "--set", "plate_insert.rigid_insert=true"])
        .args(["--set", "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0_N16.msh\"", "--json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// `--unset KEY` removes a key the file gives: pin_lug.toml gives `loading.steps = 4`; without
/// it the documented default is one step (docs/user-guide.md, `[loading]`: neither given, one
/// step). A key the file does not give is one clear line naming the flag.
#[test]
fn unset_removes_a_key_the_scene_gives() {
    let steps = |args: &[&str]| {
        let (ok, stdout, stderr) = contact2d(&[&["run", "scenes/generic/pin_lug.toml", "--json"], args].concat());
        assert!(ok, "{stderr}");
        let summary: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        summary["steps"].as_array().unwrap().len()
    };
    assert_eq!(steps(&[]), 4);
    assert_eq!(steps(&["--unset", "loading.steps"]), 1);
    // Applied before every --set, whatever the order on the command line.
    assert_eq!(steps(&["--set", "loading.steps=2", "--unset", "loading.steps"]), 2);
    let (ok, _, stderr) = contact2d(&["run", "scenes/generic/pin_lug.toml", "--unset", "loading.stepz"]);
    assert!(!ok && stderr.trim().lines().count() == 1, "{stderr}");
    assert!(stderr.contains("--unset loading.stepz: the scene gives no key \"loading.stepz\" to remove"), "{stderr}");
}

#[test]
fn a_closed_stdout_ends_quietly_without_a_panic() {
    // `contact2d mesh big.msh --json | head -1`: the reader goes away before the output is written.
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["mesh", "meshes/plate_insert/plate_insert_eps0_N64.msh", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && !stderr.contains("panicked"), "{:?} {stderr}", out.status);
}

#[test]
fn compare_runs_every_algorithm_and_pairing_and_says_why_it_skips() {
    let out = std::env::temp_dir().join(format!("contact2d-compare-{}", std::process::id()));
    let out_s = out.to_string_lossy().into_owned();
    let (ok, stdout, stderr) =
        contact2d(&["compare", "scenes/generic/two_blocks_press_slide.toml", "--repeat", "1", "--out", &out_s]);
    assert!(ok, "{stderr}");
    // 5 algorithms × 3 pairings × 1 mesh; the press-then-slide schedule is not proportional and the
    // blocks' node counts differ, so Boussinesq and node-to-node are skipped with the reason.
    let rows: Vec<&str> =
        stdout.lines().filter(|l| l.contains("| node_to_") || l.contains("| segment_to_segment |")).collect();
    assert_eq!(rows.len(), 15, "{stdout}");
    assert!(rows.iter().any(|r| r.starts_with("| boussinesq | node_to_segment") && r.contains("proportional")));
    assert!(rows.iter().filter(|r| r.contains("| node_to_node |")).all(|r| r.contains("skipped")));
    assert!(rows.iter().any(|r| r.starts_with("| augmented_lagrangian | node_to_segment") && r.contains("converged")));
    for file in ["compare.csv", "compare.json", "compare_reference.csv", "compare.md", "compare_energy.png"] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
    // One mesh: the reference is named and the columns are differences from it, not errors.
    assert!(stdout.contains("energy: difference from active_set × segment_to_segment"), "{stdout}");
    std::fs::remove_dir_all(&out).ok();
}

/// `contact2d verify` prints one PASS/FAIL line per check and a count, and exits 0 when every
/// check passes; an unknown case is an error (exit 1).
#[test]
fn verify_prints_the_table_and_counts() {
    let (ok, stdout, stderr) = contact2d(&["verify", "--cases", "interference_fit,incline"]);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("== interference_fit") && stdout.contains("== incline"), "{stdout}");
    let checks = stdout.lines().filter(|l| l.ends_with("PASS") || l.ends_with("FAIL")).count();
    assert!(stdout.contains(&format!("{checks} of {checks} checks passed")), "{stdout}");
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["verify", "--cases", "nonsense"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no such case"));
}

/// `--about X,Y` moves the moments' centre: the JSON says which (`moment_centre`), and the
/// reactions' moment moves by the transfer rule `M_c = M_0 − c × R = M_0 − (c_1 R_2 − c_2 R_1)`
/// with `R` = `reactions_total` (an identity of the sums, to their round-off: 1e-9 of |c| |R|).
/// A bad centre is a one-line error.
#[test]
fn about_moves_the_moment_centre_by_the_transfer_rule() {
    let scene = "scenes/generic/pin_lug_rigid_pin.toml";
    let run = |extra: &[&str]| {
        let (ok, stdout, stderr) = contact2d(&[&["run", scene, "--json", "-q"], extra].concat());
        assert!(ok, "{stderr}");
        serde_json::from_str::<serde_json::Value>(&stdout).unwrap()
    };
    let (origin, moved) = (run(&[]), run(&["--about", "30,-4.5"]));
    assert_eq!(origin["moment_centre"], serde_json::json!([0.0, 0.0]));
    assert_eq!(moved["moment_centre"], serde_json::json!([30.0, -4.5]));
    let r = [origin["reactions_total"][0].as_f64().unwrap(), origin["reactions_total"][1].as_f64().unwrap()];
    let m0 = origin["reaction_moment_total"].as_f64().unwrap();
    let mc = moved["reaction_moment_total"].as_f64().unwrap();
    let expected = m0 - (30.0 * r[1] - (-4.5) * r[0]);
    assert!((mc - expected).abs() <= 1e-9 * 30.4 * r[0].hypot(r[1]), "{mc} against {expected}");
    for bad in ["1", "a,b", "1,2,3", "inf,0"] {
        let (ok, _, stderr) = contact2d(&["run", scene, "--about", bad]);
        assert!(!ok && stderr.contains("--about") && !stderr.contains("panicked"), "{bad}: {stderr}");
    }
}

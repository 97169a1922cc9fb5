//! What an engineer reads from a joint (issue 26), on the bundled pin in the lug
//! (`scenes/generic/pin_lug.toml`: a pin pushed by 1 000 N per mm in x1 through a lug's hole,
//! held only by the contact and the symmetry line) and the flagship preset:
//!
//! * the force vector each contact transmits, against the pin's equilibrium;
//! * where the zones lie (points, arc length, angles about the circle's centre), against the
//!   arc length the contact length is measured by;
//! * every step's profile (`--profiles all`), against the last step's own profile;
//! * the pairing that ran (`pairing_used`), against a run that names it;
//! * the linear path that ran (`linear_used`), against a run that forces the other one;
//! * help texts against what the commands write; `-v` logs iterations on a generic scene.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

use serde_json::Value;

const PIN: &str = "scenes/generic/pin_lug.toml";

fn run(args: &[&str]) -> (Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).arg("run").args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{args:?}: {stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    (serde_json::from_str(&stdout).unwrap_or(Value::Null), stderr)
}

fn pair(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

/// The pin's x1 equilibrium: its only x1 support is the contact (the symmetry line holds u2), so
/// the force the contact transmits to the lug (the slave side) is the pin's load, 250 N per
/// step up to 1 000 N. 1e-6 relative: the solver's equilibrium tolerance (the floating pin's
/// stabilising springs carry at most 1e-9 of the load, `kkt.floating_residual`).
#[test]
fn the_resultant_balances_the_load_at_every_step() {
    let (summary, _) = run(&[PIN, "--json"]);
    for (k, step) in summary["steps"].as_array().unwrap().iter().enumerate() {
        let load = 250.0 * (k + 1) as f64;
        let [f1, _] = pair(&step["contacts"]["bore"]["resultant"]);
        assert!((f1 - load).abs() <= 1e-6 * load, "step {}: resultant {f1} against the load {load}", k + 1);
    }
    // A reversal shows: pushed and then pulled, the transmitted force changes sign.
    let (cycle, _) = run(&[PIN, "--json", "--set", "loading.schedule=[{main=1.0},{main=-1.0}]"]);
    for (step, load) in cycle["steps"].as_array().unwrap().iter().zip([1000.0, -1000.0]) {
        let [f1, _] = pair(&step["contacts"]["bore"]["resultant"]);
        assert!((f1 - load).abs() <= 1e-6 * 1000.0, "resultant {f1} against the load {load}");
    }
}

/// The zones' ends: on the pin's circle (radius 9.9 about the origin), their angles about its
/// centre are their arc length over the radius (the arc length starts on the symmetry line,
/// θ = 0), and the bearing zone starts on the side the pin is pushed to (θ = 0, x1 > 0).
/// 1e-9: the angle is atan2 of a point interpolated on the chord between two nodes, whose arc
/// differs from the chord by less than 1e-3 of a degree on this mesh (the tolerance on the
/// points' radius, 2e-3, is that chord's sag).
#[test]
fn the_zones_lie_where_their_angles_say() {
    let (summary, _) = run(&[PIN, "--json"]);
    let bore = &summary["contacts"]["bore"];
    for zones in [&bore["zones"], &bore["stick_zones"]] {
        let s: Vec<f64> = zones["s"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        let angles: Vec<f64> = zones["angles_deg"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert!(!s.is_empty() && s.len() % 2 == 0 && s.len() == angles.len(), "{zones}");
        for ((s, a), p) in s.iter().zip(&angles).zip(zones["points"].as_array().unwrap()) {
            let [x, y] = pair(p);
            assert!((x.hypot(y) - 9.9).abs() < 2e-3, "point ({x}, {y}) off the pin's circle");
            assert!((a - (s / 9.9).to_degrees()).abs() < 1e-3, "angle {a}° against s = {s}");
        }
    }
    let angles = bore["zones"]["angles_deg"].as_array().unwrap();
    assert!(angles[0].as_f64().unwrap().abs() < 1e-9, "the bearing zone starts at θ = 0: {angles:?}");
    let length = bore["contact_length"].as_f64().unwrap();
    let s = bore["zones"]["s"].as_array().unwrap();
    let spanned = s.last().unwrap().as_f64().unwrap() - s[0].as_f64().unwrap();
    assert!((spanned - length).abs() <= 1e-12 * length, "one zone spans the contact length");
}

/// `--profiles all`: every step's row carries the profile, and the last row's is the top-level
/// one (the same evaluation of the same solution: bitwise); `--out` writes a CSV per step.
#[test]
fn every_steps_profile_is_reported_and_written() {
    let dir = std::env::temp_dir().join(format!("contact2d_profiles_{}", std::process::id()));
    let out = dir.to_str().unwrap();
    let (summary, _) = run(&[PIN, "--json", "--profiles", "all", "--out", out]);
    let steps = summary["steps"].as_array().unwrap();
    for step in steps {
        assert!(step["contacts"]["bore"]["profile"]["pressure"].is_array(), "a step without its profile");
    }
    assert_eq!(steps.last().unwrap()["contacts"]["bore"]["profile"], summary["contacts"]["bore"]["profile"]);
    for k in 1..=steps.len() {
        let csv = std::fs::read_to_string(dir.join(format!("contact_bore_step_{k:03}.csv"))).unwrap();
        let rows = csv.lines().count() - 1;
        assert_eq!(rows, steps[k - 1]["contacts"]["bore"]["profile"]["s"].as_array().unwrap().len());
    }
    let readme = std::fs::read_to_string(dir.join("README.txt")).unwrap();
    assert!(readme.contains("contact_bore_step_001.csv") && readme.contains("summary.json"), "{readme}");
    let method = format!("pairing bore: {}", summary["pairing_used"]["bore"].as_str().unwrap());
    assert!(readme.contains(&method), "the README records the method: {readme}");
    let (last_only, _) = run(&[PIN, "--json"]);
    assert!(last_only["steps"][0]["contacts"]["bore"].get("profile").is_none());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The recorded pairing is the one that ran: naming it in the scene gives the same numbers.
#[test]
fn the_pairing_used_is_recorded_and_is_what_ran() {
    for (scene, contact) in [(PIN, "bore"), ("scenes/generic/two_blocks_press_slide.toml", "joint")] {
        let (automatic, _) = run(&[scene, "--json"]);
        let used = automatic["pairing_used"][contact].as_str().unwrap();
        let set = format!("contact.{contact}.pairing=\"{used}\"");
        let (named, _) = run(&[scene, "--json", "--set", &set]);
        assert_eq!(named["pairing_used"][contact], used);
        assert_eq!(named["contacts"], automatic["contacts"], "{scene}: pairing {used} named gives other numbers");
    }
    let (paper, _) = run(&["scenes/plate_insert_nogap_mu0.toml", "--json"]);
    assert_eq!(paper["pairing_used"]["hole"], "node_to_node");
}

/// The recorded linear path is the one that ran: the pin in the lug (a few dozen pairs) takes the
/// condensed path, and forcing the sparse one is recorded and gives the same resultant to 1e-9 of
/// its size (both paths end in the same contact states and solve them to round-off,
/// `crates/contact/tests/integration/sparse_path.rs` checks 1e-10 per field; 1e-9 leaves room for the
/// floating pin's proximal iteration, stopped at its default 1e-10).
#[test]
fn the_linear_path_used_is_recorded_and_is_what_ran() {
    let (auto, _) = run(&[PIN, "--json"]);
    assert_eq!(auto["linear_used"], "condensed");
    let (sparse, _) = run(&[PIN, "--json", "--set", "solver.linear=\"sparse\""]);
    assert_eq!(sparse["linear_used"], "sparse");
    let [a, b] = [pair(&auto["contacts"]["bore"]["resultant"]), pair(&sparse["contacts"]["bore"]["resultant"])];
    let size = a[0].hypot(a[1]);
    assert!((a[0] - b[0]).hypot(a[1] - b[1]) <= 1e-9 * size, "condensed {a:?}, sparse {b:?}");
    let (paper, _) = run(&["scenes/plate_insert_nogap_mu0.toml", "--json", "--set", "solver.algorithm=\"clarabel\""]);
    assert_eq!(paper["linear_used"], "condensed");
}

/// `-v` logs the algorithm's iterations of every step on a generic scene (a table row per
/// iteration, as many as the step's count), and the help promises what `--out` writes.
#[test]
fn verbose_logs_iterations_and_the_help_holds() {
    let (summary, log) = run(&[PIN, "--json", "-v"]);
    let rows = log.lines().filter(|l| l.trim_start().chars().next().is_some_and(|c| c.is_ascii_digit())).count();
    let iterations = summary["iterations"].as_u64().unwrap() as usize;
    assert_eq!(rows, iterations, "{log}");
    let help = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["run", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    for promised in ["summary.json", "README.txt", "--profiles"] {
        assert!(help.contains(promised), "run --help: {promised}");
    }
    let top = Command::new(env!("CARGO_BIN_EXE_contact2d")).arg("--help").output().unwrap();
    let top = String::from_utf8_lossy(&top.stdout);
    for command in ["mesh", "run", "sweep", "bench", "stress", "compare", "verify"] {
        assert!(top.contains(command), "--help lists {command}");
    }
}

/// On the paper's case the zones' angles about the master circle's centre are the paper's zone
/// ends: the contact zone starts at θ = (1 − l_master) 180° (on the master's own η) and ends
/// at 180°, the stick zone starts at (1 − b) 180° (variant 1: the master is the hole edge, whose
/// η is the paper's). Two measures of one end: the paper interpolates in η, the zone ends in
/// arc length with the point on the chord between nodes; they differ by the chord's bend, below
/// 1e-4° on these meshes.
#[test]
fn the_papers_zone_ends_are_the_zones_angles() {
    for (scene, variant1) in [
        ("scenes/plate_insert_nogap_mu03.toml", true),
        ("scenes/plate_insert_gap_v1_mu03.toml", true),
        ("scenes/plate_insert_gap_v2_mu03.toml", false),
    ] {
        let (summary, _) = run(&[scene, "--json"]);
        let (zones, paper) = (&summary["contacts"]["hole"], &summary["paper"]);
        let angles = |key: &str| -> Vec<f64> {
            zones[key]["angles_deg"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect()
        };
        let contact = angles("zones");
        let l_master = paper["l_master"].as_f64().unwrap();
        assert!((contact[0] - (1.0 - l_master) * 180.0).abs() < 1e-4, "{scene}: {contact:?} against l = {l_master}");
        assert!((contact[contact.len() - 1] - 180.0).abs() < 1e-9, "{scene}: {contact:?}");
        if variant1 {
            let (stick, b) = (angles("stick_zones"), paper["b"].as_f64().unwrap());
            assert!((stick[0] - (1.0 - b) * 180.0).abs() < 1e-4, "{scene}: {stick:?} against b = {b}");
        }
    }
}

//! `contact2d run GENERIC_SCENE --out DIR`: the generic outputs are written whole, listed in the
//! summary's manifest, and a later run into the same folder leaves none of the earlier run's
//! files behind.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

fn run(scene: &str, out: &Path) -> serde_json::Value {
    let status = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", scene, "--quiet", "--out"])
        .arg(out)
        .output()
        .unwrap();
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

fn listing(dir: &Path) -> BTreeSet<String> {
    std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect()
}

fn manifest(summary: &serde_json::Value) -> BTreeSet<String> {
    summary["files"].as_array().unwrap().iter().map(|f| f.as_str().unwrap().to_string()).collect()
}

#[test]
fn generic_outputs_are_listed_whole_and_replace_an_earlier_run() {
    let dir = std::env::temp_dir().join(format!("contact2d_generic_outputs_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let first = run("scenes/generic/two_blocks_press_slide.toml", &dir);
    let files = listing(&dir);
    assert_eq!(manifest(&first), files, "the manifest lists exactly the files present");
    for name in ["mesh.png", "mesh.svg", "contact_joint.png", "contact_joint.csv", "von_mises.svg", "history.png"] {
        assert!(files.contains(name), "{name} missing: {files:?}");
    }
    assert_eq!(files.iter().filter(|f| f.ends_with(".vtu")).count(), 6, "one VTU per step");
    let csv = std::fs::read_to_string(dir.join("contact_joint.csv")).unwrap();
    assert!(csv.starts_with("s,x,y,pressure,shear,gap,slip,state\n"));
    assert_eq!(csv.lines().count(), 1 + first["pairs"].as_u64().unwrap() as usize);
    // A one-step run of another scene: no file of the six-step run stays.
    let second = run("scenes/generic/cylinder_on_block.toml", &dir);
    let files = listing(&dir);
    assert_eq!(manifest(&second), files);
    assert!(!files.iter().any(|f| f.contains("joint") || f == "step_001.vtu" || f.starts_with("history")), "{files:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_generic_sweep_varies_an_array_entry_and_tabulates_dotted_quantities() {
    // Coulomb: in gross sliding the tangential force is μ P, for each μ of the sweep (P = 1000).
    let dir = std::env::temp_dir().join(format!("contact2d_generic_sweep_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", "scenes/generic/two_blocks_press_slide.toml", "--quiet", "--vary"])
        .arg("contact.joint.friction=0.1,0.2")
        .args(["--plot", "contacts.joint.tangential_force,reactions.lower_bottom.1", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let mut lines = csv.lines();
    // The varied key, the status, the scene's own columns (each interface's resultants), the
    // plotted paths, the iterations and the error.
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[..2], ["contact.joint.friction", "status"]);
    assert_eq!(header[header.len() - 2..], ["iterations", "error"]);
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}: {header:?}"));
    for (line, mu) in lines.zip([0.1, 0.2]) {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells[col("status")], "converged");
        let tangential: f64 = cells[col("contacts.joint.tangential_force")].parse().unwrap();
        assert!((tangential.abs() - mu * 1000.0).abs() < 1e-7 * 1000.0, "{line}");
        let vertical: f64 = cells[col("reactions.lower_bottom.1")].parse().unwrap();
        assert!((vertical - 1000.0).abs() < 1e-7 * 1000.0, "{line}");
        let normal: f64 = cells[col("contacts.joint.normal_force")].parse().unwrap();
        assert!((normal - 1000.0).abs() < 1e-7 * 1000.0, "{line}");
    }
    assert!(dir.join("sweep_contacts_joint_tangential_force.svg").exists());
    // An entry that does not exist is refused before any run.
    let bad = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", "scenes/generic/two_blocks_press_slide.toml", "--vary", "contact.nope.friction=0.1"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("nope"));
    let _ = std::fs::remove_dir_all(&dir);
}

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

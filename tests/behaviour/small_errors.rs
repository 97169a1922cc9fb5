//! Issue 27, item 9: small errors, each now a clear error or a right answer, end to end through
//! the command line.
//!
//! ```text
//! zero work      a step at zero load (W = 0, Φ_E round-off) no longer makes a converged run
//!                `numerical`; a release back to zero neither
//! partial link   a symbolic link planted at sweep.csv.partial is not followed
//! compare mesh   `compare` with a missing mesh (given or the scene's) exits 1 naming it
//! compare time   `compare --time-limit`: a progress line per combination on stderr, a
//!                combination past the limit listed as `timed_out`; a limit of 0 refused
//! stress ratio   `stress --ratios 1e400` (parsed as ∞) exits 1 naming the flag
//! svg names      control characters in scene and contact names leave valid SVG
//! shared nodes   two bodies sharing mesh nodes: a note naming both and the node count
//! interference   an initial interference deeper than the elements: a note naming the contact
//! ```
//! (The cleanup that removes only what the folder's record lists is in tests/behaviour/output_folders.rs,
//! `a_shorter_run_removes_the_stale_files_and_keeps_the_users`.)
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn fresh(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact2d_small_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn contact2d(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_contact2d")).args(args).output().unwrap()
}

fn json_run(scene: &str, sets: &[&str]) -> serde_json::Value {
    let mut args = vec!["run", scene, "--json"];
    for s in sets {
        args.extend(["--set", s]);
    }
    let out = contact2d(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn notes(summary: &serde_json::Value) -> Vec<String> {
    summary["notes"].as_array().unwrap().iter().map(|n| n.as_str().unwrap().to_string()).collect()
}

#[test]
fn a_step_at_zero_load_keeps_a_converged_history_converged() {
    // The long interface pressed from zero: the first step carries no load, so its work is
    // exactly 0 and its strain energy 0 up to round-off (measured 4.7e-29 of a history storing
    // 0.13). Every step converges; before the fix the balance |W − Φ| / max(W, Φ) of step 1
    // was 1 and the run `numerical`.
    let r = json_run("scenes/generic/long_interface.toml", &["loading.schedule=[{press=0.0},{press=1.0}]"]);
    assert_eq!(r["steps"][0]["work"].as_f64(), Some(0.0), "no load, no work");
    assert_eq!(r["status"], "converged", "{}", r["failed_check"]);
    // Pressed and released: the release's trapezoid W cancels the loading's to round-off while
    // the friction work stays; judged against the history's energy the balance holds.
    let r = json_run("scenes/generic/long_interface.toml", &["loading.schedule=[{press=1.0},{press=0.0}]"]);
    assert_eq!(r["status"], "converged", "{}", r["failed_check"]);
}

#[cfg(unix)]
#[test]
fn a_link_planted_at_the_partial_name_is_not_followed() {
    let dir = fresh("partial_link");
    std::fs::create_dir_all(&dir).unwrap();
    let victim = std::env::temp_dir().join(format!("contact2d_small_victim_{}", std::process::id()));
    std::fs::write(&victim, "not yours").unwrap();
    std::os::unix::fs::symlink(&victim, dir.join("sweep.csv.partial")).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", "scenes/generic/two_blocks_press_slide.toml", "--vary", "contact.0.friction=0.2,0.3"])
        .args(["--quiet", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "not yours", "the link's target is untouched");
    let csv = dir.join("sweep.csv");
    assert!(std::fs::symlink_metadata(&csv).unwrap().is_file(), "sweep.csv is a file of its own, not the link");
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 3, "a header and two rows");
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_file(&victim).unwrap();
}

#[test]
fn compare_with_a_missing_mesh_fails_naming_it() {
    let dir = fresh("compare_mesh");
    let out_dir = dir.to_string_lossy().into_owned();
    let scene = "scenes/generic/two_blocks_press_slide.toml";
    for args in [
        vec!["compare", scene, "--mesh", "meshes/generic/no_such_level.msh", "--out", &out_dir],
        vec!["compare", scene, "--set", "mesh=\"no_such_level.msh\"", "--out", &out_dir],
    ] {
        let out = contact2d(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains("no_such_level.msh") && !stderr.contains("panicked"), "{stderr}");
        assert!(!dir.join("compare.csv").exists(), "no table of failed rows");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn compare_reports_progress_and_times_out_combinations() {
    let dir = fresh("compare_time");
    let out_dir = dir.to_string_lossy().into_owned();
    // 1 ms: less than reading and building the problem, so every combination that the library
    // accepts is past its limit before its first load step.
    let args = ["compare", "scenes/generic/pin_lug.toml", "--repeat", "1", "--time-limit", "0.001", "--out", &out_dir];
    let out = contact2d(&args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let csv = std::fs::read_to_string(dir.join("compare.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    // One progress line per combination, numbered k/N with N the number of rows.
    let progress: Vec<&str> = stderr.lines().filter(|l| l.starts_with("compare ")).collect();
    assert_eq!(progress.len(), rows.len(), "{stderr}");
    assert!(progress.last().unwrap().starts_with(&format!("compare {0}/{0}:", rows.len())), "{stderr}");
    let timed_out = rows.iter().filter(|r| r.contains(",timed_out,")).count();
    assert!(timed_out > 0 && rows.iter().all(|r| r.contains(",timed_out,") || r.contains(",skipped,")), "{csv}");
    assert!(std::fs::read_to_string(dir.join("compare.md")).unwrap().contains("timed_out: time limit of 0.001 s"));
    // A limit that is no time at all is a flag error.
    let out = contact2d(&["compare", "scenes/generic/pin_lug.toml", "--time-limit", "0", "--out", &out_dir]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--time-limit"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn stress_refuses_a_ratio_beyond_the_largest_float() {
    let dir = fresh("stress");
    let out = contact2d(&["stress", "--ratios", "1e400", "--quiet", "--out", &dir.to_string_lossy()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("--ratios") && stderr.contains("inf") && !stderr.contains("panicked"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Whether `c` is a character XML 1.0 allows (production [2] Char of the XML 1.0 recommendation).
fn xml_char(c: char) -> bool {
    matches!(c, '\u{9}' | '\u{A}' | '\u{D}' | '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..)
}

#[test]
fn control_characters_in_names_leave_valid_svg() {
    let dir = fresh("svg");
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", "scenes/generic/two_blocks_press_slide.toml", "--quiet"])
        .args(["--set", r#"name="bell\u0007 and escape\u001b""#, "--set", r#"contact.0.name="jo\u0001int""#])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svgs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    assert!(svgs.len() >= 3, "{svgs:?}");
    for svg in &svgs {
        let text = std::fs::read_to_string(svg).unwrap();
        let bad: Vec<char> = text.chars().filter(|c| !xml_char(*c)).collect();
        assert!(bad.is_empty(), "{}: characters XML forbids: {bad:?}", svg.display());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Two unit squares `a` (y in 0..1) and `b` (y in 1..2), one Q4 each, sharing the nodes 3 and 4
/// at y = 1; `a` fixed at the bottom, `b` loaded at the top.
///
/// ```text
///   6 ---- 5   top (load)
///   |  b   |
///   4 ---- 3   shared by a and b
///   |  a   |
///   1 ---- 2   bottom (fixed)
/// ```
fn write_glued(dir: &Path) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let mesh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n1 3 \"bottom\"\n1 4 \"top\"\n2 1 \"a\"\n\
                2 2 \"b\"\n$EndPhysicalNames\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 1 2 0\n6 0 2 0\n\
                $EndNodes\n$Elements\n4\n1 3 2 1 1 1 2 3 4\n2 3 2 2 2 4 3 5 6\n3 1 2 3 3 1 2\n4 1 2 4 4 6 5\n\
                $EndElements\n";
    std::fs::write(dir.join("glued.msh"), mesh).unwrap();
    let body = |r: &str| format!("[[body]]\nregion = \"{r}\"\nyoungs_modulus = 1000.0\npoissons_ratio = 0.3\n\n");
    let scene = format!(
        "name = \"glued\"\nmesh = \"glued.msh\"\nplane = \"strain\"\n\n{}{}[[fix]]\ngroup = \"bottom\"\nu1 = 0.0\n\
         u2 = 0.0\n\n[[load]]\ngroup = \"top\"\nforce = [0.0, -1.0]\n",
        body("a"),
        body("b")
    );
    let path = dir.join("glued.toml");
    std::fs::write(&path, scene).unwrap();
    path
}

#[test]
fn bodies_sharing_nodes_get_a_note() {
    let dir = fresh("glued");
    let scene = write_glued(&dir);
    let r = json_run(&scene.to_string_lossy(), &[]);
    let notes = notes(&r);
    let note = notes.iter().find(|n| n.contains("share")).unwrap_or_else(|| panic!("{notes:?}"));
    // The mesh above shares exactly the nodes 3 and 4.
    assert!(note.contains("\"a\"") && note.contains("\"b\"") && note.contains("2 mesh nodes"), "{note}");
    assert!(note.contains("glued"), "{note}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_interference_deeper_than_an_element_gets_a_note() {
    // interference_fit.geo: the disk's rim r = a = 500 mm in n_arc = 16 quadratic edges over a
    // quarter circle, so the element size there is the chord 2 a sin(π / 64) = 49.068 mm.
    let chord = 2.0 * 500.0 * (std::f64::consts::PI / 64.0).sin();
    let size = format!("{chord:.4e}");
    assert_eq!(size, "4.9068e1");
    // The scene's own interference, 0.6667 mm, is far below an element: no note.
    let r = json_run("scenes/generic/interference_fit.toml", &[]);
    assert!(!notes(&r).iter().any(|n| n.contains("deeper than")), "{:?}", notes(&r));
    // 300 mm is six elements deep.
    let r = json_run("scenes/generic/interference_fit.toml", &["contact.0.gap=-300"]);
    let notes = notes(&r);
    let note = notes.iter().find(|n| n.contains("deeper than")).unwrap_or_else(|| panic!("{notes:?}"));
    assert!(note.contains("contact \"fit\"") && note.contains("3.0000e2") && note.contains(&size), "{note}");
}

//! `contact2d run --out DIR` writes a folder that is whole or absent (issue 15, item 4).
//!
//! ```text
//! lock       a second writer (live lock holder) is refused before solving; a stale lock goes
//! stale      a 3-step run then a 1-step run: history.*, step_001/002.vtu are gone, the user's
//!            own files stay (even one named like an output), summary.json lists exactly the files present
//! fail fast  an --out that cannot be created fails before the solve (no report on stdout)
//! killed     SIGTERM at any moment: either no summary.json, or one listing exactly the
//!            (non-hidden) files present
//! SIGKILL    a run killed outright leaves its files and its lock; the next run, a shorter one,
//!            removes the files the dead run's lock records (its step_001/002.vtu) before
//!            writing: its summary lists exactly the files present
//! undrawable a non-finite field: its figures skipped with a note, the rest written whole
//! ```
//! The scene is the clearance history on the N = 16 mesh (three steps, well under a second).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SCENE: &str = "scenes/plate_insert_gap_v1_mu03.toml";
const MESH: &str = "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0.05_N16.msh\"";

fn fresh(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact2d_folders_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn run(dir: &Path, extra: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", SCENE, "--set", MESH, "--quiet"])
        .args(extra)
        .arg("--out")
        .arg(dir)
        .output()
        .unwrap()
}

fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    n.sort();
    n
}

/// The files summary.json lists, sorted (None without a summary).
fn listed(dir: &Path) -> Option<Vec<String>> {
    let text = std::fs::read_to_string(dir.join("summary.json")).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut files: Vec<String> = v["files"].as_array().unwrap().iter().map(|f| f.as_str().unwrap().into()).collect();
    files.sort();
    Some(files)
}

#[test]
fn a_second_writer_is_refused_before_solving_and_a_stale_lock_is_replaced() {
    let dir = fresh("lock");
    std::fs::create_dir_all(&dir).unwrap();
    // A live process holds the lock: this test's own process.
    std::fs::write(dir.join(".contact2d.lock"), format!("{}\n", std::process::id())).unwrap();
    let out = run(&dir, &[]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("another contact2d process") && stderr.contains(&std::process::id().to_string()));
    assert!(out.stdout.is_empty(), "refused before solving: no report");
    // A lock whose process is gone (a pid above Linux's pid_max) is taken over.
    std::fs::write(dir.join(".contact2d.lock"), "4194305\n").unwrap();
    let out = run(&dir, &[]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(!dir.join(".contact2d.lock").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn two_concurrent_runs_leave_one_whole_folder() {
    let dir = fresh("concurrent");
    let spawn = || {
        Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(["run", SCENE, "--set", MESH, "--quiet", "--out"])
            .arg(&dir)
            .output()
    };
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(spawn);
        let b = s.spawn(spawn);
        (a.join().unwrap().unwrap(), b.join().unwrap().unwrap())
    });
    // Either both succeeded one after the other, or one was refused with the lock message.
    for o in [&a, &b] {
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success() || stderr.contains("another contact2d process"), "{stderr}");
    }
    assert!(a.status.success() || b.status.success());
    assert_eq!(listed(&dir).unwrap(), names(&dir));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_shorter_run_removes_the_stale_files_and_keeps_the_users() {
    let dir = fresh("stale");
    assert!(run(&dir, &[]).status.success());
    for stale in ["history.png", "step_001.vtu", "step_002.vtu"] {
        assert!(dir.join(stale).exists(), "{stale} after three steps");
    }
    std::fs::write(dir.join("my_notes.txt"), "the user's own file").unwrap();
    // Named like an output but listed by no record (issue 27): the user's, and it stays.
    std::fs::write(dir.join("step_007.vtu"), "the user's own step").unwrap();
    assert!(run(&dir, &["--set", "plate_insert.steps=1"]).status.success());
    for stale in ["history.png", "history.svg", "step_001.vtu", "step_002.vtu"] {
        assert!(!dir.join(stale).exists(), "{stale} is stale after one step");
    }
    let mut present = names(&dir);
    present.retain(|n| n != "my_notes.txt" && n != "step_007.vtu");
    assert_eq!(listed(&dir).unwrap(), present, "summary.json lists exactly the run's files");
    assert_eq!(std::fs::read_to_string(dir.join("my_notes.txt")).unwrap(), "the user's own file");
    assert_eq!(std::fs::read_to_string(dir.join("step_007.vtu")).unwrap(), "the user's own step");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_output_folder_that_cannot_be_created_fails_before_the_solve() {
    let file = fresh("notadir");
    std::fs::write(&file, "a file where a folder is asked for").unwrap();
    // N = 64: the solve alone takes longer than the refusal.
    let start = std::time::Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", SCENE, "--quiet", "--out"])
        .arg(file.join("sub"))
        .output()
        .unwrap();
    let elapsed = start.elapsed();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("sub") && stderr.trim().lines().count() == 1, "{stderr}");
    assert!(out.stdout.is_empty(), "no report: the solve never ran");
    // The same scene solves in about a second here; the refusal takes milliseconds. 0.5 s leaves a
    // loaded machine room while still failing if the solve ran first.
    assert!(elapsed.as_secs_f64() < 0.5, "took {elapsed:?}");
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["run", SCENE, "--out"]).arg(&file).output().unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("not a directory"));
    std::fs::remove_file(&file).unwrap();
    // A symbolic link to nothing is named as such, not as "File exists (os error 17)".
    let link = fresh("dangling");
    std::os::unix::fs::symlink(fresh("nowhere"), &link).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["run", SCENE, "--out"]).arg(&link).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("is a dangling symbolic link") && stderr.contains("nowhere"), "{stderr}");
    assert!(!stderr.contains("os error") && stderr.trim().lines().count() == 1, "{stderr}");
    std::fs::remove_file(&link).unwrap();
}

#[test]
fn a_run_killed_at_any_moment_leaves_a_whole_folder_or_no_summary() {
    let dir = fresh("killed");
    // A first complete run with μ = 0.1, then runs with μ = 0.3 killed at growing delays.
    assert!(run(&dir, &["--set", "plate_insert.friction=0.1"]).status.success());
    for delay_ms in [5, 40, 120, 250, 400, 700] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(["run", SCENE, "--set", MESH, "--quiet", "--set", "plate_insert.friction=0.3", "--out"])
            .arg(&dir)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(delay_ms));
        let _ = Command::new("kill").args(["-TERM", &child.id().to_string()]).status();
        child.wait().unwrap();
        let visible: Vec<String> = names(&dir).into_iter().filter(|n| !n.starts_with('.')).collect();
        if let Some(files) = listed(&dir) {
            assert_eq!(files, visible, "after {delay_ms} ms: a summary lists exactly the files present");
            let summary: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
            // The step table and the summary come from the same run (μ = 0.1 and 0.3 differ in P).
            let steps = std::fs::read_to_string(dir.join("steps.csv")).unwrap();
            let header: Vec<&str> = steps.lines().next().unwrap().split(',').collect();
            let last: Vec<&str> = steps.lines().last().unwrap().split(',').collect();
            let p = last[header.iter().position(|h| *h == "P").unwrap()].parse::<f64>().unwrap();
            assert_eq!(
                Some(p),
                summary["paper"]["P"].as_f64(),
                "after {delay_ms} ms: steps.csv and summary.json agree"
            );
        }
    }
    // The next run cleans up whatever a killed one left (stale lock, temporary files).
    assert!(run(&dir, &[]).status.success());
    assert_eq!(listed(&dir).unwrap(), names(&dir));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// What a run killed by SIGKILL while writing leaves, made exactly: the lock of a dead process
/// (a pid above Linux's pid_max) recording the three-step run's files, those files present, no
/// summary. A one-step run then writes into the folder: the dead run's step_001/002.vtu and
/// history.* go, the user's own file stays, and the summary lists exactly the files present.
#[test]
fn a_killed_runs_files_recorded_in_its_lock_are_removed_before_writing() {
    let dir = fresh("sigkill");
    assert!(run(&dir, &[]).status.success(), "three steps");
    let three = listed(&dir).unwrap();
    assert!(three.contains(&"step_002.vtu".to_string()) && three.contains(&"history.png".to_string()));
    // The killed run had removed the manifest and recorded every file it started writing.
    std::fs::remove_file(dir.join("summary.json")).unwrap();
    let record: String = three.iter().map(|f| format!("{f}\n")).collect();
    std::fs::write(dir.join(".contact2d.lock"), format!("4194305\n{record}")).unwrap();
    std::fs::write(dir.join(".contact2d-tmp-4194305-step_003.vtu"), "half").unwrap();
    std::fs::write(dir.join("notes_of_mine.txt"), "mine").unwrap();
    let out = run(&dir, &["--set", "plate_insert.steps=1"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let files = listed(&dir).unwrap();
    let present: Vec<String> = names(&dir).into_iter().filter(|n| n != "notes_of_mine.txt").collect();
    assert_eq!(files, present, "the summary lists exactly the files present");
    for gone in ["step_001.vtu", "step_002.vtu", "history.png", ".contact2d-tmp-4194305-step_003.vtu"] {
        assert!(!dir.join(gone).exists(), "{gone} of the dead run");
    }
    assert!(dir.join("notes_of_mine.txt").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The same with a real SIGKILL at growing delays: whatever moment the three-step run died,
/// the one-step run after it leaves exactly the files its summary lists.
#[test]
fn a_run_after_a_sigkill_leaves_exactly_its_own_files() {
    let dir = fresh("sigkill_real");
    for delay_ms in [150, 400, 800] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(["run", SCENE, "--set", MESH, "--quiet", "--out"])
            .arg(&dir)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_millis(delay_ms));
        let _ = Command::new("kill").args(["-KILL", &child.id().to_string()]).status();
        child.wait().unwrap();
        let out = run(&dir, &["--set", "plate_insert.steps=1"]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(listed(&dir).unwrap(), names(&dir), "after a SIGKILL at {delay_ms} ms");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn figures_that_cannot_be_drawn_are_skipped_with_a_note() {
    use contact2d::plate_insert::PlateInsertScene;
    let scene = PlateInsertScene::load(Path::new(SCENE), &[MESH.to_string()]).unwrap();
    let mut outcome = contact2d::run::solve_scene(&scene).unwrap();
    // A non-finite displacement (what w = 1e308 produced): the mesh figure and the von Mises
    // field cannot be drawn; the run's other files are still written, whole.
    outcome.steps.last_mut().unwrap().solution.displacement[0] = f64::NAN;
    let dir = fresh("undrawable");
    let written = contact2d::plate_insert::outputs::write_outputs(&dir, &scene, &outcome).unwrap();
    assert_eq!(written.last().unwrap().file_name().unwrap(), "summary.json");
    assert!(!dir.join("mesh.png").exists() && !dir.join("von_mises.svg").exists());
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let notes: Vec<&str> = summary["notes"].as_array().unwrap().iter().map(|n| n.as_str().unwrap()).collect();
    for figure in ["mesh.png", "mesh.svg", "von_mises.png", "von_mises.svg"] {
        assert!(notes.iter().any(|n| n.starts_with(&format!("{figure} not drawn"))), "{figure}: {notes:?}");
    }
    assert!(std::fs::read_to_string(dir.join("README.txt")).unwrap().contains("Not drawn"));
    assert_eq!(listed(&dir).unwrap(), names(&dir));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_run_that_fails_before_writing_leaves_the_previous_folder_untouched() {
    let dir = fresh("failed_solve");
    assert!(run(&dir, &[]).status.success());
    let before = std::fs::read(dir.join("summary.json")).unwrap();
    // A mesh without the flagship's groups: the scene loads, the set-up after the lock fails.
    let out = run(&dir, &["--set", "plate_insert.mesh=\"../meshes/fixtures/plate_hole_v41_ascii.msh\""]);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read(dir.join("summary.json")).unwrap(), before, "the previous summary stands");
    assert_eq!(listed(&dir).unwrap(), names(&dir), "and still lists exactly the files (no lock left)");
    std::fs::remove_dir_all(&dir).unwrap();
}

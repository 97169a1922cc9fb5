//! No panic, no hang, errors that say what happened (issue 15, items 5 and 7), for the triggers
//! that a file in `tests/bad_inputs/` cannot carry: a FIFO, a closed or full stderr, `bench`
//! flags, an interrupted sweep, and list values in `--vary`.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const NOGAP: &str = "scenes/plate_insert_nogap_mu0.toml";
const MESH16: &str = "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0_N16.msh\"";

/// Waits for `child` at most `limit`; kills it and fails on a hang.
fn wait_at_most(mut child: std::process::Child, limit: Duration) -> std::process::Output {
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            let _ = child.kill();
            panic!("still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[test]
fn a_fifo_as_mesh_or_scene_is_refused_without_blocking() {
    let fifo = std::env::temp_dir().join(format!("contact2d_fifo_{}", std::process::id()));
    let _ = std::fs::remove_file(&fifo);
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let fifo_s = fifo.display().to_string();
    let mesh = format!("plate_insert.mesh=\"{fifo_s}\"");
    for args in
        [vec!["run", NOGAP, "--set", mesh.as_str()], vec!["mesh", fifo_s.as_str()], vec!["run", fifo_s.as_str()]]
    {
        let child = Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let out = wait_at_most(child, Duration::from_secs(10));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains("not a regular file (a FIFO)") && stderr.contains(&fifo_s), "{args:?}: {stderr}");
    }
    std::fs::remove_file(&fifo).unwrap();
}

#[test]
fn a_closed_or_full_stderr_is_no_panic() {
    let bin = env!("CARGO_BIN_EXE_contact2d");
    // An error to report (exit 1) and a --json run with --out that reports its files on stderr.
    for (redirect, args) in [
        ("2>&-", "run scenes/none.toml"),
        ("2>/dev/full", "run scenes/none.toml"),
        ("2>/dev/full", "mesh does/not/exist.msh"),
    ] {
        let out = Command::new("sh").arg("-c").arg(format!("'{bin}' {args} {redirect}")).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{args} {redirect}: not a panic (101)");
    }
    let dir = std::env::temp_dir().join(format!("contact2d_stderr_{}", std::process::id()));
    let cmd = format!("'{bin}' run {NOGAP} --set '{MESH16}' --json --out '{}' 2>/dev/full", dir.display());
    let out = Command::new("sh").arg("-c").arg(cmd).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bench_without_a_mesh_for_a_level_is_an_error() {
    for levels in ["0", "16,17"] {
        let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
            .args(["bench", "--levels", levels, "--cases", "U3", "--quiet", "--out"])
            .arg(std::env::temp_dir().join(format!("contact2d_bench_levels_{}", std::process::id())))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "--levels {levels}: {stderr}");
        assert!(stderr.contains("--levels") && stderr.trim().lines().count() == 1, "{stderr}");
    }
}

#[test]
fn list_values_in_vary_are_split_at_top_level_commas() {
    let dir = std::env::temp_dir().join(format!("contact2d_vary_lists_{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args([
            "sweep",
            "scenes/plate_insert_gap_v1_mu03.toml",
            "--vary",
            "plate_insert.l_steps=[0.1,0.2],[0.3]",
            "--set",
            "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0.05_N16.msh\"",
            "--set",
            "solver.algorithm=boussinesq",
            "--set",
            "plate_insert.load=0",
            "--set",
            "plate_insert.steps=1",
            "--quiet",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), 2, "{csv}");
    assert!(rows[0].starts_with("\"[0.1,0.2]\",converged") && rows[1].starts_with("[0.3],converged"), "{csv}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_interrupted_sweep_keeps_its_finished_rows() {
    let dir = std::env::temp_dir().join(format!("contact2d_sweep_sigint_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    // 40 runs on the N = 64 mesh: seconds in all, so the interrupt comes mid-sweep.
    let values: Vec<String> = (0..40).map(|i| format!("{}", 0.01 * f64::from(i))).collect();
    let child = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", NOGAP, "--vary", &format!("plate_insert.friction={}", values.join(",")), "--quiet", "--out"])
        .arg(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let partial = dir.join("sweep.csv.partial");
    let start = Instant::now();
    let rows = || std::fs::read_to_string(&partial).map_or(0, |t| t.lines().count().saturating_sub(1));
    while rows() < 2 && start.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = Command::new("kill").args(["-INT", &child.id().to_string()]).status();
    let out = wait_at_most(child, Duration::from_secs(60));
    let text = std::fs::read_to_string(&partial).unwrap_or_default();
    if out.status.success() {
        // The sweep finished before the interrupt: the whole table is there instead.
        assert_eq!(std::fs::read_to_string(dir.join("sweep.csv")).unwrap().lines().count(), 41);
    } else {
        let finished: Vec<&str> = text.lines().skip(1).collect();
        assert!(finished.len() >= 2, "the finished rows are kept: {text}");
        for row in finished {
            assert!(row.contains(",converged,"), "{row}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

//! The same answer every run: a placed Boussinesq history and an active-set history, each run
//! twice with one rayon thread and twice with two, give the same JSON bit for bit (timing
//! fields aside).
//!
//! Scene: `scenes/plate_insert_gap_v1_mu03.toml` (ε = 0.05, c = 1, μ = 0.3, w = 0.3838 in three
//! steps) on the N = 16 mesh, the case where issue 15 found 20 different answers in 20 runs
//! (b between 0.028 and 0.136): the zone-end placement morphs the mesh, and the morphing
//! iterated over hash sets, whose order is random per process. The comparison is exact: there
//! is no tolerance, because nothing in the computation may depend on the run or the thread
//! count (faer runs sequentially, every parallel loop writes disjoint outputs or reduces in a
//! fixed order).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

use serde_json::Value;

/// The `--json` summary of `contact2d run ARGS` with `threads` rayon threads, timing fields
/// removed.
fn summary(args: &[&str], threads: &str) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .env("RAYON_NUM_THREADS", threads)
        .arg("run")
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let mut summary: Value = serde_json::from_slice(&out.stdout).unwrap();
    strip_times(&mut summary);
    summary
}

/// The flagship's U(1) history on the N = 16 mesh with `algorithm`.
fn run(algorithm: &str, threads: &str) -> Value {
    let algorithm = format!("solver.algorithm={algorithm}");
    let mesh = "plate_insert.mesh=../meshes/plate_insert/plate_insert_eps0.05_N16.msh";
    summary(&["scenes/plate_insert_gap_v1_mu03.toml", "--set", mesh, "--set", &algorithm], threads)
}

/// Removes every field whose name ends in `time_s` (wall times), at any depth.
fn strip_times(v: &mut Value) {
    match v {
        Value::Object(map) => {
            map.retain(|k, _| !k.ends_with("time_s"));
            map.values_mut().for_each(strip_times);
        }
        Value::Array(items) => items.iter_mut().for_each(strip_times),
        _ => {}
    }
}

fn assert_repeatable(algorithm: &str) {
    let first = run(algorithm, "1");
    assert_eq!(first["status"], "converged", "{algorithm}: {first}");
    for threads in ["1", "2", "2"] {
        let again = run(algorithm, threads);
        // serde_json keeps f64s exactly (shortest round-trip form), so equality is bitwise.
        assert_eq!(again, first, "{algorithm} with {threads} thread(s) differs from the first run");
    }
}

#[test]
fn placed_boussinesq_history_is_the_same_every_run_and_thread_count() {
    assert_repeatable("boussinesq");
}

#[test]
fn active_set_history_is_the_same_every_run_and_thread_count() {
    assert_repeatable("active_set");
}

#[test]
fn generic_histories_with_floating_bodies_are_the_same_every_run_and_thread_count() {
    // Press-then-slide (two patterns, a floating block) and the pin in a lug (clearance,
    // friction, a floating pin): the proximal iterations and the schedules add no randomness.
    for scene in ["scenes/generic/two_blocks_press_slide.toml", "scenes/generic/pin_lug.toml"] {
        let first = summary(&[scene], "1");
        assert_eq!(first["status"], "converged", "{scene}");
        for threads in ["1", "2"] {
            assert_eq!(summary(&[scene], threads), first, "{scene} with {threads} thread(s)");
        }
    }
}

//! The fretting files of a cyclic run (`scenes/generic/cattaneo_mindlin_fretting.toml`, the
//! roller cycled ±Q* twice, 20 steps per cycle): the per-pair table holds one row per pair with
//! the JSON's numbers, and the hysteresis loop closes. Truths: the loop starts and ends at the
//! same load (+Q*: the same displacement-driven state, so the same force to the solver's
//! tolerance, 1e-6 of Q*), and its area −∮ Q dδ is the work of the driven top over the cycle,
//! which is stored nowhere at the end of a cycle and so equals the energy dissipated (the
//! trapezoid rule of 10 steps per half cycle cuts the loop's corners by about 1 %: 2 %).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

#[test]
fn fretting_table_and_hysteresis_loop_are_written_and_close() {
    let dir = std::env::temp_dir().join(format!("contact2d_fretting_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let status = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", "scenes/generic/cattaneo_mindlin_fretting.toml", "--quiet", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let fretting = &summary["contacts"]["roller"]["fretting"];
    assert_eq!(fretting["steps"], serde_json::json!([41, 60]));
    let table = std::fs::read_to_string(dir.join("fretting_roller.csv")).unwrap();
    let rows: Vec<&str> = table.lines().collect();
    assert_eq!(rows[0], "s,slip_amplitude,dissipation,shear_max,sigma_tt,ruiz");
    assert_eq!(rows.len() - 1, fretting["s"].as_array().unwrap().len());
    let loop_csv = std::fs::read_to_string(dir.join("hysteresis_roller.csv")).unwrap();
    let points: Vec<(f64, f64)> = loop_csv
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').skip(1).map(|x| x.parse().unwrap()).collect();
            (v[0], v[1])
        })
        .collect();
    assert_eq!(points.len(), 21, "the step before the cycle and its 20 steps");
    let (first, last) = (points[0], points[20]);
    assert!((first.1 - last.1).abs() <= 1e-6 * first.1.abs(), "{first:?} {last:?}");
    let area: f64 = -points.windows(2).map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0)).sum::<f64>();
    let dissipated = fretting["dissipated"].as_f64().unwrap();
    assert!((area - dissipated).abs() <= 0.02 * dissipated, "loop area {area}, dissipated {dissipated}");
    for f in ["hysteresis_roller.png", "hysteresis_roller.svg", "fretting_roller.png", "fretting_roller.svg"] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The text summary states the last cycle's numbers the JSON holds (the same run, printed two
/// ways): the cycle's steps and the energy dissipated to the printed six digits.
#[test]
fn the_text_summary_reports_the_last_cycle() {
    let run = |json: bool| {
        let mut args = vec!["run", "scenes/generic/cattaneo_mindlin_fretting.toml", "--quiet"];
        if json {
            args.push("--json");
        }
        let out = Command::new(env!("CARGO_BIN_EXE_contact2d")).args(&args).output().unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8(out.stdout).unwrap()
    };
    let summary: serde_json::Value = serde_json::from_str(&run(true)).unwrap();
    let dissipated = summary["contacts"]["roller"]["fretting"]["dissipated"].as_f64().unwrap();
    let text = run(false);
    let line = text.lines().find(|l| l.contains("last cycle")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("steps 41–60") && line.contains(&format!("dissipated {dissipated:.6e}")), "{line}");
}

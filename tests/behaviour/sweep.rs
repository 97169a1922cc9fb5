//! `contact2d sweep` end to end on the N = 16 no-gap mesh (each run takes a few milliseconds).
//!
//! ```text
//! --vary plate_insert.friction=0,0.3,oops   two runs and one failing value (a row with its error)
//! check: every successful row satisfies the energy balance of proportional loading,
//!        W = P w / 2 = Φ_E1 + Φ_E2 + Φ_f   (spec §3 and §7)
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::Command;

#[test]
fn sweep_over_two_friction_values_tabulates_plots_and_keeps_failures_as_rows() {
    let dir = std::env::temp_dir().join(format!("contact2d_sweep_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args([
            "sweep",
            "scenes/plate_insert_nogap_mu0.toml",
            "--vary",
            "plate_insert.friction=0,0.3,oops",
            "--set",
            "plate_insert.mesh=\"../meshes/plate_insert/plate_insert_eps0_N16.msh\"",
            "--plot",
            "l,P",
            "--quiet",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("3 runs (1 failed)"), "{stdout}");

    let csv = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3);
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    assert_eq!(rows[2][col("status")], "error");
    assert!(rows[2][col("error")..].join(",").contains("oops"));

    // The energy balance of proportional loading; W is P w / 2 and the energies come from the
    // displacements, so they agree to the direct solver's round-off: 1e-8 relative is tight.
    for row in &rows[..2] {
        assert_eq!(row[col("status")], "converged");
        let v = |name: &str| row[col(name)].parse::<f64>().unwrap();
        let energy = v("Phi_E1") + v("Phi_E2") + v("Phi_f");
        assert!((v("W") - energy).abs() <= 1e-8 * energy, "W = {} vs Φ = {energy}", v("W"));
    }
    // Friction raises P (spec §7: "friction raises P, l, the energies and σ*").
    assert!(rows[1][col("P")].parse::<f64>().unwrap() > rows[0][col("P")].parse::<f64>().unwrap());

    let md = std::fs::read_to_string(dir.join("sweep.md")).unwrap();
    assert_eq!(md.lines().count(), 2 + 3);
    for name in ["sweep_l.png", "sweep_P.png"] {
        assert_eq!(&std::fs::read(dir.join(name)).unwrap()[..8], b"\x89PNG\r\n\x1a\n", "{name}");
    }
    assert!(std::fs::read_to_string(dir.join("sweep_P.svg")).unwrap().contains("plate_insert_nogap_mu0"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn sweep_rejects_a_malformed_vary_with_one_clear_line() {
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["sweep", "scenes/plate_insert_nogap_mu0.toml", "--vary", "plate_insert.friction", "--quiet"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(stderr.contains("--vary plate_insert.friction") && !stderr.contains("panicked"), "{stderr}");
}

//! `contact2d run SCENE --out DIR` end to end: every documented file exists and is well formed, and
//! the hole-edge CSV conserves force.
//!
//! ```text
//! scenes: plate_insert_nogap_mu03 (one proportional step) and plate_insert_gap_v1_mu03 (three load
//!         steps with clearance), both on the N = 16 meshes so that each run takes well under a second
//! files:  every scene's (summary.json, README.txt, figures .png and .svg, contact_hole.csv,
//!         steps.csv, step_NNN.vtu one per step, steps.pvd) and the preset's (hole_edge and
//!         insert_hoop figures, history = l(w), b(w) for more than one step, hole_edge.csv, insert_edge.csv)
//! check:  Σ_hole-edge nodes traction_x1 · weight + P = 0   (the plate's free-body balance in x1)
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::Command;

const PNG_SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";

fn run_with_outputs(scene: &str, mesh: &str, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact2d_outputs_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", scene, "--set", &format!("plate_insert.mesh=\"../meshes/plate_insert/{mesh}\""), "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("wrote") && stdout.contains("steps.pvd"), "the CLI lists the files: {stdout}");
    dir
}

fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows: Vec<Vec<String>> = lines.map(|l| l.split(',').map(String::from).collect()).collect();
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{}: ragged row {r:?}", path.display());
    }
    (header, rows)
}

fn column(header: &[String], rows: &[Vec<String>], name: &str) -> Vec<Option<f64>> {
    let k = header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    rows.iter().map(|r| if r[k].is_empty() { None } else { Some(r[k].parse().unwrap()) }).collect()
}

/// Every documented file is there and well formed; returns the summary.
fn check_folder(dir: &Path, steps: usize, mesh: &str) -> serde_json::Value {
    let mut figures = vec!["mesh", "contact_hole", "hole_edge", "insert_hoop", "von_mises"];
    if steps > 1 {
        figures.push("history");
    }
    for f in &figures {
        let png = std::fs::read(dir.join(format!("{f}.png"))).unwrap();
        assert_eq!(&png[..8], PNG_SIGNATURE, "{f}.png");
        let svg = std::fs::read_to_string(dir.join(format!("{f}.svg"))).unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"), "{f}.svg");
        assert!(svg.contains("plate_insert_"), "{f}.svg has the scene name in its title");
    }
    if steps == 1 {
        assert!(!dir.join("history.png").exists(), "no history figure for one step");
    }

    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["steps"].as_array().unwrap().len(), steps);

    // The summary is the manifest: it lists exactly the files in the folder, itself last.
    let mut listed: Vec<String> =
        summary["files"].as_array().unwrap().iter().map(|f| f.as_str().unwrap().to_string()).collect();
    assert_eq!(listed.last().map(String::as_str), Some("summary.json"));
    listed.sort();
    let mut present: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    present.sort();
    assert_eq!(listed, present, "summary.json lists exactly the files present (no lock, no temporary file)");

    let readme = std::fs::read_to_string(dir.join("README.txt")).unwrap();
    for entry in std::fs::read_dir(dir).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        assert!(readme.contains(&name), "README.txt describes {name}");
    }

    let (header, rows) = read_csv(&dir.join("steps.csv"));
    assert_eq!(rows.len(), steps);
    let p_csv = column(&header, &rows, "P");
    assert_eq!(p_csv[steps - 1], summary["paper"]["P"].as_f64());

    // VTU files: read back with vtkio, one point per mesh node, Quad9 cells as biquadratic quads.
    let mesh_nodes = contact2d::mesh::read_msh(format!("meshes/plate_insert/{mesh}")).unwrap().num_nodes();
    let pvd = std::fs::read_to_string(dir.join("steps.pvd")).unwrap();
    for k in 0..steps {
        let name = format!("step_{k:03}.vtu");
        assert!(pvd.contains(&format!("file=\"{name}\"")), "steps.pvd lists {name}");
        let vtk = vtkio::Vtk::import(dir.join(&name)).unwrap();
        let vtkio::model::DataSet::UnstructuredGrid { pieces, .. } = vtk.data else { panic!("{name}: not a grid") };
        let vtkio::model::Piece::Inline(piece) = &pieces[0] else { panic!("{name}: piece not inline") };
        assert_eq!(piece.num_points(), mesh_nodes, "{name}: one point per mesh node");
        assert!(piece.cells.types.iter().all(|t| *t == vtkio::model::CellType::BiquadraticQuad));
        let names: Vec<&str> = piece
            .data
            .point
            .iter()
            .map(|a| match a {
                vtkio::model::Attribute::DataArray(d) => d.name.as_str(),
                vtkio::model::Attribute::Field { name, .. } => name.as_str(),
            })
            .collect();
        for want in ["displacement", "stress", "von_mises", "contact_p", "contact_q", "contact_state"] {
            assert!(names.contains(&want), "{name}: point data {want} in {names:?}");
        }
    }
    assert_eq!(pvd.matches("<DataSet").count(), steps);
    summary
}

/// The plate is held in x1 only by the pulled edge (reaction P) and by the insert through the hole
/// edge (the other supports are rollers with x2 reactions only), so Σ traction_x1 · weight = −P.
/// The discrete balance is exact (nodal forces of an assembled system sum to zero in a rigid
/// translation) up to the direct solver's round-off (≈ 1e-12 relative for these condition
/// numbers); the CSV stores shortest round-trip numbers, so 1e-9 of P is a tight, safe bound.
fn check_hole_edge_balance(dir: &Path, summary: &serde_json::Value) {
    let (header, rows) = read_csv(&dir.join("hole_edge.csv"));
    let t1 = column(&header, &rows, "traction_x1");
    let w = column(&header, &rows, "weight");
    let resultant: f64 = t1.iter().zip(&w).map(|(t, w)| t.unwrap() * w.unwrap()).sum();
    let pull = summary["paper"]["P"].as_f64().unwrap();
    assert!(pull > 0.0);
    assert!((resultant + pull).abs() <= 1e-9 * pull, "Σ t1 w = {resultant:e}, P = {pull:e}");
    // Newton's third law: the insert edge carries the opposite forces, Σ traction_x1 · weight = +P
    // (every slave shape weight lands on an insert-edge node), to the same tolerance.
    let (ih, irows) = read_csv(&dir.join("insert_edge.csv"));
    let it1 = column(&ih, &irows, "traction_x1");
    let iw = column(&ih, &irows, "weight");
    let insert_resultant: f64 = it1.iter().zip(&iw).filter_map(|(t, w)| Some((*t)? * (*w)?)).sum();
    assert!((insert_resultant - pull).abs() <= 1e-9 * pull, "insert Σ t1 w = {insert_resultant:e}, P = {pull:e}");
    // Compression near η = 0: p < 0 on the pair at the bearing point.
    let eta = column(&header, &rows, "eta");
    let p = column(&header, &rows, "p");
    let k = eta.iter().position(|e| *e == Some(0.0)).unwrap();
    assert!(p[k].unwrap() < 0.0);
}

#[test]
fn no_gap_run_writes_every_documented_file() {
    let dir = run_with_outputs("scenes/plate_insert_nogap_mu03.toml", "plate_insert_eps0_N16.msh", "nogap");
    let summary = check_folder(&dir, 1, "plate_insert_eps0_N16.msh");
    check_hole_edge_balance(&dir, &summary);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn clearance_history_writes_one_vtu_per_step() {
    let dir = run_with_outputs("scenes/plate_insert_gap_v1_mu03.toml", "plate_insert_eps0.05_N16.msh", "gap");
    let summary = check_folder(&dir, 3, "plate_insert_eps0.05_N16.msh");
    check_hole_edge_balance(&dir, &summary);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn variant_2_pairs_balance_on_the_slave_hole_edge() {
    // Variant 2: the hole edge is the slave contour; its nodal forces come from the pairs' shape
    // weights, so the balance holds as tightly as with the hole as master.
    let dir = run_with_outputs("scenes/plate_insert_gap_v2_mu0.toml", "plate_insert_eps0.05_N16.msh", "variant2");
    let summary = check_folder(&dir, 1, "plate_insert_eps0.05_N16.msh");
    check_hole_edge_balance(&dir, &summary);
    std::fs::remove_dir_all(&dir).unwrap();
}

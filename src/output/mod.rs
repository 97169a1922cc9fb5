//! Outputs of a solved scene: figures (PNG and SVG), CSV tables, VTU files for ParaView.
//!
//! [`write_outputs`] writes the folder of `contact2d run SCENE --out DIR`:
//!
//! ```text
//! summary.json                     the run's summary (the --json object)
//! mesh, hole_edge, insert_hoop,    figures (.png and .svg) of the last step; insert_hoop only for an
//! von_mises, history               elastic insert, history only for more than one step
//! hole_edge.csv, insert_edge.csv   contour profiles of the last step
//! steps.csv                        the step table
//! step_000.vtu, ..., steps.pvd     one VTK file per step and their ParaView collection
//! README.txt                       what each file is
//! ```
//! Library code here writes files and returns what it wrote; it never prints.
//! [`chart`] is the shared line-chart API every figure of the project draws with.

pub mod chart;
pub mod csv;
mod error;
pub mod field_plot;
pub mod figures;
pub mod mesh_plot;
pub mod profiles;
pub mod readme;
pub mod step_view;
pub mod vtu;

use std::path::{Path, PathBuf};

pub use error::OutputError;

use crate::run::RunOutcome;
use crate::scene::Scene;

/// The figure formats written for every figure.
pub const FIGURE_EXTENSIONS: [&str; 2] = ["png", "svg"];

/// Writes every output of a solved scene into `dir` (created if missing) and returns the paths
/// written, in the order of the module docs.
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written.
pub fn write_outputs(dir: &Path, scene: &Scene, outcome: &RunOutcome) -> Result<Vec<PathBuf>, OutputError> {
    std::fs::create_dir_all(dir).map_err(|e| OutputError::io(dir, e))?;
    let last = outcome.steps.last().ok_or_else(|| OutputError::MissingData {
        path: dir.to_path_buf(),
        reason: "the run has no solved step".into(),
    })?;
    let mut written: Vec<PathBuf> = vec![];

    let summary = dir.join("summary.json");
    let text = serde_json::to_string_pretty(&outcome.report)
        .map_err(|e| OutputError::Serialize { path: summary.clone(), reason: e.to_string() })?;
    std::fs::write(&summary, text + "\n").map_err(|e| OutputError::io(&summary, e))?;
    written.push(summary);

    let n = outcome.steps.len();
    let step_label = format!("step {n}/{n}, w = {:.4}", last.solution.load_factor);
    let title = |what: &str| format!("{}: {what} ({step_label})", scene.name);
    let profiles: Vec<profiles::Profiles> =
        outcome.steps.iter().map(profiles::contour_profiles).collect::<Result<_, _>>()?;
    let final_profiles = profiles
        .last()
        .ok_or_else(|| OutputError::MissingData { path: dir.to_path_buf(), reason: "no contour profile".into() })?;
    let elastic_insert = last.case.problem.model.body("insert").is_some();
    let last_view = profiles::flagship_view(last, final_profiles);

    for ext in FIGURE_EXTENSIONS {
        let path = dir.join(format!("mesh.{ext}"));
        mesh_plot::draw_mesh(&path, &title("mesh"), &last_view)?;
        written.push(path);
        let path = dir.join(format!("hole_edge.{ext}"));
        let ends: Vec<(&str, f64)> = [("l", last.results.contact_end), ("b", last.results.stick_end)]
            .into_iter()
            .filter_map(|(name, v)| Some((name, v?)))
            .collect();
        figures::draw_hole_edge(&path, &title("hole edge"), &final_profiles.hole, &ends)?;
        written.push(path);
        if elastic_insert {
            let path = dir.join(format!("insert_hoop.{ext}"));
            figures::draw_insert_hoop(&path, &title("insert hoop stress"), &final_profiles.insert)?;
            written.push(path);
        }
        let path = dir.join(format!("von_mises.{ext}"));
        field_plot::draw_von_mises(&path, &title("von Mises stress"), &last_view)?;
        written.push(path);
        if n > 1 {
            let path = dir.join(format!("history.{ext}"));
            figures::draw_history(&path, &format!("{}: zone ends over the loading", scene.name), outcome)?;
            written.push(path);
        }
    }

    let tags = &last.case.problem.model.mesh.node_tags;
    let path = dir.join("hole_edge.csv");
    csv::write_profile_csv(&path, csv::HOLE_EDGE_HEADER, &final_profiles.hole, tags)?;
    written.push(path);
    let path = dir.join("insert_edge.csv");
    csv::write_profile_csv(&path, csv::INSERT_EDGE_HEADER, &final_profiles.insert, tags)?;
    written.push(path);
    let path = dir.join("steps.csv");
    csv::write_steps_csv(&path, outcome)?;
    written.push(path);

    let mut collection = vec![];
    for (k, (step, p)) in outcome.steps.iter().zip(&profiles).enumerate() {
        let name = step_file_name(k);
        let path = dir.join(&name);
        vtu::write_step_vtu(&path, &profiles::flagship_view(step, p))?;
        written.push(path);
        collection.push((step.solution.load_factor, name));
    }
    let path = dir.join("steps.pvd");
    vtu::write_pvd(&path, &collection)?;
    written.push(path);

    let path = dir.join("README.txt");
    written.push(path.clone());
    let names: Vec<String> =
        written.iter().filter_map(|p| p.file_name().map(|f| f.to_string_lossy().into_owned())).collect();
    std::fs::write(&path, readme::readme_text(scene, outcome, &names)).map_err(|e| OutputError::io(&path, e))?;
    Ok(written)
}

/// The VTU file name of step `k` (0-based): `step_000.vtu`, `step_001.vtu`, ...
pub fn step_file_name(k: usize) -> String {
    format!("step_{k:03}.vtu")
}

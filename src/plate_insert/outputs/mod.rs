//! The plate-insert preset's outputs: the flagship's figures and tables of a solved run,
//! written through the same [`OutputDir`] as every scene's:
//!
//! ```text
//! summary.json                     the run's summary (the --json object) plus "files", the list of
//!                                  this run's files: written last, so a folder without it is
//!                                  incomplete (see crate::output::atomic)
//! mesh, hole_edge, insert_hoop,    figures (.png and .svg) of the last step; insert_hoop only for an
//! von_mises, history               elastic insert, history only for more than one step
//! hole_edge.csv, insert_edge.csv   contour profiles of the last step
//! steps.csv                        the step table
//! contact_hole_step_<k>.csv        every step's interface profile (run --profiles all)
//! step_000.vtu, ..., steps.pvd     one VTK file per step and their ParaView collection
//! README.txt                       what each file is
//! ```

pub mod csv;
#[cfg(feature = "native")]
pub mod figures;
pub mod profiles;
pub mod readme;

#[cfg(feature = "native")]
use std::path::{Path, PathBuf};

#[cfg(feature = "native")]
use crate::output::{
    FIGURE_EXTENSIONS, OutputDir, OutputError, SUMMARY_FILE, atomic, field_plot, figure, mesh_plot, step_file_name, vtu,
};
#[cfg(feature = "native")]
use crate::run::RunOutcome;
#[cfg(feature = "native")]
use crate::scene::Scene;

#[cfg(feature = "native")]
/// Writes every output of a solved scene into `dir` (see [`write_outputs_into`]); the folder is
/// prepared (created, checked, locked) here. Prefer [`atomic::OutputDir::prepare`] before
/// solving and [`write_outputs_into`] after, so that a bad folder fails before the work.
///
/// # Errors
/// [`OutputError`] naming the folder or the first file that could not be written.
pub fn write_outputs(dir: &Path, scene: &Scene, outcome: &RunOutcome) -> Result<Vec<PathBuf>, OutputError> {
    write_outputs_into(OutputDir::prepare(dir, Some(SUMMARY_FILE))?, scene, outcome)
}

#[cfg(feature = "native")]
/// Writes every output of a solved scene into the prepared folder `out` and returns the paths
/// written, the summary last: each file atomically, stale files of an earlier run removed, the
/// summary (with `"files"`, the manifest) last. A figure that cannot be drawn (non-finite or
/// unrepresentable values) is skipped with a note in the summary's `notes` and the README.
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written; the folder then holds no
/// summary and none of this run's files.
pub fn write_outputs_into(
    mut out: OutputDir,
    scene: &Scene,
    outcome: &RunOutcome,
) -> Result<Vec<PathBuf>, OutputError> {
    let dir = out.path().to_path_buf();
    let last = outcome
        .steps
        .last()
        .ok_or_else(|| OutputError::MissingData { path: dir.clone(), reason: "the run has no solved step".into() })?;
    let mut skipped: Vec<String> = vec![];

    let n = outcome.steps.len();
    let step_label = format!("step {n}/{n}, w = {:.4}", last.solution.load_factor);
    let title = |what: &str| format!("{}: {what} ({step_label})", scene.name);
    let profiles: Vec<profiles::Profiles> =
        outcome.steps.iter().map(profiles::contour_profiles).collect::<Result<_, _>>()?;
    let final_profiles = profiles
        .last()
        .ok_or_else(|| OutputError::MissingData { path: dir.clone(), reason: "no contour profile".into() })?;
    let elastic_insert = last.case.problem.model.body("insert").is_some();
    let last_view = profiles::flagship_view(last, final_profiles);

    for ext in FIGURE_EXTENSIONS {
        figure(&mut out, &format!("mesh.{ext}"), &mut skipped, |p| {
            mesh_plot::draw_mesh(p, &title("mesh"), &last_view)
        })?;
        let ends: Vec<(&str, f64)> = [("l", last.results.contact_end), ("b", last.results.stick_end)]
            .into_iter()
            .filter_map(|(name, v)| Some((name, v?)))
            .collect();
        figure(&mut out, &format!("hole_edge.{ext}"), &mut skipped, |p| {
            figures::draw_hole_edge(p, &title("hole edge"), &final_profiles.hole, &ends)
        })?;
        if elastic_insert {
            figure(&mut out, &format!("insert_hoop.{ext}"), &mut skipped, |p| {
                figures::draw_insert_hoop(p, &title("insert hoop stress"), &final_profiles.insert)
            })?;
        }
        figure(&mut out, &format!("von_mises.{ext}"), &mut skipped, |p| {
            field_plot::draw_von_mises(p, &title("von Mises stress"), &last_view)
        })?;
        if n > 1 {
            figure(&mut out, &format!("history.{ext}"), &mut skipped, |p| {
                figures::draw_history(p, &format!("{}: zone ends over the loading", scene.name), outcome)
            })?;
        }
    }

    let tags = &last.case.problem.model.mesh.node_tags;
    out.write_with("hole_edge.csv", |p| csv::write_profile_csv(p, csv::HOLE_EDGE_HEADER, &final_profiles.hole, tags))?;
    out.write_with("insert_edge.csv", |p| {
        csv::write_profile_csv(p, csv::INSERT_EDGE_HEADER, &final_profiles.insert, tags)
    })?;
    out.write_with("steps.csv", |p| csv::write_steps_csv(p, outcome))?;
    crate::generic::outputs::write_step_profiles(&mut out, &outcome.report.steps)?;

    let mut collection = vec![];
    for (k, (step, p)) in outcome.steps.iter().zip(&profiles).enumerate() {
        let name = step_file_name(k);
        out.write_with(&name, |tmp| vtu::write_step_vtu(tmp, &profiles::flagship_view(step, p)))?;
        collection.push((step.solution.load_factor, name));
    }
    out.write_with("steps.pvd", |p| vtu::write_pvd(p, &collection))?;

    let mut names: Vec<String> = out.written().to_vec();
    names.extend(["README.txt".to_string(), SUMMARY_FILE.to_string()]);
    let mut readme = readme::readme_text(scene, outcome, &names);
    if !skipped.is_empty() {
        readme.push_str("\nNot drawn (the data cannot be plotted; the CSV and VTU files hold the values):\n");
        for note in &skipped {
            readme.push_str(&format!("  {note}\n"));
        }
    }
    out.write_bytes("README.txt", readme.as_bytes())?;

    let mut report = outcome.report.clone();
    report.notes.extend(skipped);
    let summary_path = dir.join(SUMMARY_FILE);
    out.finish(|files| {
        let value = serde_json::to_value(&report)
            .map_err(|e| OutputError::Serialize { path: summary_path.clone(), reason: e.to_string() })?;
        atomic::manifest_json(value, files, &summary_path)
    })
}

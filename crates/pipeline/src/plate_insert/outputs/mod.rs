//! The plate-insert preset's post-processor outputs: the flagship's figures and tables, added
//! through [`PresetFiles`] to the folder every scene's run writes
//! (`crate::generic::outputs::finish_outputs`: mesh, contact_hole, von_mises, steps.csv with the
//! paper's columns, step files, README.txt, summary.json):
//!
//! ```text
//! hole_edge.png/.svg               s_φφ, p, q along the hole edge against η (last step)
//! insert_hoop.png/.svg             the insert's hoop stress (elastic insert only)
//! history.png/.svg                 l(w) and b(w) over the steps (more than one step; in place of
//!                                  every scene's force history)
//! hole_edge.csv, insert_edge.csv   contour profiles of the last step
//! steps.csv                        + w, l, b, P, Φ_E1, Φ_E2, Φ_f, W per step
//! step_000.vtu ...                 the flagship's view: both edges' p, q (paper's signs); time = w
//! ```

pub mod csv;
#[cfg(feature = "native")]
pub mod figures;
pub mod profiles;
pub mod readme;

#[cfg(feature = "native")]
use std::path::{Path, PathBuf};

#[cfg(feature = "native")]
use crate::generic::outputs::{RunFolder, finish_outputs};
#[cfg(feature = "native")]
use crate::output::{
    FIGURE_EXTENSIONS, OutputDir, OutputError, PresetFiles, SUMMARY_FILE, figure, step_file_name, vtu,
};
#[cfg(feature = "native")]
use crate::plate_insert::PlateInsertScene;
#[cfg(feature = "native")]
use crate::run::RunOutcome;

#[cfg(feature = "native")]
/// Writes every output of a solved scene into `dir` (see [`write_outputs_into`]); the folder is
/// prepared (created, checked, locked) here. Prefer [`crate::output::atomic::OutputDir::prepare`]
/// before solving and [`write_outputs_into`] after, so that a bad folder fails before the work.
///
/// # Errors
/// [`OutputError`] naming the folder or the first file that could not be written.
pub fn write_outputs(dir: &Path, scene: &PlateInsertScene, outcome: &RunOutcome) -> Result<Vec<PathBuf>, OutputError> {
    write_outputs_into(OutputDir::prepare(dir, Some(SUMMARY_FILE))?, scene, outcome)
}

#[cfg(feature = "native")]
/// Writes every output of a solved scene into the prepared folder `out` and returns the paths
/// written: the step files in the flagship's view, then every scene's files with the preset's
/// ([`PaperFiles`]), the summary last (see `crate::generic::outputs::finish_outputs`).
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written; the folder then holds no
/// summary and none of this run's files.
pub fn write_outputs_into(
    mut out: OutputDir,
    scene: &PlateInsertScene,
    outcome: &RunOutcome,
) -> Result<Vec<PathBuf>, OutputError> {
    let missing = |reason: &str| OutputError::MissingData { path: out.path().to_path_buf(), reason: reason.into() };
    let last = outcome.steps.last().ok_or_else(|| missing("the run has no solved step"))?;
    let profiles: Vec<profiles::Profiles> =
        outcome.steps.iter().map(profiles::contour_profiles).collect::<Result<_, _>>()?;
    let final_profiles = profiles.last().ok_or_else(|| missing("no contour profile"))?;
    for (k, (step, p)) in outcome.steps.iter().zip(&profiles).enumerate() {
        out.write_with(&step_file_name(k), |tmp| vtu::write_step_vtu(tmp, &profiles::flagship_view(step, p)))?;
    }
    let folder = RunFolder {
        description: &scene.description,
        built: &last.case.built,
        report: &outcome.report,
        last: profiles::flagship_view(last, final_profiles),
        step_times: outcome.steps.iter().map(|s| s.solution.load_factor).collect(),
    };
    let files = PaperFiles { scene, outcome, profiles: final_profiles };
    finish_outputs(out, &folder, Some(&files))
}

#[cfg(feature = "native")]
/// The plate-insert preset's own files of a run (module docs).
pub struct PaperFiles<'a> {
    /// The scene.
    pub scene: &'a PlateInsertScene,
    /// The solved run.
    pub outcome: &'a RunOutcome,
    /// The last step's contour profiles.
    pub profiles: &'a profiles::Profiles,
}

#[cfg(feature = "native")]
impl PresetFiles for PaperFiles<'_> {
    fn write(&self, out: &mut OutputDir, skipped: &mut Vec<String>) -> Result<(), OutputError> {
        let (scene, outcome, last_profiles) = (self.scene, self.outcome, self.profiles);
        let Some(last) = outcome.steps.last() else { return Ok(()) };
        let n = outcome.steps.len();
        let step_label = format!("step {n}/{n}, w = {:.4}", last.solution.load_factor);
        let title = |what: &str| format!("{}: {what} ({step_label})", scene.name);
        let elastic_insert = last.case.problem.model.body("insert").is_some();
        let ends: Vec<(&str, f64)> = [("l", last.results.contact_end), ("b", last.results.stick_end)]
            .into_iter()
            .filter_map(|(name, v)| Some((name, v?)))
            .collect();
        for ext in FIGURE_EXTENSIONS {
            figure(out, &format!("hole_edge.{ext}"), skipped, |p| {
                figures::draw_hole_edge(p, &title("hole edge"), &last_profiles.hole, &ends)
            })?;
            if elastic_insert {
                figure(out, &format!("insert_hoop.{ext}"), skipped, |p| {
                    figures::draw_insert_hoop(p, &title("insert hoop stress"), &last_profiles.insert)
                })?;
            }
            if n > 1 {
                figure(out, &format!("history.{ext}"), skipped, |p| {
                    figures::draw_zone_ends(p, &format!("{}: zone ends over the loading", scene.name), outcome)
                })?;
            }
        }
        let tags = &last.case.problem.model.mesh.node_tags;
        out.write_with("hole_edge.csv", |p| {
            csv::write_profile_csv(p, csv::HOLE_EDGE_HEADER, &last_profiles.hole, tags)
        })?;
        out.write_with("insert_edge.csv", |p| {
            csv::write_profile_csv(p, csv::INSERT_EDGE_HEADER, &last_profiles.insert, tags)
        })?;
        Ok(())
    }

    fn replaces(&self, stem: &str) -> bool {
        stem == "history"
    }

    fn step_columns(&self) -> (Vec<&'static str>, Vec<Vec<String>>) {
        (csv::STEP_COLUMNS.to_vec(), csv::step_rows(self.outcome))
    }

    fn describe(&self, name: &str) -> Option<&'static str> {
        readme::describe(name)
    }

    fn readme_notes(&self) -> String {
        readme::notes()
    }
}

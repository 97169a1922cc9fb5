//! A scene file, whichever it is: one reader, one run and one outcome for every scene.
//!
//! A scene is generic, or a preset's: a section of its own (a registered [`crate::preset`];
//! today one, the paper's `[plate_insert]`) that expands into the generic description
//! ([`crate::plate_insert::preset`]) and adds a post-processor (the summary's `paper` block and
//! its files). Both run through the generic pipeline and give the one JSON summary
//! ([`GenericReport`]); the CLI, the studies and the Python module call this module only, so
//! what a scene is decides nothing outside it.
//!
//! ```text
//! TOML text ─ read ─▶ Scene::Generic ─ solve ─▶ Outcome::Generic ─▶ summary, files
//!                   └▶ Scene::Preset  ─ solve ─▶ Outcome::Preset  ─▶ summary + the preset's block,
//!                      (a section of      (expanded into a generic     files + the preset's
//!                       PRESETS)           scene)
//! ```

use std::path::{Path, PathBuf};

use contact2d_contact::{BuiltProblem, SolvedStep};
use web_time::Instant;

#[cfg(feature = "native")]
use crate::generic::outputs as generic_outputs;
use crate::generic::{
    GenericError, GenericOutcome, GenericReport, GenericScene, Progress, solve_generic_streaming, solve_generic_until,
};
#[cfg(feature = "native")]
use crate::output::{OutputDir, OutputError};
use crate::preset::{Preset, PresetOutcome, PresetScene};
pub use crate::schema::{SceneError, overridden_scene_text, read_scene_text, unset_override};

/// The registered presets, in the order the scene reader tries their sections: a new preset is
/// its module ([`crate::preset`]) and one line here.
pub const PRESETS: &[Preset] = &[crate::plate_insert::PRESET];

/// The preset whose section the TOML `text` has, if any.
pub fn preset_of(text: &str) -> Option<&'static Preset> {
    let table = toml::from_str::<toml::Table>(text).ok()?;
    PRESETS.iter().find(|p| table.contains_key(p.section))
}

/// Whether the TOML `text` is a preset's scene (it has the section of one of [`PRESETS`]).
pub fn is_preset(text: &str) -> bool {
    preset_of(text).is_some()
}

/// Whether the TOML `text` is a generic scene: it has a top-level `mesh` and no preset's section.
pub fn is_generic(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("mesh")) && !is_preset(text)
}

/// Any scene.
#[derive(Debug, Clone)]
pub enum Scene {
    /// A generic scene (bodies, fixes, loads, contacts, schedule).
    Generic(Box<GenericScene>),
    /// A preset's scene (a section of [`PRESETS`], e.g. `[plate_insert]`).
    Preset(Box<dyn PresetScene>),
}

/// A solved scene: the summary and what the outputs need.
#[derive(Debug)]
pub enum Outcome {
    /// A generic scene's run.
    Generic(Box<GenericOutcome>),
    /// A preset scene's run (its post-processor's block is in the summary).
    Preset(Box<dyn PresetOutcome>),
}

impl Scene {
    /// Reads the scene at `path` with the overrides `sets` ([`Scene::from_toml_str`]).
    ///
    /// # Errors
    /// [`SceneError`] naming the file, and the line, key or override at fault.
    pub fn load(path: &Path, sets: &[String]) -> Result<Scene, SceneError> {
        Scene::from_toml_str(&read_scene_text(path)?, path, sets)
    }

    /// Parses `text` as if read from `path`: a preset's scene when it has a preset's section
    /// ([`PRESETS`]), a generic scene otherwise; applies `sets` and checks the
    /// values.
    ///
    /// # Errors
    /// [`SceneError`] naming the file, and the line, key or override at fault.
    pub fn from_toml_str(text: &str, path: &Path, sets: &[String]) -> Result<Scene, SceneError> {
        Ok(match preset_of(text) {
            Some(preset) => Scene::Preset((preset.read)(text, path, sets)?),
            None => Scene::Generic(Box::new(GenericScene::from_toml_str(text, path, sets)?)),
        })
    }

    /// The scene's name (outputs, titles).
    pub fn name(&self) -> &str {
        match self {
            Scene::Generic(s) => &s.name,
            Scene::Preset(s) => s.name(),
        }
    }

    /// The scene file as given.
    pub fn file(&self) -> &Path {
        match self {
            Scene::Generic(s) => &s.file,
            Scene::Preset(s) => s.file(),
        }
    }

    /// The mesh file, resolved against the scene's directory.
    pub fn mesh_path(&self) -> PathBuf {
        match self {
            Scene::Generic(s) => s.mesh_path(),
            Scene::Preset(s) => s.mesh_path(),
        }
    }

    /// Whether every step's summary row carries the interfaces' profiles (`run --profiles all`).
    pub fn set_every_profile(&mut self, every: bool) {
        match self {
            Scene::Generic(s) => s.every_profile = every,
            Scene::Preset(s) => s.set_every_profile(every),
        }
    }

    /// The centre `[x, y]` the run's moments (reactions, contacts) are taken about (`run --about
    /// x,y`; default the origin), reported as `moment_centre`.
    pub fn set_moment_centre(&mut self, centre: [f64; 2]) {
        match self {
            Scene::Generic(s) => s.moment_centre = centre,
            Scene::Preset(s) => s.set_moment_centre(centre),
        }
    }

    /// Checks what can be checked before an output folder is prepared: the preset's mesh file
    /// (a generic scene's mesh is checked as it is read).
    ///
    /// # Errors
    /// [`SceneError`] naming the mesh file.
    pub fn check_mesh_file(&self) -> Result<(), SceneError> {
        match self {
            Scene::Generic(_) => Ok(()),
            Scene::Preset(s) => s.check_mesh_file(),
        }
    }

    /// Solves the scene, keeping every step, with a wall-clock deadline checked before each
    /// load step if given.
    ///
    /// # Errors
    /// [`GenericError`]: the scene's values against its mesh, the mesh, or the solve (each naming
    /// the scene and the mesh files).
    pub fn solve(&self, deadline: Option<Instant>, progress: &mut dyn Progress) -> Result<Outcome, GenericError> {
        match self {
            Scene::Generic(s) => {
                let outcome = solve_generic_until(s, deadline, &mut |done, total| {
                    progress.step_done(done, total, done as f64);
                })?;
                Ok(Outcome::Generic(Box::new(outcome)))
            }
            Scene::Preset(s) => Ok(Outcome::Preset(s.solve(deadline, progress)?)),
        }
    }

    /// Solves the scene, handing each solved step of a generic scene to `on_solved` as it is
    /// solved and keeping only the last (memory flat in the steps); a preset's scene keeps its
    /// steps (its files need all of them) and hands none over.
    ///
    /// # Errors
    /// As [`Scene::solve`].
    pub fn solve_streaming(
        &self,
        progress: &mut dyn Progress,
        on_solved: &mut dyn FnMut(&BuiltProblem, usize, &SolvedStep),
    ) -> Result<Outcome, GenericError> {
        match self {
            Scene::Generic(s) => {
                let mut on_step = |done, total| progress.step_done(done, total, done as f64);
                Ok(Outcome::Generic(Box::new(solve_generic_streaming(s, &mut on_step, on_solved)?)))
            }
            Scene::Preset(s) => Ok(Outcome::Preset(s.solve(None, progress)?)),
        }
    }
}

impl Outcome {
    /// The summary (the `--json` object).
    pub fn report(&self) -> &GenericReport {
        match self {
            Outcome::Generic(o) => &o.report,
            Outcome::Preset(o) => o.report(),
        }
    }

    /// The preset's lines of the text summary (none for a generic scene).
    pub fn preset_lines(&self) -> Vec<String> {
        match self {
            Outcome::Generic(_) => vec![],
            Outcome::Preset(o) => o.summary_lines(),
        }
    }

    /// Writes every output file of a run that kept its steps ([`Scene::solve`]) into `folder`
    /// (native builds only: the writers are not in the WebAssembly build).
    ///
    /// # Errors
    /// [`OutputError`] naming the file at fault (and a streamed run, which kept one step).
    #[cfg(feature = "native")]
    pub fn write_outputs_into(&self, folder: OutputDir) -> Result<Vec<PathBuf>, OutputError> {
        match self {
            Outcome::Generic(o) => generic_outputs::write_generic_outputs_into(folder, o),
            Outcome::Preset(o) => o.write_outputs_into(folder),
        }
    }

    /// Writes the output files of a [`Scene::solve_streaming`] run whose step files were written
    /// as the steps were solved (`crate::generic::outputs::write_step_vtu`): every other file.
    ///
    /// # Errors
    /// [`OutputError`] naming the file at fault.
    #[cfg(feature = "native")]
    pub fn finish_streamed_outputs(&self, folder: OutputDir) -> Result<Vec<PathBuf>, OutputError> {
        match self {
            Outcome::Generic(o) => generic_outputs::finish_generic_outputs(folder, o),
            Outcome::Preset(o) => o.write_outputs_into(folder),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_is_generic_or_a_presets_by_its_sections() {
        let generic = "mesh = \"m.msh\"\n[[body]]\nregion = \"a\"\n";
        let preset = "[plate_insert]\nmesh = \"m.msh\"\n";
        assert!(is_generic(generic) && !is_preset(generic));
        assert!(is_preset(preset) && !is_generic(preset));
        assert!(preset_of(preset).is_some_and(|p| p.section == "plate_insert"));
        // Both a top-level mesh and a preset's section: the preset's (not generic).
        assert!(!is_generic(&format!("mesh = \"m.msh\"\n{preset}")));
    }
}

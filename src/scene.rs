//! A scene file, whichever it is: one reader, one run and one outcome for every scene.
//!
//! A scene is generic, or a preset's: a section of its own (today one preset, the paper's
//! `[plate_insert]`) that expands into the generic description
//! ([`crate::plate_insert::preset`]) and adds a post-processor (the summary's `paper` block and
//! its files). Both run through the generic pipeline and give the one JSON summary
//! ([`GenericReport`]); the CLI, the studies and the Python module call this module only, so
//! what a scene is decides nothing outside it.
//!
//! ```text
//! TOML text ─ read ─▶ Scene::Generic      ─ solve ─▶ Outcome::Generic      ─▶ summary, files
//!                   └▶ Scene::PlateInsert ─ solve ─▶ Outcome::PlateInsert  ─▶ summary + paper block,
//!                      (preset section)      (expanded into a generic scene)    files + the paper's
//! ```

use std::path::{Path, PathBuf};

use contact2d_contact::{BuiltProblem, ContactError, SolvedStep};
use web_time::Instant;

#[cfg(feature = "native")]
use crate::generic::outputs as generic_outputs;
use crate::generic::{
    GenericError, GenericOutcome, GenericReport, GenericScene, Progress, solve_generic_streaming, solve_generic_until,
};
#[cfg(feature = "native")]
use crate::output::{OutputDir, OutputError};
use crate::plate_insert::PlateInsertScene;
use crate::plate_insert::report::PaperReport;
use crate::plate_insert::run::{RunOutcome, solve_scene_with};
pub use crate::schema::{SceneError, overridden_scene_text, read_scene_text};

/// The preset sections: a scene with one of them is that preset's, any other a generic scene.
pub const PRESET_SECTIONS: [&str; 1] = ["plate_insert"];

/// Whether the TOML `text` is a preset's scene (it has a section of [`PRESET_SECTIONS`]).
pub fn is_preset(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| PRESET_SECTIONS.iter().any(|s| t.contains_key(*s)))
}

/// Any scene.
#[derive(Debug, Clone)]
pub enum Scene {
    /// A generic scene (bodies, fixes, loads, contacts, schedule).
    Generic(Box<GenericScene>),
    /// The paper's case (a `[plate_insert]` section).
    PlateInsert(Box<PlateInsertScene>),
}

/// A solved scene: the summary and what the outputs need.
#[derive(Debug)]
pub enum Outcome {
    /// A generic scene's run.
    Generic(Box<GenericOutcome>),
    /// The paper's case: its scene (its files need the section) and its run.
    PlateInsert(Box<PlateInsertScene>, Box<RunOutcome>),
}

impl Scene {
    /// Reads the scene at `path` with the overrides `sets` ([`Scene::from_toml_str`]).
    ///
    /// # Errors
    /// [`SceneError`] naming the file, and the line, key or override at fault.
    pub fn load(path: &Path, sets: &[String]) -> Result<Scene, SceneError> {
        Scene::from_toml_str(&read_scene_text(path)?, path, sets)
    }

    /// Parses `text` as if read from `path`: a preset's scene when it has a preset section
    /// ([`PRESET_SECTIONS`]), a generic scene otherwise; applies `sets` and checks the values.
    ///
    /// # Errors
    /// [`SceneError`] naming the file, and the line, key or override at fault.
    pub fn from_toml_str(text: &str, path: &Path, sets: &[String]) -> Result<Scene, SceneError> {
        Ok(if is_preset(text) {
            Scene::PlateInsert(Box::new(PlateInsertScene::from_toml_str(text, path, sets)?))
        } else {
            Scene::Generic(Box::new(GenericScene::from_toml_str(text, path, sets)?))
        })
    }

    /// The scene's name (outputs, titles).
    pub fn name(&self) -> &str {
        match self {
            Scene::Generic(s) => &s.name,
            Scene::PlateInsert(s) => &s.name,
        }
    }

    /// The scene file as given.
    pub fn file(&self) -> &Path {
        match self {
            Scene::Generic(s) => &s.file,
            Scene::PlateInsert(s) => &s.file,
        }
    }

    /// The mesh file, resolved against the scene's directory.
    pub fn mesh_path(&self) -> PathBuf {
        match self {
            Scene::Generic(s) => s.mesh_path(),
            Scene::PlateInsert(s) => s.mesh_path(),
        }
    }

    /// Whether every step's summary row carries the interfaces' profiles (`run --profiles all`).
    pub fn set_every_profile(&mut self, every: bool) {
        match self {
            Scene::Generic(s) => s.every_profile = every,
            Scene::PlateInsert(s) => s.every_profile = every,
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
            Scene::PlateInsert(s) => s.check_mesh_file(),
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
            Scene::PlateInsert(s) => solve_preset(&PlateInsertScene { deadline, ..(**s).clone() }, progress),
        }
    }

    /// Solves the scene, handing each solved step of a generic scene to `on_solved` as it is
    /// solved and keeping only the last (memory flat in the steps); the paper's case keeps its
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
            Scene::PlateInsert(s) => solve_preset(s, progress),
        }
    }
}

/// The paper's run in the order the CLI has always checked it: the mesh file, its geometry
/// against the section (ε, the groups), then the solve; every failure names both files.
fn solve_preset(scene: &PlateInsertScene, progress: &mut dyn Progress) -> Result<Outcome, GenericError> {
    scene.check_mesh_file()?;
    let (file, mesh_path) = (scene.file.display().to_string(), scene.mesh_path());
    let mesh_name = mesh_path.display().to_string();
    let mesh = contact2d_mesh::read_msh(&mesh_path).map_err(|source| GenericError::Mesh {
        scene: file.clone(),
        mesh: mesh_name.clone(),
        source,
    })?;
    scene.check_mesh_geometry(&mesh)?;
    let contact = |source: ContactError| GenericError::Contact {
        scene: file.clone(),
        mesh: mesh_name.clone(),
        source: Box::new(source),
    };
    let run = solve_scene_with(scene, progress).map_err(contact)?;
    Ok(Outcome::PlateInsert(Box::new(scene.clone()), Box::new(run)))
}

impl Outcome {
    /// The summary (the `--json` object).
    pub fn report(&self) -> &GenericReport {
        match self {
            Outcome::Generic(o) => &o.report,
            Outcome::PlateInsert(_, run) => &run.report,
        }
    }

    /// The paper's quantities, for the paper's case.
    pub fn paper(&self) -> Option<&PaperReport> {
        match self {
            Outcome::Generic(_) => None,
            Outcome::PlateInsert(_, run) => Some(&run.paper),
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
            Outcome::PlateInsert(scene, run) => crate::plate_insert::outputs::write_outputs_into(folder, scene, run),
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
            Outcome::PlateInsert(..) => self.write_outputs_into(folder),
        }
    }
}

//! Presets: a scene section of its own that expands into a generic scene and adds a
//! post-processor — its block in the one summary, its text lines, its files, and what the studies
//! read of it. The paper's `[plate_insert]` is one.
//!
//! ```text
//! scene text with a section of scene::PRESETS ─ Preset::read ─▶ Box<dyn PresetScene>
//!     PresetScene::solve ─▶ Box<dyn PresetOutcome> ─▶ the one summary (its block inside it),
//!                                                    text lines, files through OutputDir
//! ```
//!
//! A new preset (another geometry's section and derived quantities) is one module that
//! implements [`PresetScene`] and [`PresetOutcome`], plus one line in
//! [`crate::scene::PRESETS`]: the scene reader, `run`, `compare`, `sweep` and the Python module
//! find it there and name no preset.

use std::fmt::Debug;
use std::path::{Path, PathBuf};

use web_time::Instant;

use crate::generic::{GenericError, GenericReport, Progress};
#[cfg(feature = "native")]
use crate::output::{OutputDir, OutputError};
use crate::schema::SceneError;

/// Reads a preset's scene from its text, as if read from `path`, with the overrides `sets`
/// applied and the values checked.
pub type ReadPresetScene = fn(text: &str, path: &Path, sets: &[String]) -> Result<Box<dyn PresetScene>, SceneError>;

/// A preset: the section that marks its scenes, and how to read one.
pub struct Preset {
    /// The TOML section (table) that makes a scene this preset's.
    pub section: &'static str,
    /// Reads a scene of this preset.
    pub read: ReadPresetScene,
}

/// A scene of a preset, read and checked.
pub trait PresetScene: Debug + Send + Sync {
    /// A copy behind a new box (scenes are cloned by the studies).
    fn clone_box(&self) -> Box<dyn PresetScene>;
    /// The scene's name (outputs, titles).
    fn name(&self) -> &str;
    /// The scene file as given.
    fn file(&self) -> &Path;
    /// The mesh file, resolved against the scene's directory.
    fn mesh_path(&self) -> PathBuf;
    /// Whether every step's summary row carries the interfaces' profiles.
    fn set_every_profile(&mut self, every: bool);
    /// The centre `[x, y]` the run's moments are taken about (`run --about x,y`).
    fn set_moment_centre(&mut self, centre: [f64; 2]);
    /// Checks the mesh file before an output folder is prepared.
    ///
    /// # Errors
    /// [`SceneError`] naming the mesh file.
    fn check_mesh_file(&self) -> Result<(), SceneError>;
    /// Solves the scene, keeping every step, with a wall-clock deadline checked before each load
    /// step if given.
    ///
    /// # Errors
    /// [`GenericError`] naming the scene and mesh files.
    fn solve(
        &self,
        deadline: Option<Instant>,
        progress: &mut dyn Progress,
    ) -> Result<Box<dyn PresetOutcome>, GenericError>;

    /// The dotted key of the mesh file (`compare` and `sweep` set it per mesh level).
    fn mesh_key(&self) -> &'static str;
    /// The mesh levels `compare` runs when none are given (absolute paths; empty: the scene's
    /// own mesh only).
    fn mesh_levels(&self) -> Vec<PathBuf>;
    /// The pairings `compare` runs, each as its key and the overrides that select it.
    fn pairings(&self) -> Vec<(&'static str, Vec<String>)>;
    /// The quantities `compare` reports (names in the preset's block, or dotted paths).
    fn quantities(&self) -> Vec<String>;
    /// The columns a sweep tabulates.
    fn sweep_columns(&self) -> Vec<String>;
    /// The quantities a sweep plots by default.
    fn sweep_plots(&self) -> Vec<String>;
    /// Published values of the quantities, `(quantity, value)`, for a case a source gives.
    fn published(&self) -> Vec<(String, f64)>;
}

impl Clone for Box<dyn PresetScene> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}

/// A solved preset scene: the one summary with the preset's block, and its post-processing.
pub trait PresetOutcome: Debug + Send + Sync {
    /// The summary (the `--json` object), with the preset's block in it.
    fn report(&self) -> &GenericReport;
    /// The preset's lines of the text summary, after the method line.
    fn summary_lines(&self) -> Vec<String>;
    /// Every solved step's heading and solution, for `run -v`'s iteration log.
    fn iteration_logs(&self) -> Vec<(String, &contact2d_contact::ContactSolution)>;
    /// Every solved step's model (its mesh may differ from step to step: a preset may move nodes)
    /// and solution, in load order.
    fn steps(&self) -> Vec<(&contact2d_fem::Model, &contact2d_contact::ContactSolution)>;
    /// Writes every output file of the run into `folder`.
    ///
    /// # Errors
    /// [`OutputError`] naming the file at fault.
    #[cfg(feature = "native")]
    fn write_outputs_into(&self, folder: OutputDir) -> Result<Vec<PathBuf>, OutputError>;
}

//! `contact2d.Scene`: a scene's TOML text, the path it is read as (its directory resolves the
//! mesh) and the overrides, each applied by the facade's own parser exactly as `--set` is.

use std::path::{Path, PathBuf};

use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{SceneError, scene_error};

/// A scene: TOML text plus `--set` overrides, re-loaded through the CLI's parser at every change
/// so that a bad override fails where it is made.
#[pyclass(module = "contact2d._core", frozen)]
#[derive(Debug, Clone)]
pub struct Scene {
    pub(crate) text: String,
    pub(crate) path: PathBuf,
    pub(crate) overrides: Vec<String>,
}

impl Scene {
    /// Parses the text with the overrides, as `contact2d run` does.
    ///
    /// # Errors
    /// The scene's [`contact2d::scene::SceneError`].
    pub fn parse(&self) -> Result<contact2d::scene::Scene, contact2d::scene::SceneError> {
        contact2d::scene::Scene::from_toml_str(&self.text, &self.path, &self.overrides)
    }

    fn checked(self) -> PyResult<Scene> {
        self.parse().map_err(scene_error)?;
        Ok(self)
    }
}

#[pymethods]
impl Scene {
    /// Reads a scene file (TOML), as `contact2d run PATH` does; its mesh path is resolved against
    /// the file's directory.
    ///
    /// Raises SceneError with the CLI's message (file, line or key) if it cannot be read or checked.
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<Scene> {
        let text = contact2d::scene::read_scene_text(&path).map_err(scene_error)?;
        Scene { text, path, overrides: vec![] }.checked()
    }

    /// A scene from a dict with the schema of the TOML files; the mesh path is resolved against
    /// `base_dir` (default: the current directory). Raises SceneError as `load` does, TypeError
    /// for a value with no TOML form.
    #[staticmethod]
    #[pyo3(signature = (d, base_dir = None))]
    fn from_dict(d: &Bound<'_, PyDict>, base_dir: Option<PathBuf>) -> PyResult<Scene> {
        let table = crate::convert::to_table(d, "")?;
        let text = toml::to_string(&table).map_err(|e| SceneError::new_err(format!("scene <dict>: {e}")))?;
        let path = base_dir.unwrap_or_else(|| PathBuf::from(".")).join("<dict>.toml");
        Scene { text, path, overrides: vec![] }.checked()
    }

    /// A copy of the scene with `key` (a dotted path as `--set` takes it, e.g.
    /// "contact.bore.friction") set to `value` (a str, bool, int, float, list or dict); a str is
    /// taken as TOML text as on the command line ("0.1", "clarabel"). Raises SceneError with the
    /// CLI's message if the override does not apply or the scene it makes is invalid.
    fn set(&self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<Scene> {
        let literal = match value.extract::<String>() {
            Ok(s) => s,
            Err(_) => crate::convert::to_toml(value, key)?.to_string(),
        };
        let mut overrides = self.overrides.clone();
        overrides.push(format!("{key}={literal}"));
        Scene { text: self.text.clone(), path: self.path.clone(), overrides }.checked()
    }

    /// A copy of the scene without `key` (a dotted path as `--unset` takes it, e.g.
    /// "loading.steps", or a whole entry such as "contact.1"): the key falls back to its default,
    /// or another can take its place (`.unset("loading.steps").set("loading.schedule", [...])`).
    /// Applied in order with `set`. Raises SceneError with the CLI's message if the scene does
    /// not give the key or the scene it makes is invalid.
    fn unset(&self, key: &str) -> PyResult<Scene> {
        let mut overrides = self.overrides.clone();
        overrides.push(contact2d::scene::unset_override(key));
        Scene { text: self.text.clone(), path: self.path.clone(), overrides }.checked()
    }

    /// The scene's TOML text with the overrides applied (comments and layout are not kept).
    fn to_toml(&self) -> PyResult<String> {
        contact2d::scene::overridden_scene_text(&self.text, &self.path, &self.overrides).map_err(scene_error)
    }

    /// The scene's name (its `name` key).
    #[getter]
    fn name(&self) -> PyResult<String> {
        Ok(self.parse().map_err(scene_error)?.name().to_string())
    }

    /// The path the scene is read as (a file, or `<base_dir>/<dict>.toml` for `from_dict`).
    #[getter]
    fn path(&self) -> PathBuf {
        self.path.clone()
    }

    /// The overrides applied so far, in order: `key=value` for a `set` (as `--set` takes it),
    /// `!key` for an `unset`.
    #[getter]
    fn overrides(&self) -> Vec<String> {
        self.overrides.clone()
    }

    /// The mesh file the scene names, resolved against its directory.
    #[getter]
    fn mesh_path(&self) -> PyResult<PathBuf> {
        Ok(self.parse().map_err(scene_error)?.mesh_path())
    }

    /// Whether the scene is one of the paper's case (a `[plate_insert]` section).
    #[getter]
    fn is_preset(&self) -> bool {
        contact2d::scene::is_preset(&self.text)
    }

    fn __repr__(&self) -> String {
        format!("Scene({:?}, overrides={:?})", Path::new(&self.path).display().to_string(), self.overrides)
    }
}

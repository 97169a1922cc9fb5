//! Scene files: a TOML description of a run, parsed at the edge into typed values.
//!
//! ```toml
//! name = "plate_insert_nogap_mu0"
//! description = "Solodovnikov (1998), no gap, no friction"
//!
//! [plate_insert]
//! mesh = "meshes/plate_insert/plate_insert_eps0_N64.msh"  # relative to the scene file
//! variant = "hole_master"       # or "insert_master" (the paper's variants 1 and 2)
//! stiffness_ratio = 1.0         # E2 / E1
//! rigid_insert = false          # true: the insert is a rigid, fixed contour
//! poissons_ratio = 0.3
//! plane_condition = "stress"   # or "strain" (both bodies)
//! eps = 0.0                     # geometric clearance of the mesh (insert radius 1 - eps)
//! clearance = 0.0               # c, the clearance in displacement units
//! gap = "paper"                 # default "geometric"; "paper" is the stricter u_ρc / u_rc
//! friction = 0.0                # μ
//! load = 1.0                    # w, the pulled-edge displacement
//! steps = 1                     # equal load steps from 0 to w (a history for friction)
//! l_steps = [0.05, 0.1]         # Boussinesq only: steps in the contact end l instead of w
//! pairs = "node_to_node"        # or "node_to_segment" (the mesh as given)
//!
//! [solver]
//! algorithm = "active_set"      # or "clarabel", "boussinesq"
//! max_iterations = 100
//! place_zone_ends = true        # Boussinesq: nodes placed at l* and b* (the paper's way)
//! ```
//!
//! Unknown keys are errors. `--set key.path=value` sets any value (also one the file leaves at its
//! default) before the scene is checked (the value is parsed as TOML, falling back to a string).

use std::path::{Path, PathBuf};

use serde::Deserialize;

use contact2d_element::PlaneCondition;

use crate::plate_insert::{GapModel, PairDiscretisation, PairingVariant, PlateInsert};

/// Errors reading a scene.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read scene {path}: {source}")]
    Io {
        /// Path as given.
        path: String,
        /// OS error.
        source: std::io::Error,
    },
    /// Not valid TOML, an unknown key, or a wrong type.
    #[error("scene {path}: {reason}")]
    Invalid {
        /// Path as given.
        path: String,
        /// What is wrong (with the key or line).
        reason: String,
    },
    /// A `--set` override that does not parse or names no key.
    #[error("--set {assignment}: {reason}")]
    Override {
        /// The assignment as given.
        assignment: String,
        /// What is wrong.
        reason: String,
    },
}

/// Which contact algorithm a scene runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactAlgorithm {
    /// Primal-dual active set on the condensed interface.
    ActiveSet,
    /// The QP of (5.3) solved by Clarabel in the full displacement space (Tresca fixed point
    /// with friction).
    Clarabel,
    /// The paper's paired-node Boussinesq algorithm (section 6).
    Boussinesq,
}

/// The solver section.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverSection {
    /// Algorithm.
    pub algorithm: ContactAlgorithm,
    /// Iteration limit of the active set.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: usize,
    /// Boussinesq only: place master nodes exactly at the zone ends l* and b* by root finding
    /// (the paper's mesh adjustment, default); `false` keeps the generated mesh and resolves
    /// the zone ends to its nodes.
    #[serde(default = "yes")]
    pub place_zone_ends: bool,
}

fn yes() -> bool {
    true
}

fn default_max_iterations() -> usize {
    100
}

/// The `[plate_insert]` section: the flagship problem's parameters.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlateInsertSection {
    /// Mesh path, relative to the scene file.
    pub mesh: PathBuf,
    /// `hole_master` (variant 1) or `insert_master` (variant 2).
    pub variant: VariantKey,
    /// E2 / E1.
    #[serde(default = "one")]
    pub stiffness_ratio: f64,
    /// A rigid, fixed insert contour instead of an elastic insert.
    #[serde(default)]
    pub rigid_insert: bool,
    /// ν of both bodies.
    #[serde(default = "nu")]
    pub poissons_ratio: f64,
    /// `stress` (default, the paper's thin plate) or `strain`.
    #[serde(default = "plane_stress")]
    pub plane_condition: PlaneKey,
    /// ε of the mesh.
    #[serde(default)]
    pub eps: f64,
    /// c in displacement units.
    #[serde(default)]
    pub clearance: f64,
    /// `geometric` (default) or `paper`.
    #[serde(default = "geometric")]
    pub gap: GapKey,
    /// μ.
    #[serde(default)]
    pub friction: f64,
    /// w.
    pub load: f64,
    /// Equal load steps from 0 to w (the history; 1 = one step).
    #[serde(default = "one_step")]
    pub steps: usize,
    /// With the Boussinesq algorithm: the contact ends l of the steps (the paper's loading in
    /// steps of l, on the master's own η); the load w of each step follows. `load` and `steps`
    /// are then unused.
    #[serde(default)]
    pub l_steps: Vec<f64>,
    /// `node_to_node` (slave nodes slid onto the paired points, the paper's pairs) or
    /// `node_to_segment` (the mesh as given).
    #[serde(default = "node_to_node")]
    pub pairs: PairsKey,
}

fn node_to_node() -> PairsKey {
    PairsKey::NodeToNode
}

/// Scene spelling of [`PairDiscretisation`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PairsKey {
    /// Node-to-node after morphing.
    NodeToNode,
    /// Node-to-segment on the given mesh.
    NodeToSegment,
}

fn one_step() -> usize {
    1
}
fn one() -> f64 {
    1.0
}
fn nu() -> f64 {
    0.3
}
fn plane_stress() -> PlaneKey {
    PlaneKey::Stress
}
fn geometric() -> GapKey {
    GapKey::Geometric
}

/// Scene spelling of [`PairingVariant`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum VariantKey {
    /// Variant 1.
    HoleMaster,
    /// Variant 2.
    InsertMaster,
}

/// Scene spelling of [`PlaneCondition`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlaneKey {
    /// Plane stress.
    Stress,
    /// Plane strain.
    Strain,
}

/// Scene spelling of [`GapModel`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GapKey {
    /// The paper's u_ρc / u_rc.
    Paper,
    /// Geometric distance times c/ε.
    Geometric,
}

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Short name (used in outputs).
    pub name: String,
    /// One line for people.
    #[serde(default)]
    pub description: String,
    /// The flagship problem.
    pub plate_insert: PlateInsertSection,
    /// The solver.
    pub solver: SolverSection,
    /// Directory of the scene file (mesh paths are relative to it).
    #[serde(skip)]
    pub base_dir: PathBuf,
}

impl Scene {
    /// Reads `path`, applies `overrides` (`key.path=value`), and checks the result.
    ///
    /// # Errors
    /// [`SceneError`] naming the file, key or override.
    pub fn load(path: &Path, overrides: &[String]) -> Result<Scene, SceneError> {
        let shown = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io { path: shown.clone(), source })?;
        let mut value: toml::Value =
            toml::from_str(&text).map_err(|e| SceneError::Invalid { path: shown.clone(), reason: e.to_string() })?;
        for assignment in overrides {
            apply_override(&mut value, assignment)?;
        }
        let mut scene: Scene = value
            .try_into()
            .map_err(|e: toml::de::Error| SceneError::Invalid { path: shown.clone(), reason: e.to_string() })?;
        scene.base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(scene)
    }

    /// The flagship parameters with the mesh path resolved.
    pub fn plate_insert(&self) -> PlateInsert {
        let p = &self.plate_insert;
        PlateInsert {
            mesh: self.base_dir.join(&p.mesh).display().to_string(),
            stiffness_ratio: p.stiffness_ratio,
            rigid_insert: p.rigid_insert,
            poissons_ratio: p.poissons_ratio,
            plane: match p.plane_condition {
                PlaneKey::Stress => PlaneCondition::Stress,
                PlaneKey::Strain => PlaneCondition::Strain,
            },
            variant: match p.variant {
                VariantKey::HoleMaster => PairingVariant::HoleMaster,
                VariantKey::InsertMaster => PairingVariant::InsertMaster,
            },
            eps: p.eps,
            clearance: p.clearance,
            gap_model: match p.gap {
                GapKey::Paper => GapModel::Paper,
                GapKey::Geometric => GapModel::Geometric,
            },
            friction: p.friction,
            pairs: match p.pairs {
                PairsKey::NodeToNode => PairDiscretisation::NodeToNode,
                PairsKey::NodeToSegment => PairDiscretisation::NodeToSegment,
            },
            placed_nodes: vec![],
        }
    }
}

/// Sets `a.b.c = value` in a TOML tree; the key must exist (unknown keys are errors).
fn apply_override(root: &mut toml::Value, assignment: &str) -> Result<(), SceneError> {
    let err = |reason: String| SceneError::Override { assignment: assignment.to_string(), reason };
    let (key, raw) = assignment.split_once('=').ok_or_else(|| err("expected key.path=value".into()))?;
    let parsed = toml::from_str::<toml::Table>(&format!("v = {raw}"))
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| toml::Value::String(raw.to_string()));
    let mut node = root;
    let parts: Vec<&str> = key.trim().split('.').collect();
    for (i, part) in parts.iter().enumerate() {
        let table = node.as_table_mut().ok_or_else(|| err(format!("\"{}\" is not a table", parts[..i].join("."))))?;
        if i + 1 == parts.len() {
            // A key the file leaves at its default may be set; whether it exists at all is
            // decided when the scene is checked (unknown keys are errors there).
            table.insert((*part).to_string(), parsed);
            return Ok(());
        }
        node =
            table.get_mut(*part).ok_or_else(|| err(format!("no table \"{}\" in the scene", parts[..=i].join("."))))?;
    }
    Err(err("empty key".into()))
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    const SCENE: &str = r#"
name = "t"
[plate_insert]
mesh = "m.msh"
variant = "hole_master"
load = 1.0
[solver]
algorithm = "active_set"
"#;

    fn write(text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("contact2d-scene-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!("{}.toml", text.len()));
        std::fs::write(&path, text).unwrap();
        path
    }

    #[test]
    fn loads_defaults_and_overrides() {
        let path = write(SCENE);
        let s = Scene::load(&path, &["plate_insert.load=0.5".into(), "solver.algorithm=clarabel".into()]).unwrap();
        assert_eq!(s.plate_insert.load, 0.5);
        assert_eq!(s.solver.algorithm, ContactAlgorithm::Clarabel);
        assert_eq!(s.plate_insert.poissons_ratio, 0.3);
        assert_eq!(s.plate_insert().plane, PlaneCondition::Stress);
        let s = Scene::load(&path, &["plate_insert.plane_condition=strain".into()]).unwrap();
        assert_eq!(s.plate_insert().plane, PlaneCondition::Strain);
        assert!(s.plate_insert().mesh.ends_with("m.msh"));
    }

    #[test]
    fn unknown_keys_and_bad_overrides_are_errors() {
        let path = write(&format!("{SCENE}\nbogus = 1\n"));
        assert!(matches!(Scene::load(&path, &[]), Err(SceneError::Invalid { .. })));
        let path = write(SCENE);
        assert!(matches!(Scene::load(&path, &["plate_insert.nope=1".into()]), Err(SceneError::Invalid { .. })));
        assert!(matches!(Scene::load(&path, &["nosuchtable.x=1".into()]), Err(SceneError::Override { .. })));
        let s = Scene::load(&path, &["plate_insert.friction=0.3".into()]).unwrap();
        assert_eq!(s.plate_insert.friction, 0.3);
        assert!(matches!(Scene::load(&path, &["solver.algorithm=newton".into()]), Err(SceneError::Invalid { .. })));
        assert!(matches!(Scene::load(&path, &["noequals".into()]), Err(SceneError::Override { .. })));
        assert!(matches!(Scene::load(Path::new("/nonexistent.toml"), &[]), Err(SceneError::Io { .. })));
    }
}

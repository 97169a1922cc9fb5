//! The paper's scene file (a `[plate_insert]` section; [`crate::scene::Scene`] reads any scene and
//! picks this one by its section): a TOML description of a run, parsed at the edge into typed values.
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
//! formulation = "standard"      # or "bbar": locking-free for ν → 0.5 in plane strain (both bodies)
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
//! algorithm = "active_set"      # or "clarabel", "boussinesq", "penalty", "augmented_lagrangian"
//! max_iterations = 100
//! place_zone_ends = true        # Boussinesq: nodes placed at l* and b* (the paper's way)
//! ```
//!
//! Unknown keys are errors. `--set key.path=value` sets any value (also one the file leaves at its
//! default) before the scene is checked (the value is parsed as TOML, falling back to a string).
//! Then [`PlateInsertScene::validate`] checks every range and the combinations that contradict each other,
//! and [`PlateInsertScene::check_mesh_geometry`] that the mesh is the one ε describes. Every error names the
//! file and the line (syntax, types), the dotted key (values) or the override at fault; the keys,
//! units and defaults are tabulated in `docs/user-guide.md`.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use contact2d_element::{Formulation, PlaneCondition};

use contact2d_contact::{ContactAlgorithm, SolverSettings};

use crate::plate_insert::{GapModel, PairDiscretisation, PairingVariant, PlateInsert};

mod limits;

pub use crate::schema::limits::{MAGNITUDE_RANGE, MAX_FRICTION, MAX_ITERATIONS, MAX_STEPS, STIFFNESS_RATIO_RANGE};
use crate::schema::parse_scene_toml;
pub use crate::schema::{
    SceneError, SolverEntry, algorithm_from_key, deserialize_algorithm, overridden_scene_text, read_scene_text,
    serialize_algorithm,
};

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
    /// `standard` (default) or `bbar` (projected dilatation, locking-free), for both bodies.
    #[serde(default)]
    pub formulation: FormulationKey,
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

/// Scene spelling of [`Formulation`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
pub enum FormulationKey {
    /// Standard displacement elements.
    #[default]
    #[serde(rename = "standard")]
    Standard,
    /// B-bar (the dilatation projected on the element pressure space).
    #[serde(rename = "bbar")]
    BBar,
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
pub struct PlateInsertScene {
    /// Short name (used in outputs).
    pub name: String,
    /// One line for people.
    #[serde(default)]
    pub description: String,
    /// The flagship problem.
    pub plate_insert: PlateInsertSection,
    /// The solver (the section every scene shares).
    #[serde(default)]
    pub solver: SolverEntry,
    /// Directory of the scene file (mesh paths are relative to it).
    #[serde(skip)]
    pub base_dir: PathBuf,
    /// The scene file as given (named in errors).
    #[serde(skip)]
    pub file: PathBuf,
    /// A wall-clock deadline for the run, checked before each load step (not a scene key: set
    /// by callers such as `compare --time-limit`).
    #[serde(skip)]
    pub deadline: Option<web_time::Instant>,
    /// Every step's row of the summary carries the interface's profile, not only the last (not
    /// a scene key: `run --profiles all`).
    #[serde(skip)]
    pub every_profile: bool,
    /// The centre `[x, y]` the run's moments are taken about (not a scene key: `run --about
    /// x,y`; default the origin).
    #[serde(skip)]
    pub moment_centre: [f64; 2],
}

impl PlateInsertScene {
    /// Reads `path`, applies `overrides` (`key.path=value`), and checks the result
    /// ([`PlateInsertScene::from_toml_str`] on the file's text).
    ///
    /// # Errors
    /// [`SceneError`] naming the file, and the key, line or override at fault.
    pub fn load(path: &Path, overrides: &[String]) -> Result<PlateInsertScene, SceneError> {
        PlateInsertScene::from_toml_str(&read_scene_text(path)?, path, overrides)
    }

    /// Parses a scene from TOML `text` as if read from the file `path` (named in errors; its
    /// directory resolves the mesh path), applies `overrides` and checks the values
    /// ([`PlateInsertScene::validate`]). Nothing is read from disk.
    ///
    /// # Errors
    /// [`SceneError::Invalid`] for TOML syntax, unknown keys and wrong types (with the line when
    /// the file itself is at fault, with the dotted key otherwise), [`SceneError::Override`] for a
    /// malformed `--set`, [`SceneError::Value`] for a value out of range or contradicting another.
    ///
    /// # Examples
    /// ```
    /// use contact2d_pipeline::plate_insert::PlateInsertScene;
    /// let text = "name = \"t\"\n[plate_insert]\nmesh = \"m.msh\"\nvariant = \"hole_master\"\n\
    ///             load = 1.0\n[solver]\nalgorithm = \"active_set\"\n";
    /// let path = std::path::Path::new("scenes/t.toml");
    /// let scene = PlateInsertScene::from_toml_str(text, path, &["plate_insert.friction=0.3".into()]).unwrap();
    /// assert_eq!(scene.plate_insert.friction, 0.3);
    /// assert!(PlateInsertScene::from_toml_str(text, path, &["plate_insert.poissons_ratio=0.5".into()]).is_err());
    /// ```
    pub fn from_toml_str(text: &str, path: &Path, overrides: &[String]) -> Result<PlateInsertScene, SceneError> {
        let mut scene: PlateInsertScene = parse_scene_toml(text, path, overrides, &[])?;
        scene.file = path.to_path_buf();
        scene.base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        scene.validate()?;
        Ok(scene)
    }

    /// Checks every value's range and the combinations that contradict each other (see
    /// `docs/user-guide.md`, "Scene keys"):
    ///
    /// * ranges: w, μ, ε, c finite and ≥ 0, ε < 1, E2/E1 finite and > 0, ν in (−1, 0.5),
    ///   1 ≤ steps ≤ [`MAX_STEPS`], 1 ≤ max_iterations ≤ [`MAX_ITERATIONS`], each l in l_steps in (0, 1) and increasing
    ///   (at most [`MAX_STEPS`] of them); w and c 0 or within [`MAGNITUDE_RANGE`], E2/E1 within
    ///   [`STIFFNESS_RATIO_RANGE`], μ ≤ [`MAX_FRICTION`]; no control character in the name;
    /// * contradictions: c > 0 with ε = 0 (a neat-fit mesh has no room for a clearance),
    ///   l_steps with an algorithm other than `boussinesq`, l_steps with steps ≠ 1 or load ≠ 0
    ///   (the loads then follow from l), rigid_insert with stiffness_ratio ≠ 1 (a rigid insert
    ///   has no modulus) or with variant `insert_master` (the rigid contour must be the slave).
    ///
    /// # Errors
    /// [`SceneError::Value`] naming the first key at fault.
    pub fn validate(&self) -> Result<(), SceneError> {
        let fail = |key: &str, reason: String| SceneError::Value {
            path: self.file.display().to_string(),
            key: key.to_string(),
            reason,
        };
        let p = &self.plate_insert;
        let non_negative = |key: &str, v: f64| {
            if v.is_finite() && v >= 0.0 { Ok(()) } else { Err(fail(key, format!("{v} must be finite and ≥ 0"))) }
        };
        non_negative("plate_insert.load", p.load)?;
        non_negative("plate_insert.friction", p.friction)?;
        non_negative("plate_insert.eps", p.eps)?;
        non_negative("plate_insert.clearance", p.clearance)?;
        if p.eps >= 1.0 {
            return Err(fail("plate_insert.eps", format!("{} must be < 1 (the insert radius is 1 − ε)", p.eps)));
        }
        if !(p.stiffness_ratio.is_finite() && p.stiffness_ratio > 0.0) {
            return Err(fail(
                "plate_insert.stiffness_ratio",
                format!("E2/E1 = {} must be finite and > 0", p.stiffness_ratio),
            ));
        }
        limits::validate_magnitudes(self)?;
        if !(p.poissons_ratio > -1.0 && p.poissons_ratio < 0.5) {
            return Err(fail("plate_insert.poissons_ratio", format!("ν = {} must lie in (−1, 0.5)", p.poissons_ratio)));
        }
        if !(1..=MAX_STEPS).contains(&p.steps) {
            return Err(fail("plate_insert.steps", format!("{} must lie in 1 ..= {MAX_STEPS}", p.steps)));
        }
        if !(1..=MAX_ITERATIONS).contains(&self.solver.max_iterations) {
            return Err(fail(
                "solver.max_iterations",
                format!("{} must lie in 1 ..= {MAX_ITERATIONS}", self.solver.max_iterations),
            ));
        }
        self.settings()?;
        if p.clearance > 0.0 && p.eps == 0.0 {
            return Err(fail(
                "plate_insert.clearance",
                format!("c = {} needs a mesh with a clearance (eps > 0); eps = 0 is a neat fit", p.clearance),
            ));
        }
        if p.rigid_insert && p.stiffness_ratio != 1.0 {
            return Err(fail(
                "plate_insert.stiffness_ratio",
                format!("{} is meaningless with rigid_insert = true (remove it or set 1)", p.stiffness_ratio),
            ));
        }
        if p.rigid_insert && p.variant == VariantKey::InsertMaster {
            return Err(fail(
                "plate_insert.variant",
                "rigid_insert = true needs variant = \"hole_master\" (the rigid contour is the slave)".into(),
            ));
        }
        self.validate_l_steps()
    }

    fn validate_l_steps(&self) -> Result<(), SceneError> {
        let p = &self.plate_insert;
        if p.l_steps.is_empty() {
            return Ok(());
        }
        let fail = |key: &str, reason: String| SceneError::Value {
            path: self.file.display().to_string(),
            key: key.to_string(),
            reason,
        };
        if self.solver.algorithm != ContactAlgorithm::Boussinesq {
            return Err(fail(
                "plate_insert.l_steps",
                "needs solver.algorithm = \"boussinesq\" (the paper's algorithm steps in l)".into(),
            ));
        }
        if p.steps != 1 {
            return Err(fail("plate_insert.steps", "must be left at 1 with l_steps (one step per l)".into()));
        }
        if p.load != 0.0 {
            return Err(fail(
                "plate_insert.load",
                "must be 0 with l_steps (the load of each step follows from l)".into(),
            ));
        }
        if p.l_steps.len() > MAX_STEPS {
            return Err(fail(
                "plate_insert.l_steps",
                format!("{} steps exceed the limit of {MAX_STEPS}", p.l_steps.len()),
            ));
        }
        let mut previous = 0.0;
        for (i, &l) in p.l_steps.iter().enumerate() {
            if !(l > previous && l < 1.0) {
                return Err(fail(
                    &format!("plate_insert.l_steps[{i}]"),
                    format!("{l}: the contact ends must increase strictly within (0, 1)"),
                ));
            }
            previous = l;
        }
        Ok(())
    }

    /// The library's solver settings of the `[solver]` section.
    ///
    /// # Errors
    /// [`SceneError::Value`] naming the solver key at fault.
    pub fn settings(&self) -> Result<SolverSettings, SceneError> {
        let settings = self.solver.settings(|key, reason| SceneError::Value {
            path: self.file.display().to_string(),
            key: key.to_string(),
            reason,
        })?;
        Ok(match self.deadline {
            Some(deadline) => settings.with_deadline(deadline),
            None => settings,
        })
    }

    /// The flagship parameters with the mesh path resolved.
    pub fn plate_insert(&self) -> PlateInsert {
        let p = &self.plate_insert;
        PlateInsert {
            mesh: self.mesh_path().display().to_string(),
            stiffness_ratio: p.stiffness_ratio,
            rigid_insert: p.rigid_insert,
            poissons_ratio: p.poissons_ratio,
            plane: match p.plane_condition {
                PlaneKey::Stress => PlaneCondition::Stress,
                PlaneKey::Strain => PlaneCondition::Strain,
            },
            formulation: match p.formulation {
                FormulationKey::Standard => Formulation::Standard,
                FormulationKey::BBar => Formulation::BBar,
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

    /// Checks that the mesh path names a regular file within
    /// [`crate::input_file::MAX_MESH_BYTES`] before anything reads it (a device such as
    /// `/dev/zero` never ends, a FIFO blocks). A missing file is left to the reader, which says so.
    ///
    /// # Errors
    /// [`SceneError::Value`] on `plate_insert.mesh`.
    pub fn check_mesh_file(&self) -> Result<(), SceneError> {
        use crate::input_file::{InputFileError, MAX_MESH_BYTES, check_input_file};
        let path = self.mesh_path();
        match check_input_file(&path, MAX_MESH_BYTES) {
            Ok(_) | Err(InputFileError::Io { .. }) => Ok(()),
            Err(e) => Err(SceneError::Value {
                path: self.file.display().to_string(),
                key: "plate_insert.mesh".into(),
                reason: format!("cannot read {}: {}", path.display(), e.reason()),
            }),
        }
    }

    /// The mesh path resolved against the scene file's directory.
    pub fn mesh_path(&self) -> PathBuf {
        self.base_dir.join(&self.plate_insert.mesh)
    }
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
        // One file per call: tests run in parallel and two may write the same text.
        static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let path = dir.join(format!("{call}.toml"));
        std::fs::write(&path, text).unwrap();
        path
    }

    #[test]
    fn loads_defaults_and_overrides() {
        let path = write(SCENE);
        let s = PlateInsertScene::load(&path, &["plate_insert.load=0.5".into(), "solver.algorithm=clarabel".into()])
            .unwrap();
        assert_eq!(s.plate_insert.load, 0.5);
        assert_eq!(s.solver.algorithm, ContactAlgorithm::Clarabel);
        assert_eq!(s.plate_insert.poissons_ratio, 0.3);
        assert_eq!(s.plate_insert().plane, PlaneCondition::Stress);
        let s = PlateInsertScene::load(&path, &["plate_insert.plane_condition=strain".into()]).unwrap();
        assert_eq!(s.plate_insert().plane, PlaneCondition::Strain);
        assert!(s.plate_insert().mesh.ends_with("m.msh"));
    }

    #[test]
    fn unknown_keys_and_bad_overrides_are_errors() {
        let path = write(&format!("{SCENE}\nbogus = 1\n"));
        assert!(matches!(PlateInsertScene::load(&path, &[]), Err(SceneError::Invalid { .. })));
        let path = write(SCENE);
        assert!(matches!(
            PlateInsertScene::load(&path, &["plate_insert.nope=1".into()]),
            Err(SceneError::Invalid { .. })
        ));
        // A table the file leaves out is made by `--set`; a misspelt one is an unknown key.
        let e = PlateInsertScene::load(&path, &["nosuchtable.x=1".into()]).unwrap_err();
        assert!(matches!(e, SceneError::Invalid { .. }) && e.to_string().contains("nosuchtable"), "{e}");
        let s = PlateInsertScene::load(&path, &["plate_insert.friction=0.3".into()]).unwrap();
        assert_eq!(s.plate_insert.friction, 0.3);
        assert!(matches!(
            PlateInsertScene::load(&path, &["solver.algorithm=newton".into()]),
            Err(SceneError::Invalid { .. })
        ));
        assert!(matches!(PlateInsertScene::load(&path, &["noequals".into()]), Err(SceneError::Override { .. })));
        assert!(matches!(PlateInsertScene::load(Path::new("/nonexistent.toml"), &[]), Err(SceneError::Io { .. })));
        assert!(matches!(PlateInsertScene::load(Path::new("/dev/zero"), &[]), Err(SceneError::Unreadable { .. })));
    }
}

/// The `--set` engine (`crate::schema::overrides`) on the paper's section.
#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod override_tests {
    use super::*;

    const SCENE: &str = "name = \"t\"\n[plate_insert]\nmesh = \"m.msh\"\nvariant = \"hole_master\"\nload = 1.0\n[solver]\nalgorithm = \"active_set\"\n";

    fn load(overrides: &[String]) -> Result<PlateInsertScene, SceneError> {
        PlateInsertScene::from_toml_str(SCENE, Path::new("t.toml"), overrides)
    }

    #[test]
    fn numbers_that_toml_cannot_read_are_named_as_numbers() {
        for (raw, want) in [(".3", "malformed number"), ("1e400", "out of the range"), ("-1e999", "out of the range")] {
            let e = load(&[format!("plate_insert.friction={raw}")]).unwrap_err().to_string();
            assert!(e.contains(want) && e.contains("plate_insert.friction"), "{raw}: {e}");
        }
        // Words and paths stay strings.
        assert!(load(&["plate_insert.mesh=other.msh".into()]).is_ok());
        assert_eq!(load(&["name=1e5x".into()]).unwrap().name, "1e5x", "not a number: a string");
    }

    #[test]
    fn the_overridden_text_loads_as_the_overrides_do() {
        let sets = ["plate_insert.friction=0.3".to_string()];
        let text = crate::schema::overridden_scene_text(SCENE, Path::new("t.toml"), &sets).unwrap();
        let reloaded = PlateInsertScene::from_toml_str(&text, Path::new("t.toml"), &[]).unwrap();
        assert_eq!(reloaded.plate_insert.friction, 0.3);
        assert_eq!(reloaded.plate_insert, load(&sets).unwrap().plate_insert);
        let bad = crate::schema::overridden_scene_text(SCENE, Path::new("t.toml"), &["plate_insert.friction".into()]);
        assert!(matches!(bad, Err(SceneError::Override { .. })), "{bad:?}");
        let e = crate::schema::overridden_scene_text("x = [", Path::new("t.toml"), &[]).unwrap_err().to_string();
        assert!(e.starts_with("scene t.toml: "), "{e}");
    }
}

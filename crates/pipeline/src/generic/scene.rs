//! Generic scene files: any geometry on a Gmsh mesh, parsed at the edge into a
//! [`ProblemDescription`], a [`LoadSchedule`](contact2d_contact::LoadSchedule) and [`SolverSettings`].
//!
//! ```toml
//! name = "cylinder_on_block"
//! mesh = "cylinder_on_block.msh"    # relative to the scene file
//! plane = "strain"                  # "stress" (default) or "strain"; a body may override
//! [[body]]
//! region = "cylinder"               # 2D physical group
//! youngs_modulus = 210000.0
//! poissons_ratio = 0.3
//! [[fix]]                           # 1D (or 0D) physical group; any of u1, u2
//! group = "block_bottom"
//! u1 = 0.0
//! u2 = 0.0
//! # un = 0.0, ut = 0.0            # or: normal / tangential to a curve, node by node
//! [[load]]                          # force (total, per unit thickness), traction, pressure, or
//! group = "cylinder_top"            # body_force (per unit volume) with group = a body's region
//! force = [0.0, -35000.0]
//! pattern = "press"                 # default "main"
//! [[point]]                         # a reference point coupled to a group ("distributing":
//! name = "ref"                      # RBE3; "kinematic": RBE2, fixed), or a node (neither)
//! at = [0.0, 1.0]
//! group = "cylinder_top"
//! coupling = "distributing"
//! [[load]]                          # a force and moment at the point, spread over the group
//! point = "ref"
//! moment = 10.0
//! [[contact]]
//! name = "hertz"
//! master = "cylinder_arc"
//! slave = "block_top"
//! friction = 0.0
//! [loading]                         # steps = N, or a schedule of pattern factors
//! schedule = [{ press = 0.5 }, { press = 1.0 }]
//! [solver]
//! algorithm = "active_set"
//! ```
//!
//! Every key, unit and default is in `docs/user-guide.md` ("Generic scenes"). Unknown keys are
//! errors; errors name the file and the line (syntax, types) or the dotted key (values).

use std::path::{Path, PathBuf};

use serde::Deserialize;

use contact2d_contact::{
    BodyDescription, ContactAlgorithm, ContactDescription, EdgeLoadKind, FixDescription, GapDescription,
    LoadDescription, Pairing, ProblemDescription, SolverSettings, StageActivity,
    builder::{DEFAULT_PATTERN, pattern_order},
};
use contact2d_element::{Formulation, locking_warning_in};
use contact2d_fem::Component;
use contact2d_mesh::Mesh;

use super::kinematics_key::{KinematicsKey, PlaneKey};
use crate::schema::limits::{MAX_FRICTION, STIFFNESS_RATIO_RANGE};
use crate::schema::{SceneError, SolverEntry, parse_scene_toml};

/// One `[[body]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyEntry {
    /// The 2D physical group.
    pub region: String,
    /// E (stress units).
    pub youngs_modulus: f64,
    /// ν.
    pub poissons_ratio: f64,
    /// Overrides the scene's `plane`.
    pub plane: Option<PlaneKey>,
    /// Out-of-plane thickness (default 1; none for a body of revolution).
    pub thickness: Option<f64>,
    /// `standard` (default) or `bbar` (locking-free for nearly incompressible plane strain).
    #[serde(default)]
    pub formulation: FormulationKey,
}

/// The element formulation as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum FormulationKey {
    /// Standard displacement elements.
    #[default]
    Standard,
    /// B-bar.
    Bbar,
}

impl FormulationKey {
    fn formulation(self) -> Formulation {
        match self {
            FormulationKey::Standard => Formulation::Standard,
            FormulationKey::Bbar => Formulation::BBar,
        }
    }
}

/// One `[[fix]]`: prescribed displacement components on a group or a point, or a small rigid
/// rotation of a group.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FixEntry {
    /// A 1D or 0D physical group (or give `point`).
    pub group: Option<String>,
    /// A `[[point]]` (or give `group`).
    pub point: Option<String>,
    /// Prescribed u1 (a translation with `rotation`).
    pub u1: Option<f64>,
    /// Prescribed u2 (a translation with `rotation`).
    pub u2: Option<f64>,
    /// Prescribed un, along the curve's normal (out of the body) node by node: the group must be
    /// a curve ([`contact2d_mesh::frames::node_frames`]); not with `u1` / `u2` on the same node.
    pub un: Option<f64>,
    /// Prescribed ut, along the curve's tangent `e3 × n` node by node (as `un`).
    pub ut: Option<f64>,
    /// A small rigid rotation θ (radians, counter-clockwise): of the group about `about`,
    /// `u = (u1, u2) + θ e3 × (x − about)`, or of a kinematic point.
    pub rotation: Option<f64>,
    /// The centre `[x, y]` of a group's `rotation`.
    pub about: Option<[f64; 2]>,
    /// The load pattern of its non-zero values (default `main`; a zero value is in none).
    #[serde(default = "main")]
    pub pattern: String,
    /// The first step (from 1) it holds its DOFs in, at the position they have reached at the
    /// end of the step before, plus its values (default 1: from the start).
    pub from_step: Option<usize>,
    /// The last step it holds its DOFs in; it releases them after (default: the last step).
    pub until_step: Option<usize>,
}

impl FixEntry {
    /// What it fixes, for messages: `group "NAME"` or `point "NAME"`.
    pub fn target(&self) -> String {
        match (&self.group, &self.point) {
            (Some(g), _) => format!("group \"{g}\""),
            (None, Some(p)) => format!("point \"{p}\""),
            (None, None) => "nothing".into(),
        }
    }

    /// Whether any of its values is not zero.
    pub fn moves(&self) -> bool {
        [self.u1, self.u2, self.un, self.ut, self.rotation].iter().any(|v| v.is_some_and(|v| v != 0.0))
    }
}

/// One `[[load]]`: on a group, exactly one of `force`, `traction`, `pressure` (on a 1D group)
/// or `body_force` (on a body's 2D region); on a point, a `force` and/or a `moment`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadEntry {
    /// A 1D physical group, or a body's region for `body_force` (or give `point`).
    pub group: Option<String>,
    /// A `[[point]]` (or give `group`).
    pub point: Option<String>,
    /// Total force `[F1, F2]` on the group or at the point, per unit thickness.
    pub force: Option<[f64; 2]>,
    /// Traction vector (force per unit length and thickness).
    pub traction: Option<[f64; 2]>,
    /// Pressure, positive against the body.
    pub pressure: Option<f64>,
    /// Body force `[b1, b2]` per unit volume (e.g. the weight `[0, -ρ g]`); `group` names the
    /// body's region.
    pub body_force: Option<[f64; 2]>,
    /// A moment M (counter-clockwise, per unit thickness) at a coupled point.
    pub moment: Option<f64>,
    /// The load pattern (default `main`).
    #[serde(default = "main")]
    pub pattern: String,
}

impl LoadEntry {
    /// What it loads, for messages: `group "NAME"` or `point "NAME"`.
    pub fn target(&self) -> String {
        match (&self.group, &self.point) {
            (Some(g), _) => format!("group \"{g}\""),
            (None, Some(p)) => format!("point \"{p}\""),
            (None, None) => "nothing".into(),
        }
    }
}

/// How a point is coupled to its group, as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CouplingKey {
    /// The point's force and moment spread over the group's nodes by weights, no stiffness
    /// added; its motion the group's weighted mean (Abaqus *COUPLING, DISTRIBUTING; RBE3).
    Distributing,
    /// The group moves rigidly with the point (RBE2).
    Kinematic,
}

/// One `[[point]]`: a reference point, coupled to a group (or, with neither `group` nor
/// `coupling`, a mesh node at `at`).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointEntry {
    /// Its name (`[[fix]] point`, `[[load]] point`, the outputs' `points.NAME`).
    pub name: String,
    /// Where it is, `[x, y]` (need not be a node when coupled).
    pub at: [f64; 2],
    /// The physical group it is coupled to.
    pub group: Option<String>,
    /// How it is coupled to `group`.
    pub coupling: Option<CouplingKey>,
}

/// Pairing as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PairingKey {
    /// Node to segment (the mesh as given).
    NodeToSegment,
    /// Node to node after sliding the slave nodes onto the paired points.
    NodeToNode,
    /// Segment to segment (mortar-type: gap and traction integrated over the master segments).
    SegmentToSegment,
    /// Node to segment where the curves' nodes face each other one to one, else segment to
    /// segment (the default).
    Automatic,
}

/// How far the bodies may slide along a contact, as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum SlidingKey {
    /// The pairs are formed once, in the undeformed configuration; a run whose pairs in contact
    /// slide further than [`super::sliding::SMALL_SLIDING_FRACTION`] of their segment gets a
    /// note (the default: every existing scene's pairs, and its cost, stay as they were).
    #[default]
    Small,
    /// The pairs formed again on the current configuration before every load step
    /// (node-to-segment pairing; the active set or the augmented Lagrangian;
    /// [`contact2d_contact::finite_sliding`]).
    Finite,
}

/// A gap: `"geometric"` or a number.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum GapKey {
    /// A given gap for every pair (length units; negative is an interference).
    Given(f64),
    /// `"geometric"`.
    Named(String),
}

/// One `[[contact]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactEntry {
    /// The interface's name (keys the outputs).
    pub name: String,
    /// Master curve (1D group).
    pub master: String,
    /// Slave curve (1D group).
    pub slave: String,
    /// The slave is a fixed rigid obstacle (its region is no body).
    #[serde(default)]
    pub rigid: bool,
    /// Pairing (default `automatic`: node to segment on matching meshes, else segment to segment).
    #[serde(default = "automatic")]
    pub pairing: PairingKey,
    /// Initial gap (default `"geometric"`).
    #[serde(default = "geometric")]
    pub gap: GapKey,
    /// μ (default 0).
    #[serde(default)]
    pub friction: f64,
    /// Master and slave may bound the same body (default `false`: such a pair is an error).
    #[serde(default)]
    pub self_contact: bool,
    /// `"small"` (default): paired once in the undeformed configuration; `"finite"`: paired
    /// again on the current configuration before every step.
    #[serde(default)]
    pub sliding: SlidingKey,
    /// Two groups `[A, B]` whose mean relative displacement along the contact is the abscissa
    /// of its hysteresis loop over the last load cycle (none: no loop).
    #[serde(default)]
    pub reference_groups: Option<[String; 2]>,
}

/// The `[loading]` section.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadingSection {
    /// Every pattern from 0 to 1 in this many equal steps.
    pub steps: Option<usize>,
    /// The factor of each named pattern at the end of each step (unnamed patterns: 0).
    pub schedule: Option<super::schedule_rows::ScheduleRows>,
    /// One load cycle: the factors of its steps, as in `schedule`, run after the `steps` or
    /// `schedule` (the preload) `cycles` times.
    pub cycle: Option<super::schedule_rows::ScheduleRows>,
    /// How many times `cycle` runs (1 ..= 10 000; default 1 with a `cycle`).
    pub cycles: Option<usize>,
    /// Whether a frictional run estimates the error its step size causes (`path_error`: the run
    /// solved again with every step halved, [`super::path_error`]); default true.
    #[serde(default = "yes")]
    pub path_error: bool,
    /// Adaptive stepping: the user's steps split where the path error exceeds the tolerance
    /// ([`super::adaptive`]); none by default.
    #[serde(default)]
    pub adaptive: Option<super::adaptive::AdaptiveKey>,
}

fn yes() -> bool {
    true
}

impl Default for LoadingSection {
    /// No steps, schedule or cycle given; the path error estimated.
    fn default() -> Self {
        LoadingSection { steps: None, schedule: None, cycle: None, cycles: None, path_error: true, adaptive: None }
    }
}

fn main() -> String {
    DEFAULT_PATTERN.to_string()
}
fn automatic() -> PairingKey {
    PairingKey::Automatic
}
fn geometric() -> GapKey {
    GapKey::Named("geometric".into())
}

/// A generic scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GenericScene {
    /// Short name (outputs, titles).
    pub name: String,
    /// One line for people.
    #[serde(default)]
    pub description: String,
    /// The mesh, relative to the scene file.
    pub mesh: PathBuf,
    /// `plane_stress`, `plane_strain` or `axisymmetric` ([`super::kinematics_key`]).
    pub kinematics: Option<KinematicsKey>,
    /// Default plane condition of the bodies (plane stress when neither this nor `kinematics`
    /// is given).
    pub plane: Option<PlaneKey>,
    /// Bodies.
    #[serde(default)]
    pub body: Vec<BodyEntry>,
    /// Prescribed displacements.
    #[serde(default)]
    pub fix: Vec<FixEntry>,
    /// Edge loads, body forces and point loads.
    #[serde(default)]
    pub load: Vec<LoadEntry>,
    /// Reference points and their couplings.
    #[serde(default)]
    pub point: Vec<PointEntry>,
    /// Contact interfaces.
    #[serde(default)]
    pub contact: Vec<ContactEntry>,
    /// The load schedule (default one step).
    #[serde(default)]
    pub loading: LoadingSection,
    /// The solver.
    #[serde(default)]
    pub solver: SolverEntry,
    /// The scene file's directory.
    #[serde(skip)]
    pub base_dir: PathBuf,
    /// The scene file as given.
    #[serde(skip)]
    pub file: PathBuf,
    /// Every step's row of the summary carries the interfaces' profiles, not only the last
    /// (not a scene key: `run --profiles all`).
    #[serde(skip)]
    pub every_profile: bool,
    /// The centre `[x, y]` the run's moments are taken about (not a scene key: `run --about
    /// x,y`; default the origin).
    #[serde(skip)]
    pub moment_centre: [f64; 2],
    /// The displacements are in a unit of their own, a reference displacement L0 ≪ the lengths'
    /// unit (a preset's linearised theory, as the paper's u / L0 against x / R): the
    /// small-sliding check, which compares displacements with segment lengths, does not apply
    /// (not a scene key: set by the preset that expands into this scene).
    #[serde(skip)]
    pub linearised_displacements: bool,
}

impl GenericScene {
    /// Parses `text` as if read from `path`, applies `overrides` and checks the values.
    ///
    /// # Errors
    /// [`SceneError`] naming the file and the line, key or override at fault.
    pub fn from_toml_str(text: &str, path: &Path, overrides: &[String]) -> Result<GenericScene, SceneError> {
        let mut scene: GenericScene = parse_scene_toml(text, path, overrides, &["loading", "solver"])?;
        scene.file = path.to_path_buf();
        scene.base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        scene.validate()?;
        Ok(scene)
    }

    /// The mesh path resolved against the scene file's directory.
    pub fn mesh_path(&self) -> PathBuf {
        self.base_dir.join(&self.mesh)
    }

    pub(super) fn fail(&self, key: &str, reason: String) -> SceneError {
        SceneError::Value { path: self.file.display().to_string(), key: key.to_string(), reason }
    }

    /// The bodies' stiffnesses within [`STIFFNESS_RATIO_RANGE`] of each other (the stiffness
    /// matrix's condition number grows with E_max / E_min; beyond 1e8 the softer body is
    /// round-off), as the plate-insert preset's E2/E1.
    fn validate_stiffness_ratio(&self) -> Result<(), SceneError> {
        let stiffest = self.body.iter().enumerate().max_by(|a, b| a.1.youngs_modulus.total_cmp(&b.1.youngs_modulus));
        let softest = self.body.iter().map(|b| b.youngs_modulus).fold(f64::INFINITY, f64::min);
        let Some((i, b)) = stiffest else { return Ok(()) };
        let (_, hi) = STIFFNESS_RATIO_RANGE;
        let ratio = b.youngs_modulus / softest;
        if ratio > hi {
            return Err(self.fail(
                &format!("body.{i}.youngs_modulus"),
                format!(
                    "E_max / E_min = {ratio:e} is out of the solvable range ..= {hi:e} (the stiffness matrix's \
                     condition number grows with the ratio; beyond it the softer body is round-off)"
                ),
            ));
        }
        Ok(())
    }

    /// Checks ranges and contradictions that need no mesh.
    ///
    /// # Errors
    /// [`SceneError::Value`] naming the first key at fault.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.body.is_empty() {
            return Err(self.fail("body", "no [[body]]: name at least one 2D region".into()));
        }
        if let Some(a) = self.loading.adaptive
            && !(a.tolerance.is_finite() && a.tolerance > 0.0)
        {
            return Err(self.fail("loading.adaptive.tolerance", format!("{} must be finite and > 0", a.tolerance)));
        }
        if self.loading.adaptive.is_some()
            && self.solver.place_zone_ends == Some(true)
            && self.solver.algorithm == ContactAlgorithm::Boussinesq
        {
            return Err(self.fail(
                "loading.adaptive",
                "adaptive stepping does not apply to the Boussinesq algorithm's placed zone ends (each step is solved \
                 on its own mesh, moved to the zone ends): give the steps, or set solver.place_zone_ends = false"
                    .into(),
            ));
        }
        for (i, b) in self.body.iter().enumerate() {
            if !(b.youngs_modulus.is_finite() && b.youngs_modulus > 0.0) {
                return Err(self.fail(
                    &format!("body.{i}.youngs_modulus"),
                    format!("{} must be finite and > 0", b.youngs_modulus),
                ));
            }
            if !(b.poissons_ratio > -1.0 && b.poissons_ratio < 0.5) {
                return Err(self
                    .fail(&format!("body.{i}.poissons_ratio"), format!("{} must lie in (−1, 0.5)", b.poissons_ratio)));
            }
            if self.body[..i].iter().any(|c| c.region == b.region) {
                return Err(self.fail(&format!("body.{i}.region"), format!("\"{}\" is a body twice", b.region)));
            }
        }
        self.validate_kinematics()?;
        self.validate_stiffness_ratio()?;
        self.validate_points()?;
        for (i, c) in self.contact.iter().enumerate() {
            if !(c.friction.is_finite() && c.friction >= 0.0) {
                return Err(
                    self.fail(&format!("contact.{i}.friction"), format!("{} must be finite and ≥ 0", c.friction))
                );
            }
            if c.friction > MAX_FRICTION {
                return Err(self.fail(
                    &format!("contact.{i}.friction"),
                    format!(
                        "μ = {:e} is beyond {MAX_FRICTION} (every pair sticks long before; the cone test μλ loses all digits)",
                        c.friction
                    ),
                ));
            }
            match &c.gap {
                GapKey::Named(n) if n != "geometric" => {
                    return Err(
                        self.fail(&format!("contact.{i}.gap"), format!("\"{n}\": give \"geometric\" or a number"))
                    );
                }
                GapKey::Given(g) if !g.is_finite() => {
                    return Err(self.fail(&format!("contact.{i}.gap"), format!("{g} is not finite")));
                }
                _ => {}
            }
            if self.contact[..i].iter().any(|d| d.name == c.name) {
                return Err(self.fail(&format!("contact.{i}.name"), format!("\"{}\" names two contacts", c.name)));
            }
        }
        if self.solver.algorithm == ContactAlgorithm::Boussinesq && self.contact.len() != 1 {
            return Err(self.fail(
                "solver.algorithm",
                format!("boussinesq solves exactly one contact interface; the scene has {}", self.contact.len()),
            ));
        }
        self.settings()?;
        let steps = self.schedule()?.steps().len();
        self.validate_fix_steps(steps)
    }

    /// `from_step` and `until_step` of every fix within the schedule's `steps` and in order,
    /// and only where staged supports are solved (small sliding, an algorithm other than the
    /// Boussinesq one).
    fn validate_fix_steps(&self, steps: usize) -> Result<(), SceneError> {
        for (i, f) in self.fix.iter().enumerate() {
            for (key, step) in [("from_step", f.from_step), ("until_step", f.until_step)] {
                match step {
                    Some(0) => {
                        return Err(self.fail(&format!("fix.{i}.{key}"), "0: steps count from 1".into()));
                    }
                    Some(k) if k > steps => {
                        return Err(self.fail(
                            &format!("fix.{i}.{key}"),
                            format!("step {k} is past the last step of the schedule ({steps} steps)"),
                        ));
                    }
                    _ => {}
                }
            }
            if let (Some(step), true) = (f.from_step.or(f.until_step), f.point.is_some() || f.rotation.is_some()) {
                let key = if f.from_step.is_some() { "from_step" } else { "until_step" };
                return Err(self.fail(
                    &format!("fix.{i}.{key}"),
                    format!(
                        "step {step}: staged supports hold a group's u1 / u2; a point's fix or a rotation holds in \
                         every step"
                    ),
                ));
            }
            if let (Some(from), Some(until)) = (f.from_step, f.until_step)
                && from > until
            {
                return Err(self.fail(
                    &format!("fix.{i}.from_step"),
                    format!("step {from} is after until_step = {until}: the fix would hold in no step"),
                ));
            }
        }
        let staged =
            self.fix.iter().position(|f| f.from_step.is_some_and(|k| k > 1) || f.until_step.is_some_and(|k| k < steps));
        if let Some(i) = staged {
            let key = if self.fix[i].from_step.is_some_and(|k| k > 1) { "from_step" } else { "until_step" };
            if self.contact.iter().any(|c| c.sliding == SlidingKey::Finite) {
                return Err(self.fail(
                    &format!("fix.{i}.{key}"),
                    "staged supports are solved with small sliding only (a contact has sliding = \"finite\")".into(),
                ));
            }
            if self.solver.algorithm == ContactAlgorithm::Boussinesq {
                return Err(self.fail(
                    &format!("fix.{i}.{key}"),
                    "staged supports change the problem between steps; the boussinesq algorithm grows one zone over \
                     a proportional schedule (use active_set)"
                        .into(),
                ));
            }
        }
        Ok(())
    }

    /// The stages of the scene's staged supports: runs of steps (indices from 0) over which the
    /// set of active fixes is constant, each with one flag per fix of [`GenericScene::description`]
    /// (a `[[fix]]` gives one per component it prescribes). One stage, every fix active, when
    /// no fix is staged.
    ///
    /// # Errors
    /// The schedule's errors.
    pub fn fix_stages(&self) -> Result<Vec<StageActivity>, SceneError> {
        let steps = self.schedule()?.steps().len();
        let active_in = |step: usize| -> Vec<bool> {
            let k = step + 1;
            // The fixes of the description, in its order: the groups' u1 / u2 (a rotation's and a
            // point's values are node values, held in every step).
            self.fix
                .iter()
                .filter(|f| f.rotation.is_none() && f.group.is_some())
                .flat_map(|f| {
                    let on = f.from_step.is_none_or(|from| from <= k) && f.until_step.is_none_or(|until| k <= until);
                    let count = [f.u1, f.u2, f.un, f.ut].iter().filter(|v| v.is_some()).count();
                    std::iter::repeat_n(on, count)
                })
                .collect()
        };
        let mut stages: Vec<StageActivity> = vec![];
        for step in 0..steps {
            let active = active_in(step);
            match stages.last_mut() {
                Some((range, flags)) if *flags == active => range.end = step + 1,
                _ => stages.push((step..step + 1, active)),
            }
        }
        Ok(stages)
    }

    /// The pattern names the scene's values and loads use, `main` first
    /// ([`contact2d_contact::builder::pattern_order`], the order the built problem has: the
    /// groups' values, the nodes' values (rotations, kinematic points), the group loads, the
    /// point loads).
    pub fn pattern_names(&self) -> Vec<String> {
        let plain = |f: &&FixEntry| f.group.is_some() && f.rotation.is_none();
        let values = self.fix.iter().filter(|f| plain(f) && f.moves()).map(|f| f.pattern.as_str());
        let node_values = self.fix.iter().filter(|f| !plain(f) && f.moves()).map(|f| f.pattern.as_str());
        let loads = self.load.iter().filter(|l| l.point.is_none()).map(|l| l.pattern.as_str());
        let point_loads = self.load.iter().filter(|l| l.point.is_some()).map(|l| l.pattern.as_str());
        pattern_order(values.chain(node_values).chain(loads).chain(point_loads))
    }

    /// The patterns only zero-valued fixes name (a support is in no pattern): a schedule may
    /// name them, to no effect.
    pub(super) fn inert_patterns(&self) -> Vec<String> {
        let names = self.pattern_names();
        self.fix.iter().map(|f| f.pattern.clone()).filter(|p| !names.contains(p)).collect()
    }

    /// The solver settings.
    ///
    /// # Errors
    /// An iteration limit out of range.
    pub fn settings(&self) -> Result<SolverSettings, SceneError> {
        self.solver.settings(|key, reason| self.fail(key, reason))
    }

    /// Warnings about the elements: standard elements of a nearly incompressible body in plane
    /// strain or of revolution lock.
    pub fn element_warnings(&self) -> Vec<String> {
        self.body
            .iter()
            .filter_map(|b| {
                locking_warning_in(&self.body_kinematics(b), b.poissons_ratio, b.formulation.formulation())
                    .map(|w| format!("body \"{}\": {w}", b.region))
            })
            .collect()
    }

    /// The problem description on `mesh`: the groups' fixes and loads, and the points' as
    /// values and forces of single nodes ([`GenericScene::point_conditions`]).
    ///
    /// # Errors
    /// [`SceneError::Value`] naming the `[[point]]`, `[[fix]]` or `[[load]]` key a point's
    /// group or node does not fit.
    pub fn description(&self, mesh: Mesh) -> Result<ProblemDescription, SceneError> {
        let bodies = self
            .body
            .iter()
            .map(|b| BodyDescription {
                region: b.region.clone(),
                youngs_modulus: b.youngs_modulus,
                poissons_ratio: b.poissons_ratio,
                kinematics: self.body_kinematics(b),
                formulation: b.formulation.formulation(),
            })
            .collect();
        let mut fixes = vec![];
        for (i, f) in self.fix.iter().enumerate().filter(|(_, f)| f.rotation.is_none()) {
            let Some(group) = &f.group else { continue };
            if let Some(key) = [("un", f.un), ("ut", f.ut)].iter().find(|(_, v)| v.is_some()).map(|(k, _)| *k) {
                contact2d_mesh::frames::node_frames(&mesh, group)
                    .map_err(|e| self.fail(&format!("fix.{i}.{key}"), e.to_string()))?;
            }
            let components =
                [(Component::X, f.u1), (Component::Y, f.u2), (Component::Normal, f.un), (Component::Tangent, f.ut)];
            for (component, value) in components {
                if let Some(value) = value {
                    fixes.push(FixDescription { group: group.clone(), component, value, pattern: f.pattern.clone() });
                }
            }
        }
        let loads = self
            .load
            .iter()
            .filter_map(|l| Some((l.group.as_ref()?, l)))
            .filter(|(_, l)| l.point.is_none())
            .map(|(group, l)| LoadDescription {
                group: group.clone(),
                kind: match (l.force, l.traction, l.body_force, l.pressure) {
                    (Some(f), _, _, _) => EdgeLoadKind::Force(f),
                    (_, Some(t), _, _) => EdgeLoadKind::Traction(t),
                    (_, _, Some(b), _) => EdgeLoadKind::BodyForce(b),
                    (_, _, _, p) => EdgeLoadKind::Pressure(p.unwrap_or(0.0)),
                },
                pattern: l.pattern.clone(),
            })
            .collect();
        let (node_fixes, node_loads) = self.point_conditions(&mesh)?;
        let contacts = self
            .contact
            .iter()
            .map(|c| ContactDescription {
                name: c.name.clone(),
                master: c.master.clone(),
                slave: c.slave.clone(),
                rigid_slave: c.rigid,
                pairing: match c.pairing {
                    PairingKey::NodeToSegment => Pairing::NodeToSegment,
                    PairingKey::NodeToNode => Pairing::NodeToNode,
                    PairingKey::SegmentToSegment => Pairing::SegmentToSegment,
                    PairingKey::Automatic => Pairing::Automatic,
                },
                gap: match c.gap {
                    GapKey::Given(g) => GapDescription::Given(g),
                    GapKey::Named(_) => GapDescription::Geometric,
                },
                friction: c.friction,
                self_contact: c.self_contact,
            })
            .collect();
        Ok(ProblemDescription { mesh, bodies, fixes, loads, node_fixes, node_loads, contacts })
    }
}

#[cfg(test)]
#[path = "scene_tests.rs"]
mod tests;

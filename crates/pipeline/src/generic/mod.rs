//! Generic scenes: any geometry, read from a Gmsh mesh and a TOML scene, solved through the one
//! entry point, reported as one JSON contract and written as generic outputs.
//!
//! ```text
//! scene (TOML) → GenericScene → ProblemDescription → BuiltProblem
//!   → solve(&problem, &settings, &schedule) → History → GenericReport (JSON) → outputs
//! ```

pub mod adaptive;
mod body_kinematics;
pub mod fretting;
#[cfg(feature = "native")]
pub mod fretting_outputs;
pub mod kinematics_key;
pub mod named_map;
#[cfg(feature = "native")]
pub mod outputs;
pub mod path_error;
pub mod placed;
mod placed_ends;
pub mod points;
pub mod readme;
pub mod results;
pub mod scene;
mod schedule;
pub mod schedule_rows;
pub mod setup_notes;
pub mod sliding;
pub mod step_table;
mod stepping;
mod summary;
pub mod zones;

use std::collections::BTreeMap;
use std::path::Path;
use web_time::Instant;

use serde::Serialize;

use contact2d_contact::{BuiltProblem, ContactError, History, Retention, SolvedStep, Stage, builder::group_length};
use contact2d_mesh::read_msh;

pub use named_map::NamedMap;
pub use points::{PointResult, ResolvedPoint};
pub use results::{ContactResult, FixedGroup, Kkt, NotHeldResult, Profile, StepResult};
pub use scene::GenericScene;
pub use step_table::StepTable;
use stepping::{Run, estimate_path_error, keep_user_steps, plan_path, solve_run};
pub use summary::{SummaryInput, SummaryRows, summarise};

use crate::input_file::{InputFileError, MAX_MESH_BYTES, check_input_file};
use crate::output::step_view::bounding_box;
use crate::schema::SceneError;

/// Errors of a generic run.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum GenericError {
    /// The scene file.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The mesh could not be read.
    #[error("scene {scene}: mesh {mesh}: {source}")]
    Mesh {
        /// The scene file.
        scene: String,
        /// The mesh file.
        mesh: String,
        /// Why.
        source: contact2d_mesh::MeshError,
    },
    /// Building or solving the problem.
    #[error("scene {scene}, mesh {mesh}: {source}")]
    Contact {
        /// The scene file.
        scene: String,
        /// The mesh file.
        mesh: String,
        /// Why.
        source: Box<ContactError>,
    },
    /// Evaluating results.
    #[error("scene {scene}: {source}")]
    Fem {
        /// The scene file.
        scene: String,
        /// Why.
        source: contact2d_fem::FemError,
    },
}

/// What a run tells while it goes: the CLI shows it as a progress bar (the library prints
/// nothing).
pub trait Progress {
    /// Step `done` of `total` is solved, at load w.
    fn step_done(&mut self, done: usize, total: usize, w: f64);
}

/// A [`Progress`] that ignores everything.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Progress for Silent {
    fn step_done(&mut self, _done: usize, _total: usize, _w: f64) {}
}

/// Where a run's time went, seconds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct Times {
    /// The whole run (reading to results).
    pub total: f64,
    /// Reading the mesh.
    pub read: f64,
    /// Assembly, pairing and rows.
    pub assemble: f64,
    /// Ordering and factorisation of `K` (bordered by the pair rows up to 2,000 pairs; beyond,
    /// `K`'s own factor is made only if something needs it, and the sparse path's
    /// factorisations are part of `solve`).
    pub factor: f64,
    /// Condensation onto the interface.
    pub condense: f64,
    /// The contact algorithm over every step.
    pub solve: f64,
    /// Results: resultants, reactions, energies, profiles.
    pub post: f64,
}

/// A group the scene uses: its length (1D) and bounding box, so that a swapped name shows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroupReport {
    /// The group's dimension.
    pub dim: usize,
    /// Its length (1D groups; 0 otherwise).
    pub length: f64,
    /// `[[x_min, y_min], [x_max, y_max]]` of its nodes.
    pub bbox: [[f64; 2]; 2],
}

/// A body held only by contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FloatingReport {
    /// The body.
    pub body: String,
    /// Its rigid motions that no Dirichlet condition holds.
    pub free_modes: Vec<String>,
}

/// The JSON summary of a generic run (`contact2d run --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GenericReport {
    /// The scene's name.
    pub scene: String,
    /// The worst step's status (`converged` when every step converged and the history keeps its
    /// energy balance).
    pub status: &'static str,
    /// For `numerical`: the check that failed, with its value and tolerance.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failed_check: Option<String>,
    /// For `not_held`: the contact, the step, the last load factors held and the ratio of the
    /// demanded to the available friction force (the step row's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_held: Option<NotHeldResult>,
    /// The algorithm (its scene key).
    #[serde(serialize_with = "crate::schema::serialize_algorithm")]
    pub algorithm: contact2d_contact::ContactAlgorithm,
    /// The kinematics that ran, as the scene key spells it: `plane_stress`, `plane_strain`,
    /// `axisymmetric`, or `plane` for plane bodies of both conditions.
    pub kinematics: &'static str,
    /// Free DOFs.
    pub dofs: usize,
    /// Contact pairs.
    pub pairs: usize,
    /// Iterations summed over the steps.
    pub iterations: usize,
    /// Whether the schedule was solved once and scaled (no gap, proportional loads).
    pub scaled: bool,
    /// The pairing each interface used: as the scene gives it, or what `automatic` chose.
    pub pairing_used: BTreeMap<String, &'static str>,
    /// The linear algebra the contact states were solved with (`solver.linear` resolved for this
    /// algorithm and pair count): `condensed` (the interface's dense compliances) or `sparse`
    /// (the full system, no dense block).
    pub linear_used: &'static str,
    /// The largest error the step size causes over the steps, relative (each step's
    /// `path_error`, [`path_error`]): 0 for a path-independent run (no friction, or solved once
    /// and scaled), `None` (absent from the JSON) where it was not estimated (`loading.path_error =
    /// false`, the placed Boussinesq runs, or a halved path that did not solve: the notes say).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path_error: Option<f64>,
    /// Adaptive stepping (`[loading] adaptive`): the steps its path took for the user's steps
    /// (absent without it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub steps_taken: Option<usize>,
    /// Every step, without profiles.
    pub steps: StepTable,
    /// The last step's interfaces, with profiles.
    pub contacts: BTreeMap<String, ContactResult>,
    /// The last step's reactions per fixed group (`null` in a component the group's own fixes
    /// do not prescribe).
    pub reactions: BTreeMap<String, [Option<f64>; 2]>,
    /// The last step's reactions of every constrained DOF, each once: `[R1, R2]`.
    pub reactions_total: [f64; 2],
    /// The centre `[x, y]` the moments are taken about (`run --about x,y`; default the origin).
    pub moment_centre: [f64; 2],
    /// The last step's reaction moments per fixed group about `moment_centre` (the components
    /// its own fixes prescribe).
    pub reaction_moments: BTreeMap<String, f64>,
    /// The last step's moment of every constrained DOF's reaction about `moment_centre`.
    pub reaction_moment_total: f64,
    /// The last step's strain energy per body.
    pub energies: BTreeMap<String, f64>,
    /// The last step's motion and reactions of every `[[point]]` (none without points).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub points: BTreeMap<String, PointResult>,
    /// The last step's KKT residuals.
    pub kkt: Kkt,
    /// Bodies held only by contact.
    pub floating_bodies: Vec<FloatingReport>,
    /// Every group the scene names.
    pub groups: BTreeMap<String, GroupReport>,
    /// Where the time went.
    pub time_s: Times,
    /// What a user should know about how the numbers were obtained.
    pub notes: Vec<String>,
    /// The blocks of the scene's preset, by name (`paper`: the plate-insert preset's quantities,
    /// its post-processor `src/plate_insert/report.rs`); none for a plain generic scene.
    #[serde(flatten)]
    pub post: BTreeMap<String, serde_json::Value>,
}

impl GenericReport {
    /// A copy of the summary without its step rows (`steps` empty), which grow with the
    /// number of steps.
    pub fn without_steps(&self) -> GenericReport {
        GenericReport {
            scene: self.scene.clone(),
            status: self.status,
            failed_check: self.failed_check.clone(),
            not_held: self.not_held.clone(),
            algorithm: self.algorithm,
            kinematics: self.kinematics,
            dofs: self.dofs,
            pairs: self.pairs,
            iterations: self.iterations,
            scaled: self.scaled,
            pairing_used: self.pairing_used.clone(),
            linear_used: self.linear_used,
            path_error: self.path_error,
            steps_taken: self.steps_taken,
            steps: StepTable::new(),
            contacts: self.contacts.clone(),
            reactions: self.reactions.clone(),
            reactions_total: self.reactions_total,
            moment_centre: self.moment_centre,
            reaction_moments: self.reaction_moments.clone(),
            reaction_moment_total: self.reaction_moment_total,
            energies: self.energies.clone(),
            points: self.points.clone(),
            kkt: self.kkt,
            floating_bodies: self.floating_bodies.clone(),
            groups: self.groups.clone(),
            time_s: self.time_s,
            notes: self.notes.clone(),
            post: self.post.clone(),
        }
    }
}

/// A solved generic scene: the summary and what the outputs need.
#[derive(Debug, Clone)]
pub struct GenericOutcome {
    /// The scene.
    pub scene: GenericScene,
    /// The built problem.
    pub built: BuiltProblem,
    /// The solved steps: every one after [`solve_generic`], only the last after
    /// [`solve_generic_streaming`] (whose caller saw each step as it was solved).
    pub history: History,
    /// The summary.
    pub report: GenericReport,
}

/// Reads a generic scene file (see [`GenericScene::from_toml_str`]).
///
/// # Errors
/// [`SceneError`] naming the file and what is wrong.
pub fn load_scene(path: &Path, overrides: &[String]) -> Result<GenericScene, SceneError> {
    GenericScene::from_toml_str(&crate::schema::read_scene_text(path)?, path, overrides)
}

/// Solves a generic scene, calling `on_step(done, total)` after each step.
///
/// # Errors
/// [`GenericError`] naming the scene and mesh.
pub fn solve_generic(
    scene: &GenericScene,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<GenericOutcome, GenericError> {
    solve_generic_until(scene, None, on_step)
}

/// [`solve_generic`] that streams: `on_solved(built, i, step)` is called with each step `i` (from
/// 0) as it is solved, and the outcome's history keeps only the last step's solution (the report
/// still has every step's summary row), so that memory stays flat in the number of steps. Same
/// report as [`solve_generic`].
///
/// # Errors
/// As [`solve_generic`].
pub fn solve_generic_streaming(
    scene: &GenericScene,
    on_step: &mut dyn FnMut(usize, usize),
    on_solved: &mut dyn FnMut(&BuiltProblem, usize, &SolvedStep),
) -> Result<GenericOutcome, GenericError> {
    let clock = Instant::now();
    let mesh = read_scene_mesh(scene)?;
    solve_generic_from(
        scene,
        mesh,
        clock,
        None,
        Stream { retention: Retention::Last, on_step, on_solved },
        &as_described,
    )
}

/// [`solve_generic`] with a wall-clock deadline checked before each load step
/// ([`contact2d_contact::SolverSettings::with_deadline`]).
///
/// # Errors
/// As [`solve_generic`]; a passed deadline is [`GenericError::Contact`] with
/// [`ContactError::DeadlineExceeded`].
pub fn solve_generic_until(
    scene: &GenericScene,
    deadline: Option<Instant>,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<GenericOutcome, GenericError> {
    let clock = Instant::now();
    let mesh = read_scene_mesh(scene)?;
    let stream = Stream { retention: Retention::All, on_step, on_solved: &mut |_, _, _| {} };
    solve_generic_from(scene, mesh, clock, deadline, stream, &as_described)
}

/// The scene's mesh file, checked and read.
fn read_scene_mesh(scene: &GenericScene) -> Result<contact2d_mesh::Mesh, GenericError> {
    let (scene_name, mesh_name) = (scene.file.display().to_string(), scene.mesh_path().display().to_string());
    // A FIFO or an endless device is refused before reading; the reader reports the rest.
    if let Err(e) = check_input_file(&scene.mesh_path(), MAX_MESH_BYTES)
        && !matches!(e, InputFileError::Io { .. })
    {
        let reason = format!("cannot read {mesh_name}: {}", e.reason());
        return Err(SceneError::Value { path: scene_name.clone(), key: "mesh".into(), reason }.into());
    }
    read_msh(scene.mesh_path()).map_err(|source| GenericError::Mesh { scene: scene_name, mesh: mesh_name, source })
}

/// [`solve_generic`] on a mesh already read instead of the scene's mesh file (which is neither
/// checked nor read): for callers without files, such as the WebAssembly build of the teaching
/// page. Same numbers as [`solve_generic`] on the file the mesh came from.
///
/// # Errors
/// [`GenericError`] naming the scene and mesh.
pub fn solve_generic_on_mesh(
    scene: &GenericScene,
    mesh: contact2d_mesh::Mesh,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<GenericOutcome, GenericError> {
    let stream = Stream { retention: Retention::All, on_step, on_solved: &mut |_, _, _| {} };
    solve_generic_from(scene, mesh, Instant::now(), None, stream, &as_described)
}

/// What a preset sets on the built problem that no scene key describes (the plate-insert
/// preset's gap model); nothing for a plain generic scene.
pub type Adjust<'a> = &'a dyn Fn(&mut BuiltProblem) -> Result<(), ContactError>;

/// Leaves the built problem as the scene describes it.
fn as_described(_: &mut BuiltProblem) -> Result<(), ContactError> {
    Ok(())
}

/// [`solve_generic`] of a preset's expansion on a mesh already read (`clock` started before
/// reading): `adjust` sets what the scene
/// keys do not describe on the built problem before solving; every step is kept.
///
/// # Errors
/// [`GenericError`] naming the scene and mesh.
pub fn solve_preset(
    scene: &GenericScene,
    mesh: contact2d_mesh::Mesh,
    clock: Instant,
    deadline: Option<Instant>,
    adjust: Adjust<'_>,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<GenericOutcome, GenericError> {
    let stream = Stream { retention: Retention::All, on_step, on_solved: &mut |_, _, _| {} };
    solve_generic_from(scene, mesh, clock, deadline, stream, adjust)
}

/// What a solve does with each step as it is solved, and which steps its history keeps.
struct Stream<'a> {
    retention: Retention,
    on_step: &'a mut dyn FnMut(usize, usize),
    on_solved: &'a mut dyn FnMut(&BuiltProblem, usize, &SolvedStep),
}

/// The solve of [`solve_generic`] once the mesh is read (`clock` started before reading).
fn solve_generic_from(
    scene: &GenericScene,
    mesh: contact2d_mesh::Mesh,
    clock: Instant,
    deadline: Option<Instant>,
    stream: Stream<'_>,
    adjust: Adjust<'_>,
) -> Result<GenericOutcome, GenericError> {
    let (scene_name, mesh_name) = (scene.file.display().to_string(), scene.mesh_path().display().to_string());
    let contact_error =
        |source| GenericError::Contact { scene: scene_name.clone(), mesh: mesh_name.clone(), source: Box::new(source) };
    // The key belongs to the Boussinesq algorithm; another one solves the mesh as generated (and
    // the summary's notes say so).
    if scene.solver.place_zone_ends == Some(true)
        && scene.solver.algorithm == contact2d_contact::ContactAlgorithm::Boussinesq
    {
        return solve_placed_scene(scene, mesh, clock, stream).map_err(contact_error);
    }
    let read = clock.elapsed().as_secs_f64();
    let points = scene.resolve_points(&mesh)?;
    let groups = group_reports(scene, &mesh).map_err(contact_error)?;
    let activity = scene.fix_stages()?;
    // Staged supports: one problem per stage, the first's the run's problem as built; else the
    // scene's one problem, built as it always was (no stage).
    let description = scene.description(mesh)?;
    let mut stages: Vec<Stage> = vec![];
    let mut built = if activity.len() > 1 {
        stages = description.build_stages(&activity).map_err(contact_error)?;
        for stage in &mut stages {
            adjust(&mut stage.built).map_err(contact_error)?;
        }
        stages
            .first()
            .map(|s| s.built.clone())
            .ok_or_else(|| contact_error(ContactError::InvalidInput("no stage".into())))?
    } else {
        description.build().map_err(contact_error)?
    };
    if stages.is_empty() {
        adjust(&mut built).map_err(contact_error)?;
    }
    // Set-up time: the one problem's, or every stage's.
    let build_times: Vec<_> = if stages.is_empty() {
        vec![built.problem.build_times]
    } else {
        stages.iter().map(|s| s.built.problem.build_times).collect()
    };
    let schedule = scene.schedule()?;
    let settings = scene.settings()?;
    let settings = match deadline {
        Some(d) => settings.with_deadline(d),
        None => settings,
    };
    // Finite sliding forms the pairs on the current configuration.
    let finite: Vec<bool> = scene.contact.iter().map(|c| c.sliding == scene::SlidingKey::Finite).collect();
    let total = schedule.steps().len();
    let fixed = fixed_groups(scene);
    // Adaptive stepping: the path the user's steps take (the user's own without it).
    let user_run = Run { built: &built, stages: &stages, finite: &finite, settings: &settings, schedule: &schedule };
    let plan = plan_path(scene, &user_run, &fixed).map_err(contact_error)?;
    let path = plan.path;
    // The stages cover the path's steps (each stage's problem copied only where the path differs).
    let refined = path.ends.len() != path.schedule.steps().len();
    let stages = if refined { path.stages(&stages) } else { stages };
    let schedule = path.schedule.clone();
    // Each step's summary row is made as the step is solved; of the steps before, the rows
    // keep only what the next step needs.
    let mut rows = SummaryRows::new(&built, &fixed, scene.every_profile).about(scene.moment_centre).with_points(points);
    // Finite sliding forms the pairs on the current configuration: the small-sliding check
    // (displacements against the undeformed pairs' segments) does not apply to the run.
    if scene.linearised_displacements || finite.iter().any(|f| *f) {
        rows = rows.without_sliding_check();
    }
    if finite.iter().any(|f| *f) {
        rows = rows.with_repairings();
    }
    if let Some(cycle) = scene.last_cycle() {
        let references: Vec<Option<[String; 2]>> = scene.contact.iter().map(|c| c.reference_groups.clone()).collect();
        let cycle = path.steps_of(&cycle);
        rows = rows.with_fretting(fretting::FrettingWatch::new(&built, cycle, &references).map_err(contact_error)?);
    }
    let (mut failed, mut solve_time, mut post_time) = (None, 0.0, 0.0);
    let Stream { retention, on_step, on_solved } = stream;
    let mut observe = |i: usize, step: &SolvedStep, current: &BuiltProblem| {
        let post_clock = Instant::now();
        solve_time += step.solution.time.as_secs_f64();
        if failed.is_none()
            && let Err(e) = rows.push_on(current, step)
        {
            failed = Some(e);
        }
        // The outputs see the user's steps only (every step of the path feeds the rows: the
        // work and the dissipation add up over it).
        let (user, ends) = adaptive::user_step_of(&path.ends, i);
        if ends {
            on_solved(current, user, step);
            on_step(user + 1, total);
        }
        post_time += post_clock.elapsed().as_secs_f64();
    };
    let run = Run { built: &built, stages: &stages, finite: &finite, settings: &settings, schedule: &schedule };
    let (mut history, last_built) = solve_run(&run, retention, &mut observe).map_err(contact_error)?;
    if retention == Retention::All && history.steps.len() > 1 {
        // The user's steps only (a last one that stopped early kept): the steps of the JSON.
        let last = history.steps.len() - 1;
        let kept = std::mem::take(&mut history.steps).into_iter().enumerate();
        history.steps =
            kept.filter(|(j, _)| *j == last || adaptive::user_step_of(&path.ends, *j).1).map(|(_, s)| s).collect();
    }
    if let Some(e) = failed {
        return Err(contact_error(e));
    }
    let Some(last) = history.steps.last() else {
        return Err(contact_error(ContactError::InvalidInput("no load step solved".into())));
    };
    let times = Times {
        read,
        assemble: build_times.iter().map(|t| t.assemble.as_secs_f64()).sum(),
        factor: build_times.iter().map(|t| t.factor.as_secs_f64()).sum(),
        condense: history.condense_time.as_secs_f64(),
        solve: solve_time,
        post: post_time,
        total: 0.0,
    };
    if let Some(final_built) = &last_built {
        rows.rebase(final_built);
    }
    let summarised = last_built.as_ref().unwrap_or(&built);
    let input = SummaryInput {
        scene,
        built: summarised,
        initial: &built,
        last,
        groups,
        scaled: history.scaled,
        total_steps: schedule.steps().len(),
        times,
        clock,
    };
    let mut report = summarise(input, rows).map_err(contact_error)?;
    estimate_path_error(scene, &run, &fixed, plan.errors, &mut report);
    keep_user_steps(&path, plan.note, &mut report);
    report.time_s.total = clock.elapsed().as_secs_f64();
    let built = last_built.unwrap_or(built);
    Ok(GenericOutcome { scene: scene.clone(), built, history, report })
}

/// [`solve_generic_from`] by the Boussinesq algorithm with placed zone ends
/// ([`placed::solve_placed`]): every step's problem is its own adjusted mesh's; the history
/// keeps the last step (or every step, as `stream` asks).
fn solve_placed_scene(
    scene: &GenericScene,
    mesh: contact2d_mesh::Mesh,
    clock: Instant,
    stream: Stream<'_>,
) -> Result<GenericOutcome, ContactError> {
    let Stream { retention, on_step, on_solved } = stream;
    let (mut report, steps) = placed::solve_placed(scene, mesh, clock, on_step)?;
    for (i, (built, step)) in steps.iter().enumerate() {
        on_solved(built, i, step);
    }
    let keep = if retention == Retention::Last { steps.len().saturating_sub(1) } else { 0 };
    let built = steps.last().map(|(b, _)| b.clone());
    let kept: Vec<SolvedStep> = steps.into_iter().skip(keep).map(|(_, s)| s).collect();
    let Some(built) = built else {
        return Err(ContactError::InvalidInput("no load step solved".into()));
    };
    report.time_s.total = clock.elapsed().as_secs_f64();
    let history = History { steps: kept, scaled: false, condense_time: std::time::Duration::ZERO };
    Ok(GenericOutcome { scene: scene.clone(), built, history, report })
}

/// The groups of the scene's `[[fix]]` entries, each with the components any of its entries
/// prescribes, and, for a group of staged fixes, those its active entries prescribe step by
/// step.
pub(crate) fn fixed_groups(scene: &GenericScene) -> Vec<FixedGroup> {
    let steps = scene.schedule().map_or(0, |s| s.steps().len());
    let mut out: Vec<FixedGroup> = vec![];
    for f in &scene.fix {
        let Some(name) = &f.group else { continue };
        // A rotation prescribes both components, and so does un / ut (its reaction `r = T r'`
        // has both global components).
        let turned = f.rotation.is_some() || f.un.is_some() || f.ut.is_some();
        let components = [f.u1.is_some() || turned, f.u2.is_some() || turned];
        let group = match out.iter().position(|g| g.name == *name) {
            Some(at) => &mut out[at],
            None => {
                out.push(FixedGroup { name: name.clone(), components: [false; 2], components_by_step: None });
                let last = out.len() - 1;
                &mut out[last]
            }
        };
        group.components = [group.components[0] || components[0], group.components[1] || components[1]];
        if f.from_step.is_some() || f.until_step.is_some() {
            group.components_by_step.get_or_insert_with(|| vec![[false; 2]; steps]);
        }
    }
    // The components by step of the staged groups: those of their entries active in the step
    // (a staged entry is never a rotation: the scene refuses it).
    for group in &mut out {
        let Some(by_step) = group.components_by_step.as_mut() else { continue };
        for f in scene.fix.iter().filter(|f| f.group.as_deref() == Some(group.name.as_str())) {
            let turned = f.rotation.is_some() || f.un.is_some() || f.ut.is_some();
            let (from, until) = (f.from_step.unwrap_or(1), f.until_step.unwrap_or(steps));
            for c in by_step.iter_mut().take(until).skip(from.saturating_sub(1)) {
                *c = [c[0] || f.u1.is_some() || turned, c[1] || f.u2.is_some() || turned];
            }
        }
    }
    out
}

fn unique(items: impl Iterator<Item = String>) -> Vec<String> {
    let mut out: Vec<String> = vec![];
    for i in items {
        if !out.contains(&i) {
            out.push(i);
        }
    }
    out
}

/// The length and bounding box of every group the scene names.
pub(crate) fn group_reports(
    scene: &GenericScene,
    mesh: &contact2d_mesh::Mesh,
) -> Result<BTreeMap<String, GroupReport>, ContactError> {
    let names = scene
        .body
        .iter()
        .map(|b| b.region.clone())
        .chain(scene.fix.iter().filter_map(|f| f.group.clone()))
        .chain(scene.load.iter().filter_map(|l| l.group.clone()))
        .chain(scene.point.iter().filter_map(|p| p.group.clone()))
        .chain(scene.contact.iter().flat_map(|c| [c.master.clone(), c.slave.clone()]))
        .chain(scene.contact.iter().flat_map(|c| c.reference_groups.clone().into_iter().flatten()));
    let mut out = BTreeMap::new();
    for name in unique(names) {
        let group = mesh.group(&name)?;
        let nodes = mesh.group_nodes(&name)?;
        let points: Vec<[f64; 2]> = nodes.iter().map(|n| mesh.points[n.0]).collect();
        let bbox = bounding_box(points.iter());
        let length = if group.dim == 1 { group_length(mesh, &name)? } else { 0.0 };
        out.insert(name, GroupReport { dim: group.dim, length, bbox });
    }
    Ok(out)
}

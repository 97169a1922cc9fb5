//! Running a plate-insert scene: its `[plate_insert]` section expands into a generic scene
//! ([`crate::plate_insert::PlateInsert::generic_scene`]) solved by the one generic run with the
//! paper's gaps set; the paper's own loops (steps in the contact end, placed zone ends) solve
//! theirs and their steps are summarised the same way. The paper's quantities join the one
//! summary as its `paper` block ([`crate::plate_insert::report`]).

use std::sync::Arc;
use web_time::Instant;

use contact2d_contact::{
    BoussinesqLoading, ContactAlgorithm, ContactError, ContactSolution, HistoryStep, Interface, SolvedStep,
    equal_steps, solve_boussinesq_history,
};

use crate::generic::{GenericError, GenericReport, GenericScene, SummaryInput, SummaryRows, Times, summarise};
use crate::plate_insert::PlateInsertScene;
use crate::plate_insert::report::{BLOCK, PaperReport, PaperStep, paper_report};
use crate::plate_insert::{PlacedLoading, PlacedStep, PlateInsertProblem, ZoneEndSearch, solve_placed_history};

/// A solved scene: the summary plus everything the outputs (figures, CSV, VTU) need.
#[derive(Debug, Clone)]
pub struct RunOutcome {
    /// The summary (the `--json` object): the generic one, with the paper's quantities under
    /// `paper`.
    pub report: GenericReport,
    /// The paper's quantities (the summary's `paper` block).
    pub paper: PaperReport,
    /// The solved steps in load order (one for a single or scaled solve).
    pub steps: Vec<PaperStep>,
}

/// Solves a scene: its summary plus the solved steps.
///
/// Without gap the solution is linear in w, with or without friction (spec §5.2: the zones form
/// at the first instant and never change): it is solved once at w = 1 and scaled. Otherwise the
/// load goes up in `steps` equal steps with the chosen algorithm, the slips carried over.
///
/// # Errors
/// Problem set-up failures.
pub fn solve_scene(scene: &PlateInsertScene) -> Result<RunOutcome, ContactError> {
    solve_scene_with(scene, &mut Silent)
}

pub use crate::generic::{Progress, Silent};

/// [`solve_scene`] reporting each solved step to `progress`.
///
/// # Errors
/// Problem set-up failures.
pub fn solve_scene_with(scene: &PlateInsertScene, progress: &mut dyn Progress) -> Result<RunOutcome, ContactError> {
    solve_scene_from(scene, None, progress)
}

/// [`solve_scene_with`] on a mesh already read instead of the scene's mesh file (which is
/// neither checked nor read): for callers without files, such as the WebAssembly build of the
/// teaching page, which parses bundled meshes with [`contact2d_mesh::parse_msh`]. Same numbers
/// as [`solve_scene`] on the file the mesh came from.
///
/// # Errors
/// Problem set-up failures, and the Boussinesq algorithm with placed zone ends (its search
/// re-reads the mesh file).
pub fn solve_scene_on_mesh(
    scene: &PlateInsertScene,
    mesh: contact2d_mesh::Mesh,
    progress: &mut dyn Progress,
) -> Result<RunOutcome, ContactError> {
    solve_scene_from(scene, Some(mesh), progress)
}

/// The run of [`solve_scene_with`] on the scene's mesh file (`mesh` = `None`) or on `mesh`.
fn solve_scene_from(
    scene: &PlateInsertScene,
    mesh: Option<contact2d_mesh::Mesh>,
    progress: &mut dyn Progress,
) -> Result<RunOutcome, ContactError> {
    let start = Instant::now();
    let p = &scene.plate_insert;
    if !p.load.is_finite() || p.load < 0.0 {
        return Err(ContactError::InvalidInput(format!("load w = {} must be finite and non-negative", p.load)));
    }
    if !p.l_steps.is_empty() && scene.solver.algorithm != ContactAlgorithm::Boussinesq {
        return Err(ContactError::InvalidInput("l_steps needs the boussinesq algorithm".into()));
    }
    if p.steps == 0 {
        return Err(ContactError::InvalidInput("steps must be at least 1".into()));
    }
    let placed = scene.solver.places_zone_ends();
    if mesh.is_none() {
        scene.check_mesh_file().map_err(|e| ContactError::InvalidInput(e.to_string()))?;
        check_history_memory(scene)?;
    } else if placed {
        return Err(ContactError::InvalidInput(
            "the boussinesq algorithm with placed zone ends reads the mesh file; set solver.place_zone_ends = false"
                .into(),
        ));
    }
    // Without clearance every gap is zero (both gap models scale with c), so the solution is
    // linear in w (spec §5.2): the library's solve finds the proportional loads and solves once;
    // the placed zone ends do the same here, at w = 1, scaled after.
    let scaled = p.clearance == 0.0 && p.l_steps.is_empty();
    let loads = equal_steps(p.load, p.steps);
    let total = if p.l_steps.is_empty() { loads.len() } else { p.l_steps.len() };
    let mut done = 0;
    let mut report_step = |w: f64| {
        done += 1;
        progress.step_done(done, total, w);
    };
    let case = scene.plate_insert();
    let mut expanded = case.generic_scene(&scene.name, &loads, &scene.solver);
    expanded.file = scene.file.clone();
    expanded.every_profile = scene.every_profile;
    expanded.moment_centre = scene.moment_centre;
    let w = p.l_steps.is_empty().then_some(p.load);
    if placed {
        let (unit, scale) = if scaled { (vec![1.0], p.load) } else { (loads, 1.0) };
        let loadings: Vec<PlacedLoading> = if p.l_steps.is_empty() {
            unit.iter().map(|w| PlacedLoading::Load(*w)).collect()
        } else {
            p.l_steps.iter().map(|l| PlacedLoading::ContactEnd(*l)).collect()
        };
        let placed =
            solve_placed_history(&case, &loadings, ZoneEndSearch::default(), &mut |s| report_step(s.load * scale))?;
        let notes: Vec<String> = placed
            .iter()
            .enumerate()
            .filter_map(|(i, (step, _))| step.placement_failure.as_ref().map(|why| (i, why)))
            .map(|(i, why)| {
                format!(
                    "step {}: zone ends not placed ({why}); solved on the generated mesh, l and b interpolated",
                    i + 1
                )
            })
            .collect();
        let steps = placed_steps(placed, scale)?;
        let mut outcome = outcome_of_steps(&expanded, steps, scaled, w, p.friction, start)?;
        outcome.report.notes.extend(notes);
        return Ok(outcome);
    }
    let mesh = match mesh {
        Some(mesh) => mesh,
        None => contact2d_mesh::read_msh(scene.mesh_path())?,
    };
    if !p.l_steps.is_empty() {
        let case = Arc::new(case.build_on(mesh)?);
        let history = contact_end_steps(&case, &p.l_steps, scene.solver.max_iterations, &mut report_step)?;
        let steps = history
            .into_iter()
            .map(|step| paper_step(&case, step.solution, step.dissipated))
            .collect::<Result<Vec<_>, _>>()?;
        return outcome_of_steps(&expanded, steps, false, w, p.friction, start);
    }
    // The one generic run of the expanded scene, the paper's gaps set on its pairs.
    let adjust = |built: &mut contact2d_contact::BuiltProblem| case.set_gaps(built);
    let mut on_step = |done: usize, _total: usize| report_step(loads[done - 1]);
    let generic = crate::generic::solve_preset(&expanded, mesh, start, scene.deadline, &adjust, &mut on_step)
        .map_err(contact_error)?;
    let this = Arc::new(case.case_of(generic.built)?);
    let steps = generic
        .history
        .steps
        .into_iter()
        .map(|step| {
            let mut solution = step.solution;
            solution.load_factor = step.factors[0];
            paper_step(&this, solution, step.dissipated)
        })
        .collect::<Result<Vec<_>, _>>()?;
    with_paper_block(generic.report, steps, w, p.friction, start)
}

/// The contact error inside a generic run's error (the caller names the scene and mesh).
fn contact_error(e: GenericError) -> ContactError {
    match e {
        GenericError::Contact { source, .. } => *source,
        GenericError::Mesh { source, .. } => ContactError::from(source),
        other => ContactError::InvalidInput(other.to_string()),
    }
}

/// A solved step of `case` with its paper quantities.
fn paper_step(
    case: &Arc<PlateInsertProblem>,
    solution: ContactSolution,
    dissipated: f64,
) -> Result<PaperStep, ContactError> {
    Ok(PaperStep { results: case.results(&solution)?, case: Arc::clone(case), solution, dissipated })
}

/// The outcome of a run whose generic summary is made: its `paper` block added.
fn with_paper_block(
    mut report: GenericReport,
    steps: Vec<PaperStep>,
    w: Option<f64>,
    mu: f64,
    start: Instant,
) -> Result<RunOutcome, ContactError> {
    let post = Instant::now();
    let paper = paper_report(&steps, w, mu)?;
    let block = serde_json::to_value(&paper).map_err(|e| ContactError::InvalidInput(e.to_string()))?;
    report.post.insert(BLOCK.into(), block);
    report.time_s.post += post.elapsed().as_secs_f64();
    report.time_s.total = start.elapsed().as_secs_f64();
    Ok(RunOutcome { report, paper, steps })
}

/// The outcome of steps the paper's own loops solved (in the contact end, or with placed zone
/// ends, each step on its own problem): the generic summary made of them as the one generic run
/// makes it, and the `paper` block.
fn outcome_of_steps(
    expanded: &GenericScene,
    steps: Vec<PaperStep>,
    scaled: bool,
    w: Option<f64>,
    mu: f64,
    start: Instant,
) -> Result<RunOutcome, ContactError> {
    let fixed = crate::generic::fixed_groups(expanded);
    let solved: Vec<SolvedStep> = steps
        .iter()
        .map(|s| SolvedStep {
            factors: vec![s.solution.load_factor],
            solution: s.solution.clone(),
            dissipated: s.dissipated,
            floating_iterations: 0,
            floating_residual: 0.0,
            repairings: 0,
            unstable_pairing: None,
            not_held: None,
        })
        .collect();
    let (Some(first), Some(last), Some(last_step)) = (steps.first(), steps.last(), solved.last()) else {
        return Err(ContactError::InvalidInput("no load step".into()));
    };
    let mut rows = SummaryRows::new(&first.case.built, &fixed, expanded.every_profile)
        .without_sliding_check()
        .about(expanded.moment_centre);
    for (step, solved) in steps.iter().zip(&solved) {
        rows.push(&step.case.built, solved)?;
    }
    let built = &last.case.built;
    let times = Times {
        assemble: built.problem.build_times.assemble.as_secs_f64(),
        factor: built.problem.build_times.factor.as_secs_f64(),
        solve: steps.iter().map(|s| s.solution.time.as_secs_f64()).sum(),
        ..Times::default()
    };
    let groups = crate::generic::group_reports(expanded, &built.problem.model.mesh)?;
    let total_steps = steps.len();
    let input = SummaryInput {
        scene: expanded,
        built,
        initial: built,
        last: last_step,
        groups,
        scaled,
        total_steps,
        times,
        clock: start,
    };
    let report = summarise(input, rows)?;
    with_paper_block(report, steps, w, mu, start)
}

/// The memory a loading history may take, bytes (checked before solving).
pub const MAX_HISTORY_BYTES: u64 = 4 << 30;

/// Bytes of memory per step of a Boussinesq history with placed zone ends, per byte of the mesh
/// file: each step keeps its own mesh, model and pairs. Measured 1.6 MB per step on the N = 16
/// mesh (47.6 kB), i.e. 35 bytes per byte, rounded up.
pub const PLACED_STEP_BYTES_PER_MESH_BYTE: u64 = 40;

/// Refuses a Boussinesq history with placed zone ends whose steps would together exceed
/// [`MAX_HISTORY_BYTES`] (estimated from the mesh file's size); the other algorithms keep one
/// solution vector per step, which [`crate::schema::limits::MAX_STEPS`] bounds.
fn check_history_memory(scene: &PlateInsertScene) -> Result<(), ContactError> {
    let p = &scene.plate_insert;
    if !scene.solver.places_zone_ends() {
        return Ok(());
    }
    let steps = if p.l_steps.is_empty() { p.steps } else { p.l_steps.len() } as u64;
    let mesh_bytes = std::fs::metadata(scene.mesh_path()).map_or(0, |m| m.len());
    let estimate = steps.saturating_mul(mesh_bytes).saturating_mul(PLACED_STEP_BYTES_PER_MESH_BYTE);
    if estimate > MAX_HISTORY_BYTES {
        let per_step = (mesh_bytes * PLACED_STEP_BYTES_PER_MESH_BYTE).max(1);
        return Err(ContactError::InvalidInput(format!(
            "{steps} steps of the Boussinesq algorithm with placed zone ends on this mesh would need about {} MB \
             (each step keeps its own mesh); the limit of {} MB allows {} steps here (or set \
             solver.place_zone_ends = false, or use a coarser mesh)",
            estimate >> 20,
            MAX_HISTORY_BYTES >> 20,
            MAX_HISTORY_BYTES / per_step
        )));
    }
    Ok(())
}

/// Solved steps from a history with placed zone ends; `scale` multiplies a solution that is
/// linear in the load (no gap: solved at w = 1), 1 otherwise. l and b are the placed nodes'
/// positions (exact, not interpolated).
fn placed_steps(placed: Vec<(PlacedStep, f64)>, scale: f64) -> Result<Vec<PaperStep>, ContactError> {
    placed
        .into_iter()
        .map(|(step, dissipated)| {
            let mut solution = step.step.solution;
            if scale != 1.0 {
                scale_solution(&mut solution, scale);
            }
            let case = Arc::new(step.case);
            let mut results = case.results(&solution)?;
            if !step.contact_end_placed {
                // The search failed and the step was solved on the generated mesh: the
                // interpolated zone ends of `results` stand.
                return Ok(PaperStep { case, solution, results, dissipated: dissipated * scale * scale });
            }
            results.contact_end = Some(step.contact_end_reported);
            results.contact_bracket = Some([step.contact_end_reported; 2]);
            results.contact_end_master = Some(step.contact_end);
            results.stick_end = Some(step.stick_end_reported);
            if step.stick_end_placed || step.stick_end == step.contact_end {
                results.stick_bracket = Some([step.stick_end_reported; 2]);
            }
            Ok(PaperStep { case, solution, results, dissipated: dissipated * scale * scale })
        })
        .collect()
}

/// The Boussinesq algorithm stepping in the contact end (`l_steps`, the paper's loading): each
/// l is resolved to the pair nearest to it in the zone's order along the master (η ascending),
/// and each step's load w follows from it.
///
/// # Errors
/// Those of [`solve_boussinesq_history`].
fn contact_end_steps(
    case: &PlateInsertProblem,
    l_steps: &[f64],
    max_iterations: usize,
    report_step: &mut dyn FnMut(f64),
) -> Result<Vec<HistoryStep>, ContactError> {
    let problem = &case.problem;
    let interface = Interface::new(problem);
    let eta = case.eta_master();
    let mut order: Vec<usize> = (0..eta.len()).collect();
    order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
    let loadings: Vec<BoussinesqLoading> =
        l_steps.iter().map(|l| BoussinesqLoading::ContactEnd(nearest_position(&order, &eta, *l))).collect();
    // The contact-end search of a given load moves one pair per iteration.
    let history =
        solve_boussinesq_history(problem, &interface, &order, &loadings, max_iterations.max(2 * order.len()))?;
    history.iter().for_each(|s| report_step(s.solution.load_factor));
    Ok(history)
}

/// The position in `order` of the pair whose η is nearest to `l`.
fn nearest_position(order: &[usize], eta: &[f64], l: f64) -> usize {
    order
        .iter()
        .enumerate()
        .min_by(|a, b| (eta[*a.1] - l).abs().total_cmp(&(eta[*b.1] - l).abs()))
        .map_or(0, |(pos, _)| pos)
}

/// Scales a solution of a problem that is linear in the load (no gap), solved at w = 1, to the
/// load w ([`contact2d_contact::solve::scale_solution`] of one step from the unloaded state).
fn scale_solution(s: &mut ContactSolution, w: f64) {
    contact2d_contact::solve::scale_solution(s, w, 0.0);
    s.load_factor = w;
}

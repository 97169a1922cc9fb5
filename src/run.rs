//! Running a scene: build the problem, solve with the chosen algorithm over the load history,
//! report the paper's quantities.

use std::sync::Arc;
use web_time::Instant;

use serde::Serialize;

use contact2d_contact::{
    BoussinesqLoading, ContactAlgorithm, ContactError, ContactSolution, ContactStatus, HistoryStep, Interface,
    check_energy_balance, energy_scale, equal_steps, solve_boussinesq_history, status_reason,
};

use crate::plate_insert::{
    PlacedLoading, PlacedStep, PlateInsertProblem, PlateInsertResults, ZoneEndSearch, solve_placed_history,
};
use crate::scene::Scene;

/// A solved scene: the JSON summary plus everything the outputs (figures, CSV, VTU) need.
#[derive(Debug, Clone)]
pub struct RunOutcome {
    /// The summary (the `--json` object).
    pub report: RunReport,
    /// The solved steps in load order (one for a single or scaled solve).
    pub steps: Vec<SolvedStep>,
}

/// One solved load step with the discrete problem it was solved on.
#[derive(Debug, Clone)]
pub struct SolvedStep {
    /// The problem (mesh, model, pairs) of this step; steps on the same mesh share it.
    pub case: Arc<PlateInsertProblem>,
    /// The step's contact solution (displacements in the case's global DOF order).
    pub solution: ContactSolution,
    /// The paper's quantities of this step.
    pub results: PlateInsertResults,
    /// Φ_f accumulated up to and including this step.
    pub dissipated: f64,
}

/// KKT residuals as reported in JSON.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct KktReport {
    /// max(−gap, 0).
    pub max_penetration: f64,
    /// max |λ gap|.
    pub max_complementarity: f64,
    /// max(|τ| − μλ, 0).
    pub max_cone_violation: f64,
    /// Smallest dissipation τ·Δslip over slipping pairs (0 without friction).
    pub min_dissipation: f64,
    /// Friction complementarity (dimensionless): a pair inside the cone that slips.
    pub max_slip_inside_cone: f64,
}

/// The summary of one run (the `--json` object).
#[allow(non_snake_case)]
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunReport {
    /// Scene name.
    pub scene: String,
    /// Contact end on the hole-edge angle η = 1 − φ/π.
    pub l: Option<f64>,
    /// The mesh bracket of l.
    pub l_bracket: Option<[f64; 2]>,
    /// Contact end on the master's own coordinate.
    pub l_master: Option<f64>,
    /// End of the stick zone (equal to l when nothing slips).
    pub b: Option<f64>,
    /// The mesh bracket of b.
    pub b_bracket: Option<[f64; 2]>,
    /// Pulling force.
    pub P: f64,
    /// Strain energy of the plate.
    pub Phi_E1: f64,
    /// Strain energy of the insert.
    pub Phi_E2: f64,
    /// Dissipated energy.
    pub Phi_f: f64,
    /// Work of the pulling force, ∫ P dw (trapezoid over the steps; P w / 2 for one
    /// proportional step).
    pub W: f64,
    /// Largest hoop stress on the hole edge.
    pub sigma_star: f64,
    /// K = H σ* / P.
    pub K: f64,
    /// Largest hoop stress of the insert on its edge (`None` for a rigid insert).
    pub insert_hoop_max: Option<f64>,
    /// Load w.
    pub w: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Free DOFs.
    pub dofs: usize,
    /// Contact pairs.
    pub pairs: usize,
    /// Algorithm (its scene key).
    #[serde(serialize_with = "crate::scene::serialize_algorithm")]
    pub algorithm: ContactAlgorithm,
    /// Outcome: the first step's that did not converge, else `converged`; `numerical` also
    /// when a step's answer fails [`contact2d_contact::certify()`] or the history's energy
    /// balance `W = Φ_E1 + Φ_E2 + Φ_f` fails [`contact2d_contact::check_energy_balance`].
    pub status: String,
    /// Why the status is `numerical`: the check that failed, with its value and tolerance
    /// (e.g. "step 1: complementarity … = 2.1e-3 exceeds 1e-4"); `null` when the status is
    /// not `numerical` or the algorithm itself broke down without a residual to report.
    pub failed_check: Option<String>,
    /// Iterations of the algorithm, summed over the steps.
    pub iterations: usize,
    /// KKT residuals (of the last step; the dissipation minimum over all steps).
    pub kkt: KktReport,
    /// The load history, one entry per step.
    pub steps: Vec<StepReport>,
    /// Wall time of the whole run (mesh reading to quantities), seconds.
    pub time_s: f64,
    /// Wall time of the contact algorithm alone, seconds.
    pub solve_time_s: f64,
    /// Inequalities of (5.1) a step violates (status `inadmissible`); empty when admissible.
    pub violations: Vec<ViolationReport>,
    /// What a user should know about how the numbers were obtained (e.g. a step whose zone ends
    /// could not be placed).
    pub notes: Vec<String>,
}

/// A violated contact inequality in the JSON output.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ViolationReport {
    /// The step (from 1).
    pub step: usize,
    /// The pair's index.
    pub pair: usize,
    /// η = 1 − φ/π of the pair on the hole edge.
    pub eta: f64,
    /// The condition that fails.
    pub condition: String,
}

/// One step of a history in the JSON output.
#[allow(non_snake_case)]
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepReport {
    /// Load w at the end of the step.
    pub w: f64,
    /// Contact end.
    pub l: Option<f64>,
    /// Stick end.
    pub b: Option<f64>,
    /// Pulling force.
    pub P: f64,
    /// Plate strain energy.
    pub Phi_E1: f64,
    /// Insert strain energy.
    pub Phi_E2: f64,
    /// Dissipation accumulated up to this step.
    pub Phi_f: f64,
    /// Work of the pulling force accumulated up to this step (trapezoid in w).
    pub W: f64,
}

/// Runs a scene and returns its summary (see [`solve_scene`] for what it does).
///
/// # Errors
/// Problem set-up failures.
pub fn run_scene(scene: &Scene) -> Result<RunReport, ContactError> {
    solve_scene(scene).map(|outcome| outcome.report)
}

/// Solves a scene: its summary plus the solved steps.
///
/// Without gap the solution is linear in w, with or without friction (spec §5.2: the zones form
/// at the first instant and never change): it is solved once at w = 1 and scaled. Otherwise the
/// load goes up in `steps` equal steps with the chosen algorithm, the slips carried over.
///
/// # Errors
/// Problem set-up failures.
pub fn solve_scene(scene: &Scene) -> Result<RunOutcome, ContactError> {
    solve_scene_with(scene, &mut Silent)
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

/// [`solve_scene`] reporting each solved step to `progress`.
///
/// # Errors
/// Problem set-up failures.
pub fn solve_scene_with(scene: &Scene, progress: &mut dyn Progress) -> Result<RunOutcome, ContactError> {
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
    scene: &Scene,
    mesh: contact2d_mesh::Mesh,
    progress: &mut dyn Progress,
) -> Result<RunOutcome, ContactError> {
    solve_scene_from(scene, Some(mesh), progress)
}

/// The run of [`solve_scene_with`] on the scene's mesh file (`mesh` = `None`) or on `mesh`.
fn solve_scene_from(
    scene: &Scene,
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
    if placed {
        let (unit, scale) = if scaled { (vec![1.0], p.load) } else { (loads, 1.0) };
        let loadings: Vec<PlacedLoading> = if p.l_steps.is_empty() {
            unit.iter().map(|w| PlacedLoading::Load(*w)).collect()
        } else {
            p.l_steps.iter().map(|l| PlacedLoading::ContactEnd(*l)).collect()
        };
        let placed = solve_placed_history(&scene.plate_insert(), &loadings, ZoneEndSearch::default(), &mut |s| {
            report_step(s.load * scale)
        })?;
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
        let mut report = finite(summarise(scene, &steps, start)?)?;
        report.notes.extend(notes);
        return Ok(RunOutcome { report, steps });
    }
    let case = Arc::new(match mesh {
        Some(mesh) => scene.plate_insert().build_on(mesh)?,
        None => scene.plate_insert().build()?,
    });
    let history = if p.l_steps.is_empty() {
        let settings = scene.settings().map_err(|e| ContactError::InvalidInput(e.to_string()))?;
        case.solve_loads(&settings, &loads, &mut report_step)?
    } else {
        contact_end_steps(&case, &p.l_steps, scene.solver.max_iterations, &mut report_step)?
    };
    let steps = history
        .into_iter()
        .map(|step| {
            Ok(SolvedStep {
                results: case.results(&step.solution)?,
                case: Arc::clone(&case),
                solution: step.solution,
                dissipated: step.dissipated,
            })
        })
        .collect::<Result<Vec<_>, ContactError>>()?;
    let report = finite(summarise(scene, &steps, start)?)?;
    Ok(RunOutcome { report, steps })
}

/// The report if every number in it is finite; a non-finite one (an overflow the input limits
/// did not foresee) is an error, so that no NaN is written as the JSON `null` that means "none".
fn finite(report: RunReport) -> Result<RunReport, ContactError> {
    let r = &report;
    let optional = [r.l, r.l_master, r.b, r.insert_hoop_max].into_iter().flatten();
    let brackets = [r.l_bracket, r.b_bracket].into_iter().flatten().flatten();
    let numbers = [r.P, r.Phi_E1, r.Phi_E2, r.Phi_f, r.W, r.sigma_star, r.K, r.w, r.mu];
    let steps =
        r.steps.iter().flat_map(|s| [s.w, s.P, s.Phi_E1, s.Phi_E2, s.Phi_f, s.W].into_iter().chain(s.l).chain(s.b));
    let k = &r.kkt;
    let kkt =
        [k.max_penetration, k.max_complementarity, k.max_cone_violation, k.max_slip_inside_cone, k.min_dissipation];
    match numbers.into_iter().chain(optional).chain(brackets).chain(steps).chain(kkt).find(|v| !v.is_finite()) {
        Some(v) => Err(ContactError::NotFinite(format!("a reported quantity is {v}"))),
        None => Ok(report),
    }
}

/// The memory a loading history may take, bytes (checked before solving).
pub const MAX_HISTORY_BYTES: u64 = 4 << 30;

/// Bytes of memory per step of a Boussinesq history with placed zone ends, per byte of the mesh
/// file: each step keeps its own mesh, model and pairs. Measured 1.6 MB per step on the N = 16
/// mesh (47.6 kB), i.e. 35 bytes per byte, rounded up.
pub const PLACED_STEP_BYTES_PER_MESH_BYTE: u64 = 40;

/// Refuses a Boussinesq history with placed zone ends whose steps would together exceed
/// [`MAX_HISTORY_BYTES`] (estimated from the mesh file's size); the other algorithms keep one
/// solution vector per step, which [`crate::scene::MAX_STEPS`] bounds.
fn check_history_memory(scene: &Scene) -> Result<(), ContactError> {
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
fn placed_steps(placed: Vec<(PlacedStep, f64)>, scale: f64) -> Result<Vec<SolvedStep>, ContactError> {
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
                return Ok(SolvedStep { case, solution, results, dissipated: dissipated * scale * scale });
            }
            results.contact_end = Some(step.contact_end_hole);
            results.contact_bracket = Some([step.contact_end_hole; 2]);
            results.contact_end_master = Some(step.contact_end);
            results.stick_end = Some(step.stick_end_hole);
            if step.stick_end_placed || step.stick_end == step.contact_end {
                results.stick_bracket = Some([step.stick_end_hole; 2]);
            }
            Ok(SolvedStep { case, solution, results, dissipated: dissipated * scale * scale })
        })
        .collect()
}

/// The summary of solved steps: the last step's quantities at the top level, the work W = ∫ P dw
/// by the trapezoid rule over the steps.
fn summarise(scene: &Scene, solved: &[SolvedStep], start: Instant) -> Result<RunReport, ContactError> {
    let p = &scene.plate_insert;
    let mut steps = Vec::with_capacity(solved.len());
    let (mut work, mut last_w, mut last_p) = (0.0, 0.0, 0.0);
    for step in solved {
        let q = &step.results;
        let w = step.solution.load_factor;
        work += 0.5 * (last_p + q.pull) * (w - last_w);
        (last_w, last_p) = (w, q.pull);
        steps.push(StepReport {
            w,
            l: q.contact_end,
            b: q.stick_end,
            P: q.pull,
            Phi_E1: q.energy_plate,
            Phi_E2: q.energy_insert,
            Phi_f: step.dissipated,
            W: work,
        });
    }
    let last = solved.last().ok_or_else(|| ContactError::InvalidInput("no load step".into()))?;
    let (solution, q, problem) = (&last.solution, &last.results, &last.case.problem);
    let (status, failed_check) = certified_status(scene, solved, &steps);
    Ok(RunReport {
        scene: scene.name.clone(),
        l: q.contact_end,
        l_bracket: q.contact_bracket,
        l_master: q.contact_end_master,
        b: q.stick_end,
        b_bracket: q.stick_bracket,
        P: q.pull,
        Phi_E1: q.energy_plate,
        Phi_E2: q.energy_insert,
        Phi_f: last.dissipated,
        W: work,
        sigma_star: q.sigma_star,
        K: q.stress_concentration,
        insert_hoop_max: q.insert_hoop_max,
        w: if p.l_steps.is_empty() { p.load } else { solution.load_factor },
        mu: p.friction,
        dofs: problem.system.dofs.num_free(),
        pairs: problem.num_pairs(),
        algorithm: scene.solver.algorithm,
        status: status_name(status).into(),
        failed_check,
        iterations: solved.iter().map(|s| s.solution.iterations).sum(),
        kkt: KktReport {
            max_penetration: solution.kkt.max_penetration,
            max_complementarity: solution.kkt.max_complementarity,
            max_cone_violation: solution.kkt.max_cone_violation,
            max_slip_inside_cone: solution.kkt.max_slip_inside_cone,
            min_dissipation: solved.iter().map(|s| s.solution.kkt.min_dissipation).fold(f64::INFINITY, f64::min),
        },
        steps,
        time_s: start.elapsed().as_secs_f64(),
        solve_time_s: solved.iter().map(|s| s.solution.time.as_secs_f64()).sum(),
        violations: violations(solved),
        notes: locking_notes(scene),
    })
}

/// The volumetric-locking warning of [`contact2d_element::locking_warning`] for the scene's
/// plane condition, ν and formulation (both bodies share them), as a run note.
fn locking_notes(scene: &Scene) -> Vec<String> {
    let p = scene.plate_insert();
    contact2d_element::locking_warning(p.plane, p.poissons_ratio, p.formulation).into_iter().collect()
}

/// The status of a history — as good as its worst step: the first step that did not converge,
/// or failed the energy balance — and, for `numerical`, the check that failed.
fn certified_status(scene: &Scene, solved: &[SolvedStep], steps: &[StepReport]) -> (ContactStatus, Option<String>) {
    let p = &scene.plate_insert;
    // One proportional step from the unloaded state (no gap: solved once and scaled) makes
    // W = P w / 2 exact; otherwise W is the trapezoid rule over the steps.
    let exact = p.clearance == 0.0 && p.l_steps.is_empty();
    let scale = energy_scale(steps.iter().map(|r| (r.W, r.Phi_E1 + r.Phi_E2, r.Phi_f)));
    for (i, (step, report)) in solved.iter().zip(steps).enumerate() {
        let status = step.solution.status;
        if status != ContactStatus::Converged {
            let why = status_reason(&step.case.problem, &step.solution).map(|f| format!("step {}: {f}", i + 1));
            return (status, why);
        }
        let balance = check_energy_balance(report.W, report.Phi_E1 + report.Phi_E2, report.Phi_f, exact, scale);
        if let Err(f) = balance {
            return (ContactStatus::Numerical, Some(format!("step {}: {f}", i + 1)));
        }
    }
    (solved.last().map_or(ContactStatus::Converged, |s| s.solution.status), None)
}

/// Every violated inequality of every step, with the pair's η on the hole edge.
fn violations(solved: &[SolvedStep]) -> Vec<ViolationReport> {
    let mut all = vec![];
    for (i, step) in solved.iter().enumerate() {
        if step.solution.violations.is_empty() {
            continue;
        }
        let eta = step.case.eta_hole();
        all.extend(step.solution.violations.iter().map(|v| ViolationReport {
            step: i + 1,
            pair: v.pair,
            eta: eta.get(v.pair).copied().unwrap_or(f64::NAN),
            condition: v.condition.to_string(),
        }));
    }
    all
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

fn status_name(status: ContactStatus) -> &'static str {
    match status {
        ContactStatus::Converged => "converged",
        ContactStatus::MaxIterations => "max_iterations",
        ContactStatus::Infeasible => "infeasible",
        ContactStatus::Numerical => "numerical",
        ContactStatus::Inadmissible => "inadmissible",
        ContactStatus::Penalised => "penalised",
    }
}

/// Scales a solution of a problem that is linear in the load (no gap), solved at w = 1, to the
/// load w ([`contact2d_contact::solve::scale_solution`] of one step from the unloaded state).
fn scale_solution(s: &mut ContactSolution, w: f64) {
    contact2d_contact::solve::scale_solution(s, w, 0.0);
    s.load_factor = w;
}

//! The summary of a solved history, the one JSON contract of every run: each step's row made as
//! the step is solved ([`SummaryRows`]), then the worst step's status, the last step's interfaces
//! with profiles, the notes, and the check that no number in it is non-finite ([`summarise`]).

use std::collections::BTreeMap;
use web_time::Instant;

use contact2d_contact::{BuiltProblem, ContactError, LinearSolver, SolvedStep, check_energy_balance, energy_scale};

use super::fretting::FrettingWatch;
use super::results::{self, FixedGroup, StepResult};
use super::sliding::SlidingWatch;
use super::{FloatingReport, GenericReport, GenericScene, GroupReport, Times, scene, setup_notes};

/// The summary rows of a history, made one step at a time as each is solved (see
/// [`results::StepResults`]), with the first non-finite number found in them.
pub struct SummaryRows<'a> {
    results: results::StepResults<'a>,
    every_profile: bool,
    rows: super::StepTable,
    first_non_finite: Option<String>,
    sliding: SlidingWatch,
    fretting: Option<FrettingWatch>,
    /// Whether each row reports its step's re-pairings (finite sliding).
    repairings: bool,
}

impl<'a> SummaryRows<'a> {
    /// Before the first step of a history of `built`, reporting the reactions of `fixed`, each
    /// row with the interfaces' profiles if `every_profile`.
    pub fn new(built: &'a BuiltProblem, fixed: &'a [FixedGroup], every_profile: bool) -> Self {
        SummaryRows {
            results: results::StepResults::new(built, fixed),
            every_profile,
            rows: super::StepTable::new(),
            first_non_finite: None,
            sliding: SlidingWatch::new(built),
            fretting: None,
            repairings: false,
        }
    }

    /// The same rows without the small-sliding check, for a scene whose displacements are in a
    /// unit of their own ([`super::GenericScene::linearised_displacements`]).
    pub fn without_sliding_check(self) -> Self {
        SummaryRows { sliding: SlidingWatch::none(), ..self }
    }

    /// The same rows with moments about `centre` instead of the origin.
    pub fn about(self, centre: [f64; 2]) -> Self {
        SummaryRows { results: self.results.about(centre), ..self }
    }

    /// The same rows, reporting the motion and reactions of `points` in each.
    pub fn with_points(self, points: Vec<super::points::ResolvedPoint>) -> Self {
        SummaryRows { results: self.results.with_points(points), ..self }
    }

    /// The same rows, following the fretting numbers of the last load cycle too.
    pub fn with_fretting(self, watch: FrettingWatch) -> Self {
        SummaryRows { fretting: Some(watch), ..self }
    }

    /// The same rows, each with its step's re-pairings (finite sliding,
    /// [`contact2d_contact::finite_sliding`]).
    pub fn with_repairings(self) -> Self {
        SummaryRows { repairings: true, ..self }
    }

    /// The row of the next step, solved on `built` (the history's problem, or one of the same
    /// topology whose nodes moved).
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] when the step does not fit the problem.
    pub fn push(&mut self, built: &'a BuiltProblem, step: &SolvedStep) -> Result<(), ContactError> {
        self.results.rebase(built);
        self.push_on(built, step)
    }

    /// The row of the next step, solved on `current`, a problem of its own that these rows do
    /// not keep (finite sliding's pairs of the step, [`contact2d_contact::finite_sliding`]);
    /// [`SummaryRows::rebase`] on the last one before the summary.
    ///
    /// # Errors
    /// As [`SummaryRows::push`].
    pub fn push_on(&mut self, current: &BuiltProblem, step: &SolvedStep) -> Result<(), ContactError> {
        let mut row = self.results.push_on(current, step, self.every_profile)?;
        if self.repairings {
            row.repairings = Some(step.repairings);
        }
        self.sliding.observe(&step.solution);
        if let Some(watch) = &mut self.fretting {
            watch.observe(current, &step.solution)?;
        }
        // Checked one row at a time: the whole summary as one JSON value grows with the steps.
        if self.first_non_finite.is_none() {
            let value = serde_json::to_value(&row).unwrap_or(serde_json::Value::Null);
            self.first_non_finite = non_finite(&value, &format!("steps.{}", self.rows.len()));
        }
        self.rows.push(row);
        Ok(())
    }

    /// The next rows, and the summary's profiles, are of `built` (the problem of the last step
    /// pushed with [`SummaryRows::push_on`]).
    pub fn rebase(&mut self, built: &'a BuiltProblem) {
        self.results.rebase(built);
    }
}

/// What a summary needs besides its rows: the scene, the last step and its problem, and the
/// run's facts.
pub struct SummaryInput<'s> {
    /// The scene (expanded, for a preset).
    pub scene: &'s GenericScene,
    /// The problem the last step was solved on.
    pub built: &'s BuiltProblem,
    /// The problem as built from the scene, before any step: the initial gaps and the pairs the
    /// fixes hold are read here (with finite sliding `built` holds the last step's pairs, whose
    /// gaps are that step's linearised offsets, not an initial interference).
    pub initial: &'s BuiltProblem,
    /// The last solved step.
    pub last: &'s SolvedStep,
    /// The groups the scene names.
    pub groups: BTreeMap<String, GroupReport>,
    /// Whether the history was solved once and scaled.
    pub scaled: bool,
    /// The number of steps the schedule asked for.
    pub total_steps: usize,
    /// Where the time went (`total` and `post` are completed here).
    pub times: Times,
    /// When the run started.
    pub clock: Instant,
}

/// The summary of a solved history from its rows: the worst step's status, the last step's
/// interfaces with profiles, reactions and energies, and the notes.
///
/// # Errors
/// [`ContactError::InvalidInput`] without a solved step, [`ContactError::NotFinite`] naming the
/// first non-finite number.
pub fn summarise(input: SummaryInput<'_>, rows: SummaryRows<'_>) -> Result<GenericReport, ContactError> {
    let post_clock = Instant::now();
    let SummaryInput { scene, built, initial, last: last_step, groups, scaled, total_steps: total, mut times, clock } =
        input;
    let SummaryRows { results, rows: summary_steps, first_non_finite, sliding, fretting, .. } = rows;
    let Some(last) = summary_steps.last() else {
        return Err(ContactError::InvalidInput("no load step solved".into()));
    };
    let mut contacts = results.contacts_with_profiles(&last_step.solution);
    if let Some(found) = fretting.as_ref().and_then(|w| w.results(built)) {
        for (info, f) in built.interfaces.iter().zip(found) {
            if let Some(c) = contacts.get_mut(&info.name) {
                c.fretting = Some(Box::new(f));
            }
        }
    }
    let last = StepResult { contacts, ..last };
    // A body held only by contact that crosses a gap under a force moves rigidly first: the work
    // of the force on that travel is stored nowhere in a quasi-static model (there is no kinetic
    // energy), so the energy balance is no check of the numbers there.
    // An interference (a negative initial gap) stores energy that no load put in: no balance
    // either.
    let extent = initial.problem.model.mesh.bounding_box().map_or(1.0, |[lo, hi]| (hi[0] - lo[0]).max(hi[1] - lo[1]));
    let interference = initial.problem.gap.iter().any(|g| *g < -1e-9 * extent);
    // Gaps below 1e-9 of the extent (round-off of a turned or morphed geometry) close with no
    // rigid travel worth counting.
    let touching = initial.problem.gap.iter().all(|g| g.abs() <= 1e-9 * extent);
    let balance_checked = !interference && (scaled || built.problem.system.floating.is_empty() || touching);
    // The round-off of an energy ½ uᵀ K u is about n ε k̄ U² (k̄ the largest stiffness entry, U
    // the largest displacement, n ε ≤ 1e-10 up to 10⁶ DOFs): a history that stores no more (a
    // body turned or moved rigidly by its supports) has no energy flow to balance.
    let largest = last_step.solution.displacement.iter().fold(0.0f64, |a, u| a.max(u.abs()));
    let round_off = 1e-10 * built.problem.stiffness_scale * largest * largest;
    let (status, failed_check) = certified_status(scaled, &summary_steps, balance_checked, round_off);
    let floating_bodies = built
        .problem
        .system
        .floating
        .iter()
        .map(|p| FloatingReport { body: p.body.clone(), free_modes: p.mode_names() })
        .collect();
    let mut notes = scene.element_warnings();
    let regions: Vec<String> = scene.body.iter().map(|b| b.region.clone()).collect();
    notes.extend(setup_notes::shared_node_notes(&built.problem.model.mesh, &regions));
    notes.extend(setup_notes::deep_interference_notes(initial));
    notes.extend(setup_notes::axis_notes(&built.problem.model));
    notes.extend(setup_notes::held_pair_notes(initial, &last_step.solution.gap));
    let node_to_segment: Vec<bool> =
        scene.contact.iter().map(|c| c.pairing == scene::PairingKey::NodeToSegment).collect();
    notes.extend(setup_notes::quadratic_node_to_segment_notes(built, &node_to_segment));
    notes.extend(sliding.notes());
    if scene.solver.place_zone_ends == Some(true)
        && scene.solver.algorithm != contact2d_contact::ContactAlgorithm::Boussinesq
    {
        // As for the plate-insert preset, the key belongs to the Boussinesq algorithm: another
        // algorithm (chosen with --set, or by compare) solves the mesh as generated, and says so.
        notes.push(format!(
            "solver.place_zone_ends = true places zone ends with the boussinesq algorithm only; {} solved the mesh \
             as generated",
            scene.solver.algorithm.key()
        ));
    }
    let (poor, count) = crate::mesh_summary::poor_cells(&built.problem.model.mesh);
    if count > 0 {
        let worst: Vec<String> = poor.iter().take(3).map(ToString::to_string).collect();
        notes.push(format!(
            "{count} cells below quality {} (det J varies more than 20-fold inside) or shape {} (scaled Jacobian at \
             the corners: a corner under about 10° or over 170°); stresses near them are not to be trusted, the \
             worst: {}",
            crate::mesh_summary::MIN_QUALITY,
            crate::mesh_summary::MIN_SHAPE,
            worst.join("; ")
        ));
    }
    if interference {
        notes.push(
            "energy balance not checked: the initial interference (negative gaps) stores energy that no load put in"
                .into(),
        );
    } else if !balance_checked {
        notes.push(
            "energy balance not checked: a body held only by contact meets initial gaps under a force, and the work \
             of the force on any rigid travel before contact is stored nowhere in a quasi-static model"
                .into(),
        );
    }
    if summary_steps.len() < total {
        notes.push(format!(
            "the history stopped after step {} of {total}: it did not converge ({status})",
            summary_steps.len()
        ));
    }
    times.post += post_clock.elapsed().as_secs_f64();
    times.total = clock.elapsed().as_secs_f64();
    let report = GenericReport {
        scene: scene.name.clone(),
        status,
        failed_check,
        not_held: summary_steps.first_not_held(),
        algorithm: scene.solver.algorithm,
        kinematics: kinematics_used(&built.problem.model),
        dofs: built.problem.system.dofs.num_free(),
        pairs: built.problem.num_pairs(),
        iterations: summary_steps.iter().map(|s| s.iterations).sum(),
        scaled,
        pairing_used: built.interfaces.iter().map(|i| (i.name.clone(), i.pairing.key())).collect(),
        // The solve already refused a path the algorithm cannot take, so the error arm is unreachable
        // for a solved history; it names the only other path.
        linear_used: scene
            .solver
            .linear
            .resolve(scene.solver.algorithm, built.problem.num_pairs())
            .map_or(LinearSolver::Condensed.key(), LinearSolver::key),
        path_error: None,
        steps_taken: None,
        steps: summary_steps,
        contacts: last.contacts.to_btree(),
        reactions: last.reactions.to_btree(),
        reactions_total: last.reactions_total,
        moment_centre: scene.moment_centre,
        reaction_moments: last.reaction_moments.to_btree(),
        reaction_moment_total: last.reaction_moment_total,
        energies: last.energies.to_btree(),
        points: last.points.to_btree(),
        kkt: last.kkt,
        floating_bodies,
        groups,
        time_s: times,
        notes,
        post: BTreeMap::new(),
    };
    match non_finite_report(&report, first_non_finite) {
        Some(path) => Err(ContactError::NotFinite(format!("{path} of the summary"))),
        None => Ok(report),
    }
}

/// The dotted path of the first non-finite number of `report` (as [`non_finite`] of the whole
/// summary), its step rows already checked one by one (`in_steps`: the first path found there),
/// so that the summary is never one JSON value with every step.
fn non_finite_report(report: &GenericReport, in_steps: Option<String>) -> Option<String> {
    let head = report.without_steps();
    let serde_json::Value::Object(map) = serde_json::to_value(&head).unwrap_or(serde_json::Value::Null) else {
        return Some("the summary".into());
    };
    let mut in_steps = in_steps;
    map.into_iter().find_map(|(k, v)| {
        if k == "steps" {
            return in_steps.take();
        }
        non_finite(&serde_json::Value::Object(std::iter::once((k, v)).collect()), "")
    })
}

/// The dotted path of the first non-finite number in a serialised summary (serde_json writes
/// NaN and ±∞ as `null`). The only other `null`s are a group reaction's component that the group
/// does not prescribe (`reactions.<group>.<c>`): it is skipped, a NaN there being caught in
/// `reactions_total`, which sums every constrained DOF; and the `mean_pressure` of an interface
/// with no contact length (a NaN normal force is caught in `normal_force`).
fn non_finite(value: &serde_json::Value, at: &str) -> Option<String> {
    let join = |k: &str| if at.is_empty() { k.to_string() } else { format!("{at}.{k}") };
    match value {
        serde_json::Value::Null => Some(if at.is_empty() { "the summary".into() } else { at.to_string() }),
        serde_json::Value::Array(items) => {
            items.iter().enumerate().find_map(|(i, v)| non_finite(v, &join(&i.to_string())))
        }
        serde_json::Value::Object(map) => map.iter().find_map(|(k, v)| match (k.as_str(), v) {
            // A mean pressure over no contact length is null by definition.
            ("mean_pressure", serde_json::Value::Null) => None,
            ("reactions", serde_json::Value::Object(groups)) => groups.iter().find_map(|(g, f)| {
                let components = f.as_array().map(|c| c.iter().filter(|v| !v.is_null()).cloned().collect());
                non_finite(&serde_json::Value::Array(components.unwrap_or_default()), &join(&format!("reactions.{g}")))
            }),
            _ => non_finite(v, &join(k)),
        }),
        _ => None,
    }
}

/// The status of a history — its worst step's; `numerical` (with the check) when a step's
/// solution fails [`contact2d_contact::certify`] or the history breaks its energy balance `W = Φ_E + Φ_f`
/// ([`check_energy_balance`]: tight when solved once and scaled, where W is exact; the
/// trapezoid rule's tolerance otherwise; `scaled`: whether the history was; each step's own
/// allowance for the trapezoid rule's bound and round-off). A history whose
/// energies stay below `round_off` is not checked (its work and strain energy are round-off).
fn certified_status(
    scaled: bool,
    steps: &super::StepTable,
    balance: bool,
    round_off: f64,
) -> (&'static str, Option<String>) {
    let converged = results::status_name(contact2d_contact::ContactStatus::Converged);
    if let Some((i, step)) = steps.iter().enumerate().find(|(_, s)| s.status != converged) {
        let why = step.failed_check.as_deref().unwrap_or("no check named");
        return (step.status, Some(format!("step {}: {why}", i + 1)));
    }
    let stored = |step: &StepResult| step.energies.values().sum::<f64>();
    let scale = energy_scale(steps.iter().map(|s| (s.work, stored(&s), s.dissipated)));
    for (i, step) in steps.iter().enumerate().filter(|_| balance && scale > round_off) {
        if let Err(f) =
            check_energy_balance(step.work, stored(&step), step.dissipated, scaled, scale, step.energy_allowance)
        {
            return ("numerical", Some(format!("step {}: {f}", i + 1)));
        }
    }
    ("converged", None)
}

/// The kinematics of the model's bodies as the scene key spells it (`plane` where plane bodies
/// differ in their condition).
fn kinematics_used(model: &contact2d_fem::Model) -> &'static str {
    let key = |b: &contact2d_fem::Body| match b.kinematics {
        contact2d_element::Kinematics::PlaneStress { .. } => "plane_stress",
        contact2d_element::Kinematics::PlaneStrain { .. } => "plane_strain",
        contact2d_element::Kinematics::Axisymmetric => "axisymmetric",
    };
    let first = model.bodies.first().map_or("plane_stress", key);
    if model.bodies.iter().all(|b| key(b) == first) { first } else { "plane" }
}

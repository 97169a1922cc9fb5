//! The run of a scene's steps: on the one problem, stage by stage or on pairs that follow the
//! motion ([`solve_run`]); the path the user's steps take with adaptive stepping ([`plan_path`],
//! [`super::adaptive`]); and the step size's error of a frictional run
//! ([`estimate_path_error`], [`super::path_error`]).

use contact2d_contact::{
    BuiltProblem, ContactError, History, LoadSchedule, Retention, SolvedStep, SolverSettings, Stage,
    solve_finite_sliding, solve_keeping, solve_stages,
};

use super::{FixedGroup, GenericReport, GenericScene, adaptive, path_error, results};

/// What a run of a scene's steps needs: its problem (the first stage's with staged supports),
/// its stages (none without), which contacts slide finitely, the settings and the schedule.
pub(super) struct Run<'a> {
    pub built: &'a BuiltProblem,
    pub stages: &'a [Stage],
    pub finite: &'a [bool],
    pub settings: &'a SolverSettings,
    pub schedule: &'a LoadSchedule,
}

/// Solves a scene's steps: stage by stage with staged supports, on the pairs of each step's own
/// configuration with finite sliding, else on the one problem; `observe(i, step, current)` is
/// told each step with the problem it was solved on. Returns the history and, for stages or
/// finite sliding, the problem of the last step.
pub(super) fn solve_run(
    run: &Run<'_>,
    retention: Retention,
    observe: &mut dyn FnMut(usize, &SolvedStep, &BuiltProblem),
) -> Result<(History, Option<BuiltProblem>), ContactError> {
    let Run { built, stages, finite, settings, schedule } = *run;
    if !stages.is_empty() {
        let (history, last) = solve_stages(stages, settings, schedule, retention, observe)?;
        Ok((history, stages.get(last).map(|s| s.built.clone())))
    } else if finite.iter().any(|f| *f) {
        let (history, last) = solve_finite_sliding(built, finite, settings, schedule, retention, observe)?;
        Ok((history, Some(last)))
    } else {
        let history =
            solve_keeping(&built.problem, settings, schedule, retention, &mut |i, step| observe(i, step, built))?;
        Ok((history, None))
    }
}

/// Whether some contact of the scene has friction (else its answer does not depend on the path).
fn frictional(scene: &GenericScene) -> bool {
    scene.contact.iter().any(|c| c.friction > 0.0)
}

/// The path the user's steps take ([`plan_path`]): the steps, a note where adaptive stepping
/// stopped short, and the path error of each of its steps where the last round measured it.
pub(super) struct Plan {
    pub path: adaptive::Refined,
    pub note: Option<String>,
    pub errors: Option<Vec<f64>>,
}

/// Fills `report`'s `path_error`, per step and for the run ([`path_error`]): 0 without friction
/// or for a run solved once and scaled; else `known` (the errors adaptive stepping measured on
/// this path) or the run solved again on the halved path and compared at the user's steps, with
/// a note above [`path_error::NOTE_ABOVE`]. Not estimated (absent, with a note) when the scene
/// turns it off or the halved path does not solve.
pub(super) fn estimate_path_error(
    scene: &GenericScene,
    run: &Run<'_>,
    fixed: &[FixedGroup],
    known: Option<Vec<f64>>,
    report: &mut GenericReport,
) {
    if !scene.loading.path_error {
        return;
    }
    if !frictional(scene) || report.scaled {
        report.path_error = Some(0.0);
        (0..report.steps.len()).for_each(|i| report.steps.set_path_error(i, Some(0.0)));
        return;
    }
    let errors = match known {
        Some(errors) => errors,
        None => match halved_points(run, fixed) {
            Ok(fine) => {
                let coarse: Vec<path_error::PathPoint> =
                    report.steps.iter().map(|row| path_error::PathPoint::of(&row)).collect();
                path_error::step_errors(&coarse, &fine)
            }
            Err(e) => {
                report.notes.push(format!("path_error: not estimated, the path of half the step did not solve: {e}"));
                return;
            }
        },
    };
    for (i, e) in errors.iter().enumerate() {
        report.steps.set_path_error(i, Some(*e));
    }
    report.path_error = (errors.len() == report.steps.len()).then(|| errors.iter().copied().fold(0.0, f64::max));
    if let Some(e) = report.path_error.filter(|e| *e > path_error::NOTE_ABOVE) {
        report.notes.push(format!(
            "path_error {:.2} %: friction makes the answer depend on the load path, and halving the steps moves the \
             contact forces or the dissipation by about that much (relative to the largest contact force, and to \
             the work of the loads); use more steps",
            100.0 * e
        ));
    } else if report.path_error.is_none() {
        report.notes.push("path_error: the path of half the step stopped before the last step".into());
    }
}

/// The path of the user's steps: refined by adaptive stepping where the scene asks for it and
/// friction makes the answer depend on the path ([`adaptive`]), else the user's own; with a note
/// when the refinement stopped before the tolerance.
pub(super) fn plan_path(scene: &GenericScene, run: &Run<'_>, fixed: &[FixedGroup]) -> Result<Plan, ContactError> {
    let mut path = adaptive::Refined::of(run.schedule);
    let stop = |path, note: String, errors| Ok(Plan { path, note: Some(note), errors });
    let Some(key) = scene.loading.adaptive.filter(|_| frictional(scene)) else {
        return Ok(Plan { path, note: None, errors: None });
    };
    for _ in 0..adaptive::MAX_ROUNDS {
        let stages = path.stages(run.stages);
        let current = Run { schedule: &path.schedule, stages: &stages, ..*run };
        let coarse = run_points(&current, fixed, &|_| true)?;
        let fine = halved_points(&current, fixed)?;
        let errors = path_error::step_errors(&coarse, &fine);
        if errors.len() < path.schedule.steps().len() {
            return stop(path, "adaptive stepping stopped refining: a step of its path did not converge".into(), None);
        }
        let contributions = path_error::step_contributions(&coarse, &fine);
        match adaptive::next(&path, &errors, &contributions, key.tolerance)? {
            None => return answered_finer(&path, None, errors),
            Some(next) if next.schedule.steps().len() > adaptive::MAX_STEPS => {
                let note = format!(
                    "adaptive stepping stopped refining at {} steps: the tolerance {:e} needs more than {} steps",
                    path.schedule.steps().len(),
                    key.tolerance,
                    adaptive::MAX_STEPS
                );
                return answered_finer(&path, Some(note), errors);
            }
            Some(next) => path = next,
        }
    }
    let note = format!(
        "adaptive stepping stopped refining after {} rounds at {} steps above the tolerance {:e}",
        adaptive::MAX_ROUNDS,
        path.schedule.steps().len(),
        key.tolerance
    );
    stop(path, note, None)
}

/// The plan that answers on `path` with every step halved: the finer of the two paths whose
/// difference gave `errors` (local extrapolation, as step doubling takes its two half steps). Each
/// half step carries its step's error: under first-order convergence the finer path's own error is
/// about half of it, so the reported error bounds it.
fn answered_finer(path: &adaptive::Refined, note: Option<String>, errors: Vec<f64>) -> Result<Plan, ContactError> {
    let finer = path.split(&vec![true; path.schedule.steps().len()])?;
    let errors = errors.iter().flat_map(|e| [*e, *e]).collect();
    Ok(Plan { path: finer, note, errors: Some(errors) })
}

/// The step table at the user's steps only (adaptive stepping): each row the state at the end of
/// its user step, its `substeps` the steps it took and its `path_error` the largest of theirs; a
/// last row that ended a user step early (a step that did not converge) kept as well.
pub(super) fn keep_user_steps(path: &adaptive::Refined, note: Option<String>, report: &mut GenericReport) {
    if path.ends.iter().enumerate().all(|(i, e)| *e == i) {
        return;
    }
    let substeps = path.substeps();
    let rows = std::mem::take(&mut report.steps);
    let last = rows.len().saturating_sub(1);
    let mut worst: f64 = 0.0;
    let mut any = false;
    for (j, mut row) in rows.iter().enumerate() {
        if let Some(e) = row.path_error {
            worst = worst.max(e);
            any = true;
        }
        let (user, ends) = adaptive::user_step_of(&path.ends, j);
        if ends || j == last {
            row.substeps = substeps.get(user).copied();
            row.path_error = any.then_some(worst);
            report.steps.push(row);
            (worst, any) = (0.0, false);
        }
    }
    report.steps_taken = Some(path.schedule.steps().len());
    report.notes.push(format!(
        "adaptive stepping: {} steps for the user's {} (`steps[i].substeps`): the path whose path_error is within \
         the tolerance, every step of it halved",
        path.schedule.steps().len(),
        path.ends.len()
    ));
    report.notes.extend(note);
}

/// A run's points ([`path_error::PathPoint`]) at the steps `keep` selects, up to its first step
/// that does not converge.
fn run_points(
    run: &Run<'_>,
    fixed: &[FixedGroup],
    keep: &dyn Fn(usize) -> bool,
) -> Result<Vec<path_error::PathPoint>, ContactError> {
    let mut results = results::StepResults::new(run.built, fixed);
    let (mut points, mut failed, mut stopped) = (path_error::PathPoints::default(), None, false);
    solve_run(run, Retention::Last, &mut |i, step, current| match results.push_on(current, step, false) {
        Ok(row) if row.status != "converged" => stopped = true,
        Ok(row) if keep(i) && !stopped => points.push(&row),
        Ok(_) => {}
        Err(e) => failed = failed.take().or(Some(e)),
    })?;
    failed.map_or(Ok(points.into_points()), Err)
}

/// The run on the halved path (every step split at its middle, [`adaptive::Refined::split`]),
/// its points at the end of each of the run's steps.
fn halved_points(run: &Run<'_>, fixed: &[FixedGroup]) -> Result<Vec<path_error::PathPoint>, ContactError> {
    let halved = adaptive::Refined::of(run.schedule).split(&vec![true; run.schedule.steps().len()])?;
    let stages = halved.stages(run.stages);
    run_points(&Run { schedule: &halved.schedule, stages: &stages, ..*run }, fixed, &|i| i % 2 == 1)
}

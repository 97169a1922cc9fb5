//! Staged supports: fixes that hold their DOFs over a run of steps only (`from_step`,
//! `until_step` of a scene's `[[fix]]`), solved stage by stage in the total formulation.
//!
//! ```text
//! stage s = a run of steps over which the set of active fixes is constant
//!   its problem: the bodies with only the active fixes (its own DOF map and factorisation;
//!   the same pairs and load patterns in every stage)
//!   a DOF held at the stage start (constrained now, by no fix that was active in the stage
//!   before):  u_c = u_{K−1} + Σ_p F_i[p] u_c,p      (u_{K−1}: where the step before left it)
//!   the other constrained DOFs:  u_c = Σ_p F_i[p] u_c,p
//!   every step from the slips, tangential forces and pair states the step before ended with
//! ```
//!
//! The held positions are one more load pattern of the stage's problem, at factor 1 in each of
//! its steps, `r_held = −K_fc u_held` (no nodal load); the steps handed on carry the scene's
//! patterns' factors only. In linear elasticity the stage's first step at the previous step's
//! factors reproduces the previous step's state exactly: a clamp added after a fit carries no
//! reaction until the load changes, and a released support's reaction falls to zero (the
//! trapezoid rule of the work, `½ (f_{i−1} + f_i)·Δu`, is exact for that linear unloading).
//! Floating bodies are found per stage (a body may be held in one stage and float in the next).

use std::ops::Range;

use contact2d_fem::Model;

use crate::builder::{BuiltProblem, ProblemDescription};
use crate::error::ContactError;
use crate::history::Retention;
use crate::loading::LoadSchedule;
use crate::problem::LoadPattern;
use crate::solution::{PairState, StepStart};
use crate::solve::{History, RunStart, SolvedStep, SolverSettings, solve_run_from};

/// The name of the pattern that holds a stage's newly held DOFs where they were (never a
/// pattern of a schedule: the steps handed on carry the problem's own patterns only).
pub const HELD_PATTERN: &str = "held where the stage began";

/// A stage's steps (indices from 0) and which fixes are active in them (one flag per fix of
/// the [`ProblemDescription`]).
pub type StageActivity = (Range<usize>, Vec<bool>);

/// One stage: its steps and its problem.
#[derive(Debug, Clone)]
pub struct Stage {
    /// The steps of the schedule it solves (indices from 0).
    pub steps: Range<usize>,
    /// Its problem: the bodies with the fixes active in these steps.
    pub built: BuiltProblem,
    /// Per global DOF: held where it is at the stage start (constrained in this stage by fixes
    /// none of which was active in the stage before; none in the first stage).
    pub held: Vec<bool>,
}

impl ProblemDescription {
    /// One problem per stage: `activity` lists each stage's steps (consecutive, from step 0 to
    /// the schedule's last) and which fixes are active in them (one flag per fix).
    ///
    /// # Errors
    /// No stage, stages that do not follow each other, a flag count that differs from the
    /// number of fixes, and every error of [`ProblemDescription::build_stage`].
    pub fn build_stages(&self, activity: &[StageActivity]) -> Result<Vec<Stage>, ContactError> {
        if activity.is_empty() {
            return Err(ContactError::InvalidInput("staged supports without a stage".into()));
        }
        let mut stages: Vec<Stage> = Vec::with_capacity(activity.len());
        let mut before: Option<&[bool]> = None;
        let mut next = 0;
        for (steps, active) in activity {
            if steps.start != next || steps.is_empty() {
                return Err(ContactError::InvalidInput(format!(
                    "stage of steps {steps:?} does not follow step {next} or is empty"
                )));
            }
            let built = self.build_stage(active)?;
            let held = match (before, stages.last()) {
                (Some(before), Some(previous)) => {
                    let frames = (&previous.built.problem.system.dofs, &built.problem.system.dofs);
                    self.held_at_start(&built.problem.model, active, before, frames)?
                }
                _ => vec![false; built.problem.system.dofs.num_global()],
            };
            stages.push(Stage { steps: steps.clone(), built, held });
            before = Some(active);
            next = steps.end;
        }
        Ok(stages)
    }

    /// The DOFs constrained by fixes `now` active, none of them `before` active; and both DOFs of
    /// a node a newly active fix touches whose local frame (`un`, `ut`) changes between the
    /// stages' DOF maps `frames` (before, now): its DOFs are other directions now, held where the
    /// node is (its conditions there are zero supports, which the position reached satisfies).
    fn held_at_start(
        &self,
        model: &Model,
        now: &[bool],
        before: &[bool],
        frames: (&contact2d_fem::DofMap, &contact2d_fem::DofMap),
    ) -> Result<Vec<bool>, ContactError> {
        let n = model.mesh.num_nodes() * 2;
        let (mut new, mut kept) = (vec![false; n], vec![false; n]);
        for ((f, _), before) in self.fixes.iter().zip(now).zip(before).filter(|((_, now), _)| **now) {
            for node in model.mesh.group_nodes(&f.group)? {
                let d = contact2d_fem::Dof::of(node.0, f.component).0;
                if *before {
                    kept[d] = true;
                } else {
                    new[d] = true;
                }
            }
        }
        let mut held: Vec<bool> = new.iter().zip(&kept).map(|(n, k)| *n && !*k).collect();
        if frames.0.has_frames() || frames.1.has_frames() {
            for node in 0..n / 2 {
                if (new[2 * node] || new[2 * node + 1]) && frames.0.frame(node) != frames.1.frame(node) {
                    held[2 * node] = true;
                    held[2 * node + 1] = true;
                }
            }
        }
        Ok(held)
    }
}

/// Solves `schedule` stage by stage (module docs): `on_step(i, step, built)` is told each
/// solved step with the problem of its stage; the history stops after the first step that
/// does not converge; [`History::scaled`] is false. Returns the history and the index of the
/// stage of its last step.
///
/// # Errors
/// Stages that do not cover the schedule's steps one after the other, problems of different
/// pairs or patterns, a schedule naming a pattern the problems do not have, the Boussinesq
/// algorithm, a passed deadline, and every error of a step.
pub fn solve_stages(
    stages: &[Stage],
    settings: &SolverSettings,
    schedule: &LoadSchedule,
    retention: Retention,
    on_step: &mut dyn FnMut(usize, &SolvedStep, &BuiltProblem),
) -> Result<(History, usize), ContactError> {
    let total = schedule.steps().len();
    check_stages(stages, total)?;
    let Some(first) = stages.first() else {
        return Err(ContactError::InvalidInput("staged supports without a stage".into()));
    };
    let names: Vec<&str> = first.built.problem.patterns().iter().map(|p| p.name.as_str()).collect();
    let pairs = first.built.problem.num_pairs();
    let mut u = vec![0.0; first.built.problem.system.dofs.num_global()];
    let mut start = StepStart::initial(pairs);
    let mut guess: Option<Vec<PairState>> = None;
    let mut previous = vec![0.0; names.len()];
    let (mut dissipated, mut steps, mut last_stage) = (0.0, vec![], 0);
    for (s, stage) in stages.iter().enumerate() {
        let targets: Vec<Vec<f64>> =
            stage.steps.clone().map(|i| schedule.factors_for(i, &names)).collect::<Result<_, _>>()?;
        let (problem, held) = with_held(stage, &u)?;
        let extend = |f: &[f64]| -> Vec<f64> { f.iter().copied().chain(held.then_some(1.0)).collect() };
        let run_targets: Vec<Vec<f64>> = targets.iter().map(|t| extend(t)).collect();
        let run_previous = extend(&previous);
        let run = RunStart {
            previous: &run_previous,
            start: &start,
            guess: guess.as_deref(),
            first_step: stage.steps.start + 1,
            total_steps: total,
        };
        // Each step is handed on as it is solved, so that memory stays flat with
        // `Retention::Last`.
        let mut count = 0;
        let mut hand_on = |outcome: crate::solve::StepOutcome| {
            dissipated += outcome.solution.dissipation;
            let step = SolvedStep {
                factors: targets[count].clone(),
                solution: outcome.solution,
                dissipated,
                floating_iterations: outcome.iterations,
                floating_residual: outcome.residual,
                repairings: 0,
                unstable_pairing: None,
                not_held: outcome.not_held,
            };
            on_step(stage.steps.start + count, &step, &stage.built);
            count += 1;
            if retention == Retention::Last {
                steps.clear();
            }
            steps.push(step);
        };
        let done = solve_run_from(&problem, settings, &run_targets, &run, &mut hand_on)?;
        last_stage = s;
        let Some(last) = steps.last() else { break };
        u.clone_from(&last.solution.displacement);
        start = StepStart::after(&last.solution);
        guess = Some(last.solution.state.clone());
        previous.clone_from(&last.factors);
        if done < targets.len() || !last.solution.status.is_solved() {
            break;
        }
    }
    Ok((History { steps, scaled: false, condense_time: std::time::Duration::ZERO }, last_stage))
}

/// Stages that cover steps `0..total` one after the other, on problems of the same pairs and
/// patterns.
fn check_stages(stages: &[Stage], total: usize) -> Result<(), ContactError> {
    let mut next = 0;
    for stage in stages {
        if stage.steps.start != next || stage.steps.is_empty() {
            return Err(ContactError::InvalidInput(format!(
                "stage of steps {:?} does not follow step {next} or is empty",
                stage.steps
            )));
        }
        next = stage.steps.end;
        let (a, b) = (&stages[0].built.problem, &stage.built.problem);
        let same_patterns = a.patterns().iter().map(|p| &p.name).eq(b.patterns().iter().map(|p| &p.name));
        if a.num_pairs() != b.num_pairs() || !same_patterns {
            return Err(ContactError::InvalidInput("the stages' problems differ in their pairs or patterns".into()));
        }
    }
    if next != total {
        return Err(ContactError::InvalidInput(format!("the stages cover {next} steps of {total}")));
    }
    Ok(())
}

/// The stage's problem to solve: its own, or, when DOFs held at the stage start have moved
/// (`u` where the step before left them), a copy with one more pattern that holds them there
/// ([`HELD_PATTERN`]); and whether it has that pattern.
fn with_held(stage: &Stage, u: &[f64]) -> Result<(crate::ContactProblem, bool), ContactError> {
    let problem = &stage.built.problem;
    let dofs = &problem.system.dofs;
    // The position reached, in the stage's DOFs (`un`, `ut` at a framed node).
    let u = dofs.to_local(u);
    let held: Vec<f64> = dofs
        .constrained_dofs()
        .iter()
        .map(|d| if stage.held.get(d.0).copied().unwrap_or(false) { u.get(d.0).copied().unwrap_or(0.0) } else { 0.0 })
        .collect();
    if held.iter().all(|v| *v == 0.0) {
        return Ok((problem.clone(), false));
    }
    let nodal = vec![0.0; dofs.num_global()];
    let rhs = problem.system.rhs_with(&nodal, &held);
    let mut patterns: Vec<LoadPattern> = problem.patterns().to_vec();
    patterns.push(LoadPattern { name: HELD_PATTERN.into(), rhs, prescribed: held, nodal });
    let mut solving = problem.clone();
    solving.set_patterns(patterns)?;
    Ok((solving, true))
}

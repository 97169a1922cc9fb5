//! The paper's post-processor: its quantities (η, l, b, P, Φ_E1, Φ_E2, Φ_f, W, σ*, K) of every
//! solved step, reported as the `paper` block of the one JSON summary.

use std::sync::Arc;

use serde::Serialize;

use contact2d_contact::{ContactError, ContactSolution};

use super::{PlateInsertProblem, PlateInsertResults};

/// The name of the block in the summary.
pub const BLOCK: &str = "paper";

/// One solved load step with the discrete problem it was solved on and its paper quantities.
#[derive(Debug, Clone)]
pub struct PaperStep {
    /// The problem (mesh, model, pairs) of this step; steps on the same mesh share it.
    pub case: Arc<PlateInsertProblem>,
    /// The step's contact solution (its `load_factor` is the step's load w).
    pub solution: ContactSolution,
    /// The paper's quantities of this step.
    pub results: PlateInsertResults,
    /// Φ_f accumulated up to and including this step.
    pub dissipated: f64,
}

/// The paper's quantities of a run (the summary's `paper` block).
#[allow(non_snake_case)]
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PaperReport {
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
    /// Work of the pulling force, W = ∫ P dw (trapezoid over the steps; P w / 2 for one
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
    /// The load history, one entry per step.
    pub steps: Vec<StepReport>,
    /// Inequalities of (5.1) a step violates (status `inadmissible`); empty when admissible.
    pub violations: Vec<ViolationReport>,
}

/// A violated contact inequality.
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

/// One step of a history.
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

/// The paper's quantities of solved steps: the last step's at the top, the work W = ∫ P dw by
/// the trapezoid rule over the steps; `w` the scene's load (the last step's for a history in l),
/// `mu` its friction coefficient.
///
/// # Errors
/// [`ContactError::InvalidInput`] without a step, [`ContactError::NotFinite`] for a non-finite
/// quantity (never written as the JSON `null` that means "none").
pub fn paper_report(solved: &[PaperStep], w: Option<f64>, mu: f64) -> Result<PaperReport, ContactError> {
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
    let q = &last.results;
    finite(PaperReport {
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
        w: w.unwrap_or(last.solution.load_factor),
        mu,
        steps,
        violations: violations(solved),
    })
}

/// The report if every number in it is finite.
fn finite(report: PaperReport) -> Result<PaperReport, ContactError> {
    let r = &report;
    let optional = [r.l, r.l_master, r.b, r.insert_hoop_max].into_iter().flatten();
    let brackets = [r.l_bracket, r.b_bracket].into_iter().flatten().flatten();
    let numbers = [r.P, r.Phi_E1, r.Phi_E2, r.Phi_f, r.W, r.sigma_star, r.K, r.w, r.mu];
    let steps =
        r.steps.iter().flat_map(|s| [s.w, s.P, s.Phi_E1, s.Phi_E2, s.Phi_f, s.W].into_iter().chain(s.l).chain(s.b));
    match numbers.into_iter().chain(optional).chain(brackets).chain(steps).find(|v| !v.is_finite()) {
        Some(v) => Err(ContactError::NotFinite(format!("a reported quantity of the paper's case is {v}"))),
        None => Ok(report),
    }
}

/// Every violated inequality of every step, with the pair's η on the hole edge.
fn violations(solved: &[PaperStep]) -> Vec<ViolationReport> {
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

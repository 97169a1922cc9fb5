//! A block clamped onto an elastic base through a reference point, then pulled sideways until
//! friction lets go (`scenes/generic/clamped_block.toml`, mesh from the gmsh Python API:
//! `python/examples/clamped_block_mesh.py`): reference points with a distributing coupling, a
//! force and a moment on a point, and a staged support.
//!
//! ```text
//!            M ↺  P ↓  F →            the point "clamp" at p = (2, 2), coupled to block_top
//!   block_left ┌────●────┐            step 1: P = 1000 N/mm and M = 100 N·mm/mm; block_left
//!   (u1 = 0,   │  block  │                    holds u1 (the block floats otherwise)
//!   step 1)    └─────────┘  μ = 0.35  steps 2…: block_left released (until_step = 1), the
//!      ┌────────────────────────┐             point pulled by F = 1000 λ, λ = 0.1, 0.2, …, 0.5
//!                                             (the bundled scene stops at 0.3: held)
//!      │ base (clamped below)   │
//!      └────────────────────────┘
//! ```
//!
//! Closed forms, from the statics of the block (its loads act at p; the contact and, in step 1,
//! the side support hold it), with the contact's resultant R and moment m_p about p of the force
//! the interface transmits to the base (its slave side):
//!
//! ```text
//!   R2 = −P                          N = P  (every step)
//!   R1 = F + S1                      S the side support's reaction on the block (0 once released)
//!   m_p = M + m_p(S)                 m_p(S) the support's reaction moment about p
//!   held ⇔ |R1| ≤ μ N  ⇔  λ ≤ λ* = μ P / F(1) = 0.35   (Coulomb, gross slip of the block)
//! ```
//!
//! Source: rigid-body statics with Coulomb's law (Meriam & Kraige, *Engineering Mechanics:
//! Statics*, §6/2, a block on a rough plane); the balance of moments about any point.
//!
//! Checks and tolerances: N, R1 and m_p at every converged step against statics within 1e-8
//! relative (force) and 1e-8 of P times the block's width (moment) — the pair forces sum to the
//! loads to round-off (measured ~1e-15); the run ends `not_held` at the first step past λ*, and
//! its last held factor λ_h satisfies λ* − Δλ < λ_h ≤ λ* with the step Δλ = 0.1: the check is
//! `|λ_h − λ*| ≤ Δλ` (the step size is the tolerance; a run that ends otherwise has no λ_h and
//! fails); the demanded friction force at that step against the pull F within 1e-5 relative (the
//! free motion comes from an SVD of a forward-difference Jacobian, accurate to ~1e-6).

use std::path::Path;

use super::{CaseReport, Check, Figure, Level, Tolerance, VerifyError, gallery_scene, scene_path};
use crate::generic::solve_generic;
use crate::output::chart::{Axes, Series};

const SCENE: &str = "scenes/generic/clamped_block.toml";
/// The clamping force P (N/mm) and moment M (N·mm/mm), the pull F at factor 1 (N/mm).
const P: f64 = 1000.0;
const M: f64 = 100.0;
const PULL: f64 = 1000.0;
const MU: f64 = 0.35;
/// The point's position p and the block's width (the moment's length scale).
const AT: [f64; 2] = [2.0, 2.0];
const WIDTH: f64 = 2.0;
/// The pull step Δλ.
const STEP: f64 = 0.1;
/// The pull factors of the case: the bundled scene's 0.1, 0.2, 0.3 (held), then past λ*.
const PULLS: [f64; 5] = [0.1, 0.2, 0.3, 0.4, 0.5];

/// The override that extends the bundled scene's schedule (the clamp, then the pull to 0.3) past
/// the slip load: the clamp, then the pull in steps of 0.1 to 0.5.
pub fn schedule_override() -> String {
    let pulls: Vec<String> = PULLS.iter().map(|f| format!("{{clamp = 1.0, pull = {f}}}")).collect();
    format!("loading.schedule=[{{clamp = 1.0}}, {}]", pulls.join(", "))
}

/// The pull factor at which friction lets go: λ* = μ P / F(1).
pub fn slip_factor() -> f64 {
    MU * P / PULL
}

/// The moment about `c` of a force `f` at `x`, from its moment `m0` about the origin.
fn moment_about(m0: f64, f: [f64; 2], c: [f64; 2]) -> f64 {
    m0 - (c[0] * f[1] - c[1] * f[0])
}

/// Runs the case.
///
/// # Errors
/// A scene that cannot be read or solved, or a step without the interface.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let scene = gallery_scene(&scene_path(root, SCENE), &[schedule_override()])?;
    let out = solve_generic(&scene, &mut |_, _| {})?;
    let mut report = CaseReport {
        name: "clamped_block".into(),
        source: "statics of a block clamped through a reference point (N = P, T = F, moment about the point = M) \
                 and Coulomb's slip load μP"
            .into(),
        ..CaseReport::default()
    };
    let mut computed = vec![];
    for (i, step) in out.report.steps.iter().enumerate() {
        if step.status != "converged" {
            continue;
        }
        let lambda = step.factors.get("pull").copied().unwrap_or(0.0);
        let contact = step.contacts.get("joint").ok_or_else(|| missing("no interface \"joint\""))?;
        let side = step.reactions.get("block_left").and_then(|r| r[0]).unwrap_or(0.0);
        let side_moment = step.reaction_moments.get("block_left").map_or(0.0, |m0| moment_about(*m0, [side, 0.0], AT));
        let mesh = format!("step {}, λ = {lambda}", i + 1);
        let force = |quantity: &str, measured: f64, reference: f64| Check {
            quantity: quantity.into(),
            mesh: mesh.clone(),
            measured,
            reference,
            tolerance: Tolerance::Relative(1e-8),
        };
        report.checks.push(force("normal force N = P", contact.normal_force, P));
        report.checks.push(force("tangential force R1 = F + S1", contact.resultant[0], lambda * PULL + side));
        report.checks.push(Check {
            quantity: "moment about the point m_p = M + m_p(S)".into(),
            mesh: mesh.clone(),
            measured: moment_about(contact.moment, contact.resultant, AT),
            reference: M + side_moment,
            tolerance: Tolerance::Absolute(1e-8 * P * WIDTH),
        });
        computed.push((lambda, contact.resultant[0] / contact.normal_force));
    }
    let held = out.report.not_held.as_ref();
    if held.is_none() {
        report.notes.push(format!("the run ended {} instead of not_held", out.report.status));
    }
    report.checks.push(Check {
        quantity: "last held pull factor λ_h (λ* − Δλ < λ_h ≤ λ*)".into(),
        mesh: format!("Δλ = {STEP}"),
        measured: held.and_then(|h| h.last_held_factors.get("pull").copied()).unwrap_or(f64::NAN),
        reference: slip_factor(),
        tolerance: Tolerance::Absolute(STEP),
    });
    if let Some(h) = held {
        let lambda = out.report.steps.last().and_then(|s| s.factors.get("pull").copied()).unwrap_or(f64::NAN);
        report.checks.push(Check {
            quantity: "demanded friction force at the step not held = F".into(),
            mesh: format!("step {}, λ = {lambda}", h.step),
            measured: h.demanded,
            reference: lambda * PULL,
            tolerance: Tolerance::Relative(1e-5),
        });
        if h.last_held_factors.get("pull").is_some_and(|l| *l > slip_factor()) {
            report.notes.push("the last held factor is past λ*".into());
        }
    }
    report.figures.push(Figure {
        file: "clamped_block_friction.svg".into(),
        axes: Axes {
            title: "Clamped block: friction force over normal force against the pull".into(),
            x_label: "pull factor λ = F / 1000".into(),
            y_label: "T / N".into(),
            ..Axes::default()
        },
        series: vec![
            Series { label: "computed (converged steps)".into(), points: computed, markers: true },
            Series {
                label: "statics once released: T/N = F/P, capped by μ".into(),
                points: vec![(0.0, 0.0), (slip_factor(), MU), (0.5, MU)],
                markers: false,
            },
        ],
    });
    Ok(report)
}

fn missing(reason: &str) -> VerifyError {
    VerifyError::Missing { case: "clamped_block".into(), reason: reason.into() }
}

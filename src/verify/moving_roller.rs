//! The moving roller of finite sliding (`scenes/generic/moving_roller.toml`): an elastic steel
//! roller (R = 50 mm) pressed into an aluminium block by its top, then driven along the block by
//! 16 block cells (h = a/32, half a Hertz half-width) in moves of h/2 with `sliding = "finite"`,
//! frictionless, plane strain, segment-to-segment pairs. The Hertz pressure travels with it.
//!
//! ```text
//! E* = [(1−ν1²)/E1 + (1−ν2²)/E2]⁻¹,  a = √(4FR/(πE*)),  p0 = 2F/(πa)   (the gallery's Hertz form,
//!                                     evaluated at the step's measured normal force F = Σ λ_k)
//! pressure centre  x_c = Σ λ_k (X_k + u_k)·e1 / Σ λ_k  =  d   (d: the driven top's u1;
//!                                     frictionless and symmetric, the pressure is centred under it)
//! energy  W = E + D,  D = 0              (W: trapezoid work of the loads and reactions, E: stored
//!                                     strain energy; frictionless contact dissipates nothing)
//! ```
//!
//! Source: Johnson, *Contact Mechanics* (1985) §4.2 (the closed form of the gallery's `hertz`
//! case). Each position is one step: finite sliding forms the step's pairs again on its answer
//! until they hold (`contact2d_contact::finite_sliding`), so the pressure sits under the roller at
//! every position with no settle step; every step after the press is checked.
//!
//! Measures as the `hertz` case takes them, on the undeformed master curve (small strain: the
//! closed form's lengths and tractions are per undeformed length, while finite sliding forms each
//! step's pairs, their arc lengths and tributary lengths on the current curve, shorter by the
//! roller's surface strain, 0.4 % here): a is half the contact length along the roller's arc
//! between the zone ends placed where the gap opens like the 3/2 power
//! (`crate::generic::zones`), p(0) the pressure λ/w of the pair of the roller's lowest node.
//!
//! Tolerances, at every step after the press: a within 1 % and p(0) within 1.5 %, the
//! gallery's Hertz ones (asserted there on its finest mesh, 32 cells across a, as here; a/R =
//! 0.06 and a block 100 mm deep and 100 mm longer than the path on either side keep the
//! half-plane closed form); the pressure centre within h/10 of d (no lag: the pairs are those of
//! the step's answer; the meshes' asymmetry is what is left); the energy balance |W − E − D| ≤ 1 %
//! of E at every step from the end of the press: the press is displacement driven in four steps
//! and the trapezoid rule errs where the contact stiffens as it grows (5.4 %, 1.7 %, 0.8 %, 0.5 %
//! of E after steps 1–4).

use std::f64::consts::PI;
use std::path::Path;

use contact2d_contact::{BuiltProblem, PairState, SolvedStep};

use super::{CaseReport, Check, Figure, Measurement, Tolerance, VerifyError, gallery_scene, mesh_override, scene_path};
use crate::generic::solve_generic_streaming;
use crate::generic::zones::zone_length;
use crate::output::chart::{Axes, Series};

use super::Level;

const SCENE: &str = "scenes/generic/moving_roller.toml";
/// The mesh the case is checked on (level 3, 32 cells across a): the scene file's own mesh is
/// level 1 (8 cells across a), for quick runs and the every-scene tests.
const MESH: &str = "moving_roller_L3.msh";
const CONTACT: &str = "roller";
const DRIVEN: &str = "roller_top";
const R: f64 = 50.0;
/// The block cell along the path (the mesh: a = 3 mm, 32 cells across a on level 3).
pub const CELL: f64 = 3.0 / 32.0;
/// Steps of the press (the drive starts after them).
const PRESS_STEPS: usize = 4;

/// E* of the steel roller and the aluminium block (the gallery's materials).
fn e_star() -> f64 {
    1.0 / ((1.0 - 0.09) / 210_000.0 + (1.0 - 0.09) / 70_000.0)
}

/// The Hertz half-width and peak pressure at normal force `force` per unit thickness:
/// `a = √(4FR/(πE*))`, `p0 = 2F/(πa)`.
pub fn closed_form(force: f64) -> (f64, f64) {
    let a = (4.0 * force * R / (PI * e_star())).sqrt();
    (a, 2.0 * force / (PI * a))
}

/// One solved step measured.
#[derive(Debug, Clone, PartialEq)]
pub struct RollerStep {
    /// The driven top's displacement u1 (the roller's travel).
    pub drive: f64,
    /// F = Σ λ over the interface.
    pub force: f64,
    /// Half the contact length along the undeformed master curve.
    pub a: f64,
    /// λ / w (undeformed tributary length) at the roller's lowest node.
    pub p_centre: f64,
    /// The pressure centre Σ λ x / Σ λ on the current configuration.
    pub centre: f64,
    /// Work of the loads and reactions up to the step.
    pub work: f64,
    /// Stored strain energy.
    pub stored: f64,
    /// Friction dissipation up to the step.
    pub dissipated: f64,
    /// The profile: current x of the master nodes and λ / w.
    pub profile: Vec<(f64, f64)>,
}

/// The master-curve data of the undeformed configuration: per pair (index into the interface)
/// its arc length and tributary length, and the pair of the lowest node.
struct Undeformed {
    arc: Vec<f64>,
    weight: Vec<f64>,
    order: Vec<usize>,
    lowest: usize,
}

impl Undeformed {
    /// From the first step's problem, whose pairs are formed on the undeformed configuration.
    fn of(built: &BuiltProblem) -> Option<Undeformed> {
        let iface = built.interfaces.iter().find(|i| i.name == CONTACT)?;
        let pairs = &built.problem.pairs[iface.pairs.clone()];
        let points = &built.problem.model.mesh.points;
        let mut order: Vec<usize> = (0..pairs.len()).collect();
        order.sort_by(|a, b| pairs[*a].master_arc_length.total_cmp(&pairs[*b].master_arc_length));
        let lowest =
            (0..pairs.len()).min_by(|a, b| points[pairs[*a].master.0][1].total_cmp(&points[pairs[*b].master.0][1]))?;
        Some(Undeformed {
            arc: pairs.iter().map(|p| p.master_arc_length).collect(),
            weight: pairs.iter().map(|p| p.weight).collect(),
            order,
            lowest,
        })
    }
}

/// Measures one step solved on `built` (its pairs formed at the step's start).
fn measure_step(built: &BuiltProblem, step: &SolvedStep, reference: &Undeformed) -> Option<RollerStep> {
    let iface = built.interfaces.iter().find(|i| i.name == CONTACT)?;
    let problem = &built.problem;
    let s = &step.solution;
    let u = &s.displacement;
    let first = iface.pairs.start;
    let points = &problem.model.mesh.points;
    let x_now = |k: usize| {
        let m = problem.pairs[first + k].master.0;
        points[m][0] + u[2 * m]
    };
    let lambda = |k: usize| s.normal_force[first + k];
    let n = iface.pairs.len();
    let force: f64 = (0..n).map(lambda).sum();
    let centre = (0..n).map(|k| lambda(k) * x_now(k)).sum::<f64>() / force;
    let ordered = &reference.order;
    let arc: Vec<f64> = ordered.iter().map(|&k| reference.arc[k]).collect();
    let in_contact: Vec<bool> = ordered.iter().map(|&k| s.state[first + k] != PairState::Free).collect();
    let gap: Vec<f64> = ordered.iter().map(|&k| s.gap[first + k].max(0.0)).collect();
    let a = 0.5 * zone_length(&arc, &in_contact, &gap, &in_contact);
    let top = problem.model.mesh.group_nodes(DRIVEN).ok()?;
    let drive = u[2 * top.first()?.0];
    Some(RollerStep {
        drive,
        force,
        a,
        p_centre: lambda(reference.lowest) / reference.weight[reference.lowest],
        centre,
        work: 0.0,
        stored: 0.0,
        dissipated: 0.0,
        profile: ordered.iter().map(|&k| (x_now(k), lambda(k) / reference.weight[k])).collect(),
    })
}

/// Solves the scene on its level-3 mesh (`moving_roller_L3.msh`; the scene file's own is the coarse level 1)
/// with `overrides` after it, and measures every step.
///
/// # Errors
/// A scene that cannot be read or solved, a step that does not converge, or a missing interface.
pub fn measure(root: &Path, overrides: &[String]) -> Result<Vec<RollerStep>, VerifyError> {
    let missing = |reason: String| VerifyError::Missing { case: "moving_roller".into(), reason };
    let mut sets = vec![mesh_override(MESH)];
    sets.extend_from_slice(overrides);
    let scene = gallery_scene(&scene_path(root, SCENE), &sets)?;
    let mut reference: Option<Undeformed> = None;
    let mut steps: Vec<Option<RollerStep>> = vec![];
    let out = solve_generic_streaming(&scene, &mut |_, _| {}, &mut |built, _, step| {
        if reference.is_none() {
            reference = Undeformed::of(built);
        }
        steps.push(reference.as_ref().and_then(|r| measure_step(built, step, r)));
    })?;
    if out.report.status != "converged" {
        return Err(missing(format!("status {}", out.report.status)));
    }
    let mut measured = vec![];
    for (i, (row, step)) in out.report.steps.iter().zip(steps).enumerate() {
        let mut step = step.ok_or_else(|| missing(format!("step {}: no interface \"{CONTACT}\"", i + 1)))?;
        step.work = row.work;
        step.stored = row.energies.values().sum();
        step.dissipated = row.dissipated;
        measured.push(step);
    }
    Ok(measured)
}

/// The worst value of `f` over `steps` by absolute value, with its step (from 1); a value that is
/// not a number is the worst (so that its check fails).
fn worst(steps: &[(usize, &RollerStep)], f: impl Fn(&RollerStep) -> f64) -> (usize, f64) {
    steps
        .iter()
        .map(|(i, s)| (*i, f(s)))
        .fold((0, 0.0), |w, (i, v)| if w.1.is_nan() || v.abs() <= w.1.abs() { w } else { (i, v) })
}

/// Runs the case (one mesh: the level does not change it).
///
/// # Errors
/// A scene that cannot be read or solved.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let steps = measure(root, &[])?;
    let mut report = CaseReport {
        name: "moving_roller".into(),
        source: "Hertz (Johnson, Contact Mechanics §4.2) under a roller driven along the block with finite sliding"
            .into(),
        ..CaseReport::default()
    };
    let numbered: Vec<(usize, &RollerStep)> = steps.iter().enumerate().map(|(i, s)| (i + 1, s)).collect();
    // After the press: one step per position.
    let settled: Vec<(usize, &RollerStep)> = numbered.get(PRESS_STEPS..).unwrap_or_default().to_vec();
    let from_press = numbered.get(PRESS_STEPS - 1..).unwrap_or_default();
    if settled.is_empty() {
        return Err(VerifyError::Missing { case: "moving_roller".into(), reason: "no step after the press".into() });
    }
    let a_error = |s: &RollerStep| s.a / closed_form(s.force).0 - 1.0;
    let p_error = |s: &RollerStep| s.p_centre / closed_form(s.force).1 - 1.0;
    let offset = |s: &RollerStep| (s.centre - s.drive) / CELL;
    let balance = |s: &RollerStep| (s.work - s.stored - s.dissipated) / s.stored;
    let travel = settled.last().map_or(0.0, |(_, s)| s.drive / CELL);
    let mesh = format!("32 cells across a, {} positions, travel {travel:.1} cells", settled.len());
    let check = |quantity: &str, (step, measured): (usize, f64), tolerance: Tolerance| Check {
        quantity: format!("{quantity}, worst step ({step})"),
        mesh: mesh.clone(),
        measured,
        reference: 0.0,
        tolerance,
    };
    report.checks.extend([
        check("moving: a / a_Hertz − 1", worst(&settled, a_error), Tolerance::Absolute(0.01)),
        check("moving: p(0) / p0 − 1", worst(&settled, p_error), Tolerance::Absolute(0.015)),
        check("moving: (x_c − d) / h", worst(&settled, offset), Tolerance::Absolute(0.1)),
        check("(W − E − D) / E from the end of the press", worst(from_press, balance), Tolerance::Absolute(0.01)),
    ]);
    let mut add = |quantity: String, value: f64| {
        report.measurements.push(Measurement { quantity, mesh: "32 cells across a".into(), value });
    };
    add(
        "(W − E − D) / E after step 1 (the press's first step)".into(),
        numbered.first().map_or(f64::NAN, |s| balance(s.1)),
    );
    for (i, s) in settled.iter().step_by(8).chain(settled.last()) {
        add(format!("step {i} (d = {:.1} h): a / a_Hertz − 1", s.drive / CELL), a_error(s));
        add(format!("step {i} (d = {:.1} h): p(0) / p0 − 1", s.drive / CELL), p_error(s));
        add(format!("step {i} (d = {:.1} h): (x_c − d) / h", s.drive / CELL), offset(s));
        add(format!("step {i} (d = {:.1} h): (W − E − D) / E", s.drive / CELL), balance(s));
    }
    report.figures.push(figure(&settled));
    Ok(report)
}

/// The pressure along the block at five positions of the travel, against Hertz centred
/// on the driven top (each at its step's force).
fn figure(settled: &[(usize, &RollerStep)]) -> Figure {
    let mut series = vec![];
    let mut curves = vec![];
    let last = settled.len().saturating_sub(1);
    for q in 0..=4 {
        let Some((i, s)) = settled.get(q * last / 4) else { continue };
        let (a, p0) = closed_form(s.force);
        curves.push((s.drive, a));
        series.push(Series {
            label: format!("step {i}, d = {:.1} h", s.drive / CELL),
            points: s
                .profile
                .iter()
                .filter(|(x, _)| (x - s.drive).abs() <= 1.3 * a)
                .map(|(x, p)| (*x, p / p0))
                .collect(),
            markers: true,
        });
    }
    for (k, (d, a)) in curves.iter().enumerate() {
        series.push(Series {
            label: if k == 0 { "Hertz, centred on the driven top".into() } else { String::new() },
            points: (0..=200)
                .map(|j| -1.3 + 2.6 * f64::from(j) / 200.0)
                .map(|t| (d + t * a, (1.0 - t * t).max(0.0).sqrt()))
                .collect(),
            markers: false,
        });
    }
    Figure {
        file: "moving_roller_pressure.svg".into(),
        axes: Axes {
            title: "Moving roller, finite sliding: the Hertz pressure travels with the roller".into(),
            x_label: "x on the block (mm)".into(),
            y_label: "p / p0".into(),
            ..Axes::default()
        },
        series,
    }
}

//! Friction threshold on an incline (`scenes/generic/incline_push.toml`): an elastic block under
//! its own weight G (a body force) on a rigid incline, tan α = 0.1, μ = 0.3, pushed up the slope by
//! a horizontal force F with the weight held.
//!
//! ```text
//! statics of the block (held only by the contact):  N = G cos α + F sin α,  T = F cos α − G sin α
//! Coulomb, gross sliding up the slope:  T = μ N  ⇔  F/G = (tan α + μ) / (1 − μ tan α) = 0.412371…
//! ```
//!
//! Source: rigid-body statics with Coulomb's law (e.g. Meriam & Kraige, *Engineering Mechanics:
//! Statics*, §6/2, the block pushed up an incline). The discrete Coulomb law holds pair by pair
//! (|τ_k| ≤ μ λ_k) and the pair forces sum to N and T exactly, so the discrete onset is the closed
//! form's; the elastic block only decides how the slip zone grows before it.
//!
//! Checks and tolerances: N and T at every step against statics within 1e-8 relative (the
//! floating body's proximal iteration stops when the springs carry less than 1e-10 of the force
//! scale); the onset, bracketed by bisection on F/G between a step that converges and one whose
//! block is not held, within 0.5 % (the issue's target; the bracket is 2e-5 wide).

use std::path::Path;

use contact2d_contact::ContactError;

use super::{CaseReport, Check, Figure, Level, Measurement, Tolerance, VerifyError, gallery_scene, scene_path};
use crate::generic::{GenericError, solve_generic};
use crate::output::chart::{Axes, Series};

const SCENE: &str = "scenes/generic/incline_push.toml";
const SLOPE: f64 = 0.1;
const MU: f64 = 0.3;
/// The block's weight per unit thickness: ρ g = 1e-5 N/mm³ on 40 × 10 mm (the scene's values).
const WEIGHT: f64 = 4e-3;

/// F/G at the onset of gross sliding.
pub fn onset_closed_form() -> f64 {
    (SLOPE + MU) / (1.0 - MU * SLOPE)
}

/// Runs the case: the scene's push history, then the bisection for the onset.
///
/// # Errors
/// A scene that cannot be read or solved below the onset.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let path = scene_path(root, SCENE);
    let out = solve_generic(&gallery_scene(&path, &[])?, &mut |_, _| {})?;
    let alpha = SLOPE.atan();
    let mut report = CaseReport {
        name: "incline".into(),
        source: "rigid-body statics with Coulomb friction: onset F/G = (tan α + μ)/(1 − μ tan α)".into(),
        ..CaseReport::default()
    };
    let mut stick = vec![];
    for step in out.report.steps.iter() {
        let push = step.factors.get("push").copied().unwrap_or(0.0);
        let contact = step.contacts.get("incline").ok_or_else(|| missing("no interface \"incline\""))?;
        let f = push * WEIGHT;
        let mesh = format!("F/G = {push}");
        let statics = [
            ("N", contact.normal_force, WEIGHT * alpha.cos() + f * alpha.sin()),
            ("T", contact.tangential_force, f * alpha.cos() - WEIGHT * alpha.sin()),
        ];
        for (name, measured, reference) in statics {
            // T passes through zero at F/G = tan α: compare it on the force scale G there.
            let tolerance = if reference.abs() < 1e-3 * WEIGHT {
                Tolerance::Absolute(1e-8 * WEIGHT)
            } else {
                Tolerance::Relative(1e-8)
            };
            report.checks.push(Check {
                quantity: format!("{name} (statics)"),
                mesh: mesh.clone(),
                measured,
                reference,
                tolerance,
            });
        }
        if step.status != "converged" {
            report.notes.push(format!("step at F/G = {push}: {}", step.status));
        }
        stick.push((push, contact.stick_length / contact.contact_length.max(f64::MIN_POSITIVE)));
    }
    let (held, slides) = bisect_onset(&path, 0.40, 0.42, 10)?;
    report.checks.push(Check {
        quantity: "onset of gross sliding F/G".into(),
        mesh: format!("bracket [{held:.6}, {slides:.6}]"),
        measured: 0.5 * (held + slides),
        reference: onset_closed_form(),
        tolerance: Tolerance::Relative(0.005),
    });
    report.measurements.extend(stick.iter().map(|(push, fraction)| Measurement {
        quantity: "stick fraction of the contact".into(),
        mesh: format!("F/G = {push}"),
        value: *fraction,
    }));
    report.figures.push(Figure {
        file: "incline_stick_fraction.svg".into(),
        axes: Axes {
            title: "Block on an incline: partial slip before gross sliding".into(),
            x_label: "F/G".into(),
            y_label: "stick length / contact length".into(),
            ..Axes::default()
        },
        series: vec![
            Series { label: "computed".into(), points: stick, markers: true },
            Series {
                label: "closed-form onset of sliding".into(),
                points: vec![(onset_closed_form(), 0.0), (onset_closed_form(), 1.0)],
                markers: false,
            },
        ],
    });
    Ok(report)
}

/// Brackets the onset: `held` converges with the block held, `slides` leaves it not held.
fn bisect_onset(path: &Path, mut held: f64, mut slides: f64, halvings: usize) -> Result<(f64, f64), VerifyError> {
    for _ in 0..halvings {
        let mid = 0.5 * (held + slides);
        if is_held(path, mid)? {
            held = mid;
        } else {
            slides = mid;
        }
    }
    Ok((held, slides))
}

/// Whether the block is held at `F/G = push` (weight applied first, then the push in one step).
fn is_held(path: &Path, push: f64) -> Result<bool, VerifyError> {
    let schedule = format!("loading.schedule=[{{weight = 1.0}}, {{weight = 1.0, push = {push}}}]");
    let scene = gallery_scene(path, &[schedule])?;
    match solve_generic(&scene, &mut |_, _| {}) {
        Ok(out) => Ok(out.report.status == "converged"),
        Err(GenericError::Contact { source, .. }) if matches!(*source, ContactError::BodyNotHeld { .. }) => Ok(false),
        Err(e) => Err(e.into()),
    }
}

fn missing(reason: &str) -> VerifyError {
    VerifyError::Missing { case: "incline".into(), reason: reason.into() }
}

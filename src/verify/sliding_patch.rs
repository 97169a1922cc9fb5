//! The sliding patch test of finite sliding (`scenes/generic/sliding_patch_*.toml`): an elastic
//! block (E = 1000, ν = 0, 1 × 0.5) pressed by p = 10 onto a long rigid flat, then its top
//! driven 1.5 along it (15 block cells, 30 steps) with `sliding = "finite"`, μ = 0.3.
//!
//! ```text
//! uniform sliding state:  σ = [[0, μp], [μp, −p]]    (side tractions (0, ±μp) applied)
//! pressure p_k = p at every pair;  T = μ P = μ p · 1 = 3
//! stored energy  E = ½ (p²/E + (μp)²/G) · A = 0.0295      (G = E/2 at ν = 0, A = 0.5)
//! energy balance per step:  ΔW = ΔE + ΔD                  (W: trapezoid work of the loads
//!                                                          and reactions; D: Coulomb's τ Δs)
//! ```
//!
//! Source: closed form (a uniform stress meets every boundary and Coulomb condition; ν = 0 makes
//! it compatible with the top's uniform prescribed u1). Quadratic elements reproduce it exactly,
//! so the tolerances are round-off: 1e-6 for force, pressure and stored energy (the issue's), and
//! 1e-9 of the step's work for the balance. Checked at every step from the second push on (at
//! the first push's start the interface still sticks: the trapezoid rule of the work is exact
//! only when the states do not change within a step, so that step's gap is reported, not
//! asserted). The worst value over those steps is the check's measured value.

use std::path::Path;

use super::{CaseReport, Check, Level, Measurement, Tolerance, VerifyError, gallery_scene, scene_path};
use crate::generic::{GenericReport, solve_generic};

const SCENES: [(&str, &str); 2] = [
    ("matching", "scenes/generic/sliding_patch_matching.toml"),
    ("non-matching", "scenes/generic/sliding_patch_nonmatching.toml"),
];
const P: f64 = 10.0;
const MU: f64 = 0.3;
/// `½ (p²/E + (μp)²/G) · A` of the module docs.
const STORED: f64 = 0.0295;
/// The first step (from 1) whose start already slips: steps 1–2 press, step 3 the first push.
const FIRST_STEADY: usize = 4;

/// The worst deviations over the steady steps of one run.
#[derive(Debug, Default)]
struct Worst {
    tangential: f64,
    pressure: f64,
    stored: f64,
    balance: f64,
    /// The largest change of a pair's pressure from one step to the next, relative to p.
    jump: f64,
}

/// Runs the case on both meshes (the level does not change them: they are the patch test's).
///
/// # Errors
/// A scene that cannot be read or solved, or a step without the interface's profile.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let mut report = CaseReport {
        name: "sliding_patch".into(),
        source: "closed form: the uniform sliding state σ = [[0, μp], [μp, −p]] of a block on a rigid flat".into(),
        ..CaseReport::default()
    };
    for (mesh, scene) in SCENES {
        let mut scene = gallery_scene(&scene_path(root, scene), &[])?;
        scene.every_profile = true;
        let out = solve_generic(&scene, &mut |_, _| {})?;
        let (worst, transition) = measure(&out.report)?;
        let check = |q: &str, m: f64, r: f64, t: Tolerance| Check::on(mesh, q, m, r, t);
        report.checks.extend([
            check("tangential force T / (μP), worst step", worst.tangential, 1.0, Tolerance::Relative(1e-6)),
            check("max abs(p_k − p) / p, worst step", worst.pressure, 0.0, Tolerance::Absolute(1e-6)),
            check("stored energy / closed form, worst step", worst.stored, 1.0, Tolerance::Relative(1e-6)),
            check("abs(ΔW − ΔE − ΔD) / ΔW, worst step", worst.balance, 0.0, Tolerance::Absolute(1e-9)),
        ]);
        report.measurements.extend([
            Measurement {
                quantity: "largest step-to-step pressure change / p".into(),
                mesh: mesh.into(),
                value: worst.jump,
            },
            Measurement {
                quantity: "(W − E − D) / W after the first push (stick to slip within the step)".into(),
                mesh: mesh.into(),
                value: transition,
            },
        ]);
    }
    Ok(report)
}

/// The worst deviations over the steady steps, and the energy gap after the first push.
fn measure(report: &GenericReport) -> Result<(Worst, f64), VerifyError> {
    let missing = |reason: String| VerifyError::Missing { case: "sliding_patch".into(), reason };
    let steps = &report.steps.to_vec();
    if steps.len() <= FIRST_STEADY {
        return Err(missing(format!("{} steps solved, more than {FIRST_STEADY} expected", steps.len())));
    }
    let stored = |i: usize| steps[i].energies.values().sum::<f64>();
    let first = &steps[FIRST_STEADY - 2];
    let transition = (first.work - stored(FIRST_STEADY - 2) - first.dissipated) / first.work;
    // The ratios start at their exact value, the deviations at zero.
    let mut worst = Worst { tangential: 1.0, stored: 1.0, ..Worst::default() };
    let mut before: Option<Vec<f64>> = None;
    for i in FIRST_STEADY - 1..steps.len() {
        let contact = steps[i].contacts.get("slide").ok_or_else(|| missing("no interface \"slide\"".into()))?;
        let profile = contact.profile.as_ref().ok_or_else(|| missing(format!("step {}: no profile", i + 1)))?;
        let t = contact.tangential_force.abs() / (MU * P);
        worst.tangential = if (t - 1.0).abs() > (worst.tangential - 1.0).abs() { t } else { worst.tangential };
        let deviation = profile.pressure.iter().fold(0.0f64, |m, p| m.max((p - P).abs() / P));
        worst.pressure = worst.pressure.max(deviation);
        let e = stored(i) / STORED;
        worst.stored = if (e - 1.0).abs() > (worst.stored - 1.0).abs() { e } else { worst.stored };
        let work = steps[i].work - steps[i - 1].work;
        let balance = work - (stored(i) - stored(i - 1)) - (steps[i].dissipated - steps[i - 1].dissipated);
        worst.balance = worst.balance.max((balance / work).abs());
        if let Some(b) = &before {
            let jump = b.iter().zip(&profile.pressure).fold(0.0f64, |m, (a, p)| m.max((p - a).abs() / P));
            worst.jump = worst.jump.max(jump);
        }
        before = Some(profile.pressure.clone());
    }
    Ok((worst, transition))
}

//! Cattaneo–Mindlin partial slip (`scenes/generic/cattaneo_mindlin.toml`): a steel roller
//! (R = 50 mm) pressed on a steel block, then sheared with the press held, μ = 0.3, plane strain.
//!
//! ```text
//! elastically similar bodies (same E, ν): the normal and tangential problems uncouple
//! E* = E / (2 (1 − ν²)),  a = √(4 P R / (π E*)),  p0 = 2 P / (π a)
//! stick half-width  c = a √(1 − Q / (μ P))
//! q(x) = μ p0 [√(1 − x²/a²) − (c/a) √(1 − x²/c²)]      (second term only for |x| < c)
//! ```
//!
//! Source: C. Cattaneo (1938), R. D. Mindlin (1949); K. L. Johnson, *Contact Mechanics* (1985),
//! §7.1. P and Q are the measured reactions of the driven top face, so the closed form is
//! evaluated at the forces the model carries.
//!
//! Checks at the finest mesh run (tolerances from the issue): c/a within 2 % at each of the three
//! ratios Q/(μP) ≈ 0.25, 0.5, 0.75 (c measured as half the stick zone, its ends placed where the
//! slip opens like the 3/2 power, as the flagship places b); the shear profile's L2 error over
//! |x| ≤ a within 3 % of μ p0. The closed form is for half-spaces with a ≪ R: the scene keeps
//! a/R = 0.01, where the roller's bulk tension ~P/(πR) (absent from the block) shifts the stick
//! zone by about 0.5 % of a (see `meshes/generic/cattaneo_mindlin.geo`). Coarser meshes and a
//! load-step study are reported as measurements.

use std::f64::consts::PI;
use std::path::Path;

use super::profile::l2_error;
use super::{
    CaseReport, Check, Figure, Level, Measurement, Tolerance, VerifyError, gallery_scene, mesh_override, scene_path,
    solve_on_mesh,
};
use crate::generic::GenericOutcome;
use crate::generic::results::contact_result;
use crate::output::chart::{Axes, Series};

const SCENE: &str = "scenes/generic/cattaneo_mindlin.toml";
const E: f64 = 210_000.0;
const NU: f64 = 0.3;
const R: f64 = 50.0;
const MU: f64 = 0.3;

/// The closed form at the measured forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedForm {
    /// Contact half-width.
    pub a: f64,
    /// Peak pressure.
    pub p0: f64,
    /// Stick half-width.
    pub c: f64,
}

impl ClosedForm {
    /// Hertz and Cattaneo–Mindlin for normal force `p` and tangential force `q` per unit
    /// thickness.
    pub fn new(p: f64, q: f64) -> ClosedForm {
        let e_star = E / (2.0 * (1.0 - NU * NU));
        let a = (4.0 * p * R / (PI * e_star)).sqrt();
        ClosedForm { a, p0: 2.0 * p / (PI * a), c: a * (1.0 - q.abs() / (MU * p)).max(0.0).sqrt() }
    }

    /// The shear traction magnitude at `x`.
    pub fn shear(&self, x: f64) -> f64 {
        let root = |x: f64, h: f64| (1.0 - (x / h).powi(2)).max(0.0).sqrt();
        let stick = if x.abs() < self.c { (self.c / self.a) * root(x, self.c) } else { 0.0 };
        MU * self.p0 * (root(x, self.a) - stick)
    }
}

/// One sheared step measured: Q/(μP), the closed form, c_h, the profile (x, q·sign Q).
struct Sheared {
    ratio: f64,
    exact: ClosedForm,
    c: f64,
    shear: Vec<(f64, f64)>,
}

/// Every sheared step of a solved scene.
fn sheared_steps(out: &GenericOutcome) -> Result<Vec<Sheared>, VerifyError> {
    let iface = out.built.interfaces.first().ok_or_else(|| missing("the scene has no contact"))?;
    let mut steps = vec![];
    for (result, step) in out.report.steps.iter().zip(&out.history.steps) {
        if result.factors.get("shear").is_none_or(|f| *f == 0.0) {
            continue;
        }
        let [Some(q), Some(p)] =
            *result.reactions.get("cylinder_top").ok_or_else(|| missing("no reaction on cylinder_top"))?
        else {
            return Err(missing("cylinder_top is not driven in both directions"));
        };
        let p = -p;
        let exact = ClosedForm::new(p, q);
        let contact = contact_result(&out.built, iface, &step.solution, 0.0, true);
        let profile = contact.profile.ok_or_else(|| missing("no profile"))?;
        let sign = contact.tangential_force.signum();
        let shear = profile.x.iter().zip(&profile.shear).map(|(x, s)| (*x, sign * s)).collect();
        steps.push(Sheared { ratio: q.abs() / (MU * p), exact, c: 0.5 * contact.stick_length, shear });
    }
    Ok(steps)
}

/// Solves the scene on `mesh` with optional extra overrides.
fn solve(root: &Path, mesh: &str, extra: &[String]) -> Result<GenericOutcome, VerifyError> {
    solve_on_mesh(root, SCENE, mesh, extra)
}

/// The L2 error of a step's shear profile over |x| ≤ a, relative to μ p0.
fn shear_error(s: &Sheared) -> f64 {
    l2_error(&s.shear, -s.exact.a, s.exact.a, |x| s.exact.shear(x)).map_or(f64::NAN, |e| e / (MU * s.exact.p0))
}

/// Runs the case over the mesh levels of `level`, then the load-step study on the finest.
///
/// # Errors
/// A scene that cannot be read or solved.
pub fn run(root: &Path, level: Level) -> Result<CaseReport, VerifyError> {
    let levels: &[&str] = match level {
        Level::Fast => &["L1", "L2"],
        Level::Full => &["L1", "L2", "L3"],
    };
    let mut report = CaseReport {
        name: "cattaneo_mindlin".into(),
        source: "Cattaneo (1938), Mindlin (1949); Johnson, Contact Mechanics §7.1".into(),
        ..CaseReport::default()
    };
    let mut finest = vec![];
    for (i, l) in levels.iter().enumerate() {
        let out = solve(root, &format!("cattaneo_mindlin_{l}.msh"), &[])?;
        if out.report.status != "converged" {
            report.notes.push(format!("{l}: status {}", out.report.status));
        }
        let steps = sheared_steps(&out)?;
        let last = i + 1 == levels.len();
        for s in &steps {
            let at = format!("Q/(μP) = {:.3}", s.ratio);
            let (c_ratio, error) = (s.c / s.exact.a, shear_error(s));
            if last {
                report.checks.push(Check {
                    quantity: format!("c/a at {at}"),
                    mesh: l.to_string(),
                    measured: c_ratio,
                    reference: s.exact.c / s.exact.a,
                    tolerance: Tolerance::Relative(0.02),
                });
                report.checks.push(Check {
                    quantity: format!("shear L2 error / μp0 at {at}"),
                    mesh: l.to_string(),
                    measured: error,
                    reference: 0.0,
                    tolerance: Tolerance::Absolute(0.03),
                });
            } else {
                report.measurements.push(Measurement {
                    quantity: format!("c/a at {at}"),
                    mesh: l.to_string(),
                    value: c_ratio,
                });
                report.measurements.push(Measurement {
                    quantity: format!("shear L2 error / μp0 at {at}"),
                    mesh: l.to_string(),
                    value: error,
                });
            }
        }
        if last {
            finest = steps;
            step_study(root, l, &mut report)?;
        }
    }
    report.figures.push(figure(&finest, levels.last().copied().unwrap_or("L1")));
    Ok(report)
}

/// The last shear step reached in 1, 2 and 4 equal increments after the press: c/a and the
/// shear error should not depend on the increments (monotone loading).
fn step_study(root: &Path, mesh: &str, report: &mut CaseReport) -> Result<(), VerifyError> {
    let file = format!("cattaneo_mindlin_{mesh}.msh");
    let scene = gallery_scene(&scene_path(root, SCENE), &[mesh_override(&file)])?;
    let schedule = scene.schedule()?;
    let at = schedule.patterns().iter().position(|p| p == "shear");
    let last_shear = at.and_then(|i| schedule.steps().last().map(|f| f[i]));
    let last_shear = last_shear.ok_or_else(|| missing("no shear pattern in the schedule"))?;
    for n in [1usize, 2, 4] {
        let steps: Vec<String> =
            (1..=n).map(|k| format!("{{press = 1.0, shear = {}}}", last_shear * k as f64 / n as f64)).collect();
        let schedule = format!("loading.schedule=[{{press = 1.0}}, {}]", steps.join(", "));
        let out = solve(root, &file, &[schedule])?;
        let s = sheared_steps(&out)?.pop().ok_or_else(|| missing("no sheared step"))?;
        let at = format!("{mesh}, {n} shear step(s)");
        report.measurements.push(Measurement {
            quantity: "step study: c/a".into(),
            mesh: at.clone(),
            value: s.c / s.exact.a,
        });
        report.measurements.push(Measurement {
            quantity: "step study: shear L2 error / μp0".into(),
            mesh: at,
            value: shear_error(&s),
        });
    }
    Ok(())
}

/// q/(μ p0) against x/a: computed (markers) and closed form (lines), per ratio.
fn figure(steps: &[Sheared], mesh: &str) -> Figure {
    let mut series = vec![];
    for s in steps {
        let (a, scale) = (s.exact.a, MU * s.exact.p0);
        let computed = s.shear.iter().filter(|(x, _)| x.abs() <= 1.1 * a).map(|(x, q)| (x / a, q / scale)).collect();
        let exact =
            (0..=400).map(|k| -1.1 + 2.2 * f64::from(k) / 400.0).map(|t| (t, s.exact.shear(t * a) / scale)).collect();
        series.push(Series { label: format!("{mesh}, Q/(μP) = {:.2}", s.ratio), points: computed, markers: true });
        series.push(Series {
            label: format!("closed form, c/a = {:.3}", s.exact.c / a),
            points: exact,
            markers: false,
        });
    }
    Figure {
        file: "cattaneo_mindlin_shear.svg".into(),
        axes: Axes {
            title: "Cattaneo–Mindlin: shear traction under partial slip".into(),
            x_label: "x / a".into(),
            y_label: "q / (μ p0)".into(),
            ..Axes::default()
        },
        series,
    }
}

fn missing(reason: &str) -> VerifyError {
    VerifyError::Missing { case: "cattaneo_mindlin".into(), reason: reason.into() }
}

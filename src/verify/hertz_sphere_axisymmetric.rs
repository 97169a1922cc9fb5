//! Hertz's sphere on a flat as bodies of revolution: a steel hemisphere of radius R = 10 mm
//! pressed by a total force P = 8000 N onto an aluminium block of radius and depth 40 mm,
//! frictionless (`scenes/generic/hertz_sphere_axisymmetric.toml`, `kinematics = "axisymmetric"`),
//! on two mesh levels of every element type (T3 T6 Q4 Q8 Q9,
//! `meshes/generic/hertz_sphere_axisymmetric_{kind}_L{1,2}.msh`).
//!
//! ```text
//! 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2,  a = (3PR/(4E*))^⅓ = 1.0132 mm,
//! p0 = 3P/(2πa²) = 3721.1 MPa,  p(r) = p0 √(1 − r²/a²)
//! ```
//!
//! Source: H. Hertz (1882); K. L. Johnson, *Contact Mechanics* (1985), §4.2.
//!
//! Measured: a, the radius of the contact zone's end (the undeformed r of its last point); p0, the
//! least-squares amplitude of p0 √(1 − r²/a²) through the pairs' pressures over r < 0.8a, weighed
//! by r (the ring's measure); the profile's error, the root mean square of p − p(r) over
//! r < 0.8a weighed by r, relative to p0. The pressure at the axis node is reported beside them.
//!
//! Tolerance: h/a on each, h the master nodes' spacing at the contact (a/12 on level 1, a/24 on
//! level 2, every element type: the .geo's grading). The discrete contact zone ends between two
//! nodes, so a is resolved to one spacing; the pressure's amplitude and profile follow the zone's
//! end to first order in h/a. The finite block (a/W = 1/40) moves a and p only at higher order: the
//! compliance it removes is, to first order, a rigid shift of the contact zone (a block 4 times
//! larger changes a by 0.02 % and p0 by 0.06 % on Q9 level 1, docs/verification.md). A wrong
//! measure (a pair weight, load or stiffness without 2πr) is an O(1) error.

use std::f64::consts::PI;
use std::path::Path;

use super::{CaseReport, Check, Level, Measurement, Tolerance, VerifyError, solve_on_mesh};

const SCENE: &str = "scenes/generic/hertz_sphere_axisymmetric.toml";
const P: f64 = 8000.0;
const R: f64 = 10.0;
/// The element types of the bundled meshes, as in their file names.
pub const KINDS: [&str; 5] = ["T3", "T6", "Q4", "Q8", "Q9"];
/// The a the meshes were graded with (`hertz_sphere_axisymmetric.geo`).
const A_GRADING: f64 = 1.013;

/// (a, p0) of the closed form.
pub fn closed_form() -> (f64, f64) {
    let e_star = 1.0 / ((1.0 - 0.09) / 210_000.0 + (1.0 - 0.09) / 70_000.0);
    let a = (3.0 * P * R / (4.0 * e_star)).cbrt();
    (a, 3.0 * P / (2.0 * PI * a * a))
}

/// The master nodes' spacing at the contact on `level` (1, 2): a/12 · 2^(1 − level).
pub fn node_spacing(level: u32) -> f64 {
    A_GRADING / (12.0 * f64::from(1u32 << (level - 1)))
}

/// One mesh measured.
#[derive(Debug, Clone, PartialEq)]
pub struct SphereRun {
    /// The contact zone's radius (its end's undeformed r).
    pub a: f64,
    /// The fitted amplitude p0 over r < 0.8a.
    pub p0: f64,
    /// The pressure of the pair on the axis.
    pub p_axis: f64,
    /// The r-weighed RMS error of the profile over r < 0.8a, relative to p0.
    pub profile_error: f64,
    /// The largest |p − p(r)| / p0 over 0 < r < 0.8a.
    pub profile_max_error: f64,
    /// The total normal force over the circumference.
    pub normal_force: f64,
}

/// The r-weighed least-squares amplitude of `shape` through `(r, p)` samples and the r-weighed
/// RMS error of `p − amplitude_ref · shape` (trapezoid rule on the samples), both over the samples
/// given (sorted by r).
pub(super) fn weighted_fit_and_error(samples: &[(f64, f64)], shape: impl Fn(f64) -> f64, reference: f64) -> (f64, f64) {
    let (num, den) =
        samples.iter().fold((0.0, 0.0), |(n, d), &(r, p)| (n + r * p * shape(r), d + r * shape(r).powi(2)));
    let (mut sum, mut measure) = (0.0, 0.0);
    for w in samples.windows(2) {
        let dr = w[1].0 - w[0].0;
        let e = |(r, p): (f64, f64)| r * (p - reference * shape(r)).powi(2);
        sum += 0.5 * dr * (e(w[0]) + e(w[1]));
        measure += 0.5 * dr * (w[0].0 + w[1].0);
    }
    (if den > 0.0 { num / den } else { f64::NAN }, if measure > 0.0 { (sum / measure).sqrt() } else { f64::NAN })
}

/// Solves the scene on the bundled mesh of `kind` and `level` (`mesh` overrides the file name).
///
/// # Errors
/// A scene that cannot be read or solved, a status other than converged, or no interface `hertz`.
pub fn measure(root: &Path, mesh: &str) -> Result<SphereRun, VerifyError> {
    let out = solve_on_mesh(root, SCENE, mesh, &[])?;
    let missing = |reason: &str| VerifyError::Missing {
        case: "hertz_sphere_axisymmetric".into(),
        reason: format!("{mesh}: {reason}"),
    };
    if out.report.status != "converged" {
        return Err(missing(&format!("status {}", out.report.status)));
    }
    let hertz = out.report.contacts.get("hertz").ok_or_else(|| missing("no interface \"hertz\""))?;
    let profile = hertz.profile.as_ref().ok_or_else(|| missing("no profile"))?;
    let end = hertz.zones.points.last().ok_or_else(|| missing("no contact zone"))?;
    let (a, p0) = closed_form();
    let mut points: Vec<(f64, f64)> = profile.x.iter().copied().zip(profile.pressure.iter().copied()).collect();
    points.sort_by(|u, v| u.0.total_cmp(&v.0));
    let shape = |r: f64| (1.0 - (r / a).powi(2)).max(0.0).sqrt();
    let inner: Vec<(f64, f64)> = points.iter().copied().filter(|(r, _)| *r < 0.8 * a).collect();
    let (fit, error) = weighted_fit_and_error(&inner, shape, p0);
    let max_error =
        inner.iter().filter(|(r, _)| *r > 0.0).map(|(r, p)| (p - p0 * shape(*r)).abs() / p0).fold(0.0, f64::max);
    Ok(SphereRun {
        a: end[0],
        p0: fit,
        p_axis: points.first().map_or(f64::NAN, |q| q.1),
        profile_error: error / p0,
        profile_max_error: max_error,
        normal_force: hertz.normal_force,
    })
}

/// Runs the case: every element type on both levels (both `fast` and `full`: twenty small
/// meshes, under a second in all).
///
/// # Errors
/// A scene that cannot be read or solved.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let (a, p0) = closed_form();
    let mut report = CaseReport {
        name: "hertz_sphere_axisymmetric".into(),
        source: "Hertz's sphere on a flat, bodies of revolution (Johnson, Contact Mechanics §4.2)".into(),
        ..CaseReport::default()
    };
    for level in [1u32, 2] {
        let h = node_spacing(level) / a;
        for kind in KINDS {
            let run = measure(root, &format!("hertz_sphere_axisymmetric_{kind}_L{level}.msh"))?;
            let mesh = format!("{kind} L{level}");
            let check = |q: &str, m: f64, r: f64, t: Tolerance| Check::on(&mesh, q, m, r, t);
            report.checks.push(check("a (mm)", run.a, a, Tolerance::Relative(h)));
            report.checks.push(check("p0, fitted over r < 0.8a (MPa)", run.p0, p0, Tolerance::Relative(h)));
            report.checks.push(check(
                "pressure L2 error / p0, r < 0.8a",
                run.profile_error,
                0.0,
                Tolerance::Absolute(h),
            ));
            for (q, v) in
                [("p at the axis (MPa)", run.p_axis), ("pressure max error / p0, 0 < r < 0.8a", run.profile_max_error)]
            {
                report.measurements.push(Measurement { quantity: q.into(), mesh: mesh.clone(), value: v });
            }
        }
    }
    report.notes.push(format!(
        "tolerance h/a: the master nodes' spacing at the contact over a (1/{:.0} on L1, 1/{:.0} on L2)",
        a / node_spacing(1),
        a / node_spacing(2)
    ));
    Ok(report)
}

//! Boussinesq's rigid flat punch as a body of revolution: a rigid flat-ended cylindrical punch of
//! radius a = 1 mm indenting an elastic cylinder of radius and depth L = 50a (the half-space) by
//! δ = 0.001 mm, frictionless, E = 200 000 MPa, ν = 0.3 (`scenes/generic/punch_axisymmetric.toml`:
//! the punch is a fixed rigid obstacle, exact; the block's bottom is moved up by δ), on two mesh
//! levels of every element type (`meshes/generic/punch_axisymmetric_{kind}_L{1,2}.msh`).
//!
//! ```text
//! P = 2aEδ/(1 − ν²) = 439.56 N (over the circumference),
//! p(r) = P / (2πa √(a² − r²)),  p(0) = P/(2πa²) = 69.96 MPa
//! ```
//!
//! Source: J. Boussinesq (1885); I. N. Sneddon (1946); K. L. Johnson, *Contact Mechanics* (1985),
//! §3.8.
//!
//! Tolerance on P and on the profile's error (the root mean square of p − p(r) over 0 < r ≤ 0.7a,
//! weighed by r, relative to p(0)): 1.09 a/L + h/a, with h the cell size at the punch's edge
//! (a/64 and a/128 for linear cells, a/32 and a/64 for quadratic ones on levels 1 and 2).
//! * The finite domain: holding the bottom at depth L removes the half-space's compliance below it,
//!   about the axial displacement of Boussinesq's point force at that depth,
//!   u_z(L) = P(1 + ν)(3 − 2ν)/(2πEL), i.e. a stiffening u_z(L)/δ = (1 + ν)(3 − 2ν)a/(π(1 − ν²)L)
//!   = 1.09 a/L = 2.2 % (an upper bound: the free side gives some back; measured 1.3 %, from the
//!   same meshes on L = 100a, docs/verification.md).
//! * The singular edge: the displacement near the edge grows as ρ^½, whose energy error on cells
//!   of size h is O(h/a), and P δ/2 is the energy.
//!
//! The profile excludes the node on the axis: on a quadratic edge its ring area ∫N 2πr ds is 0, so
//! its pressure λ/w is not defined (reported 0); the pressure there is reported as a measurement.

use std::f64::consts::PI;
use std::path::Path;

use super::hertz_sphere_axisymmetric::{KINDS, weighted_fit_and_error};
use super::{CaseReport, Check, Level, Measurement, Tolerance, VerifyError, solve_on_mesh};

const SCENE: &str = "scenes/generic/punch_axisymmetric.toml";
const A: f64 = 1.0;
/// The block's radius and depth over a.
pub const DOMAIN: f64 = 50.0;

/// (P, p(0)) of the closed form.
pub fn closed_form() -> (f64, f64) {
    let (e, nu, delta) = (200_000.0, 0.3, 0.001);
    let force = 2.0 * A * e * delta / (1.0 - nu * nu);
    (force, force / (2.0 * PI * A * A))
}

/// The bound on the finite domain's stiffening, (1 + ν)(3 − 2ν)a/(π(1 − ν²)L) (module docs).
pub fn domain_bound() -> f64 {
    let nu: f64 = 0.3;
    (1.0 + nu) * (3.0 - 2.0 * nu) / (PI * (1.0 - nu * nu) * DOMAIN)
}

/// The cell size at the punch's edge over a on `level` (1, 2) for linear or quadratic cells.
pub fn edge_cell(level: u32, quadratic: bool) -> f64 {
    1.0 / (32.0 * f64::from(1u32 << (level - 1)) * if quadratic { 1.0 } else { 2.0 })
}

/// One mesh measured.
#[derive(Debug, Clone, PartialEq)]
pub struct PunchRun {
    /// The total normal force over the circumference.
    pub force: f64,
    /// The r-weighed RMS error of the profile over 0 < r ≤ 0.7a, relative to p(0).
    pub profile_error: f64,
    /// The largest |p − p(r)| / p(0) over 0 < r ≤ 0.7a.
    pub profile_max_error: f64,
    /// The pressure of the pair on the axis.
    pub p_axis: f64,
}

/// Solves the scene on the bundled mesh `mesh` of `meshes/generic/`.
///
/// # Errors
/// A scene that cannot be read or solved, a status other than converged, or no interface `punch`.
pub fn measure(root: &Path, mesh: &str) -> Result<PunchRun, VerifyError> {
    let out = solve_on_mesh(root, SCENE, mesh, &[])?;
    let missing =
        |reason: &str| VerifyError::Missing { case: "punch_axisymmetric".into(), reason: format!("{mesh}: {reason}") };
    if out.report.status != "converged" {
        return Err(missing(&format!("status {}", out.report.status)));
    }
    let punch = out.report.contacts.get("punch").ok_or_else(|| missing("no interface \"punch\""))?;
    let profile = punch.profile.as_ref().ok_or_else(|| missing("no profile"))?;
    let (_, p_centre) = closed_form();
    let mut points: Vec<(f64, f64)> = profile.x.iter().copied().zip(profile.pressure.iter().copied()).collect();
    points.sort_by(|u, v| u.0.total_cmp(&v.0));
    let shape = |r: f64| A / (A * A - r * r).max(f64::MIN_POSITIVE).sqrt();
    let inner: Vec<(f64, f64)> = points.iter().copied().filter(|(r, _)| *r > 0.0 && *r <= 0.7 * A).collect();
    let (_, error) = weighted_fit_and_error(&inner, shape, p_centre);
    let max_error = inner.iter().map(|(r, p)| (p - p_centre * shape(*r)).abs() / p_centre).fold(0.0, f64::max);
    Ok(PunchRun {
        force: punch.normal_force,
        profile_error: error / p_centre,
        profile_max_error: max_error,
        p_axis: points.first().map_or(f64::NAN, |q| q.1),
    })
}

/// Runs the case: every element type on both levels (both `fast` and `full`).
///
/// # Errors
/// A scene that cannot be read or solved.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let (force, _) = closed_form();
    let mut report = CaseReport {
        name: "punch_axisymmetric".into(),
        source: "Boussinesq's rigid flat punch on a half-space (Johnson, Contact Mechanics §3.8)".into(),
        ..CaseReport::default()
    };
    for level in [1u32, 2] {
        for kind in KINDS {
            let quadratic = matches!(kind, "T6" | "Q8" | "Q9");
            let tolerance = domain_bound() + edge_cell(level, quadratic);
            let run = measure(root, &format!("punch_axisymmetric_{kind}_L{level}.msh"))?;
            let mesh = format!("{kind} L{level}");
            let check = |q: &str, m: f64, r: f64, t: Tolerance| Check::on(&mesh, q, m, r, t);
            report.checks.push(check("P (N)", run.force, force, Tolerance::Relative(tolerance)));
            report.checks.push(check(
                "pressure L2 error / p(0), 0 < r ≤ 0.7a",
                run.profile_error,
                0.0,
                Tolerance::Absolute(tolerance),
            ));
            for (q, v) in [
                ("p at the axis (MPa)", run.p_axis),
                ("pressure max error / p(0), 0 < r ≤ 0.7a", run.profile_max_error),
            ] {
                report.measurements.push(Measurement { quantity: q.into(), mesh: mesh.clone(), value: v });
            }
        }
    }
    report.notes.push(format!(
        "tolerance 1.09 a/L + h/a: the finite domain's stiffening bound ({:.2} % at L = {DOMAIN}a) plus the cell \
         size at the punch's edge over a",
        100.0 * domain_bound()
    ));
    Ok(report)
}

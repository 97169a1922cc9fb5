//! Mindlin–Deresiewicz fretting (`scenes/generic/cattaneo_mindlin_fretting.toml`): the
//! Cattaneo–Mindlin roller (R = 50 mm, steel on steel, μ = 0.3, plane strain) pressed, sheared
//! to +Q* and cycled +Q* → −Q* → +Q* with the press held.
//!
//! ```text
//! E* = E / (2 (1 − ν²)),  a = √(4 P R / (π E*)),  p0 = 2 P / (π a),  c* = a √(1 − Q*/(μ P))
//! unloading from Q* to Q (Masing: the change is twice a Cattaneo loading by (Q* − Q)/2):
//!   stick half-width   c' = a √(1 − (Q* − Q) / (2 μ P))
//!   q(x) = q_C(x; c*) − 2 q_C(x; c')      (along Q*), q_C(x; c) = μ p0 [√(1 − x²/a²) − (c/a) √(1 − x²/c²)]
//! energy per full cycle (docs/theory.md, "Fretting: energy per cycle of a cylinder"):
//!   W = 8 μ² p0² a² / E* · I(k),  k = c*/a,
//!   I(k) = ∫_k^1 √(1 − ξ²) [ξ √(ξ² − k²) − k² ln((ξ + √(ξ² − k²))/k)] dξ
//! ```
//!
//! Source: R. D. Mindlin, H. Deresiewicz (1953), J. Appl. Mech. 20, 327–344; K. L. Johnson,
//! *Contact Mechanics* (1985), §7.1–7.2 (the plane forms). P and Q are the measured reactions
//! of the driven top, so the closed forms are evaluated at the forces the model carries.
//!
//! Checks on the L2 mesh (`fast`; and L3, `full`), Q*/(μP) ≈ 0.48, at every unloading step of
//! the last cycle (its first half, +Q* → −Q*):
//! * c'/a within one pair spacing Δ/a (0.031 on L2, 0.016 on L3): each end of the stick zone is
//!   placed inside the pair interval where the state changes, and the 3/2-power rule that
//!   places it is exact only for a monotonic Cattaneo end, not for a reverse-slip front.
//!   Measured: ≤ 0.020 on L2, ≤ 0.0055 on L3.
//! * the shear profile's L2 error over |x| ≤ a within 7 % of μ p0: the unloading traction
//!   `q_C(c*) − 2 q_C(c')` has two fronts where the pair tractions oscillate (up to 0.2 μ p0 at
//!   the pairs next to them on L2, the front c' with weight 2); the monotonic Cattaneo case's
//!   3 % covers one front of weight 1. Measured: ≤ 6.1 % on L2, ≤ 2.8 % on L3 (the error halves
//!   with the spacing).
//! * the energy per cycle within 2 %: W ∝ a² I(k), and I(k) changes by about 2 % per 1 % of
//!   k = c*/a near 0.72, which the zone ends carry to about 0.5 % (the roller's bulk tension,
//!   see `cattaneo_mindlin.rs`). Measured: 0.47 % on L2, 0.012 % on L3.
//! * the largest slip amplitude against s_C(a; c*) (the contact edge), within the relative
//!   s_C'(a) Δ / s_C(a) (the last pair in contact lies up to one spacing inside a): 17 % on L2,
//!   8.5 % on L3. Measured: 8.6 % on L2, 2.5 % on L3.
//! * the work of the driven top over the cycle less the change of the stored energy equals the
//!   energy dissipated within 2 %: the step rows' `work` is the trapezoid rule over 10 steps per
//!   half cycle, which cuts the corners of the curved loop by about 1 % (measured 1.05 %, 1.0 %).

use std::f64::consts::PI;
use std::path::Path;

use super::profile::l2_error;
use super::{CaseReport, Check, Level, Measurement, Tolerance, VerifyError, gallery_scene, mesh_override, scene_path};
use crate::generic::results::contact_result;
use crate::generic::{GenericOutcome, solve_generic};

/// The scene.
pub const SCENE: &str = "scenes/generic/cattaneo_mindlin_fretting.toml";
const E: f64 = 210_000.0;
const NU: f64 = 0.3;
const R: f64 = 50.0;
const MU: f64 = 0.3;
/// The unloading shear profile's L2 error bound, relative to μ p0 (see the module docs).
const SHEAR_TOLERANCE: f64 = 0.07;

/// Mindlin–Deresiewicz for a cylinder on a flat of the same material at normal force `p` and
/// tangential amplitude `q_star` (per unit thickness).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// Contact half-width a.
    pub a: f64,
    /// Peak pressure p0.
    pub p0: f64,
    /// μ P.
    pub limit: f64,
    /// Q*.
    pub q_star: f64,
    /// E*.
    pub e_star: f64,
}

impl Cycle {
    /// The closed forms at `p` and `q_star`.
    pub fn new(p: f64, q_star: f64) -> Cycle {
        let e_star = E / (2.0 * (1.0 - NU * NU));
        let a = (4.0 * p * R / (PI * e_star)).sqrt();
        Cycle { a, p0: 2.0 * p / (PI * a), limit: MU * p, q_star: q_star.abs(), e_star }
    }

    /// Stick half-width after loading by `dq` (`c = a √(1 − dq/(μP))`).
    fn stick(&self, dq: f64) -> f64 {
        self.a * (1.0 - dq.abs() / self.limit).max(0.0).sqrt()
    }

    /// The stick half-width c' when unloaded from Q* to `q` (along Q*).
    pub fn unloading_stick(&self, q: f64) -> f64 {
        self.stick(0.5 * (self.q_star - q))
    }

    /// The Cattaneo traction with stick half-width `c`.
    fn cattaneo(&self, x: f64, c: f64) -> f64 {
        let root = |x: f64, h: f64| (1.0 - (x / h).powi(2)).max(0.0).sqrt();
        let stick = if x.abs() < c { (c / self.a) * root(x, c) } else { 0.0 };
        MU * self.p0 * (root(x, self.a) - stick)
    }

    /// The shear traction at `x` (along Q*) when unloaded from Q* to `q`:
    /// `q_C(x; c*) − 2 q_C(x; c')`.
    pub fn unloading_shear(&self, x: f64, q: f64) -> f64 {
        self.cattaneo(x, self.stick(self.q_star)) - 2.0 * self.cattaneo(x, self.unloading_stick(q))
    }

    /// The slip amplitude at the contact edge, `s_C(a; c*) = (μ p0/(a E*)) [a √(a² − c*²) −
    /// c*² ln((a + √(a² − c*²))/c*)]` (half the travel 2 s_C of a half cycle), and its slope
    /// `ds_C/dx(a) = 2 μ p0 √(a² − c*²) / (a E*)`.
    pub fn edge_slip(&self) -> (f64, f64) {
        let (a, c) = (self.a, self.stick(self.q_star));
        let r = (a * a - c * c).max(0.0).sqrt();
        let scale = MU * self.p0 / (a * self.e_star);
        let log = if c > 0.0 { ((a + r) / c).ln() } else { 0.0 };
        (scale * (a * r - c * c * log), 2.0 * scale * r)
    }

    /// The energy dissipated per full cycle ±Q*: `W = 8 μ² p0² a² / E* · I(c*/a)`.
    pub fn energy_per_cycle(&self) -> f64 {
        let k = self.stick(self.q_star) / self.a;
        8.0 * (MU * self.p0 * self.a).powi(2) / self.e_star * slip_integral(k)
    }
}

/// `I(k) = ∫_k^1 √(1 − ξ²) [ξ √(ξ² − k²) − k² ln((ξ + √(ξ² − k²))/k)] dξ` by composite
/// five-point Gauss–Legendre on 2 000 panels (the integrand's end singularities are of the
/// orders 3/2 and 1/2: relative error below 1e-7, far under the checks' tolerances).
pub fn slip_integral(k: f64) -> f64 {
    const G: [(f64, f64); 5] = contact2d_mesh::GAUSS5;
    if !(k > 0.0 && k < 1.0) {
        return 0.0;
    }
    let f = |xi: f64| {
        let r = (xi * xi - k * k).max(0.0).sqrt();
        (1.0 - xi * xi).max(0.0).sqrt() * (xi * r - k * k * ((xi + r) / k).ln())
    };
    let n = 2000;
    let h = (1.0 - k) / f64::from(n);
    (0..n)
        .map(|i| {
            let mid = k + h * (f64::from(i) + 0.5);
            G.iter().map(|(g, w)| w * 0.5 * h * f(mid + 0.5 * h * g)).sum::<f64>()
        })
        .sum()
}

/// P and Q of a step from the driven top's reactions.
fn forces(out: &GenericOutcome, step: usize) -> Result<(f64, f64), VerifyError> {
    let row = out.report.steps.get(step).ok_or_else(|| missing("a step is missing"))?;
    match row.reactions.get("cylinder_top") {
        Some([Some(q), Some(p)]) => Ok((-p, *q)),
        _ => Err(missing("cylinder_top is not driven in both directions")),
    }
}

/// Runs the case on the L2 mesh (`fast`), and on L3 too (`full`).
///
/// # Errors
/// A scene that cannot be read or solved, or a result missing.
pub fn run(root: &Path, level: Level) -> Result<CaseReport, VerifyError> {
    let levels: &[&str] = match level {
        Level::Fast => &["L2"],
        Level::Full => &["L2", "L3"],
    };
    let mut report = CaseReport {
        name: "mindlin_deresiewicz".into(),
        source: "Mindlin & Deresiewicz (1953); Johnson, Contact Mechanics §7.2".into(),
        ..CaseReport::default()
    };
    for l in levels {
        check_mesh(root, l, &mut report)?;
    }
    Ok(report)
}

/// The checks on one mesh level.
fn check_mesh(root: &Path, mesh: &str, report: &mut CaseReport) -> Result<(), VerifyError> {
    let overrides = [mesh_override(&format!("cattaneo_mindlin_{mesh}.msh"))];
    let scene = gallery_scene(&scene_path(root, SCENE), &overrides)?;
    let cycle = scene.last_cycle().ok_or_else(|| missing("the scene has no load cycle"))?;
    let out = solve_generic(&scene, &mut |_, _| {})?;
    let mesh = mesh.to_string();
    if out.report.status != "converged" {
        report.notes.push(format!("{mesh}: status {}", out.report.status));
    }
    let iface = out.built.interfaces.first().ok_or_else(|| missing("the scene has no contact"))?;
    let peak = cycle.start.checked_sub(1).ok_or_else(|| missing("no step before the cycle"))?;
    let (p, q_star) = forces(&out, peak)?;
    let exact = Cycle::new(p, q_star);
    // The pair spacing inside the contact (the zone ends are placed within one spacing).
    let spacing = {
        let step = out.history.steps.get(peak).ok_or_else(|| missing("a step is missing"))?;
        let profile = contact_result(&out.built, iface, &step.solution, 0.0, true).profile;
        let x: Vec<f64> = profile.map(|p| p.x.into_iter().filter(|x| x.abs() <= exact.a).collect()).unwrap_or_default();
        x.windows(2).map(|w| (w[1] - w[0]).abs()).fold(0.0, f64::max)
    };
    // The unloading half of the last cycle: its first half, from +Q* down to −Q*.
    for i in cycle.start..cycle.start + cycle.len() / 2 {
        let (_, q) = forces(&out, i)?;
        let q_along = q * q_star.signum();
        let step = out.history.steps.get(i).ok_or_else(|| missing("a step is missing"))?;
        let contact = contact_result(&out.built, iface, &step.solution, 0.0, true);
        let profile = contact.profile.ok_or_else(|| missing("no profile"))?;
        let at = format!("step {}, Q/Q* = {:.2}", i + 1, q_along / exact.q_star);
        report.checks.push(Check {
            quantity: format!("unloading c'/a at {at}"),
            mesh: mesh.clone(),
            measured: 0.5 * contact.stick_length / exact.a,
            reference: exact.unloading_stick(q_along) / exact.a,
            tolerance: Tolerance::Absolute(spacing / exact.a),
        });
        let shear: Vec<(f64, f64)> =
            profile.x.iter().zip(&profile.shear).map(|(x, s)| (*x, s * q_star.signum())).collect();
        let error = l2_error(&shear, -exact.a, exact.a, |x| exact.unloading_shear(x, q_along))
            .map_or(f64::NAN, |e| e / (MU * exact.p0));
        report.checks.push(Check {
            quantity: format!("unloading shear L2 error / μp0 at {at}"),
            mesh: mesh.clone(),
            measured: error,
            reference: 0.0,
            tolerance: Tolerance::Absolute(SHEAR_TOLERANCE),
        });
    }
    let fretting = out
        .report
        .contacts
        .get(&iface.name)
        .and_then(|c| c.fretting.as_deref())
        .ok_or_else(|| missing("no fretting numbers"))?;
    report.checks.push(Check {
        quantity: "energy dissipated per cycle".into(),
        mesh: mesh.clone(),
        measured: fretting.dissipated,
        reference: exact.energy_per_cycle(),
        tolerance: Tolerance::Relative(0.02),
    });
    let rows = &out.report.steps.to_vec();
    let (Some(before), Some(last)) = (rows.get(peak), rows.get(cycle.end - 1)) else {
        return Err(missing("a step is missing"));
    };
    let stored = |r: &crate::generic::StepResult| r.energies.values().sum::<f64>();
    report.checks.push(Check {
        quantity: "work of the driven top over the cycle − Δ stored energy".into(),
        mesh: mesh.clone(),
        measured: last.work - before.work - (stored(last) - stored(before)),
        reference: fretting.dissipated,
        tolerance: Tolerance::Relative(0.02),
    });
    let measure = |quantity: &str, value: f64| Measurement { quantity: quantity.into(), mesh: mesh.clone(), value };
    report.measurements.push(measure("Q*/(μP)", q_star / (MU * p)));
    report.measurements.push(measure("pair spacing / a", spacing / exact.a));
    // The largest amplitude is the last pair in contact's, up to one spacing inside the edge,
    // where s_C is smaller by at most its slope times the spacing.
    let amplitude = fretting.slip_amplitude.iter().fold(0.0, |m: f64, v| m.max(*v));
    let (edge, slope) = exact.edge_slip();
    report.checks.push(Check {
        quantity: "largest slip amplitude / a".into(),
        mesh: mesh.clone(),
        measured: amplitude / exact.a,
        reference: edge / exact.a,
        tolerance: Tolerance::Relative(slope * spacing / edge),
    });
    report.measurements.push(measure("Ruiz maximum at x/a", fretting.ruiz_max[2] / exact.a));
    Ok(())
}

fn missing(reason: &str) -> VerifyError {
    VerifyError::Missing { case: "mindlin_deresiewicz".into(), reason: reason.into() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_slip_integral_vanishes_at_full_stick_and_grows_with_the_load() {
        assert_eq!(slip_integral(1.0), 0.0);
        // k → 0 (gross slip): I(0) = ∫_0^1 ξ² √(1 − ξ²) dξ = π/16.
        assert!((slip_integral(1e-9) - PI / 16.0).abs() < 1e-6, "{}", slip_integral(1e-9));
        assert!(slip_integral(0.5) > slip_integral(0.7));
    }

    #[test]
    fn unloading_to_minus_q_star_mirrors_the_peak() {
        let c = Cycle::new(450.0, 60.0);
        for x in [-0.4, -0.1, 0.0, 0.2, 0.45] {
            let at_peak = c.cattaneo(x, c.stick(c.q_star));
            assert!((c.unloading_shear(x, -c.q_star) + at_peak).abs() < 1e-9 * c.p0);
            assert!((c.unloading_shear(x, c.q_star) - at_peak).abs() < 1e-9 * c.p0);
        }
    }
}

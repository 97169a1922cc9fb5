//! The fretting files of a generic run's folder (a scene with a `[loading] cycle`):
//!
//! ```text
//! fretting_<name>.csv         per pair over the last cycle: s, slip_amplitude, dissipation,
//!                             shear_max, sigma_tt, ruiz (the columns of contacts.<name>.fretting)
//! hysteresis_<name>.csv       the loop: step, displacement δ, tangential_force Q
//! hysteresis_<name>.png/.svg  Q against δ (with the contact's reference_groups)
//! fretting_<name>.png/.svg    along the contact: slip amplitude, dissipation per unit length and
//!                             the Ruiz parameter, each over its largest value (named in the legend)
//! ```

use std::fmt::Write as _;
use std::path::Path;

use super::fretting::{Fretting, HysteresisLoop};
use crate::output::OutputError;
use crate::output::chart::{Axes, Series, line_chart};

/// The per-pair table of [`Fretting`].
pub fn fretting_csv(f: &Fretting) -> String {
    let mut out = String::from("s,slip_amplitude,dissipation,shear_max,sigma_tt,ruiz\n");
    for i in 0..f.s.len() {
        let _ = writeln!(
            out,
            "{:e},{:e},{:e},{:e},{:e},{:e}",
            f.s[i], f.slip_amplitude[i], f.dissipation[i], f.shear_max[i], f.sigma_tt[i], f.ruiz[i]
        );
    }
    out
}

/// The loop's table: the step (from 1; the first row is the step before the cycle), δ and Q.
pub fn hysteresis_csv(f: &Fretting, h: &HysteresisLoop) -> String {
    let mut out = String::from("step,displacement,tangential_force\n");
    let first = f.steps[0].saturating_sub(1);
    for (k, (d, q)) in h.displacement.iter().zip(&h.tangential_force).enumerate() {
        let _ = writeln!(out, "{},{:e},{:e}", first + k, d, q);
    }
    out
}

/// Q against δ over the last cycle.
///
/// # Errors
/// [`OutputError`] from the chart.
pub fn draw_hysteresis(path: &Path, title: &str, h: &HysteresisLoop) -> Result<(), OutputError> {
    let points = h.displacement.iter().copied().zip(h.tangential_force.iter().copied()).collect();
    let series = [Series { label: "Q = Σ τ (on the master side)".into(), points, markers: true }];
    let axes = Axes {
        title: title.into(),
        x_label: format!("δ = t · (ū({}) − ū({}))", h.groups[0], h.groups[1]),
        y_label: "tangential force Q".into(),
        ..Axes::default()
    };
    line_chart(path, &axes, &series)
}

/// Slip amplitude, dissipation per unit length and the Ruiz parameter along the contact over the
/// last cycle, each divided by its largest value (`q / max q`, the largest given in the legend with
/// where it lies) so that the three share one axis: where the contact frets, wears and cracks.
///
/// # Errors
/// [`OutputError`] from the chart.
pub fn draw_fretting(path: &Path, title: &str, f: &Fretting) -> Result<(), OutputError> {
    let shown = fretting_span(f);
    let scaled = |name: &str, values: &[f64]| {
        let (at, max) = values.iter().enumerate().fold((0, 0.0_f64), |b, (i, &v)| if v > b.1 { (i, v) } else { b });
        let points = (shown.clone())
            .filter_map(|i| Some((*f.s.get(i)?, values.get(i).map_or(0.0, |&v| if max > 0.0 { v / max } else { 0.0 }))))
            .collect();
        let label = format!("{name} / {max:.3e} (its largest, at s = {:.4})", f.s.get(at).copied().unwrap_or(0.0));
        Series { label, points, markers: true }
    };
    let series = [
        scaled("slip amplitude", &f.slip_amplitude),
        scaled("dissipation per length", &f.dissipation),
        scaled("Ruiz σ_tt·τ·δ", &f.ruiz),
    ];
    let axes = Axes {
        title: title.into(),
        x_label: "s (arc length of the master node; the pairs that slip, and one on each side)".into(),
        y_label: "each over its largest value".into(),
        ..Axes::default()
    };
    line_chart(path, &axes, &series)
}

/// The pairs the fretting figure shows: those that slip or dissipate in the cycle, and one more on
/// each side (a contact zone is often a small part of its curve); every pair when none does.
fn fretting_span(f: &Fretting) -> std::ops::Range<usize> {
    let active = |i: &usize| f.slip_amplitude[*i] > 0.0 || f.dissipation[*i] > 0.0 || f.ruiz[*i] > 0.0;
    let n = f.s.len().min(f.slip_amplitude.len()).min(f.dissipation.len()).min(f.ruiz.len());
    match ((0..n).find(active), (0..n).rev().find(active)) {
        (Some(first), Some(last)) => first.saturating_sub(1)..(last + 2).min(n),
        _ => 0..n,
    }
}

//! The fretting files of a generic run's folder (a scene with a `[loading] cycle`):
//!
//! ```text
//! fretting_<name>.csv         per pair over the last cycle: s, slip_amplitude, dissipation,
//!                             shear_max, sigma_tt, ruiz (the columns of contacts.<name>.fretting)
//! hysteresis_<name>.csv       the loop: step, displacement δ, tangential_force Q
//! hysteresis_<name>.png/.svg  Q against δ (with the contact's reference_groups)
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

//! The paper's line figures (spec §7): the hole-edge profiles, the insert's hoop stress, and the
//! zone ends over a loading history, drawn with [`crate::output::chart::line_chart`].
//!
//! ```text
//! hole_edge     s_φφ, p, q on Γ_p vs η = 1 − φ/π      (stresses and tractions / E1)
//! insert_hoop   s_θθ on Γ_c vs η = 1 − θ/π            (skipped for a rigid insert)
//! history       l(w), b(w) over the steps             (only with more than one step)
//! ```

use std::path::Path;

use super::profiles::ProfileRow;
use crate::output::OutputError;
use crate::output::chart::{Axes, Series, line_chart};
use crate::run::RunOutcome;

/// The x label of every profile figure.
const ETA_LABEL: &str = "η = 1 − angle/π (non-dimensional; 0 where the plate bears on the insert)";
/// The y label of every stress figure.
const STRESS_LABEL: &str = "stress / E1 (non-dimensional)";

/// A series of `value(row)` against η, points without a value left out.
fn series_of(label: &str, rows: &[ProfileRow], value: impl Fn(&ProfileRow) -> Option<f64>) -> Series {
    let mut points: Vec<(f64, f64)> = rows.iter().filter_map(|r| value(r).map(|v| (r.eta, v))).collect();
    points.sort_by(|a, b| a.0.total_cmp(&b.0));
    Series { label: label.into(), points, markers: false }
}

/// s_φφ, p and q along the hole edge vs η, with the zone ends (e.g. `[("l", 0.47), ("b", 0.15)]`)
/// as vertical lines across the data.
///
/// # Errors
/// As [`line_chart`].
pub fn draw_hole_edge(
    path: &Path,
    title: &str,
    hole: &[ProfileRow],
    zone_ends: &[(&str, f64)],
) -> Result<(), OutputError> {
    let mut series = vec![
        series_of("s_φφ (hoop stress of the plate)", hole, |r| r.hoop_stress),
        series_of("p (normal contact traction, < 0 in compression)", hole, |r| r.contact.map(|c| c.pressure)),
        series_of("q (tangential contact traction)", hole, |r| r.contact.map(|c| c.shear)),
    ];
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo < hi {
        for (name, eta) in zone_ends.iter().filter(|(_, eta)| eta.is_finite()) {
            let label = format!("{name} = {eta:.4}");
            series.push(Series { label, points: vec![(*eta, lo), (*eta, hi)], markers: false });
        }
    }
    let axes = Axes { title: title.into(), x_label: ETA_LABEL.into(), y_label: STRESS_LABEL.into(), ..Axes::default() };
    line_chart(path, &axes, &series)
}

/// The insert's hoop stress s_θθ along its edge vs η.
///
/// # Errors
/// As [`line_chart`].
pub fn draw_insert_hoop(path: &Path, title: &str, insert: &[ProfileRow]) -> Result<(), OutputError> {
    let series = [series_of("s_θθ (hoop stress of the insert)", insert, |r| r.hoop_stress)];
    let axes = Axes { title: title.into(), x_label: ETA_LABEL.into(), y_label: STRESS_LABEL.into(), ..Axes::default() };
    line_chart(path, &axes, &series)
}

/// The contact end l and the stick end b against the load w over the steps.
///
/// # Errors
/// As [`line_chart`].
pub fn draw_zone_ends(path: &Path, title: &str, outcome: &RunOutcome) -> Result<(), OutputError> {
    let steps = &outcome.paper.steps;
    let points = |pick: fn(&crate::plate_insert::report::StepReport) -> Option<f64>| -> Vec<(f64, f64)> {
        steps.iter().filter_map(|s| pick(s).map(|v| (s.w, v))).collect()
    };
    let series = [
        Series { label: "l (contact end)".into(), points: points(|s| s.l), markers: true },
        Series { label: "b (stick end)".into(), points: points(|s| s.b), markers: true },
    ];
    let axes = Axes {
        title: title.into(),
        x_label: "w (pulled-edge displacement, non-dimensional)".into(),
        y_label: "η of the zone end (non-dimensional)".into(),
        ..Axes::default()
    };
    line_chart(path, &axes, &series)
}

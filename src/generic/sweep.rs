//! Sweeps of generic scenes: any key varied (as `--set` takes it, array entries by index or
//! name), any number of the JSON summary plotted by its dotted path.
//!
//! ```text
//! contact2d sweep scenes/generic/cylinder_on_block.toml --vary load.0.force=[0,-5000],[0,-17500] \
//!     --plot contacts.hertz.contact_length,contacts.hertz.max_pressure
//! quantity paths:  contacts.<name>.<field>, reactions.<group>.0 (or .1), energies.<body>,
//!                  kkt.<residual>, iterations, time_s.total, ...
//! ```

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use super::{load_scene, solve_generic};
use crate::output::chart::{Axes, Series, line_chart};
use crate::output::{FIGURE_EXTENSIONS, OutputDir, OutputError};
use crate::sweep::{MAX_RUNS, SweepError, Variation, combinations};

/// One run of a generic sweep.
#[derive(Debug, Clone)]
pub struct GenericSweepRow {
    /// One value per varied key.
    pub values: Vec<String>,
    /// The run's JSON summary, or why it failed.
    pub result: Result<serde_json::Value, String>,
}

/// Checks the variations of a generic sweep before any run: each key is one the scene takes
/// (the scene loads with the key set to its first value, or fails for another reason than an
/// unknown key), no key is varied twice, and at most [`MAX_RUNS`] combinations.
///
/// # Errors
/// [`SweepError::UnknownKey`], [`SweepError::DuplicateKey`], [`SweepError::TooManyRuns`].
pub fn check_generic_variations(scene: &Path, variations: &[Variation], base: &[String]) -> Result<usize, SweepError> {
    for (i, v) in variations.iter().enumerate() {
        if variations[..i].iter().any(|w| w.key == v.key) {
            return Err(SweepError::DuplicateKey { key: v.key.clone() });
        }
        let mut overrides = base.to_vec();
        overrides.push(format!("{}={}", v.key, v.values[0]));
        if let Err(e) = load_scene(scene, &overrides) {
            let shown = e.to_string();
            if shown.contains("unknown field") || shown.contains("no table") || shown.contains("no entry") {
                return Err(SweepError::Vary { argument: v.key.clone(), reason: shown });
            }
        }
    }
    let runs = variations.iter().try_fold(1usize, |n, v| n.checked_mul(v.values.len())).unwrap_or(usize::MAX);
    if runs > MAX_RUNS {
        return Err(SweepError::TooManyRuns { runs });
    }
    Ok(runs)
}

/// Runs every combination in parallel, handing each finished row to `on_row`.
pub fn run_generic_sweep(
    scene: &Path,
    variations: &[Variation],
    base: &[String],
    on_row: impl Fn(&GenericSweepRow) + Sync,
) -> Vec<GenericSweepRow> {
    combinations(variations)
        .into_par_iter()
        .map(|values| {
            let mut overrides = base.to_vec();
            overrides.extend(variations.iter().zip(&values).map(|(v, value)| format!("{}={value}", v.key)));
            let result = load_scene(scene, &overrides)
                .map_err(|e| e.to_string())
                .and_then(|s| solve_generic(&s, &mut |_, _| {}).map_err(|e| e.to_string()))
                .and_then(|o| serde_json::to_value(&o.report).map_err(|e| e.to_string()));
            let row = GenericSweepRow { values, result };
            on_row(&row);
            row
        })
        .collect()
}

/// The number at a dotted path of a JSON summary (`contacts.hertz.normal_force`,
/// `reactions.block_bottom.1`), `None` if there is none.
pub fn quantity(summary: &serde_json::Value, path: &str) -> Option<f64> {
    path.split('.')
        .try_fold(summary, |v, part| match v {
            serde_json::Value::Array(items) => part.parse::<usize>().ok().and_then(|i| items.get(i)),
            _ => v.get(part),
        })
        .and_then(serde_json::Value::as_f64)
}

/// The default quantities of a scene's sweep: each interface's normal force and contact length.
pub fn default_quantities(contacts: &[String]) -> Vec<String> {
    contacts
        .iter()
        .flat_map(|c| [format!("contacts.{c}.normal_force"), format!("contacts.{c}.contact_length")])
        .collect()
}

/// The CSV header: varied keys, status, quantities, iterations, error.
pub fn csv_header(variations: &[Variation], quantities: &[String]) -> String {
    let mut h: Vec<String> = variations.iter().map(|v| v.key.clone()).collect();
    h.push("status".into());
    h.extend(quantities.iter().cloned());
    h.extend(["iterations".into(), "error".into()]);
    h.iter().map(|c| quote(c)).collect::<Vec<_>>().join(",") + "\n"
}

/// One CSV row.
pub fn csv_row(row: &GenericSweepRow, quantities: &[String]) -> String {
    let mut c: Vec<String> = row.values.clone();
    match &row.result {
        Ok(v) => {
            c.push(v["status"].as_str().unwrap_or("").into());
            c.extend(quantities.iter().map(|q| quantity(v, q).map_or(String::new(), |x| format!("{x:?}"))));
            c.push(v["iterations"].to_string());
            c.push(String::new());
        }
        Err(e) => {
            c.push("error".into());
            c.extend(quantities.iter().map(|_| String::new()));
            c.push(String::new());
            c.push(e.clone());
        }
    }
    c.iter().map(|x| quote(x)).collect::<Vec<_>>().join(",") + "\n"
}

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) { format!("\"{}\"", s.replace('"', "\"\"").replace('\n', " ")) } else { s.into() }
}

/// A Markdown table of the rows.
pub fn markdown(variations: &[Variation], rows: &[GenericSweepRow], quantities: &[String]) -> String {
    let header = csv_header(variations, quantities);
    let cells = |line: &str| line.trim_end().replace('|', "\\|").replace(',', " | ");
    let n = header.trim_end().split(',').count();
    let mut t = format!("| {} |\n|{}\n", cells(&header), "---|".repeat(n));
    for row in rows {
        let _ = writeln!(t, "| {} |", cells(&csv_row(row, quantities)));
    }
    t
}

/// Writes sweep.csv, sweep.md and one plot per quantity (against the first varied key, one line
/// per combination of the others) into the prepared folder; returns the paths written.
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written.
pub fn write_generic_sweep(
    mut out: OutputDir,
    name: &str,
    variations: &[Variation],
    rows: &[GenericSweepRow],
    quantities: &[String],
) -> Result<Vec<PathBuf>, OutputError> {
    let mut csv = csv_header(variations, quantities);
    rows.iter().for_each(|r| csv.push_str(&csv_row(r, quantities)));
    out.write_bytes("sweep.csv", csv.as_bytes())?;
    let mut md = markdown(variations, rows, quantities);
    for q in quantities {
        let stem = format!("sweep_{}", q.replace(|c: char| !c.is_ascii_alphanumeric() && c != '_', "_"));
        for ext in FIGURE_EXTENSIONS {
            match out.write_with(&format!("{stem}.{ext}"), |p| plot(p, name, variations, rows, q)) {
                Ok(_) => {}
                Err(OutputError::Undrawable { reason, .. }) => {
                    let _ = writeln!(md, "\n{stem}.{ext} not drawn: {reason}");
                }
                Err(e) => return Err(e),
            }
        }
    }
    out.write_bytes("sweep.md", md.as_bytes())?;
    out.close()
}

fn plot(
    path: &Path,
    name: &str,
    variations: &[Variation],
    rows: &[GenericSweepRow],
    q: &str,
) -> Result<(), OutputError> {
    let x = |row: &GenericSweepRow| -> f64 {
        let value = row.values.first().map_or("", String::as_str);
        value
            .parse()
            .unwrap_or_else(|_| variations[0].values.iter().position(|v| v == value).map_or(f64::NAN, |i| i as f64))
    };
    let mut series: Vec<Series> = vec![];
    for row in rows {
        let label = if variations.len() > 1 {
            variations[1..]
                .iter()
                .zip(&row.values[1..])
                .map(|(v, x)| format!("{}={x}", v.key))
                .collect::<Vec<_>>()
                .join(", ")
        } else {
            q.to_string()
        };
        let y = row.result.as_ref().ok().and_then(|v| quantity(v, q)).unwrap_or(f64::NAN);
        match series.iter_mut().find(|s| s.label == label) {
            Some(s) => s.points.push((x(row), y)),
            None => series.push(Series { label, points: vec![(x(row), y)], markers: true }),
        }
    }
    let axes = Axes {
        title: format!("{name}: {q}"),
        x_label: variations.first().map_or(String::new(), |v| v.key.clone()),
        y_label: q.to_string(),
        ..Axes::default()
    };
    line_chart(path, &axes, &series)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantities_are_found_by_their_dotted_path() {
        let v: serde_json::Value =
            serde_json::from_str(r#"{"contacts": {"h": {"normal_force": 2.5}}, "reactions": {"b": [1.0, -3.0]}}"#)
                .unwrap_or_default();
        assert_eq!(quantity(&v, "contacts.h.normal_force"), Some(2.5));
        assert_eq!(quantity(&v, "reactions.b.1"), Some(-3.0));
        assert_eq!(quantity(&v, "reactions.b.2"), None);
        assert_eq!(quantity(&v, "contacts.x.normal_force"), None);
    }
}

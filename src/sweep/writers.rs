//! What a sweep writes: sweep.csv (a row per run: the varied values, the status, the columns,
//! the iterations and the error of a failed run), sweep.md (the same as a table) and one figure
//! per plotted quantity against the first varied key, one line per combination of the others.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::{SweepRow, Variation};
use crate::output::chart::{Axes, Series, line_chart};
use crate::output::{FIGURE_EXTENSIONS, OutputDir, OutputError};
use crate::subject::quantity;

/// The CSV header: varied keys, status, quantities, iterations, error.
pub fn csv_header(variations: &[Variation], quantities: &[String]) -> String {
    let mut h: Vec<String> = variations.iter().map(|v| v.key.clone()).collect();
    h.push("status".into());
    h.extend(quantities.iter().cloned());
    h.extend(["iterations".into(), "error".into()]);
    h.iter().map(|c| quote(c)).collect::<Vec<_>>().join(",") + "\n"
}

/// One CSV row.
pub fn csv_row(row: &SweepRow, quantities: &[String]) -> String {
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
pub fn markdown(variations: &[Variation], rows: &[SweepRow], quantities: &[String]) -> String {
    let header = csv_header(variations, quantities);
    let cells = |line: &str| line.trim_end().replace('|', "\\|").replace(',', " | ");
    let n = header.trim_end().split(',').count();
    let mut t = format!("| {} |\n|{}\n", cells(&header), "---|".repeat(n));
    for row in rows {
        let _ = writeln!(t, "| {} |", cells(&csv_row(row, quantities)));
    }
    t
}

/// Writes sweep.csv and sweep.md with the `columns`, and one plot per quantity of `plots`
/// (against the first varied key, one line per combination of the others), into the prepared
/// folder; returns the paths written.
///
/// # Errors
/// [`OutputError`] naming the first file that could not be written.
pub fn write_sweep(
    mut out: OutputDir,
    name: &str,
    variations: &[Variation],
    rows: &[SweepRow],
    columns: &[String],
    plots: &[String],
) -> Result<Vec<PathBuf>, OutputError> {
    let mut csv = csv_header(variations, columns);
    rows.iter().for_each(|r| csv.push_str(&csv_row(r, columns)));
    out.write_bytes("sweep.csv", csv.as_bytes())?;
    let mut md = markdown(variations, rows, columns);
    for q in plots {
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

fn plot(path: &Path, name: &str, variations: &[Variation], rows: &[SweepRow], q: &str) -> Result<(), OutputError> {
    let x = |row: &SweepRow| -> f64 {
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

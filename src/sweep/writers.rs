//! What a sweep writes: sweep.csv (a row per run: the varied values, the status, the load
//! factor last held ([`super::last_held_factor`]), the columns,
//! the iterations and the error of a failed run), sweep.md (the same as a table) and one figure
//! per plotted quantity against the first varied key, one line per combination of the others.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::{SweepRow, Variation};
use crate::output::chart::{Axes, Series, line_chart};
use crate::output::{FIGURE_EXTENSIONS, OutputDir, OutputError};
use crate::subject::quantity;

/// The CSV header: varied keys, status, last_held_factor, quantities, iterations, error.
pub fn csv_header(variations: &[Variation], quantities: &[String]) -> String {
    let mut h: Vec<String> = variations.iter().map(|v| v.key.clone()).collect();
    h.extend(["status".into(), super::capacity::COLUMN.into()]);
    h.extend(quantities.iter().cloned());
    h.extend(["iterations".into(), "error".into()]);
    h.iter().map(|c| quote(c)).collect::<Vec<_>>().join(",") + "\n"
}

/// One CSV row.
pub fn csv_row(row: &SweepRow, quantities: &[String]) -> String {
    row_cells(row, quantities).iter().map(|x| quote(x)).collect::<Vec<_>>().join(",") + "\n"
}

/// The cells of a row: the varied values, the status, the load factor last held, the quantities, the iterations, the error.
fn row_cells(row: &SweepRow, quantities: &[String]) -> Vec<String> {
    let mut c: Vec<String> = row.values.clone();
    match &row.result {
        Ok(v) => {
            c.push(v["status"].as_str().unwrap_or("").into());
            c.push(super::last_held_factor(v).map_or(String::new(), |x| format!("{x:?}")));
            c.extend(quantities.iter().map(|q| quantity(v, q).map_or(String::new(), |x| format!("{x:?}"))));
            c.push(v["iterations"].to_string());
            c.push(String::new());
        }
        Err(e) => {
            c.push("error".into());
            c.push(String::new());
            c.extend(quantities.iter().map(|_| String::new()));
            c.push(String::new());
            c.push(e.clone());
        }
    }
    c
}

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) { format!("\"{}\"", s.replace('"', "\"\"").replace('\n', " ")) } else { s.into() }
}

/// A Markdown table of the rows; each cell escaped (`|` and line breaks), so that a vector
/// value or an error message with commas stays in its cell.
pub fn markdown(variations: &[Variation], rows: &[SweepRow], quantities: &[String]) -> String {
    let mut header: Vec<String> = variations.iter().map(|v| v.key.clone()).collect();
    header.extend(["status".into(), super::capacity::COLUMN.into()]);
    header.extend(quantities.iter().cloned());
    header.extend(["iterations".into(), "error".into()]);
    let line = |cells: &[String]| {
        let escaped: Vec<String> = cells.iter().map(|c| c.replace('|', "\\|").replace('\n', " ")).collect();
        format!("| {} |", escaped.join(" | "))
    };
    let mut t = format!("{}\n|{}\n", line(&header), "---|".repeat(header.len()));
    for row in rows {
        let _ = writeln!(t, "{}", line(&row_cells(row, quantities)));
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

/// A plot's x coordinate of a varied value.
type XValue<'a> = Box<dyn Fn(&str) -> f64 + 'a>;

/// The x axis of a sweep's plots: the first varied key's value; for a vector value (`[25.0, 0.0]`)
/// the one component that varies, or the vector's norm when several do; otherwise the value's
/// ordinal.
fn x_axis(variation: &Variation) -> (String, XValue<'_>) {
    let vector = |v: &str| -> Option<Vec<f64>> {
        let parsed = toml::from_str::<toml::Table>(&format!("v = {v}")).ok()?;
        parsed.get("v")?.as_array()?.iter().map(|x| x.as_float().or_else(|| x.as_integer().map(|i| i as f64))).collect()
    };
    let vectors: Option<Vec<Vec<f64>>> = variation.values.iter().map(|v| vector(v)).collect();
    if let Some(vectors) = vectors.filter(|v| v.iter().all(|x| !x.is_empty() && x.len() == v[0].len())) {
        let varying: Vec<usize> =
            (0..vectors[0].len()).filter(|&c| vectors.iter().any(|v| v[c] != vectors[0][c])).collect();
        if let [c] = varying[..] {
            return (format!("{}[{c}]", variation.key), Box::new(move |v| vector(v).map_or(f64::NAN, |x| x[c])));
        }
        let norm = move |v: &str| vector(v).map_or(f64::NAN, |x| x.iter().map(|c| c * c).sum::<f64>().sqrt());
        return (format!("|{}| (norm)", variation.key), Box::new(norm));
    }
    let ordinal = |value: &str| {
        value
            .parse()
            .unwrap_or_else(|_| variation.values.iter().position(|v| v == value).map_or(f64::NAN, |i| i as f64))
    };
    (variation.key.clone(), Box::new(ordinal))
}

fn plot(path: &Path, name: &str, variations: &[Variation], rows: &[SweepRow], q: &str) -> Result<(), OutputError> {
    let Some(first) = variations.first() else { return Ok(()) };
    let (x_label, value) = x_axis(first);
    let x = |row: &SweepRow| value(row.values.first().map_or("", String::as_str));
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
    let axes = Axes { title: format!("{name}: {q}"), x_label, y_label: q.to_string(), ..Axes::default() };
    line_chart(path, &axes, &series)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn force(values: &[&str]) -> Variation {
        Variation { key: "load.pin_back.force".into(), values: values.iter().map(|v| v.to_string()).collect() }
    }

    /// A vector value and an error message with commas and a bar stay in their cells: every
    /// line has as many cells as the header.
    #[test]
    fn markdown_cells_hold_commas_and_bars() {
        let v = force(&["[25.0, 0.0]", "[50.0, 0.0]"]);
        let rows = [
            SweepRow { values: vec!["[25.0, 0.0]".into()], result: Ok(serde_json::json!({"status": "converged"})) },
            SweepRow { values: vec!["[50.0, 0.0]".into()], result: Err("no equilibrium, step 1 | pin".into()) },
        ];
        let table = markdown(&[v], &rows, &["P".into()]);
        let cells = |line: &str| line.split(" | ").count();
        let lines: Vec<&str> = table.lines().filter(|l| !l.starts_with("|-")).collect();
        assert!(lines.iter().all(|l| cells(l) == cells(lines[0])), "{table}");
        assert!(table.contains("[25.0, 0.0]") && table.contains("step 1 \\| pin"), "{table}");
    }

    /// A vector key is plotted against the one component that varies, or its norm.
    #[test]
    fn a_vector_key_is_plotted_against_its_varying_component_or_norm() {
        let one = force(&["[25.0, 0.0]", "[50.0, 0.0]"]);
        let (label, x) = x_axis(&one);
        assert_eq!((label.as_str(), x("[50.0, 0.0]")), ("load.pin_back.force[0]", 50.0));
        let both = force(&["[3.0, 4.0]", "[6.0, 8.0]"]);
        let (label, x) = x_axis(&both);
        assert_eq!((label.as_str(), x("[6.0, 8.0]")), ("|load.pin_back.force| (norm)", 10.0));
        let scalar = force(&["0.1", "0.2"]);
        let (label, x) = x_axis(&scalar);
        assert_eq!((label.as_str(), x("0.2")), ("load.pin_back.force", 0.2));
    }
}

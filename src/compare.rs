//! `contact2d compare SCENE`: every algorithm × pairing on one generic scene over mesh levels,
//! with run time, iterations, KKT residuals and the error of the scene's key outputs.
//!
//! ```text
//! runs        ContactAlgorithm::ALL × Pairing::ALL × meshes (the scene's own mesh if none given);
//!             a combination the library refuses (Boussinesq on a schedule that is not
//!             proportional, node-to-node with unequal node counts, …) is listed as skipped with
//!             the library's reason
//! time        median over --repeat runs of the whole run (reading to results) and of the
//!             contact solve alone (the summary's time_s.total and time_s.solve)
//! quantities  per contact c: contacts.c.max_pressure, contacts.c.contact_length, and with
//!             friction contacts.c.tangential_force; the total strain energy `energy`; and every
//!             path given with --reference (dotted keys into the JSON summary)
//! reference   per quantity, stated in the table:
//!             closed form   the value given with --reference path=value
//!             Richardson    three or more meshes: Aitken's Δ² extrapolation of the baseline
//!                           (the first algorithm × pairing that runs) on the three finest,
//!                           q∞ = q₃ − (q₃ − q₂)² / ((q₃ − q₂) − (q₂ − q₁)), when the differences
//!                           shrink monotonically; otherwise the baseline's finest value
//!             finest mesh   two meshes: the baseline's value on the finest
//!             same mesh     one mesh: the baseline on the same mesh (the method's error alone)
//! error       |q − q_ref| / |q_ref|
//! ```
//!
//! Writes `compare.csv`, `compare.md` and one work-precision figure per quantity
//! (`compare_<quantity>.png`: error against whole-run time, one line per algorithm × pairing
//! through its mesh levels).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use contact2d_contact::{ContactAlgorithm, Pairing};
use serde_json::Value;

use crate::generic::{load_scene, solve_generic};
use crate::output::OutputError;
use crate::output::chart::{Axes, Series, line_chart};
use crate::scene::SceneError;

/// Command-line flags of `contact2d compare`.
#[derive(Debug, Clone, clap::Args)]
pub struct CompareArgs {
    /// The generic scene (TOML).
    pub scene: PathBuf,
    /// A mesh level (repeat for several, coarse to fine; default: the scene's own mesh).
    #[arg(long = "mesh")]
    pub meshes: Vec<PathBuf>,
    /// Runs per combination; the median time is reported.
    #[arg(long, default_value_t = 3)]
    pub repeat: usize,
    /// A closed-form reference, `dotted.json.path=value` (repeatable).
    #[arg(long = "reference")]
    pub references: Vec<String>,
    /// Scene overrides applied to every run (`--set key=value`, repeatable).
    #[arg(long = "set")]
    pub sets: Vec<String>,
    /// Output directory.
    #[arg(long, default_value = "compare-out")]
    pub out: PathBuf,
}

/// What can stop a comparison (a combination that fails is a row, not an error).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CompareError {
    /// The scene cannot be read.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A flag is malformed.
    #[error("{flag}: {reason}")]
    Flag {
        /// The flag.
        flag: &'static str,
        /// Why.
        reason: String,
    },
    /// Writing the results.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Drawing a figure.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// One algorithm × pairing × mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareRow {
    /// The algorithm's scene key.
    pub algorithm: &'static str,
    /// The pairing's scene key.
    pub pairing: &'static str,
    /// The mesh level (index into the meshes) and its file name.
    pub level: usize,
    /// The mesh file.
    pub mesh: String,
    /// The status, or `skipped`.
    pub status: String,
    /// Why it was skipped or failed (the library's message).
    pub reason: Option<String>,
    /// Median whole-run and solve time, seconds.
    pub time: f64,
    /// Median contact-solve time, seconds.
    pub solve_time: f64,
    /// Iterations summed over the steps.
    pub iterations: usize,
    /// Pairs.
    pub pairs: usize,
    /// The largest KKT residuals: penetration, complementarity, cone.
    pub kkt: [f64; 3],
    /// The quantities' values.
    pub values: BTreeMap<String, f64>,
    /// Their relative errors against the references.
    pub errors: BTreeMap<String, f64>,
}

/// A quantity's reference and how it was obtained.
#[derive(Debug, Clone, PartialEq)]
pub struct Reference {
    /// The value (per mesh level for "same mesh").
    pub values: Vec<f64>,
    /// "closed form", "Richardson (…)", "finest mesh" or "same mesh".
    pub kind: String,
}

/// The outcome of a comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// Every combination.
    pub rows: Vec<CompareRow>,
    /// The reference of each quantity.
    pub references: BTreeMap<String, Reference>,
}

/// Runs the comparison and writes its files; returns the markdown table.
///
/// # Errors
/// An unreadable scene, a malformed flag, or an output that cannot be written.
pub fn run_command(args: &CompareArgs) -> Result<String, CompareError> {
    let comparison = compare(args)?;
    std::fs::create_dir_all(&args.out).map_err(|source| CompareError::Io { path: args.out.clone(), source })?;
    let write = |name: &str, text: String| {
        let path = args.out.join(name);
        std::fs::write(&path, text).map_err(|source| CompareError::Io { path, source })
    };
    let markdown = markdown(&comparison);
    write("compare.md", markdown.clone())?;
    write("compare.csv", csv(&comparison))?;
    for quantity in comparison.references.keys() {
        draw(&args.out.join(format!("compare_{}.png", quantity.replace('.', "_"))), quantity, &comparison.rows)?;
    }
    Ok(markdown)
}

/// Runs every combination (see the module docs).
///
/// # Errors
/// An unreadable scene or a malformed `--reference`.
pub fn compare(args: &CompareArgs) -> Result<Comparison, CompareError> {
    let closed: Vec<(String, f64)> = args
        .references
        .iter()
        .map(|r| {
            let (path, value) = r.split_once('=').ok_or_else(|| CompareError::Flag {
                flag: "--reference",
                reason: format!("{r:?}: expected dotted.path=value"),
            })?;
            let value = value.trim().parse::<f64>().ok().filter(|v| v.is_finite() && *v != 0.0).ok_or_else(|| {
                CompareError::Flag {
                    flag: "--reference",
                    reason: format!("{r:?}: the value must be a non-zero number"),
                }
            })?;
            Ok((path.trim().to_string(), value))
        })
        .collect::<Result<_, CompareError>>()?;
    let base = load_scene(&args.scene, &args.sets)?;
    let meshes: Vec<Option<PathBuf>> = if args.meshes.is_empty() {
        vec![None]
    } else {
        args.meshes.iter().map(|m| Some(std::path::absolute(m).unwrap_or_else(|_| m.clone()))).collect()
    };
    let mut quantities: Vec<String> = vec![];
    for c in &base.contact {
        quantities.push(format!("contacts.{}.max_pressure", c.name));
        quantities.push(format!("contacts.{}.contact_length", c.name));
        if c.friction > 0.0 {
            quantities.push(format!("contacts.{}.tangential_force", c.name));
        }
    }
    quantities.push("energy".into());
    quantities.extend(closed.iter().map(|(p, _)| p.clone()).filter(|p| !quantities.contains(p)).collect::<Vec<_>>());
    let mut rows = vec![];
    for &algorithm in &ContactAlgorithm::ALL {
        for &pairing in Pairing::ALL {
            for (level, mesh) in meshes.iter().enumerate() {
                rows.push(run_one(args, base.contact.len(), algorithm, pairing, level, mesh.as_deref(), &quantities));
            }
        }
    }
    let references = references(&quantities, &closed, &rows, meshes.len());
    for row in &mut rows {
        for (q, r) in &references {
            let reference = if r.values.len() == 1 { r.values[0] } else { r.values[row.level] };
            if let Some(v) = row.values.get(q) {
                row.errors.insert(q.clone(), (v - reference).abs() / reference.abs().max(f64::MIN_POSITIVE));
            }
        }
    }
    Ok(Comparison { rows, references })
}

fn run_one(
    args: &CompareArgs,
    contacts: usize,
    algorithm: ContactAlgorithm,
    pairing: Pairing,
    level: usize,
    mesh: Option<&Path>,
    quantities: &[String],
) -> CompareRow {
    let mut sets = args.sets.clone();
    sets.push(format!("solver.algorithm={}", algorithm.key()));
    sets.extend((0..contacts).map(|i| format!("contact.{i}.pairing={}", pairing.key())));
    if let Some(m) = mesh {
        sets.push(format!("mesh={}", toml::Value::String(m.display().to_string())));
    }
    let mut row = CompareRow {
        algorithm: algorithm.key(),
        pairing: pairing.key(),
        level,
        mesh: mesh
            .map_or_else(|| "(scene)".into(), |m| m.file_name().unwrap_or_default().to_string_lossy().into_owned()),
        status: "skipped".into(),
        reason: None,
        time: f64::NAN,
        solve_time: f64::NAN,
        iterations: 0,
        pairs: 0,
        kkt: [f64::NAN; 3],
        values: BTreeMap::new(),
        errors: BTreeMap::new(),
    };
    let scene = match load_scene(&args.scene, &sets) {
        Ok(s) => s,
        Err(e) => {
            row.reason = Some(e.to_string());
            return row;
        }
    };
    let (mut times, mut solve_times) = (vec![], vec![]);
    for _ in 0..args.repeat.max(1) {
        match solve_generic(&scene, &mut |_, _| {}) {
            Ok(outcome) => {
                let report = &outcome.report;
                times.push(report.time_s.total);
                solve_times.push(report.time_s.solve);
                row.status = report.status.to_string();
                row.reason = report.failed_check.clone();
                row.iterations = report.iterations;
                row.pairs = report.pairs;
                row.kkt = [report.kkt.max_penetration, report.kkt.max_complementarity, report.kkt.max_cone_violation];
                let json = serde_json::to_value(report).unwrap_or(Value::Null);
                for q in quantities {
                    if let Some(v) = quantity(&json, q) {
                        row.values.insert(q.clone(), v);
                    }
                }
            }
            Err(e) => {
                row.reason = Some(e.to_string());
                return row;
            }
        }
    }
    row.time = median(times);
    row.solve_time = median(solve_times);
    row
}

/// A dotted path into the summary, or `energy` (the sum of the bodies' strain energies).
fn quantity(json: &Value, path: &str) -> Option<f64> {
    if path == "energy" {
        return json.get("energies")?.as_object().map(|m| m.values().filter_map(Value::as_f64).sum());
    }
    path.split('.').try_fold(json, |v, key| v.get(key))?.as_f64()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The reference of each quantity (module docs).
fn references(
    quantities: &[String],
    closed: &[(String, f64)],
    rows: &[CompareRow],
    levels: usize,
) -> BTreeMap<String, Reference> {
    // The baseline: the first combination that ran at every level.
    let ran = |r: &CompareRow| r.status != "skipped" && !r.values.is_empty();
    let baseline: Vec<&CompareRow> =
        rows.chunks(levels).find(|chunk| chunk.iter().all(ran)).map(|chunk| chunk.iter().collect()).unwrap_or_default();
    let name = baseline.first().map_or_else(String::new, |r| format!("{} × {}", r.algorithm, r.pairing));
    let mut out = BTreeMap::new();
    for q in quantities {
        if let Some((_, v)) = closed.iter().find(|(p, _)| p == q) {
            out.insert(q.clone(), Reference { values: vec![*v], kind: "closed form".into() });
            continue;
        }
        let values: Vec<f64> = baseline.iter().filter_map(|r| r.values.get(q).copied()).collect();
        if values.len() != levels || values.is_empty() {
            continue;
        }
        let reference = match levels {
            1 => Reference { values, kind: format!("same mesh ({name})") },
            2 => Reference { values: vec![values[1]], kind: format!("finest mesh ({name})") },
            _ => {
                let (q1, q2, q3) = (values[levels - 3], values[levels - 2], values[levels - 1]);
                let (d1, d2) = (q2 - q1, q3 - q2);
                if d1 != 0.0 && d2 * d1 > 0.0 && d2.abs() < d1.abs() {
                    Reference {
                        values: vec![q3 - d2 * d2 / (d2 - d1)],
                        kind: format!("Richardson (Aitken Δ², {name}, ratio {:.2})", d2 / d1),
                    }
                } else {
                    Reference {
                        values: vec![q3],
                        kind: format!("finest mesh ({name}; differences not monotone, no extrapolation)"),
                    }
                }
            }
        };
        out.insert(q.clone(), reference);
    }
    out
}

fn markdown(c: &Comparison) -> String {
    let quantities: Vec<&String> = c.references.keys().collect();
    let mut s = String::from("References:\n\n| quantity | reference | how |\n|---|---|---|\n");
    for (q, r) in &c.references {
        let shown = if r.values.len() == 1 { format!("{:.6e}", r.values[0]) } else { "per mesh".into() };
        s += &format!("| {q} | {shown} | {} |\n", r.kind);
    }
    s += "\n| algorithm | pairing | mesh | pairs | status | time s | solve s | iterations | penetration | complementarity |";
    for q in &quantities {
        s += &format!(" error {q} |");
    }
    s += "\n|---|---|---|---|---|---|---|---|---|---|";
    s += &"---|".repeat(quantities.len());
    s += "\n";
    for r in &c.rows {
        if r.status == "skipped" {
            let reason = r.reason.as_deref().unwrap_or("").replace('|', "/");
            s += &format!("| {} | {} | {} | | skipped: {reason} |", r.algorithm, r.pairing, r.mesh);
            s += &" |".repeat(5 + quantities.len());
            s += "\n";
            continue;
        }
        s += &format!(
            "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {} | {:.1e} | {:.1e} |",
            r.algorithm, r.pairing, r.mesh, r.pairs, r.status, r.time, r.solve_time, r.iterations, r.kkt[0], r.kkt[1]
        );
        for q in &quantities {
            s += &r.errors.get(*q).map_or(" — |".into(), |e| format!(" {e:.2e} |"));
        }
        s += "\n";
    }
    s
}

fn csv(c: &Comparison) -> String {
    let quantities: Vec<&String> = c.references.keys().collect();
    let mut s = String::from(
        "algorithm,pairing,level,mesh,pairs,status,reason,time_s,solve_time_s,iterations,max_penetration,max_complementarity,max_cone_violation",
    );
    for q in &quantities {
        s += &format!(",{q},error_{q}");
    }
    s += "\n";
    let quote = |t: &str| format!("\"{}\"", t.replace('"', "\"\""));
    for r in &c.rows {
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.algorithm,
            r.pairing,
            r.level,
            quote(&r.mesh),
            r.pairs,
            r.status,
            quote(r.reason.as_deref().unwrap_or("")),
            r.time,
            r.solve_time,
            r.iterations,
            r.kkt[0],
            r.kkt[1],
            r.kkt[2]
        );
        for q in &quantities {
            let v = r.values.get(*q).map_or(String::new(), |v| v.to_string());
            let e = r.errors.get(*q).map_or(String::new(), |v| v.to_string());
            s += &format!(",{v},{e}");
        }
        s += "\n";
    }
    s
}

/// Error against whole-run time, one line per algorithm × pairing through its mesh levels.
fn draw(path: &Path, quantity: &str, rows: &[CompareRow]) -> Result<(), OutputError> {
    let mut series: Vec<Series> = vec![];
    for r in rows.iter().filter(|r| r.status != "skipped") {
        let Some(e) = r.errors.get(quantity).copied().filter(|e| *e > 0.0 && r.time > 0.0) else { continue };
        let label = format!("{} × {}", r.algorithm, r.pairing);
        match series.iter_mut().find(|s| s.label == label) {
            Some(s) => s.points.push((r.time, e)),
            None => series.push(Series { label, points: vec![(r.time, e)], markers: true }),
        }
    }
    if series.is_empty() {
        return Ok(());
    }
    let axes = Axes {
        title: format!("work-precision: {quantity}"),
        x_label: "whole-run wall time (s, median)".into(),
        y_label: format!("relative error of {quantity}"),
        log_x: true,
        log_y: true,
    };
    line_chart(path, &axes, &series)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn row(algorithm: &'static str, level: usize, value: Option<f64>) -> CompareRow {
        CompareRow {
            algorithm,
            pairing: "node_to_segment",
            level,
            mesh: format!("L{level}"),
            status: if value.is_some() { "converged".into() } else { "skipped".into() },
            reason: None,
            time: 1.0,
            solve_time: 1.0,
            iterations: 1,
            pairs: 1,
            kkt: [0.0; 3],
            values: value.map(|v| BTreeMap::from([("q".to_string(), v)])).unwrap_or_default(),
            errors: BTreeMap::new(),
        }
    }

    #[test]
    fn aitken_extrapolation_is_exact_for_geometric_convergence() {
        // q_n = 2 + 3 · 4^(−n): Aitken's Δ² recovers the limit 2 exactly (to round-off); the
        // first combination is skipped, so the baseline is the second.
        let q = |n: i32| 2.0 + 3.0 * 4f64.powi(-n);
        let mut rows: Vec<CompareRow> = (0..3).map(|l| row("skipped_one", l, None)).collect();
        rows.extend((0..3).map(|l| row("second", l, Some(q(l as i32 + 1)))));
        let r = references(&["q".to_string()], &[], &rows, 3);
        assert!((r["q"].values[0] - 2.0).abs() < 1e-13, "{:?}", r["q"]);
        assert!(r["q"].kind.starts_with("Richardson") && r["q"].kind.contains("second"));
        // A closed form takes precedence; differences that do not shrink are not extrapolated.
        let r = references(&["q".to_string()], &[("q".to_string(), 2.5)], &rows, 3);
        assert_eq!((r["q"].values[0], r["q"].kind.as_str()), (2.5, "closed form"));
        let rows: Vec<CompareRow> = [1.0, 2.0, 4.0].iter().enumerate().map(|(l, v)| row("a", l, Some(*v))).collect();
        let r = references(&["q".to_string()], &[], &rows, 3);
        assert_eq!(r["q"].values[0], 4.0);
        assert!(r["q"].kind.contains("not monotone"));
    }

    #[test]
    fn quantities_are_dotted_paths_and_energy_is_the_sum() {
        let json: Value =
            serde_json::json!({"contacts": {"c": {"max_pressure": 3.0}}, "energies": {"a": 1.0, "b": 2.5}});
        assert_eq!(quantity(&json, "contacts.c.max_pressure"), Some(3.0));
        assert_eq!(quantity(&json, "energy"), Some(3.5));
        assert_eq!(quantity(&json, "contacts.nope"), None);
    }
}

//! `contact2d compare SCENE`: every algorithm × pairing on one scene — a generic one or the
//! paper's case — over mesh levels, with run time, iterations, KKT residuals and the error of
//! the scene's key outputs (`subject.rs` says what differs between the two kinds).
//!
//! ```text
//! runs        ContactAlgorithm::ALL × the scene's pairings × meshes (if none given: the scene's
//!             own, or for the paper's case its N = 16, 32, 64 meshes);
//!             a combination the library refuses (Boussinesq on a schedule that is not
//!             proportional, node-to-node with unequal node counts, …) is listed as skipped with
//!             the library's reason
//! time        median over --repeat runs of the whole run (reading to results) and of the
//!             contact solve alone (the summary's time_s.total and time_s.solve)
//! quantities  generic: per contact c: contacts.c.max_pressure, contacts.c.contact_length, and
//!             with friction contacts.c.tangential_force; the total strain energy `energy`;
//!             the paper's case: P, l, b (with friction), Phi_E1, Phi_E2, sigma_star, and each
//!             again as `published:<q>` against the published value; and every path given with
//!             --reference (dotted keys into the JSON summary)
//! reference   per quantity, stated in the table:
//!             closed form   the value given with --reference path=value
//!             published     Solodovnikov (1998), for the `published:` quantities
//!             Richardson    three or more meshes: Aitken's Δ² extrapolation of the baseline
//!                           (the first algorithm × pairing that runs) on the three finest,
//!                           q∞ = q₃ − (q₃ − q₂)² / ((q₃ − q₂) − (q₂ − q₁)), when the differences
//!                           shrink monotonically; otherwise the baseline's finest value
//!             finest mesh   two meshes: the baseline's value on the finest
//!             same mesh     one mesh: the baseline on the same mesh (the method's error alone)
//! error       |q − q_ref| / |q_ref|
//! time limit  --time-limit seconds per combination (all its repeats), checked before each load
//!             step: a combination past it stops and is listed as `timed_out`
//! progress    one line per combination, reported through the caller's callback (the CLI
//!             prints it to stderr)
//! ```
//! Every mesh (the `--mesh` levels, or the scene's own) is read before the first combination: a
//! missing or malformed mesh is an error, not a table of failed rows.
//!
//! Writes `compare.csv`, `compare.md` and one work-precision figure per quantity
//! (`compare_<quantity>.png`: error against whole-run time, one line per algorithm × pairing
//! through its mesh levels).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use contact2d_contact::ContactAlgorithm;
use serde_json::Value;

use crate::output::chart::{Axes, Series, line_chart};
use crate::output::{OutputDir, OutputError};
use crate::schema::SceneError;

use crate::scene::Scene;
use crate::subject::RunFailure;

/// The prefix of a quantity compared with its published value (the paper's case), e.g.
/// `published:P`: the same value as `P`, against another reference.
const PUBLISHED: &str = "published:";

/// Command-line flags of `contact2d compare`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct CompareArgs {
    /// The scene (TOML): a generic scene, or one of the paper's case (`[plate_insert]`).
    pub scene: PathBuf,
    /// A mesh level (repeat for several, coarse to fine; default: the scene's own mesh).
    #[cfg_attr(feature = "cli", arg(long = "mesh"))]
    pub meshes: Vec<PathBuf>,
    /// Runs per combination; the median time is reported.
    #[cfg_attr(feature = "cli", arg(long, default_value_t = 3))]
    pub repeat: usize,
    /// A closed-form reference, `dotted.json.path=value` (repeatable).
    #[cfg_attr(feature = "cli", arg(long = "reference"))]
    pub references: Vec<String>,
    /// Scene overrides applied to every run (`--set key=value`, repeatable).
    #[cfg_attr(feature = "cli", arg(long = "set"))]
    pub sets: Vec<String>,
    /// Output directory.
    #[cfg_attr(feature = "cli", arg(long, default_value = "compare-out"))]
    pub out: PathBuf,
    /// Wall-clock limit per combination in seconds (all its repeats together), checked before
    /// each load step: a combination past it is listed as `timed_out` and the next one starts.
    #[cfg_attr(feature = "cli", arg(long = "time-limit", default_value_t = DEFAULT_TIME_LIMIT_S))]
    pub time_limit: f64,
}

/// The default `--time-limit` of a combination, seconds: a pin-cycle combination that converges
/// finishes in seconds, so two minutes leaves ample room while a table of a dozen combinations
/// that never finish still ends within the half hour.
pub const DEFAULT_TIME_LIMIT_S: f64 = 120.0;

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
    /// A mesh level (or the scene's own mesh) that cannot be read.
    #[error("mesh {path}: {reason}")]
    Mesh {
        /// The mesh file.
        path: PathBuf,
        /// Why it cannot be used.
        reason: String,
    },
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
    /// The status, `skipped` (refused or failed, see `reason`) or `timed_out` (past
    /// `--time-limit`).
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

/// Runs the comparison and writes its files; returns the markdown table. `on_row(done, total,
/// row)` is called after each combination (progress).
///
/// # Errors
/// An unreadable scene or mesh, a malformed flag, or an output that cannot be written.
pub fn run_command(
    args: &CompareArgs,
    on_row: &mut dyn FnMut(usize, usize, &CompareRow),
) -> Result<String, CompareError> {
    check_flags(args)?;
    // The folder is checked and locked before the combinations run.
    let mut out = OutputDir::prepare(&args.out, None)?;
    let comparison = compare(args, on_row)?;
    let markdown = markdown(&comparison);
    out.write_bytes("compare.md", markdown.as_bytes())?;
    out.write_bytes("compare.csv", csv(&comparison).as_bytes())?;
    for quantity in comparison.references.keys() {
        let name = format!("compare_{}.png", quantity.replace('.', "_"));
        if has_points(quantity, &comparison.rows) {
            out.write_with(&name, |path| draw(path, quantity, &comparison.rows))?;
        }
    }
    out.close()?;
    Ok(markdown)
}

/// Checks the flags that need no file: `--time-limit` finite and positive.
fn check_flags(args: &CompareArgs) -> Result<(), CompareError> {
    if !(args.time_limit.is_finite() && args.time_limit > 0.0) {
        return Err(CompareError::Flag {
            flag: "--time-limit",
            reason: format!("{} must be a positive number of seconds", args.time_limit),
        });
    }
    Ok(())
}

/// Runs every combination (see the module docs), calling `on_row(done, total, row)` after each.
///
/// # Errors
/// An unreadable scene or mesh, or a malformed `--reference` or `--time-limit`.
pub fn compare(
    args: &CompareArgs,
    on_row: &mut dyn FnMut(usize, usize, &CompareRow),
) -> Result<Comparison, CompareError> {
    check_flags(args)?;
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
    let base = Scene::load(&args.scene, &args.sets)?;
    let meshes: Vec<Option<PathBuf>> = if args.meshes.is_empty() {
        base.default_meshes()
    } else {
        args.meshes.iter().map(|m| Some(std::path::absolute(m).unwrap_or_else(|_| m.clone()))).collect()
    };
    for mesh in &meshes {
        let path = mesh.clone().unwrap_or_else(|| base.mesh_path());
        check_mesh(&path)?;
    }
    let mut quantities = base.quantities();
    quantities.extend(closed.iter().map(|(p, _)| p.clone()).filter(|p| !quantities.contains(p)).collect::<Vec<_>>());
    let mut fixed: Vec<(String, f64, String)> =
        closed.into_iter().map(|(q, v)| (q, v, "closed form".to_string())).collect();
    for (q, v) in base.published() {
        let name = format!("{PUBLISHED}{q}");
        quantities.push(name.clone());
        fixed.push((name, v, "published (Solodovnikov 1998)".into()));
    }
    let pairings = base.pairings();
    let mut rows = vec![];
    let total = ContactAlgorithm::ALL.len() * pairings.len() * meshes.len();
    for &algorithm in &ContactAlgorithm::ALL {
        for (pairing, pairing_sets) in &pairings {
            for (level, mesh) in meshes.iter().enumerate() {
                let case = Case { algorithm, pairing, pairing_sets, level, mesh: mesh.as_deref() };
                let row = run_one(args, &base, &case, &quantities);
                on_row(rows.len() + 1, total, &row);
                rows.push(row);
            }
        }
    }
    let references = references(&quantities, &fixed, &rows, meshes.len());
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

/// Reads `path` as a mesh (the reader's checks: size, FIFO, syntax).
fn check_mesh(path: &Path) -> Result<(), CompareError> {
    let fail = |reason: String| CompareError::Mesh { path: path.to_path_buf(), reason };
    crate::input_file::check_input_file(path, crate::input_file::MAX_MESH_BYTES).map_err(|e| fail(e.reason()))?;
    contact2d_mesh::read_msh(path).map(drop).map_err(|e| fail(e.to_string()))
}

/// One algorithm × pairing × mesh level.
struct Case<'a> {
    algorithm: ContactAlgorithm,
    pairing: &'static str,
    pairing_sets: &'a [String],
    level: usize,
    mesh: Option<&'a Path>,
}

fn run_one(args: &CompareArgs, base: &Scene, case: &Case, quantities: &[String]) -> CompareRow {
    let mut sets = args.sets.clone();
    sets.push(format!("solver.algorithm={}", case.algorithm.key()));
    sets.extend_from_slice(case.pairing_sets);
    if let Some(m) = case.mesh {
        sets.push(base.mesh_override(m));
    }
    let mut row = CompareRow {
        algorithm: case.algorithm.key(),
        pairing: case.pairing,
        level: case.level,
        mesh: case
            .mesh
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
    let subject = match Scene::load(&args.scene, &sets) {
        Ok(s) => s,
        Err(e) => {
            row.reason = Some(e.to_string());
            return row;
        }
    };
    let (mut times, mut solve_times) = (vec![], vec![]);
    let limit = std::time::Duration::from_secs_f64(args.time_limit);
    let deadline = web_time::Instant::now() + limit;
    for _ in 0..args.repeat.max(1) {
        match subject.run(Some(deadline)) {
            Ok(run) => {
                times.push(run.times.0);
                solve_times.push(run.times.1);
                (row.status, row.reason) = run.status;
                row.iterations = run.iterations;
                row.pairs = run.pairs;
                row.kkt = run.kkt;
                for q in quantities {
                    if let Some(v) = quantity(&run.json, q) {
                        row.values.insert(q.clone(), v);
                    }
                }
            }
            Err(RunFailure::TimedOut(why)) => {
                row.status = "timed_out".into();
                row.reason = Some(format!("time limit of {} s: {why}", args.time_limit));
                row.values.clear();
                return row;
            }
            Err(RunFailure::Failed(why)) => {
                row.status = "skipped".into();
                row.reason = Some(why);
                row.values.clear();
                return row;
            }
        }
    }
    row.time = median(times);
    row.solve_time = median(solve_times);
    row
}

/// The quantity at `path` of a summary ([`crate::subject::quantity`]); a `published:` quantity
/// is the value of the path after the prefix.
fn quantity(json: &Value, path: &str) -> Option<f64> {
    crate::subject::quantity(json, path.strip_prefix(PUBLISHED).unwrap_or(path))
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The reference of each quantity (module docs).
fn references(
    quantities: &[String],
    fixed: &[(String, f64, String)],
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
        if let Some((_, v, kind)) = fixed.iter().find(|(p, _, _)| p == q) {
            out.insert(q.clone(), Reference { values: vec![*v], kind: kind.clone() });
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
        if r.status == "skipped" || r.status == "timed_out" {
            let reason = r.reason.as_deref().unwrap_or("").replace('|', "/");
            s += &format!("| {} | {} | {} | | {}: {reason} |", r.algorithm, r.pairing, r.mesh, r.status);
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

/// Whether any row has a point of `quantity` to draw.
fn has_points(quantity: &str, rows: &[CompareRow]) -> bool {
    rows.iter().any(|r| r.errors.get(quantity).is_some_and(|e| *e > 0.0) && r.time > 0.0)
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
        let r = references(&["q".to_string()], &[("q".to_string(), 2.5, "closed form".to_string())], &rows, 3);
        assert_eq!((r["q"].values[0], r["q"].kind.as_str()), (2.5, "closed form"));
        let rows: Vec<CompareRow> = [1.0, 2.0, 4.0].iter().enumerate().map(|(l, v)| row("a", l, Some(*v))).collect();
        let r = references(&["q".to_string()], &[], &rows, 3);
        assert_eq!(r["q"].values[0], 4.0);
        assert!(r["q"].kind.contains("not monotone"));
    }

    #[test]
    fn a_published_quantity_reads_the_path_after_its_prefix() {
        let json: Value = serde_json::json!({"P": 0.19});
        assert_eq!(quantity(&json, "published:P"), Some(0.19));
        assert_eq!(quantity(&json, "P"), Some(0.19));
    }
}

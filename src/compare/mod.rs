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
//! reference   per quantity, named in every output (`reference.rs`: the order of preference):
//!             a closed form (--reference path=value), the published value, or from the most
//!             accurate method that ran on the most accurate level (quadratic before linear,
//!             then the most nodes; segment-to-segment before node-to-segment, exact
//!             algorithms before regularised ones) a Richardson extrapolation of its three
//!             finest levels when the rate is clean (kind `richardson`), else its value there
//!             (kind `finest`)
//! error       |q − q_ref| / |q_ref|; on one mesh with a reference from the runs it is the
//!             relative difference from the reference method, labelled "difference from X"
//! time limit  --time-limit seconds per combination (all its repeats), checked before each load
//!             step: a combination past it stops and is listed as `timed_out`
//! progress    one line per combination, reported through the caller's callback (the CLI
//!             prints it to stderr)
//! ```
//! Every mesh (the `--mesh` levels, or the scene's own) is read before the first combination: a
//! missing or malformed mesh is an error, not a table of failed rows.
//!
//! Writes `compare.json` (the references and the rows), `compare.csv`, `compare_reference.csv`,
//! `compare.md` (`tables.rs`) and one work-precision figure per quantity
//! (`compare_<quantity>.png`: error against whole-run time, one line per algorithm × pairing
//! through its mesh levels, the legend beside the plot).

mod reference;
mod tables;

pub use reference::{
    Deviation, Extrapolation, Level, RATE_BAND, RATE_CONSISTENCY, RATIO_CONSISTENCY, Reference, ReferenceKind,
    richardson,
};
pub use tables::{csv, deviation_column, json, markdown, reference_csv, reference_json};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use contact2d_contact::ContactAlgorithm;
use contact2d_mesh::CellKind;
use serde_json::Value;

use crate::output::chart::{Axes, Series, line_chart_legend_beside};
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
    /// Their relative errors against the references (on one mesh: relative differences from
    /// the reference method, [`Deviation::Difference`]).
    pub errors: BTreeMap<String, f64>,
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
    out.write_bytes("compare.json", json(&comparison).as_bytes())?;
    out.write_bytes("compare.csv", csv(&comparison).as_bytes())?;
    out.write_bytes("compare_reference.csv", reference_csv(&comparison).as_bytes())?;
    for (quantity, reference) in &comparison.references {
        let name = format!("compare_{}.png", quantity.replace('.', "_"));
        if has_points(quantity, &comparison.rows) {
            out.write_with(&name, |path| draw(path, reference, &comparison.rows))?;
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
    let mut levels = vec![];
    for mesh in &meshes {
        let path = mesh.clone().unwrap_or_else(|| base.mesh_path());
        let (nodes, order) = check_mesh(&path)?;
        levels.push(Level { mesh: mesh_name(mesh.as_deref()), nodes, order });
    }
    let mut quantities = base.quantities();
    quantities.extend(closed.iter().map(|(p, _)| p.clone()).filter(|p| !quantities.contains(p)).collect::<Vec<_>>());
    let mut fixed: Vec<(String, f64, ReferenceKind, String)> =
        closed.into_iter().map(|(q, v)| (q, v, ReferenceKind::ClosedForm, "--reference".to_string())).collect();
    for (q, v) in base.published() {
        let name = format!("{PUBLISHED}{q}");
        quantities.push(name.clone());
        fixed.push((name, v, ReferenceKind::Published, "Solodovnikov (1998)".into()));
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
    let references = reference::references(&quantities, &fixed, &rows, &levels);
    for row in &mut rows {
        for (q, r) in &references {
            if let Some(v) = row.values.get(q) {
                row.errors.insert(q.clone(), (v - r.value).abs() / r.value.abs().max(f64::MIN_POSITIVE));
            }
        }
    }
    Ok(Comparison { rows, references })
}

/// Reads `path` as a mesh (the reader's checks: size, FIFO, syntax); returns its nodes and its
/// element order (the lowest of its 2D cells': 1 linear, 2 quadratic).
fn check_mesh(path: &Path) -> Result<(usize, u8), CompareError> {
    let fail = |reason: String| CompareError::Mesh { path: path.to_path_buf(), reason };
    crate::input_file::check_input_file(path, crate::input_file::MAX_MESH_BYTES).map_err(|e| fail(e.reason()))?;
    let mesh = contact2d_mesh::read_msh(path).map_err(|e| fail(e.to_string()))?;
    let order = mesh
        .blocks
        .iter()
        .filter(|b| b.kind.dim() == 2)
        .map(|b| if matches!(b.kind, CellKind::Tri3 | CellKind::Quad4) { 1 } else { 2 })
        .min()
        .unwrap_or(1);
    Ok((mesh.points.len(), order))
}

/// The name of a mesh level in the rows: the file's name, or `(scene)` for the scene's own.
fn mesh_name(mesh: Option<&Path>) -> String {
    mesh.map_or_else(|| "(scene)".into(), |m| m.file_name().unwrap_or_default().to_string_lossy().into_owned())
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
        mesh: mesh_name(case.mesh),
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

/// Whether any row has a point of `quantity` to draw.
fn has_points(quantity: &str, rows: &[CompareRow]) -> bool {
    rows.iter().any(|r| r.errors.get(quantity).is_some_and(|e| *e > 0.0) && r.time > 0.0)
}

/// Error against whole-run time, one line per algorithm × pairing through its mesh levels (in
/// level order), the legend beside the plot; on one mesh the vertical axis is the relative
/// difference from the reference method. A point of zero error (the reference's own row) has
/// no place on the log axis and is left out.
pub(crate) fn draw(path: &Path, reference: &Reference, rows: &[CompareRow]) -> Result<(), OutputError> {
    let quantity = reference.quantity.as_str();
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
    let y_label = match reference.deviation {
        Deviation::Error => format!("relative error of {quantity}"),
        Deviation::Difference => {
            format!("relative difference from {}", reference.from.split(" on ").next().unwrap_or(&reference.from))
        }
    };
    let axes = Axes {
        title: format!("work-precision: {quantity}"),
        x_label: "whole-run wall time (s, median)".into(),
        y_label,
        log_x: true,
        log_y: true,
    };
    line_chart_legend_beside(path, &axes, &series)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
pub(crate) mod tests {
    use super::*;
    use crate::output::chart::FIGURE_SIZE;

    /// A row of `algorithm` × `pairing` on mesh `level` with the value `q` (skipped without one).
    pub(crate) fn row(algorithm: &'static str, pairing: &'static str, level: usize, value: Option<f64>) -> CompareRow {
        CompareRow {
            algorithm,
            pairing,
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

    /// The (x, y, text, font size, anchor) of every `<text>` and the (cx, cy, r) of every
    /// `<circle>` of an SVG written by the chart module (attributes in double quotes).
    #[allow(clippy::type_complexity)]
    fn svg_items(svg: &str) -> (Vec<(f64, f64, String, f64, String)>, Vec<(f64, f64, f64)>, Vec<[f64; 4]>) {
        let attr = |tag: &str, name: &str| -> Option<f64> {
            let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
            tag[start..].split('"').next()?.parse().ok()
        };
        let (mut texts, mut circles, mut boxes) = (vec![], vec![], vec![]);
        for piece in svg.split('<').skip(1) {
            let (tag, rest) = piece.split_once('>').unwrap_or((piece, ""));
            if tag.starts_with("text ") {
                let anchor = ["end", "middle"].into_iter().find(|a| tag.contains(&format!("text-anchor=\"{a}\"")));
                let kind =
                    format!("{}{}", anchor.unwrap_or("start"), if tag.contains("rotate(") { " rotated" } else { "" });
                let size = attr(tag, "font-size").unwrap();
                texts.push((attr(tag, "x").unwrap(), attr(tag, "y").unwrap(), rest.trim().to_string(), size, kind));
            } else if tag.starts_with("circle ") {
                circles.push((attr(tag, "cx").unwrap(), attr(tag, "cy").unwrap(), attr(tag, "r").unwrap()));
            } else if tag.starts_with("rect ") && tag.contains("stroke=\"#000000\"") {
                let (x, y) = (attr(tag, "x").unwrap(), attr(tag, "y").unwrap());
                boxes.push([x, y, x + attr(tag, "width").unwrap(), y + attr(tag, "height").unwrap()]);
            }
        }
        (texts, circles, boxes)
    }

    #[test]
    fn the_work_precision_figure_keeps_its_texts_on_the_canvas_and_its_legend_off_the_points() {
        // Every algorithm × pairing of a generic scene on three levels, errors filling
        // [9.99e-6, 1.2e-3] (the issue's range) against times of 0.05 s to 60 s.
        let mut rows = vec![];
        for (a, algorithm) in ContactAlgorithm::ALL.iter().enumerate() {
            for (p, pairing) in ["node_to_segment", "node_to_node", "segment_to_segment"].into_iter().enumerate() {
                for level in 0..3 {
                    let k = (3 * a + p) as f64;
                    let mut r = row(algorithm.key(), "node_to_segment", level, Some(1.0));
                    r.pairing = pairing;
                    r.time = 0.05 * 4f64.powi(level as i32) * (1.0 + k / 3.0);
                    r.errors.insert(
                        "q".into(),
                        1.2e-3 * 0.3f64.powi(level as i32) / (1.0 + k) + 9.99e-6 * (k - 14.0).abs().min(1.0),
                    );
                    rows.push(r);
                }
            }
        }
        let reference = Reference {
            quantity: "q".into(),
            kind: ReferenceKind::Richardson,
            from: "active_set × segment_to_segment on L0, L1, L2".into(),
            value: 1.0,
            how: String::new(),
            deviation: Deviation::Error,
        };
        let dir = std::env::temp_dir().join(format!("contact2d_compare_figure_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("wp.svg");
        draw(&path, &reference, &rows).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let (texts, circles, boxes) = svg_items(&svg);
        let (w, h) = (f64::from(FIGURE_SIZE.0), f64::from(FIGURE_SIZE.1));
        // Every text on the canvas: its anchor point, and its extent along its line by an upper
        // bound of DejaVu Sans' advance (under 0.62 em a character for these labels).
        for (x, y, text, size, kind) in &texts {
            let width = 0.62 * size * text.chars().count() as f64;
            let (lo, hi) = match kind.split(' ').next().unwrap() {
                "end" => (x - width, *x),
                "middle" => (x - width / 2.0, x + width / 2.0),
                _ => (*x, x + width),
            };
            let (along, length) = if kind.ends_with("rotated") { (*y, h) } else { (*x, w) };
            let (lo, hi) = (lo - x + along, hi - x + along);
            assert!((0.0..=w).contains(x) && (0.0..=h).contains(y), "{text:?} at ({x}, {y})");
            assert!(lo >= 0.0 && hi <= length, "{text:?} spans [{lo}, {hi}] of {length}");
        }
        // Round tick labels only (no "9999999998e-5").
        assert!(texts.iter().all(|t| !t.2.contains("9999") && !t.2.contains("0000")), "{texts:?}");
        // One legend box (the only framed rectangle right of the plot); its sample markers sit
        // in it, every data marker (15 lines × 3 levels) outside it.
        let legend = *boxes.iter().max_by(|a, b| a[0].total_cmp(&b[0])).unwrap();
        let inside = |c: &&(f64, f64, f64)| {
            c.0 + c.2 >= legend[0] && c.0 - c.2 <= legend[2] && c.1 + c.2 >= legend[1] && c.1 - c.2 <= legend[3]
        };
        let (in_legend, data): (Vec<&(f64, f64, f64)>, Vec<_>) = circles.iter().partition(inside);
        assert_eq!((data.len(), in_legend.len()), (45, 15), "legend {legend:?}: {circles:?}");
        assert!(in_legend.iter().all(|c| c.0 > legend[0] && c.0 < legend[2]));
        // The legend names each algorithm × pairing once; each is one line through its levels.
        assert!(texts.iter().filter(|t| t.2 == "augmented_lagrangian × segment_to_segment").count() == 1);
    }

    #[test]
    fn a_published_quantity_reads_the_path_after_its_prefix() {
        let json: Value = serde_json::json!({"P": 0.19});
        assert_eq!(quantity(&json, "published:P"), Some(0.19));
        assert_eq!(quantity(&json, "P"), Some(0.19));
    }
}

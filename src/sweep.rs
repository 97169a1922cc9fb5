//! Parameter sweeps: a scene run over the Cartesian product of varied values, in parallel, with the
//! summary quantities tabulated (CSV, Markdown) and plotted against the first varied parameter.
//!
//! ```text
//! --vary plate_insert.friction=0,0.1,0.3 --vary plate_insert.stiffness_ratio=0.5,1,2
//!   → 9 runs: (0, 0.5), (0, 1), (0, 2), (0.1, 0.5), ...   (the last key varies fastest)
//! ```
//! Each run loads the scene afresh with the base `--set` overrides followed by its own values
//! (`Scene::load(path, overrides)`), so a varied key may be any key `--set` accepts. A run that
//! fails (bad value, set-up error) is a row with its error, never an abort of the sweep. Before
//! any run, [`check_variations`] refuses unknown or repeated keys and more than [`MAX_RUNS`]
//! combinations.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::output::chart::{Axes, Series, line_chart};
use crate::output::{OutputDir, OutputError};
use crate::run::{RunReport, run_scene};
use crate::scene::Scene;

/// Errors of a sweep's set-up or of writing its files (failed runs are rows, not errors).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// A `--vary` argument that is not `KEY=V1,V2,...`.
    #[error("--vary {argument}: {reason}")]
    Vary {
        /// The argument as given.
        argument: String,
        /// What is wrong.
        reason: String,
    },
    /// A `--plot` name that is no summary quantity.
    #[error(
        "--plot: unknown quantity \"{0}\" (known: l, b, P, Phi_E1, Phi_E2, Phi_f, W, sigma_star, K, insert_hoop_max)"
    )]
    UnknownQuantity(String),
    /// A varied key that no scene has.
    #[error("--vary {key}: no such scene key (known: {})", crate::scene::SCENE_KEYS.join(", "))]
    UnknownKey {
        /// The key as given.
        key: String,
    },
    /// The same key varied twice (its rows would be mislabelled).
    #[error("--vary {key}: the key is varied twice; give all its values in one --vary")]
    DuplicateKey {
        /// The key.
        key: String,
    },
    /// More combinations than [`MAX_RUNS`].
    #[error("--vary: {runs} combinations exceed the limit of {MAX_RUNS} runs per sweep")]
    TooManyRuns {
        /// The number of combinations asked for (saturated at `usize::MAX`).
        runs: usize,
    },
    /// Writing a file failed.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// The largest number of runs (combinations) a sweep may ask for; checked before any run or
/// allocation. Each row keeps a summary of a few kB, and at the measured 0.05 .. 2 s per run on
/// the bundled meshes 10 000 runs take hours already.
pub const MAX_RUNS: usize = 10_000;

/// Checks the variations before any run: every key is a scene key, none is varied twice, and the
/// combinations number at most [`MAX_RUNS`].
///
/// # Errors
/// [`SweepError::UnknownKey`], [`SweepError::DuplicateKey`], [`SweepError::TooManyRuns`].
pub fn check_variations(variations: &[Variation]) -> Result<usize, SweepError> {
    for (i, v) in variations.iter().enumerate() {
        if !crate::scene::SCENE_KEYS.contains(&v.key.as_str()) {
            return Err(SweepError::UnknownKey { key: v.key.clone() });
        }
        if variations[..i].iter().any(|w| w.key == v.key) {
            return Err(SweepError::DuplicateKey { key: v.key.clone() });
        }
    }
    let runs = variations.iter().try_fold(1usize, |n, v| n.checked_mul(v.values.len())).unwrap_or(usize::MAX);
    if runs > MAX_RUNS {
        return Err(SweepError::TooManyRuns { runs });
    }
    Ok(runs)
}

/// Splits `text` at the commas outside brackets, braces and quotes (`[0.1,0.2],[0.3]` is two
/// values).
fn split_top_level(text: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut quote, mut start) = (vec![], 0usize, None, 0);
    for (i, c) in text.char_indices() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '"' | '\'') => quote = Some(c),
            (None, '[' | '{') => depth += 1,
            (None, ']' | '}') => depth = depth.saturating_sub(1),
            (None, ',') if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// One varied scene key and its values (as `--set` would take them).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Variation {
    /// Dotted key, e.g. `plate_insert.friction`.
    pub key: String,
    /// The values in the order given.
    pub values: Vec<String>,
}

impl Variation {
    /// Parses `KEY=V1,V2,...` (split at the commas outside brackets and quotes, so a value may
    /// be a list: `plate_insert.l_steps=[0.1,0.2],[0.3]`).
    ///
    /// # Errors
    /// [`SweepError::Vary`] without `=`, with an empty key, or without a value.
    pub fn parse(argument: &str) -> Result<Variation, SweepError> {
        let err = |reason: &str| SweepError::Vary { argument: argument.into(), reason: reason.into() };
        let (key, values) = argument.split_once('=').ok_or_else(|| err("expected KEY=V1,V2,..."))?;
        let key = key.trim();
        if key.is_empty() {
            return Err(err("empty key"));
        }
        let values: Vec<String> =
            split_top_level(values).into_iter().map(|v| v.trim().to_string()).filter(|v| !v.is_empty()).collect();
        if values.is_empty() {
            return Err(err("no values"));
        }
        Ok(Variation { key: key.into(), values })
    }
}

/// A summary quantity of a run that a sweep tabulates and plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Contact end l.
    ContactEnd,
    /// Stick end b.
    StickEnd,
    /// Pulling force P.
    Pull,
    /// Plate strain energy Φ_E1.
    EnergyPlate,
    /// Insert strain energy Φ_E2.
    EnergyInsert,
    /// Dissipated energy Φ_f.
    Dissipation,
    /// Work of the pulling force W.
    Work,
    /// Largest hoop stress σ* on the hole edge.
    SigmaStar,
    /// Stress concentration factor K.
    StressConcentration,
    /// Largest hoop stress of the insert.
    InsertHoopMax,
}

impl Quantity {
    /// All quantities, in table order.
    pub const ALL: [Quantity; 10] = [
        Quantity::ContactEnd,
        Quantity::StickEnd,
        Quantity::Pull,
        Quantity::EnergyPlate,
        Quantity::EnergyInsert,
        Quantity::Dissipation,
        Quantity::Work,
        Quantity::SigmaStar,
        Quantity::StressConcentration,
        Quantity::InsertHoopMax,
    ];

    /// The name used on the command line and in column headers (the JSON summary's key).
    pub fn name(self) -> &'static str {
        match self {
            Quantity::ContactEnd => "l",
            Quantity::StickEnd => "b",
            Quantity::Pull => "P",
            Quantity::EnergyPlate => "Phi_E1",
            Quantity::EnergyInsert => "Phi_E2",
            Quantity::Dissipation => "Phi_f",
            Quantity::Work => "W",
            Quantity::SigmaStar => "sigma_star",
            Quantity::StressConcentration => "K",
            Quantity::InsertHoopMax => "insert_hoop_max",
        }
    }

    /// The axis label: quantity and unit.
    pub fn label(self) -> &'static str {
        match self {
            Quantity::ContactEnd => "contact end l (η, non-dimensional)",
            Quantity::StickEnd => "stick end b (η, non-dimensional)",
            Quantity::Pull => "pulling force P (non-dimensional: / E1 L0)",
            Quantity::EnergyPlate => "plate strain energy Φ_E1 (non-dimensional: / E1 L0²)",
            Quantity::EnergyInsert => "insert strain energy Φ_E2 (non-dimensional: / E1 L0²)",
            Quantity::Dissipation => "dissipated energy Φ_f (non-dimensional: / E1 L0²)",
            Quantity::Work => "work W of the pull (non-dimensional: / E1 L0²)",
            Quantity::SigmaStar => "σ* (largest hole-edge hoop stress / E1)",
            Quantity::StressConcentration => "K = H σ* / P (-)",
            Quantity::InsertHoopMax => "largest insert hoop stress / E1",
        }
    }

    /// Parses a name (as [`Quantity::name`]; also `sigma*`, any case).
    ///
    /// # Errors
    /// [`SweepError::UnknownQuantity`].
    pub fn parse(name: &str) -> Result<Quantity, SweepError> {
        let n = name.trim();
        Quantity::ALL
            .into_iter()
            .find(|q| q.name().eq_ignore_ascii_case(n) || (n == "sigma*" && *q == Quantity::SigmaStar))
            .ok_or_else(|| SweepError::UnknownQuantity(n.into()))
    }

    /// The quantity's value in a run's summary (`None` where the run has none, e.g. no contact end).
    pub fn value(self, r: &RunReport) -> Option<f64> {
        match self {
            Quantity::ContactEnd => r.l,
            Quantity::StickEnd => r.b,
            Quantity::Pull => Some(r.P),
            Quantity::EnergyPlate => Some(r.Phi_E1),
            Quantity::EnergyInsert => Some(r.Phi_E2),
            Quantity::Dissipation => Some(r.Phi_f),
            Quantity::Work => Some(r.W),
            Quantity::SigmaStar => Some(r.sigma_star),
            Quantity::StressConcentration => Some(r.K),
            Quantity::InsertHoopMax => r.insert_hoop_max,
        }
    }
}

/// One run of a sweep: its values of the varied keys and its summary or error.
#[derive(Debug, Clone)]
pub struct SweepRow {
    /// One value per varied key, in the order of the variations.
    pub values: Vec<String>,
    /// The run's summary, or why it failed.
    pub result: Result<RunReport, String>,
}

/// The Cartesian product of the variations' values (the last variation varies fastest).
pub fn combinations(variations: &[Variation]) -> Vec<Vec<String>> {
    variations.iter().fold(vec![vec![]], |acc, v| {
        acc.iter()
            .flat_map(|prefix| {
                v.values.iter().map(move |value| {
                    let mut c = prefix.clone();
                    c.push(value.clone());
                    c
                })
            })
            .collect()
    })
}

/// Runs every combination in parallel; `on_done` is called after each run (for a progress bar).
pub fn run_sweep(
    scene: &Path,
    variations: &[Variation],
    base_overrides: &[String],
    on_done: impl Fn() + Sync,
) -> Vec<SweepRow> {
    run_sweep_with(scene, variations, base_overrides, |_| on_done())
}

/// [`run_sweep`] handing each finished row to `on_row` as it finishes (in completion order), e.g.
/// to append it to a file so that an interrupted sweep keeps its finished rows.
pub fn run_sweep_with(
    scene: &Path,
    variations: &[Variation],
    base_overrides: &[String],
    on_row: impl Fn(&SweepRow) + Sync,
) -> Vec<SweepRow> {
    combinations(variations)
        .into_par_iter()
        .map(|values| {
            let mut overrides = base_overrides.to_vec();
            overrides.extend(variations.iter().zip(&values).map(|(v, value)| format!("{}={value}", v.key)));
            let result = Scene::load(scene, &overrides)
                .map_err(|e| e.to_string())
                .and_then(|s| run_scene(&s).map_err(|e| e.to_string()));
            let row = SweepRow { values, result };
            on_row(&row);
            row
        })
        .collect()
}

/// The cells of one row: varied values, status, the quantities, iterations, error.
fn cells(row: &SweepRow, digits: Option<usize>) -> Vec<String> {
    let mut c = row.values.clone();
    let num = |v: Option<f64>| match (v, digits) {
        (Some(x), Some(d)) => significant(x, d),
        (Some(x), None) => format!("{x:?}"),
        (None, _) => String::new(),
    };
    match &row.result {
        Ok(r) => {
            c.push(r.status.clone());
            c.extend(Quantity::ALL.iter().map(|q| num(q.value(r))));
            c.push(r.iterations.to_string());
            c.push(String::new());
        }
        Err(e) => {
            c.push("error".into());
            c.extend(Quantity::ALL.iter().map(|_| String::new()));
            c.push(String::new());
            c.push(e.clone());
        }
    }
    c
}

/// `x` with `d` significant digits: fixed point for 1e-3 ≤ |x| < 1e5, scientific otherwise.
fn significant(x: f64, d: usize) -> String {
    let a = x.abs();
    if x == 0.0 || !(1e-3..1e5).contains(&a) {
        return if x == 0.0 { "0".into() } else { format!("{x:.prec$e}", prec = d.saturating_sub(1)) };
    }
    let decimals = (d as i32 - 1 - a.log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The column names: varied keys, status, quantities, iterations, error.
fn header(variations: &[Variation]) -> Vec<String> {
    let mut h: Vec<String> = variations.iter().map(|v| v.key.clone()).collect();
    h.push("status".into());
    h.extend(Quantity::ALL.iter().map(|q| q.name().to_string()));
    h.push("iterations".into());
    h.push("error".into());
    h
}

/// The sweep as CSV (numbers in shortest round-trip form; errors quoted).
pub fn sweep_csv(variations: &[Variation], rows: &[SweepRow]) -> String {
    let mut t = sweep_csv_header(variations);
    for row in rows {
        t.push_str(&sweep_csv_row(row));
    }
    t
}

/// The header line of [`sweep_csv`] (with its newline).
pub fn sweep_csv_header(variations: &[Variation]) -> String {
    header(variations).join(",") + "\n"
}

/// One row line of [`sweep_csv`] (with its newline).
pub fn sweep_csv_row(row: &SweepRow) -> String {
    let quote = |s: &str| {
        if s.contains([',', '"', '\n']) {
            format!("\"{}\"", s.replace('"', "\"\"").replace('\n', " "))
        } else {
            s.into()
        }
    };
    let line: Vec<String> = cells(row, None).iter().map(|c| quote(c)).collect();
    line.join(",") + "\n"
}

/// The sweep as a Markdown table (numbers to four significant digits).
pub fn sweep_markdown(variations: &[Variation], rows: &[SweepRow]) -> String {
    let h = header(variations);
    let mut t = format!("| {} |\n|{}\n", h.join(" | "), "---|".repeat(h.len()));
    for row in rows {
        let line: Vec<String> = cells(row, Some(4)).iter().map(|c| c.replace('|', "\\|").replace('\n', " ")).collect();
        let _ = writeln!(t, "| {} |", line.join(" | "));
    }
    t
}

/// Plots `quantity` against the first varied key, one line per combination of the others; the x
/// axis is logarithmic when the values are positive and span more than two decades. Non-numeric
/// first-key values are plotted at their index.
///
/// # Errors
/// As [`line_chart`].
pub fn plot_sweep(
    path: &Path,
    title: &str,
    variations: &[Variation],
    rows: &[SweepRow],
    quantity: Quantity,
) -> Result<(), OutputError> {
    let first = variations.first().map(|v| v.key.as_str()).unwrap_or("");
    let numeric: Option<Vec<f64>> = variations
        .first()
        .map_or(Some(vec![]), |v| v.values.iter().map(|s| s.parse::<f64>().ok()).collect::<Option<Vec<f64>>>());
    let x_of = |value: &str| -> f64 {
        match &numeric {
            Some(_) => value.parse().unwrap_or(f64::NAN),
            None => variations[0].values.iter().position(|v| v == value).map_or(f64::NAN, |i| i as f64),
        }
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
            quantity.name().to_string()
        };
        let y = row.result.as_ref().ok().and_then(|r| quantity.value(r)).unwrap_or(f64::NAN);
        let point = (x_of(row.values.first().map_or("", String::as_str)), y);
        match series.iter_mut().find(|s| s.label == label) {
            Some(s) => s.points.push(point),
            None => series.push(Series { label, points: vec![point], markers: true }),
        }
    }
    for s in &mut series {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    let log_x = numeric.as_ref().is_some_and(|x| {
        let (lo, hi) = x.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        lo > 0.0 && hi / lo > 100.0
    });
    let x_label = match &numeric {
        Some(_) => first.to_string(),
        None => format!("{first} (index of: {})", variations[0].values.join(", ")),
    };
    let axes = Axes { title: title.into(), x_label, y_label: quantity.label().into(), log_x, log_y: false };
    line_chart(path, &axes, &series)
}

/// Writes `sweep.csv`, `sweep.md` and `sweep_<quantity>.png/.svg` for each plotted quantity into
/// `dir` (see [`write_sweep_into`]); the folder is prepared (created, checked, locked) here.
///
/// # Errors
/// [`SweepError::Output`] naming the folder or the file that could not be written.
pub fn write_sweep(
    dir: &Path,
    scene_name: &str,
    variations: &[Variation],
    rows: &[SweepRow],
    plots: &[Quantity],
) -> Result<Vec<PathBuf>, SweepError> {
    write_sweep_into(OutputDir::prepare(dir, None)?, scene_name, variations, rows, plots)
}

/// Writes the plots, `sweep.md` and `sweep.csv` (rows in combination order) into the prepared
/// folder `out`, each atomically, the CSV last; stale sweep files of an earlier sweep go. A plot
/// that cannot be drawn (no finite value, an unrepresentable range) is skipped with a note at the
/// end of `sweep.md`. Returns the paths written.
///
/// # Errors
/// [`SweepError::Output`] naming the file that could not be written.
pub fn write_sweep_into(
    mut out: OutputDir,
    scene_name: &str,
    variations: &[Variation],
    rows: &[SweepRow],
    plots: &[Quantity],
) -> Result<Vec<PathBuf>, SweepError> {
    let mut skipped = vec![];
    if !variations.is_empty() {
        for q in plots {
            for ext in crate::output::FIGURE_EXTENSIONS {
                let name = format!("sweep_{}.{ext}", q.name());
                let title = format!("{scene_name}: {} against {}", q.name(), variations[0].key);
                match out.write_with(&name, |p| plot_sweep(p, &title, variations, rows, *q)) {
                    Ok(_) => {}
                    Err(OutputError::Undrawable { reason, .. }) => skipped.push(format!("{name} not drawn: {reason}")),
                    Err(e) => return Err(e.into()),
                }
            }
        }
    }
    let mut md = sweep_markdown(variations, rows);
    if !skipped.is_empty() {
        let _ = writeln!(md, "\nNot drawn:\n");
        for note in &skipped {
            let _ = writeln!(md, "* {note}");
        }
    }
    out.write_bytes("sweep.md", md.as_bytes())?;
    out.write_bytes("sweep.csv", sweep_csv(variations, rows).as_bytes())?;
    Ok(out.close()?)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn variations_parse_and_multiply() {
        let a = Variation::parse("plate_insert.friction=0, 0.1,0.3").unwrap();
        assert_eq!(a.values, ["0", "0.1", "0.3"]);
        let b = Variation::parse("solver.algorithm=active_set,clarabel").unwrap();
        let c = combinations(&[a, b]);
        assert_eq!(c.len(), 6);
        assert_eq!(c[1], ["0", "clarabel"]);
        assert_eq!(combinations(&[]), vec![Vec::<String>::new()]);
        for bad in ["noequals", "=1,2", "key="] {
            assert!(matches!(Variation::parse(bad), Err(SweepError::Vary { .. })), "{bad}");
        }
    }

    #[test]
    fn values_split_at_top_level_commas_and_keys_are_checked() {
        let v = Variation::parse("plate_insert.l_steps=[0.1,0.2],[0.3], \"a,b\"").unwrap();
        assert_eq!(v.values, ["[0.1,0.2]", "[0.3]", "\"a,b\""]);
        let nope = Variation::parse("plate_insert.nope=1").unwrap();
        assert!(matches!(check_variations(&[nope]), Err(SweepError::UnknownKey { .. })));
        let f = Variation::parse("plate_insert.friction=0,0.1").unwrap();
        assert!(matches!(check_variations(&[f.clone(), f.clone()]), Err(SweepError::DuplicateKey { .. })));
        assert_eq!(check_variations(std::slice::from_ref(&f)).unwrap(), 2);
        // 10^8 combinations are refused before any is built.
        let big = |key: &str| Variation { key: key.into(), values: (0..100).map(|i| i.to_string()).collect() };
        let many = [
            big("plate_insert.friction"),
            big("plate_insert.load"),
            big("plate_insert.eps"),
            big("plate_insert.steps"),
        ];
        assert!(matches!(check_variations(&many), Err(SweepError::TooManyRuns { runs: 100_000_000 })));
    }

    #[test]
    fn quantities_parse_by_name() {
        for q in Quantity::ALL {
            assert_eq!(Quantity::parse(q.name()).unwrap(), q);
        }
        assert_eq!(Quantity::parse("sigma*").unwrap(), Quantity::SigmaStar);
        assert_eq!(Quantity::parse("p").unwrap(), Quantity::Pull);
        assert!(matches!(Quantity::parse("nope"), Err(SweepError::UnknownQuantity(_))));
    }

    #[test]
    fn a_failed_run_is_a_row_with_its_error() {
        let v = [Variation::parse("plate_insert.friction=0.1").unwrap()];
        let rows = [SweepRow { values: vec!["0.1".into()], result: Err("bad, \"value\"".into()) }];
        let csv = sweep_csv(&v, &rows);
        assert!(csv.lines().nth(1).unwrap().starts_with("0.1,error,"));
        assert!(csv.contains("\"bad, \"\"value\"\"\""));
        let md = sweep_markdown(&v, &rows);
        assert_eq!(md.lines().count(), 3);
        assert_eq!(significant(0.19497, 4), "0.1950");
        assert_eq!(significant(4.651e-5, 4), "4.651e-5");
    }
}

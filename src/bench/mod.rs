//! `contact2d bench`: wall time against discretisation error for the flagship cases, mesh levels
//! and contact algorithms.
//!
//! ```text
//! for case in {no gap μ = 0, no gap μ = 0.3, Table 2 U(1), U(2), U(3)}     (the bundled scenes)
//!   for N in levels (the bundled Quad9 meshes *_N16/32/64/128.msh; Q9 is the only element type
//!                    the plate-with-insert meshes exist for)
//!     for algorithm in {boussinesq, active_set, clarabel}
//!       solve_scene(scene with the level's mesh and the algorithm) `repeats` times
//!       → median, min, max of the wall time; P, Φ_E = Φ_E1 + Φ_E2, l, b, σ*
//! reference per case and quantity: Richardson extrapolation from the three finest levels
//!   (see [`reference`]); error = |q − q_ref| / |q_ref|
//! ```
//!
//! A combination is skipped (with a note) when the previous level of the same case and algorithm
//! took so long that four times its median (the DOFs grow fourfold per level, and no part of the
//! solve is cheaper than linear) exceeds `--max-seconds`; repeats stop once the combination has
//! used `--max-seconds` (at least one run is always made).

pub mod report;

use std::path::{Path, PathBuf};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use crate::output::OutputDir;
use crate::run::{RunOutcome, solve_scene};
use contact2d_contact::ContactAlgorithm;

use crate::plate_insert::PlateInsertScene;
use crate::scene::SceneError;

// The references are shared with verify (pin_lug), which the `studies` feature builds without bench.
pub use crate::reference::{self, Quantity, Reference, ReferenceMethod, richardson};

/// Errors of the benchmark command.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum BenchError {
    /// A scene could not be loaded.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A flag value that names nothing.
    #[error("{flag}: {reason}")]
    Flag {
        /// The flag.
        flag: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// An output file could not be written.
    #[error("cannot write {path}: {reason}")]
    Output {
        /// The file.
        path: String,
        /// The cause.
        reason: String,
    },
}

/// The flagship cases of the benchmark (the bundled scenes).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BenchCase {
    /// No gap, μ = 0 (`plate_insert_nogap_mu0.toml`).
    NogapMu0,
    /// No gap, μ = 0.3 (`plate_insert_nogap_mu03.toml`).
    NogapMu03,
    /// Table 2 U(1): c = 1, ε = 0.05, variant 1, μ = 0.3, three load steps.
    U1,
    /// Table 2 U(2): variant 2, μ = 0.3, three load steps.
    U2,
    /// Table 2 U(3): variant 2, μ = 0.
    U3,
}

impl BenchCase {
    /// Every case, in table order.
    pub const ALL: [BenchCase; 5] =
        [BenchCase::NogapMu0, BenchCase::NogapMu03, BenchCase::U1, BenchCase::U2, BenchCase::U3];

    /// The name used on the command line and in outputs.
    pub fn name(self) -> &'static str {
        match self {
            BenchCase::NogapMu0 => "nogap_mu0",
            BenchCase::NogapMu03 => "nogap_mu03",
            BenchCase::U1 => "U1",
            BenchCase::U2 => "U2",
            BenchCase::U3 => "U3",
        }
    }

    /// The bundled scene file.
    pub fn scene_file(self) -> &'static str {
        match self {
            BenchCase::NogapMu0 => "plate_insert_nogap_mu0.toml",
            BenchCase::NogapMu03 => "plate_insert_nogap_mu03.toml",
            BenchCase::U1 => "plate_insert_gap_v1_mu03.toml",
            BenchCase::U2 => "plate_insert_gap_v2_mu03.toml",
            BenchCase::U3 => "plate_insert_gap_v2_mu0.toml",
        }
    }

    /// Whether the case has friction (b differs from l only then).
    pub fn frictional(self) -> bool {
        matches!(self, BenchCase::NogapMu03 | BenchCase::U1 | BenchCase::U2)
    }

    fn parse(s: &str) -> Option<BenchCase> {
        BenchCase::ALL.into_iter().find(|c| c.name().eq_ignore_ascii_case(s.trim()))
    }
}

/// Command-line flags of `contact2d bench`.
#[derive(Debug, Clone, clap::Args)]
pub struct BenchArgs {
    /// Cases, comma separated: nogap_mu0, nogap_mu03, U1, U2, U3.
    #[arg(long, value_delimiter = ',', default_value = "nogap_mu0,nogap_mu03,U1,U2,U3")]
    pub cases: Vec<String>,
    /// Mesh levels N (elements on the half circle), comma separated; bundled: 16, 32, 64, 128.
    #[arg(long, value_delimiter = ',', default_value = "16,32,64,128")]
    pub levels: Vec<usize>,
    /// Algorithms, comma separated: boussinesq, active_set, clarabel.
    #[arg(long, value_delimiter = ',', default_value = "boussinesq,active_set,clarabel")]
    pub algorithms: Vec<String>,
    /// Runs per combination (the median, min and max are reported).
    #[arg(long, default_value_t = 3)]
    pub repeats: usize,
    /// Time budget per combination in seconds (see the module documentation).
    #[arg(long, default_value_t = 30.0)]
    pub max_seconds: f64,
    /// Directory of the bundled scenes.
    #[arg(long, default_value = "scenes")]
    pub scenes: PathBuf,
    /// Output directory (bench.csv, bench.md, bench_CASE.svg and .png).
    #[arg(long, default_value = "bench-out")]
    pub out: PathBuf,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// The validated grid.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchConfig {
    /// Cases.
    pub cases: Vec<BenchCase>,
    /// Mesh levels, ascending.
    pub levels: Vec<usize>,
    /// Algorithms.
    pub algorithms: Vec<ContactAlgorithm>,
    /// Runs per combination.
    pub repeats: usize,
    /// Time budget per combination, seconds.
    pub max_seconds: f64,
    /// Directory of the bundled scenes.
    pub scenes: PathBuf,
}

impl BenchConfig {
    /// Parses and checks the flags.
    ///
    /// # Errors
    /// [`BenchError::Flag`] for an unknown case or algorithm, an empty list, no repeats or a
    /// non-positive budget.
    pub fn from_args(args: &BenchArgs) -> Result<BenchConfig, BenchError> {
        let flag = |flag, reason: String| BenchError::Flag { flag, reason };
        let cases = args
            .cases
            .iter()
            .map(|s| BenchCase::parse(s).ok_or_else(|| flag("--cases", format!("unknown case {s:?}"))))
            .collect::<Result<Vec<_>, _>>()?;
        let algorithms = args
            .algorithms
            .iter()
            .map(|s| {
                crate::schema::algorithm_from_key(s)
                    .ok_or_else(|| flag("--algorithms", format!("unknown algorithm {s:?}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut levels = args.levels.clone();
        levels.sort_unstable();
        levels.dedup();
        if cases.is_empty() || algorithms.is_empty() || levels.is_empty() {
            return Err(flag("--cases/--levels/--algorithms", "empty list".into()));
        }
        if let Some(bad) = levels.iter().find(|n| **n == 0) {
            return Err(flag("--levels", format!("{bad}: a mesh level is at least 1 (bundled: 16, 32, 64, 128)")));
        }
        if args.repeats == 0 {
            return Err(flag("--repeats", "must be at least 1".into()));
        }
        if !(args.max_seconds.is_finite() && args.max_seconds > 0.0) {
            return Err(flag("--max-seconds", format!("must be positive, got {}", args.max_seconds)));
        }
        Ok(BenchConfig {
            cases,
            levels,
            algorithms,
            repeats: args.repeats,
            max_seconds: args.max_seconds,
            scenes: args.scenes.clone(),
        })
    }

    /// Number of (case, level, algorithm) combinations.
    pub fn combinations(&self) -> usize {
        self.cases.len() * self.levels.len() * self.algorithms.len()
    }
}

/// The quantities of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Values {
    /// Pulling force P.
    pub pull: f64,
    /// Φ_E = Φ_E1 + Φ_E2.
    pub energy: f64,
    /// Contact end l.
    pub contact_end: Option<f64>,
    /// Stick end b.
    pub stick_end: Option<f64>,
    /// σ*.
    pub sigma_star: f64,
}

impl Values {
    /// The value of one quantity.
    pub fn get(&self, q: Quantity) -> Option<f64> {
        match q {
            Quantity::Pull => Some(self.pull),
            Quantity::Energy => Some(self.energy),
            Quantity::ContactEnd => self.contact_end,
            Quantity::StickEnd => self.stick_end,
            Quantity::SigmaStar => Some(self.sigma_star),
        }
    }
}

/// One (case, level, algorithm) combination.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// Case.
    pub case: BenchCase,
    /// Mesh level N.
    pub level: usize,
    /// Algorithm.
    pub algorithm: ContactAlgorithm,
    /// Free DOFs (0 when not run).
    pub dofs: usize,
    /// Contact pairs.
    pub pairs: usize,
    /// Status of the last run ("skipped" or "error" when there is none).
    pub status: String,
    /// Iterations (summed over the load steps).
    pub iterations: usize,
    /// Wall times of the whole run (mesh reading to quantities), seconds, one per repeat.
    pub times: Vec<f64>,
    /// Wall times of the contact algorithm alone, seconds, one per repeat.
    pub solve_times: Vec<f64>,
    /// The quantities (of the last run; `None` when not run).
    pub values: Option<Values>,
    /// Why the combination was skipped or repeated fewer times, or the error.
    pub note: String,
}

impl Measurement {
    /// Median of the wall times.
    pub fn median_time(&self) -> Option<f64> {
        median(&self.times)
    }
}

/// Median of a sample (the mean of the middle two for an even count).
pub fn median(v: &[f64]) -> Option<f64> {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(s[n / 2]),
        _ => Some(0.5 * (s[n / 2 - 1] + s[n / 2])),
    }
}

/// The mesh of `level` in place of the scene's own: `..._N64.msh` becomes `..._N{level}.msh`.
fn mesh_for_level(mesh: &Path, level: usize) -> Option<String> {
    let text = mesh.to_str()?;
    let at = text.rfind("_N")?;
    text[at..].ends_with(".msh").then(|| format!("{}_N{level}.msh", &text[..at]))
}

/// A progress bar over `len` steps, drawn on stderr only when stdout is a terminal and not
/// `quiet` (hidden otherwise).
pub fn progress_bar(len: usize, quiet: bool) -> ProgressBar {
    use std::io::IsTerminal;
    let bar = ProgressBar::with_draw_target(
        Some(len as u64),
        if quiet || !std::io::stdout().is_terminal() {
            ProgressDrawTarget::hidden()
        } else {
            ProgressDrawTarget::stderr()
        },
    );
    if let Ok(style) = ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}") {
        bar.set_style(style);
    }
    bar
}

/// The whole command: checks the flags, runs the grid with a progress bar, writes `bench.csv`,
/// `bench.md` and the figures into `args.out`, and returns the markdown.
///
/// # Errors
/// Bad flags, an unloadable scene, or an output that cannot be written.
pub fn run_command(args: &BenchArgs) -> Result<String, BenchError> {
    let config = BenchConfig::from_args(args)?;
    check_meshes(&config)?;
    // The output folder is checked and locked before the grid runs.
    let out = OutputDir::prepare(&args.out, None).map_err(|e| out_err(&args.out, &e))?;
    let bar = progress_bar(config.combinations(), args.quiet);
    let measurements = run_bench(&config, &bar)?;
    if let Some(first) = measurements.first()
        && measurements.iter().all(|m| m.status == "error")
    {
        return Err(BenchError::Flag {
            flag: "--cases/--levels/--algorithms",
            reason: format!("every combination failed; the first: {}", first.note),
        });
    }
    write_outputs_into(out, &measurements)
}

/// Checks before any run that every (case, level) has its mesh file.
///
/// # Errors
/// [`BenchError::Flag`] on `--levels` naming the missing mesh; [`BenchError::Scene`].
pub fn check_meshes(config: &BenchConfig) -> Result<(), BenchError> {
    for &case in &config.cases {
        let path = config.scenes.join(case.scene_file());
        let base = PlateInsertScene::load(&path, &[])?;
        for &level in &config.levels {
            let Some(mesh) = mesh_for_level(&base.plate_insert.mesh, level) else { continue };
            let mesh = base.base_dir.join(mesh);
            if !mesh.is_file() {
                return Err(BenchError::Flag {
                    flag: "--levels",
                    reason: format!(
                        "no mesh for N = {level} of case {}: {} is not a file",
                        case.name(),
                        mesh.display()
                    ),
                });
            }
        }
    }
    Ok(())
}

fn out_err(path: &Path, e: &dyn std::fmt::Display) -> BenchError {
    BenchError::Output { path: path.display().to_string(), reason: e.to_string() }
}

/// Writes `bench.csv`, `bench.md` and the figures into `dir`; returns the markdown.
///
/// # Errors
/// [`BenchError::Output`] naming the file.
pub fn write_outputs(dir: &Path, measurements: &[Measurement]) -> Result<String, BenchError> {
    let out = OutputDir::prepare(dir, None).map_err(|e| out_err(dir, &e))?;
    write_outputs_into(out, measurements)
}

/// [`write_outputs`] into a prepared folder: each file atomic, stale bench files removed.
///
/// # Errors
/// [`BenchError::Output`] naming the file.
pub fn write_outputs_into(mut out: OutputDir, measurements: &[Measurement]) -> Result<String, BenchError> {
    let dir = out.path().to_path_buf();
    let refs = report::references(measurements);
    let md = report::markdown(measurements, &refs);
    for (name, axes, series) in report::figure_specs(measurements, &refs) {
        out.write_with(&name, |p| crate::output::chart::line_chart(p, &axes, &series))
            .map_err(|e| out_err(&dir.join(&name), &e))?;
    }
    for (name, text) in [("bench.md", md.clone()), ("bench.csv", report::csv(measurements, &refs))] {
        out.write_bytes(name, text.as_bytes()).map_err(|e| out_err(&dir.join(name), &e))?;
    }
    out.close().map_err(|e| out_err(&dir, &e))?;
    Ok(md)
}

/// Runs the grid, advancing `bar` by one per combination.
///
/// # Errors
/// A scene that cannot be loaded; a failing run is recorded as a measurement with its error.
pub fn run_bench(config: &BenchConfig, bar: &ProgressBar) -> Result<Vec<Measurement>, BenchError> {
    let mut out = Vec::new();
    for &case in &config.cases {
        let path = config.scenes.join(case.scene_file());
        let base = PlateInsertScene::load(&path, &[])?;
        for &algorithm in &config.algorithms {
            let mut previous: Option<f64> = None;
            for &level in &config.levels {
                bar.set_message(format!("{} N = {level} {}", case.name(), algorithm.key()));
                let m = measure(config, case, &path, &base, level, algorithm, previous)?;
                previous = m.median_time().or(previous.map(|t| 4.0 * t));
                out.push(m);
                bar.inc(1);
            }
        }
    }
    bar.finish_and_clear();
    Ok(out)
}

fn measure(
    config: &BenchConfig,
    case: BenchCase,
    path: &Path,
    base: &PlateInsertScene,
    level: usize,
    algorithm: ContactAlgorithm,
    previous: Option<f64>,
) -> Result<Measurement, BenchError> {
    let mut m = Measurement {
        case,
        level,
        algorithm,
        dofs: 0,
        pairs: 0,
        status: "skipped".into(),
        iterations: 0,
        times: vec![],
        solve_times: vec![],
        values: None,
        note: String::new(),
    };
    if let Some(t) = previous
        && 4.0 * t > config.max_seconds
    {
        m.note =
            format!("predicted ≥ {:.0} s (4 × the previous level), over --max-seconds {}", 4.0 * t, config.max_seconds);
        return Ok(m);
    }
    let mesh = mesh_for_level(&base.plate_insert.mesh, level).ok_or_else(|| BenchError::Flag {
        flag: "--levels",
        reason: format!("scene mesh {} has no _N<level>.msh name", base.plate_insert.mesh.display()),
    })?;
    let overrides = [format!("plate_insert.mesh={mesh:?}"), format!("solver.algorithm=\"{}\"", algorithm.key())];
    let scene = PlateInsertScene::load(path, &overrides)?;
    let budget = Instant::now();
    for _ in 0..config.repeats {
        match solve_scene(&scene) {
            Ok(RunOutcome { report: r, paper: q, .. }) => {
                m.dofs = r.dofs;
                m.pairs = r.pairs;
                m.status = r.status.into();
                m.iterations = r.iterations;
                m.times.push(r.time_s.total);
                m.solve_times.push(r.time_s.solve);
                m.values = Some(Values {
                    pull: q.P,
                    energy: q.Phi_E1 + q.Phi_E2,
                    contact_end: q.l,
                    stick_end: q.b,
                    sigma_star: q.sigma_star,
                });
            }
            Err(e) => {
                m.status = "error".into();
                m.note = e.to_string();
                return Ok(m);
            }
        }
        if budget.elapsed().as_secs_f64() > config.max_seconds {
            break;
        }
    }
    if m.times.len() < config.repeats {
        m.note = format!("{} of {} repeats (over --max-seconds {})", m.times.len(), config.repeats, config.max_seconds);
    }
    Ok(m)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn median_of_odd_and_even_samples() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
        assert_eq!(median(&[]), None);
    }

    #[test]
    fn mesh_names_follow_the_level() {
        let m = mesh_for_level(Path::new("../meshes/plate_insert/plate_insert_eps0.05_N64.msh"), 16).unwrap();
        assert_eq!(m, "../meshes/plate_insert/plate_insert_eps0.05_N16.msh");
        assert!(mesh_for_level(Path::new("mesh.msh"), 16).is_none());
    }

    #[test]
    fn flags_are_checked() {
        let args = BenchArgs {
            cases: vec!["U1".into()],
            levels: vec![32, 16, 32],
            algorithms: vec!["active_set".into()],
            repeats: 1,
            max_seconds: 1.0,
            scenes: "scenes".into(),
            out: "o".into(),
            quiet: true,
        };
        let c = BenchConfig::from_args(&args).unwrap();
        assert_eq!(c.levels, vec![16, 32]);
        assert_eq!(c.cases, vec![BenchCase::U1]);
        let bad = BenchArgs { cases: vec!["U9".into()], ..args.clone() };
        assert!(matches!(BenchConfig::from_args(&bad), Err(BenchError::Flag { .. })));
        let bad = BenchArgs { algorithms: vec!["newton".into()], ..args.clone() };
        assert!(BenchConfig::from_args(&bad).is_err());
        let bad = BenchArgs { repeats: 0, ..args };
        assert!(BenchConfig::from_args(&bad).is_err());
    }
}

//! `contact2d stress`: numerical stress tests of the flagship problem at extreme parameters.
//!
//! ```text
//! main grid (plane stress, ν = 0.3, the mesh as generated):
//!   E2/E1 ∈ {1e-4, 1e-2, 1, 1e2, 1e4, 1e6} × μ ∈ {0, 0.1, 0.3, 0.6, 1.0, 1.5} × ε ∈ {0, 1e-6, 1e-3, 0.05, 0.2}
//! extra axes (on E2/E1 ∈ {1e-4, 1, 1e6} × μ ∈ {0, 0.3, 1.5} × ε ∈ {0, 0.05}):
//!   plane strain with ν = 0.45 and 0.49;  plane stress, ν = 0.3, interior nodes distorted by
//!   0.15, 0.25 and 0.3 of their local spacing ([`distort`]; 0.3 inverts a cell of the N = 16
//!   mesh, which shows how that is reported)
//! every cell: variant 1, c = 1 with the paper's gap when ε > 0 (w = 0.3838 in 3 steps), neat
//!   fit otherwise (w = 1), each algorithm (active set, Clarabel, Boussinesq), see [`cell`]
//! ```
//!
//! Meshes: the bundled `plate_insert_eps{ε}_N{N}.msh` (ε = 1e-6, 1e-3, 0.2 exist for N = 16 and
//! 32 only); distorted meshes are written to a temporary directory.

pub mod cell;
pub mod distort;
pub mod report;

use std::path::{Path, PathBuf};

use contact2d_element::PlaneCondition;
use contact2d_mesh::{MshFormat, read_msh, write_msh};

use crate::bench::progress_bar;
use contact2d_contact::ContactAlgorithm;

pub use cell::{CellResult, StressCell, run_cell};

/// Errors of the stress command.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StressError {
    /// A flag value that names nothing.
    #[error("{flag}: {reason}")]
    Flag {
        /// The flag.
        flag: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// A file could not be read or written.
    #[error("{path}: {reason}")]
    File {
        /// The file.
        path: String,
        /// The cause.
        reason: String,
    },
}

/// Command-line flags of `contact2d stress`.
#[derive(Debug, Clone, clap::Args)]
pub struct StressArgs {
    /// Mesh level N (16 or 32: the clearance meshes exist for these).
    #[arg(long, default_value_t = 16)]
    pub level: usize,
    /// Stiffness ratios E2/E1 of the main grid, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1e-4,1e-2,1,1e2,1e4,1e6")]
    pub ratios: Vec<f64>,
    /// Friction coefficients of the main grid.
    #[arg(long, value_delimiter = ',', default_value = "0,0.1,0.3,0.6,1.0,1.5")]
    pub frictions: Vec<f64>,
    /// Clearances ε of the main grid (0, 1e-6, 1e-3, 0.05, 0.2 have meshes).
    #[arg(long, value_delimiter = ',', default_value = "0,1e-6,1e-3,0.05,0.2")]
    pub eps: Vec<f64>,
    /// Leave out the plane-strain and distorted-mesh cells.
    #[arg(long)]
    pub no_extra: bool,
    /// Poisson's ratios of the plane-strain cells.
    #[arg(long, value_delimiter = ',', default_value = "0.45,0.49")]
    pub strain_nu: Vec<f64>,
    /// Distortion amplitudes of the distorted-mesh cells (fractions of the local node spacing).
    #[arg(long, value_delimiter = ',', default_value = "0.15,0.25,0.3")]
    pub distortions: Vec<f64>,
    /// Algorithms, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "active_set,clarabel,boussinesq")]
    pub algorithms: Vec<String>,
    /// Seed of the mesh distortion.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Directory of the bundled scenes (the base scene is plate_insert_gap_v1_mu03.toml).
    #[arg(long, default_value = "scenes")]
    pub scenes: PathBuf,
    /// Output directory (stress.csv, stress.md).
    #[arg(long, default_value = "stress-out")]
    pub out: PathBuf,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// The axes of the grid.
#[derive(Debug, Clone, PartialEq)]
pub struct GridAxes {
    /// E2/E1 of the main grid.
    pub ratios: Vec<f64>,
    /// μ of the main grid.
    pub frictions: Vec<f64>,
    /// ε of the main grid.
    pub eps: Vec<f64>,
    /// ν of the plane-strain cells (none: no such cells).
    pub strain_nu: Vec<f64>,
    /// Distortion amplitudes (none: no distorted cells).
    pub distortions: Vec<f64>,
}

/// The cells of the grid: the main grid, then the plane-strain and distorted cells.
pub fn grid(axes: &GridAxes) -> Vec<StressCell> {
    let GridAxes { ratios, frictions, eps, .. } = axes;
    let base = StressCell { ratio: 1.0, mu: 0.0, eps: 0.0, nu: 0.3, plane: PlaneCondition::Stress, distortion: 0.0 };
    let mut cells = Vec::new();
    for &e in eps {
        for &ratio in ratios {
            for &mu in frictions {
                cells.push(StressCell { ratio, mu, eps: e, ..base });
            }
        }
    }
    let variants = axes
        .strain_nu
        .iter()
        .map(|&nu| StressCell { nu, plane: PlaneCondition::Strain, ..base })
        .chain(axes.distortions.iter().map(|&distortion| StressCell { distortion, ..base }));
    for v in variants {
        for e in [0.0, 0.05] {
            for ratio in [1e-4, 1.0, 1e6] {
                for mu in [0.0, 0.3, 1.5] {
                    cells.push(StressCell { ratio, mu, eps: e, ..v });
                }
            }
        }
    }
    cells
}

/// The bundled mesh file name of ε (`None` if there is none).
pub fn mesh_name(eps: f64, level: usize) -> Option<String> {
    let tag = [(0.0, "0"), (1e-6, "1e-6"), (1e-3, "0.001"), (0.05, "0.05"), (0.2, "0.2")]
        .iter()
        .find(|(e, _)| *e == eps)
        .map(|(_, t)| *t)?;
    Some(format!("plate_insert_eps{tag}_N{level}.msh"))
}

/// Runs one cell, distorting the mesh first when the cell asks for it (written into `tmp`).
///
/// # Errors
/// [`StressError::File`] when the mesh cannot be read or the distorted mesh written;
/// [`StressError::Flag`] for an ε without a bundled mesh.
pub fn run_stress_cell(
    scenes: &Path,
    level: usize,
    cell: StressCell,
    algorithms: &[ContactAlgorithm],
    seed: u64,
    tmp: &Path,
) -> Result<CellResult, StressError> {
    let name = mesh_name(cell.eps, level)
        .ok_or_else(|| StressError::Flag { flag: "--eps", reason: format!("no bundled mesh for ε = {}", cell.eps) })?;
    let base_scene = scenes.join("plate_insert_gap_v1_mu03.toml");
    let bundled = format!("../meshes/plate_insert/{name}");
    if cell.distortion == 0.0 {
        return Ok(run_cell(&base_scene, &bundled, cell, algorithms, None));
    }
    let file = |path: &Path, e: &dyn std::fmt::Display| StressError::File {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    let source = scenes.join(&bundled);
    let mut mesh = read_msh(&source).map_err(|e| file(&source, &e))?;
    distort::distort_interior(&mut mesh, cell.distortion, seed);
    let quality = distort::jacobian_quality(&mesh);
    std::fs::create_dir_all(tmp).map_err(|e| file(tmp, &e))?;
    let path = tmp.join(format!("distorted_{}_{}_{seed}_{name}", cell.distortion, level));
    write_msh(&mesh, &path, MshFormat::V41Binary).map_err(|e| file(&path, &e))?;
    let absolute = std::fs::canonicalize(&path).map_err(|e| file(&path, &e))?;
    Ok(run_cell(&base_scene, &absolute.display().to_string(), cell, algorithms, quality))
}

/// Checks every value of the grid's axes (clap parses `1e400` as ∞): a ratio positive and
/// finite, a friction coefficient, clearance or distortion finite and ≥ 0, a Poisson's ratio in
/// (−1, 0.5).
///
/// # Errors
/// [`StressError::Flag`] naming the flag and the value.
pub fn check_axes(args: &StressArgs) -> Result<(), StressError> {
    type Rule = (&'static str, fn(f64) -> bool, &'static str);
    let rules: [(&[f64], Rule); 5] = [
        (&args.ratios, ("--ratios", |v| v.is_finite() && v > 0.0, "a positive finite stiffness ratio")),
        (&args.frictions, ("--frictions", |v| v.is_finite() && v >= 0.0, "a finite friction coefficient ≥ 0")),
        (&args.eps, ("--eps", |v| v.is_finite() && v >= 0.0, "a finite clearance ≥ 0")),
        (&args.strain_nu, ("--strain-nu", |v| v > -1.0 && v < 0.5, "a Poisson's ratio in (-1, 0.5)")),
        (&args.distortions, ("--distortions", |v| v.is_finite() && v >= 0.0, "a finite distortion ≥ 0")),
    ];
    for (values, (flag, admissible, what)) in rules {
        if let Some(v) = values.iter().find(|v| !admissible(**v)) {
            return Err(StressError::Flag {
                flag,
                reason: format!("{v} is not {what} (a value beyond ±1.8e308 reads as inf)"),
            });
        }
    }
    Ok(())
}

/// A fresh folder of this process for the distorted meshes, created with `create_dir` (which
/// refuses an existing name, a planted link included): `contact2d-stress-<pid>-<k>` in the
/// system's temporary folder, the first `k` free.
fn private_temp_dir() -> std::io::Result<PathBuf> {
    let mut last = None;
    for k in 0..100 {
        let dir = std::env::temp_dir().join(format!("contact2d-stress-{}-{k}", std::process::id()));
        match std::fs::create_dir(&dir) {
            Ok(()) => return Ok(dir),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| std::io::Error::other("no free temporary folder name")))
}

/// The whole command: runs the grid with a progress bar, writes `stress.csv` and `stress.md` into
/// `args.out`, and returns the markdown.
///
/// # Errors
/// Bad flags, unreadable meshes or unwritable outputs.
pub fn run_command(args: &StressArgs) -> Result<String, StressError> {
    let algorithms = args
        .algorithms
        .iter()
        .map(|s| {
            crate::schema::algorithm_from_key(s)
                .ok_or_else(|| StressError::Flag { flag: "--algorithms", reason: format!("unknown algorithm {s:?}") })
        })
        .collect::<Result<Vec<_>, _>>()?;
    check_axes(args)?;
    let extra = |v: &Vec<f64>| if args.no_extra { vec![] } else { v.clone() };
    let cells = grid(&GridAxes {
        ratios: args.ratios.clone(),
        frictions: args.frictions.clone(),
        eps: args.eps.clone(),
        strain_nu: extra(&args.strain_nu),
        distortions: extra(&args.distortions),
    });
    // The output folder is checked and locked before the grid runs.
    let file = |path: &Path, e: &dyn std::fmt::Display| StressError::File {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    let mut out = crate::output::OutputDir::prepare(&args.out, None).map_err(|e| file(&args.out, &e))?;
    let bar = progress_bar(cells.len(), args.quiet);
    let tmp = private_temp_dir().map_err(|e| file(&std::env::temp_dir(), &e))?;
    let mut results = Vec::with_capacity(cells.len());
    for cell in cells {
        bar.set_message(format!("E2/E1 {:e} μ {} ε {:e}", cell.ratio, cell.mu, cell.eps));
        results.push(run_stress_cell(&args.scenes, args.level, cell, &algorithms, args.seed, &tmp)?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    // Best effort: the temporary meshes are not needed any more.
    let _ = std::fs::remove_dir_all(&tmp);
    let md = report::markdown(&results, args.level);
    for (name, text) in [("stress.csv", report::csv(&results)), ("stress.md", md.clone())] {
        out.write_bytes(name, text.as_bytes()).map_err(|e| file(&args.out.join(name), &e))?;
    }
    out.close().map_err(|e| file(&args.out, &e))?;
    Ok(md)
}

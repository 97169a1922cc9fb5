//! `contact2d verify`: the verification gallery — contact problems with closed-form or published
//! answers, each run through the same scene files and code paths a user runs, each quantity
//! compared with its reference and a stated tolerance.
//!
//! ```text
//! case (scene + closed form) → solve_generic / solve_scene → Check { measured, reference, tolerance }
//! relative error e = |measured − reference| / |reference|   (or |measured − reference| for an
//! absolute tolerance);  PASS ⇔ e ≤ tolerance
//! ```
//!
//! The tests in `tests/verification/verify_*.rs` call these same functions and assert that every check
//! passes, so the table `contact2d verify` prints and `docs/verification.md` shows is the one the
//! tests check. Each case documents its source, its closed form and why its tolerance is what it
//! is.

pub mod cattaneo_mindlin;
pub mod clamped_block;
pub mod contact_patch;
pub mod flagship;
pub mod hertz;
pub mod hertz_sphere_axisymmetric;
pub mod hills_nowell;
pub mod incline;
pub mod interference_fit;
pub mod mindlin_deresiewicz;
pub mod moving_roller;
pub mod pin_lug;
pub mod press_fit;
mod profile;
pub mod punch_axisymmetric;
pub mod report;
pub mod shrink_fit_axisymmetric;
pub mod sliding_patch;

use std::path::{Path, PathBuf};

use crate::generic::{GenericOutcome, GenericScene, load_scene, solve_generic};
use crate::output::chart::{Axes, Series};
use crate::schema::SceneError;

/// How much of the gallery to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    /// The coarse and middle meshes (seconds; what CI runs).
    Fast,
    /// Every bundled mesh level, the finest included (the issue's targets are stated there).
    Full,
}

/// A tolerance on one quantity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// `|m − r| / |r| ≤ tol`.
    Relative(f64),
    /// `|m − r| ≤ tol`.
    Absolute(f64),
}

/// One compared quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Check {
    /// What is compared, e.g. `c/a at Q/(μP) = 0.50`.
    pub quantity: String,
    /// The mesh level or variant it was measured on.
    pub mesh: String,
    /// Our value.
    pub measured: f64,
    /// The closed form or published value.
    pub reference: f64,
    /// The allowed deviation.
    pub tolerance: Tolerance,
}

impl Check {
    /// The check of `quantity` on `mesh`: `measured` against `reference` within `tolerance`.
    pub fn on(mesh: &str, quantity: &str, measured: f64, reference: f64, tolerance: Tolerance) -> Check {
        Check { quantity: quantity.into(), mesh: mesh.into(), measured, reference, tolerance }
    }

    /// The check of the value among `values` farthest from `reference` (NaN when there is none,
    /// which fails), on the bundled mesh, within `relative` of the reference.
    pub fn worst_of(quantity: &str, values: &[f64], reference: f64, relative: f64) -> Check {
        let measured = values
            .iter()
            .copied()
            .max_by(|x, y| (x - reference).abs().total_cmp(&(y - reference).abs()))
            .unwrap_or(f64::NAN);
        Check {
            quantity: quantity.into(),
            mesh: "bundled".into(),
            measured,
            reference,
            tolerance: Tolerance::Relative(relative),
        }
    }

    /// The deviation in the tolerance's own measure (relative or absolute).
    pub fn error(&self) -> f64 {
        let d = (self.measured - self.reference).abs();
        match self.tolerance {
            Tolerance::Relative(_) => d / self.reference.abs().max(f64::MIN_POSITIVE),
            Tolerance::Absolute(_) => d,
        }
    }

    /// Whether the measured value is finite and within the tolerance.
    pub fn passed(&self) -> bool {
        let limit = match self.tolerance {
            Tolerance::Relative(t) | Tolerance::Absolute(t) => t,
        };
        self.measured.is_finite() && self.error() <= limit
    }
}

/// A measured quantity without a reference (a convergence rate, an error that is reported but
/// not asserted, a step study).
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// What it is.
    pub quantity: String,
    /// The mesh level or variant.
    pub mesh: String,
    /// The value.
    pub value: f64,
}

/// A figure of a case: computed against analytical curves.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// File name (without directory), `.svg` or `.png`.
    pub file: String,
    /// Title and axes.
    pub axes: Axes,
    /// The curves.
    pub series: Vec<Series>,
}

/// The outcome of one case.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CaseReport {
    /// Short name (`incline`, `cattaneo_mindlin`, ...).
    pub name: String,
    /// The source of the closed form or of the published values.
    pub source: String,
    /// The compared quantities.
    pub checks: Vec<Check>,
    /// Quantities reported without a reference.
    pub measurements: Vec<Measurement>,
    /// The figures.
    pub figures: Vec<Figure>,
    /// What a reader should know (a measured gap and its cause, a left-out variant).
    pub notes: Vec<String>,
}

impl CaseReport {
    /// Whether every check passed.
    pub fn passed(&self) -> bool {
        self.checks.iter().all(Check::passed)
    }
}

/// Why a case could not be run.
#[derive(Debug, thiserror::Error)]
pub enum VerifyError {
    /// A scene could not be read.
    #[error(transparent)]
    Scene(#[from] crate::scene::SceneError),
    /// A generic scene failed to solve.
    #[error(transparent)]
    Generic(#[from] crate::generic::GenericError),
    /// A flagship scene failed to solve.
    #[error(transparent)]
    Contact(#[from] contact2d_contact::ContactError),
    /// A result the case needs is missing or not finite.
    #[error("{case}: {reason}")]
    Missing {
        /// The case.
        case: String,
        /// What is missing.
        reason: String,
    },
}

/// The names of the gallery's cases, in the order they run.
pub const CASES: [&str; 16] = [
    "contact_patch",
    "hertz",
    "cattaneo_mindlin",
    "mindlin_deresiewicz",
    "hills_nowell",
    "interference_fit",
    "shrink_fit_axisymmetric",
    "hertz_sphere_axisymmetric",
    "punch_axisymmetric",
    "incline",
    "pin_lug",
    "flagship",
    "sliding_patch",
    "press_fit",
    "moving_roller",
    "clamped_block",
];

/// Runs one case by name; `root` is the repository root (where `scenes/` and `meshes/` are).
///
/// # Errors
/// [`VerifyError::Missing`] for an unknown name; what the case's solve returns otherwise.
pub fn run_case(name: &str, root: &Path, level: Level) -> Result<CaseReport, VerifyError> {
    match name {
        "contact_patch" => contact_patch::run(root, level),
        "hertz" => hertz::run(root, level),
        "cattaneo_mindlin" => cattaneo_mindlin::run(root, level),
        "mindlin_deresiewicz" => mindlin_deresiewicz::run(root, level),
        "hills_nowell" => hills_nowell::run(root, level),
        "interference_fit" => interference_fit::run(root, level),
        "shrink_fit_axisymmetric" => shrink_fit_axisymmetric::run(root, level),
        "hertz_sphere_axisymmetric" => hertz_sphere_axisymmetric::run(root, level),
        "punch_axisymmetric" => punch_axisymmetric::run(root, level),
        "incline" => incline::run(root, level),
        "pin_lug" => pin_lug::run(root, level),
        "flagship" => flagship::run(root, level),
        "sliding_patch" => sliding_patch::run(root, level),
        "press_fit" => press_fit::run(root, level),
        "moving_roller" => moving_roller::run(root, level),
        "clamped_block" => clamped_block::run(root, level),
        other => Err(VerifyError::Missing {
            case: other.to_string(),
            reason: format!("no such case (cases: {})", CASES.join(", ")),
        }),
    }
}

/// Command-line flags of `contact2d verify`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "cli", derive(clap::Args))]
pub struct VerifyArgs {
    /// `fast` (coarse and middle meshes, what CI runs) or `full` (every bundled level).
    #[cfg_attr(feature = "cli", arg(long, default_value = "fast", value_parser = ["fast", "full"]))]
    pub level: String,
    /// Cases to run, comma separated (default: all of contact_patch, hertz, cattaneo_mindlin,
    /// mindlin_deresiewicz, hills_nowell, interference_fit, shrink_fit_axisymmetric,
    /// hertz_sphere_axisymmetric, punch_axisymmetric, incline, pin_lug,
    /// flagship, sliding_patch,
    /// press_fit, moving_roller, clamped_block).
    #[cfg_attr(feature = "cli", arg(long, value_delimiter = ','))]
    pub cases: Vec<String>,
    /// The repository root (where `scenes/` and `meshes/` are).
    #[cfg_attr(feature = "cli", arg(long, default_value = "."))]
    pub root: PathBuf,
    /// Write the figures and the markdown tables (`verification.md`) into this directory.
    #[cfg_attr(feature = "cli", arg(long, value_name = "DIR"))]
    pub out: Option<PathBuf>,
    /// Print the markdown tables instead of the text table.
    #[cfg_attr(feature = "cli", arg(long))]
    pub markdown: bool,
}

/// Runs `contact2d verify`: the chosen cases, the table, the figures. Returns the table and
/// whether every check passed.
///
/// # Errors
/// A case that cannot be run, or an output that cannot be written.
#[cfg(feature = "cli")]
pub fn run_command(args: &VerifyArgs) -> anyhow::Result<(String, bool)> {
    let level = if args.level == "full" { Level::Full } else { Level::Fast };
    let names: Vec<String> =
        if args.cases.is_empty() { CASES.iter().map(|c| c.to_string()).collect() } else { args.cases.clone() };
    let reports = names.iter().map(|n| run_case(n, &args.root, level)).collect::<Result<Vec<_>, _>>()?;
    if let Some(dir) = &args.out {
        report::write(dir, &reports)?;
    }
    let table = if args.markdown { report::markdown(&reports) } else { report::text_table(&reports) };
    Ok((table, reports.iter().all(CaseReport::passed)))
}

/// A scene of the repository by its path below `root`.
fn scene_path(root: &Path, relative: &str) -> PathBuf {
    root.join(relative)
}

/// A gallery case's scene, read with `overrides` and without the step size's error estimate
/// (`loading.path_error = false`): each check compares the steps solved with a closed form or a
/// second run, and the estimate would solve the whole run a second time for a number no check
/// reads.
///
/// # Errors
/// As [`load_scene`].
fn gallery_scene(path: &Path, overrides: &[String]) -> Result<GenericScene, SceneError> {
    let mut sets = vec!["loading.path_error=false".to_string()];
    sets.extend_from_slice(overrides);
    load_scene(path, &sets)
}

/// The override that points a generic scene in `scenes/generic/` at another bundled mesh.
fn mesh_override(file: &str) -> String {
    format!("mesh=\"../../meshes/generic/{file}\"")
}

/// Solves the generic `scene` (relative to `root`) on the bundled mesh `mesh` of
/// `meshes/generic/`, with the overrides `extra` after the mesh's.
///
/// # Errors
/// A scene that cannot be read or solved.
fn solve_on_mesh(root: &Path, scene: &str, mesh: &str, extra: &[String]) -> Result<GenericOutcome, VerifyError> {
    let mut overrides = vec![mesh_override(mesh)];
    overrides.extend_from_slice(extra);
    Ok(solve_generic(&gallery_scene(&scene_path(root, scene), &overrides)?, &mut |_, _| {})?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_compare_in_their_own_measure() {
        let c = |m: f64, r: f64, t: Tolerance| Check {
            quantity: "q".into(),
            mesh: "L1".into(),
            measured: m,
            reference: r,
            tolerance: t,
        };
        assert!(c(1.004, 1.0, Tolerance::Relative(0.005)).passed());
        assert!(!c(1.006, 1.0, Tolerance::Relative(0.005)).passed());
        assert!(c(0.104, 0.1, Tolerance::Absolute(0.005)).passed());
        assert!(!c(f64::NAN, 0.1, Tolerance::Absolute(0.005)).passed());
    }
}

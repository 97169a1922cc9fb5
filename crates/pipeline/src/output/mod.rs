//! Writers of (problem, solution) every scene's outputs use: the output folder written whole
//! ([`atomic`]), line charts ([`chart`]), the mesh and von Mises figures, VTU files for ParaView,
//! and the README's descriptions. Every run's folder is written by one writer,
//! `crate::generic::outputs`; a preset adds its own files through [`PresetFiles`] (the
//! plate-insert preset's hole-edge and insert figures and tables, `crate::plate_insert::outputs`).
//! `summary.json`, the run's summary with `"files"` (the list of this run's files), is written
//! last, so a folder without it is incomplete (see [`atomic`]).
//! Library code here writes files and returns what it wrote; it never prints.
//! [`chart`] is the shared line-chart API every figure of the project draws with.

pub mod atomic;
#[cfg(feature = "native")]
pub mod chart;
pub mod drawable;
mod error;
#[cfg(feature = "native")]
pub mod field_plot;
#[cfg(feature = "native")]
pub mod mesh_plot;
pub mod preset_files;
pub mod step_view;
#[cfg(feature = "native")]
pub mod vtu;

#[cfg(feature = "native")]
use std::path::Path;

pub use atomic::OutputDir;
pub use error::OutputError;
pub use preset_files::PresetFiles;

/// The figure formats written for every figure.
pub const FIGURE_EXTENSIONS: [&str; 2] = ["png", "svg"];

/// The manifest of a run folder: the summary, written last, listing the run's files.
pub const SUMMARY_FILE: &str = "summary.json";

#[cfg(feature = "native")]
/// Draws one figure through `out`; a figure that cannot be drawn is noted in `skipped` instead.
pub(crate) fn figure(
    out: &mut OutputDir,
    name: &str,
    skipped: &mut Vec<String>,
    draw: impl FnOnce(&Path) -> Result<(), OutputError>,
) -> Result<(), OutputError> {
    match out.write_with(name, draw) {
        Ok(_) => Ok(()),
        Err(OutputError::Undrawable { reason, .. }) => {
            skipped.push(format!("{name} not drawn: {reason}"));
            Ok(())
        }
        Err(e) => Err(e),
    }
}

/// The VTU file name of step `k` (0-based): `step_000.vtu`, `step_001.vtu`, ...
pub fn step_file_name(k: usize) -> String {
    format!("step_{k:03}.vtu")
}

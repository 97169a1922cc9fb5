//! The one error type of the output module: every variant names the file it concerns and the cause.

use std::path::PathBuf;

/// Why writing an output file failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum OutputError {
    /// The bundled font could not be registered with the plotting library.
    #[error("the bundled font (assets/fonts/DejaVuSans.ttf) could not be registered with plotters")]
    Font,
    /// The file's extension names no format this writer produces.
    #[error("{path}: unsupported file extension (expected {expected})")]
    UnsupportedFormat {
        /// The file asked for.
        path: PathBuf,
        /// The extensions accepted, e.g. "\".png\" or \".svg\"".
        expected: &'static str,
    },
    /// Drawing a figure failed (the plotting backend's message).
    #[error("{path}: drawing failed: {reason}")]
    Draw {
        /// The figure file.
        path: PathBuf,
        /// The plotting backend's message.
        reason: String,
    },
    /// Creating a directory or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
    /// Serialising data (JSON, VTK) failed.
    #[error("{path}: could not serialise: {reason}")]
    Serialize {
        /// The file being written.
        path: PathBuf,
        /// The serialiser's message.
        reason: String,
    },
    /// The solved scene lacks what this output needs (e.g. a contour or a solved step).
    #[error("{path}: {reason}")]
    MissingData {
        /// The file that could not be produced.
        path: PathBuf,
        /// What is missing.
        reason: String,
    },
    /// The output path exists and is not a directory.
    #[error("{path}: exists and is not a directory (choose another --out)")]
    NotADirectory {
        /// The path given as the output folder.
        path: PathBuf,
    },
    /// The output path is a symbolic link to nothing (its target does not exist).
    #[error(
        "{path}: is a dangling symbolic link (to {}, which does not exist); remove the link or create its target",
        target.display()
    )]
    DanglingLink {
        /// The path given as the output folder.
        path: PathBuf,
        /// Where the link points.
        target: PathBuf,
    },
    /// Another process writes into the folder (its lock file exists).
    #[error(
        "{dir}: another contact2d process{} is writing into this folder (lock file {lock}); wait for it, \
         choose another folder, or delete the lock file if no such process runs",
        pid.map_or(String::new(), |p| format!(" (pid {p})"))
    )]
    Locked {
        /// The folder.
        dir: PathBuf,
        /// The lock file.
        lock: PathBuf,
        /// The process id recorded in the lock file, if readable.
        pid: Option<u32>,
    },
    /// The data cannot be drawn (non-finite values, a zero or unrepresentable range); the writer
    /// skips the figure and notes why.
    #[error("{path}: not drawn: {reason}")]
    Undrawable {
        /// The figure file.
        path: PathBuf,
        /// Why.
        reason: String,
    },
    /// Recovering stresses or reactions from the solution failed.
    #[error("post-processing: {0}")]
    Fem(#[from] contact2d_fem::FemError),
    /// Evaluating an element (isoparametric map, stress) failed.
    #[error("post-processing: {0}")]
    Element(#[from] contact2d_element::ElementError),
}

impl OutputError {
    /// An [`OutputError::Io`] for `path`.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Self::Io { path: path.into(), source }
    }

    /// The same error with the file `from` (a temporary name) replaced by `to` where it names it.
    #[must_use]
    pub fn at_path(mut self, from: &std::path::Path, to: &std::path::Path) -> Self {
        match &mut self {
            Self::UnsupportedFormat { path, .. }
            | Self::Draw { path, .. }
            | Self::Io { path, .. }
            | Self::Serialize { path, .. }
            | Self::MissingData { path, .. }
            | Self::Undrawable { path, .. }
                if path == from =>
            {
                *path = to.to_path_buf();
            }
            _ => {}
        }
        self
    }

    /// An [`OutputError::Draw`] for `path` from any displayable plotting error.
    pub fn draw(path: impl Into<PathBuf>, reason: impl std::fmt::Display) -> Self {
        Self::Draw { path: path.into(), reason: reason.to_string() }
    }
}

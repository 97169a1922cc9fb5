//! What every scene shares, the generic ones and the plate-insert preset alike: reading the file
//! (a regular, bounded UTF-8 file) and parsing its TOML with the `--set` overrides, the one
//! `[solver]` section, and the errors, which name the file and the line, key or override at
//! fault.

pub mod limits;
mod overrides;
mod parse;
mod solver;

pub(crate) use overrides::apply_override;
pub use overrides::{overridden_scene_text, unset_override};
pub(crate) use parse::parse_scene_toml;
pub use parse::read_scene_text;
pub use solver::{SolverEntry, algorithm_from_key, deserialize_algorithm, serialize_algorithm};

/// Errors reading a scene.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The file could not be read.
    #[error("cannot read scene {path}: {source}")]
    Io {
        /// Path as given.
        path: String,
        /// OS error.
        source: std::io::Error,
    },
    /// Not valid TOML, an unknown key, or a wrong type.
    #[error("scene {path}: {reason}")]
    Invalid {
        /// Path as given.
        path: String,
        /// What is wrong (with the key or line).
        reason: String,
    },
    /// A value out of its range, or two values that contradict each other.
    #[error("scene {path}: {key}: {reason}")]
    Value {
        /// Path as given.
        path: String,
        /// The dotted key at fault.
        key: String,
        /// What is wrong.
        reason: String,
    },
    /// A physical group of the mesh that is not where the flagship needs it (e.g. two group
    /// names swapped).
    #[error("scene {path}: mesh {mesh}: group \"{group}\" {reason}")]
    Group {
        /// Path of the scene as given.
        path: String,
        /// The mesh file.
        mesh: String,
        /// The group at fault.
        group: String,
        /// Where it must lie and the node that does not.
        reason: String,
    },
    /// A file that is refused before reading (not a regular file, or too large).
    #[error("cannot read scene {path}: {reason}")]
    Unreadable {
        /// Path as given.
        path: String,
        /// Why.
        reason: String,
    },
    /// A `--set` override that does not parse or names no key, or an `--unset` that names no
    /// key the scene gives.
    #[error("{}: {reason}", overrides::as_flag(assignment))]
    Override {
        /// The assignment as given (`key=value`, or [`unset_override`]`(key)` for an `--unset`).
        assignment: String,
        /// What is wrong.
        reason: String,
    },
}

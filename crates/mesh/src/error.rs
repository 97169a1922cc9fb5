//! Errors of the mesh crate.

use thiserror::Error;

/// Where in a file an error was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Location {
    /// 1-based line number of an ASCII file.
    Line(usize),
    /// 0-based byte offset from the start of a binary file.
    Byte(usize),
}

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Location::Line(n) => write!(f, "line {n}"),
            Location::Byte(n) => write!(f, "byte {n}"),
        }
    }
}

/// Everything that can go wrong reading or querying a mesh.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum MeshError {
    /// The file could not be opened or read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The path as given.
        path: String,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// The content is not a valid MSH file.
    #[error("malformed MSH file at {at}: {reason}")]
    Msh {
        /// Where the problem was found.
        at: Location,
        /// What is wrong.
        reason: String,
    },
    /// A valid MSH feature contact2d does not read (an element type, a format version).
    #[error("unsupported MSH content at {at}: {what}")]
    Unsupported {
        /// Where it was found.
        at: Location,
        /// What is not supported.
        what: String,
    },
    /// No physical group has this name.
    #[error("no physical group named \"{0}\" in the mesh")]
    UnknownPhysicalGroup(String),
    /// The mesh cannot be written: it is inconsistent (a node id out of range, duplicate tags,
    /// a physical tag without a group, ...) or the requested format cannot store it.
    #[error("cannot write the mesh: {reason}")]
    CannotWrite {
        /// What is wrong.
        reason: String,
    },
    /// Moving nodes ([`crate::morph::move_nodes`]) would invert a cell: its nodes would no
    /// longer run the way they did (see [`crate::orientation`]). The mesh is left unchanged.
    #[error(
        "moving node {node} from ({}, {}) to ({}, {}) would invert cell {cell}: the move is too large for \
         the cells around the node (refine the mesh there)",
        from[0], from[1], to[0], to[1]
    )]
    MorphInvertsElement {
        /// Element tag of the cell that would be inverted.
        cell: u64,
        /// Node tag of the moved node responsible (a node of the cell if one was moved, else the
        /// nearest moved node).
        node: u64,
        /// Where that node was.
        from: [f64; 2],
        /// Where it was asked to go.
        to: [f64; 2],
    },
    /// A geometric query failed (contour not a simple chain, ...).
    #[error("{0}")]
    Geometry(String),
}

//! Meshes for contact2d: the in-memory model and our own Gmsh `.msh` reader.

pub mod contour;
pub mod error;
pub mod frames;
pub mod generate;
pub mod mesh;
pub mod morph;
pub mod msh;
pub mod orientation;

pub use contour::{Contour, ContourEdge, GAUSS5, line_cell_length};
pub use error::{Location, MeshError};
pub use frames::{NodeFrames, node_frames};
pub use mesh::{CellBlock, CellKind, Mesh, NodeId, PhysicalGroup};
pub use msh::{MshFormat, MshReport, encode_msh, parse_msh, parse_msh_with_report, read_msh, write_msh};
pub use orientation::{Orientation, cell_orientation, reversing_permutation, signed_area};

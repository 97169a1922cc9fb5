//! contact2d: 2D finite-element contact mechanics with Coulomb friction.
//!
//! This facade re-exports the pipeline's crates and hosts what sits at the edge: the command
//! line, summaries, scene files and outputs.
//!
//! ```text
//! mesh (Gmsh .msh) → fem::Model → assemble → solve → contact → results → output
//! ```

pub use contact2d_contact as contact;
pub use contact2d_element as element;
pub use contact2d_fem as fem;
pub use contact2d_mesh as mesh;

#[cfg(feature = "native")]
pub mod bench;
#[cfg(feature = "native")]
pub mod compare;
pub mod doc_sections;
pub mod generic;
pub mod input_file;
pub mod mesh_summary;
pub mod output;
pub mod plate_insert;
pub mod run;
pub mod scene;
pub mod schema;
#[cfg(feature = "native")]
pub mod stress;
#[cfg(feature = "native")]
pub mod subject;
#[cfg(feature = "native")]
pub mod sweep;
#[cfg(feature = "native")]
pub mod verify;

// The README's library example is compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

//! contact2d: 2D finite-element contact mechanics with Coulomb friction.
//!
//! This facade re-exports the pipeline's crates and hosts what sits at the edge: the command
//! line, summaries, scene files and outputs.
//!
//! ```text
//! mesh (Gmsh .msh) → fem::Model → assemble → solve → contact → results → output
//!
//! schema        what every scene file shares: reading, --set overrides, [solver], limits
//! generic       the one pipeline: scene → built problem → solve → summary → outputs
//! plate_insert  the paper's case as a preset: its [plate_insert] section (scene), its expansion
//!               into a generic scene (preset), its run and post-processor (run, report, outputs)
//! output        the writers every run's folder uses
//! scene         any scene file: one reader, one run, one outcome (generic or a preset's)
//! subject       what the studies (compare, sweep) read of a scene: pairings, quantities, meshes
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
/// The plate-insert preset's run (`crate::plate_insert::run`), at its historical path.
pub use plate_insert::run;
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

//! contact2d: 2D finite-element contact mechanics with Coulomb friction.
//!
//! This facade re-exports the crates of the pipeline and hosts what sits on top of it: the
//! command line and the studies that run scenes through the one pipeline.
//!
//! ```text
//! mesh (Gmsh .msh) → fem::Model → assemble → solve → contact → results → output
//!
//! crates: mesh, element, fem, contact (pairing, problem, algorithms, zone-end placement),
//!         pipeline (scene → built problem → solve → summary, post-processors, outputs;
//!         re-exported here as generic, plate_insert, scene, schema, output, ...)
//!
//! bench         wall time against discretisation error on the flagship cases
//! stress        the flagship at extreme parameters
//! compare       every algorithm × pairing on one scene over mesh levels
//! sweep         one scene over the product of varied values
//! verify        the verification gallery: closed-form and published cases
//! doc_sections  generated tables written into docs/
//! ```

pub use contact2d_contact as contact;
pub use contact2d_element as element;
pub use contact2d_fem as fem;
pub use contact2d_mesh as mesh;
pub use contact2d_pipeline as pipeline;
#[cfg(feature = "studies")]
pub use contact2d_pipeline::subject;
pub use contact2d_pipeline::{generic, input_file, mesh_summary, output, plate_insert, run, scene, schema};

// Features: `studies` (compare, sweep, verify and the writers they need: what the Python binding
// uses) and `cli` (the command line on top: clap, progress bars, bench, stress). See Cargo.toml.
#[cfg(feature = "cli")]
pub mod bench;
#[cfg(feature = "studies")]
pub mod compare;
pub mod doc_sections;
#[cfg(feature = "studies")]
pub mod reference;
#[cfg(feature = "cli")]
pub mod stress;
#[cfg(feature = "studies")]
pub mod sweep;
#[cfg(feature = "studies")]
pub mod verify;

// The README's library example is compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

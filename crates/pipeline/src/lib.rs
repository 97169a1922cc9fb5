//! contact2d's one pipeline: any scene file, generic or a preset's, read, built, solved and
//! written through the same path.
//!
//! ```text
//! scene file ─ schema, scene ─▶ generic::GenericScene ─ generic (build, solve) ─▶ GenericOutcome
//!    (a preset's section expands      (plate_insert::preset)        ─▶ summary (the one JSON contract)
//!     into a generic scene)                                          + post-processors (a preset's
//!                                                                      block and files)
//!                                                                  ─ output ─▶ the run's folder
//!
//! schema        what every scene file shares: reading, --set overrides, [solver], limits
//! scene         any scene file: one reader, one run, one outcome (generic or a preset's)
//! generic       scene → built problem → solve → summary → outputs
//! plate_insert  the paper's case as a preset: its [plate_insert] section (scene), its expansion
//!               into a generic scene (preset), its run and post-processor (run, report, outputs)
//! preset        the registered presets (a section that expands into a generic scene, and its
//!               post-processor): one module each, and one line of scene::PRESETS
//! output        the writers every run's folder uses (no scene type)
//! subject       what the studies (compare, sweep) read of a scene: pairings, quantities, meshes
//! input_file    reading an input file with a size limit
//! mesh_summary  what a mesh is made of, and its poor cells
//! ```
//!
//! The command line and the studies built on this pipeline (`bench`, `stress`, `compare`,
//! `sweep`, `verify`) are the `contact2d` package; the Python module and the WebAssembly build
//! call this crate's [`scene`] and [`generic`] entries.

pub mod generic;
pub mod input_file;
pub mod mesh_summary;
pub mod output;
pub mod plate_insert;
pub mod preset;
/// The plate-insert preset's run (`crate::plate_insert::run`), at its historical path.
pub use plate_insert::run;
pub mod scene;
pub mod schema;
#[cfg(feature = "native")]
pub mod subject;

/// The repository's root (scenes, meshes, docs), for this crate's tests.
#[cfg(test)]
pub(crate) const REPOSITORY_ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

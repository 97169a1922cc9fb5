//! The contact crate's integration tests, one module per subject (the algorithms agreeing, the
//! certificates, condensation, finite sliding, floating bodies, the full-system and sparse paths).
//! One test binary: the modules run in parallel in one process and link once.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "../fixtures/two_blocks.rs"]
mod fixture;

mod algorithms_agree;
mod certify;
mod condensation;
mod finite_sliding;
mod floating_bodies;
mod full_system_algorithms;
mod sparse_path;

//! Helpers shared by the integration tests.
#![allow(clippy::unwrap_used, dead_code)]

use std::path::PathBuf;

/// Every bundled generic scene (`scenes/generic/*.toml`), sorted: a test over them covers new
/// scenes without a list to keep.
pub fn bundled_scenes() -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = std::fs::read_dir("scenes/generic")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    out.sort();
    out
}

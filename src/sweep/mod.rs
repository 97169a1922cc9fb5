//! Parameter sweeps: a scene — generic, or the paper's case — run over the Cartesian product of
//! varied values, in parallel, with the summary quantities tabulated (CSV, Markdown) and plotted
//! against the first varied parameter. One sweep for every scene: rows are the runs' JSON
//! summaries ([`crate::subject`]), quantities their dotted paths.
//!
//! ```text
//! --vary plate_insert.friction=0,0.1,0.3 --vary plate_insert.stiffness_ratio=0.5,1,2
//!   → 9 runs: (0, 0.5), (0, 1), (0, 2), (0.1, 0.5), ...   (the last key varies fastest)
//! --vary contact.bore.friction=0,0.2 --plot contacts.bore.contact_length
//! columns:  status, last_held_factor (the load factor last held: capacity::last_held_factor),
//!           the scene's own (generic: each interface's normal force and contact length; the
//!           paper's case: l, b, P, Phi_E1, Phi_E2, Phi_f, W, sigma_star, K, insert_hoop_max)
//!           and every plotted path
//! ```
//! Each run loads the scene afresh with the base `--set` overrides followed by its own values, so
//! a varied key may be any key `--set` accepts (array entries by index or name). A run that
//! fails (bad value, set-up error) is a row with its error, never an abort of the sweep. Before
//! any run, [`check_variations`] refuses keys the scene does not take, repeated keys and more
//! than [`MAX_RUNS`] combinations.

use std::path::Path;

use rayon::prelude::*;

use crate::output::OutputError;
use crate::scene::Scene;

mod capacity;
mod shard;
mod writers;
pub use capacity::last_held_factor;
pub use shard::Shard;
pub use writers::{csv_header, csv_row, markdown, write_sweep};

/// Errors of a sweep's set-up or of writing its files (failed runs are rows, not errors).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// A `--vary` argument that is not `KEY=V1,V2,...`.
    #[error("--vary {argument}: {reason}")]
    Vary {
        /// The argument as given.
        argument: String,
        /// What is wrong.
        reason: String,
    },
    /// A varied key the scene does not take.
    #[error("--vary {key}: {reason}")]
    UnknownKey {
        /// The key as given.
        key: String,
        /// The scene's own error.
        reason: String,
    },
    /// The same key varied twice (its rows would be mislabelled).
    #[error("--vary {key}: the key is varied twice; give all its values in one --vary")]
    DuplicateKey {
        /// The key.
        key: String,
    },
    /// More combinations than [`MAX_RUNS`].
    #[error("--vary: {runs} combinations exceed the limit of {MAX_RUNS} runs per sweep")]
    TooManyRuns {
        /// The number of combinations asked for (saturated at `usize::MAX`).
        runs: usize,
    },
    /// A `--shard`/`--shards` pair that names no shard.
    #[error("--shard {index} --shards {count}: {reason}")]
    Shard {
        /// The shard asked for (from 0).
        index: usize,
        /// The number of shards.
        count: usize,
        /// What is wrong.
        reason: String,
    },
    /// Writing a file failed.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// The largest number of runs (combinations) a sweep may ask for; checked before any run or
/// allocation. Each row keeps a summary of a few kB, and at the measured 0.05 .. 2 s per run on
/// the bundled meshes 10 000 runs take hours already.
pub const MAX_RUNS: usize = 10_000;

/// Checks the variations before any run: each key is one the scene takes (the scene loads with
/// the key set to its first value, or fails for another reason than an unknown key), no key is
/// varied twice, and the combinations number at most [`MAX_RUNS`].
///
/// # Errors
/// [`SweepError::UnknownKey`], [`SweepError::DuplicateKey`], [`SweepError::TooManyRuns`].
pub fn check_variations(scene: &Path, variations: &[Variation], base: &[String]) -> Result<usize, SweepError> {
    for (i, v) in variations.iter().enumerate() {
        if variations[..i].iter().any(|w| w.key == v.key) {
            return Err(SweepError::DuplicateKey { key: v.key.clone() });
        }
        let mut overrides = base.to_vec();
        overrides.push(format!("{}={}", v.key, v.values[0]));
        if let Err(e) = Scene::load(scene, &overrides) {
            let shown = e.to_string();
            if shown.contains("unknown field") || shown.contains("no table") || shown.contains("no entry") {
                return Err(SweepError::UnknownKey { key: v.key.clone(), reason: shown });
            }
        }
    }
    let runs = variations.iter().try_fold(1usize, |n, v| n.checked_mul(v.values.len())).unwrap_or(usize::MAX);
    if runs > MAX_RUNS {
        return Err(SweepError::TooManyRuns { runs });
    }
    Ok(runs)
}

/// Splits `text` at the commas outside brackets, braces and quotes (`[0.1,0.2],[0.3]` is two
/// values).
fn split_top_level(text: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut quote, mut start) = (vec![], 0usize, None, 0);
    for (i, c) in text.char_indices() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '"' | '\'') => quote = Some(c),
            (None, '[' | '{') => depth += 1,
            (None, ']' | '}') => depth = depth.saturating_sub(1),
            (None, ',') if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

/// One varied scene key and its values (as `--set` would take them).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Variation {
    /// Dotted key, e.g. `plate_insert.friction`.
    pub key: String,
    /// The values in the order given.
    pub values: Vec<String>,
}

impl Variation {
    /// Parses `KEY=V1,V2,...` (split at the commas outside brackets and quotes, so a value may
    /// be a list: `plate_insert.l_steps=[0.1,0.2],[0.3]`).
    ///
    /// # Errors
    /// [`SweepError::Vary`] without `=`, with an empty key, or without a value.
    pub fn parse(argument: &str) -> Result<Variation, SweepError> {
        let err = |reason: &str| SweepError::Vary { argument: argument.into(), reason: reason.into() };
        let (key, values) = argument.split_once('=').ok_or_else(|| err("expected KEY=V1,V2,..."))?;
        let key = key.trim();
        if key.is_empty() {
            return Err(err("empty key"));
        }
        let values: Vec<String> =
            split_top_level(values).into_iter().map(|v| v.trim().to_string()).filter(|v| !v.is_empty()).collect();
        if values.is_empty() {
            return Err(err("no values"));
        }
        Ok(Variation { key: key.into(), values })
    }
}

/// One run of a sweep: its values of the varied keys and its JSON summary or error.
#[derive(Debug, Clone)]
pub struct SweepRow {
    /// One value per varied key, in the order of the variations.
    pub values: Vec<String>,
    /// The run's JSON summary, or why it failed.
    pub result: Result<serde_json::Value, String>,
}

/// The Cartesian product of the variations' values (the last variation varies fastest).
pub fn combinations(variations: &[Variation]) -> Vec<Vec<String>> {
    variations.iter().fold(vec![vec![]], |acc, v| {
        acc.iter()
            .flat_map(|prefix| {
                v.values.iter().map(move |value| {
                    let mut c = prefix.clone();
                    c.push(value.clone());
                    c
                })
            })
            .collect()
    })
}

/// Runs every combination in parallel, handing each finished row to `on_row` as it finishes (in
/// completion order), e.g. to append it to a file so that an interrupted sweep keeps its rows.
pub fn run_sweep(
    scene: &Path,
    variations: &[Variation],
    base: &[String],
    on_row: impl Fn(&SweepRow) + Sync,
) -> Vec<SweepRow> {
    run_sweep_shard(scene, variations, base, Shard::WHOLE, on_row)
}

/// [`run_sweep`] of one shard's cases only (see [`Shard`]): its rows are those of the unsharded
/// sweep at the shard's indices, in the same order.
pub fn run_sweep_shard(
    scene: &Path,
    variations: &[Variation],
    base: &[String],
    shard: Shard,
    on_row: impl Fn(&SweepRow) + Sync,
) -> Vec<SweepRow> {
    let mut cases = combinations(variations);
    let range = shard.range(cases.len());
    cases.truncate(range.end);
    cases.drain(..range.start);
    cases
        .into_par_iter()
        .map(|values| {
            let mut overrides = base.to_vec();
            overrides.extend(variations.iter().zip(&values).map(|(v, value)| format!("{}={value}", v.key)));
            let result = Scene::load(scene, &overrides)
                .map_err(|e| e.to_string())
                .and_then(|s| s.run(None).map(|r| r.json).map_err(|e| e.to_string()));
            let row = SweepRow { values, result };
            on_row(&row);
            row
        })
        .collect()
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn variations_parse_and_multiply() {
        let a = Variation::parse("plate_insert.friction=0, 0.1,0.3").unwrap();
        assert_eq!(a.values, ["0", "0.1", "0.3"]);
        let b = Variation::parse("solver.algorithm=active_set,clarabel").unwrap();
        let c = combinations(&[a, b]);
        assert_eq!(c.len(), 6);
        assert_eq!(c[1], ["0", "clarabel"]);
        assert_eq!(combinations(&[]), vec![Vec::<String>::new()]);
        for bad in ["noequals", "=1,2", "key="] {
            assert!(matches!(Variation::parse(bad), Err(SweepError::Vary { .. })), "{bad}");
        }
    }

    #[test]
    fn values_split_at_top_level_commas_and_keys_are_checked() {
        let v = Variation::parse("plate_insert.l_steps=[0.1,0.2],[0.3], \"a,b\"").unwrap();
        assert_eq!(v.values, ["[0.1,0.2]", "[0.3]", "\"a,b\""]);
        let scene = Path::new("scenes/plate_insert_nogap_mu0.toml");
        let nope = Variation::parse("plate_insert.nope=1").unwrap();
        assert!(matches!(check_variations(scene, &[nope], &[]), Err(SweepError::UnknownKey { .. })));
        let f = Variation::parse("plate_insert.friction=0,0.1").unwrap();
        assert!(matches!(check_variations(scene, &[f.clone(), f.clone()], &[]), Err(SweepError::DuplicateKey { .. })));
        assert_eq!(check_variations(scene, std::slice::from_ref(&f), &[]).unwrap(), 2);
        // 10^8 combinations are refused before any is built.
        let big = |key: &str| Variation { key: key.into(), values: (0..100).map(|i| i.to_string()).collect() };
        let many = [
            big("plate_insert.friction"),
            big("plate_insert.load"),
            big("plate_insert.eps"),
            big("plate_insert.steps"),
        ];
        assert!(matches!(check_variations(scene, &many, &[]), Err(SweepError::TooManyRuns { runs: 100_000_000 })));
    }
}

//! The `[solver]` section every scene shares, the paper's preset and generic scenes alike: the
//! library's [`ContactAlgorithm`] by its scene key, the iteration limit, the penalty method's
//! parameters and the Boussinesq algorithm's zone-end placement.
//!
//! ```toml
//! [solver]
//! algorithm = "active_set"   # clarabel, boussinesq, penalty, augmented_lagrangian
//! max_iterations = 100       # per step
//! penalty = 1e3              # penalty only: normal penalty / k_c
//! tangential_penalty = 1e3   # penalty only: stick penalty / k_c (default: penalty)
//! place_zone_ends = true     # boussinesq: nodes at l* and b* (preset default; generic: straight or circular master)
//! linear = "auto"            # condensed, sparse: how the contact states' equations are solved
//! stick_continuation = "auto" # off: the active set without regularised stick stages or coarse levels
//! floating_tolerance = 1e-10 # bodies held only by contact: the pins' force left, relative
//! ```

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serializer};

use contact2d_contact::{ContactAlgorithm, LinearSolver, PenaltyParameters, SolverSettings, StickContinuation};

use super::SceneError;

/// The scene keys of [`ContactAlgorithm::ALL`], in that order (serde needs them as a static
/// list for its "expected one of" message).
const ALGORITHM_KEYS: [&str; 5] = ["active_set", "clarabel", "boussinesq", "penalty", "augmented_lagrangian"];

/// Reads an algorithm from its scene key ([`ContactAlgorithm::key`]).
///
/// # Errors
/// An unknown key, naming the five that exist.
pub fn deserialize_algorithm<'de, D: Deserializer<'de>>(d: D) -> Result<ContactAlgorithm, D::Error> {
    let key = String::deserialize(d)?;
    algorithm_from_key(&key).ok_or_else(|| D::Error::unknown_variant(&key, &ALGORITHM_KEYS))
}

/// The algorithm whose scene key ([`ContactAlgorithm::key`]) is `key` (surrounding blanks
/// ignored), if any.
pub fn algorithm_from_key(key: &str) -> Option<ContactAlgorithm> {
    ContactAlgorithm::ALL.into_iter().find(|a| a.key() == key.trim())
}

/// Writes an algorithm as its scene key (the JSON summaries' `algorithm`).
///
/// # Errors
/// Those of the serializer.
pub fn serialize_algorithm<S: Serializer>(algorithm: &ContactAlgorithm, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(algorithm.key())
}

/// The scene keys of [`LinearSolver::ALL`], in that order.
const LINEAR_KEYS: [&str; 3] = ["auto", "condensed", "sparse"];

/// Reads `solver.linear` from its scene key ([`LinearSolver::key`]).
fn deserialize_linear<'de, D: Deserializer<'de>>(d: D) -> Result<LinearSolver, D::Error> {
    let key = String::deserialize(d)?;
    LinearSolver::ALL
        .into_iter()
        .find(|l| l.key() == key.trim())
        .ok_or_else(|| D::Error::unknown_variant(&key, &LINEAR_KEYS))
}

/// The scene keys of [`StickContinuation::ALL`], in that order.
const CONTINUATION_KEYS: [&str; 2] = ["auto", "off"];

/// Reads `solver.stick_continuation` from its scene key ([`StickContinuation::key`]).
fn deserialize_continuation<'de, D: Deserializer<'de>>(d: D) -> Result<StickContinuation, D::Error> {
    let key = String::deserialize(d)?;
    StickContinuation::ALL
        .into_iter()
        .find(|c| c.key() == key.trim())
        .ok_or_else(|| D::Error::unknown_variant(&key, &CONTINUATION_KEYS))
}

/// The `[solver]` section.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolverEntry {
    /// Algorithm (default `active_set`).
    #[serde(default = "active_set", deserialize_with = "deserialize_algorithm")]
    pub algorithm: ContactAlgorithm,
    /// Iteration limit per step (default 100).
    #[serde(default = "hundred")]
    pub max_iterations: usize,
    /// The penalty method's normal penalty relative to the contact stiffness scale `k_c`
    /// (default 1e3; `penalty` only).
    #[serde(default)]
    pub penalty: Option<f64>,
    /// Its tangential (stick) penalty relative to `k_c` (default: `penalty`).
    #[serde(default)]
    pub tangential_penalty: Option<f64>,
    /// Boussinesq only: place master nodes exactly at the zone ends l* and b* by root finding
    /// (the paper's mesh adjustment, `contact2d_contact::placement`; default `true` on the plate-insert
    /// preset; on a generic scene only when set, for a straight or circular master curve);
    /// `false` keeps the mesh and resolves the zone ends to its nodes.
    #[serde(default)]
    pub place_zone_ends: Option<bool>,
    /// How the contact states' linear equations are solved: `auto` (default), `condensed` or
    /// `sparse` ([`LinearSolver`]).
    #[serde(default, deserialize_with = "deserialize_linear")]
    pub linear: LinearSolver,
    /// Whether the active set follows a regularised stick law to the exact one on long
    /// frictional interfaces: `auto` (default) or `off` ([`StickContinuation`]).
    #[serde(default, deserialize_with = "deserialize_continuation")]
    pub stick_continuation: StickContinuation,
    /// Bodies held only by contact: the force their pins may still carry, relative to the
    /// step's force scale (default 1e-10; [`SolverSettings::with_floating_tolerance`]).
    #[serde(default)]
    pub floating_tolerance: Option<f64>,
}

impl Default for SolverEntry {
    fn default() -> Self {
        SolverEntry {
            algorithm: ContactAlgorithm::ActiveSet,
            max_iterations: 100,
            penalty: None,
            tangential_penalty: None,
            place_zone_ends: None,
            linear: LinearSolver::Auto,
            stick_continuation: StickContinuation::Auto,
            floating_tolerance: None,
        }
    }
}

fn active_set() -> ContactAlgorithm {
    ContactAlgorithm::ActiveSet
}

fn hundred() -> usize {
    100
}

impl SolverEntry {
    /// Whether the Boussinesq algorithm places its zone ends (the default where it can).
    pub fn places_zone_ends(&self) -> bool {
        self.algorithm == ContactAlgorithm::Boussinesq && self.place_zone_ends.unwrap_or(true)
    }

    /// The library's settings. `fail(key, reason)` makes the scene's error.
    ///
    /// # Errors
    /// An iteration limit out of range, a penalty given to another algorithm or out of range.
    pub fn settings(&self, fail: impl Fn(&str, String) -> SceneError) -> Result<SolverSettings, SceneError> {
        let algorithm = self.algorithm;
        let settings = SolverSettings::new(algorithm)
            .with_max_iterations(self.max_iterations)
            .map_err(|e| fail("solver.max_iterations", e.to_string()))?
            .with_linear(self.linear)
            .map_err(|e| fail("solver.linear", e.to_string()))?
            .with_stick_continuation(self.stick_continuation);
        let settings = match self.floating_tolerance {
            Some(tolerance) => settings
                .with_floating_tolerance(tolerance)
                .map_err(|e| fail("solver.floating_tolerance", e.to_string()))?,
            None => settings,
        };
        let given = [("solver.penalty", self.penalty), ("solver.tangential_penalty", self.tangential_penalty)];
        if algorithm != ContactAlgorithm::Penalty {
            if let Some((key, _)) = given.iter().find(|(_, v)| v.is_some()) {
                return Err(fail(key, "a penalty applies to solver.algorithm = \"penalty\" only".into()));
            }
            return Ok(settings);
        }
        let defaults = PenaltyParameters::default();
        let normal = self.penalty.unwrap_or(defaults.normal);
        let tangential = self.tangential_penalty.unwrap_or(normal);
        let key = if self.penalty.is_some_and(|v| !(1e-3..=1e15).contains(&v)) {
            "solver.penalty"
        } else {
            "solver.tangential_penalty"
        };
        settings.with_penalty(normal, tangential).map_err(|e| fail(key, e.to_string()))
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn linear_reads_its_keys_and_refuses_sparse_where_it_does_not_apply() {
        for (linear, key) in LinearSolver::ALL.into_iter().zip(LINEAR_KEYS) {
            assert_eq!(linear.key(), key);
            let entry: SolverEntry = toml::from_str(&format!("linear = \"{key}\"")).unwrap();
            assert_eq!(entry.linear, linear);
        }
        let wrong = toml::from_str::<SolverEntry>("linear = \"dense\"").unwrap_err().to_string();
        for (continuation, key) in StickContinuation::ALL.into_iter().zip(CONTINUATION_KEYS) {
            assert_eq!(continuation.key(), key);
            let entry: SolverEntry = toml::from_str(&format!("stick_continuation = \"{key}\"")).unwrap();
            assert_eq!(entry.stick_continuation, continuation);
        }
        let unknown = toml::from_str::<SolverEntry>("stick_continuation = \"on\"").unwrap_err().to_string();
        assert!(unknown.contains("off"), "{unknown}");
        assert!(wrong.contains("condensed"), "{wrong}");
        let entry: SolverEntry = toml::from_str("algorithm = \"clarabel\"\nlinear = \"sparse\"").unwrap();
        let fail = |key: &str, reason: String| SceneError::Value { path: "s.toml".into(), key: key.into(), reason };
        assert!(matches!(entry.settings(fail), Err(SceneError::Value { key, .. }) if key == "solver.linear"));
    }

    #[test]
    fn the_floating_tolerance_is_passed_on_and_refused_out_of_range() {
        let fail = |key: &str, reason: String| SceneError::Value { path: "s.toml".into(), key: key.into(), reason };
        let entry: SolverEntry = toml::from_str("floating_tolerance = 1e-13").unwrap();
        assert_eq!(entry.settings(fail).unwrap().floating_tolerance(), 1e-13);
        assert_eq!(SolverEntry::default().settings(fail).unwrap().floating_tolerance(), 1e-10);
        let entry: SolverEntry = toml::from_str("floating_tolerance = 0.1").unwrap();
        let refused = entry.settings(fail);
        assert!(matches!(refused, Err(SceneError::Value { key, .. }) if key == "solver.floating_tolerance"));
    }

    #[test]
    fn every_algorithm_reads_and_writes_its_key() {
        for (algorithm, key) in ContactAlgorithm::ALL.into_iter().zip(ALGORITHM_KEYS) {
            assert_eq!(algorithm.key(), key);
            let entry: SolverEntry = toml::from_str(&format!("algorithm = \"{key}\"")).unwrap();
            assert_eq!(entry.algorithm, algorithm);
        }
        let wrong = toml::from_str::<SolverEntry>("algorithm = \"newton\"").unwrap_err().to_string();
        assert!(wrong.contains("augmented_lagrangian"), "{wrong}");
    }
}

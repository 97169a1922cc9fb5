//! The limits of scene values: every loop and allocation a scene asks for is bounded, and
//! magnitudes that f64 arithmetic cannot carry through the solve are refused up front, naming
//! the key (issue 15).
//!
//! ```text
//! steps, len(l_steps)   ≤ MAX_STEPS = 1000
//! max_iterations        ≤ MAX_ITERATIONS = 10 000
//! w, c                  0 or 1e-100 ..= 1e100     (energies ∝ w², c² stay normal f64 numbers)
//! E2/E1                 1e-8 ..= 1e8              (condition number ∝ max(E2/E1, E1/E2))
//! μ                     ≤ 1000
//! name                  no control characters     (they corrupt SVG and CSV)
//! ```

use super::{Scene, SceneError};

/// The largest number of load steps a scene may ask for (`steps` or the length of `l_steps`).
///
/// Every step keeps its solution in memory and writes one VTU file: with the active set about
/// 20 bytes per mesh node and step (1 GB for 1000 steps of the N = 128 mesh); the Boussinesq
/// algorithm with placed zone ends keeps a whole problem per step (about 2 kB per node and step),
/// which [`crate::run`] bounds further by [`crate::run::MAX_HISTORY_BYTES`].
pub const MAX_STEPS: usize = 1000;

/// The largest iteration limit a scene may set: each iteration of the active set solves the
/// condensed interface system once (milliseconds on the bundled meshes), so the limit bounds a
/// step that cycles to minutes, not days.
pub const MAX_ITERATIONS: usize = 10_000;

/// The magnitudes of the load w and the clearance c that are accepted besides 0: quantities
/// scale with their square (energies ∝ w², c²), which stays within f64's normal range
/// (2.2e-308 ..= 1.8e308) only for magnitudes within 1e-100 ..= 1e100.
pub const MAGNITUDE_RANGE: (f64, f64) = (1e-100, 1e100);

/// The accepted stiffness ratios E2/E1: the assembled stiffness's condition number grows in
/// proportion to max(E2/E1, E1/E2); beyond 1e8 it passes 1e8 × the mesh's own, and the
/// softer body's stiffness drowns in the round-off (1e-16 relative) of the stiffer one.
pub const STIFFNESS_RATIO_RANGE: (f64, f64) = (1e-8, 1e8);

/// The largest friction coefficient accepted.
pub const MAX_FRICTION: f64 = 1000.0;

/// Checks the magnitudes and the name (called by [`Scene::validate`] after the finiteness and
/// sign checks).
pub(super) fn validate_magnitudes(scene: &Scene) -> Result<(), SceneError> {
    let fail = |key: &str, reason: String| SceneError::Value {
        path: scene.file.display().to_string(),
        key: key.to_string(),
        reason,
    };
    let p = &scene.plate_insert;
    if let Some(c) = scene.name.chars().find(|c| c.is_control()) {
        return Err(fail(
            "name",
            format!("contains the control character U+{:04X}; it would corrupt every figure and table", u32::from(c)),
        ));
    }
    for (key, v) in [("plate_insert.load", p.load), ("plate_insert.clearance", p.clearance)] {
        let (lo, hi) = MAGNITUDE_RANGE;
        if v != 0.0 && !(lo..=hi).contains(&v) {
            return Err(fail(
                key,
                format!(
                    "{v:e} is out of the representable range: 0 or {lo:e} ..= {hi:e} (energies scale with its square)"
                ),
            ));
        }
    }
    if p.friction > MAX_FRICTION {
        return Err(fail(
            "plate_insert.friction",
            format!(
                "μ = {:e} is beyond {MAX_FRICTION} (every pair sticks long before; the cone test μλ loses all digits)",
                p.friction
            ),
        ));
    }
    let (lo, hi) = STIFFNESS_RATIO_RANGE;
    if !(lo..=hi).contains(&p.stiffness_ratio) {
        return Err(fail(
            "plate_insert.stiffness_ratio",
            format!(
                "E2/E1 = {:e} is out of the solvable range {lo:e} ..= {hi:e} (the stiffness matrix's condition \
                     number grows with the ratio; beyond it the softer body is round-off)",
                p.stiffness_ratio
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::panic)]
mod tests {
    use super::*;
    use std::path::Path;

    const SCENE: &str = "name = \"t\"\n[plate_insert]\nmesh = \"m.msh\"\nvariant = \"hole_master\"\nload = 1.0\n[solver]\nalgorithm = \"active_set\"\n";

    fn load(overrides: &[String]) -> Result<Scene, SceneError> {
        Scene::from_toml_str(SCENE, Path::new("t.toml"), overrides)
    }

    #[test]
    fn absurd_magnitudes_and_control_characters_name_their_key() {
        for (set, key) in [
            ("plate_insert.stiffness_ratio=1e308", "plate_insert.stiffness_ratio"),
            ("plate_insert.stiffness_ratio=1e-9", "plate_insert.stiffness_ratio"),
            ("plate_insert.load=1e101", "plate_insert.load"),
            ("plate_insert.load=1e-310", "plate_insert.load"),
            ("plate_insert.friction=1e308", "plate_insert.friction"),
            ("plate_insert.steps=1001", "plate_insert.steps"),
            ("solver.max_iterations=10001", "solver.max_iterations"),
            ("name=\"a\\u0000b\"", "name"),
            ("name=\"tab\\there\"", "name"),
        ] {
            let e = load(&[set.into()]).unwrap_err();
            assert!(matches!(&e, SceneError::Value { key: k, .. } if k == key), "{set}: {e}");
        }
        assert!(load(&["plate_insert.stiffness_ratio=1e8".into()]).is_ok());
    }
}

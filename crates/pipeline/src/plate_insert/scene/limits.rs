//! The plate-insert scene's checks of the shared limits ([`crate::schema::limits`]).

use super::{PlateInsertScene, SceneError};
use crate::schema::limits::{MAGNITUDE_RANGE, MAX_FRICTION, STIFFNESS_RATIO_RANGE};

/// Checks the magnitudes and the name (called by [`PlateInsertScene::validate`] after the finiteness and
/// sign checks).
pub(super) fn validate_magnitudes(scene: &PlateInsertScene) -> Result<(), SceneError> {
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

    fn load(overrides: &[String]) -> Result<PlateInsertScene, SceneError> {
        PlateInsertScene::from_toml_str(SCENE, Path::new("t.toml"), overrides)
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

//! The meshes and scene files compiled into the module (the page has no file system): the
//! flagship's teaching meshes (N = 16 and 32 elements along the half hole edge, one per bundled
//! clearance ε), the coarsest NAFEMS Hertz mesh L1 (L2 takes over a second per
//! solve in the browser, too slow to follow a slider), the Cattaneo–Mindlin teaching mesh L0 (4
//! cells across the contact half-width; the gallery's L1 has 8), and the bundled scene files that
//! set up the published cases, the Hertz benchmark and Cattaneo–Mindlin.

use crate::WebError;

/// The clearances ε of the bundled flagship meshes (`meshes/plate_insert/`), ascending.
pub const FLAGSHIP_EPS: [f64; 5] = [0.0, 1e-6, 0.001, 0.05, 0.2];

/// The refinements N of the bundled flagship meshes (elements along the half hole edge).
pub const FLAGSHIP_REFINEMENTS: [u32; 2] = [16, 32];

/// The refinement levels of the bundled Hertz meshes (`meshes/generic/cylinder_on_block_*.msh`).
pub const HERTZ_LEVELS: [&str; 1] = ["L1"];

/// The Hertz scene file `scenes/generic/cylinder_on_block.toml`.
pub const HERTZ_SCENE: &str = include_str!("../../../scenes/generic/cylinder_on_block.toml");

/// The mesh levels of the bundled Cattaneo–Mindlin meshes (`meshes/generic/cattaneo_mindlin_*.msh`).
pub const CATTANEO_MINDLIN_LEVELS: [&str; 1] = ["L0"];

/// The Cattaneo–Mindlin scene file `scenes/generic/cattaneo_mindlin.toml`.
pub const CATTANEO_MINDLIN_SCENE: &str = include_str!("../../../scenes/generic/cattaneo_mindlin.toml");

/// The bundled flagship scene files of the published cases, as (scene name, TOML text).
pub const PUBLISHED_SCENES: [(&str, &str); 5] = [
    ("plate_insert_nogap_mu0", include_str!("../../../scenes/plate_insert_nogap_mu0.toml")),
    ("plate_insert_nogap_mu03", include_str!("../../../scenes/plate_insert_nogap_mu03.toml")),
    ("plate_insert_gap_v1_mu03", include_str!("../../../scenes/plate_insert_gap_v1_mu03.toml")),
    ("plate_insert_gap_v2_mu03", include_str!("../../../scenes/plate_insert_gap_v2_mu03.toml")),
    ("plate_insert_gap_v2_mu0", include_str!("../../../scenes/plate_insert_gap_v2_mu0.toml")),
];

/// (ε, N, file name, bytes) of every bundled flagship mesh.
const FLAGSHIP_MESHES: [(f64, u32, &str, &[u8]); 10] = [
    (0.0, 16, "plate_insert_eps0_N16.msh", include_bytes!("../../../meshes/plate_insert/plate_insert_eps0_N16.msh")),
    (0.0, 32, "plate_insert_eps0_N32.msh", include_bytes!("../../../meshes/plate_insert/plate_insert_eps0_N32.msh")),
    (
        1e-6,
        16,
        "plate_insert_eps1e-6_N16.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps1e-6_N16.msh"),
    ),
    (
        1e-6,
        32,
        "plate_insert_eps1e-6_N32.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps1e-6_N32.msh"),
    ),
    (
        0.001,
        16,
        "plate_insert_eps0.001_N16.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.001_N16.msh"),
    ),
    (
        0.001,
        32,
        "plate_insert_eps0.001_N32.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.001_N32.msh"),
    ),
    (
        0.05,
        16,
        "plate_insert_eps0.05_N16.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.05_N16.msh"),
    ),
    (
        0.05,
        32,
        "plate_insert_eps0.05_N32.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.05_N32.msh"),
    ),
    (
        0.2,
        16,
        "plate_insert_eps0.2_N16.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.2_N16.msh"),
    ),
    (
        0.2,
        32,
        "plate_insert_eps0.2_N32.msh",
        include_bytes!("../../../meshes/plate_insert/plate_insert_eps0.2_N32.msh"),
    ),
];

/// (level, file name, bytes) of every bundled Hertz mesh.
const HERTZ_MESHES: [(&str, &str, &[u8]); 1] =
    [("L1", "cylinder_on_block_L1.msh", include_bytes!("../../../meshes/generic/cylinder_on_block_L1.msh"))];

/// (level, file name, bytes) of every bundled Cattaneo–Mindlin mesh.
const CATTANEO_MINDLIN_MESHES: [(&str, &str, &[u8]); 1] =
    [("L0", "cattaneo_mindlin_L0.msh", include_bytes!("../../../meshes/generic/cattaneo_mindlin_L0.msh"))];

/// A bundled mesh file: its name (as in `meshes/`) and its bytes.
#[derive(Debug, Clone, Copy)]
pub struct BundledMesh {
    /// File name, e.g. `plate_insert_eps0_N16.msh`.
    pub file: &'static str,
    /// The .msh file's bytes.
    pub bytes: &'static [u8],
}

/// The flagship mesh of clearance `eps` and refinement `n`.
///
/// # Errors
/// [`WebError::NoMesh`] when no bundled mesh has this ε (exactly one of [`FLAGSHIP_EPS`]) and N.
pub fn flagship_mesh(eps: f64, n: u32) -> Result<BundledMesh, WebError> {
    FLAGSHIP_MESHES
        .iter()
        .find(|m| m.0 == eps && m.1 == n)
        .map(|m| BundledMesh { file: m.2, bytes: m.3 })
        .ok_or_else(|| WebError::NoMesh(format!("no bundled flagship mesh with eps = {eps} and N = {n}")))
}

/// The Hertz mesh of refinement `level` ("L1").
///
/// # Errors
/// [`WebError::NoMesh`] for another level.
pub fn hertz_mesh(level: &str) -> Result<BundledMesh, WebError> {
    HERTZ_MESHES
        .iter()
        .find(|m| m.0 == level)
        .map(|m| BundledMesh { file: m.1, bytes: m.2 })
        .ok_or_else(|| WebError::NoMesh(format!("no bundled Hertz mesh at level {level:?} (L1)")))
}

/// The Cattaneo–Mindlin mesh of refinement `level` ("L0").
///
/// # Errors
/// [`WebError::NoMesh`] for another level.
pub fn cattaneo_mindlin_mesh(level: &str) -> Result<BundledMesh, WebError> {
    CATTANEO_MINDLIN_MESHES
        .iter()
        .find(|m| m.0 == level)
        .map(|m| BundledMesh { file: m.1, bytes: m.2 })
        .ok_or_else(|| WebError::NoMesh(format!("no bundled Cattaneo–Mindlin mesh at level {level:?} (L0)")))
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn every_bundled_flagship_mesh_is_found_and_names_its_eps_and_n() {
        for eps in FLAGSHIP_EPS {
            for n in FLAGSHIP_REFINEMENTS {
                let mesh = flagship_mesh(eps, n).unwrap();
                assert!(mesh.file.ends_with(&format!("_N{n}.msh")), "{}", mesh.file);
                assert!(mesh.bytes.starts_with(b"$MeshFormat"));
            }
        }
        assert!(matches!(flagship_mesh(0.01, 16), Err(WebError::NoMesh(_))));
        assert!(matches!(flagship_mesh(0.0, 64), Err(WebError::NoMesh(_))));
        assert!(matches!(hertz_mesh("L3"), Err(WebError::NoMesh(_))));
        for level in CATTANEO_MINDLIN_LEVELS {
            assert!(cattaneo_mindlin_mesh(level).unwrap().bytes.starts_with(b"$MeshFormat"));
        }
        assert!(matches!(cattaneo_mindlin_mesh("L1"), Err(WebError::NoMesh(_))));
    }
}

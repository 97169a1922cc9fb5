//! contact2d in the browser: the teaching page's WebAssembly module (`web/`, built by
//! `web/build.sh`).
//!
//! The page sets parameters with sliders and calls one function per scene; each returns the
//! whole solved state as one JSON text (numbers in shortest round-trip form, so the page and
//! the tests read exactly the computed values):
//!
//! ```text
//! solve_flagship({"friction": 0.3, "stiffness_ratio": 1, "eps": 0, "refinement": 16,
//!                 "load": 1, "variant": "hole_master"})
//!   → {summary (the generic report; l, b, P, Φ, σ*, K under paper), published, hole {eta, s, hoop, p, q, state},
//!      insert {...}, pairs {master, state, normal_force, tangent}, mesh {points, edges, displacement}}
//! solve_hertz({"force": 35000, "level": "L1"})
//!   → {summary (generic report with the interface profile), closed_form {a, p0, x, pressure},
//!      pairs, mesh}
//! solve_cattaneo_mindlin({"press": 1, "shear": 0.293, "level": "L0"})
//!   → {summary, measured {P, Q, Q/(μP), a, c}, closed_form {a, p0, c, x, pressure, shear},
//!      pairs, mesh}
//! solve_generic({"scene": "pin_lug", "overrides": ["contact.bore.friction=0.3"]})
//!   → {scene, description, mesh_file, summary (with every interface's profile), pairs, mesh}
//! solve_user_scene(scene name, scene bytes, mesh name, mesh bytes, ["--set" strings])
//!   → the same view, for a scene and mesh dropped on the page (the CLI's limits and messages),
//!     with frames [{displacement, pairs, contacts}] of every load step when it has several
//! ```
//! The scenes are the facade's own ([`contact2d_pipeline::run::solve_scene_on_mesh`],
//! [`contact2d_pipeline::generic::solve_generic_on_mesh`]) on meshes compiled into the module
//! ([`bundled`]): the numbers are those of `contact2d run` on the same files. A new scene is one
//! module with its parameters, its solve and its view, plus one
//! exported function here.
//!
//! The module builds natively too (the tests, and the `web_reference` binary that writes the
//! native numbers the page's tests compare with).

use wasm_bindgen::prelude::*;

pub mod bundled;
pub mod cattaneo_mindlin;
pub mod flagship;
pub mod generic_scene;
pub mod hertz;
pub mod view;

pub use cattaneo_mindlin::{CattaneoMindlinParams, CattaneoMindlinView, solve_cattaneo_mindlin};
pub use flagship::{FlagshipParams, FlagshipView, solve_flagship};
pub use generic_scene::{GenericParams, GenericView, solve_bundled_generic, solve_user_scene};
pub use hertz::{HertzParams, HertzView, solve_hertz};

/// Errors of the page's module.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WebError {
    /// The parameters are not valid JSON of the scene's parameter object.
    #[error("parameters: {0}")]
    Params(#[from] serde_json::Error),
    /// No bundled mesh matches the parameters.
    #[error("{0}")]
    NoMesh(String),
    /// A parameter out of range (the scene file's checks).
    #[error(transparent)]
    Scene(#[from] contact2d_pipeline::scene::SceneError),
    /// A bundled mesh does not parse.
    #[error(transparent)]
    Mesh(#[from] contact2d_mesh::MeshError),
    /// The problem could not be set up or solved.
    #[error(transparent)]
    Contact(#[from] contact2d_contact::ContactError),
    /// A generic scene could not be set up or solved.
    #[error(transparent)]
    Generic(#[from] contact2d_pipeline::generic::GenericError),
    /// The solution could not be post-processed.
    #[error("post-processing: {0}")]
    Solve(String),
}

/// Solves the flagship for the JSON [`FlagshipParams`] and returns the JSON [`FlagshipView`].
///
/// # Errors
/// [`WebError`] (as a JavaScript `Error`) for bad parameters or a failed solve.
pub fn flagship_json(params: &str) -> Result<String, WebError> {
    let params: FlagshipParams = serde_json::from_str(params)?;
    Ok(serde_json::to_string(&solve_flagship(&params)?)?)
}

/// Solves the Hertz scene for the JSON [`HertzParams`] and returns the JSON [`HertzView`].
///
/// # Errors
/// [`WebError`] for bad parameters or a failed solve.
pub fn hertz_json(params: &str) -> Result<String, WebError> {
    let params: HertzParams = serde_json::from_str(params)?;
    Ok(serde_json::to_string(&solve_hertz(&params)?)?)
}

/// Solves the Cattaneo–Mindlin scene for the JSON [`CattaneoMindlinParams`] and returns the JSON
/// [`CattaneoMindlinView`].
///
/// # Errors
/// [`WebError`] for bad parameters or a failed solve.
pub fn cattaneo_mindlin_json(params: &str) -> Result<String, WebError> {
    let params: CattaneoMindlinParams = serde_json::from_str(params)?;
    Ok(serde_json::to_string(&solve_cattaneo_mindlin(&params)?)?)
}

/// Solves a bundled generic scene for the JSON [`GenericParams`] and returns the JSON
/// [`GenericView`].
///
/// # Errors
/// [`WebError`] for bad parameters or a failed solve.
pub fn generic_json(params: &str) -> Result<String, WebError> {
    let params: GenericParams = serde_json::from_str(params)?;
    Ok(serde_json::to_string(&solve_bundled_generic(&params)?)?)
}

/// Solves a user's scene (file names and bytes as dropped on the page; `overrides` a JSON array
/// of `--set` strings) and returns the JSON [`GenericView`].
///
/// # Errors
/// [`WebError`] for input the CLI would refuse or a failed solve.
pub fn user_scene_json(
    scene_name: &str,
    scene_bytes: &[u8],
    mesh_name: &str,
    mesh_bytes: &[u8],
    overrides: &str,
) -> Result<String, WebError> {
    let overrides: Vec<String> = serde_json::from_str(overrides)?;
    let view = solve_user_scene(scene_name, scene_bytes, mesh_name, mesh_bytes, &overrides)?;
    Ok(serde_json::to_string(&view)?)
}

/// The page's entry point for the bundled generic scenes: [`generic_json`] with the error as a
/// JavaScript `Error`.
///
/// # Errors
/// The [`WebError`]'s message.
#[wasm_bindgen]
pub fn solve_generic_json(params: &str) -> Result<String, JsError> {
    generic_json(params).map_err(|e| JsError::new(&e.to_string()))
}

/// The page's entry point for a user's scene: [`user_scene_json`] with the error as a
/// JavaScript `Error`.
///
/// # Errors
/// The [`WebError`]'s message.
#[wasm_bindgen]
pub fn solve_user_scene_json(
    scene_name: &str,
    scene_bytes: &[u8],
    mesh_name: &str,
    mesh_bytes: &[u8],
    overrides: &str,
) -> Result<String, JsError> {
    user_scene_json(scene_name, scene_bytes, mesh_name, mesh_bytes, overrides).map_err(|e| JsError::new(&e.to_string()))
}

/// The page's entry point for the flagship: [`flagship_json`] with the error as a JavaScript
/// `Error`.
///
/// # Errors
/// The [`WebError`]'s message.
#[wasm_bindgen]
pub fn solve_flagship_json(params: &str) -> Result<String, JsError> {
    flagship_json(params).map_err(|e| JsError::new(&e.to_string()))
}

/// The page's entry point for the Hertz scene: [`hertz_json`] with the error as a JavaScript
/// `Error`.
///
/// # Errors
/// The [`WebError`]'s message.
#[wasm_bindgen]
pub fn solve_hertz_json(params: &str) -> Result<String, JsError> {
    hertz_json(params).map_err(|e| JsError::new(&e.to_string()))
}

/// The page's entry point for the Cattaneo–Mindlin scene: [`cattaneo_mindlin_json`] with the
/// error as a JavaScript `Error`.
///
/// # Errors
/// The [`WebError`]'s message.
#[wasm_bindgen]
pub fn solve_cattaneo_mindlin_json(params: &str) -> Result<String, JsError> {
    cattaneo_mindlin_json(params).map_err(|e| JsError::new(&e.to_string()))
}

/// The bundled meshes and the page's fixed choices, as JSON: `{"flagship_eps": [...],
/// "flagship_refinements": [...], "hertz_levels": [...], "cattaneo_mindlin_levels": [...],
/// "clearance_per_eps": ω, "generic": [{name, mesh_file}], "max_scene_bytes", "max_mesh_bytes"}`.
#[wasm_bindgen]
pub fn bundled_json() -> String {
    serde_json::json!({
        "flagship_eps": bundled::FLAGSHIP_EPS,
        "flagship_refinements": bundled::FLAGSHIP_REFINEMENTS,
        "hertz_levels": bundled::HERTZ_LEVELS,
        "cattaneo_mindlin_levels": bundled::CATTANEO_MINDLIN_LEVELS,
        "clearance_per_eps": flagship::CLEARANCE_PER_EPS,
        "generic": generic_scene::BUNDLED_GENERIC.iter().map(|b| serde_json::json!({
            "name": b.name, "mesh_file": b.mesh_file,
        })).collect::<Vec<_>>(),
        "max_scene_bytes": contact2d_pipeline::input_file::MAX_SCENE_BYTES,
        "max_mesh_bytes": contact2d_pipeline::input_file::MAX_MESH_BYTES,
    })
    .to_string()
}

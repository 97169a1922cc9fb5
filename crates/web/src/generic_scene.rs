//! Any generic scene on the page, through the one pipeline of `contact2d run`: a scene's TOML
//! text, the `--set` overrides of the page's sliders ([`contact2d_pipeline::schema`]'s override engine),
//! a mesh parsed from bytes, [`contact2d_pipeline::generic::solve_generic_on_mesh`]. Two sources of text
//! and mesh, one solve:
//!
//! ```text
//! bundled   scenes/generic/<name>.toml + its teaching mesh, compiled in ([`BUNDLED_GENERIC`])
//! user      a scene .toml and its .msh dropped on the page (bytes; nothing leaves the machine),
//!           refused as `contact2d run` refuses files: scene ≤ MAX_SCENE_BYTES (1 MiB) of UTF-8,
//!           mesh ≤ MAX_MESH_BYTES (1 GiB), a generic scene (a top-level `mesh`, no
//!           `[plate_insert]`), with the CLI's messages
//! overrides "key.path=value" strings, exactly as `contact2d run --set` takes them
//! ```
//! The mesh named by the scene's `mesh` key is replaced by the one given (a bundled scene's by
//! its teaching mesh, a user's by the file dropped beside it); nothing else differs from
//! `contact2d run <scene> --set mesh=<that file> --set ...`.

use std::path::Path;

use serde::{Deserialize, Serialize};

use contact2d_mesh::parse_msh;
use contact2d_pipeline::generic::results::{ContactResult, contact_result};
use contact2d_pipeline::generic::{GenericOutcome, GenericReport, GenericScene, solve_generic_on_mesh};
use contact2d_pipeline::input_file::{MAX_MESH_BYTES, MAX_SCENE_BYTES};
use contact2d_pipeline::output::step_view::state_label;
use contact2d_pipeline::scene::SceneError;
use contact2d_pipeline::scene::is_generic;

use crate::WebError;
use crate::view::{MeshView, PairsView, mesh_view};

/// A bundled generic scene: its name (the file stem in `scenes/generic/`), its text, and the
/// teaching mesh the page solves it on (file name in `meshes/generic/` and bytes).
#[derive(Debug, Clone, Copy)]
pub struct BundledGeneric {
    /// The scene's file stem, e.g. `pin_lug`.
    pub name: &'static str,
    /// The scene file's text.
    pub text: &'static str,
    /// The mesh file solved on (in `meshes/generic/`).
    pub mesh_file: &'static str,
    /// Its bytes.
    pub mesh_bytes: &'static [u8],
}

/// The bundled generic scenes the page solves through [`solve_bundled_generic`]. The pin in a
/// lug runs on `pin_lug_L1.msh` (20 elements per arc; the scene's own L2 mesh takes about
/// 0.2 s per update natively, too slow to follow a slider in the browser); the others on the
/// scene's own mesh (the ball on a plate, a body of revolution, on its small teaching mesh).
pub const BUNDLED_GENERIC: [BundledGeneric; 5] = [
    BundledGeneric {
        name: "pin_lug",
        text: include_str!("../../../scenes/generic/pin_lug.toml"),
        mesh_file: "pin_lug_L1.msh",
        mesh_bytes: include_bytes!("../../../meshes/generic/pin_lug_L1.msh"),
    },
    BundledGeneric {
        name: "interference_fit",
        text: include_str!("../../../scenes/generic/interference_fit.toml"),
        mesh_file: "interference_fit.msh",
        mesh_bytes: include_bytes!("../../../meshes/generic/interference_fit.msh"),
    },
    BundledGeneric {
        name: "incline_push",
        text: include_str!("../../../scenes/generic/incline_push.toml"),
        mesh_file: "incline.msh",
        mesh_bytes: include_bytes!("../../../meshes/generic/incline.msh"),
    },
    BundledGeneric {
        name: "ball_on_plate",
        text: include_str!("../../../scenes/generic/ball_on_plate.toml"),
        mesh_file: "ball_on_plate.msh",
        mesh_bytes: include_bytes!("../../../meshes/generic/ball_on_plate.msh"),
    },
    BundledGeneric {
        name: "two_blocks_press_slide",
        text: include_str!("../../../scenes/generic/two_blocks_press_slide.toml"),
        mesh_file: "two_blocks.msh",
        mesh_bytes: include_bytes!("../../../meshes/generic/two_blocks.msh"),
    },
];

/// The page's request for a bundled generic scene.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GenericParams {
    /// The bundled scene's name (one of [`BUNDLED_GENERIC`]).
    pub scene: String,
    /// `--set` overrides, e.g. `contact.bore.friction=0.3`.
    #[serde(default)]
    pub overrides: Vec<String>,
}

/// Everything the page shows of one generic solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GenericView {
    /// The scene's name.
    pub scene: String,
    /// The scene's description.
    pub description: String,
    /// The mesh file solved on.
    pub mesh_file: String,
    /// The summary, as `contact2d run --json` writes it (with every interface's profile).
    pub summary: GenericReport,
    /// The pairs of the last step (a pair in contact without friction is `contact`).
    pub pairs: PairsView,
    /// The deformed mesh of the last step.
    pub mesh: MeshView,
    /// A user's scene of more than one step: every solved step, for the page's player (none
    /// for the bundled scenes, a one-step run, or a run too large to keep: [`MAX_FRAME_NUMBERS`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub frames: Vec<StepFrame>,
}

/// One solved step of a multi-step run as the page's player draws it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepFrame {
    /// Nodal displacements of the step, two numbers per node (as [`MeshView::displacement`]).
    pub displacement: Vec<f64>,
    /// The pairs at the step.
    pub pairs: PairsView,
    /// Every interface at the step, with its profile.
    pub contacts: std::collections::BTreeMap<String, ContactResult>,
}

/// The most numbers (displacements and pair values, over all steps) a run's frames may hold:
/// a larger run sends only its last step (the player then has nothing to play; the page says so).
pub const MAX_FRAME_NUMBERS: usize = 4_000_000;

/// Every solved step of `outcome` as a frame (empty for a run of one step, for a run whose pairs
/// were formed again (finite sliding: the last step's pairs are not the earlier steps'), and for
/// one over [`MAX_FRAME_NUMBERS`]).
pub fn step_frames(outcome: &GenericOutcome) -> Vec<StepFrame> {
    let built = &outcome.built;
    let problem = &built.problem;
    let steps = &outcome.history.steps;
    let per_step = 2 * problem.model.mesh.num_nodes() + 8 * problem.pairs.len();
    let same_pairs = steps.iter().all(|s| s.solution.state.len() == problem.pairs.len());
    if steps.len() < 2 || !same_pairs || steps.len().saturating_mul(per_step) > MAX_FRAME_NUMBERS {
        return vec![];
    }
    let rows = &outcome.report.steps;
    steps
        .iter()
        .enumerate()
        .map(|(k, step)| {
            let s = &step.solution;
            let state = s.state.iter().zip(&problem.friction).map(|(st, mu)| state_label(*st, *mu)).collect();
            let contacts = built
                .interfaces
                .iter()
                .map(|iface| {
                    // The step row's dissipation of the interface (the report accumulates it).
                    let dissipation = rows.get(k).and_then(|r| r.contacts.get(&iface.name).map(|c| c.dissipation));
                    (iface.name.clone(), contact_result(built, iface, s, dissipation.unwrap_or(0.0), true))
                })
                .collect();
            StepFrame {
                displacement: mesh_view(problem, s).displacement,
                pairs: PairsView {
                    master: problem.pairs.iter().map(|p| p.master.0).collect(),
                    state,
                    normal_force: s.normal_force.clone(),
                    tangent: problem.pairs.iter().map(|p| p.tangent).collect(),
                },
                contacts,
            }
        })
        .collect()
}

/// The bundled generic scene `name`.
///
/// # Errors
/// [`WebError::NoMesh`] for a name that is not bundled.
pub fn bundled_generic(name: &str) -> Result<&'static BundledGeneric, WebError> {
    BUNDLED_GENERIC.iter().find(|b| b.name == name).ok_or_else(|| {
        let names: Vec<&str> = BUNDLED_GENERIC.iter().map(|b| b.name).collect();
        WebError::NoMesh(format!("no bundled generic scene {name:?} (bundled: {})", names.join(", ")))
    })
}

/// The checked scene of `text` with `overrides`, solved on the mesh file `mesh_file`, as if read
/// from `scene_file` (the mesh path is relative to its directory).
///
/// # Errors
/// [`WebError::Scene`] for text that is not a generic scene or an override or value that
/// does not apply.
pub fn generic_scene(
    text: &str,
    scene_file: &Path,
    mesh_file: &str,
    overrides: &[String],
) -> Result<GenericScene, WebError> {
    if toml::from_str::<toml::Table>(text).is_err() {
        // Not TOML at all: the CLI's own message, with the line and column at fault.
        return Err(WebError::Scene(GenericScene::from_toml_str(text, scene_file, &[]).err().unwrap_or_else(|| {
            SceneError::Invalid { path: scene_file.display().to_string(), reason: "not TOML".into() }
        })));
    }
    if !is_generic(text) {
        return Err(WebError::Scene(SceneError::Invalid {
            path: scene_file.display().to_string(),
            reason: "not a generic scene (it needs a top-level `mesh` key and no [plate_insert] \
                     section; the plate-with-insert scenes are the page's first tab)"
                .into(),
        }));
    }
    let mut all = vec![format!("mesh={mesh_file:?}")];
    all.extend(overrides.iter().cloned());
    Ok(GenericScene::from_toml_str(text, scene_file, &all)?)
}

/// Solves a bundled generic scene on its teaching mesh (the page's path).
///
/// # Errors
/// [`WebError`] for a scene that is not bundled, an override that does not apply, or a failed
/// set-up.
pub fn solve_bundled_generic(params: &GenericParams) -> Result<GenericView, WebError> {
    let bundled = bundled_generic(&params.scene)?;
    let scene_file = format!("scenes/generic/{}.toml", bundled.name);
    let mesh_path = format!("../../meshes/generic/{}", bundled.mesh_file);
    let scene = generic_scene(bundled.text, Path::new(&scene_file), &mesh_path, &params.overrides)?;
    let mesh = parse_msh(bundled.mesh_bytes)?;
    let outcome = solve_generic_on_mesh(&scene, mesh, &mut |_, _| {})?;
    Ok(generic_view(bundled.mesh_file, &outcome))
}

/// Solves a user's scene: the bytes of a scene file named `scene_name` and of its mesh file
/// named `mesh_name`, with `overrides`, refused as `contact2d run` refuses files.
///
/// # Errors
/// [`WebError::Scene`] for a file over the CLI's limits, a scene that is not UTF-8 or not a
/// generic scene (with the CLI's messages); [`WebError::Mesh`] for a mesh that does not parse;
/// [`WebError::Generic`] for a failed set-up.
pub fn solve_user_scene(
    scene_name: &str,
    scene_bytes: &[u8],
    mesh_name: &str,
    mesh_bytes: &[u8],
    overrides: &[String],
) -> Result<GenericView, WebError> {
    let too_large = |size: usize, limit: u64| format!("{size} bytes exceed the limit of {limit} bytes");
    if scene_bytes.len() as u64 > MAX_SCENE_BYTES {
        let reason = too_large(scene_bytes.len(), MAX_SCENE_BYTES);
        return Err(WebError::Scene(SceneError::Unreadable { path: scene_name.into(), reason }));
    }
    let text = std::str::from_utf8(scene_bytes).map_err(|e| {
        let reason = format!("not UTF-8 text (invalid byte at offset {})", e.valid_up_to());
        WebError::Scene(SceneError::Invalid { path: scene_name.into(), reason })
    })?;
    if mesh_bytes.len() as u64 > MAX_MESH_BYTES {
        let reason = format!("cannot read {mesh_name}: {}", too_large(mesh_bytes.len(), MAX_MESH_BYTES));
        return Err(WebError::Scene(SceneError::Value { path: scene_name.into(), key: "mesh".into(), reason }));
    }
    let scene = generic_scene(text, Path::new(scene_name), mesh_name, overrides)?;
    let mesh = parse_msh(mesh_bytes).map_err(|source| {
        WebError::Generic(contact2d_pipeline::generic::GenericError::Mesh {
            scene: scene_name.into(),
            mesh: mesh_name.into(),
            source,
        })
    })?;
    let outcome = solve_generic_on_mesh(&scene, mesh, &mut |_, _| {})?;
    Ok(GenericView { frames: step_frames(&outcome), ..generic_view(mesh_name, &outcome) })
}

/// The page's view of a solved generic scene.
pub fn generic_view(mesh_file: &str, outcome: &GenericOutcome) -> GenericView {
    let problem = &outcome.built.problem;
    let (pairs, mesh) = match outcome.history.steps.last() {
        Some(step) => {
            let solution = &step.solution;
            let state = solution.state.iter().zip(&problem.friction).map(|(s, mu)| state_label(*s, *mu)).collect();
            let pairs = PairsView {
                master: problem.pairs.iter().map(|p| p.master.0).collect(),
                state,
                normal_force: solution.normal_force.clone(),
                tangent: problem.pairs.iter().map(|p| p.tangent).collect(),
            };
            (pairs, mesh_view(problem, solution))
        }
        None => (
            PairsView::empty(),
            MeshView { points: vec![], edges: vec![], edge_body: vec![], bodies: vec![], displacement: vec![] },
        ),
    };
    GenericView {
        scene: outcome.scene.name.clone(),
        description: outcome.scene.description.clone(),
        mesh_file: mesh_file.to_string(),
        summary: outcome.report.clone(),
        pairs,
        mesh,
        frames: vec![],
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn solve(scene: &str, overrides: &[&str]) -> Result<GenericView, WebError> {
        let overrides = overrides.iter().map(|s| s.to_string()).collect();
        solve_bundled_generic(&GenericParams { scene: scene.into(), overrides })
    }

    /// Lamé's shrink fit (the scene's comment): p = E δ (b² − a²) / (2 a b²) = 100 MPa for
    /// E = 2e5 MPa, δ = 0.6667 mm, a = 500 mm, b = 1000 mm. The interface's largest pressure
    /// on this mesh is within 3 % of it (the bundled scene's own verification holds 2 % on
    /// the same mesh; 3 % leaves room for the pressure recovery at the quarter model's ends);
    /// the pressure is linear in δ, so halving δ halves it (to 3 % likewise).
    #[test]
    fn interference_fit_pressure_is_lame() {
        let lame = |delta: f64| 2e5 * delta * (1e6 - 2.5e5) / (2.0 * 500.0 * 1e6);
        for delta in [0.6667, 0.33335] {
            let view = solve("interference_fit", &[&format!("contact.fit.gap={}", -delta)]).unwrap();
            assert_eq!(view.summary.status, "converged");
            let p = view.summary.contacts["fit"].max_pressure;
            assert!((p / lame(delta) - 1.0).abs() < 0.03, "p = {p} vs Lamé {}", lame(delta));
        }
    }

    /// Coulomb on the incline (the scene's comment): below F/G = (tan α + μ)/(1 − μ tan α)
    /// = 0.4124 the block holds; with μ = 0.3 and F/G = 0.2 it holds with part of the
    /// interface sticking.
    #[test]
    fn incline_holds_below_the_threshold() {
        let view = solve("incline_push", &["loading.schedule=[{weight = 1.0}, {weight = 1.0, push = 0.2}]"]).unwrap();
        assert_eq!(view.summary.status, "converged");
        assert!(view.pairs.state.contains(&"stick"));
    }

    /// Coulomb on the two blocks (the scene's comment): once the whole interface slips, the
    /// tangential force is μ P = 0.3 × 1000 = 300 per unit thickness. The slip pairs carry
    /// exactly μ λ each, so the sum equals it to round-off of the force balance (1e-9 relative).
    #[test]
    fn two_blocks_slide_at_mu_p() {
        let view = solve("two_blocks_press_slide", &[]).unwrap();
        assert_eq!(view.summary.status, "converged");
        let joint = &view.summary.contacts["joint"];
        assert!((joint.tangential_force.abs() / 300.0 - 1.0).abs() < 1e-9, "Q = {}", joint.tangential_force);
        assert!((joint.normal_force / 1000.0 - 1.0).abs() < 1e-9, "P = {}", joint.normal_force);
    }

    /// Unknown scenes, keys and mesh bytes are typed errors with the CLI's messages.
    #[test]
    fn bad_input_is_an_error() {
        assert!(matches!(solve("nope", &[]), Err(WebError::NoMesh(_))));
        let e = solve("pin_lug", &["contact.bore.friciton=0.3"]).unwrap_err();
        assert!(matches!(e, WebError::Scene(_)) && e.to_string().contains("friciton"), "{e}");
        let bundled = bundled_generic("two_blocks_press_slide").unwrap();
        let e = solve_user_scene("s.toml", bundled.text.as_bytes(), "m.msh", b"not a mesh", &[]).unwrap_err();
        assert!(e.to_string().contains("m.msh"), "{e}");
        let e = solve_user_scene("s.toml", &[0xff, 0xfe], "m.msh", bundled.mesh_bytes, &[]).unwrap_err();
        assert!(e.to_string().contains("not UTF-8"), "{e}");
        let big = vec![b'#'; MAX_SCENE_BYTES as usize + 1];
        let e = solve_user_scene("s.toml", &big, "m.msh", bundled.mesh_bytes, &[]).unwrap_err();
        assert!(e.to_string().contains("exceed the limit"), "{e}");
        let preset = include_str!("../../../scenes/plate_insert_nogap_mu0.toml");
        let e = solve_user_scene("s.toml", preset.as_bytes(), "m.msh", bundled.mesh_bytes, &[]).unwrap_err();
        assert!(e.to_string().contains("not a generic scene"), "{e}");
        // A TOML syntax error gets the CLI's line and column (`contact2d run` on the same text:
        // "line 3, column 9: unclosed table, expected `]`").
        let broken = "name = \"x\"\nmesh = \"a.msh\"\n[loading\nsteps = 2\n";
        let e = solve_user_scene("s.toml", broken.as_bytes(), "m.msh", bundled.mesh_bytes, &[]).unwrap_err();
        assert!(e.to_string().contains("line 3, column 9: unclosed table"), "{e}");
        assert!(!e.to_string().contains("not a generic scene"), "{e}");
    }

    /// A user's scene (the bundled two-blocks text and mesh as if dropped on the page) gives
    /// the bundled path's numbers: one pipeline.
    #[test]
    fn user_scene_equals_bundled() {
        let bundled = bundled_generic("two_blocks_press_slide").unwrap();
        let user =
            solve_user_scene("two_blocks.toml", bundled.text.as_bytes(), "two_blocks.msh", bundled.mesh_bytes, &[])
                .unwrap();
        let same = solve("two_blocks_press_slide", &[]).unwrap();
        assert_eq!(user.pairs, same.pairs);
        assert_eq!(user.mesh, same.mesh);
    }

    /// A user's scene of six steps (press in two, then slide in four) keeps both for the player: the last
    /// frame is the view's last step, and each frame's interface forces are the report's step
    /// rows (computed apart, by the run's own summary), exactly.
    #[test]
    fn user_scene_keeps_every_step() {
        let bundled = bundled_generic("two_blocks_press_slide").unwrap();
        let user =
            solve_user_scene("two_blocks.toml", bundled.text.as_bytes(), "two_blocks.msh", bundled.mesh_bytes, &[])
                .unwrap();
        assert_eq!(user.frames.len(), user.summary.steps.len());
        assert!(user.frames.len() > 1);
        let last = user.frames.last().unwrap();
        assert_eq!(last.displacement, user.mesh.displacement);
        assert_eq!(last.pairs, user.pairs);
        for (frame, row) in user.frames.iter().zip(user.summary.steps.iter()) {
            let (f, r) = (&frame.contacts["joint"], &row.contacts["joint"]);
            assert_eq!((f.normal_force, f.tangential_force), (r.normal_force, r.tangential_force));
            assert!(f.profile.is_some());
        }
        assert!(solve("two_blocks_press_slide", &[]).unwrap().frames.is_empty());
    }
}

//! Writes the native numbers the teaching page's tests compare the WebAssembly module with:
//! each bundled case solved natively from the mesh *files* (`contact2d run`'s path:
//! [`contact2d_pipeline::run::solve_scene`], [`contact2d_pipeline::generic::solve_generic`]), as JSON on stdout:
//!
//! ```text
//! {"flagship": [{"params": {...}, "view": FlagshipView}, ...],
//!  "hertz":    [{"params": {...}, "view": HertzView}, ...],
//!  "cattaneo_mindlin": [{"params": {...}, "view": CattaneoMindlinView}, ...],
//!  "generic": [{"params": {"scene", "overrides"}, "view": GenericView}, ...]}
//! ```
//! `web/tests/wasm_matches_native.mjs` solves the same params in the module (meshes compiled
//! in, parsed from bytes) and requires every number to agree to 1e-12 relative.
//!
//! Usage: `cargo build --release --workspace --bins && target/release/web_reference > web/out/reference.json`
//! (what `web/test.sh` runs: the workspace's features, so that the test build is reused).

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use serde_json::{Value, json};

use contact2d_pipeline::generic::{load_scene, solve_generic};
use contact2d_pipeline::run::solve_scene;
use contact2d_web::bundled::{cattaneo_mindlin_mesh, flagship_mesh, hertz_mesh};
use contact2d_web::cattaneo_mindlin::{CattaneoMindlinParams, cattaneo_mindlin_view};
use contact2d_web::flagship::{FlagshipParams, flagship_view};
use contact2d_web::generic_scene::{GenericParams, bundled_generic, generic_view};
use contact2d_web::hertz::{HertzParams, hertz_view};

/// The flagship cases: the page's default with μ = 0 and μ = 0.3 (the browser test's), the
/// published Table 2 set-ups (clearance, 3 steps, both variants), the first of them without
/// clearance, a stiff insert, N = 32, and one step of a loading history.
fn flagship_cases() -> Vec<Value> {
    let case = |friction: f64, stiffness_ratio: f64, eps: f64, refinement: u32, load: f64, variant: &str| {
        json!({"friction": friction, "stiffness_ratio": stiffness_ratio, "eps": eps,
               "refinement": refinement, "load": load, "variant": variant})
    };
    let mut history = case(0.3, 1.0, 0.05, 16, 0.3838 * 0.4, "hole_master");
    history["steps"] = json!(4);
    vec![
        case(0.0, 1.0, 0.0, 16, 1.0, "hole_master"),
        case(0.3, 1.0, 0.0, 16, 1.0, "hole_master"),
        // The browser test's "ε moved to 0 during a history at the Table 2 U(1) set-up".
        case(0.3, 1.0, 0.0, 16, 0.3838, "hole_master"),
        case(0.3, 1.0, 0.05, 16, 0.3838, "hole_master"),
        case(0.3, 1.0, 0.05, 16, 0.3838, "insert_master"),
        case(0.0, 1.0, 0.05, 16, 0.3838, "insert_master"),
        case(0.3, 4.0, 0.0, 16, 1.0, "insert_master"),
        case(0.3, 1.0, 0.001, 32, 0.3838, "hole_master"),
        case(0.3, 1.0, 0.0, 32, 1.0, "hole_master"),
        history,
    ]
}

/// The Hertz cases: the benchmark's force and about a third of it.
fn hertz_cases() -> Vec<Value> {
    vec![json!({"force": 35000.0, "level": "L1"}), json!({"force": 12000.0, "level": "L1"})]
}

/// The Cattaneo–Mindlin cases: the page's default (the scene's press, shear 0.3: Q/(μP) ≈ 0.5,
/// where the browser test moves the slider to), a lighter press sheared less, and a cycle.
fn cattaneo_mindlin_cases() -> Vec<Value> {
    vec![
        json!({"press": 1.0, "shear": 0.3, "level": "L0"}),
        json!({"press": 0.75, "shear": 0.18, "level": "L0"}),
        // A Mindlin–Deresiewicz cycle as the page runs it (amplitude 0.3: down to −0.3, back up).
        json!({"press": 1.0, "shear": 0.3, "level": "L0", "cycle": cycle_path(0.3)}),
    ]
}

/// The page's Mindlin–Deresiewicz path after the first loading to `amplitude`: ten equal steps
/// down to −amplitude and ten back up (the same rounding as `web/scenes_paper.js`).
fn cycle_path(amplitude: f64) -> Vec<f64> {
    let round = |v: f64| (v * 1e4).round() / 1e4;
    let down = (1..=10).map(|k| round(amplitude - 2.0 * amplitude * f64::from(k) / 10.0));
    let up = (1..=10).map(|k| round(-amplitude + 2.0 * amplitude * f64::from(k) / 10.0));
    down.chain(up).collect()
}

/// The bundled generic scenes: each as the page opens it (its sliders at their defaults, the
/// same override strings as `web/app.js` builds) and once with its sliders moved.
fn generic_cases() -> Vec<Value> {
    let case = |scene: &str, overrides: &[&str]| json!({"scene": scene, "overrides": overrides});
    vec![
        case("pin_lug", &["contact.bore.friction=0.2", "load.pin_back.force=[1000, 0]"]),
        case("pin_lug", &["contact.bore.friction=0.4", "load.pin_back.force=[1500, 0]"]),
        case("interference_fit", &["contact.fit.gap=-0.65", "contact.fit.friction=0"]),
        case("interference_fit", &["contact.fit.gap=-0.3", "contact.fit.friction=0.2"]),
        case(
            "incline_push",
            &["contact.incline.friction=0.3", "loading.schedule=[{weight = 1}, {weight = 1, push = 0.3}]"],
        ),
        case(
            "incline_push",
            &["contact.incline.friction=0.5", "loading.schedule=[{weight = 1}, {weight = 1, push = 0.1}]"],
        ),
        case("ball_on_plate", &["load.ball_top.force=[0, -5000]", "contact.ball.friction=0"]),
        case("ball_on_plate", &["load.ball_top.force=[0, -10000]", "contact.ball.friction=0.2"]),
        case(
            "two_blocks_press_slide",
            &["contact.joint.friction=0.3", "loading.schedule=[{press = 1}, {press = 1, slide = 1}]"],
        ),
        case(
            "two_blocks_press_slide",
            &["contact.joint.friction=0.5", "loading.schedule=[{press = 1}, {press = 1, slide = 0.5}]"],
        ),
    ]
}

fn main() -> anyhow::Result<()> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut flagship = vec![];
    for value in flagship_cases() {
        let params: FlagshipParams = serde_json::from_value(value.clone())?;
        let file = flagship_mesh(params.eps, params.refinement)?.file;
        let scene = params.scene(&format!("../meshes/plate_insert/{file}"), &root.join("scenes/teaching.toml"))?;
        let outcome = solve_scene(&scene).with_context(|| format!("{value}"))?;
        flagship.push(json!({"params": value, "view": flagship_view(&params, file, &outcome)?}));
    }
    let mut hertz = vec![];
    for value in hertz_cases() {
        let params: HertzParams = serde_json::from_value(value.clone())?;
        let file = hertz_mesh(&params.level)?.file;
        let scene_file = root.join("scenes/generic/cylinder_on_block.toml");
        let scene = params.scene(&format!("../../meshes/generic/{file}"), Path::new(&scene_file))?;
        let outcome = solve_generic(&scene, &mut |_, _| {}).with_context(|| format!("{value}"))?;
        hertz.push(json!({"params": value, "view": hertz_view(&params, file, &outcome)}));
    }
    let mut cattaneo_mindlin = vec![];
    for value in cattaneo_mindlin_cases() {
        let params: CattaneoMindlinParams = serde_json::from_value(value.clone())?;
        let file = cattaneo_mindlin_mesh(&params.level)?.file;
        let scene_file = root.join("scenes/generic/cattaneo_mindlin.toml");
        let scene = params.scene(&format!("../../meshes/generic/{file}"), Path::new(&scene_file))?;
        let outcome = solve_generic(&scene, &mut |_, _| {}).with_context(|| format!("{value}"))?;
        cattaneo_mindlin.push(json!({"params": value, "view": cattaneo_mindlin_view(file, &outcome)?}));
    }
    let mut generic = vec![];
    for value in generic_cases() {
        let params: GenericParams = serde_json::from_value(value.clone())?;
        let bundled = bundled_generic(&params.scene)?;
        let mut overrides = vec![format!("mesh=\"../../meshes/generic/{}\"", bundled.mesh_file)];
        overrides.extend(params.overrides.iter().cloned());
        let scene = load_scene(&root.join(format!("scenes/generic/{}.toml", bundled.name)), &overrides)?;
        let outcome = solve_generic(&scene, &mut |_, _| {}).with_context(|| format!("{value}"))?;
        generic.push(json!({"params": value, "view": generic_view(bundled.mesh_file, &outcome)}));
    }
    println!(
        "{}",
        json!({"flagship": flagship, "hertz": hertz, "cattaneo_mindlin": cattaneo_mindlin, "generic": generic})
    );
    Ok(())
}

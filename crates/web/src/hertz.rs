//! The NAFEMS Hertz benchmark on the page: the bundled generic scene
//! `scenes/generic/cylinder_on_block.toml` (a steel roller on an aluminium block, plane strain,
//! frictionless, half model) with the load from a slider, beside its closed form.
//!
//! ```text
//! E* = [(1 − ν1²)/E1 + (1 − ν2²)/E2]⁻¹        (plane strain, two half-spaces)
//! a  = √(4 F R / (π E*))                       half-width of the contact
//! p(x) = p0 √(1 − x²/a²),  p0 = 2 F / (π a)    pressure, |x| ≤ a
//! F: force per unit thickness on the whole roller (the half model carries F/2), R = 50 mm
//! ```
//!
//! # References
//! K. L. Johnson, *Contact Mechanics*, 1985, eqs. (4.43)–(4.45); NAFEMS benchmark via Code_Aster
//! SSNP154 (E1 = 210 GPa, E2 = 70 GPa, ν = 0.3, F = 35 kN/mm: a = 6.21 mm, p0 = 3585 MPa).

use std::path::Path;

use serde::{Deserialize, Serialize};

use contact2d_mesh::parse_msh;
use contact2d_pipeline::generic::{GenericOutcome, GenericReport, GenericScene, solve_generic_on_mesh};

use crate::WebError;
use crate::bundled::{HERTZ_SCENE, hertz_mesh};
use crate::view::{MeshView, PairsView, mesh_view, pairs_view};

/// The roller radius of the bundled Hertz meshes, mm.
pub const ROLLER_RADIUS: f64 = 50.0;

/// The name of the bundled scene's one interface.
const INTERFACE: &str = "hertz";

/// Samples of the closed-form pressure drawn beside the computed profile.
const CLOSED_FORM_SAMPLES: usize = 101;

/// The page's Hertz parameters (the sliders).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HertzParams {
    /// F: force per mm of thickness on the whole roller, N/mm (the scene's is 35 000).
    pub force: f64,
    /// The mesh: "L1" (the one bundled).
    pub level: String,
}

impl HertzParams {
    /// The checked scene: the bundled scene on the bundled mesh `mesh` with F/2 on the half
    /// roller, as if read from `scene_file` (the mesh path is relative to its directory).
    ///
    /// # Errors
    /// [`WebError::Scene`] for a force out of range.
    pub fn scene(&self, mesh: &str, scene_file: &Path) -> Result<GenericScene, WebError> {
        if !(self.force.is_finite() && self.force > 0.0) {
            return Err(WebError::Scene(contact2d_pipeline::scene::SceneError::Value {
                path: scene_file.display().to_string(),
                key: "force".into(),
                reason: format!("F = {} must be finite and > 0", self.force),
            }));
        }
        // Node-to-segment on the page: with segment-to-segment the roller's proximal iterations
        // amplify the one-ulp differences of the platforms' `hypot` (wasm's libm against glibc)
        // to 2.8e-12, past the page's 1e-12 agreement with native; on L1 node-to-segment's
        // profile is within 1.6 % of p0 (docs/verification.md) and agrees to 5e-13.
        let overrides = [
            format!("mesh={mesh:?}"),
            format!("load.cylinder_top.force=[0.0, {:?}]", -0.5 * self.force),
            "contact.hertz.pairing=\"node_to_segment\"".to_string(),
        ];
        Ok(GenericScene::from_toml_str(HERTZ_SCENE, scene_file, &overrides)?)
    }
}

/// The Hertz closed form of a scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HertzClosedForm {
    /// E*, MPa.
    pub e_star: f64,
    /// Half-width a, mm.
    pub a: f64,
    /// Peak pressure p0, MPa.
    pub p0: f64,
    /// x of the samples, 0 ..= a.
    pub x: Vec<f64>,
    /// p(x) at the samples.
    pub pressure: Vec<f64>,
}

impl HertzClosedForm {
    /// The closed form for force `force` (per unit thickness, whole roller) between bodies of
    /// moduli `e` and Poisson's ratios `nu`, roller radius [`ROLLER_RADIUS`].
    pub fn new(force: f64, e: [f64; 2], nu: [f64; 2]) -> HertzClosedForm {
        let e_star = 1.0 / ((1.0 - nu[0] * nu[0]) / e[0] + (1.0 - nu[1] * nu[1]) / e[1]);
        let a = (4.0 * force * ROLLER_RADIUS / (std::f64::consts::PI * e_star)).sqrt();
        let p0 = 2.0 * force / (std::f64::consts::PI * a);
        let x: Vec<f64> = (0..CLOSED_FORM_SAMPLES).map(|i| a * i as f64 / (CLOSED_FORM_SAMPLES - 1) as f64).collect();
        let pressure = x.iter().map(|x| p0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt()).collect();
        HertzClosedForm { e_star, a, p0, x, pressure }
    }
}

/// Everything the page shows of one Hertz solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HertzView {
    /// The bundled mesh file solved on.
    pub mesh_file: String,
    /// The generic summary, as `contact2d run --json` writes it (with the interface's profile:
    /// s, x, pressure, shear, gap, state along the roller).
    pub summary: GenericReport,
    /// The closed form at this force.
    pub closed_form: HertzClosedForm,
    /// The pairs of the last step.
    pub pairs: PairsView,
    /// The deformed mesh of the last step.
    pub mesh: MeshView,
}

/// Solves the Hertz scene on its bundled mesh (the page's path).
///
/// # Errors
/// [`WebError`] for a force out of range, a mesh that is not bundled, or a failed set-up.
pub fn solve_hertz(params: &HertzParams) -> Result<HertzView, WebError> {
    let bundled = hertz_mesh(&params.level)?;
    let scene = params.scene(bundled.file, Path::new("cylinder_on_block.toml"))?;
    let mesh = parse_msh(bundled.bytes)?;
    let outcome = solve_generic_on_mesh(&scene, mesh, &mut |_, _| {})?;
    Ok(hertz_view(params, bundled.file, &outcome))
}

/// The page's view of a solved Hertz scene.
pub fn hertz_view(params: &HertzParams, mesh_file: &str, outcome: &GenericOutcome) -> HertzView {
    let scene = &outcome.scene;
    let e = [scene.body[0].youngs_modulus, scene.body[1].youngs_modulus];
    let nu = [scene.body[0].poissons_ratio, scene.body[1].poissons_ratio];
    let problem = &outcome.built.problem;
    let friction = scene.contact.iter().find(|c| c.name == INTERFACE).map_or(0.0, |c| c.friction);
    let (pairs, mesh) = match outcome.history.steps.last() {
        Some(step) => (pairs_view(problem, &step.solution, friction), mesh_view(problem, &step.solution)),
        None => (
            PairsView::empty(),
            MeshView { points: vec![], edges: vec![], edge_body: vec![], bodies: vec![], displacement: vec![] },
        ),
    };
    HertzView {
        mesh_file: mesh_file.to_string(),
        summary: outcome.report.clone(),
        closed_form: HertzClosedForm::new(params.force, e, nu),
        pairs,
        mesh,
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    /// The benchmark's published closed-form values (Code_Aster SSNP154): a = 6.21 mm,
    /// p0 = 3585 MPa, to their printed digits.
    #[test]
    fn closed_form_reproduces_the_benchmark() {
        let c = HertzClosedForm::new(35_000.0, [210_000.0, 70_000.0], [0.3, 0.3]);
        assert!((c.a - 6.21).abs() < 0.005, "a = {}", c.a);
        assert!((c.p0 - 3585.0).abs() < 1.0, "p0 = {}", c.p0);
        assert_eq!(c.pressure[0], c.p0);
        assert_eq!(*c.pressure.last().unwrap(), 0.0);
    }

    /// The L1 solve's contact half-width lies within 10 % of the closed form's a (the coarse
    /// mesh resolves a to about one element of the contact zone; L3 is within 1 %, see
    /// tests/verification/verify_nafems_hertz.rs); a bad force is a typed error.
    #[test]
    fn coarse_mesh_half_width_near_the_closed_form() {
        let view = solve_hertz(&HertzParams { force: 35_000.0, level: "L1".into() }).unwrap();
        assert_eq!(view.summary.status, "converged");
        let a = view.summary.contacts[INTERFACE].contact_length;
        assert!((a / view.closed_form.a - 1.0).abs() < 0.1, "a = {a} vs {}", view.closed_form.a);
        assert!(matches!(solve_hertz(&HertzParams { force: -1.0, level: "L1".into() }), Err(WebError::Scene(_))));
        assert!(matches!(solve_hertz(&HertzParams { force: 1.0, level: "L9".into() }), Err(WebError::NoMesh(_))));
    }
}

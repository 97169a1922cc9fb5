//! The flagship on the page: the plate with an insert (Solodovnikov 1998) on a bundled teaching
//! mesh, set up as the bundled scene `scenes/plate_insert_nogap_mu03.toml` with `--set`
//! overrides from the sliders, and solved by the facade's own run
//! ([`contact2d_pipeline::run::solve_scene_on_mesh`], the same code as `contact2d run`).
//!
//! ```text
//! sliders: μ, E2/E1, ε (picks the bundled mesh), w, pairing variant, N (16 or 32)
//! clearance  c = ω ε with ω = 20: the paper's Table 2 scaling (c = 1 at ε = 0.05)
//! gap        the paper's model u_ρc = −c(1 + cos φ)/ρ_s (variant 1), −c(1 + cos φ̂) (variant 2)
//! steps      3 equal load steps with clearance and friction (the paper's Table 2 history),
//!            else 1 (without clearance the solution is linear in w and solved once)
//! algorithm  primal-dual active set, at most 100 iterations (as the bundled scenes)
//! ```
//! A set-up that equals a bundled published scene's but for the mesh refinement is that
//! published case: its values from [`contact2d_pipeline::plate_insert::published`] are returned beside
//! the live ones.

use std::path::Path;

use serde::{Deserialize, Serialize};

use contact2d_mesh::parse_msh;
use contact2d_pipeline::generic::GenericReport;
use contact2d_pipeline::plate_insert::outputs::profiles::{ProfileRow, contour_profiles};
use contact2d_pipeline::plate_insert::published::{PUBLISHED, PublishedCase};
use contact2d_pipeline::plate_insert::scene::{PlateInsertScene, VariantKey};
use contact2d_pipeline::run::{RunOutcome, Silent, solve_scene_on_mesh};

use crate::WebError;
use crate::bundled::{PUBLISHED_SCENES, flagship_mesh};
use crate::view::{MeshView, PairsView, mesh_view, pairs_view};

/// The bundled scene the page's set-ups override: the paper's neat fit with friction (the
/// defaults every slider leaves alone — ν = 0.3, the paper's gap model, the active set with at
/// most 100 iterations — are this file's).
pub const BASE_SCENE: &str = include_str!("../../../scenes/plate_insert_nogap_mu03.toml");

/// ω = c / ε of the page: the paper's Table 2 has c = 1 at ε = 0.05.
pub const CLEARANCE_PER_EPS: f64 = 20.0;

/// The page's flagship parameters (the sliders).
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FlagshipParams {
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// E2 / E1.
    pub stiffness_ratio: f64,
    /// ε of the mesh: one of [`crate::bundled::FLAGSHIP_EPS`].
    pub eps: f64,
    /// N of the mesh: 16 or 32.
    pub refinement: u32,
    /// The load w (pulled-edge displacement).
    pub load: f64,
    /// `hole_master` (variant 1) or `insert_master` (variant 2).
    pub variant: VariantKey,
    /// Equal load steps from 0 to w (default: 3 with clearance and friction, else 1).
    #[serde(default)]
    pub steps: Option<usize>,
}

impl FlagshipParams {
    /// c = ω ε.
    pub fn clearance(&self) -> f64 {
        CLEARANCE_PER_EPS * self.eps
    }

    /// The load steps: as given, else 3 with clearance and friction, else 1.
    pub fn steps(&self) -> usize {
        self.steps.unwrap_or(if self.clearance() > 0.0 && self.friction > 0.0 { 3 } else { 1 })
    }

    /// The `--set` overrides of these parameters on the mesh file `mesh`, applied to the bundled
    /// scene [`BASE_SCENE`] (numbers in Rust's shortest round-trip spelling, so the scene holds
    /// exactly these values): the page's set-up is that scene file with `contact2d run --set ...`.
    pub fn overrides(&self, mesh: &str) -> Vec<String> {
        let variant = match self.variant {
            VariantKey::HoleMaster => "hole_master",
            VariantKey::InsertMaster => "insert_master",
        };
        vec![
            "name=\"teaching\"".into(),
            "description=\"the teaching page's set-up\"".into(),
            format!("plate_insert.mesh={mesh:?}"),
            format!("plate_insert.variant=\"{variant}\""),
            format!("plate_insert.stiffness_ratio={:?}", self.stiffness_ratio),
            format!("plate_insert.eps={:?}", self.eps),
            format!("plate_insert.clearance={:?}", self.clearance()),
            format!("plate_insert.friction={:?}", self.friction),
            format!("plate_insert.load={:?}", self.load),
            format!("plate_insert.steps={}", self.steps()),
        ]
    }

    /// The checked scene of these parameters on the mesh file `mesh`, as if read from
    /// `scene_file` (the mesh path is relative to its directory): [`BASE_SCENE`] with
    /// [`FlagshipParams::overrides`], through the scene files' one override engine and checks.
    ///
    /// # Errors
    /// [`WebError::Scene`] for a value out of range (the scene file's own checks).
    pub fn scene(&self, mesh: &str, scene_file: &Path) -> Result<PlateInsertScene, WebError> {
        Ok(PlateInsertScene::from_toml_str(BASE_SCENE, scene_file, &self.overrides(mesh))?)
    }

    /// The published case these parameters set up (any refinement), if any.
    pub fn published(&self) -> Option<&'static PublishedCase> {
        let scene = self.scene("m.msh", Path::new("teaching.toml")).ok()?;
        let p = &scene.plate_insert;
        PUBLISHED_SCENES.iter().find_map(|(name, text)| {
            let q = PlateInsertScene::from_toml_str(text, Path::new("scenes/published.toml"), &[]).ok()?.plate_insert;
            let same = (p.variant, p.stiffness_ratio, p.eps, p.clearance, p.friction, p.load, p.steps)
                == (q.variant, q.stiffness_ratio, q.eps, q.clearance, q.friction, q.load, q.steps)
                && (p.gap, p.poissons_ratio, p.rigid_insert, p.pairs)
                    == (q.gap, q.poissons_ratio, q.rigid_insert, q.pairs);
            if same { PUBLISHED.iter().find(|c| c.scene == *name) } else { None }
        })
    }
}

/// A contour's profile along its arc, node by node from φ = 0 (η = 1) to φ = π (η = 0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContourView {
    /// η = 1 − angle/π.
    pub eta: Vec<f64>,
    /// Arc length from η = 0 (the point where the plate bears on the insert): s = r π η.
    pub s: Vec<f64>,
    /// Hoop stress (empty on a rigid insert).
    pub hoop: Vec<f64>,
    /// Normal traction in the paper's sign (p < 0 in compression on the hole edge; p̂ = s_ρρ on
    /// the insert edge); `null` at nodes without a pair.
    pub p: Vec<Option<f64>>,
    /// Tangential traction (q, q̂); `null` at nodes without a pair.
    pub q: Vec<Option<f64>>,
    /// The state of the node's pair (`none` without a pair).
    pub state: Vec<&'static str>,
}

/// A published case's values, in the paper's column order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PublishedView {
    /// The bundled scene that sets the case up.
    pub scene: &'static str,
    /// The paper's label.
    pub label: &'static str,
    /// (quantity name, published value); names as in the summary (`sigma*` is `sigma_star`).
    pub values: Vec<(&'static str, f64)>,
}

/// Everything the page shows of one flagship solve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlagshipView {
    /// The bundled mesh file solved on.
    pub mesh_file: String,
    /// c = ω ε.
    pub clearance: f64,
    /// The summary, as `contact2d run --json` writes it (status, steps, the interface's profile,
    /// reactions ..., and the paper's l, b, P, Φ, σ*, K under `paper`).
    pub summary: GenericReport,
    /// The published case these parameters set up, if any.
    pub published: Option<PublishedView>,
    /// The hole edge Γ_p.
    pub hole: ContourView,
    /// The insert edge Γ_c.
    pub insert: ContourView,
    /// The pairs of the last step.
    pub pairs: PairsView,
    /// The deformed mesh of the last step.
    pub mesh: MeshView,
}

/// Solves the flagship on its bundled mesh (the page's path).
///
/// # Errors
/// [`WebError`] for parameters out of range, a mesh that is not bundled, or a failed set-up.
pub fn solve_flagship(params: &FlagshipParams) -> Result<FlagshipView, WebError> {
    let bundled = flagship_mesh(params.eps, params.refinement)?;
    let scene = params.scene(bundled.file, Path::new("teaching.toml"))?;
    let mesh = parse_msh(bundled.bytes)?;
    let outcome = solve_scene_on_mesh(&scene, mesh, &mut Silent)?;
    flagship_view(params, bundled.file, &outcome)
}

/// The page's view of a solved flagship run.
///
/// # Errors
/// [`WebError::Solve`] when the stresses along the contours cannot be recovered.
pub fn flagship_view(params: &FlagshipParams, mesh_file: &str, outcome: &RunOutcome) -> Result<FlagshipView, WebError> {
    let last = outcome.steps.last().ok_or_else(|| WebError::Solve("the run has no solved step".into()))?;
    let profiles = contour_profiles(last).map_err(|e| WebError::Solve(e.to_string()))?;
    let friction = params.friction;
    let contour = |rows: &[ProfileRow], radius: f64| ContourView {
        eta: rows.iter().map(|r| r.eta).collect(),
        s: rows.iter().map(|r| radius * std::f64::consts::PI * r.eta).collect(),
        hoop: rows.iter().filter_map(|r| r.hoop_stress).collect(),
        p: rows.iter().map(|r| r.contact.map(|c| c.pressure)).collect(),
        q: rows.iter().map(|r| r.contact.map(|c| c.shear)).collect(),
        state: rows
            .iter()
            .map(|r| {
                r.contact.map_or("none", |c| contact2d_pipeline::output::step_view::state_label(c.state, friction))
            })
            .collect(),
    };
    let problem = &last.case.problem;
    Ok(FlagshipView {
        mesh_file: mesh_file.to_string(),
        clearance: params.clearance(),
        summary: outcome.report.clone(),
        published: params.published().map(|c| PublishedView {
            scene: c.scene,
            label: c.label,
            values: c
                .quantities()
                .into_iter()
                .map(|(k, v)| (if k == "sigma*" { "sigma_star" } else { k }, v))
                .collect(),
        }),
        hole: contour(&profiles.hole, 1.0),
        insert: contour(&profiles.insert, 1.0 - last.case.eps),
        pairs: pairs_view(problem, &last.solution, friction),
        mesh: mesh_view(problem, &last.solution),
    })
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    fn params(friction: f64, eps: f64) -> FlagshipParams {
        FlagshipParams {
            friction,
            stiffness_ratio: 1.0,
            eps,
            refinement: 16,
            load: if eps == 0.0 { 1.0 } else { 0.3838 },
            variant: VariantKey::HoleMaster,
            steps: None,
        }
    }

    /// The sliders on a published set-up name that case; off it, none.
    #[test]
    fn published_cases_are_recognised_from_the_bundled_scenes() {
        assert_eq!(params(0.3, 0.0).published().unwrap().scene, "plate_insert_nogap_mu03");
        assert_eq!(params(0.0, 0.0).published().unwrap().scene, "plate_insert_nogap_mu0");
        assert_eq!(params(0.3, 0.05).published().unwrap().scene, "plate_insert_gap_v1_mu03");
        let v2 = FlagshipParams { variant: VariantKey::InsertMaster, ..params(0.0, 0.05) };
        assert_eq!(v2.published().unwrap().scene, "plate_insert_gap_v2_mu0");
        assert!(params(0.2, 0.0).published().is_none());
        assert!(FlagshipParams { stiffness_ratio: 2.0, ..params(0.3, 0.0) }.published().is_none());
    }

    /// Out-of-range values are the scene file's typed errors, never a panic.
    #[test]
    fn bad_parameters_are_errors() {
        assert!(matches!(solve_flagship(&params(-0.1, 0.0)), Err(WebError::Scene(_))));
        assert!(matches!(
            solve_flagship(&FlagshipParams { load: f64::NAN, ..params(0.0, 0.0) }),
            Err(WebError::Scene(_))
        ));
        assert!(matches!(solve_flagship(&params(0.0, 0.3)), Err(WebError::NoMesh(_))));
    }

    /// Friction grows a stick zone: at μ = 0 every pair in contact is `contact`, at μ = 0.3
    /// some stick and b < l (the no-gap case of spec §7); the hoop stress along the hole edge
    /// peaks at σ* of the summary.
    #[test]
    fn friction_makes_a_stick_zone() {
        let free = solve_flagship(&params(0.0, 0.0)).unwrap();
        assert!(free.pairs.state.iter().all(|s| *s == "contact" || *s == "free"));
        let rough = solve_flagship(&params(0.3, 0.0)).unwrap();
        assert!(rough.pairs.state.contains(&"stick"));
        let paper = &rough.summary.post["paper"];
        let (l, b) = (paper["l"].as_f64().unwrap(), paper["b"].as_f64().unwrap());
        assert!(0.0 < b && b < l, "b = {b}, l = {l}");
        let peak = rough.hole.hoop.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(Some(peak), paper["sigma_star"].as_f64());
        assert_eq!(rough.mesh.displacement.len(), rough.mesh.points.len());
    }
}

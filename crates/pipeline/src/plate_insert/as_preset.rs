//! The plate with an insert as a registered preset ([`crate::preset`]): its section, its run
//! through the one pipeline, its `paper` block's text lines and files, and what the studies read
//! of it.
//!
//! ```text
//!                 the paper's case
//! pairings        plate_insert.pairs = node_to_node, node_to_segment
//! mesh key        plate_insert.mesh
//! meshes          its *_N16, *_N32, *_N64 siblings (those that exist)
//! quantities      P, l, b (with friction), Phi_E1, Phi_E2, sigma_star
//! sweep columns   l, b, P, Phi_E1, Phi_E2, Phi_f, W, sigma_star, K, insert_hoop_max
//! sweep plots     l, b, P
//! published       Solodovnikov (1998) for the bundled scenes
//! ```

use std::path::{Path, PathBuf};

use contact2d_contact::{ContactError, ContactSolution};
use web_time::Instant;

use crate::generic::{GenericError, GenericReport, Progress};
#[cfg(feature = "native")]
use crate::output::{OutputDir, OutputError};
use crate::plate_insert::PlateInsertScene;
use crate::plate_insert::published::published_case;
use crate::plate_insert::report::PaperReport;
use crate::plate_insert::run::{RunOutcome, solve_scene_with};
use crate::preset::{Preset, PresetOutcome, PresetScene};
use crate::schema::SceneError;

/// The paper's preset: scenes with a `[plate_insert]` section.
pub const PRESET: Preset = Preset { section: "plate_insert", read };

fn read(text: &str, path: &Path, sets: &[String]) -> Result<Box<dyn PresetScene>, SceneError> {
    Ok(Box::new(PlateInsertScene::from_toml_str(text, path, sets)?))
}

/// A solved plate-insert scene: its section (its files need it) and its run.
#[derive(Debug)]
pub struct PlateInsertOutcome {
    /// The scene as solved.
    pub scene: PlateInsertScene,
    /// The run: the summary with the `paper` block, and the solved steps.
    pub run: RunOutcome,
}

impl PresetScene for PlateInsertScene {
    fn clone_box(&self) -> Box<dyn PresetScene> {
        Box::new(self.clone())
    }

    fn name(&self) -> &str {
        &self.name
    }

    fn file(&self) -> &Path {
        &self.file
    }

    fn mesh_path(&self) -> PathBuf {
        PlateInsertScene::mesh_path(self)
    }

    fn set_every_profile(&mut self, every: bool) {
        self.every_profile = every;
    }

    fn set_moment_centre(&mut self, centre: [f64; 2]) {
        self.moment_centre = centre;
    }

    fn check_mesh_file(&self) -> Result<(), SceneError> {
        PlateInsertScene::check_mesh_file(self)
    }

    /// The paper's run in the order the CLI has always checked it: the mesh file, its geometry
    /// against the section (ε, the groups), then the solve; every failure names both files.
    fn solve(
        &self,
        deadline: Option<Instant>,
        progress: &mut dyn Progress,
    ) -> Result<Box<dyn PresetOutcome>, GenericError> {
        let scene = PlateInsertScene { deadline: deadline.or(self.deadline), ..self.clone() };
        scene.check_mesh_file()?;
        let (file, mesh_path) = (scene.file.display().to_string(), scene.mesh_path());
        let mesh_name = mesh_path.display().to_string();
        let mesh = contact2d_mesh::read_msh(&mesh_path).map_err(|source| GenericError::Mesh {
            scene: file.clone(),
            mesh: mesh_name.clone(),
            source,
        })?;
        scene.check_mesh_geometry(&mesh)?;
        let contact = |source: ContactError| GenericError::Contact {
            scene: file.clone(),
            mesh: mesh_name.clone(),
            source: Box::new(source),
        };
        let run = solve_scene_with(&scene, progress).map_err(contact)?;
        Ok(Box::new(PlateInsertOutcome { scene, run }))
    }

    fn mesh_key(&self) -> &'static str {
        "plate_insert.mesh"
    }

    fn mesh_levels(&self) -> Vec<PathBuf> {
        let own = PlateInsertScene::mesh_path(self);
        let name = own.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let Some((stem, _)) = name.rsplit_once("_N") else { return vec![] };
        ["16", "32", "64"]
            .iter()
            .map(|n| own.with_file_name(format!("{stem}_N{n}.msh")))
            .filter(|p| p.is_file())
            // Absolute: a mesh override is resolved against the scene's directory.
            .map(|p| std::path::absolute(&p).unwrap_or(p))
            .collect()
    }

    fn pairings(&self) -> Vec<(&'static str, Vec<String>)> {
        ["node_to_node", "node_to_segment"].into_iter().map(|p| (p, vec![format!("plate_insert.pairs={p}")])).collect()
    }

    fn quantities(&self) -> Vec<String> {
        let mut q: Vec<String> = ["P", "l"].map(String::from).to_vec();
        if self.plate_insert.friction > 0.0 {
            q.push("b".into());
        }
        q.extend(["Phi_E1", "Phi_E2", "sigma_star"].map(String::from));
        q
    }

    fn sweep_columns(&self) -> Vec<String> {
        ["l", "b", "P", "Phi_E1", "Phi_E2", "Phi_f", "W", "sigma_star", "K", "insert_hoop_max"]
            .map(String::from)
            .to_vec()
    }

    fn sweep_plots(&self) -> Vec<String> {
        ["l", "b", "P"].map(String::from).to_vec()
    }

    fn published(&self) -> Vec<(String, f64)> {
        let Some(case) = published_case(&self.name) else { return vec![] };
        let compared = self.quantities();
        case.quantities()
            .into_iter()
            .filter(|(q, _)| compared.iter().any(|c| c == q))
            .map(|(q, v)| (q.into(), v))
            .collect()
    }
}

impl PresetOutcome for PlateInsertOutcome {
    fn report(&self) -> &GenericReport {
        &self.run.report
    }

    fn summary_lines(&self) -> Vec<String> {
        paper_lines(&self.run.paper)
    }

    fn iteration_logs(&self) -> Vec<(String, &ContactSolution)> {
        let steps = self.run.steps.iter().enumerate();
        steps.map(|(i, s)| (format!("step {}: w = {:.6}", i + 1, s.solution.load_factor), &s.solution)).collect()
    }

    fn steps(&self) -> Vec<(&contact2d_fem::Model, &ContactSolution)> {
        self.run.steps.iter().map(|s| (&s.case.built.problem.model, &s.solution)).collect()
    }

    #[cfg(feature = "native")]
    fn write_outputs_into(&self, folder: OutputDir) -> Result<Vec<PathBuf>, OutputError> {
        crate::plate_insert::outputs::write_outputs_into(folder, &self.scene, &self.run)
    }
}

/// The paper's quantities as lines of the text summary.
fn paper_lines(r: &PaperReport) -> Vec<String> {
    let opt = |v: Option<f64>| v.map_or("-".to_string(), |x| format!("{x:.4}"));
    // Where a zone end sits: a node placed there, or between two nodes (then interpolated).
    let bracket = |b: Option<[f64; 2]>| match b {
        Some([lo, hi]) if lo == hi => "node placed there".to_string(),
        Some([lo, hi]) => format!("between nodes at {lo:.5} and {hi:.5}"),
        None => "no transition".to_string(),
    };
    let mut lines = vec![
        format!("  w      = {}   mu = {}", r.w, r.mu),
        format!("  l      = {}   ({}; master's own {})", opt(r.l), bracket(r.l_bracket), opt(r.l_master)),
        format!("  b      = {}   ({})", opt(r.b), bracket(r.b_bracket)),
        format!("  P      = {:.5}   W = {:.6}", r.P, r.W),
        format!("  Phi_E1 = {:.6}   Phi_E2 = {:.6}   Phi_f = {:.6}", r.Phi_E1, r.Phi_E2, r.Phi_f),
        format!("  sigma* = {:.4}   K = {:.3}", r.sigma_star, r.K),
    ];
    lines.extend(
        r.violations
            .iter()
            .map(|v| format!("  violated at step {}, pair {} (η = {:.4}): {}", v.step, v.pair, v.eta, v.condition)),
    );
    lines
}

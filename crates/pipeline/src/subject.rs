//! What the studies (`compare`, `sweep`) read of a scene ([`Scene`]): a generic scene, or a
//! preset's (its [`crate::preset::PresetScene`] answers; the paper's case in
//! `crate::plate_insert::as_preset`), behind one interface — its pairings, its quantities, its
//! mesh levels, its published references and one run as the JSON summary — so that the tables,
//! the references and the figures are the same code for every scene.
//!
//! ```text
//!                 generic scene                        a preset's scene
//! pairings        contact.<i>.pairing = every Pairing  the preset's (paper: plate_insert.pairs)
//! mesh key        mesh                                 the preset's (paper: plate_insert.mesh)
//! meshes          the scene's own                      the preset's levels (paper: *_N16, *_N32, *_N64)
//! quantities      contacts.<c>.max_pressure,           the preset's (paper: P, l, b, Phi_E1, ...)
//! (compare)       contact_length, tangential_force
//!                 (μ > 0), energy
//! sweep columns   contacts.<c>.normal_force,            the preset's
//!                 contacts.<c>.contact_length
//! sweep plots     the sweep columns                     the preset's (paper: l, b, P)
//! published       —                                    the preset's (paper: Solodovnikov 1998)
//! ```

use std::path::{Path, PathBuf};

use contact2d_contact::{ContactError, Pairing};
use serde_json::Value;

use crate::generic::{GenericError, GenericReport, Silent};
use crate::scene::Scene;

/// One run as `compare` reads it.
#[derive(Debug, Clone)]
pub struct RunSummary {
    /// The JSON summary (quantities are dotted paths into it).
    pub json: Value,
    /// Whole-run and contact-solve wall time, seconds.
    pub times: (f64, f64),
    /// The status and, for one that is not `converged`, its failed check.
    pub status: (String, Option<String>),
    /// Iterations summed over the steps.
    pub iterations: usize,
    /// Contact pairs.
    pub pairs: usize,
    /// Largest penetration, complementarity and cone violation.
    pub kkt: [f64; 3],
}

/// Why a run gave no summary.
#[derive(Debug, thiserror::Error)]
pub enum RunFailure {
    /// The deadline passed (the message says where).
    #[error("{0}")]
    TimedOut(String),
    /// Refused or failed (the library's message).
    #[error("{0}")]
    Failed(String),
}

impl Scene {
    /// The mesh levels to run when none are given: the scene's own mesh (`None`), or a preset's
    /// levels (the paper's case: the N = 16, 32, 64 meshes beside it that exist).
    pub fn default_meshes(&self) -> Vec<Option<PathBuf>> {
        let levels: Vec<Option<PathBuf>> = match self {
            Scene::Generic(_) => vec![],
            Scene::Preset(s) => s.mesh_levels().into_iter().map(Some).collect(),
        };
        if levels.is_empty() { vec![None] } else { levels }
    }

    /// The override that sets the mesh.
    pub fn mesh_override(&self, mesh: &Path) -> String {
        let key = match self {
            Scene::Generic(_) => "mesh",
            Scene::Preset(s) => s.mesh_key(),
        };
        format!("{key}={}", toml::Value::String(mesh.display().to_string()))
    }

    /// The pairings to run, each as its key and the overrides that select it.
    pub fn pairings(&self) -> Vec<(&'static str, Vec<String>)> {
        match self {
            Scene::Generic(s) => Pairing::ALL
                .iter()
                .map(|p| (p.key(), (0..s.contact.len()).map(|i| format!("contact.{i}.pairing={}", p.key())).collect()))
                .collect(),
            Scene::Preset(s) => s.pairings(),
        }
    }

    /// The quantities compared (dotted paths into the JSON summary, or `energy`).
    pub fn quantities(&self) -> Vec<String> {
        match self {
            Scene::Generic(s) => {
                let mut q = vec![];
                for c in &s.contact {
                    q.push(format!("contacts.{}.max_pressure", c.name));
                    q.push(format!("contacts.{}.contact_length", c.name));
                    if c.friction > 0.0 {
                        q.push(format!("contacts.{}.tangential_force", c.name));
                    }
                }
                q.push("energy".into());
                q
            }
            Scene::Preset(s) => s.quantities(),
        }
    }

    /// The columns a sweep tabulates: each interface's normal force and contact length, or the
    /// preset's quantities.
    pub fn sweep_columns(&self) -> Vec<String> {
        match self {
            Scene::Generic(s) => s
                .contact
                .iter()
                .flat_map(|c| {
                    [format!("contacts.{}.normal_force", c.name), format!("contacts.{}.contact_length", c.name)]
                })
                .collect(),
            Scene::Preset(s) => s.sweep_columns(),
        }
    }

    /// The quantities a sweep plots by default: its columns, or the preset's choice (the
    /// paper's l, b and P).
    pub fn sweep_plots(&self) -> Vec<String> {
        match self {
            Scene::Generic(_) => self.sweep_columns(),
            Scene::Preset(s) => s.sweep_plots(),
        }
    }

    /// The published values of the scene's quantities (the paper's bundled cases), as
    /// `(quantity, value)`; empty for a generic scene or a case no source gives.
    pub fn published(&self) -> Vec<(String, f64)> {
        match self {
            Scene::Generic(_) => vec![],
            Scene::Preset(s) => s.published(),
        }
    }

    /// One run, with a wall-clock deadline checked before each load step if given.
    ///
    /// # Errors
    /// [`RunFailure`] with the library's message.
    pub fn run(&self, deadline: Option<web_time::Instant>) -> Result<RunSummary, RunFailure> {
        match self.solve(deadline, &mut Silent) {
            Ok(outcome) => Ok(RunSummary::of(outcome.report())),
            Err(GenericError::Contact { source, .. }) if matches!(*source, ContactError::DeadlineExceeded { .. }) => {
                Err(RunFailure::TimedOut(source.to_string()))
            }
            Err(e) => Err(RunFailure::Failed(e.to_string())),
        }
    }
}

impl RunSummary {
    /// What a study reads of a run's summary (the one JSON contract of every scene).
    fn of(r: &GenericReport) -> RunSummary {
        RunSummary {
            json: serde_json::to_value(r).unwrap_or(Value::Null),
            times: (r.time_s.total, r.time_s.solve),
            status: (r.status.to_string(), r.failed_check.clone()),
            iterations: r.iterations,
            pairs: r.pairs,
            kkt: [r.kkt.max_penetration, r.kkt.max_complementarity, r.kkt.max_cone_violation],
        }
    }
}

/// The number at a dotted path of a JSON summary (`contacts.hertz.normal_force`,
/// `reactions.block_bottom.1`, `paper.P`), or `energy`: the sum of the bodies' strain energies;
/// `None` if there is none. A path that names nothing at the top level is looked up in the
/// preset's block, so the paper's quantities keep their names (`P` is `paper.P`).
pub fn quantity(summary: &Value, path: &str) -> Option<f64> {
    if path == "energy" {
        return summary.get("energies")?.as_object().map(|m| m.values().filter_map(Value::as_f64).sum());
    }
    at_path(summary, path).or_else(|| at_path(summary.get(crate::plate_insert::report::BLOCK)?, path))
}

/// The number at a dotted path.
fn at_path(summary: &Value, path: &str) -> Option<f64> {
    path.split('.')
        .try_fold(summary, |v, part| match v {
            Value::Array(items) => part.parse::<usize>().ok().and_then(|i| items.get(i)),
            _ => v.get(part),
        })
        .and_then(Value::as_f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantities_are_dotted_paths_and_energy_is_the_sum() {
        let json: Value = serde_json::json!({
            "contacts": {"c": {"max_pressure": 3.0}},
            "energies": {"a": 1.0, "b": 2.5},
            "reactions": {"b": [1.0, -3.0]}
        });
        assert_eq!(quantity(&json, "contacts.c.max_pressure"), Some(3.0));
        assert_eq!(quantity(&json, "energy"), Some(3.5));
        assert_eq!(quantity(&json, "reactions.b.1"), Some(-3.0));
        assert_eq!(quantity(&json, "reactions.b.2"), None);
        assert_eq!(quantity(&json, "contacts.nope"), None);
        let paper: Value = serde_json::json!({"status": "converged", "paper": {"P": 0.2, "steps": [{"l": 0.4}]}});
        assert_eq!(quantity(&paper, "P"), Some(0.2));
        assert_eq!(quantity(&paper, "paper.steps.0.l"), Some(0.4));
    }
}

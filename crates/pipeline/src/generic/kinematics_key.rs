//! The scene's kinematics: which 2D reduction of 3D elasticity its bodies stand for.
//!
//! ```toml
//! kinematics = "axisymmetric"   # or "plane_stress", "plane_strain"; x is r ≥ 0, y is z
//! ```
//!
//! Without `kinematics`, `plane = "stress" | "strain"` (scene-wide, or per body) chooses the plane
//! condition as it always has, with `thickness` per body (default 1). A body of revolution has no
//! thickness and no plane condition: its forces, reactions and contact resultants are totals over
//! the circumference, and its axis nodes hold `u_r = 0` ([`contact2d_fem::Model::fix_axis_nodes`]).
//! A moment or a rotation has no meaning about the axis of a body loaded without twist, so both
//! are refused, naming the key.

use contact2d_element::{Kinematics, PlaneCondition};
use serde::Deserialize;

use super::scene::{BodyEntry, GenericScene};
use crate::schema::SceneError;

/// The kinematics as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum KinematicsKey {
    /// Plane stress (σ33 = 0), thickness per body.
    PlaneStress,
    /// Plane strain (ε33 = 0), thickness per body.
    PlaneStrain,
    /// A body of revolution about the y axis.
    Axisymmetric,
}

impl KinematicsKey {
    /// The plane condition it names, `None` for a body of revolution.
    fn plane(self) -> Option<PlaneCondition> {
        match self {
            KinematicsKey::PlaneStress => Some(PlaneCondition::Stress),
            KinematicsKey::PlaneStrain => Some(PlaneCondition::Strain),
            KinematicsKey::Axisymmetric => None,
        }
    }
}

impl GenericScene {
    /// Whether the scene's bodies are bodies of revolution.
    pub fn is_axisymmetric(&self) -> bool {
        self.kinematics == Some(KinematicsKey::Axisymmetric)
    }

    /// The plane condition of body `b` (its own `plane`, else the scene's, else the one
    /// `kinematics` names, else plane stress); plane strain for a body of revolution, whose
    /// in-plane block is the plane-strain matrix.
    pub fn body_plane(&self, b: &BodyEntry) -> PlaneCondition {
        b.plane
            .or(self.plane)
            .map(|p| p.condition())
            .or_else(|| self.kinematics.map(|k| k.plane().unwrap_or(PlaneCondition::Strain)))
            .unwrap_or(PlaneCondition::Stress)
    }

    /// The [`Kinematics`] of body `b` (a validated scene: the thickness is positive).
    pub fn body_kinematics(&self, b: &BodyEntry) -> Kinematics {
        if self.is_axisymmetric() {
            return Kinematics::Axisymmetric;
        }
        let thickness = b.thickness.unwrap_or(1.0);
        match self.body_plane(b) {
            PlaneCondition::Stress => Kinematics::PlaneStress { thickness },
            PlaneCondition::Strain => Kinematics::PlaneStrain { thickness },
        }
    }

    /// Keys that contradict the kinematics, or have no meaning in it.
    ///
    /// # Errors
    /// [`SceneError::Value`] naming the key.
    pub(super) fn validate_kinematics(&self) -> Result<(), SceneError> {
        for (i, b) in self.body.iter().enumerate() {
            if let Some(t) = b.thickness
                && !(t.is_finite() && t > 0.0)
            {
                return Err(self.fail(&format!("body.{i}.thickness"), format!("{t} must be finite and > 0")));
            }
        }
        let Some(key) = self.kinematics else { return Ok(()) };
        let Some(plane) = key.plane() else { return self.validate_revolution() };
        let named = |p: Option<super::scene::PlaneKey>| p.is_some_and(|p| p.condition() != plane);
        if named(self.plane) {
            return Err(self.fail("plane", "contradicts kinematics; give one of the two".into()));
        }
        if let Some(i) = self.body.iter().position(|b| named(b.plane)) {
            return Err(self.fail(&format!("body.{i}.plane"), "contradicts the scene's kinematics".into()));
        }
        Ok(())
    }

    /// A body of revolution has no thickness, plane condition, moment or rotation.
    fn validate_revolution(&self) -> Result<(), SceneError> {
        let why = "has no meaning with kinematics = \"axisymmetric\"";
        if self.plane.is_some() {
            return Err(self.fail("plane", format!("{why} (a body of revolution is neither plane stress nor strain)")));
        }
        for (i, b) in self.body.iter().enumerate() {
            if b.thickness.is_some() {
                return Err(self
                    .fail(&format!("body.{i}.thickness"), format!("{why}: forces are totals over the circumference")));
            }
            if b.plane.is_some() {
                return Err(self.fail(&format!("body.{i}.plane"), why.into()));
            }
        }
        if let Some(i) = self.load.iter().position(|l| l.moment.is_some()) {
            return Err(self.fail(
                &format!("load.{i}.moment"),
                format!("{why}: a body of revolution loaded without twist carries no moment about its axis"),
            ));
        }
        if let Some(i) = self.fix.iter().position(|f| f.rotation.is_some()) {
            return Err(self.fail(
                &format!("fix.{i}.rotation"),
                format!("{why}: a body of revolution moves rigidly only along its axis"),
            ));
        }
        Ok(())
    }
}

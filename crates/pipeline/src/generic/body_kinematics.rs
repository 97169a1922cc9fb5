//! What each body of a scene stands for: its plane condition or a body of revolution, from the
//! scene's `kinematics` and `plane` keys ([`super::kinematics_key`]), and the checks that refuse
//! what a body of revolution cannot carry (thickness, a plane, a moment or a rotation, r < 0).
//!
//! ```text
//! kinematics = axisymmetric            → Kinematics::Axisymmetric (every body)
//! body.plane, else scene plane, else the kinematics' plane, else plane stress
//!                                       → Kinematics::PlaneStress/PlaneStrain { thickness (default 1) }
//! ```

use contact2d_element::{Kinematics, PlaneCondition};

use super::kinematics_key::KinematicsKey;
use super::scene::{BodyEntry, GenericScene};
use crate::schema::SceneError;

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
        let named = |p: Option<super::kinematics_key::PlaneKey>| p.is_some_and(|p| p.condition() != plane);
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

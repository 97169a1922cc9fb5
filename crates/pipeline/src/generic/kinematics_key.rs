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

use contact2d_element::PlaneCondition;
use serde::Deserialize;

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
    pub(super) fn plane(self) -> Option<PlaneCondition> {
        match self {
            KinematicsKey::PlaneStress => Some(PlaneCondition::Stress),
            KinematicsKey::PlaneStrain => Some(PlaneCondition::Strain),
            KinematicsKey::Axisymmetric => None,
        }
    }
}

/// The plane condition as spelled in scene files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlaneKey {
    /// Plane stress.
    Stress,
    /// Plane strain.
    Strain,
}

impl PlaneKey {
    pub(super) fn condition(self) -> PlaneCondition {
        match self {
            PlaneKey::Stress => PlaneCondition::Stress,
            PlaneKey::Strain => PlaneCondition::Strain,
        }
    }
}

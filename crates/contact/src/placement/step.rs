//! What a step with zone ends placed on the mesh is: how it is loaded, the search's tolerances,
//! and what it returns (shared by the search and its fallback on the generated mesh), for any [`super::PlaceableContact`].

use crate::{BoussinesqStep, StepStart};

/// How a step with placed zone ends is loaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlacedLoading {
    /// The load w is given; l* follows from the Boussinesq condition p(l*) = 0 at the placed node.
    Load(f64),
    /// The contact end l* is given (c on the master curve: η for the preset, the paper's steps
    /// in l);
    /// w follows from the Boussinesq condition.
    ContactEnd(f64),
}

/// Tolerances of the zone-end search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZoneEndSearch {
    /// Tolerance on l* and b* in η (default 1e-9: the root finders converge superlinearly, so
    /// a tight tolerance costs a mesh or two and leaves residuals near round-off).
    pub tolerance: f64,
    /// Largest number of meshes solved for one step.
    pub max_evaluations: usize,
}

impl Default for ZoneEndSearch {
    fn default() -> Self {
        ZoneEndSearch { tolerance: 1e-9, max_evaluations: 80 }
    }
}

/// One step solved with nodes placed at its zone ends, on a problem of type `C`.
#[derive(Debug, Clone)]
pub struct PlacedStep<C> {
    /// l* on the master curve's coordinate c.
    pub contact_end: f64,
    /// b* on c (l* when nothing slips: the stick zone is the whole
    /// contact zone).
    pub stick_end: f64,
    /// Whether a node was placed at l* (false when the search failed and the step was solved on
    /// the generated mesh instead, see `placement_failure`).
    pub contact_end_placed: bool,
    /// Why the zone-end search failed, when it did: the step was then solved by the Boussinesq
    /// algorithm on the generated mesh (zone ends at its nodes, l and b interpolated).
    pub placement_failure: Option<String>,
    /// Whether a node was placed at b* (false when nothing slips, or when b* is closer to l*
    /// than two corners can be placed; b is then interpolated between the pairs like the slip).
    pub stick_end_placed: bool,
    /// l* on the case's report coordinate ([`super::PlacedCase::report_coordinates`]: for the
    /// plate-insert preset the hole-edge angle η = 1 − φ/π, the paired hole point's in variant 2).
    pub contact_end_reported: f64,
    /// b* likewise.
    pub stick_end_reported: f64,
    /// The load w (given, or from the Boussinesq condition).
    pub load: f64,
    /// |p(l*)| left by the search, relative to the largest contact pressure.
    pub residual_pressure: f64,
    /// |σ q − μ|p|| at b* left by the search, relative to the largest contact pressure.
    pub residual_cone: f64,
    /// Meshes solved.
    pub evaluations: usize,
    /// The step's start on the adjusted mesh's pairs (the history carried over), for checks
    /// by other algorithms on the same discrete problem.
    pub start: StepStart,
    /// The problem on the adjusted mesh.
    pub case: C,
    /// Its Boussinesq step (solution, zones, violated inequalities).
    pub step: BoussinesqStep,
}

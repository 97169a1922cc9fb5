//! Zone ends finer than the mesh, on any contact whose master curve can be morphed: the paper's
//! placed Boussinesq algorithm (Solodovnikov 1998, spec §6: "the contour nodes at η = b* and
//! η = l* are placed there (the mesh is adjusted)") as a method of the framework.
//!
//! ```text
//! c          the master curve's coordinate: 0 at the end where the zone starts, growing along
//!            the zone (η = 1 − φ/π on the plate-insert preset's circles; s/L, the arc length
//!            over the curve's length, on a generic straight or circular master curve)
//! corners    the master contour's even nodes (quadratic edges); one corner may move strictly
//!            between its neighbours along the curve, its edges' mid nodes re-centred and the
//!            interior relaxed (contact2d_mesh::morph), the topology unchanged
//! family     builds the problem with given corners placed at given c, reusing the generated
//!            mesh's symbolic factorisation (ContactProblem::rebuild_moved)
//! ```
//!
//! [`PlaceableContact`] is what a geometry gives the search (`search.rs`); the search, its root
//! finders (`roots.rs`), the corners' limits (`corners.rs`) and the history carried between
//! meshes (`history.rs`) use nothing else.
//! The geometries implement it above this crate: the plate-insert preset on its circles
//! (`contact2d::plate_insert::PlateInsertFamily`), a generic scene when its one contact's master
//! curve is straight or circular ([`curve::MasterCurve`]; `contact2d::generic::placed::GenericFamily`).

mod corners;
pub mod curve;
mod generated_mesh;
mod history;
mod roots;
mod search;
mod step;

use crate::{ContactError, ContactProblem};
use contact2d_mesh::NodeId;

pub use history::ContourHistory;
pub use search::{PlacedHistory, place_zone_ends, solve_placed_history};
pub use step::{PlacedLoading, PlacedStep, ZoneEndSearch};

/// A master corner node moved along the master curve to coordinate `eta`, its two edges' mid
/// nodes re-centred and the interior relaxed (topology unchanged).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodePlacement {
    /// Target coordinate c on the master curve (η on the preset's master circle).
    pub eta: f64,
    /// The corner to move: its position in the master contour's node list (even, interior). It
    /// may travel strictly between its neighbouring corners of the generated mesh
    /// ([`corner_range`]).
    pub corner: usize,
}

/// A built contact problem whose single interface has a master curve with a coordinate c (see
/// the module docs): what the zone-end search reads off each mesh it solves.
pub trait PlacedCase: Clone {
    /// The contact problem (its load the unit of the search's load w).
    fn problem(&self) -> &ContactProblem;
    /// The master contour's nodes in contour order (corners at even positions).
    fn master_nodes(&self) -> &[NodeId];
    /// c of a point on the master curve.
    fn coordinate_of(&self, x: [f64; 2]) -> f64;
    /// The coordinate the zone ends are reported on, per pair (the preset's η on the hole edge;
    /// c itself by default).
    fn report_coordinates(&self) -> Vec<f64> {
        pair_coordinates(self)
    }
}

/// A family of problems of one mesh topology whose master corners can be placed along the
/// master curve.
pub trait PlaceableContact {
    /// The built problem of one member.
    type Case: PlacedCase;
    /// The problem on the generated mesh (no node moved).
    ///
    /// # Errors
    /// Model, pairing or factorisation errors.
    fn build_generated(&self) -> Result<Self::Case, ContactError>;
    /// The problem with the corners `placed` moved along the master curve, reusing the
    /// symbolic factorisation of `base` (the generated mesh's problem).
    ///
    /// # Errors
    /// A placement outside its corner's range or reordering the corners; model, pairing or
    /// factorisation errors.
    fn build_placed(&self, placed: &[NodePlacement], base: &ContactProblem) -> Result<Self::Case, ContactError>;
}

/// c of each pair's master node.
pub fn pair_coordinates<C: PlacedCase>(case: &C) -> Vec<f64> {
    let p = case.problem();
    p.pairs.iter().map(|pair| case.coordinate_of(p.model.mesh.points[pair.master.0])).collect()
}

/// c of each master contour node, in contour order.
pub fn node_coordinates<C: PlacedCase>(case: &C) -> Vec<f64> {
    let points = &case.problem().model.mesh.points;
    case.master_nodes().iter().map(|v| case.coordinate_of(points[v.0])).collect()
}

/// The interior corner of the master contour nearest to `eta`, other than those in `exclude`:
/// the node a search for a zone end at about `eta` moves.
pub fn nearest_corner<C: PlacedCase>(case: &C, eta: f64, exclude: &[usize]) -> Option<usize> {
    let node_eta = node_coordinates(case);
    (1..node_eta.len().saturating_sub(1) / 2)
        .map(|c| 2 * c)
        .filter(|c| !exclude.contains(c))
        .min_by(|a, b| (node_eta[*a] - eta).abs().total_cmp(&(node_eta[*b] - eta).abs()))
}

/// The c interval (ascending) a corner may be placed in: strictly between its neighbouring
/// corners of `case`'s mesh.
pub fn corner_range<C: PlacedCase>(case: &C, corner: usize) -> Option<[f64; 2]> {
    let node_eta = node_coordinates(case);
    let (a, b) = (*node_eta.get(corner.checked_sub(2)?)?, *node_eta.get(corner + 2)?);
    Some([a.min(b), a.max(b)])
}

/// Pair indices sorted by c (the order the zone grows in).
pub fn coordinate_order<C: PlacedCase>(case: &C) -> Vec<usize> {
    let eta = pair_coordinates(case);
    let mut order: Vec<usize> = (0..eta.len()).collect();
    order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
    order
}

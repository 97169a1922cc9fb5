//! The plate-insert preset as a [`PlaceableContact`]: its master circle (the hole, or the
//! insert edge in variant 2) with the coordinate η = 1 − φ/π (φ about the circle's centre), the
//! paper's own builder moving the corners ([`PlateInsert::build_reusing`]).

use contact2d_contact::{ContactError, ContactProblem};
use contact2d_mesh::{Mesh, NodeId};

use super::{PlateInsert, PlateInsertProblem};
use contact2d_contact::placement::{
    self, ContourHistory, NodePlacement, PlaceableContact, PlacedCase, PlacedLoading, ZoneEndSearch,
};

/// One step of the preset solved with nodes placed at its zone ends.
pub type PlacedStep = placement::PlacedStep<PlateInsertProblem>;

impl PlacedCase for PlateInsertProblem {
    fn problem(&self) -> &ContactProblem {
        &self.built.problem
    }

    fn master_nodes(&self) -> &[NodeId] {
        &self.master().nodes
    }

    fn coordinate_of(&self, x: [f64; 2]) -> f64 {
        self.eta_of_master_point(x)
    }

    /// η on the hole edge (the paper reports l and b on it): [`PlateInsertProblem::eta_hole`].
    fn report_coordinates(&self) -> Vec<f64> {
        self.eta_hole()
    }
}

/// The meshes of one generated plate-insert mesh with master corners moved along the master
/// circle: the preset's [`PlaceableContact`].
#[derive(Debug, Clone)]
pub struct PlateInsertFamily<'a> {
    /// The case (its `placed_nodes` ignored).
    pub template: &'a PlateInsert,
    /// Its generated mesh, read once.
    pub mesh: &'a Mesh,
}

impl PlaceableContact for PlateInsertFamily<'_> {
    type Case = PlateInsertProblem;

    fn build_generated(&self) -> Result<PlateInsertProblem, ContactError> {
        PlateInsert { placed_nodes: vec![], ..self.template.clone() }.build_on(self.mesh.clone())
    }

    fn build_placed(
        &self,
        placed: &[NodePlacement],
        base: &ContactProblem,
    ) -> Result<PlateInsertProblem, ContactError> {
        let template = PlateInsert { placed_nodes: placed.to_vec(), ..self.template.clone() };
        template.build_reusing(self.mesh.clone(), Some(base))
    }
}

/// [`placement::place_zone_ends`] on the preset: one step with nodes placed at l* and b*.
/// `mesh` is the generated mesh of `template` (read once by the caller); `template`'s own
/// `placed_nodes` are ignored.
///
/// # Errors
/// Set-up failures on the generated mesh (a failed search is not one: see
/// [`placement::PlacedStep::placement_failure`]).
pub fn place_zone_ends(
    template: &PlateInsert,
    mesh: &Mesh,
    loading: PlacedLoading,
    history: &ContourHistory,
    search: ZoneEndSearch,
) -> Result<PlacedStep, ContactError> {
    placement::place_zone_ends(&PlateInsertFamily { template, mesh }, loading, history, search)
}

/// [`placement::solve_placed_history`] on the preset's mesh file.
///
/// # Errors
/// Reading the mesh; those of [`placement::solve_placed_history`].
pub fn solve_placed_history(
    template: &PlateInsert,
    loadings: &[PlacedLoading],
    search: ZoneEndSearch,
    on_step: &mut dyn FnMut(&PlacedStep),
) -> Result<Vec<(PlacedStep, f64)>, ContactError> {
    let mesh = contact2d_mesh::read_msh(&template.mesh)?;
    placement::solve_placed_history(&PlateInsertFamily { template, mesh: &mesh }, loadings, search, on_step)
}

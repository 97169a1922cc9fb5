//! One cell's stiffness matrix in the DOFs of a [`DofMap`], and the kinds of those DOFs: what
//! the free-free pattern ([`crate::pattern`]), the constrained blocks ([`crate::assembly`]) and
//! the re-assembly of moved cells ([`crate::reassembly`]) each scatter.
//!
//! ```text
//! K_e' = T_eᵀ K_e T_e     (T_e: the rotations of the cell's nodes with a local frame; I elsewhere)
//! ```

use nalgebra::DMatrix;

use crate::dof::{DofKind, DofMap};
use crate::error::FemError;
use crate::model::Model;

/// The DOF kinds of cell `i` of body `b`, in element order.
pub(crate) fn cell_kinds(model: &Model, dofs: &DofMap, b: usize, i: usize) -> Vec<DofKind> {
    model.bodies[b].cell_dofs(i).map(|d| dofs.kind(d)).collect()
}

/// The stiffness matrix of cell `i` of body `b` ([`crate::model::Body::cell_stiffness`]) in the
/// DOFs of `dofs`: `T_eᵀ K_e T_e` at nodes with a local frame ([`DofMap::rotate_cell_matrix`]).
pub(crate) fn element_matrix(model: &Model, dofs: &DofMap, b: usize, i: usize) -> Result<DMatrix<f64>, FemError> {
    let body = &model.bodies[b];
    let mut k = body.cell_stiffness(&model.mesh, i)?;
    dofs.rotate_cell_matrix(body.cell_nodes(i).iter().map(|n| n.0), &mut k);
    Ok(k)
}

//! Assembly of a model whose nodes moved (mesh morphing: the same cells, the same DOFs),
//! reusing the element matrices of the cells that did not move.
//!
//! ```text
//! K_e = ∫ Bᵀ D B t dΩ over cell e: a function of its nodal coordinates x_e alone (its element
//!       type, material, thickness and formulation are the base model's: the bodies must be equal)
//! reuse:    K_e of the base model where x_e is bit for bit the base's; computed anew elsewhere
//! K_ff[p] = Σ_e K_e[entry of e at p], summed over the cells in ascending order, as `assemble`
//!           sums it (there each entry lies in one column block, whose cells are visited in
//!           ascending order); K_fc, K_cc from the same triplets in the same order
//! ```
//!
//! So [`ElementMatrices::assemble_moved`] gives bit for bit the system [`assemble`] gives for the
//! moved model. Why: the zone-end search of the placed Boussinesq algorithm solves some thirty
//! meshes per load step that differ from the generated one by a few placed nodes and their
//! relaxed neighbourhoods (`contact2d_mesh::morph`); their element matrices were an eighth of
//! its time (docs/benchmarks.md).

use faer::sparse::SymbolicSparseColMat;
use nalgebra::DMatrix;
use rayon::prelude::*;

use crate::assembly::{LinearSystem, Triplets, assemble, floating_of, model_cells, scatter_constrained, system_of};
use crate::cell_matrix::{cell_kinds, element_matrix};
use crate::dof::{DofKind, DofMap};
use crate::error::FemError;
use crate::model::{Body, Model};
use crate::sparse::Csc;

/// The element matrices of an assembled model, and where each entry goes in `K_ff`: what a
/// moved copy of the model can reuse ([`ElementMatrices::assemble_moved`]).
#[derive(Debug, Clone)]
pub struct ElementMatrices {
    /// The base model's bodies (cells, element types, materials).
    bodies: Vec<Body>,
    /// Its DOF numbering.
    dofs: DofMap,
    /// Per cell, bodies in order.
    cells: Vec<CellMatrix>,
    /// The pattern of `K_ff` (lower triangle).
    pattern: SymbolicSparseColMat<usize>,
}

/// One cell of the base model.
#[derive(Debug, Clone)]
struct CellMatrix {
    /// Its nodal coordinates.
    coords: Vec<[f64; 2]>,
    /// Its stiffness matrix.
    matrix: DMatrix<f64>,
    /// Its DOFs' kinds, in element order.
    kinds: Vec<DofKind>,
    /// `(entry, position)`: the matrix entry (column-major index) added at each position of
    /// `K_ff`'s values (the lower triangle's free-free entries).
    scatter: Vec<(usize, usize)>,
}

impl ElementMatrices {
    /// The element matrices of `model`, whose assembled system is `system`.
    ///
    /// # Errors
    /// An element failure, or a free-free entry outside `system`'s stiffness pattern (a system
    /// that is not `model`'s).
    pub fn new(model: &Model, system: &LinearSystem) -> Result<ElementMatrices, FemError> {
        let k = system.stiffness.symbolic();
        let (col_ptr, row_idx) = (k.col_ptr(), k.row_idx());
        let pattern = SymbolicSparseColMat::new_checked(k.nrows(), k.ncols(), col_ptr.to_vec(), None, row_idx.to_vec());
        let cells = model_cells(model)
            .par_iter()
            .map(|&(b, i)| {
                let kinds = cell_kinds(model, &system.dofs, b, i);
                let mut scatter = vec![];
                for (a, col) in kinds.iter().enumerate() {
                    let DofKind::Free(col) = *col else { continue };
                    let rows = &row_idx[col_ptr[col]..col_ptr[col + 1]];
                    for (bb, row) in kinds.iter().enumerate() {
                        let DofKind::Free(row) = *row else { continue };
                        if row >= col {
                            let at = rows.binary_search(&row).map_err(|_| {
                                FemError::InvalidInput(format!("element matrices: ({row}, {col}) not in the pattern"))
                            })?;
                            scatter.push((a * kinds.len() + bb, col_ptr[col] + at));
                        }
                    }
                }
                Ok(CellMatrix {
                    coords: model.bodies[b].cell_coords(&model.mesh, i),
                    matrix: element_matrix(model, &system.dofs, b, i)?,
                    kinds,
                    scatter,
                })
            })
            .collect::<Result<Vec<_>, FemError>>()?;
        Ok(ElementMatrices { bodies: model.bodies.clone(), dofs: system.dofs.clone(), cells, pattern })
    }

    /// The system of `model`, a moved copy of the base model: bit for bit [`assemble`]`(model)`,
    /// with the matrices of the cells whose coordinates did not change taken from the base. A
    /// model with other bodies or another DOF numbering is assembled anew.
    ///
    /// # Errors
    /// As [`assemble`].
    pub fn assemble_moved(&self, model: &Model) -> Result<LinearSystem, FemError> {
        let dofs = model.dof_map()?;
        if dofs != self.dofs || model.bodies != self.bodies {
            return assemble(model);
        }
        let floating = floating_of(model, &dofs)?;
        let cells = model_cells(model);
        let fresh = cells
            .par_iter()
            .zip(&self.cells)
            .map(
                |(&(b, i), base)| {
                    if base.moved(model, b, i) { element_matrix(model, &self.dofs, b, i).map(Some) } else { Ok(None) }
                },
            )
            .collect::<Result<Vec<Option<DMatrix<f64>>>, FemError>>()?;
        let mut values = vec![0.0; self.pattern.row_idx().len()];
        let mut triplets = Triplets::default();
        for (base, fresh) in self.cells.iter().zip(&fresh) {
            let k = fresh.as_ref().unwrap_or(&base.matrix);
            let entries = k.as_slice();
            for &(e, p) in &base.scatter {
                values[p] += entries[e];
            }
            if base.kinds.iter().any(|k| matches!(k, DofKind::Constrained(_))) {
                scatter_constrained(&base.kinds, k, &mut triplets);
            }
        }
        system_of(model, dofs, floating, Csc::new(self.pattern.clone(), values), &triplets)
    }

    /// How many of `model`'s cells [`ElementMatrices::assemble_moved`] computes anew (their
    /// coordinates differ from the base's).
    pub fn moved_cells(&self, model: &Model) -> usize {
        model_cells(model).iter().zip(&self.cells).filter(|(cell, base)| base.moved(model, cell.0, cell.1)).count()
    }
}

impl CellMatrix {
    /// Whether cell `i` of body `b` of `model` has other coordinates than this base cell (in any
    /// bit: the matrix is then computed anew).
    fn moved(&self, model: &Model, b: usize, i: usize) -> bool {
        let same = |p: [f64; 2], q: [f64; 2]| p[0].to_bits() == q[0].to_bits() && p[1].to_bits() == q[1].to_bits();
        let nodes = model.bodies[b].cell_nodes(i);
        !nodes.iter().zip(&self.coords).all(|(n, x)| same(model.mesh.points[n.0], *x))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::dof::Component;
    use contact2d_element::{Kinematics, Material};
    use contact2d_mesh::generate::rectangle;
    use contact2d_mesh::morph::move_nodes;
    use contact2d_mesh::{CellKind, NodeId};

    fn model(mesh: contact2d_mesh::Mesh) -> Model {
        let mut model = Model::new(mesh);
        model.add_body("domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
        model.fix("left", Component::X, 0.0).unwrap();
        model.fix("bottom", Component::Y, 0.0).unwrap();
        model.fix("right", Component::X, 0.1).unwrap();
        model
    }

    fn bits(m: &Csc) -> Vec<u64> {
        m.val().iter().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn a_moved_model_assembles_bit_for_bit_as_anew() {
        let mesh = rectangle(CellKind::Quad9, [0.0, 6.0], [0.0, 4.0], 6, 4);
        let base = model(mesh.clone());
        let matrices = ElementMatrices::new(&base, &assemble(&base).unwrap()).unwrap();
        // Slide a bottom node along its edge: it and its relaxed neighbours move, the far cells not.
        let node = (0..mesh.points.len()).find(|&i| mesh.points[i] == [3.0, 0.0]).unwrap();
        let mut moved_mesh = mesh;
        move_nodes(&mut moved_mesh, &[(NodeId(node), [3.2, 0.0])], 1).unwrap();
        let moved = model(moved_mesh);
        let moved_cells = matrices.moved_cells(&moved);
        assert!(moved_cells > 0 && moved_cells < moved.bodies[0].num_cells(), "{moved_cells} cells moved");
        let (anew, reused) = (assemble(&moved).unwrap(), matrices.assemble_moved(&moved).unwrap());
        assert_eq!(bits(&anew.stiffness), bits(&reused.stiffness));
        assert_eq!(anew.stiffness.symbolic().row_idx(), reused.stiffness.symbolic().row_idx());
        assert_eq!(bits(&anew.coupling), bits(&reused.coupling));
        assert_eq!(bits(&anew.constrained), bits(&reused.constrained));
        assert_eq!(anew.load, reused.load);
        // The base itself reuses every matrix.
        assert_eq!(matrices.moved_cells(&base), 0);
    }

    #[test]
    fn another_topology_is_assembled_anew() {
        let base = model(rectangle(CellKind::Quad9, [0.0, 6.0], [0.0, 4.0], 6, 4));
        let matrices = ElementMatrices::new(&base, &assemble(&base).unwrap()).unwrap();
        let other = model(rectangle(CellKind::Quad9, [0.0, 6.0], [0.0, 4.0], 3, 2));
        let (anew, reused) = (assemble(&other).unwrap(), matrices.assemble_moved(&other).unwrap());
        assert_eq!(bits(&anew.stiffness), bits(&reused.stiffness));
    }
}

//! The solution of a linear elastic model: displacements, reactions, strain energies.
//!
//! ```text
//! u = [u_f; u_c],   r_c = K_cf u_f + K_cc u_c - f_c,   Φ_E(body) = Σ_e ½ u_eᵀ K_e u_e
//! ```

use rayon::prelude::*;

use crate::assembly::{LinearSystem, assemble};
use crate::dof::{Component, Dof};
use crate::error::FemError;
use crate::model::{BodyId, Model};
use crate::solve::CholeskySolver;

/// Displacements and reactions, both in global DOF order (`2 × nodes`).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Displacement of every DOF (zero at inactive nodes).
    pub displacement: Vec<f64>,
    /// Reaction force at every constrained DOF (zero elsewhere), in global components (`r = T r'`
    /// at a node with a local frame: both components of a node held in `un` only).
    pub reactions: Vec<f64>,
}

impl Solution {
    /// Builds the full solution from the free unknowns and the prescribed values.
    pub fn from_free(system: &LinearSystem, u_free: &[f64], prescribed: &[f64]) -> Solution {
        let displacement = system.dofs.expand(u_free, prescribed);
        let reactions = system.dofs.reactions_global(&system.reactions(u_free, prescribed));
        Solution { displacement, reactions }
    }

    /// Displacement `[u1, u2]` of node `n`.
    pub fn node_displacement(&self, n: usize) -> [f64; 2] {
        [self.displacement[2 * n], self.displacement[2 * n + 1]]
    }

    /// Sum of the reactions over the nodes of a physical group: `[R1, R2]`.
    ///
    /// # Errors
    /// Unknown group.
    pub fn reaction_resultant(&self, model: &Model, group: &str) -> Result<[f64; 2], FemError> {
        let mut sum = [0.0; 2];
        for n in model.mesh.group_nodes(group)? {
            for c in [Component::X, Component::Y] {
                sum[c.index()] += self.reactions[Dof::of(n.0, c).0];
            }
        }
        Ok(sum)
    }
}

/// Assembles, factors and solves a model with the prescribed values it carries.
///
/// # Errors
/// As [`assemble`] and [`CholeskySolver::factor`].
pub fn solve_linear(model: &Model) -> Result<(LinearSystem, CholeskySolver, Solution), FemError> {
    let system = assemble(model)?;
    let solver = CholeskySolver::factor(&system.stiffness)?;
    let prescribed = system.dofs.prescribed_values().to_vec();
    let u_free = solver.solve(&system.rhs(&prescribed));
    let solution = Solution::from_free(&system, &u_free, &prescribed);
    Ok((system, solver, solution))
}

/// Strain energy `Φ_E = Σ_e ½ u_eᵀ K_e u_e` of one body for global displacements `u`.
///
/// # Errors
/// Element failures (not expected once the body was validated).
pub fn strain_energy(model: &Model, body: BodyId, u: &[f64]) -> Result<f64, FemError> {
    let b = &model.bodies[body.0];
    (0..b.num_cells())
        .into_par_iter()
        .map(|i| {
            let k = b.cell_stiffness(&model.mesh, i)?;
            let ue = nalgebra::DVector::from_iterator(k.nrows(), b.cell_dofs(i).map(|d| u[d.0]));
            Ok(0.5 * ue.dot(&(&k * &ue)))
        })
        .collect::<Result<Vec<f64>, FemError>>()
        // Summed in cell order, not by rayon's scheduling-dependent reduction tree, so that the
        // energy is the same bit for bit whatever the number of threads.
        .map(|per_cell| per_cell.iter().sum())
}

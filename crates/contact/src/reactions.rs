//! Reactions of a contact problem: the forces the supports exert on the bodies, contact included.
//!
//! ```text
//! K u = f + B_Nᵀ λ + B_Tᵀ τ + r          (every DOF; r: the reactions, zero at free DOFs)
//! r_c = K_cf u_f + K_cc u_c − f_c − (B_Nᵀ λ + B_Tᵀ τ)_c        (constrained DOFs)
//! ```
//!
//! `B_Nᵀ λ` puts `+λ_k n_k` on the master node and `−N_j λ_k n_k` on the slave nodes (the sign
//! of the rows, [`crate::problem`]); a contact force that lands on a constrained DOF (a slave edge
//! held by a support, a node on a symmetry line) is carried by that support, so it enters its
//! reaction. Units: force (per unit thickness where the thickness is 1).
//!
//! Global balance. `K` annihilates each body's translations, so summing the first line over
//! every DOF of one direction gives
//!
//! ```text
//! Σ f + Σ r + Σ_rigid R_k = 0      R_k = Σ_a (row k)_a (λ_k or τ_k)   (force of pair k on the bodies)
//! ```
//!
//! A deformable pair's rows sum to zero per direction (the master's `n` against the slave's
//! `Σ_j N_j n = n`), so its forces are internal; a rigid obstacle's nodes carry no DOF, so its
//! pairs' resultant `R_k` is the force the obstacle exerts on the bodies — a support like the
//! others, reported beside the reactions.

use contact2d_fem::Dof;

use crate::error::ContactError;
use crate::problem::{ContactProblem, PairRow};
use crate::solution::ContactSolution;

impl ContactProblem {
    /// Reactions at the constrained DOFs (per constrained index; in the local frame at a node
    /// with one, see [`contact2d_fem::DofMap::reactions_global`]) of a solution under the load
    /// with pattern factors `factors`, the contact forces on constrained DOFs included:
    ///
    /// ```text
    /// r_c = K_cf u_f + K_cc u_c − Σ_p f_p f_c,p − (B_Nᵀ λ + B_Tᵀ τ)_c
    /// ```
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] when the solution's sizes do not fit this problem or the
    /// factor count differs from the number of patterns.
    pub fn reactions(&self, solution: &ContactSolution, factors: &[f64]) -> Result<Vec<f64>, ContactError> {
        self.check_solution(solution)?;
        if factors.len() != self.patterns().len() {
            return Err(ContactError::InvalidInput(format!(
                "reactions: {} load factors for {} patterns",
                factors.len(),
                self.patterns().len()
            )));
        }
        let dofs = &self.system.dofs;
        let u = &solution.displacement;
        let u_free = dofs.restrict_free(u);
        let u_c = dofs.restrict_constrained(u);
        // LinearSystem::reactions subtracts the model's own loads; add them back and subtract
        // the patterns' instead (at a framed node, all in its local frame: f' = Tᵀ f).
        let mut r = self.system.reactions(&u_free, &u_c);
        let load = dofs.to_local(&self.system.load);
        let nodal: Vec<_> = self.patterns().iter().map(|p| dofs.to_local(&p.nodal)).collect();
        for (j, d) in dofs.constrained_dofs().iter().enumerate() {
            r[j] += load[d.0];
            for (p, f) in nodal.iter().zip(factors) {
                r[j] -= f * p[d.0];
            }
        }
        let forces = solution.normal_force.iter().zip(&self.normal_rows);
        for (force, row) in forces.chain(solution.tangential_force.iter().zip(&self.tangent_rows)) {
            for (j, c) in &row.constrained {
                r[*j] -= c * force;
            }
        }
        Ok(r)
    }

    /// The force pair `k` exerts on the bodies, summed per direction over its rows' entries,
    /// `[Σ_a (B_N)_ka λ_k + (B_T)_ka τ_k]` for the DOFs `a` in x1 and in x2: zero up to
    /// round-off for a pair between two bodies (action and reaction), the obstacle's force on
    /// the body for a rigid obstacle.
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] for a pair index out of range.
    pub fn pair_resultant(&self, k: usize, normal_force: f64, tangential_force: f64) -> Result<[f64; 2], ContactError> {
        self.pair_force_on(k, normal_force, tangential_force, |_| true)
    }

    /// The force pair `k` exerts on the nodes that `on` selects (by node index),
    /// `[Σ_{a ∈ on} (B_N)_ka λ_k + (B_T)_ka τ_k]` in x1 and x2: e.g. on one side of the pair,
    /// whose sum over the pairs of an interface is the force that side receives.
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] for a pair index out of range.
    pub fn pair_force_on(
        &self,
        k: usize,
        normal_force: f64,
        tangential_force: f64,
        on: impl Fn(usize) -> bool,
    ) -> Result<[f64; 2], ContactError> {
        let (Some(normal), Some(tangent)) = (self.normal_rows.get(k), self.tangent_rows.get(k)) else {
            return Err(ContactError::InvalidInput(format!("pair {k} of {}", self.num_pairs())));
        };
        let mut out = [0.0; 2];
        for (row, force) in [(normal, normal_force), (tangent, tangential_force)] {
            for (dof, c) in self.row_entries(row).filter(|(dof, _)| on(dof.0 / 2)) {
                out[dof.0 % 2] += c * force;
            }
        }
        Ok(out)
    }

    /// The moment about `centre` of the force pair `k` exerts on the nodes that `on` selects
    /// (by node index), counter-clockwise positive, at the nodes' undeformed positions `x_a`
    /// (small strain):
    ///
    /// ```text
    /// M_k = Σ_{a ∈ on} (x_a − c) × f_a = Σ_{a ∈ on} (x_a,1 − c_1) f_a,2 − (x_a,2 − c_2) f_a,1
    /// f_a = (B_N)_ka λ_k + (B_T)_ka τ_k
    /// ```
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] for a pair index out of range.
    pub fn pair_moment_on(
        &self,
        k: usize,
        (normal_force, tangential_force): (f64, f64),
        centre: [f64; 2],
        on: impl Fn(usize) -> bool,
    ) -> Result<f64, ContactError> {
        let (Some(normal), Some(tangent)) = (self.normal_rows.get(k), self.tangent_rows.get(k)) else {
            return Err(ContactError::InvalidInput(format!("pair {k} of {}", self.num_pairs())));
        };
        let points = &self.model.mesh.points;
        let mut moment = 0.0;
        for (row, force) in [(normal, normal_force), (tangent, tangential_force)] {
            for (dof, c) in self.row_entries(row).filter(|(dof, _)| on(dof.0 / 2)) {
                let Some(x) = points.get(dof.0 / 2) else { continue };
                // x × f for a force c·force along x1 (dof even) or x2 (dof odd).
                let arm = if dof.0 % 2 == 0 { -(x[1] - centre[1]) } else { x[0] - centre[0] };
                moment += arm * c * force;
            }
        }
        Ok(moment)
    }

    /// A row's entries with their global DOFs.
    fn row_entries<'a>(&'a self, row: &'a PairRow) -> impl Iterator<Item = (Dof, f64)> + 'a {
        let dofs = &self.system.dofs;
        let free = row.free.iter().map(|(i, c)| (dofs.free_dofs()[*i], *c));
        free.chain(row.constrained.iter().map(|(j, c)| (dofs.constrained_dofs()[*j], *c)))
    }

    fn check_solution(&self, s: &ContactSolution) -> Result<(), ContactError> {
        let (n, pairs) = (self.system.dofs.num_global(), self.num_pairs());
        if s.displacement.len() != n || s.normal_force.len() != pairs || s.tangential_force.len() != pairs {
            return Err(ContactError::InvalidInput(format!(
                "reactions: a solution with {} displacements and {} + {} pair forces for {n} DOFs and {pairs} pairs",
                s.displacement.len(),
                s.normal_force.len(),
                s.tangential_force.len()
            )));
        }
        Ok(())
    }
}

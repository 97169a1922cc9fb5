//! Each step's strain energy per body, from the assembled stiffness blocks, with what bounds its
//! round-off (the energy balance's allowance, [`super::StepResults`]).

use contact2d_contact::ContactProblem;

/// The body owning each global DOF (`usize::MAX`: none, e.g. a rigid obstacle's node).
pub(super) fn dof_owners(problem: &ContactProblem) -> Vec<usize> {
    let mut owner = vec![usize::MAX; problem.system.dofs.num_global()];
    for (b, body) in problem.model.bodies.iter().enumerate() {
        for i in 0..body.num_cells() {
            for d in body.cell_dofs(i) {
                owner[d.0] = b;
            }
        }
    }
    owner
}

/// The strain energy of every body, `½ uᵀ K u` summed over the DOFs it owns, from the assembled
/// blocks instead of the element matrices (the bodies share no DOF, so `K` is block diagonal by
/// body; `K_ff` is stored as its lower triangle and carries the floating pieces' springs `D`,
/// which are no strain energy):
///
/// ```text
/// U_b = ½ u_fᵀ (K_ff − D) u_f + u_fᵀ K_fc u_c + ½ u_cᵀ K_cc u_c     (rows of body b)
/// ```
///
/// The same energy as the sum over the cells of `½ u_eᵀ K_e u_e` up to round-off, at the cost
/// of one pass over the matrix per step instead of every element's stiffness. Also returns what
/// bounds the round-off of these sums: `|K||u|` per global DOF and `½ |u|ᵀ|K||u|` over all
/// bodies (with the springs `D`, whose `K u` terms are rounded as well).
pub(super) fn body_energies(problem: &ContactProblem, owner: &[usize], u: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let dofs = &problem.system.dofs;
    // The blocks are in the DOFs `u' = Tᵀ u` at framed nodes (`u` itself without frames).
    let u = &*dofs.to_local(u);
    let (free, fixed) = (dofs.free_dofs(), dofs.constrained_dofs());
    // `K u` row by row first (each row's rigid-motion terms cancel there, to ε |K_i| |u|, as in
    // `K_e u_e`), then `½ Σ u_g (K u)_g` per body: summing the products `u_i K_ij u_j` one by
    // one instead loses the cancellation (1e-7 relative on a sliding block).
    let mut ku = vec![0.0; dofs.num_global()];
    let mut abs_ku = vec![0.0; dofs.num_global()];
    let kff = problem.system.stiffness.as_ref();
    for (j, dj) in free.iter().enumerate() {
        // Column j's own entries `(K u)_j` and `(|K||u|)_j` are summed in registers, in the
        // order the entries come (the diagonal's term where it comes, then each one below it):
        // the same sums, term for term, as adding each to memory, without a store per term
        // (the rows below the diagonal, i > j, are other DOFs than j).
        let (mut ku_j, mut abs_ku_j) = (ku[dj.0], abs_ku[dj.0]);
        let uj = u[dj.0];
        for (i, v) in kff.row_idx_of_col(j).zip(kff.val_of_col(j)) {
            if i == j {
                ku_j += v * uj;
                abs_ku_j += (v * uj).abs();
            } else {
                let di = free[i];
                ku[di.0] += v * uj;
                abs_ku[di.0] += (v * uj).abs();
                ku_j += v * u[di.0];
                abs_ku_j += (v * u[di.0]).abs();
            }
        }
        ku[dj.0] = ku_j;
        abs_ku[dj.0] = abs_ku_j;
    }
    for &(i, k) in &problem.system.stabilisation {
        ku[free[i].0] -= k * u[free[i].0];
        abs_ku[free[i].0] += (k * u[free[i].0]).abs();
    }
    let kfc = problem.system.coupling.as_ref();
    let kcc = problem.system.constrained.as_ref();
    for (j, dj) in fixed.iter().enumerate() {
        for (i, v) in kfc.row_idx_of_col(j).zip(kfc.val_of_col(j)) {
            ku[free[i].0] += v * u[dj.0];
            ku[dj.0] += v * u[free[i].0];
            abs_ku[free[i].0] += (v * u[dj.0]).abs();
            abs_ku[dj.0] += (v * u[free[i].0]).abs();
        }
        for (i, v) in kcc.row_idx_of_col(j).zip(kcc.val_of_col(j)) {
            ku[fixed[i].0] += v * u[dj.0];
            abs_ku[fixed[i].0] += (v * u[dj.0]).abs();
        }
    }
    let mut energy = vec![0.0; problem.model.bodies.len()];
    for (g, (kug, ug)) in ku.iter().zip(u).enumerate() {
        if let Some(e) = energy.get_mut(owner[g]) {
            *e += 0.5 * ug * kug;
        }
    }
    let abs_energy = abs_ku.iter().zip(u).map(|(k, v)| 0.5 * k * v.abs()).sum();
    (energy, abs_ku, abs_energy)
}

//! The bodies condensed onto the contact pairs.
//!
//! ```text
//! u_f = w u0 + Z λ + Zt τ,    u0 = K⁻¹ r,   Z = K⁻¹ B_N,fᵀ,   Zt = K⁻¹ B_T,fᵀ   (one multi-RHS solve)
//! gap = g0 + w h + C λ + Cnt τ,   h = B_N,f u0 + B_N,c u_c,   C = B_N,f Z (symmetric positive definite)
//! ```
//!
//! Each body's stiffness is factored once (in [`crate::ContactProblem`]); the interface work is
//! dense and of the size of the number of pairs, and the full displacement field is recovered
//! once at the end. Without friction (every μ = 0) the tangential rows play no part, so their
//! columns are not solved for: `Zt` and the `C_·T`, `C_T·` blocks are then empty (0 columns).

use faer::Mat;
use nalgebra::DMatrix;

use crate::problem::{ContactProblem, PairRow};

/// Compliances of the contact pairs.
#[derive(Debug, Clone)]
pub struct Interface {
    /// `u0 = K⁻¹ r`: free displacements of the unit load without contact.
    pub u0: Vec<f64>,
    /// `Z = K⁻¹ B_N,fᵀ` (free DOFs × pairs).
    pub z_normal: Mat<f64>,
    /// `Zt = K⁻¹ B_T,fᵀ` (free DOFs × pairs).
    pub z_tangent: Mat<f64>,
    /// `h = B_N u0` (with the constrained part of the load pattern).
    pub h_normal: Vec<f64>,
    /// `B_T u0` likewise.
    pub h_tangent: Vec<f64>,
    /// `C_NN = B_N Z`, `C_NT = B_N Zt`, `C_TN`, `C_TT`.
    pub c_nn: DMatrix<f64>,
    /// Normal rows against tangential forces.
    pub c_nt: DMatrix<f64>,
    /// Tangential rows against normal forces.
    pub c_tn: DMatrix<f64>,
    /// Tangential rows against tangential forces.
    pub c_tt: DMatrix<f64>,
}

fn rows_to_columns(n: usize, rows: &[PairRow]) -> Mat<f64> {
    let mut b = Mat::zeros(n, rows.len());
    for (k, row) in rows.iter().enumerate() {
        for (i, v) in &row.free {
            b[(*i, k)] += v;
        }
    }
    b
}

fn apply_rows(rows: &[PairRow], z: &Mat<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), z.ncols(), |k, j| rows[k].free.iter().map(|(i, v)| v * z[(*i, j)]).sum())
}

impl Interface {
    /// Condenses `problem` onto its pairs (one multi-RHS solve with the existing factorisation).
    pub fn new(problem: &ContactProblem) -> Interface {
        let n = problem.system.dofs.num_free();
        let u0 = problem.solver.solve(&problem.pattern_rhs);
        let z_normal = problem.solver.solve_many(&rows_to_columns(n, &problem.normal_rows));
        let frictional = problem.friction.iter().any(|mu| *mu > 0.0);
        let z_tangent = if frictional {
            problem.solver.solve_many(&rows_to_columns(n, &problem.tangent_rows))
        } else {
            Mat::zeros(n, 0)
        };
        let h = |rows: &[PairRow]| rows.iter().map(|r| r.dot(&u0, &problem.pattern_prescribed)).collect::<Vec<_>>();
        Interface {
            h_normal: h(&problem.normal_rows),
            h_tangent: h(&problem.tangent_rows),
            c_nn: apply_rows(&problem.normal_rows, &z_normal),
            c_nt: apply_rows(&problem.normal_rows, &z_tangent),
            c_tn: if frictional { apply_rows(&problem.tangent_rows, &z_normal) } else { DMatrix::zeros(0, 0) },
            c_tt: apply_rows(if frictional { &problem.tangent_rows } else { &[] }, &z_tangent),
            u0,
            z_normal,
            z_tangent,
        }
    }

    /// Free displacements `w u0 + Z λ + Zt τ`.
    pub fn free_displacement(&self, w: f64, lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        (0..self.u0.len())
            .map(|i| {
                w * self.u0[i]
                    + lambda.iter().enumerate().map(|(k, l)| self.z_normal[(i, k)] * l).sum::<f64>()
                    + tau
                        .iter()
                        .take(self.z_tangent.ncols())
                        .enumerate()
                        .map(|(k, t)| self.z_tangent[(i, k)] * t)
                        .sum::<f64>()
            })
            .collect()
    }
}

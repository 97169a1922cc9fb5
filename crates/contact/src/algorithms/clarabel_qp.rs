//! Frictionless contact as the convex QP of (5.3), solved by Clarabel in the full displacement
//! space (an independent check of the condensed algorithms: no condensation, no active set).
//!
//! ```text
//! minimise   ½ u_fᵀ K_ff u_f − w rᵀ u_f
//! subject to g0 + w B_N,c u_c + B_N,f u_f ≥ 0
//! Clarabel form:  A x + s = b, s ∈ R₊ᵐ  with  A = −B_N,f,  b = g0 + w B_N,c u_c;  λ = z (dual)
//! ```
//!
//! The QP is solved non-dimensional and diagonally equilibrated, so that the interior-point
//! method's tolerances (1e-12, printing off) act on O(1) numbers at any stiffness contrast:
//!
//! ```text
//! s   = the largest gap or prescribed value (length scale),  k_c = the contact stiffness scale
//!       (crate::algorithms::full_system::contact_stiffness)
//! u_i = s d_i y_i,   d_i = √(k_c / K_ii)                (Jacobi: P = D K D / k_c has unit diagonal)
//! objective / (k_c s²):   ½ yᵀ P y − (w D r / (k_c s))ᵀ y
//! row k / (s ‖(B_N D)_k‖):   −ρ_k (B_N D)_k y ≤ ρ_k b_k / s,   ρ_k = 1 / ‖(B_N D)_k‖
//! forces:  λ_k = k_c s ρ_k z_k                           (from K u = w r + B_Nᵀ λ)
//! ```
//!
//! Without the equilibration (`u = s x`, the objective over `s²`, as before issue 12) the
//! diagonal of `P` spans the stiffness contrast (1e6 between the bodies at E2/E1 = 1e6, beyond
//! Clarabel's own Ruiz equilibration, whose factors are bounded to [1e-4, 1e4]), and the duals
//! `z = λ / s` carry the force unit: its absolute tolerances then lost the contact forces of the
//! soft body (docs/stability.md, "Clarabel as a verifier").

use std::time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};

use crate::algorithms::full_system::contact_stiffness;
use crate::problem::{ContactProblem, PairRow};
use crate::report::{RawSolution, finish_from_displacement};
use crate::solution::{ContactSolution, ContactStatus, StepStart};

pub(crate) fn map_status(status: SolverStatus) -> ContactStatus {
    match status {
        SolverStatus::Solved => ContactStatus::Converged,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => ContactStatus::Infeasible,
        SolverStatus::MaxIterations | SolverStatus::MaxTime | SolverStatus::AlmostSolved => {
            ContactStatus::MaxIterations
        }
        _ => ContactStatus::Numerical,
    }
}

/// The equilibration of the module docs: `u_i = s d_i y_i`, the objective over `k_c s²`.
pub(crate) struct QpScaling {
    /// Length scale `s`.
    pub length: f64,
    /// Contact stiffness scale `k_c`.
    pub stiffness: f64,
    /// `d_i = √(k_c / K_ii)` per free DOF.
    pub d: Vec<f64>,
}

impl QpScaling {
    pub(crate) fn new(problem: &ContactProblem, length: f64) -> QpScaling {
        let stiffness = contact_stiffness(problem);
        let k = problem.system.stiffness.as_ref();
        let d = (0..k.ncols())
            .map(|j| {
                let kjj = k.row_idx_of_col(j).zip(k.val_of_col(j)).find(|(i, _)| *i == j).map_or(0.0, |(_, v)| *v);
                if kjj > 0.0 { (stiffness / kjj).sqrt() } else { 1.0 }
            })
            .collect();
        QpScaling { length, stiffness, d }
    }

    /// The upper triangle of `D K D / k_c` (from the stored lower triangle of `K`: entry
    /// `(i, j)`, `i ≥ j`, becomes `(j, i)`) as triplets, sized `dim × dim`.
    pub(crate) fn hessian(&self, problem: &ContactProblem, dim: usize) -> CscMatrix<f64> {
        let k = problem.system.stiffness.as_ref();
        let (mut rows, mut cols, mut vals) = (vec![], vec![], vec![]);
        for j in 0..k.ncols() {
            for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
                rows.push(j);
                cols.push(i);
                vals.push(v * self.d[i] * self.d[j] / self.stiffness);
            }
        }
        CscMatrix::new_from_triplets(dim, dim, rows, cols, vals)
    }

    /// `q = −w D r / (k_c s)`.
    pub(crate) fn linear_term(&self, problem: &ContactProblem, w: f64) -> Vec<f64> {
        let scale = self.stiffness * self.length;
        problem.pattern_rhs.iter().zip(&self.d).map(|(r, d)| -w * r * d / scale).collect()
    }

    /// `‖(B D)_k‖` of a row's free part (1 when it has none).
    pub(crate) fn row_norm(&self, row: &PairRow) -> f64 {
        let norm = row.free.iter().map(|(i, v)| (v * self.d[*i]).powi(2)).sum::<f64>().sqrt();
        if norm > 0.0 { norm } else { 1.0 }
    }

    /// `u = s D y`.
    pub(crate) fn displacement(&self, y: &[f64]) -> Vec<f64> {
        y.iter().zip(&self.d).map(|(y, d)| self.length * d * y).collect()
    }

    /// The force of a dual `z` of a row scaled by `1/(s ‖(B D)_k‖)`: `k_c s z / ‖(B D)_k‖`.
    pub(crate) fn force(&self, z: f64, row_norm: f64) -> f64 {
        self.stiffness * self.length * z / row_norm
    }
}

/// Solves the frictionless problem at load factor `w` with Clarabel.
pub fn solve_frictionless_qp(problem: &ContactProblem, w: f64) -> ContactSolution {
    let start = Instant::now();
    let n = problem.system.dofs.num_free();
    let m = problem.num_pairs();
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let b: Vec<f64> = problem
        .normal_rows
        .iter()
        .zip(&problem.gap)
        .map(|(row, g0)| g0 + row.constrained.iter().map(|(j, v)| v * prescribed[*j]).sum::<f64>())
        .collect();
    let s = b.iter().chain(&prescribed).fold(0.0f64, |a, v| a.max(v.abs()));
    let s = if s > 0.0 { s } else { 1.0 };
    let scaling = QpScaling::new(problem, s);
    let p = scaling.hessian(problem, n);
    let norms: Vec<f64> = problem.normal_rows.iter().map(|r| scaling.row_norm(r)).collect();
    let b: Vec<f64> = b.iter().zip(&norms).map(|(v, rho)| v / (s * rho)).collect();
    let q = scaling.linear_term(problem, w);
    let (mut ar, mut ac, mut av) = (vec![], vec![], vec![]);
    for (kk, row) in problem.normal_rows.iter().enumerate() {
        for (i, v) in &row.free {
            ar.push(kk);
            ac.push(*i);
            av.push(-v * scaling.d[*i] / norms[kk]);
        }
    }
    let a = CscMatrix::new_from_triplets(m, n, ar, ac, av);
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_gap_abs(1e-12)
        .tol_gap_rel(1e-12)
        .tol_feas(1e-12)
        .max_iter(200)
        .build();
    let cones = [NonnegativeConeT(m)];
    let (status, x, z, iterations) = match settings {
        Ok(settings) => match DefaultSolver::new(&p, &q, &a, &b, &cones, settings) {
            Ok(mut solver) => {
                solver.solve();
                let sol = &solver.solution;
                let x = scaling.displacement(&sol.x);
                let z: Vec<f64> = sol.z.iter().zip(&norms).map(|(z, rho)| scaling.force(*z, *rho)).collect();
                (map_status(sol.status), x, z, sol.iterations as usize)
            }
            Err(_) => (ContactStatus::Numerical, vec![0.0; n], vec![0.0; m], 0),
        },
        Err(_) => (ContactStatus::Numerical, vec![0.0; n], vec![0.0; m], 0),
    };
    let raw = RawSolution {
        load_factor: w,
        normal_force: z,
        tangential_force: vec![0.0; m],
        status,
        iterations,
        time: start.elapsed(),
    };
    finish_from_displacement(problem, &x, raw, &StepStart::initial(m))
}

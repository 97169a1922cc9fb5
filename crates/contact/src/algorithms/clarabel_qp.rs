//! Frictionless contact as the convex QP of (5.3), solved by Clarabel in the full displacement
//! space (an independent check of the condensed algorithms: no condensation, no active set).
//!
//! ```text
//! minimise   ½ u_fᵀ K_ff u_f − w rᵀ u_f
//! subject to g0 + w B_N,c u_c + B_N,f u_f ≥ 0
//! Clarabel form:  A x + s = b, s ∈ R₊ᵐ  with  A = −B_N,f,  b = g0 + w B_N,c u_c;  λ = z (dual)
//! ```
//!
//! The interior point's answer is then polished: the exact solution of its own contact set (one
//! sparse LU of the full system, crate::algorithms::augmented_lagrangian) replaces it when that
//! passes the certificate (crate::certify::certify); the contact set is Clarabel's, so the check
//! stays independent of the active set.
//!
//! `P` is the upper triangle of `K_ff`. The displacements are scaled by `s` = the largest gap or
//! prescribed value (`u = s x`, the objective divided by `s²`, so `λ = s z`): the interior-point
//! method's tolerances (1e-12, printing off) then act on O(1) numbers.

use web_time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};

use crate::algorithms::augmented_lagrangian::polish_state;
use crate::problem::ContactProblem;
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

/// The displacement the load alone produces, `max |K⁻¹ w r|`: the scale of the variables where
/// every gap and prescribed value is zero (bodies touching and pressed by forces), so that the
/// interior point's tolerances act on O(1) numbers there too.
pub(crate) fn displacement_scale(problem: &ContactProblem, w: f64) -> f64 {
    let rhs: Vec<f64> = problem.pattern_rhs.iter().map(|r| w * r).collect();
    problem.solver.solve(&rhs).iter().fold(0.0f64, |a, v| if v.is_finite() { a.max(v.abs()) } else { a })
}

/// Solves the frictionless problem at load factor `w` with Clarabel.
pub fn solve_frictionless_qp(problem: &ContactProblem, w: f64) -> ContactSolution {
    let start = Instant::now();
    let n = problem.system.dofs.num_free();
    let m = problem.num_pairs();
    // Upper triangle of K_ff from its stored lower triangle: entry (i, j), i ≥ j, becomes (j, i).
    let k = problem.system.stiffness.as_ref();
    let (mut rows, mut cols, mut vals) = (vec![], vec![], vec![]);
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            rows.push(j);
            cols.push(i);
            vals.push(*v);
        }
    }
    let p = CscMatrix::new_from_triplets(n, n, rows, cols, vals);
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let b: Vec<f64> = problem
        .normal_rows
        .iter()
        .zip(&problem.gap)
        .map(|(row, g0)| g0 + row.constrained.iter().map(|(j, v)| v * prescribed[*j]).sum::<f64>())
        .collect();
    let s = b.iter().chain(&prescribed).fold(0.0f64, |a, v| a.max(v.abs()));
    let s = s.max(displacement_scale(problem, w));
    let s = if s > 0.0 { s } else { 1.0 };
    let b: Vec<f64> = b.iter().map(|v| v / s).collect();
    let q: Vec<f64> = problem.pattern_rhs.iter().map(|r| -w * r / s).collect();
    let (mut ar, mut ac, mut av) = (vec![], vec![], vec![]);
    for (kk, row) in problem.normal_rows.iter().enumerate() {
        for (i, v) in &row.free {
            ar.push(kk);
            ac.push(*i);
            av.push(-v);
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
                let x: Vec<f64> = sol.x.iter().map(|v| v * s).collect();
                let z: Vec<f64> = sol.z.iter().map(|v| v * s).collect();
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
    let start = StepStart::initial(m);
    let solution = finish_from_displacement(problem, &x, raw, &start);
    // Polishing, as for the Tresca QPs (crate::algorithms::clarabel_tresca): the exact answer of
    // the interior point's own contact set, kept only if it passes the certificate.
    if matches!(solution.status, ContactStatus::Converged | ContactStatus::Numerical)
        && let Some(mut polished) = polish_state(problem, w, &start, &solution.state, solution.iterations + 1)
        && polished.status == ContactStatus::Converged
    {
        polished.time += solution.time;
        return polished;
    }
    solution
}

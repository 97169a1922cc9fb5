//! Frictionless contact by a primal-dual active set (semi-smooth Newton) on the condensed
//! interface.
//!
//! ```text
//! find λ ≥ 0 with gap = g0 + w h + C λ ≥ 0 and λ · gap = 0, written as  min(λ, c·gap) = 0:
//!   A = { k : λ_k − c gap_k > 0 }          (active: in contact)
//!   C_AA λ_A = −(g0 + w h)_A,  λ_I = 0     (gap closed on A, no force elsewhere)
//! until A repeats; c = 1 / mean(diag C) makes both terms the same units.
//! ```
//!
//! # References
//! Hintermüller, Ito & Kunisch (2002), SIAM J. Optim. 13(3): the primal-dual active set strategy
//! as a semi-smooth Newton method.

use web_time::Instant;

use nalgebra::{DMatrix, DVector};

use crate::algorithms::sparse_active_set::solve_sparse_active_set;
use crate::algorithms::stick_continuation::{IterationLimit, StartingStates, StickContinuation};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_forces};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, StepStart};

/// Solves the frictionless problem at load factor `w` with at most `max_iterations` active-set
/// updates (on an interface of the sparse path, [`Interface::sparse`], with the sparse state
/// equations of `sparse_active_set.rs`).
pub fn solve_frictionless_active_set(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    max_iterations: usize,
) -> ContactSolution {
    if !interface.is_condensed() {
        // The sparse path solves the problem's own friction law: a frictionless copy if it has
        // friction.
        let frictionless;
        let problem = if problem.is_frictional() {
            frictionless = {
                let mut copy = problem.clone();
                copy.friction.iter_mut().for_each(|mu| *mu = 0.0);
                copy
            };
            &frictionless
        } else {
            problem
        };
        let initial = StepStart::initial(problem.num_pairs());
        return solve_sparse_active_set(
            problem,
            interface,
            w,
            &initial,
            None,
            StartingStates::AllStick,
            IterationLimit::whole(max_iterations),
            StickContinuation::Off,
        );
    }
    let start = Instant::now();
    let m = problem.num_pairs();
    let g_free: Vec<f64> = (0..m).map(|k| problem.gap[k] + w * interface.h_normal[k]).collect();
    let mean_diag = (0..m).map(|k| interface.c_nn[(k, k)]).sum::<f64>() / m.max(1) as f64;
    let c = if mean_diag > 0.0 { 1.0 / mean_diag } else { 1.0 };
    // A pair without a normal unknown (held along its normal by fixes) is left to the fixes.
    let mut active: Vec<bool> = (0..m).map(|k| problem.normal[k] && g_free[k] < 0.0).collect();
    let mut lambda = vec![0.0; m];
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    for it in 1..=max_iterations {
        iterations = it;
        let idx: Vec<usize> = (0..m).filter(|&k| active[k]).collect();
        lambda = vec![0.0; m];
        if !idx.is_empty() {
            let c_aa = DMatrix::from_fn(idx.len(), idx.len(), |a, b| interface.c_nn[(idx[a], idx[b])]);
            let rhs = DVector::from_iterator(idx.len(), idx.iter().map(|&k| -g_free[k]));
            let Some(chol) = c_aa.cholesky() else {
                status = ContactStatus::Numerical;
                break;
            };
            let sol = chol.solve(&rhs);
            for (a, &k) in idx.iter().enumerate() {
                lambda[k] = sol[a];
            }
        }
        let gap: Vec<f64> =
            (0..m).map(|k| g_free[k] + (0..m).map(|j| interface.c_nn[(k, j)] * lambda[j]).sum::<f64>()).collect();
        let next: Vec<bool> = (0..m).map(|k| problem.normal[k] && lambda[k] - c * gap[k] > 0.0).collect();
        trace.push(IterationRecord {
            iteration: it,
            changed: next.iter().zip(&active).filter(|(a, b)| a != b).count(),
            in_contact: active.iter().filter(|a| **a).count(),
            slipping: 0,
            residual: 0.0,
        });
        if next == active {
            status = ContactStatus::Converged;
            break;
        }
        active = next;
    }
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: vec![0.0; m],
        status,
        iterations,
        time: start.elapsed(),
    };
    let mut solution = finish_from_forces(problem, interface, raw, &StepStart::initial(m));
    solution.trace = trace;
    solution
}

//! The linear equations of one contact state on the condensed interface, shared by the
//! primal-dual active set and the Boussinesq algorithm.
//!
//! ```text
//! unknowns [λ; τ] (2 × pairs); one row pair per contact pair k:
//!   free:   λ_k = 0,                         τ_k = 0
//!   stick:  gap_k = 0 (C_NN λ + C_NT τ = −g0 − w h_N),   Δs_k = 0 (C_TN λ + C_TT τ = s_start − w h_T)
//!   slip±:  gap_k = 0,                       τ_k ± μ λ_k = 0  (slip+: τ = −μλ; slip−: τ = +μλ)
//!   (no tangential unknown, or μ = 0: τ_k = 0)
//! right-hand side in two columns: per unit load w (A1) and the gaps and history (A2);
//! the state's solution at load w is w x₁ + x₂.
//! ```

use nalgebra::DMatrix;

use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{PairState, StepStart};

/// The matrix of a state and its two right-hand-side columns (A1: unit load, A2: gaps, history).
pub(crate) struct StateSystem {
    /// `2m × 2m`, nonsymmetric through the slip rows.
    pub matrix: DMatrix<f64>,
    /// `2m × 2`.
    pub rhs: DMatrix<f64>,
}

/// Builds the equations of `state`; `frictional` says whether the interface has tangential
/// compliances.
pub(crate) fn state_system(
    problem: &ContactProblem,
    interface: &Interface,
    start: &StepStart,
    state: &[PairState],
    frictional: bool,
) -> StateSystem {
    let m = state.len();
    let mut a = DMatrix::<f64>::zeros(2 * m, 2 * m);
    let mut b = DMatrix::<f64>::zeros(2 * m, 2);
    for k in 0..m {
        let (rn, rt) = (k, m + k);
        if state[k] == PairState::Free {
            a[(rn, k)] = 1.0;
            a[(rt, m + k)] = 1.0;
            continue;
        }
        for j in 0..m {
            a[(rn, j)] = interface.c_nn[(k, j)];
            if frictional {
                a[(rn, m + j)] = interface.c_nt[(k, j)];
            }
        }
        b[(rn, 0)] = -interface.h_normal[k];
        b[(rn, 1)] = -problem.gap[k];
        let mu = problem.friction[k];
        if !frictional || !problem.tangential[k] || mu == 0.0 {
            a[(rt, m + k)] = 1.0;
            continue;
        }
        match state[k] {
            PairState::Stick => {
                for j in 0..m {
                    a[(rt, j)] = interface.c_tn[(k, j)];
                    a[(rt, m + j)] = interface.c_tt[(k, j)];
                }
                b[(rt, 0)] = -interface.h_tangent[k];
                b[(rt, 1)] = start.slip[k];
            }
            PairState::SlipPositive => {
                a[(rt, m + k)] = 1.0;
                a[(rt, k)] = mu;
            }
            PairState::SlipNegative => {
                a[(rt, m + k)] = 1.0;
                a[(rt, k)] = -mu;
            }
            PairState::Free => {}
        }
    }
    StateSystem { matrix: a, rhs: b }
}

impl StateSystem {
    /// Solves for both columns at once (one LU): `[x₁ x₂]`, or `None` if singular/non-finite.
    pub(crate) fn solve(self) -> Option<DMatrix<f64>> {
        let x = self.matrix.lu().solve(&self.rhs)?;
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// `(λ, τ)` of the combination `w x₁ + x₂`.
pub(crate) fn combine(x: &DMatrix<f64>, w: f64) -> (Vec<f64>, Vec<f64>) {
    let m = x.nrows() / 2;
    let v: Vec<f64> = (0..2 * m).map(|i| w * x[(i, 0)] + x[(i, 1)]).collect();
    (v[..m].to_vec(), v[m..].to_vec())
}

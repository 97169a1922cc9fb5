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
//!
//! [`solve_state_equations`] solves only the unknowns the state leaves open: with `A` the pairs in
//! contact, `S ⊂ A` the sticking ones with a tangential unknown and `σ_j μ_j` the slip factor
//! (`τ_j = σ_j μ_j λ_j`, σ = −1 for slip+, +1 for slip−, 0 otherwise), the free pairs' rows
//! give `λ = τ = 0` and the slip rows give `τ` from `λ`, so
//!
//! ```text
//! [ C_NN[A,A] + C_NT[A,A] D   C_NT[A,S] ] [λ_A]   [ −w h_N[A] − g0[A]      ]
//! [ C_TN[S,A] + C_TT[S,A] D   C_TT[S,S] ] [τ_S] = [ −w h_T[S] + s_start[S] ],   D = diag(σ μ)
//! ```
//!
//! of size `|A| + |S|` instead of `2 × pairs`; its factorisation is kept on the interface and
//! reused while the state (and μ) stay the same (each load step starts from the previous one's
//! states, so its first iteration repeats the previous step's last matrix), factored by faer's blocked partial-pivoting LU
//! with the fixed [`contact2d_fem::parallelism`]: the same solution up to round-off, at the
//! cost of the contact zone only (a long interface with a short contact zone pays for its zone).

use faer::Mat;
use nalgebra::DMatrix;

use crate::algorithms::state_layout::{Layout, Tangential};
use crate::algorithms::state_update::{StateUpdate, UPDATE_FROM};
use crate::factor_cache::{DenseLu, StateFactor};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{PairState, StepStart};

/// The matrix of a state and its two right-hand-side columns (A1: unit load, A2: gaps, history).
#[cfg(test)]
pub(crate) struct StateSystem {
    /// `2m × 2m`, nonsymmetric through the slip rows.
    pub matrix: DMatrix<f64>,
    /// `2m × 2`.
    pub rhs: DMatrix<f64>,
}

/// Builds the full `2m × 2m` equations of `state` (the reference [`solve_state_equations`] is
/// tested against); `frictional` says whether the interface has tangential
/// compliances.
#[cfg(test)]
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

#[cfg(test)]
impl StateSystem {
    /// Solves for both columns at once (one LU): `[x₁ x₂]`, or `None` if singular/non-finite.
    pub(crate) fn solve(self) -> Option<DMatrix<f64>> {
        let x = self.matrix.lu().solve(&self.rhs)?;
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// Solves the equations of `state` on the reduced system of the module docs: `[x₁ x₂]`
/// (`2m × 2`, the same as the full system's solution up to round-off), or `None` if the
/// reduced matrix is singular or the solution not finite.
pub(crate) fn solve_state_equations(
    problem: &ContactProblem,
    interface: &Interface,
    start: &StepStart,
    state: &[PairState],
    frictional: bool,
) -> Option<DMatrix<f64>> {
    solve_regularised_state_equations(problem, interface, start, state, frictional, &[])
}

/// [`solve_state_equations`] with the stick rows regularised: `Δs_k + e_k τ_k = 0` instead of
/// `Δs_k = 0` (an elastic tangential spring of compliance `e_k` in series with the interface;
/// `stick_compliance` empty: `e = 0`, the exact equations). A state close to the one factored
/// last on a large interface is solved as a low-rank update of that factor
/// (`state_update.rs`).
pub(crate) fn solve_regularised_state_equations(
    problem: &ContactProblem,
    interface: &Interface,
    start: &StepStart,
    state: &[PairState],
    frictional: bool,
    stick_compliance: &[f64],
) -> Option<DMatrix<f64>> {
    let m = state.len();
    let layout = Layout::of(problem, state, frictional);
    let (contact, stick, tangential) = (&layout.contact, &layout.stick, &layout.tangential);
    let r = layout.size();
    let mut x = DMatrix::<f64>::zeros(2 * m, 2);
    if r == 0 {
        return Some(x);
    }
    let compliance_bits = stick_compliance.iter().map(|e| e.to_bits()).collect();
    let key = (state.to_vec(), problem.friction.clone(), problem.tangential.clone(), frictional, compliance_bits);
    let mut cache = interface.last_state.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let hit = cache.as_ref().is_some_and(|c| c.key == key && c.lu.size() == r);
    if !hit && let Some(base) = cache.as_mut() {
        let system = StateUpdate { problem, interface, frictional, stick_compliance, from: UPDATE_FROM };
        if let Some(z) = system.solve(base, &key, &layout, &layout.full_rhs(problem, interface, start)) {
            drop(cache);
            for c in 0..2 {
                for i in 0..2 * m {
                    x[(i, c)] = z[(i, c)];
                }
            }
            return x.iter().all(|v| v.is_finite()).then_some(x);
        }
    }
    let mut a = if hit { Mat::<f64>::zeros(0, 0) } else { Mat::<f64>::zeros(r, r) };
    let mut b = Mat::<f64>::zeros(r, 2);
    let rows = layout.rows();
    for (i, &(k, normal)) in rows.iter().enumerate() {
        if normal {
            b[(i, 0)] = -interface.h_normal[k];
            b[(i, 1)] = -problem.gap[k];
        } else {
            b[(i, 0)] = -interface.h_tangent[k];
            b[(i, 1)] = start.slip[k];
        }
    }
    if !hit {
        // Column by column: the compliances and `a` are column-major, so both are read and
        // written along their columns.
        for (jc, &j) in contact.iter().enumerate() {
            let nn = interface.c_nn.column(j);
            // The tangential compliances exist (the interface is frictional) whenever a pair
            // has a tangential unknown or a stick row.
            let tangents = (tangential[j] != Tangential::Zero || !stick.is_empty())
                .then(|| (interface.c_nt.column(j), interface.c_tn.column(j), interface.c_tt.column(j)));
            for (i, &(row, normal)) in rows.iter().enumerate() {
                let (c_n, c_t) = match (&tangents, normal) {
                    (None, _) => (nn[row], 0.0),
                    (Some((nt, _, _)), true) => (nn[row], nt[row]),
                    (Some((_, tn, tt)), false) => (tn[row], tt[row]),
                };
                let mut v = c_n;
                match tangential[j] {
                    Tangential::Slip(f) => v += c_t * f,
                    Tangential::Unknown(col) => a[(i, col)] = c_t,
                    Tangential::Zero => {}
                }
                a[(i, jc)] = v;
            }
        }
        for (si, &k) in stick.iter().enumerate() {
            if let Some(&e) = stick_compliance.get(k) {
                a[(contact.len() + si, contact.len() + si)] += e;
            }
        }
    }
    if !hit {
        let carried = cache.as_ref().and_then(|c| c.compliance_row_norm);
        *cache = Some(StateFactor::new(key, DenseLu::factor(a), carried));
    }
    let factored = cache.as_ref()?;
    if (0..r).any(|i| factored.lu.pivot(i) == 0.0) {
        return None;
    }
    factored.lu.solve_in_place(&mut b);
    drop(cache);
    for (jc, &j) in contact.iter().enumerate() {
        for c in 0..2 {
            let l = b[(jc, c)];
            x[(j, c)] = l;
            x[(m + j, c)] = match tangential[j] {
                Tangential::Zero => 0.0,
                Tangential::Unknown(col) => b[(col, c)],
                Tangential::Slip(f) => f * l,
            };
        }
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// `(λ, τ)` of the combination `w x₁ + x₂`.
pub(crate) fn combine(x: &DMatrix<f64>, w: f64) -> (Vec<f64>, Vec<f64>) {
    let m = x.nrows() / 2;
    let v: Vec<f64> = (0..2 * m).map(|i| w * x[(i, 0)] + x[(i, 1)]).collect();
    (v[..m].to_vec(), v[m..].to_vec())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
    use contact2d_mesh::CellKind;
    use proptest::prelude::*;

    use super::*;
    use crate::interface::Interface;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]
        /// The reduced system and the full `2m × 2m` system (a second, independent elimination)
        /// give the same forces for any state, with and without friction and history.
        #[test]
        fn reduced_system_matches_the_full_one(
            picks in proptest::collection::vec(0usize..4, 40),
            mu in prop_oneof![Just(0.0), 0.05..0.8f64],
            slip in -1e-3..1e-3f64,
            nb in 3usize..7,
        ) {
            let mut problem = crate::test_fixtures::two_blocks(CellKind::Quad9, 0.0, 0.004, 2.0, 0.05, 5, nb);
            problem.set_friction(mu).unwrap();
            let interface = Interface::new(&problem);
            let m = problem.num_pairs();
            let state: Vec<PairState> = (0..m).map(|k| PairState::ALL[picks[k % picks.len()]]).collect();
            let start = StepStart {
                slip: (0..m).map(|k| slip * (k as f64 - 2.0)).collect(),
                tangential_force: vec![0.0; m],
            };
            let frictional = interface.c_tt.nrows() == m;
            let full = state_system(&problem, &interface, &start, &state, frictional).solve().unwrap();
            let reduced = solve_state_equations(&problem, &interface, &start, &state, frictional).unwrap();
            // Both are backward-stable LU solutions of systems whose condition number is that of
            // the compliances of a few-cell mesh (< 1e6): they agree to ~1e6 ε ≈ 2e-10 of the
            // largest force; 1e-8 leaves a margin for the slip rows' coupling.
            for c in 0..2 {
                let scale = (0..2 * m).fold(f64::MIN_POSITIVE, |a, i| a.max(full[(i, c)].abs()));
                for i in 0..2 * m {
                    prop_assert!((full[(i, c)] - reduced[(i, c)]).abs() <= 1e-8 * scale,
                        "column {c} row {i}: full {} reduced {}", full[(i, c)], reduced[(i, c)]);
                }
            }
        }
    }
}

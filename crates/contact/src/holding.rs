//! Whether friction can hold the floating pieces at all: the rigid-body statics of the pieces on
//! their pairs, a small linear programme (a lower-bound limit analysis).
//!
//! A body held only by contact is in equilibrium only if the pairs' forces balance its load in
//! every rigid mode (`floating.rs`: `K R = 0`, so `Rᵀ(f + B_Nᵀλ + B_Tᵀτ) = 0`). Whatever the
//! deformation, those forces lie in the friction cones. So the step's load can be held only if
//!
//! ```text
//! find λ, τ:   Rᵀ B_Nᵀ λ + Rᵀ B_Tᵀ τ = −Rᵀ f,   λ ≥ 0,   |τ_i| ≤ k μ_i λ_i      (P_k)
//! ```
//!
//! is feasible at `k = 1`, over every pair of the problem (open ones included: a piece may land
//! on them). The least `k` for which (P_k) is feasible is the friction the load demands against
//! the friction available, at the least demanding distribution of the normal forces:
//!
//! ```text
//! ratio = k_min,   available = Σ_i μ_i λ_i,   demanded = k_min · available
//! ```
//!
//! For a block pressed by N on a flat base and pushed sideways by F, `k_min = F / (μ N)`; on an
//! incline, `(F cos α − G sin α) / (μ (F sin α + G cos α))`. Infeasibility at `k = 1` is a proof
//! (to the programme's tolerance) that no state of the contact holds the load, so it is the
//! certificate behind [`crate::ContactStatus::NotHeld`] when the floating iteration does not find
//! the free motion itself.
//!
//! (P_k) is solved by Clarabel as a feasibility problem (no objective) and `k_min` by bisection.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus, ZeroConeT};

/// A load that (P_1) cannot balance: `k_min > 1` and the state that needs least friction.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Demand {
    /// `k_min`: the friction demanded over the friction available (> 1).
    pub ratio: f64,
    /// `Σ μ_i λ_i` at the least demanding distribution.
    pub available: f64,
    /// The pairs carrying a normal force in that distribution (indices into the problem's pairs).
    pub pairs: Vec<usize>,
    /// The virtual rigid motion (in the pieces' modes) along which the load is not held: the
    /// certificate of (P_1)'s infeasibility.
    pub direction: Vec<f64>,
}

/// One pair's columns in the modal equations: `(Rᵀ B_N,iᵀ, Rᵀ B_T,iᵀ, μ_i)`, `μ_i = 0` for a
/// frictionless pair.
pub(crate) struct PairColumns {
    pub normal: Vec<f64>,
    pub tangent: Vec<f64>,
    pub friction: f64,
}

/// The margin above 1 at which (P_k) must still be infeasible for the load to be "not held":
/// the programme's feasibility tolerance is 1e-9 of the load, so a demand within 1e-6 of the
/// friction available is not judged.
const MARGIN: f64 = 1e-6;

/// The largest ratio sought: a load that needs more friction than this (or no finite amount,
/// e.g. one that pulls a piece off its contact) is not reported as a ratio.
const LARGEST_RATIO: f64 = 1e6;

/// `Some(Demand)` when the modal load `load` (`Rᵀ f`, one entry per mode) cannot be held by the
/// pairs `pairs` at their friction coefficients (with a finite `k_min`); `None` when it can, or
/// when the programme fails to decide.
pub(crate) fn friction_demand(load: &[f64], pairs: &[PairColumns]) -> Option<Demand> {
    let scale = load.iter().map(|l| l * l).sum::<f64>().sqrt();
    if scale.is_nan() || scale <= 0.0 || pairs.is_empty() {
        return None;
    }
    let load: Vec<f64> = load.iter().map(|l| l / scale).collect();
    let Feasibility::Infeasible(direction) = feasible(&load, pairs, 1.0 + MARGIN)? else {
        return None;
    };
    // Bracket k_min: double until feasible.
    let (mut low, mut high) = (1.0 + MARGIN, 2.0);
    let mut forces = loop {
        match feasible(&load, pairs, high)? {
            Feasibility::Feasible(x) => break x,
            Feasibility::Infeasible(_) if high < LARGEST_RATIO => (low, high) = (high, 2.0 * high),
            Feasibility::Infeasible(_) => return None,
        }
    };
    // Bisection to 1e-7 relative, `high` always feasible with `forces` its solution. Clarabel
    // does not decide (insufficient progress) at `k` within about 1e-4 of `k_min`, where the
    // feasible set is a sliver: such a `k` is taken as infeasible, which only moves `low`, so the
    // ratio reported is still one at which the load is held, and it stays an upper bound.
    while high - low > 1e-7 * high {
        let middle = 0.5 * (low + high);
        match feasible(&load, pairs, middle) {
            Some(Feasibility::Feasible(x)) => (high, forces) = (middle, x),
            Some(Feasibility::Infeasible(_)) | None => low = middle,
        }
    }
    let largest = forces[..pairs.len()].iter().fold(0.0f64, |a, l| a.max(*l));
    let available = pairs.iter().zip(&forces).map(|(p, l)| p.friction * l.max(0.0)).sum::<f64>() * scale;
    let carrying = (0..pairs.len()).filter(|&i| forces[i] > 1e-9 * largest).collect();
    Some(Demand { ratio: high, available, pairs: carrying, direction })
}

enum Feasibility {
    /// `[λ, τ]` (λ of every pair, then τ of the frictional ones), in units of the load.
    Feasible(Vec<f64>),
    /// The equality rows' part of the infeasibility certificate.
    Infeasible(Vec<f64>),
}

/// Solves (P_k) for `load` (unit norm); `None` when Clarabel neither solves nor certifies.
fn feasible(load: &[f64], pairs: &[PairColumns], k: f64) -> Option<Feasibility> {
    let modes = load.len();
    let frictional: Vec<usize> = (0..pairs.len()).filter(|&i| pairs[i].friction > 0.0).collect();
    let n = pairs.len() + frictional.len();
    let (mut rows, mut columns, mut values) = (vec![], vec![], vec![]);
    let mut push = |r: usize, c: usize, v: f64| {
        if v != 0.0 {
            rows.push(r);
            columns.push(c);
            values.push(v);
        }
    };
    // The modal equations (ZeroCone): Σ λ_i n_i + Σ τ_i t_i = −load.
    for (i, pair) in pairs.iter().enumerate() {
        pair.normal.iter().enumerate().for_each(|(j, v)| push(j, i, *v));
    }
    for (q, &i) in frictional.iter().enumerate() {
        pairs[i].tangent.iter().enumerate().for_each(|(j, v)| push(j, pairs.len() + q, *v));
    }
    // The cones (NonnegativeCone, b − A x ≥ 0): −λ_i ≥ ... i.e. λ_i ≥ 0, k μ λ_i ∓ τ_i ≥ 0.
    for i in 0..pairs.len() {
        push(modes + i, i, -1.0);
    }
    for (q, &i) in frictional.iter().enumerate() {
        let row = modes + pairs.len() + 2 * q;
        for (offset, sign) in [(0, 1.0), (1, -1.0)] {
            push(row + offset, pairs.len() + q, sign);
            push(row + offset, i, -k * pairs[i].friction);
        }
    }
    let m = modes + pairs.len() + 2 * frictional.len();
    let a = CscMatrix::new_from_triplets(m, n, rows, columns, values);
    let mut b = vec![0.0; m];
    b[..modes].iter_mut().zip(load).for_each(|(b, l)| *b = -l);
    let p = CscMatrix::zeros((n, n));
    let q = vec![0.0; n];
    let cones = [ZeroConeT(modes), NonnegativeConeT(m - modes)];
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_feas(1e-10)
        .tol_infeas_abs(1e-10)
        .tol_infeas_rel(1e-10)
        .max_iter(200)
        .build()
        .ok()?;
    let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, settings).ok()?;
    solver.solve();
    let solution = &solver.solution;
    match solution.status {
        SolverStatus::Solved => Some(Feasibility::Feasible(solution.x.clone())),
        SolverStatus::PrimalInfeasible => Some(Feasibility::Infeasible(solution.z[..modes].to_vec())),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

    use super::*;

    /// A rigid block on a flat base at two corner pairs x = ±1 (modes: u1, u2, rotation about
    /// the centre, base normal +y at y = −1): the pairs' forces in the modes.
    fn block_pairs(mu: f64) -> Vec<PairColumns> {
        [-1.0, 1.0]
            .iter()
            .map(|&x| PairColumns {
                // A force λ (0, 1) at (x, −1): modal (0, λ, x λ).
                normal: vec![0.0, 1.0, x],
                // A force τ (1, 0) at (x, −1): modal (τ, 0, τ).
                tangent: vec![1.0, 0.0, 1.0],
                friction: mu,
            })
            .collect()
    }

    #[test]
    fn a_block_pushed_past_mu_n_demands_f_over_mu_n() {
        // Weight N = 1 down, push F = 0.5 along x through the centre, μ = 0.3:
        // F / (μ N) = 5/3; available μ N = 0.3 (times the load's norm).
        let (n, f, mu) = (1.0, 0.5, 0.3);
        let load = [f, -n, 0.0];
        let demand = friction_demand(&load, &block_pairs(mu)).expect("not held");
        assert!((demand.ratio - f / (mu * n)).abs() < 1e-5, "{}", demand.ratio);
        assert!((demand.available - mu * n).abs() < 1e-5, "{}", demand.available);
        // The certificate is a virtual motion along which the load does positive work (Farkas:
        // bᵀz < 0 with b = −load) and that moves the block along the push.
        let work: f64 = load.iter().zip(&demand.direction).map(|(l, d)| l * d).sum();
        assert!(work > 0.0 && demand.direction[0] > 0.0, "{:?}", demand.direction);
    }

    #[test]
    fn a_push_below_mu_n_is_held_and_a_pull_off_has_no_ratio() {
        assert!(friction_demand(&[0.29, -1.0, 0.0], &block_pairs(0.3)).is_none());
        // Pulled up: no normal force can hold it, whatever the friction.
        assert!(friction_demand(&[0.1, 1.0, 0.0], &block_pairs(0.3)).is_none());
    }
}

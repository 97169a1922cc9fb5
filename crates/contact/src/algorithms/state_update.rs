//! The equations of a state close to the one factored last, as a low-rank update of that
//! factor (Sherman–Morrison–Woodbury), for the active set's later iterations on long
//! interfaces.
//!
//! ```text
//! F(s) z = b    the full 2m × 2m system of state s, z = [λ; τ] (state_equations.rs: one gap row
//!               and one tangential row per pair; a free pair's gap row and a τ-less pair's
//!               tangential row are rows of the identity, a slipping pair's is τ_k − f_k λ_k)
//! F_b⁻¹ y       from the base state's reduced LU R: the trivial unknowns (free λ, the τ of the
//!               identity and slip rows) take t₀ = y at their rows, the open ones
//!               o = R⁻¹ (y_O − F_OT t₀), then τ_slip = t₀ + f λ
//! F(s) = F_b + U D     U: unit columns of the p full rows whose kind changed (free ↔ contact,
//!                      stick ↔ slip±), D: the p rows' differences (p × 2m)
//! z  = z₀ − Z S⁻¹ D z₀,    z₀ = F_b⁻¹ b,  Z = F_b⁻¹ U (kept per row while the base lives),
//!                          S = I + D Z  (p × p)
//! accepted if ‖b − F(s) z‖∞ ≤ 1e-14 (‖F‖∞ ‖z‖∞ + ‖b‖∞), after one step of iterative
//! refinement if it is not at first
//! ```
//!
//! Why: on a long interface the iterations after the first few change the state of a handful
//! of pairs, while a fresh LU of the reduced system costs `2r³/3` flops (`r` ≈ 2 × the pairs in
//! contact: 16 GFlop at 1,521 pairs, most of a history's time). The update costs `p` solves with
//! the kept LU, `p² · 2m` flops for `S` and four compliance products for the residual. It is
//! tried from `r ≥ 600` with at most `r/6` rows changed; otherwise, if the accuracy test fails,
//! or if the state is the one updated last (a load step repeating the last answer's state: its
//! own factor is then reused), the caller factors the new state afresh and that factor becomes
//! the base. Its
//! solution is the fresh LU's up to round-off (both backward stable to ~1e-16 of `‖F‖ ‖z‖`).

use contact2d_fem::parallelism;
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat};
use nalgebra::DMatrix;

use crate::algorithms::state_layout::{Layout, Tangential};
use crate::factor_cache::{DenseLu, StateFactor, StateKey};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::PairState;

/// The smallest reduced system updated rather than factored afresh (below it an LU costs a few
/// milliseconds and the update's fixed costs, the compliance products, would not pay).
pub(crate) const UPDATE_FROM: usize = 600;
/// At most `r / MAX_CHANGED_FRACTION` changed rows per update (`S` and `Z` grow like `p`).
const MAX_CHANGED_FRACTION: usize = 6;
/// At most `r / MAX_KEPT_FRACTION` kept columns of `F_b⁻¹ U` per base.
const MAX_KEPT_FRACTION: usize = 3;
/// The normwise backward error an updated solution must reach (a fresh partial-pivoting LU
/// reaches ~1e-16; a solution this close solves a system within 1e-14 of `F`).
const BACKWARD_ERROR: f64 = 1e-14;

/// What a full row of the system says (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
enum RowKind {
    /// `z_i = b_i`.
    Identity,
    /// Pair `k`'s gap: `C_NN[k,·] λ + C_NT[k,·] τ`.
    Gap(usize),
    /// Pair `k`'s slip: `C_TN[k,·] λ + C_TT[k,·] τ + e_k τ_k`.
    Stick(usize),
    /// Pair `k` slipping: `τ_k − f λ_k`.
    Slip(usize, f64),
}

/// One state's layout and states, as the full system reads them.
struct FullSystem<'a> {
    state: &'a [PairState],
    layout: &'a Layout,
}

impl FullSystem<'_> {
    fn row_kind(&self, i: usize) -> RowKind {
        let m = self.state.len();
        if i < m {
            return if self.state[i] == PairState::Free { RowKind::Identity } else { RowKind::Gap(i) };
        }
        let k = i - m;
        match self.layout.tangential[k] {
            Tangential::Zero => RowKind::Identity,
            Tangential::Unknown(_) => RowKind::Stick(k),
            Tangential::Slip(f) => RowKind::Slip(k, f),
        }
    }
}

/// The compliances and constants a state's full system is made of.
pub(crate) struct StateUpdate<'a> {
    pub(crate) problem: &'a ContactProblem,
    pub(crate) interface: &'a Interface,
    pub(crate) frictional: bool,
    pub(crate) stick_compliance: &'a [f64],
    /// The smallest reduced system updated ([`UPDATE_FROM`]; smaller in tests).
    pub(crate) from: usize,
}

impl StateUpdate<'_> {
    /// The solution `z` (`2m × 2`) of the state `key` (layout `layout`, right-hand sides `b`)
    /// as an update of `base`, or `None` when the update does not apply (another friction,
    /// regularisation or flags, a small system, too many changed rows) or misses the accuracy.
    pub(crate) fn solve(
        &self,
        base: &mut StateFactor,
        key: &StateKey,
        layout: &Layout,
        b: &Mat<f64>,
    ) -> Option<Mat<f64>> {
        let r = base.lu.size();
        let same_matrix_family =
            base.key.1 == key.1 && base.key.2 == key.2 && base.key.3 == key.3 && base.key.4 == key.4;
        // A state solved twice in a row (a load step starting from the last one's answer) is
        // worth its own factor: the next solves of it are then reuses.
        let repeated = base.last_updated.as_ref() == Some(&key.0);
        // A singular base (kept by the cache even when its state was refused) updates nothing.
        if r < self.from || !same_matrix_family || repeated || !base.lu.is_regular() {
            return None;
        }
        let base_state = base.key.0.clone();
        let base_layout = Layout::of(self.problem, &base_state, self.frictional);
        let old = FullSystem { state: &base_state, layout: &base_layout };
        let new = FullSystem { state: &key.0, layout };
        let m = key.0.len();
        let changed: Vec<usize> = (0..2 * m).filter(|&i| old.row_kind(i) != new.row_kind(i)).collect();
        if changed.is_empty() {
            // Other states, the same rows (e.g. stick and slip without friction): `F_b` itself.
            let mut z = b.clone();
            self.apply_base_inverse(base, &old, &mut z);
            return Some(z);
        }
        if changed.len() * MAX_CHANGED_FRACTION > r {
            return None;
        }
        let kept = self.keep_columns(base, &old, &changed)?;
        let compliance = *base.compliance_row_norm.get_or_insert_with(|| self.compliance_row_norm());
        let norm = self.row_norm(compliance);
        let p = changed.len();
        let columns = Mat::<f64>::from_fn(2 * m, p, |i, j| base.update_columns[kept[j]].1[i]);
        let mut d = Mat::<f64>::zeros(p, 2 * m);
        for (q, &i) in changed.iter().enumerate() {
            self.add_row(&mut d, q, i, new.row_kind(i), 1.0);
            self.add_row(&mut d, q, i, old.row_kind(i), -1.0);
        }
        let par = parallelism();
        let mut s = Mat::<f64>::identity(p, p);
        matmul(s.as_mut(), Accum::Add, d.as_ref(), columns.as_ref(), 1.0, par);
        let capacitance = DenseLu::factor(s);
        if !capacitance.is_regular() {
            return None;
        }
        let woodbury = |y: &Mat<f64>| -> Mat<f64> {
            let mut z = y.clone();
            self.apply_base_inverse(base, &old, &mut z);
            let mut t = Mat::<f64>::zeros(p, y.ncols());
            matmul(t.as_mut(), Accum::Replace, d.as_ref(), z.as_ref(), 1.0, par);
            capacitance.solve_in_place(&mut t);
            matmul(z.as_mut(), Accum::Add, columns.as_ref(), t.as_ref(), -1.0, par);
            z
        };
        let accurate = |z: &Mat<f64>, residual: &Mat<f64>| {
            let inf = |v: faer::ColRef<'_, f64>| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            // (`max` passes over NaN, so finiteness is its own test.)
            z.col_iter().all(|col| col.iter().all(|v| v.is_finite()))
                && (0..b.ncols())
                    .all(|c| inf(residual.col(c)) <= BACKWARD_ERROR * (norm * inf(z.col(c)) + inf(b.col(c))))
        };
        let mut z = woodbury(b);
        let residual = self.residual(&new, &z, b);
        let mut accurate_now = accurate(&z, &residual);
        if !accurate_now {
            // One step of iterative refinement.
            z += &woodbury(&residual);
            accurate_now = accurate(&z, &self.residual(&new, &z, b));
        }
        base.last_updated = Some(key.0.clone());
        if !accurate_now {
            return None;
        }
        // The trivial rows hold exactly, as in a fresh solve: a free pair carries no force and
        // a slipping pair's τ is f λ (their right-hand sides are zero).
        for k in 0..m {
            for c in 0..b.ncols() {
                if new.row_kind(k) == RowKind::Identity {
                    z[(k, c)] = 0.0;
                }
                match new.row_kind(m + k) {
                    RowKind::Identity => z[(m + k, c)] = 0.0,
                    RowKind::Slip(_, f) => z[(m + k, c)] = f * z[(k, c)],
                    RowKind::Gap(_) | RowKind::Stick(_) => {}
                }
            }
        }
        Some(z)
    }

    /// Computes and keeps `F_b⁻¹ e_i` for the rows `changed` not kept yet, and returns where
    /// each row's column is kept; `None` if the base would then keep more than
    /// `r / MAX_KEPT_FRACTION` columns.
    fn keep_columns(&self, base: &mut StateFactor, old: &FullSystem<'_>, changed: &[usize]) -> Option<Vec<usize>> {
        let missing: Vec<usize> =
            changed.iter().copied().filter(|i| !base.update_columns.iter().any(|(row, _)| row == i)).collect();
        if (base.update_columns.len() + missing.len()) * MAX_KEPT_FRACTION > base.lu.size() {
            return None;
        }
        let n = 2 * old.state.len();
        let mut y = Mat::<f64>::from_fn(n, missing.len(), |i, j| if i == missing[j] { 1.0 } else { 0.0 });
        self.apply_base_inverse(base, old, &mut y);
        for (j, &row) in missing.iter().enumerate() {
            base.update_columns.push((row, y.col(j).iter().copied().collect()));
        }
        changed.iter().map(|i| base.update_columns.iter().position(|(row, _)| row == i)).collect()
    }

    /// `d[q, ·] += sign × F[i, ·]`, row `i` of kind `kind`.
    fn add_row(&self, d: &mut Mat<f64>, q: usize, i: usize, kind: RowKind, sign: f64) {
        let it = self.interface;
        let m = it.c_nn.nrows();
        match kind {
            RowKind::Identity => d[(q, i)] += sign,
            RowKind::Gap(k) => {
                for j in 0..m {
                    d[(q, j)] += sign * it.c_nn[(k, j)];
                    if self.frictional {
                        d[(q, m + j)] += sign * it.c_nt[(k, j)];
                    }
                }
            }
            RowKind::Stick(k) => {
                for j in 0..m {
                    d[(q, j)] += sign * it.c_tn[(k, j)];
                    d[(q, m + j)] += sign * it.c_tt[(k, j)];
                }
                d[(q, m + k)] += sign * self.stick_compliance.get(k).copied().unwrap_or(0.0);
            }
            RowKind::Slip(k, f) => {
                d[(q, m + k)] += sign;
                d[(q, k)] -= sign * f;
            }
        }
    }

    /// `y ← F_b⁻¹ y` for the base state `old` (module docs), `y` of `2m` rows.
    fn apply_base_inverse(&self, base: &StateFactor, old: &FullSystem<'_>, y: &mut Mat<f64>) {
        let it = self.interface;
        let (layout, m, k) = (old.layout, old.state.len(), y.ncols());
        let rows = layout.rows();
        let r = rows.len();
        let mut o = Mat::<f64>::from_fn(r, k, |i, c| {
            let (p, normal) = rows[i];
            y[(if normal { p } else { m + p }, c)]
        });
        // y_O − F_OT t₀: the columns of the trivial unknowns whose t₀ is nonzero (none for the
        // state's own right-hand sides, one for a unit column).
        for c in 0..k {
            for j in 0..m {
                let lambda = if old.state[j] == PairState::Free { y[(j, c)] } else { 0.0 };
                let tau = match layout.tangential[j] {
                    Tangential::Unknown(_) => 0.0,
                    _ if self.frictional => y[(m + j, c)],
                    _ => 0.0,
                };
                if lambda != 0.0 {
                    for (i, &(p, normal)) in rows.iter().enumerate() {
                        o[(i, c)] -= lambda * if normal { it.c_nn[(p, j)] } else { it.c_tn[(p, j)] };
                    }
                }
                if tau != 0.0 {
                    for (i, &(p, normal)) in rows.iter().enumerate() {
                        o[(i, c)] -= tau * if normal { it.c_nt[(p, j)] } else { it.c_tt[(p, j)] };
                    }
                }
            }
        }
        base.lu.solve_in_place(&mut o);
        let mut position = vec![usize::MAX; m];
        for (jc, &j) in layout.contact.iter().enumerate() {
            position[j] = jc;
        }
        for c in 0..k {
            for j in 0..m {
                let lambda = if position[j] == usize::MAX { y[(j, c)] } else { o[(position[j], c)] };
                y[(j, c)] = lambda;
                y[(m + j, c)] = match layout.tangential[j] {
                    Tangential::Zero => y[(m + j, c)],
                    Tangential::Unknown(col) => o[(col, c)],
                    Tangential::Slip(f) => y[(m + j, c)] + f * lambda,
                };
            }
        }
    }

    /// `b − F z` for the state `new`.
    fn residual(&self, new: &FullSystem<'_>, z: &Mat<f64>, b: &Mat<f64>) -> Mat<f64> {
        let it = self.interface;
        let (m, k) = (new.state.len(), z.ncols());
        let (lambda, tau) = (z.as_ref().subrows(0, m), z.as_ref().subrows(m, m));
        let product = |c: &DMatrix<f64>, x: faer::MatRef<'_, f64>| {
            let mut y = Mat::<f64>::zeros(m, k);
            if c.nrows() == m {
                let c = faer::MatRef::from_column_major_slice(c.as_slice(), m, m);
                matmul(y.as_mut(), Accum::Replace, c, x, 1.0, parallelism());
            }
            y
        };
        let nn = product(&it.c_nn, lambda);
        let (nt, tn, tt) = if self.frictional {
            (product(&it.c_nt, tau), product(&it.c_tn, lambda), product(&it.c_tt, tau))
        } else {
            (Mat::zeros(m, k), Mat::zeros(m, k), Mat::zeros(m, k))
        };
        Mat::<f64>::from_fn(2 * m, k, |i, c| {
            let fz = match new.row_kind(i) {
                RowKind::Identity => z[(i, c)],
                RowKind::Gap(p) => nn[(p, c)] + nt[(p, c)],
                RowKind::Stick(p) => {
                    tn[(p, c)] + tt[(p, c)] + self.stick_compliance.get(p).copied().unwrap_or(0.0) * z[(m + p, c)]
                }
                RowKind::Slip(p, f) => z[(m + p, c)] - f * z[(p, c)],
            };
            b[(i, c)] - fz
        })
    }

    /// The largest absolute row sums of the interface's compliance rows: `[C_NN]`,
    /// `[C_NN C_NT]` and `[C_TN C_TT]` (the last two zero without tangential compliances).
    fn compliance_row_norm(&self) -> [f64; 3] {
        let it = self.interface;
        let m = it.c_nn.nrows();
        let tangents = it.c_tt.nrows() == m && it.c_nt.nrows() == m && it.c_tn.nrows() == m;
        let (mut nn, mut nt, mut t) = (vec![0.0f64; m], vec![0.0f64; m], vec![0.0f64; m]);
        for j in 0..m {
            for i in 0..m {
                nn[i] += it.c_nn[(i, j)].abs();
                if tangents {
                    nt[i] += it.c_nt[(i, j)].abs();
                    t[i] += it.c_tn[(i, j)].abs() + it.c_tt[(i, j)].abs();
                }
            }
        }
        let max = |v: &[f64]| v.iter().fold(0.0f64, |a, s| a.max(*s));
        let with_nt: Vec<f64> = nn.iter().zip(&nt).map(|(a, b)| a + b).collect();
        [max(&nn), max(&with_nt), max(&t)]
    }

    /// A bound of `‖F‖∞` over every state from the compliance rows' sums: the gap rows (with
    /// `C_NT` when frictional), the slip rows with the largest regularising compliance, and
    /// `1 + max μ` of the slipping pairs' rows.
    fn row_norm(&self, [nn, with_nt, slip]: [f64; 3]) -> f64 {
        let e = self.stick_compliance.iter().fold(0.0f64, |a, e| a.max(e.abs()));
        let mu = self.problem.friction.iter().fold(0.0f64, |a, f| a.max(f.abs()));
        let rows = if self.frictional { with_nt.max(slip + e) } else { nn };
        rows.max(1.0 + mu)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
    use contact2d_mesh::CellKind;
    use proptest::prelude::*;

    use super::*;
    use crate::algorithms::state_equations::{solve_regularised_state_equations, state_system};
    use crate::solution::StepStart;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        /// A state reached from a factored one by changing a few pairs (the update path, size
        /// threshold lifted) gives the solution of its own full `2m × 2m` system, with and
        /// without friction and a regularised stick law.
        #[test]
        fn updated_solution_is_that_of_the_full_system(
            picks in proptest::collection::vec(1usize..4, 40),
            changes in proptest::collection::vec((0usize..200, 0usize..4), 1..6),
            mu in prop_oneof![Just(0.0), 0.05..0.8f64],
            regularised in any::<bool>(),
            slip in -1e-3..1e-3f64,
        ) {
            let mut problem = crate::test_fixtures::two_blocks(CellKind::Quad9, 0.0, 0.004, 2.0, 0.05, 24, 30);
            problem.set_friction(mu).unwrap();
            let interface = Interface::new(&problem);
            let m = problem.num_pairs();
            // The base in contact everywhere, so that its system (≥ m rows) takes the ≤ 10
            // changed rows as an update (at most r/6).
            let base: Vec<PairState> = (0..m).map(|k| PairState::ALL[picks[k % picks.len()]]).collect();
            let mut state = base.clone();
            for &(k, s) in &changes {
                state[k % m] = PairState::ALL[s];
            }
            let start = StepStart {
                slip: (0..m).map(|k| slip * (k as f64 - 2.0)).collect(),
                tangential_force: vec![0.0; m],
            };
            let frictional = interface.c_tt.nrows() == m;
            let compliance: Vec<f64> = if regularised { (0..m).map(|k| 1e-4 * (1.0 + k as f64 / m as f64)).collect() } else { Vec::new() };
            // Factor the base state (fresh: the cache is empty).
            prop_assume!(solve_regularised_state_equations(&problem, &interface, &start, &base, frictional, &compliance).is_some());
            let layout = Layout::of(&problem, &state, frictional);
            let key = (state.clone(), problem.friction.clone(), problem.tangential.clone(), frictional, compliance.iter().map(|e| e.to_bits()).collect());
            let rhs = layout.full_rhs(&problem, &interface, &start);
            let update = StateUpdate { problem: &problem, interface: &interface, frictional, stick_compliance: &compliance, from: 0 };
            let mut cache = interface.last_state.0.lock().unwrap();
            let Some(base_factor) = cache.as_mut() else { return Ok(()) };
            let Some(updated) = update.solve(base_factor, &key, &layout, &rhs) else {
                prop_assert!(false, "update refused");
                return Ok(());
            };
            drop(cache);
            let mut full = state_system(&problem, &interface, &start, &state, frictional);
            for &k in &layout.stick {
                if let Some(&e) = compliance.get(k) {
                    full.matrix[(m + k, m + k)] += e;
                }
            }
            let Some(full) = full.solve() else { return Ok(()) };
            // Both are backward-stable solutions (the update's backward error is tested at 1e-14
            // of ‖F‖ ‖z‖) of systems whose condition number is that of the compliances of a
            // few-cell mesh (< 1e6): they agree to ~1e6 × 1e-14 = 1e-8 of the largest force.
            for c in 0..2 {
                let scale = (0..2 * m).fold(f64::MIN_POSITIVE, |a, i| a.max(full[(i, c)].abs()));
                for i in 0..2 * m {
                    prop_assert!((full[(i, c)] - updated[(i, c)]).abs() <= 1e-8 * scale,
                        "column {c} row {i}: full {} updated {}", full[(i, c)], updated[(i, c)]);
                }
            }
        }
    }
}

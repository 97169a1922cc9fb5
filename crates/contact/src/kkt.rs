//! The equations of one contact state on the full (not condensed) system, for the sparse path
//! ([`crate::LinearSolver::Sparse`]): displacements and pair forces together, factored sparse.
//!
//! ```text
//! unknowns  x = [u_f; z_N; z_T],   λ = −s z_N,  τ = −s z_T    (s: the row scale below)
//! K u_f + s Σ_{k in contact} (b_k + f_k t_k)ᵀ z_N,k + s Σ_{k stick} t_kᵀ z_T,k = w r
//! s b_k · u_f = −s ĝ_k              (k in contact: gap_k = ĝ_k + b_k·u_f = 0)
//! s t_k · u_f − s² e_k z_T,k = s (s_start,k − ŝ_k)  (k stick: Δs_k + e_k τ_k = 0; e = 0 but in
//!                                    the regularised stages of algorithms/stick_continuation.rs)
//! z_N,k = 0 (k free),   z_T,k = 0 (k not stick: τ_k = f_k λ_k for slip, 0 otherwise)
//! b_k, t_k: free parts of B_N, B_T;  ĝ_k = g0_k + w (B_N,c u_c)_k,  ŝ_k = w (B_T,c u_c)_k
//! f_k = −μ_k (slip+), +μ_k (slip−), 0 otherwise
//! ```
//!
//! These are the condensed state equations (`algorithms/state_equations.rs`) before `u_f` is
//! eliminated: the same solution. The matrix is symmetric except for the slip pairs' friction
//! columns `f_k t_kᵀ`. Its symmetric part `A_sym` (slip pairs as frictionless contact pairs) is
//! factored by [`contact2d_fem::SaddlePointSolver`] (symbolic analysis once per interface,
//! numeric per change of the pairs in contact or sticking), and the whole matrix is solved by
//! GMRES right-preconditioned with that factor:
//!
//! ```text
//! A A_sym⁻¹ = I + F A_sym⁻¹,   F = the friction columns: rank ≤ #slip, relative size ~ μ
//! ```
//!
//! so GMRES converges in a few iterations (one without slip). (A stale factor of the previous
//! state as the preconditioner, `A` then differing by a low-rank term as well, was measured:
//! GMRES needed 15–30 iterations, and a solve with the factor costs a third of a refactorisation
//! at 579k DOFs (0.095 s against 0.28 s: it reads `L` twice and is bound by memory bandwidth);
//! refactoring is cheaper than that, and than an exact low-rank update, which needs one or two
//! such solves per changed row.) The active set solves its trial states to a relative residual
//! of 1e-4 ([`Accuracy::Trial`]) and the state that repeats to 1e-14 or the round-off floor
//! ([`Accuracy::Final`], warm-started). The row scale `s = k_c` (the contact stiffness of the pairs,
//! `algorithms/full_system.rs`) gives the constraint rows the units of the force rows, so that
//! GMRES's residual weighs both alike.

use contact2d_fem::{FemError, SaddlePointSolver};
use rayon::prelude::*;

use crate::problem::ContactProblem;
use crate::solution::{PairState, StepStart};

/// GMRES iterations allowed per solve (a safeguard: friction columns converge in a handful).
const BUDGET: usize = 200;

/// How accurately a state is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Accuracy {
    /// Relative residual 1e-4: enough to choose the next state while the iteration moves.
    Trial,
    /// Relative residual 1e-14, or the residual's round-off floor `ε (‖b‖ + ‖|A| |x|‖)` where
    /// that is larger: the answer.
    Final,
}

impl Accuracy {
    fn tolerance(self) -> f64 {
        match self {
            Accuracy::Trial => 1e-4,
            Accuracy::Final => 1e-14,
        }
    }
}

/// The largest relative residual accepted as the round-off floor: the floor is set by
/// round-off in `A x` itself (`ε ‖|A| |x|‖`, which exceeds `1e-14 ‖b‖` where the forces in
/// `K u` nearly cancel: 3e-14 at 37k DOFs, 1e-11 at 952k DOFs on the long-interface benchmark). A sanity bound, not the accuracy: GMRES
/// preconditioned by the exact factor reduces the residual geometrically until that floor.
const ROUND_OFF_FLOOR: f64 = 1e-9;

/// Krylov vectors kept before GMRES restarts (two vectors of the system's size each: 120 MB at
/// 952k DOFs; the solves converge in a few iterations or stop at the round-off floor).
const RESTART: usize = 8;

/// The sparse state system of an interface: the analysed saddle-point factor and which rows
/// its last numeric factorisation switched on.
#[derive(Debug)]
pub(crate) struct StateKkt {
    solver: SaddlePointSolver,
    /// Rows switched on in the last factorisation (normal rows, then tangential rows), and the
    /// bits of the stick compliances it was factored with.
    factored: Option<(Vec<bool>, Vec<u64>)>,
    /// Row scale `s`.
    scale: f64,
    /// Whether the tangential rows are part of the system.
    frictional: bool,
    /// The active set's complementarity constants `(c_N, c_T)`, computed once per interface.
    pub(crate) constants: (f64, f64),
    /// Numeric factorisations and GMRES iterations done (statistics).
    pub(crate) factorizations: usize,
    pub(crate) krylov_iterations: usize,
    /// The unknowns of the last solve: the warm start of the next solve given none (the next
    /// coarse level, the next inner solve of a floating iteration, the next step).
    last: Option<Vec<f64>>,
}

/// A state's solution: forces and free displacements.
pub(crate) struct StateSolution {
    pub(crate) normal_force: Vec<f64>,
    pub(crate) tangential_force: Vec<f64>,
    pub(crate) displacement: Vec<f64>,
    /// All unknowns `x` (a warm start for the same state).
    pub(crate) unknowns: Vec<f64>,
}

/// How pair `k`'s tangential force follows from its state.
fn slip_factor(problem: &ContactProblem, state: PairState, k: usize, frictional: bool) -> f64 {
    if !frictional || !problem.tangential[k] {
        return 0.0;
    }
    match state {
        PairState::SlipPositive => -problem.friction[k],
        PairState::SlipNegative => problem.friction[k],
        PairState::Free | PairState::Stick => 0.0,
    }
}

/// Whether pair `k` has its stick row on.
fn sticks(problem: &ContactProblem, state: PairState, k: usize, frictional: bool) -> bool {
    frictional && state == PairState::Stick && problem.tangential[k] && problem.friction[k] > 0.0
}

impl StateKkt {
    /// Analyses the system of `problem` (every normal row and, when `frictional`, every
    /// tangential row) with row scale `scale`; the complementarity constants are zero until
    /// the caller sets them.
    ///
    /// # Errors
    /// From the analysis.
    pub(crate) fn new(problem: &ContactProblem, frictional: bool, scale: f64) -> Result<StateKkt, FemError> {
        let scaled = |rows: &[crate::problem::PairRow]| -> Vec<Vec<(usize, f64)>> {
            rows.iter().map(|r| r.free.iter().map(|&(j, v)| (j, scale * v)).collect()).collect()
        };
        let mut rows = scaled(&problem.normal_rows);
        if frictional {
            rows.extend(scaled(&problem.tangent_rows));
        }
        let refs: Vec<&[(usize, f64)]> = rows.iter().map(Vec::as_slice).collect();
        let solver = SaddlePointSolver::analyse(&problem.system.stiffness, &refs)?;
        Ok(StateKkt {
            solver,
            factored: None,
            scale,
            frictional,
            constants: (0.0, 0.0),
            factorizations: 0,
            krylov_iterations: 0,
            last: None,
        })
    }

    /// Order of the state system: the free DOFs, then every row analysed.
    pub(crate) fn dim(&self) -> usize {
        self.solver.dim() + self.solver.row_count()
    }

    /// `K_ff⁻¹ b` in the first `n` entries of each column of `b` (of [`StateKkt::dim`] entries,
    /// zero beyond `n`), in place: one multi-RHS solve with the factor of the state system with
    /// every row switched off, `[K_ff 0; 0 I]`. The sparse path's solves with `K_ff` alone, so
    /// that it needs no factor of `K_ff` of its own (`crate::stiffness_factor`). `false` if that
    /// factorisation fails (`K_ff` not positive definite).
    pub(crate) fn solve_stiffness_many(&mut self, b: &mut faer::Mat<f64>) -> bool {
        let key = (vec![false; self.solver.row_count()], vec![]);
        if self.factored.as_ref() != Some(&key) {
            self.factored = None;
            if self.solver.factor(&key.0).is_err() {
                return false;
            }
            self.factored = Some(key);
            self.factorizations += 1;
        }
        self.solver.solve_many_in_place(b.as_mut())
    }

    /// Whether the tangential rows are part of the system.
    pub(crate) fn is_frictional(&self) -> bool {
        self.frictional
    }

    /// Rows of `A_sym` switched on for `state`.
    fn rows_on(&self, problem: &ContactProblem, state: &[PairState]) -> Vec<bool> {
        let m = state.len();
        let mut on: Vec<bool> = (0..m).map(|k| state[k] != PairState::Free && problem.normal[k]).collect();
        if self.frictional {
            on.extend((0..m).map(|k| sticks(problem, state[k], k, true)));
        }
        on
    }

    /// Solves the state equations of the module docs at load `w` from `start` to the relative
    /// residual `accuracy`, GMRES starting from `warm` (a previous solution of this solve) or,
    /// given none and solving to round-off, from the last solve's unknowns on this interface (the
    /// previous coarse level, inner solve or step: GMRES to round-off from zero took 7–9
    /// iterations a state on the coarse levels of a floating pad at 3,001 pairs, each a solve
    /// with the factor), dropped for zero where its residual exceeds `‖b‖`; with the stick rows'
    /// compliances `e` (empty: the exact law); `None` if the
    /// factorisation fails (dependent rows in contact) or GMRES does not converge.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn solve(
        &mut self,
        problem: &ContactProblem,
        w: f64,
        start: &StepStart,
        state: &[PairState],
        accuracy: Accuracy,
        warm: Option<&[f64]>,
        compliances: &[f64],
    ) -> Option<StateSolution> {
        let (n, m) = (problem.system.dofs.num_free(), state.len());
        let on = self.rows_on(problem, state);
        // The constraint block's diagonal −s² e_k on the stick rows (module docs).
        let s2 = self.scale * self.scale;
        let diagonal: Vec<f64> = if compliances.is_empty() || !self.frictional {
            vec![]
        } else {
            (0..2 * m).map(|q| if q >= m && on[q] { s2 * compliances[q - m] } else { 0.0 }).collect()
        };
        let key = (on.clone(), diagonal.iter().map(|v| v.to_bits()).collect::<Vec<u64>>());
        if self.factored.as_ref() != Some(&key) {
            self.factored = None;
            self.solver.factor_with_compliance(&on, &diagonal).ok()?;
            self.factored = Some(key);
            self.factorizations += 1;
        }
        let system =
            Operator { problem, state, on: &on, scale: self.scale, frictional: self.frictional, diagonal: &diagonal };
        let b = system.rhs(w, start);
        // Only a solve to round-off starts from another solve's unknowns: a trial solve could
        // stop at once on them (their residual already below 1e-4 of `‖b‖`) and return the
        // other solve's answer as this state's.
        let last = if accuracy == Accuracy::Final { self.last.take() } else { None };
        let warm = warm.map(<[f64]>::to_vec).or(last);
        let x = self.gmres(&system, &b, warm.as_deref(), accuracy.tolerance())?;
        self.last = Some(x.clone());
        let s = self.scale;
        let normal_force: Vec<f64> = (0..m).map(|k| if on[k] { -s * x[n + k] } else { 0.0 }).collect();
        let tangential_force = (0..m)
            .map(|k| {
                if self.frictional && on[m + k] {
                    -s * x[n + m + k]
                } else {
                    slip_factor(problem, state[k], k, self.frictional) * normal_force[k]
                }
            })
            .collect();
        Some(StateSolution { normal_force, tangential_force, displacement: x[..n].to_vec(), unknowns: x })
    }

    /// Restarted GMRES on `A x = b`, right-preconditioned by the last factor, from `warm` (or
    /// zero), at most [`BUDGET`] iterations; `None` unless `‖b − A x‖ ≤ tolerance ‖b‖` or the
    /// residual stalls below [`ROUND_OFF_FLOOR`] `‖b‖` (or on breakdown).
    fn gmres(&mut self, system: &Operator, b: &[f64], warm: Option<&[f64]>, tolerance: f64) -> Option<Vec<f64>> {
        let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let scale = norm(b);
        let mut x = match warm {
            Some(w) if w.len() == b.len() => w.to_vec(),
            _ => vec![0.0; b.len()],
        };
        if scale == 0.0 {
            return Some(vec![0.0; b.len()]);
        }
        // Below the round-off of the residual itself no iteration can be told from another:
        // `|fl(b − A x) − (b − A x)| ≲ ε (|b| + |A| |x|)`, the floor a tolerance finer than
        // the trial one stops at (measured at 579k DOFs: a floor of 2.2e-9 against
        // ‖b‖ = 156, where GMRES's estimates went on falling tenfold per solve, unverifiably,
        // down to 1e-14 ‖b‖).
        let target_from = |x: &[f64]| {
            let target = tolerance * scale;
            if tolerance < ROUND_OFF_FLOOR {
                target.max(f64::EPSILON * (scale + norm(&system.apply_magnitude(x))))
            } else {
                target
            }
        };
        let mut target = target_from(&x);
        let mut used = 0;
        let mut previous = f64::INFINITY;
        // Whether the last cycle ended with GMRES's own residual estimate below the target.
        let mut estimated = false;
        // A warm start further from the answer than zero is (another state's, another load's)
        // is dropped.
        let mut judge_warm = warm.is_some();
        loop {
            let mut r = system.apply(&x);
            r.iter_mut().zip(b).for_each(|(r, b)| *r = b - *r);
            let beta = norm(&r);
            if std::mem::take(&mut judge_warm) && beta > scale {
                x.iter_mut().for_each(|v| *v = 0.0);
                target = target_from(&x);
                continue;
            }
            // Converged; or at the round-off floor of the residual: the last cycle's estimate
            // reached the target but the true residual did not, or a whole cycle did not halve
            // it (the floor is checked against ROUND_OFF_FLOOR ‖b‖).
            let floor = (estimated || beta > 0.5 * previous) && beta <= ROUND_OFF_FLOOR * scale;
            if beta <= target || floor {
                return x.iter().all(|v| v.is_finite()).then_some(x);
            }
            if used >= BUDGET {
                return None;
            }
            previous = beta;
            let steps = RESTART.min(BUDGET - used);
            let mut basis: Vec<Vec<f64>> = vec![r.iter().map(|v| v / beta).collect()];
            let mut preconditioned: Vec<Vec<f64>> = vec![];
            let mut h: Vec<Vec<f64>> = vec![];
            let (mut cs, mut sn): (Vec<f64>, Vec<f64>) = (vec![], vec![]);
            let mut g = vec![beta];
            for j in 0..steps {
                used += 1;
                self.krylov_iterations += 1;
                let mut z = basis[j].clone();
                if !self.solver.solve_in_place(&mut z) {
                    return None;
                }
                let mut v = system.apply(&z);
                preconditioned.push(z);
                // Modified Gram–Schmidt, twice (the Krylov vectors stay orthogonal to round-off).
                let mut column = vec![0.0; j + 2];
                for _ in 0..2 {
                    for (i, q) in basis.iter().enumerate() {
                        let d: f64 = q.iter().zip(&v).map(|(a, b)| a * b).sum();
                        column[i] += d;
                        v.iter_mut().zip(q).for_each(|(v, q)| *v -= d * q);
                    }
                }
                column[j + 1] = norm(&v);
                for i in 0..j {
                    let (a, c) = (column[i], column[i + 1]);
                    column[i] = cs[i] * a + sn[i] * c;
                    column[i + 1] = -sn[i] * a + cs[i] * c;
                }
                let (a, c) = (column[j], column[j + 1]);
                let radius = a.hypot(c);
                if radius == 0.0 {
                    return None;
                }
                cs.push(a / radius);
                sn.push(c / radius);
                column[j] = radius;
                column[j + 1] = 0.0;
                g.push(-sn[j] * g[j]);
                g[j] *= cs[j];
                let next_norm = norm(&v);
                h.push(column);
                estimated = g[j + 1].abs() <= 0.5 * target;
                if estimated || next_norm == 0.0 || j + 1 == steps {
                    // y = H⁻¹ g (upper triangular), x += Σ y_i M⁻¹ v_i.
                    let k = j + 1;
                    let mut y = vec![0.0; k];
                    for i in (0..k).rev() {
                        let s: f64 = (i + 1..k).map(|l| h[l][i] * y[l]).sum();
                        y[i] = (g[i] - s) / h[i][i];
                    }
                    for (yi, zi) in y.iter().zip(&preconditioned) {
                        x.iter_mut().zip(zi).for_each(|(x, z)| *x += yi * z);
                    }
                    break;
                }
                basis.push(v.iter().map(|x| x / next_norm).collect());
            }
        }
    }
}

/// The exact matrix of a state (module docs) as an operator.
struct Operator<'a> {
    problem: &'a ContactProblem,
    state: &'a [PairState],
    on: &'a [bool],
    scale: f64,
    frictional: bool,
    /// `s² e_k` of each stick row (index `m + k`; empty: none).
    diagonal: &'a [f64],
}

impl Operator<'_> {
    /// The right-hand side `[w r; s rhs_N; s rhs_T]` at load `w`.
    fn rhs(&self, w: f64, start: &StepStart) -> Vec<f64> {
        let p = self.problem;
        let m = self.state.len();
        let prescribed: Vec<f64> = p.pattern_prescribed.iter().map(|v| w * v).collect();
        let constrained =
            |row: &crate::problem::PairRow| row.constrained.iter().map(|(j, v)| v * prescribed[*j]).sum::<f64>();
        let mut b: Vec<f64> = p.pattern_rhs.iter().map(|r| w * r).collect();
        b.extend((0..m).map(
            |k| {
                if self.on[k] { -self.scale * (p.gap[k] + constrained(&p.normal_rows[k])) } else { 0.0 }
            },
        ));
        if self.frictional {
            b.extend((0..m).map(|k| {
                if self.on[m + k] { self.scale * (start.slip[k] - constrained(&p.tangent_rows[k])) } else { 0.0 }
            }));
        }
        b
    }

    /// `A x`.
    fn apply(&self, x: &[f64]) -> Vec<f64> {
        self.product::<false>(x)
    }

    /// `|A| |x|`: the scale of the round-off in `A x` (`|fl(A x) − A x| ≤ γ |A| |x|`).
    fn apply_magnitude(&self, x: &[f64]) -> Vec<f64> {
        let x: Vec<f64> = x.iter().map(|v| v.abs()).collect();
        self.product::<true>(&x)
    }

    /// `A x`, or with `MAGNITUDE` every coefficient of `A` taken by its magnitude.
    fn product<const MAGNITUDE: bool>(&self, x: &[f64]) -> Vec<f64> {
        let a = |v: f64| if MAGNITUDE { v.abs() } else { v };
        let p = self.problem;
        let (n, m, s) = (p.system.dofs.num_free(), self.state.len(), a(self.scale));
        let k = p.system.stiffness.as_ref();
        // `K x` from the lower triangle, by blocks of columns in parallel, the blocks' parts
        // summed in block order: the same bits on any number of threads.
        let blocks = column_blocks(k.col_ptr(), PRODUCT_BLOCKS);
        let parts: Vec<Vec<f64>> = blocks
            .par_iter()
            .copied()
            .map(|(first, end)| {
                // Block [first, end) reaches rows first.. only (the lower triangle).
                let mut part = vec![0.0; n - first];
                for j in first..end {
                    for (i, &v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
                        let v = a(v);
                        part[i - first] += v * x[j];
                        if i != j {
                            part[j - first] += v * x[i];
                        }
                    }
                }
                part
            })
            .collect();
        let mut y = vec![0.0; x.len()];
        for (part, &(first, _)) in parts.iter().zip(&blocks) {
            y[first..n].iter_mut().zip(part).for_each(|(y, p)| *y += p);
        }
        let dot = |row: &crate::problem::PairRow| row.free.iter().map(|&(i, v)| a(v) * x[i]).sum::<f64>();
        for kk in 0..m {
            let (row_n, row_t) = (&p.normal_rows[kk], &p.tangent_rows[kk]);
            if self.on[kk] {
                let z = s * x[n + kk];
                row_n.free.iter().for_each(|&(i, v)| y[i] += a(v) * z);
                let f = a(slip_factor(p, self.state[kk], kk, self.frictional));
                if f != 0.0 {
                    row_t.free.iter().for_each(|&(i, v)| y[i] += f * a(v) * z);
                }
                y[n + kk] = s * dot(row_n);
            } else {
                y[n + kk] = x[n + kk];
            }
            if self.frictional {
                let q = n + m + kk;
                if self.on[m + kk] {
                    let z = s * x[q];
                    row_t.free.iter().for_each(|&(i, v)| y[i] += a(v) * z);
                    let d = self.diagonal.get(m + kk).map_or(0.0, |d| a(*d) * x[q]);
                    y[q] = if MAGNITUDE { s * dot(row_t) + d } else { s * dot(row_t) - d };
                } else {
                    y[q] = x[q];
                }
            }
        }
        y
    }
}

/// Column blocks of `K`'s product in [`Operator`] (a constant, not the thread count, so that
/// the product's bits are the same on any machine).
const PRODUCT_BLOCKS: usize = 4;

/// `blocks` ranges `[first, end)` of the columns with about equal numbers of entries (from the
/// column pointers `col_ptr`).
fn column_blocks(col_ptr: &[usize], blocks: usize) -> Vec<(usize, usize)> {
    let n = col_ptr.len() - 1;
    let nnz = col_ptr[n];
    let mut ranges = Vec::with_capacity(blocks);
    let mut first = 0;
    for b in 1..=blocks {
        let end = if b == blocks { n } else { col_ptr.partition_point(|&p| p < nnz * b / blocks).min(n).max(first) };
        ranges.push((first, end));
        first = end;
    }
    ranges
}

/// The state system an interface keeps for the sparse path (a cache, like
/// [`crate::factor_cache::StateFactorCache`]: a clone starts empty).
#[derive(Debug, Default)]
pub(crate) struct KktCache(pub(crate) std::sync::Mutex<Option<StateKkt>>);

impl Clone for KktCache {
    fn clone(&self) -> KktCache {
        KktCache::default()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
    use contact2d_mesh::CellKind;

    use super::*;
    use crate::algorithms::full_system::contact_stiffness;

    /// A solve to round-off given no warm start starts from the last solve's unknowns, and one
    /// whose residual exceeds `‖b‖` is dropped: each answer is the cold solve's. Truth: the
    /// same state's solution from zero; GMRES stops at 1e-14 of `‖b‖` or the round-off floor, so
    /// the solutions agree to ~1e-12 of the largest force (1e-10 leaves margin).
    #[test]
    fn a_solve_starts_from_the_last_ones_unknowns_or_from_zero() {
        let mut problem = crate::test_fixtures::two_blocks(CellKind::Quad9, 0.0, 0.005, 2.0, 0.05, 6, 4);
        problem.set_friction(0.3).unwrap();
        let m = problem.num_pairs();
        let start = StepStart::initial(m);
        let state = vec![PairState::Stick; m];
        let mut kkt = StateKkt::new(&problem, true, contact_stiffness(&problem)).unwrap();
        let cold = kkt.solve(&problem, 1.0, &start, &state, Accuracy::Final, None, &[]).unwrap();
        assert!(kkt.last.is_some());
        let scale = cold.normal_force.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        assert!(scale > 0.0);
        let agree = |x: &StateSolution| {
            x.normal_force.iter().zip(&cold.normal_force).all(|(a, b)| (a - b).abs() <= 1e-10 * scale)
                && x.tangential_force.iter().zip(&cold.tangential_force).all(|(a, b)| (a - b).abs() <= 1e-10 * scale)
        };
        // From the last solve's unknowns (the same state: GMRES has nothing left to do).
        let before = kkt.krylov_iterations;
        let again = kkt.solve(&problem, 1.0, &start, &state, Accuracy::Final, None, &[]).unwrap();
        assert!(agree(&again));
        assert!(kkt.krylov_iterations - before <= 1, "{} iterations", kkt.krylov_iterations - before);
        // A warm start a million times the answer: dropped for zero.
        let far: Vec<f64> = cold.unknowns.iter().map(|v| 1e6 * v + 1.0).collect();
        let dropped = kkt.solve(&problem, 1.0, &start, &state, Accuracy::Final, Some(&far), &[]).unwrap();
        assert!(agree(&dropped));
        // A trial solve never starts from another solve's unknowns: given the answer itself as
        // the last solve's, it still solves from zero (GMRES iterates), where it would have
        // stopped at once and returned the other solve's unknowns.
        kkt.last = Some(cold.unknowns.clone());
        let before = kkt.krylov_iterations;
        let trial = kkt.solve(&problem, 1.0, &start, &state, Accuracy::Trial, None, &[]).unwrap();
        assert!(kkt.krylov_iterations > before);
        // Its relative residual of 1e-4: on this small mesh the forces within 1e-3 of the largest.
        assert!(trial.normal_force.iter().zip(&cold.normal_force).all(|(a, b)| (a - b).abs() <= 1e-3 * scale));
    }
}

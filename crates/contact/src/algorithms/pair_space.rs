//! The penalty and augmented Lagrangian methods on the condensed interface: every linear system
//! of their Newton iterations solved exactly in the pairs' rows (the Schur complement of `K`, i.e.
//! the Woodbury identity), with no sparse factorisation per iteration.
//!
//! ```text
//! every iterate:  u = K⁻¹ (a w r + Bᵀ g)        (a: scalar, g = (g_N, g_T): one value per pair row)
//! its pair rows:  y = B u = a w y0 + C g         (y0 = B u0, u0 = K⁻¹ r; C = B K⁻¹ Bᵀ, the interface's)
//! K u − w r − Bᵀ f = (a − 1) w r + Bᵀ (g − f)    (a sparse vector of size n: no solve)
//! ```
//!
//! `B` here is the free part of the pair rows (`B_N` then `B_T`, `2m` rows); the constrained
//! part stays in the offsets `ĝ`, `ŝ` of [`crate::algorithms::full_system`]. Both methods start
//! from `u = 0` (`a = 0`, `g = 0`) and step to the solution `û = K⁻¹(w r + Bᵀ f̂)` of a contact
//! state's linear equations (`a = 1`, `g = f̂`, the state's forces); the backtracking's convex
//! combinations `x + α (x̂ − x)` keep the form. So each iterate, its merit and its state are the
//! full system's (to round-off), the linear algebra of an iteration is a dense LU of the rows the
//! state loads (at most `2m`), and the displacement is recovered once at the end by one solve
//! with `K`'s factor ([`Interface::free_displacement`]).

use nalgebra::DMatrix;

use crate::algorithms::full_system::dot_free;
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::PairState;

/// The pair rows of a problem on its condensed interface.
pub(crate) struct PairSpace<'a> {
    problem: &'a ContactProblem,
    interface: &'a Interface,
    m: usize,
    /// Whether the interface has the tangential rows (a frictional problem).
    tangential: bool,
    /// `y0 = B u0` (free parts; the tangential half zero without tangential rows).
    y0: Vec<f64>,
}

impl<'a> PairSpace<'a> {
    /// The pair space of `problem` on its condensed `interface` (at the problem's current load).
    pub(crate) fn new(problem: &'a ContactProblem, interface: &'a Interface) -> PairSpace<'a> {
        let m = problem.num_pairs();
        let tangential = m > 0 && interface.c_tt.nrows() == m;
        let u0 = &interface.u0;
        let mut y0: Vec<f64> = problem.normal_rows.iter().map(|r| dot_free(r, u0)).collect();
        if tangential {
            y0.extend(problem.tangent_rows.iter().map(|r| dot_free(r, u0)));
        } else {
            y0.resize(2 * m, 0.0);
        }
        PairSpace { problem, interface, m, tangential, y0 }
    }

    /// Whether row `i` (`0..2m`: normal rows, then tangential) is in the interface.
    pub(crate) fn has_row(&self, i: usize) -> bool {
        i < self.m || self.tangential
    }

    /// `C_ij` (rows and columns `0..2m` as [`PairSpace::has_row`]; both must be in the interface).
    pub(crate) fn compliance(&self, i: usize, j: usize) -> f64 {
        let (m, c) = (self.m, self.interface);
        match (i < m, j < m) {
            (true, true) => c.c_nn[(i, j)],
            (true, false) => c.c_nt[(i, j - m)],
            (false, true) => c.c_tn[(i - m, j)],
            (false, false) => c.c_tt[(i - m, j - m)],
        }
    }

    /// `y = aw · y0 + C g` (`g` of length `2m`, or shorter: the rest zero; its entries on rows
    /// not in the interface are ignored).
    pub(crate) fn rows(&self, aw: f64, g: &[f64]) -> Vec<f64> {
        let (m, c) = (self.m, self.interface);
        let mut y: Vec<f64> = self.y0.iter().map(|v| aw * v).collect();
        for (s, &gs) in g.iter().enumerate() {
            if gs == 0.0 || !self.has_row(s) {
                continue;
            }
            let normal = if s < m { c.c_nn.column(s) } else { c.c_nt.column(s - m) };
            y[..m].iter_mut().zip(normal.iter()).for_each(|(y, c)| *y += c * gs);
            if self.tangential {
                let tangent = if s < m { c.c_tn.column(s) } else { c.c_tt.column(s - m) };
                y[m..].iter_mut().zip(tangent.iter()).for_each(|(y, c)| *y += c * gs);
            }
        }
        y
    }

    /// `(a − 1) w r + Bᵀ d` (`d` of length `2m`): the equilibrium residual `K u − w r − Bᵀ f` of
    /// the iterate `(a, g)` with `d = g − f`.
    pub(crate) fn equilibrium(&self, a: f64, w: f64, d: &[f64]) -> Vec<f64> {
        let p = self.problem;
        let mut out: Vec<f64> = p.pattern_rhs.iter().map(|r| (a - 1.0) * w * r).collect();
        let rows = p.normal_rows.iter().chain(&p.tangent_rows);
        for (row, &v) in rows.zip(d) {
            if v != 0.0 {
                row.free.iter().for_each(|&(i, b)| out[i] += b * v);
            }
        }
        out
    }

    /// The free displacements `u = K⁻¹ (aw r + Bᵀ g)` (one solve with the interface's factor).
    pub(crate) fn displacement(&self, aw: f64, g: &[f64]) -> Vec<f64> {
        let m = self.m;
        let tau: &[f64] = if self.tangential { &g[m..] } else { &[] };
        self.interface.free_displacement(aw, &g[..m], tau)
    }
}

/// `τ = sign · μλ` of a slip state: slip− (θ > 0) +1, slip+ −1, otherwise 0.
pub(crate) fn slip_sign(state: PairState) -> f64 {
    match state {
        PairState::SlipNegative => 1.0,
        PairState::SlipPositive => -1.0,
        _ => 0.0,
    }
}

/// A state's equations in its loaded forces, as the penalty and the augmented Lagrangian share
/// them:
///
/// ```text
/// U = {k : state_k ≠ free} ∪ {m + k : state_k ≠ free, pair k frictional}   (sorted)
/// slip± row of τ_k:   τ_k − sign_k μ_k λ_k = 0
/// every other row i:  scale · Σ_(j ∈ U) C_ij f_j   (+ the method's own diagonal and right side)
/// ```
pub(crate) struct LoadedForces {
    /// `U`, sorted: `k` for the normal force of pair `k`, `m + k` for its tangential force.
    pub(crate) unknowns: Vec<usize>,
    /// The matrix above.
    pub(crate) matrix: DMatrix<f64>,
}

impl LoadedForces {
    /// Row `a` is a slip row (its equation is complete; no right-hand side).
    pub(crate) fn is_slip_row(&self, a: usize, state: &[PairState]) -> bool {
        let (i, m) = (self.unknowns[a], state.len());
        i >= m && slip_sign(state[i % m]) != 0.0
    }

    /// The Newton target `(a = 1, g)` with `g` the solved forces on `U` and 0 elsewhere.
    pub(crate) fn target(&self, m: usize, forces: Vec<f64>) -> Vec<f64> {
        let mut target = vec![0.0; 1 + 2 * m];
        target[0] = 1.0;
        self.unknowns.iter().zip(forces).for_each(|(&s, f)| target[1 + s] = f);
        target
    }
}

impl PairSpace<'_> {
    /// The [`LoadedForces`] of `state` (`frictional[k]`: pair `k` has a tangential force);
    /// `None` if a slip row's pair has no normal unknown (not a state of a pair in contact).
    pub(crate) fn loaded_forces(
        &self,
        state: &[PairState],
        frictional: &[bool],
        friction: &[f64],
        scale: f64,
    ) -> Option<LoadedForces> {
        let m = state.len();
        let mut unknowns: Vec<usize> = vec![];
        for (k, s) in state.iter().enumerate() {
            if *s != PairState::Free {
                unknowns.push(k);
                if frictional[k] {
                    unknowns.push(m + k);
                }
            }
        }
        unknowns.sort_unstable();
        let column = |s: usize| unknowns.binary_search(&s).ok();
        let mut matrix = DMatrix::<f64>::zeros(unknowns.len(), unknowns.len());
        for (a, &i) in unknowns.iter().enumerate() {
            let k = i % m;
            let sign = slip_sign(state[k]);
            if i >= m && sign != 0.0 {
                matrix[(a, a)] = 1.0;
                matrix[(a, column(k)?)] = -sign * friction[k];
                continue;
            }
            for (b, &j) in unknowns.iter().enumerate() {
                matrix[(a, b)] = scale * self.compliance(i, j);
            }
        }
        Some(LoadedForces { unknowns, matrix })
    }
}

/// `A⁻¹ b` by a dense LU with partial pivoting; `None` if `A` is singular or the answer is not
/// finite.
pub(crate) fn dense_solve(matrix: DMatrix<f64>, rhs: Vec<f64>) -> Option<Vec<f64>> {
    let n = rhs.len();
    if n == 0 {
        return Some(vec![]);
    }
    let x = matrix.lu().solve(&nalgebra::DVector::from_vec(rhs))?;
    let out: Vec<f64> = x.iter().copied().collect();
    (out.len() == n && out.iter().all(|v| v.is_finite())).then_some(out)
}

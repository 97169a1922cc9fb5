//! The bodies condensed onto the contact pairs.
//!
//! ```text
//! u_f = w u0 + K⁻¹ (B_N,fᵀ λ + B_T,fᵀ τ),   u0 = K⁻¹ r
//! gap = g0 + w h + C_NN λ + C_NT τ,   h = B_N,f u0 + B_N,c u_c,   C = B K⁻¹ Bᵀ
//! ```
//!
//! `K_ff` is factored bordered by the pair rows ([`crate::ContactProblem`]):
//!
//! ```text
//! P [K Bᵀ; B 0] Pᵀ = L D Lᵀ,  the rows last:  L_bb D_b L_bbᵀ = −B K⁻¹ Bᵀ = −C
//! C = W Wᵀ,  W = L_bb |D_b|^½             (dense, of the size of the rows: 2 per pair)
//! ```
//!
//! (`contact2d_fem::CholeskySolver::factor_with_constraints`.) The condensation costs the
//! factorisation (done once, in the problem) plus dense work of the size of the interface; the
//! full displacement field is recovered once at the end by one solve. Without friction (every
//! μ = 0) the tangential rows play no part: the `C_·T`, `C_T·` blocks are then empty (0
//! columns). If the rows were dependent (the factor has none), the compliances are computed by
//! multi-RHS solves.

use contact2d_fem::parallelism;
use faer::Mat;
use faer::linalg::matmul::matmul;
use nalgebra::DMatrix;

use contact2d_fem::CholeskySolver;

use crate::problem::{ContactProblem, PairRow, condensed_rows};
use crate::stiffness_factor::StiffnessFactor;

/// Compliances of the contact pairs.
#[derive(Debug, Clone)]
pub struct Interface {
    /// `u0 = K⁻¹ r`: free displacements of the unit load without contact. Empty on the sparse
    /// path's interface ([`Interface::sparse`]) until [`Interface::update_load`]: its
    /// algorithms solve each contact state on the full system and read no `u0`.
    pub u0: Vec<f64>,
    /// `h = B_N u0` (with the constrained part of the load pattern); empty with `u0`.
    pub h_normal: Vec<f64>,
    /// `B_T u0` likewise.
    pub h_tangent: Vec<f64>,
    /// `C_NN = B_N K⁻¹ B_Nᵀ`; `C_NT`, `C_TN`, `C_TT` likewise.
    pub c_nn: DMatrix<f64>,
    /// Normal rows against tangential forces.
    pub c_nt: DMatrix<f64>,
    /// Tangential rows against normal forces.
    pub c_tn: DMatrix<f64>,
    /// Tangential rows against tangential forces.
    pub c_tt: DMatrix<f64>,
    /// The factorisation of `K_ff` (the problem's, or the one bordered here), for `u0` and the
    /// final recovery.
    solver: StiffnessFactor,
    /// `B_N` and, with friction, `B_T` (free parts), for the final recovery.
    normal_rows: Vec<PairRow>,
    tangent_rows: Vec<PairRow>,
    /// `K⁻¹ r_p` per load pattern of the problem, solved when a step first needs it
    /// ([`Interface::update_load_factors`]).
    pattern_u0: Vec<Option<Vec<f64>>>,
    /// The factored equations of the last contact state solved on this interface, reused when
    /// the next solve has the same state (a load step starting from the previous step's
    /// states).
    pub(crate) last_state: crate::factor_cache::StateFactorCache,
    /// The last two contact forces whose displacements were solved ([`Interface::free_displacement`]).
    force_span: crate::force_span::ForceSpan,
    /// Whether the compliances were computed ([`Interface::new`]) or left empty for the sparse
    /// path ([`Interface::sparse`]).
    condensed: bool,
    /// The sparse state system of the sparse path, analysed when first needed.
    pub(crate) kkt: crate::kkt::KktCache,
}

/// `Bᵀ` restricted to free DOFs, as dense columns of length `n`.
fn rows_to_columns(n: usize, rows: &[PairRow]) -> Mat<f64> {
    let mut b = Mat::zeros(n, rows.len());
    for (k, row) in rows.iter().enumerate() {
        for (i, v) in &row.free {
            b[(*i, k)] += v;
        }
    }
    b
}

fn to_dmatrix(m: &Mat<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(m.nrows(), m.ncols(), |i, j| m[(i, j)])
}

/// The blocks `(C_NN, C_NT, C_TN, C_TT)` of `C = B K⁻¹ Bᵀ` from the factor bordered by the
/// problem's rows, or `None` if the factor has no rows (they were dependent). The rows left out
/// of the factor (a negligible free part, [`condensed_rows`]) get theirs by one multi-RHS solve,
/// which also gives `u0 = K⁻¹ r` (its last column): one pass over the factor for both.
fn condensed_blocks(
    problem: &ContactProblem,
    solver: &CholeskySolver,
    tangent: &[PairRow],
) -> Option<([Mat<f64>; 4], Vec<f64>)> {
    let (index, rows) = condensed_rows(&problem.normal_rows, &problem.tangent_rows);
    if solver.constraint_count() != rows.len() {
        return None;
    }
    let factored = solver.condensed()?;
    let m = problem.normal_rows.len();
    let all: Vec<&PairRow> = problem.normal_rows.iter().chain(&problem.tangent_rows).collect();
    let mut c = Mat::zeros(all.len(), all.len());
    for (p, &i) in index.iter().enumerate() {
        for (q, &j) in index.iter().enumerate() {
            c[(i, j)] = factored[(p, q)];
        }
    }
    let mut in_factor = vec![false; all.len()];
    index.iter().for_each(|&i| in_factor[i] = true);
    // The rows left out and the load, solved together (one pass over the factor).
    let left_out: Vec<usize> = (0..all.len()).filter(|&i| !in_factor[i] && !all[i].free.is_empty()).collect();
    let load = left_out.len();
    let mut b = Mat::zeros(problem.system.dofs.num_free(), load + 1);
    for (col, &i) in left_out.iter().enumerate() {
        all[i].free.iter().for_each(|&(d, v)| b[(d, col)] += v);
    }
    b.col_mut(load).iter_mut().zip(&problem.pattern_rhs).for_each(|(x, r)| *x = *r);
    let z = solver.solve_many(&b);
    let u0 = z.col(load).iter().copied().collect();
    for (col, &i) in left_out.iter().enumerate() {
        for (j, other) in all.iter().enumerate() {
            let v: f64 = other.free.iter().map(|&(d, w)| w * z[(d, col)]).sum();
            (c[(i, j)], c[(j, i)]) = (v, v);
        }
    }
    let t = tangent.len();
    let block = |r: std::ops::Range<usize>, k: std::ops::Range<usize>| {
        c.as_ref().submatrix(r.start, k.start, r.len(), k.len()).to_owned()
    };
    Some(([block(0..m, 0..m), block(0..m, m..m + t), block(m..m + t, 0..m), block(m..m + t, m..m + t)], u0))
}

/// `A B` with the fixed [`parallelism`] (faer's `*` reads the global setting, which follows the
/// thread pool).
fn product(a: faer::MatRef<'_, f64>, b: &Mat<f64>) -> Mat<f64> {
    let mut c = Mat::zeros(a.nrows(), b.ncols());
    matmul(c.as_mut(), faer::Accum::Replace, a, b.as_ref(), 1.0, parallelism());
    c
}

impl Interface {
    /// Condenses `problem` onto its pairs with the existing factorisation: `C = W Wᵀ` from the
    /// last block of the factor bordered by the rows, and one multi-RHS solve for `u0` and the
    /// rows left out of the border. A problem factored without its rows (many pairs,
    /// [`ContactProblem::is_bordered`]) is factored bordered here first (the same factor the
    /// problem would have made); if that fails the compliances come from multi-RHS solves.
    pub fn new(problem: &ContactProblem) -> Interface {
        // The problem's factor, or (many pairs: the problem holds `K`'s own or none yet) `K`
        // bordered here; `K`'s own if that fails (dependent rows).
        let bordered = (!problem.is_bordered())
            .then(|| {
                let (_, rows) = condensed_rows(&problem.normal_rows, &problem.tangent_rows);
                CholeskySolver::factor_with_constraints(&problem.system.stiffness, &rows).ok()
            })
            .flatten();
        let solver = match bordered {
            Some(s) => StiffnessFactor::made(std::sync::Arc::clone(&problem.system), s),
            None => problem.stiffness_factor().clone(),
        };
        let n = problem.system.dofs.num_free();
        let frictional = problem.is_frictional();
        let normal = &problem.normal_rows[..];
        let tangent: &[PairRow] = if frictional { &problem.tangent_rows } else { &[] };
        let blocks = solver.get().ok().and_then(|s| condensed_blocks(problem, s, tangent));
        let ((c_nn, c_nt, c_tn, c_tt), u0) = match blocks {
            Some(([c_nn, c_nt, c_tn, c_tt], u0)) => ((c_nn, c_nt, c_tn, c_tt), u0),
            None => {
                let b_n = rows_to_columns(n, normal);
                let b_t = rows_to_columns(n, tangent);
                let (z_n, z_t) = (solver.solve_many_or_nan(&b_n), solver.solve_many_or_nan(&b_t));
                let (bnt, btt) = (b_n.transpose(), b_t.transpose());
                let blocks = (product(bnt, &z_n), product(bnt, &z_t), product(btt, &z_n), product(btt, &z_t));
                (blocks, solver.solve_or_nan(&problem.pattern_rhs))
            }
        };
        let h = |rows: &[PairRow]| rows.iter().map(|r| r.dot(&u0, &problem.pattern_prescribed)).collect::<Vec<_>>();
        Interface {
            h_normal: h(&problem.normal_rows),
            h_tangent: h(&problem.tangent_rows),
            c_nn: to_dmatrix(&c_nn),
            c_nt: to_dmatrix(&c_nt),
            c_tn: if frictional { to_dmatrix(&c_tn) } else { DMatrix::zeros(0, 0) },
            c_tt: to_dmatrix(&c_tt),
            u0,
            solver,
            normal_rows: normal.to_vec(),
            tangent_rows: tangent.to_vec(),
            pattern_u0: vec![None; problem.patterns().len()],
            last_state: Default::default(),
            force_span: Default::default(),
            condensed: true,
            kkt: Default::default(),
        }
    }

    /// The interface of the sparse path ([`crate::LinearSolver::Sparse`]): no compliances
    /// (`c_nn`, `c_nt`, `c_tn`, `c_tt` are empty, 0 × 0) and no `u0` or `h` until
    /// [`Interface::update_load`] (empty): the algorithms that support it solve each contact
    /// state on the full system (`crate::kkt`) at the cost of a sparse factorisation, with no
    /// dense block of the size of the interface, and need no solve with `K_ff` alone (whose
    /// factor the problem then makes only if something else asks for it).
    pub fn sparse(problem: &ContactProblem) -> Interface {
        let frictional = problem.is_frictional();
        let tangent: &[PairRow] = if frictional { &problem.tangent_rows } else { &[] };
        Interface {
            h_normal: vec![],
            h_tangent: vec![],
            c_nn: DMatrix::zeros(0, 0),
            c_nt: DMatrix::zeros(0, 0),
            c_tn: DMatrix::zeros(0, 0),
            c_tt: DMatrix::zeros(0, 0),
            u0: vec![],
            solver: problem.stiffness_factor().clone(),
            normal_rows: problem.normal_rows.clone(),
            tangent_rows: tangent.to_vec(),
            pattern_u0: vec![None; problem.patterns().len()],
            last_state: Default::default(),
            force_span: Default::default(),
            condensed: false,
            kkt: Default::default(),
        }
    }

    /// Whether the compliances were computed ([`Interface::new`]); false on the sparse path
    /// ([`Interface::sparse`]).
    pub fn is_condensed(&self) -> bool {
        self.condensed
    }

    /// This interface if it holds the compliances, else the problem's condensed one: for the
    /// algorithms that work on the compliances (Boussinesq, Clarabel) when the sparse path's
    /// interface, which holds none, is handed to them.
    pub fn condensed<'a>(&'a self, problem: &ContactProblem) -> std::borrow::Cow<'a, Interface> {
        if self.condensed { std::borrow::Cow::Borrowed(self) } else { std::borrow::Cow::Owned(Interface::new(problem)) }
    }

    /// Recomputes the load terms `u0` and `h` after the problem's load changed
    /// ([`ContactProblem::apply_load`]): one solve; the compliances are kept. NaN if `K_ff`
    /// cannot be factored (only a sparse path's interface factors it here:
    /// `crate::stiffness_factor`).
    pub fn update_load(&mut self, problem: &ContactProblem) {
        self.u0 = self.solver.solve_or_nan(&problem.pattern_rhs);
        let h =
            |rows: &[PairRow]| rows.iter().map(|r| r.dot(&self.u0, &problem.pattern_prescribed)).collect::<Vec<_>>();
        self.h_normal = h(&problem.normal_rows);
        self.h_tangent = h(&problem.tangent_rows);
    }

    /// Like [`Interface::update_load`] after [`ContactProblem::apply_load`] with `factors` and no
    /// extra right-hand side, by superposition instead of a solve per step:
    ///
    /// ```text
    /// u0 = K⁻¹ Σ_p f_p r_p = Σ_p f_p (K⁻¹ r_p)     (one solve per pattern, the first time it is used)
    /// ```
    ///
    /// The same `u0` up to round-off; a history of many steps over few patterns pays a few
    /// solves instead of one per step. The sparse path's interface ([`Interface::sparse`]) of
    /// a problem with pairs is left as it is: its algorithms read no `u0`.
    pub fn update_load_factors(&mut self, problem: &ContactProblem, factors: &[f64]) {
        if !self.condensed && problem.num_pairs() > 0 {
            return;
        }
        let patterns = problem.patterns();
        if factors.len() != patterns.len() || self.pattern_u0.len() != patterns.len() {
            self.update_load(problem);
            return;
        }
        let mut u0 = vec![0.0; self.solver.dim()];
        let solver = &self.solver;
        for ((pattern, f), cached) in patterns.iter().zip(factors).zip(&mut self.pattern_u0) {
            if *f == 0.0 {
                continue;
            }
            let up = cached.get_or_insert_with(|| solver.solve_or_nan(&pattern.rhs));
            u0.iter_mut().zip(up.iter()).for_each(|(u, v)| *u += f * v);
        }
        self.u0 = u0;
        let h =
            |rows: &[PairRow]| rows.iter().map(|r| r.dot(&self.u0, &problem.pattern_prescribed)).collect::<Vec<_>>();
        self.h_normal = h(&problem.normal_rows);
        self.h_tangent = h(&problem.tangent_rows);
    }

    /// Free displacements `w u0 + K⁻¹ (B_Nᵀ λ + B_Tᵀ τ)` (one solve; `τ` is ignored without
    /// friction). On the sparse path's interface, after [`Interface::update_load`] (before it
    /// `u0` is empty, and so is the answer). On a large problem, forces in the span of the last two solved take their
    /// displacements by linearity, without a solve (`force_span.rs`).
    pub fn free_displacement(&self, w: f64, lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let x = if self.u0.len() >= crate::force_span::SPAN_FROM_DOFS {
            let forces: Vec<f64> = lambda
                .iter()
                .take(self.normal_rows.len())
                .chain(tau.iter().take(self.tangent_rows.len()))
                .copied()
                .collect();
            self.force_span.solution(&forces).unwrap_or_else(|| {
                let x = self.contact_displacement(lambda, tau);
                self.force_span.remember(forces, x.clone());
                x
            })
        } else {
            self.contact_displacement(lambda, tau)
        };
        x.iter().zip(&self.u0).map(|(x, u)| w * u + x).collect()
    }

    /// `K⁻¹ (B_Nᵀ λ + B_Tᵀ τ)` (one solve; NaN as [`Interface::update_load`]).
    fn contact_displacement(&self, lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let mut f = vec![0.0; self.solver.dim()];
        for (row, l) in self.normal_rows.iter().zip(lambda) {
            for &(i, v) in &row.free {
                f[i] += v * l;
            }
        }
        for (row, t) in self.tangent_rows.iter().zip(tau) {
            for &(i, v) in &row.free {
                f[i] += v * t;
            }
        }
        self.solver.solve_or_nan(&f)
    }
}

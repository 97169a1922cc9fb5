//! Contact as convex QPs in the contact forces (the dual, condensed problem), solved by Clarabel:
//! the frictionless problem here, and the Tresca problems of the Coulomb fixed point
//! (crate::algorithms::clarabel_tresca) by the same routine.
//!
//! ```text
//! f = (λ, τ_F),   C = B K⁻¹ Bᵀ (crate::Interface),   d_N = g0 + w h_N,   d_T = w h_T − s_start
//! minimise   ½ fᵀ C f + d_Nᵀ λ + d_Tᵀ τ_F
//! subject to λ ≥ 0,   −g_k ≤ τ_k ≤ g_k  (k ∈ F: frictional pairs with a slip bound g_k > 0)
//! KKT:       gap = d_N + C_NN λ + C_NT τ ≥ 0 ⟂ λ ≥ 0   (the multiplier of λ ≥ 0 is the gap)
//!            Δs = d_T + C_TN λ + C_TT τ = −ν,  ν in the normal cone of the box: τ opposes slip
//! Clarabel:  A x + s = b, s ∈ R₊ᵐ:  rows −e_λ (b = 0), +e_τ and −e_τ (b = g)
//! ```
//!
//! This is the minimum of the complementary energy (Duvaut and Lions; Kikuchi and Oden 1988,
//! ch. 5): the same conditions as the active set's, reached by an interior point instead of a
//! semi-smooth Newton iteration. The dense `C` is of the size of the pairs; only the pairs of a
//! working set `S` enter the QP (the others have λ = τ = 0), and `S` grows by every pair that
//! the answer penetrates, until none does (constraint generation: the final QP's answer, with
//! λ = 0 outside `S`, satisfies every condition of the full problem).
//!
//! The interior point's answer is then polished: the exact solution of its own contact states
//! (one sparse LU of the full, not condensed, system, crate::algorithms::augmented_lagrangian)
//! replaces it when that passes the certificate (crate::certify::certify); the states are
//! Clarabel's, so the check stays independent of the active set.
//!
//! Scaling: `f = F x` with `F = U / c̄` (`U` the largest of |d| and |w u0|, `c̄` the mean
//! diagonal of `C` over `S`), the objective divided by `F U`: `P = C / c̄`, `q = d / U`, and
//! the bounds `g / F`; the interior point's tolerances (1e-10) then act on O(1) numbers.

use web_time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};

use crate::algorithms::state_equations::{combine, solve_state_equations};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_forces};
use crate::solution::{ContactSolution, ContactStatus, PairState, StepStart};

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

/// The data of the dual QPs of one step: the interface and the open gaps and slips.
pub(crate) struct DualProblem<'a> {
    interface: &'a Interface,
    /// `d_N = g0 + w h_N`: the gaps without contact forces.
    open_gap: Vec<f64>,
    /// `d_T = w h_T − s_start`: the slip increments without contact forces (empty without
    /// friction).
    open_slip: Vec<f64>,
    /// Pairs with a tangential law (μ > 0 and a tangential row) when the interface has `C_TT`.
    frictional: Vec<bool>,
    /// `U`: the length scale of the variables.
    length: f64,
    /// Pairs with a normal unknown ([`ContactProblem::normal`]); the others are held along
    /// their normal by fixes, never enter the working set and keep λ = 0 (the fix takes the
    /// force), as in every algorithm.
    normal: Vec<bool>,
}

/// What one dual solve found (forces over all pairs; zero outside the working set).
pub(crate) struct DualAnswer {
    pub status: ContactStatus,
    pub lambda: Vec<f64>,
    pub tau: Vec<f64>,
    /// Interior-point iterations summed over the working-set rounds.
    pub iterations: usize,
}

impl<'a> DualProblem<'a> {
    /// The dual data of the step at load factor `w` from `start`.
    pub(crate) fn new(problem: &ContactProblem, interface: &'a Interface, w: f64, start: &StepStart) -> Self {
        let m = problem.num_pairs();
        let open_gap: Vec<f64> = (0..m).map(|k| problem.gap[k] + w * interface.h_normal[k]).collect();
        let with_friction = interface.c_tt.nrows() == m && m > 0;
        let open_slip: Vec<f64> =
            if with_friction { (0..m).map(|k| w * interface.h_tangent[k] - start.slip[k]).collect() } else { vec![] };
        let frictional = (0..m).map(|k| with_friction && problem.tangential[k] && problem.friction[k] > 0.0).collect();
        let u0 = interface.u0.iter().fold(0.0f64, |a, u| a.max((w * u).abs()));
        let length = open_gap.iter().chain(&open_slip).fold(u0, |a, v| a.max(v.abs()));
        let length = if length > 0.0 && length.is_finite() { length } else { 1.0 };
        DualProblem { interface, open_gap, open_slip, frictional, length, normal: problem.normal.clone() }
    }

    /// The working set to start from: every pair the load alone closes or nearly closes
    /// (`d_N ≤ 1e-6 U`).
    pub(crate) fn initial_working_set(&self) -> Vec<bool> {
        self.open_gap.iter().zip(&self.normal).map(|(d, has_normal)| *has_normal && *d <= 1e-6 * self.length).collect()
    }

    /// Whether pair `k` has a normal unknown (may enter the working set).
    pub(crate) fn is_normal(&self, k: usize) -> bool {
        self.normal[k]
    }

    /// `U`, the length scale of the variables.
    pub(crate) fn length(&self) -> f64 {
        self.length
    }

    /// Gaps of all pairs under forces `λ, τ`: `d_N + C_NN λ + C_NT τ`.
    pub(crate) fn gaps(&self, lambda: &[f64], tau: &[f64]) -> Vec<f64> {
        let c = self.interface;
        let m = self.open_gap.len();
        let active_n: Vec<usize> = (0..m).filter(|&k| lambda[k] != 0.0).collect();
        let active_t: Vec<usize> = (0..tau.len().min(c.c_nt.ncols())).filter(|&k| tau[k] != 0.0).collect();
        (0..m)
            .map(|i| {
                self.open_gap[i]
                    + active_n.iter().map(|&j| c.c_nn[(i, j)] * lambda[j]).sum::<f64>()
                    + active_t.iter().map(|&j| c.c_nt[(i, j)] * tau[j]).sum::<f64>()
            })
            .collect()
    }

    /// Solves the Tresca dual with slip bounds `bound` (zeros: frictionless) on the working set
    /// `working`, growing it by the pairs its answer penetrates until none does.
    pub(crate) fn solve(&self, bound: &[f64], working: &mut [bool]) -> DualAnswer {
        let m = self.open_gap.len();
        let mut iterations = 0;
        // Each round adds at least one pair: at most m + 1 rounds.
        for _ in 0..=m {
            let normal: Vec<usize> = (0..m).filter(|&k| working[k]).collect();
            let friction: Vec<usize> = normal
                .iter()
                .copied()
                .filter(|&k| self.frictional[k] && bound.get(k).is_some_and(|g| *g > 0.0))
                .collect();
            let mut answer = self.solve_on(&normal, &friction, bound);
            iterations += answer.iterations;
            answer.iterations = iterations;
            if answer.status != ContactStatus::Converged {
                return answer;
            }
            let gaps = self.gaps(&answer.lambda, &answer.tau);
            let mut grown = false;
            for (k, in_set) in working.iter_mut().enumerate() {
                if !*in_set && gaps[k] < 0.0 && self.normal[k] {
                    *in_set = true;
                    grown = true;
                }
            }
            if !grown {
                return answer;
            }
        }
        DualAnswer { status: ContactStatus::Numerical, lambda: vec![0.0; m], tau: vec![0.0; m], iterations }
    }

    /// One Clarabel solve on the pairs `normal` (λ) and `friction` (τ) of the module docs.
    fn solve_on(&self, normal: &[usize], friction: &[usize], bound: &[f64]) -> DualAnswer {
        let m = self.open_gap.len();
        let c = self.interface;
        let (a, b) = (normal.len(), friction.len());
        let n = a + b;
        let failed = |status, iterations| DualAnswer { status, lambda: vec![0.0; m], tau: vec![0.0; m], iterations };
        if n == 0 {
            return DualAnswer { status: ContactStatus::Converged, ..failed(ContactStatus::Converged, 0) };
        }
        // Entry of C between unknowns i and j (λ first, then τ).
        let entry = |i: usize, j: usize| -> f64 {
            match (i < a, j < a) {
                (true, true) => c.c_nn[(normal[i], normal[j])],
                (true, false) => c.c_nt[(normal[i], friction[j - a])],
                (false, true) => c.c_tn[(friction[i - a], normal[j])],
                (false, false) => c.c_tt[(friction[i - a], friction[j - a])],
            }
        };
        let diagonal = (0..n).map(|i| entry(i, i)).sum::<f64>() / n as f64;
        let c_mean = if diagonal > 0.0 && diagonal.is_finite() { diagonal } else { 1.0 };
        // The length scale of this QP: the largest open gap or slip of its unknowns (the gaps
        // of far pairs outside the working set do not enter; a scale set by them would leave
        // the answer below the interior point's absolute tolerances).
        let mut q: Vec<f64> = normal.iter().map(|&k| self.open_gap[k]).collect();
        q.extend(friction.iter().map(|&k| self.open_slip[k]));
        let length = q.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        if length == 0.0 {
            // Nothing opens or closes a pair: λ = τ = 0 is optimal.
            return DualAnswer { status: ContactStatus::Converged, ..failed(ContactStatus::Converged, 0) };
        }
        if !length.is_finite() {
            return failed(ContactStatus::Numerical, 0);
        }
        q.iter_mut().for_each(|v| *v /= length);
        let force = length / c_mean;
        // P: the upper triangle of C / c̄, column by column; symmetrised (C is symmetric up to
        // round-off of the factor).
        let mut colptr = Vec::with_capacity(n + 1);
        let mut rowval = Vec::with_capacity(n * (n + 1) / 2);
        let mut nzval = Vec::with_capacity(n * (n + 1) / 2);
        colptr.push(0);
        for j in 0..n {
            for i in 0..=j {
                rowval.push(i);
                nzval.push(0.5 * (entry(i, j) + entry(j, i)) / c_mean);
            }
            colptr.push(rowval.len());
        }
        let p = CscMatrix::new(n, n, colptr, rowval, nzval);
        // Rows: −λ_i ≤ 0; τ_j ≤ g_j; −τ_j ≤ g_j.
        let rows = a + 2 * b;
        let (mut ar, mut ac, mut av) = (Vec::with_capacity(rows), Vec::with_capacity(rows), Vec::with_capacity(rows));
        let mut rhs = vec![0.0; rows];
        for i in 0..a {
            ar.push(i);
            ac.push(i);
            av.push(-1.0);
        }
        for (j, &k) in friction.iter().enumerate() {
            let g = bound[k] / force;
            for (offset, sign) in [(0, 1.0), (1, -1.0)] {
                let row = a + 2 * j + offset;
                ar.push(row);
                ac.push(a + j);
                av.push(sign);
                rhs[row] = g;
            }
        }
        let a_matrix = CscMatrix::new_from_triplets(rows, n, ar, ac, av);
        let settings = DefaultSettingsBuilder::default()
            .verbose(false)
            .tol_gap_abs(1e-10)
            .tol_gap_rel(1e-10)
            .tol_feas(1e-10)
            .max_iter(200)
            .build();
        let cones = [NonnegativeConeT(rows)];
        let Ok(settings) = settings else { return failed(ContactStatus::Numerical, 0) };
        let Ok(mut solver) = DefaultSolver::new(&p, &q, &a_matrix, &rhs, &cones, settings) else {
            return failed(ContactStatus::Numerical, 0);
        };
        solver.solve();
        let sol = &solver.solution;
        let iterations = sol.iterations as usize;
        // An answer "almost solved" (reduced tolerances) still identifies the contact states,
        // which is all the polishing needs; the certificate judges the polished answer.
        let status = match sol.status {
            SolverStatus::AlmostSolved => ContactStatus::Converged,
            other => map_status(other),
        };
        let (mut lambda, mut tau) = (vec![0.0; m], vec![0.0; m]);
        for (i, &k) in normal.iter().enumerate() {
            lambda[k] = force * sol.x[i];
        }
        for (j, &k) in friction.iter().enumerate() {
            tau[k] = force * sol.x[a + j];
        }
        DualAnswer { status, lambda, tau, iterations }
    }
}

/// Solves the frictionless problem at load factor `w` with Clarabel (the interface is built
/// from the problem's factorisation; [`solve_frictionless_qp_on`] reuses one).
pub fn solve_frictionless_qp(problem: &ContactProblem, w: f64) -> ContactSolution {
    let interface = Interface::new(problem);
    solve_frictionless_qp_on(problem, &interface, w)
}

/// Solves the frictionless problem at load factor `w` with Clarabel on `interface` (module
/// docs): the dual QP, then the polishing of its contact set.
pub fn solve_frictionless_qp_on(problem: &ContactProblem, interface: &Interface, w: f64) -> ContactSolution {
    // The sparse path's interface holds no compliances: condense here (this algorithm works on them).
    let condensed = interface.condensed(problem);
    let interface = &*condensed;
    let clock = Instant::now();
    let m = problem.num_pairs();
    let start = StepStart::initial(m);
    // Frictionless: no tangential unknowns, whatever the interface holds.
    let dual = DualProblem::new(problem, interface, w, &start);
    let mut working = dual.initial_working_set();
    let answer = dual.solve(&vec![0.0; m], &mut working);
    let raw = RawSolution {
        load_factor: w,
        normal_force: answer.lambda,
        tangential_force: vec![0.0; m],
        status: answer.status,
        iterations: answer.iterations,
        time: clock.elapsed(),
    };
    let solution = finish_from_forces(problem, interface, raw, &start);
    if !matches!(solution.status, ContactStatus::Converged | ContactStatus::Numerical) {
        return solution;
    }
    match polish(problem, interface, w, &start, &solution.state, solution.iterations) {
        Some(mut polished) if polished.status == ContactStatus::Converged => {
            polished.time = clock.elapsed();
            polished
        }
        _ => solution,
    }
}

/// Polishing: the interior point resolves the pair states (free, stick, slip±), but the forces
/// only to its tolerance (a degenerate pair — λ = gap = 0, or stuck on the cone — to about its
/// square root). The linear equations of those states on the interface, solved exactly
/// (crate::algorithms::state_equations), give the answer they imply, evaluated and certified
/// like any answer (crate::report, crate::certify::certify): `Converged` only if every
/// contact and friction condition holds. The states are Clarabel's, so the check stays
/// independent of the active set's iteration. `None` if the states' equations are singular.
pub(crate) fn polish(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    state: &[PairState],
    iterations: usize,
) -> Option<ContactSolution> {
    let clock = Instant::now();
    let frictional = interface.c_tt.nrows() == problem.num_pairs();
    let x = solve_state_equations(problem, interface, start, state, frictional)?;
    let (normal_force, tangential_force) = combine(&x, w);
    let raw = RawSolution {
        load_factor: w,
        normal_force,
        tangential_force,
        status: ContactStatus::Converged,
        iterations,
        time: clock.elapsed(),
    };
    Some(finish_from_forces(problem, interface, raw, start))
}

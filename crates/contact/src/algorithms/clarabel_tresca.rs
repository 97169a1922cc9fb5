//! Coulomb friction by Clarabel: each load step as a sequence of Tresca problems (convex QPs with
//! a given slip bound `g_k`), the bound updated to `μ λ_k` of the last iterate until the Coulomb
//! fixed point — an independent check of the condensed active-set algorithms.
//!
//! ```text
//! Tresca QP:  minimise  ½ uᵀK u − w rᵀu + Σ_k g_k t_k
//!             subject to  gap_k = g0_k + (B_N u)_k ≥ 0,   t_k ≥ |Δs_k|,  Δs_k = (B_T u)_k − s_start,k
//! duals:      λ = z_N,   τ = z₋ − z₊ (z₊, z₋ of the rows t − Δs ≥ 0 and t + Δs ≥ 0),  z₊ + z₋ = g
//!             (from K u = w r + B_Nᵀ z_N − B_Tᵀ(z₊ − z₋), the problem's K u = w r + B_Nᵀλ + B_Tᵀτ)
//! fixed point: g⁽ʲ⁺¹⁾ = μ λ⁽ʲ⁾, from the frictionless λ, until max|Δλ| ≤ 1e-7 max λ, or until
//!             it stalls below 1e-5 for five iterations (the noise floor of degenerate pairs)
//!             (the interior-point solves are accurate to ~1e-9 relative, and to ~1e-7 where a
//!             pair is degenerate — λ = gap = 0 —, so a tighter test would measure their noise)
//! ```
//!
//! Variables are scaled like the frictionless QP (`u = s x`, `t = s y`). Each Tresca QP is solved
//! to 1e-10 (tighter tolerances stall on the slip rows, whose optimal face is degenerate where
//! t = |Δs| = 0); that is ample for a fixed point tested at 1e-7 and for the 1e-6 agreement
//! asked of the check. The fixed point need not converge for large μ: the limit is then
//! reported as [`ContactStatus::MaxIterations`].

use web_time::Instant;

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT};

use crate::algorithms::augmented_lagrangian::polish_state;
use crate::algorithms::clarabel_qp::{displacement_scale, map_status, solve_frictionless_qp};
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_displacement, force_scale};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// One Tresca solve: `(status, u_free, λ, τ, iterations)`.
type TrescaAnswer = (ContactStatus, Vec<f64>, Vec<f64>, Vec<f64>, usize);

/// Solves one frictional step to load factor `w` from `start` by the Tresca fixed point.
pub fn solve_frictional_qp(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    max_fixed_point: usize,
) -> ContactSolution {
    let clock = Instant::now();
    let m = problem.num_pairs();
    let frictionless = solve_frictionless_qp(problem, w);
    let mut in_contact: Vec<bool> = frictionless.state.iter().map(|s| *s != PairState::Free).collect();
    let mut lambda = frictionless.normal_force;
    let mut answer: TrescaAnswer = (ContactStatus::MaxIterations, vec![], vec![0.0; m], vec![0.0; m], 0);
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let (mut best_change, mut stalled) = (f64::INFINITY, 0);
    let mut settled = false;
    for it in 1..=max_fixed_point {
        iterations = it;
        let bound: Vec<f64> =
            (0..m).map(|k| if in_contact[k] { problem.friction[k] * lambda[k].max(0.0) } else { 0.0 }).collect();
        answer = solve_tresca(problem, w, start, &bound);
        if answer.0 != ContactStatus::Converged {
            status = answer.0;
            break;
        }
        let scale = answer.2.iter().fold(0.0f64, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
        let change = answer.2.iter().zip(&lambda).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        lambda.clone_from(&answer.2);
        let next = contact_set(problem, w, &answer.1, &lambda);
        trace.push(IterationRecord {
            iteration: it,
            changed: next.iter().zip(&in_contact).filter(|(a, b)| a != b).count(),
            in_contact: next.iter().filter(|c| **c).count(),
            slipping: (0..m)
                .filter(|&k| next[k] && answer.3[k].abs() >= bound[k] * (1.0 - 1e-6) && bound[k] > 0.0)
                .count(),
            residual: change / scale,
        });
        in_contact = next;
        // Converged at 1e-7; or at the solves' noise floor: below 1e-5 with no improvement over
        // five iterations (a degenerate pair flipping at round-off level).
        if change < best_change {
            (best_change, stalled) = (change, 0);
        } else {
            stalled += 1;
        }
        if change <= 1e-7 * scale || (best_change <= 1e-5 * scale && stalled >= 5) {
            status = ContactStatus::Converged;
            settled = true;
            break;
        }
    }
    let (_, u_free, normal_force, tangential_force, _) = answer;
    let u_free = if u_free.is_empty() { vec![0.0; problem.system.dofs.num_free()] } else { u_free };
    let raw = RawSolution { load_factor: w, normal_force, tangential_force, status, iterations, time: clock.elapsed() };
    let mut solution = finish_from_displacement(problem, &u_free, raw, start);
    solution.trace = trace;
    // The fixed point settles on λ; whether Coulomb's law holds depends on the accuracy of the
    // Tresca QPs (absolute tolerances on badly scaled data lose it at extreme stiffness ratios).
    // A pair inside the cone that slips, or beyond it, makes the answer a numerical failure.
    let cone = solution.kkt.max_cone_violation / force_scale_of(&solution).max(f64::MIN_POSITIVE);
    if solution.status == ContactStatus::Converged
        && (solution.kkt.max_slip_inside_cone > COULOMB_TOLERANCE || cone > COULOMB_TOLERANCE)
    {
        solution.status = ContactStatus::Numerical;
    }
    // Polishing (issue 12): the interior point resolves the pair states, but the forces only to
    // its tolerance (a degenerate pair — stuck on the cone, λ = gap = 0 — to about its square
    // root). The linear equations of its own states, solved exactly once (the full system,
    // crate::algorithms::augmented_lagrangian), give the answer those states imply; it replaces
    // the interior point's only if it passes every check of crate::certify::certify.
    if settled || status == ContactStatus::MaxIterations {
        let time = solution.time;
        if let Some(mut polished) = polish_state(problem, w, start, &solution.state, solution.iterations + 1)
            && polished.status == ContactStatus::Converged
        {
            polished.trace = std::mem::take(&mut solution.trace);
            polished.time += time;
            return polished;
        }
    }
    solution
}

/// Largest Coulomb residual (dimensionless) a converged fixed point may leave. On a degenerate
/// pair (stuck exactly on the cone) an interior point with tolerance 1e-10 resolves the slip and
/// the slack each to about √1e-10 = 1e-5 of their scales, so their product to 1e-10: two decades
/// above that; a wrong stick/slip split leaves 1e-7 and more (docs/stability.md).
const COULOMB_TOLERANCE: f64 = 1e-8;

/// The largest contact force of a solution (the scale of the cone violation).
fn force_scale_of(s: &ContactSolution) -> f64 {
    s.normal_force.iter().chain(&s.tangential_force).fold(0.0f64, |a, v| a.max(v.abs()))
}

/// Pairs in contact: the normalised force exceeds the normalised gap (an interior-point λ of a
/// free pair is tiny but not zero, and must not become a slip bound).
fn contact_set(problem: &ContactProblem, w: f64, u_free: &[f64], lambda: &[f64]) -> Vec<bool> {
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let gap: Vec<f64> =
        problem.normal_rows.iter().zip(&problem.gap).map(|(row, g0)| g0 + row.dot(u_free, &prescribed)).collect();
    let length = u_free.iter().chain(&gap).fold(0.0f64, |a, u| a.max(u.abs())).max(f64::MIN_POSITIVE);
    let force = force_scale(problem, w, lambda, &[], length);
    gap.iter().zip(lambda).map(|(g, l)| *l / force > g.max(0.0) / length).collect()
}

fn solve_tresca(problem: &ContactProblem, w: f64, start: &StepStart, bound: &[f64]) -> TrescaAnswer {
    let n = problem.system.dofs.num_free();
    let m = problem.num_pairs();
    // Pairs with a zero bound have τ = 0 (|τ| ≤ 0) and no slip variable: a free t with zero cost
    // would leave the QP an unbounded optimal face.
    let friction_pairs: Vec<usize> =
        (0..m).filter(|&k| problem.tangential[k] && problem.friction[k] > 0.0 && bound[k] > 0.0).collect();
    let nt = friction_pairs.len();
    let prescribed: Vec<f64> = problem.pattern_prescribed.iter().map(|v| w * v).collect();
    let constrained_part =
        |row: &crate::problem::PairRow| row.constrained.iter().map(|(j, v)| v * prescribed[*j]).sum::<f64>();
    let b_normal: Vec<f64> =
        problem.normal_rows.iter().zip(&problem.gap).map(|(r, g0)| g0 + constrained_part(r)).collect();
    let c_t: Vec<f64> =
        friction_pairs.iter().map(|&k| constrained_part(&problem.tangent_rows[k]) - start.slip[k]).collect();
    let s = b_normal.iter().chain(&prescribed).chain(&c_t).fold(0.0f64, |a, v| a.max(v.abs()));
    let s = s.max(displacement_scale(problem, w));
    let s = if s > 0.0 { s } else { 1.0 };

    // P = [K 0; 0 0] (upper triangle of K from its stored lower triangle).
    let k = problem.system.stiffness.as_ref();
    let (mut pr, mut pc, mut pv) = (vec![], vec![], vec![]);
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            pr.push(j);
            pc.push(i);
            pv.push(*v);
        }
    }
    let p = CscMatrix::new_from_triplets(n + nt, n + nt, pr, pc, pv);
    let mut q: Vec<f64> = problem.pattern_rhs.iter().map(|r| -w * r / s).collect();
    q.extend(friction_pairs.iter().map(|&k| bound[k] / s));

    let (mut ar, mut ac, mut av, mut b) = (vec![], vec![], vec![], vec![]);
    for (row, r) in problem.normal_rows.iter().enumerate() {
        for (i, v) in &r.free {
            ar.push(row);
            ac.push(*i);
            av.push(-v);
        }
        b.push(b_normal[row] / s);
    }
    for (j, &kk) in friction_pairs.iter().enumerate() {
        for (sign, offset) in [(1.0, m + 2 * j), (-1.0, m + 2 * j + 1)] {
            // sign +1: t − Δs ≥ 0 ;  sign −1: t + Δs ≥ 0
            for (i, v) in &problem.tangent_rows[kk].free {
                ar.push(offset);
                ac.push(*i);
                av.push(sign * v);
            }
            ar.push(offset);
            ac.push(n + j);
            av.push(-1.0);
            b.push(-sign * c_t[j] / s);
        }
    }
    let a = CscMatrix::new_from_triplets(m + 2 * nt, n + nt, ar, ac, av);
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_gap_abs(1e-10)
        .tol_gap_rel(1e-10)
        .tol_feas(1e-10)
        .max_iter(200)
        .build();
    let cones = [NonnegativeConeT(m + 2 * nt)];
    let Ok(settings) = settings else { return (ContactStatus::Numerical, vec![], vec![0.0; m], vec![0.0; m], 0) };
    let Ok(mut solver) = DefaultSolver::new(&p, &q, &a, &b, &cones, settings) else {
        return (ContactStatus::Numerical, vec![], vec![0.0; m], vec![0.0; m], 0);
    };
    solver.solve();
    let sol = &solver.solution;
    let u: Vec<f64> = sol.x[..n].iter().map(|v| v * s).collect();
    let lambda: Vec<f64> = sol.z[..m].iter().map(|v| v * s).collect();
    let mut tau = vec![0.0; m];
    for (j, &kk) in friction_pairs.iter().enumerate() {
        tau[kk] = s * (sol.z[m + 2 * j + 1] - sol.z[m + 2 * j]);
    }
    (map_status(sol.status), u, lambda, tau, sol.iterations as usize)
}

//! Coulomb friction by Clarabel: each load step as a sequence of Tresca problems (convex QPs with
//! a given slip bound `g_k`), the bound updated to `μ λ_k` of the last iterate until the Coulomb
//! fixed point — an independent check of the condensed active-set algorithms.
//!
//! ```text
//! Tresca QP (dual, crate::algorithms::clarabel_qp):
//!             minimise  ½ fᵀ C f + d_Nᵀ λ + d_Tᵀ τ   subject to  λ ≥ 0,  |τ_k| ≤ g_k
//!             (C = B K⁻¹ Bᵀ on the interface, d_N = g0 + w h_N, d_T = w h_T − s_start:
//!             the gap is the multiplier of λ ≥ 0, and τ opposes the slip Δs where |τ| = g)
//! fixed point: g⁽ʲ⁺¹⁾ = μ λ⁽ʲ⁾ on the pairs in contact, from the frictionless λ
//! each iterate: its pair states (free, stick, slip±; crate::report) and their exact equations
//!             (polishing, crate::algorithms::clarabel_qp::polish); the first polished answer
//!             that passes crate::certify::certify ends the step
//! otherwise:  until max|Δλ| ≤ 1e-7 max λ, or until it stalls below 1e-5 for five iterations
//!             (the noise floor of degenerate pairs); the last iterate is then reported, and
//!             as Numerical if it breaks Coulomb's law by more than COULOMB_TOLERANCE
//! ```
//!
//! The iterate only has to find the states: the polished answer is the exact solution of
//! them, so its forces agree with any other exact solver's (the active set's) to round-off
//! when the states are the same, and the certificate (penetration, complementarity, cone,
//! slip inside the cone, dissipation sign) judges it whatever found them. Each Tresca QP is
//! solved to 1e-10 on scaled data (crate::algorithms::clarabel_qp). The fixed point need not
//! converge for large μ: the limit is then reported as [`ContactStatus::MaxIterations`].

use web_time::Instant;

use crate::algorithms::clarabel_qp::{DualAnswer, DualProblem, polish};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_forces};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// Solves one frictional step to load factor `w` from `start` by the Tresca fixed point (the
/// interface is built from the problem's factorisation; [`solve_frictional_qp_on`] reuses one).
pub fn solve_frictional_qp(
    problem: &ContactProblem,
    w: f64,
    start: &StepStart,
    max_fixed_point: usize,
) -> ContactSolution {
    let interface = Interface::new(problem);
    solve_frictional_qp_on(problem, &interface, w, start, max_fixed_point)
}

/// Solves one frictional step to load factor `w` from `start` by the Tresca fixed point on
/// `interface` (module docs).
pub fn solve_frictional_qp_on(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    max_fixed_point: usize,
) -> ContactSolution {
    solve_frictional_qp_from(problem, interface, w, start, None, max_fixed_point)
}

/// [`solve_frictional_qp_on`] with the fixed point warm-started from the pair states `guess`
/// (those of the step before, or of the previous inner solve of a body held only by contact):
///
/// ```text
/// λ⁰ = the exact solution of the guessed states (polishing), in place of the frictionless λ:
///      the first thresholds are g = μ λ⁰ on the pairs it closes
/// if λ⁰ passes the certificate, it is the candidate: the first Tresca QP checks it
///      (max|λ¹ − λ⁰| ≤ 1e-5 max λ¹ and the states of λ¹ are the guess's: a fixed point of
///      the Tresca map, it ends the step)
/// otherwise the fixed point goes on from λ¹ as from any iterate
/// ```
///
/// The fixed point converges from any thresholds g ≥ 0 (where it converges at all), and the
/// answer is accepted by the same tests as without a guess (a certified polish that the Tresca
/// QP of its own thresholds reproduces, or λ settled), so a guess changes the work, not the
/// conditions the answer meets; the states are still those of a Clarabel solve. A guess of
/// another length than the pairs, with every pair free, or whose equations are singular, is
/// ignored: the fixed point then starts from the frictionless λ.
pub fn solve_frictional_qp_from(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_fixed_point: usize,
) -> ContactSolution {
    // The sparse path's interface holds no compliances: condense here (this algorithm works on them).
    let condensed = interface.condensed(problem);
    let interface = &*condensed;
    let clock = Instant::now();
    let m = problem.num_pairs();
    let dual = DualProblem::new(problem, interface, w, start);
    let mut working = dual.initial_working_set();
    let warm = guess
        .filter(|states| states.len() == m && states.iter().any(|s| *s != PairState::Free))
        .and_then(|states| polish(problem, interface, w, start, states, 0))
        .filter(|polished| polished.normal_force.iter().chain(&polished.tangential_force).all(|f| f.is_finite()));
    // A polished, certified answer waiting for its consistency check (see below).
    let mut candidate: Option<ContactSolution> = None;
    let (mut lambda, mut in_contact, mut tau, mut status);
    if let Some(polished) = warm {
        // The guess's contact pairs join the working set (a pair of the set with λ = 0 costs
        // one unknown, never the answer).
        for (k, in_set) in working.iter_mut().enumerate() {
            *in_set |= dual.is_normal(k) && polished.normal_force[k] > 0.0;
        }
        lambda = polished.normal_force.clone();
        in_contact = contact_set(&dual, &lambda, &polished.tangential_force);
        (tau, status) = (vec![0.0; m], ContactStatus::Converged);
        if polished.status == ContactStatus::Converged {
            candidate = Some(polished);
        }
    } else {
        let frictionless = dual.solve(&vec![0.0; m], &mut working);
        lambda = frictionless.lambda;
        in_contact = contact_set(&dual, &lambda, &frictionless.tau);
        (tau, status) = (vec![0.0; m], frictionless.status);
    }
    // The warm candidate's check failing is no sign of cycling (it is not an iterate): the
    // iterates after it may still take the shortcut.
    let mut warm_candidate = candidate.is_some();
    let mut iterations = 0;
    let mut trace = Vec::new();
    let (mut best_change, mut stalled) = (f64::INFINITY, 0);
    // Whether a certified polish may jump the thresholds to its λ; after one candidate fails
    // its check the iterates go on plainly until λ settles (no cycling between two states).
    let mut shortcut = true;
    let fixed_point = if status == ContactStatus::Converged { max_fixed_point } else { 0 };
    for it in 1..=fixed_point {
        iterations = it;
        status = ContactStatus::MaxIterations;
        let bound: Vec<f64> =
            (0..m).map(|k| if in_contact[k] { problem.friction[k] * lambda[k].max(0.0) } else { 0.0 }).collect();
        let answer = dual.solve(&bound, &mut working);
        if answer.status != ContactStatus::Converged {
            status = answer.status;
            break;
        }
        let scale = answer.lambda.iter().fold(0.0f64, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
        let change = answer.lambda.iter().zip(&lambda).fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
        // The candidate is a fixed point of the Tresca map when the QP with its thresholds
        // returns its λ (to 1e-5, the agreement the check promises): then it ends the step. An
        // earlier iterate's states can pass the certificate's 1e-4 and still be another Coulomb
        // state than the fixed point's (pin_lug step 4: 3e-5 off in the normal force); this
        // check costs one QP where waiting for the iterates to settle cost several.
        if let Some(mut accepted) = candidate.take() {
            // A guess's candidate must also be the states of this QP's answer, as a candidate of
            // the iteration is the states of an answer: a guess can sit on another Coulomb state
            // within the certificate's tolerance (a degenerate pair on the cone, cattaneo_mindlin
            // step 4: dissipation −7e-8 where the iteration finds 0).
            let reproduced = !warm_candidate || states_of(problem, interface, w, start, &answer) == accepted.state;
            if change <= 1e-5 * scale && reproduced {
                if warm_candidate {
                    // The one Tresca QP that checked the guess.
                    accepted.iterations = it;
                }
                accepted.trace = trace;
                accepted.time = clock.elapsed();
                return accepted;
            }
            shortcut = warm_candidate;
            warm_candidate = false;
        }
        (lambda, tau) = (answer.lambda, answer.tau);
        let next = contact_set(&dual, &lambda, &tau);
        trace.push(IterationRecord {
            iteration: it,
            changed: next.iter().zip(&in_contact).filter(|(a, b)| a != b).count(),
            in_contact: next.iter().filter(|c| **c).count(),
            slipping: (0..m).filter(|&k| next[k] && tau[k].abs() >= bound[k] * (1.0 - 1e-6) && bound[k] > 0.0).count(),
            residual: change / scale,
        });
        in_contact = next;
        // The states of this iterate (free, stick, slip±, crate::report) and their exact
        // equations (polishing): a certified answer ends the step once λ has settled (1e-5);
        // before that it becomes the candidate, its λ the next thresholds.
        let raw = RawSolution {
            load_factor: w,
            normal_force: lambda.clone(),
            tangential_force: tau.clone(),
            status: ContactStatus::Converged,
            iterations: it,
            time: clock.elapsed(),
        };
        let states = finish_from_forces(problem, interface, raw, start).state;
        let settled = change <= 1e-5 * scale;
        if (settled || shortcut)
            && let Some(mut polished) = polish(problem, interface, w, start, &states, it)
            && polished.status == ContactStatus::Converged
        {
            if settled {
                polished.trace = trace;
                polished.time = clock.elapsed();
                return polished;
            }
            lambda.clone_from(&polished.normal_force);
            in_contact = contact_set(&dual, &lambda, &polished.tangential_force);
            candidate = Some(polished);
            continue;
        }
        // Converged at 1e-7; or at the solves' noise floor: below 1e-5 with no improvement over
        // five iterations (a degenerate pair flipping at round-off level).
        if change < best_change {
            (best_change, stalled) = (change, 0);
        } else {
            stalled += 1;
        }
        if change <= 1e-7 * scale || (best_change <= 1e-5 * scale && stalled >= 5) {
            status = ContactStatus::Converged;
            break;
        }
    }
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: tau,
        status,
        iterations: iterations.max(1),
        time: clock.elapsed(),
    };
    let mut solution = finish_from_forces(problem, interface, raw, start);
    solution.trace = trace;
    // The fixed point settles on λ; whether Coulomb's law holds depends on the accuracy of the
    // Tresca QPs. A pair inside the cone that slips, or beyond it, makes the answer a numerical
    // failure.
    let cone = solution.kkt.max_cone_violation / force_scale_of(&solution).max(f64::MIN_POSITIVE);
    if solution.status == ContactStatus::Converged
        && (solution.kkt.max_slip_inside_cone > COULOMB_TOLERANCE || cone > COULOMB_TOLERANCE)
    {
        solution.status = ContactStatus::Numerical;
    }
    solution
}

/// The pair states (free, stick, slip±; crate::report) of a Tresca QP's answer.
fn states_of(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    answer: &DualAnswer,
) -> Vec<PairState> {
    let raw = RawSolution {
        load_factor: w,
        normal_force: answer.lambda.clone(),
        tangential_force: answer.tau.clone(),
        status: ContactStatus::Converged,
        iterations: 0,
        time: std::time::Duration::ZERO,
    };
    finish_from_forces(problem, interface, raw, start).state
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
fn contact_set(dual: &DualProblem, lambda: &[f64], tau: &[f64]) -> Vec<bool> {
    let gap = dual.gaps(lambda, tau);
    let length = gap.iter().fold(dual.length(), |a, g| a.max(g.abs())).max(f64::MIN_POSITIVE);
    let force = lambda.iter().chain(tau).fold(0.0f64, |a, l| a.max(l.abs())).max(f64::MIN_POSITIVE);
    gap.iter().zip(lambda).map(|(g, l)| *l / force > g.max(0.0) / length).collect()
}

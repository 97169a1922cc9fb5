//! Coulomb friction in one quasi-static load step by a primal-dual active set (semi-smooth
//! Newton) on the condensed interface.
//!
//! ```text
//! gap = g0 + w h_N + C_NN λ + C_NT τ          s = w h_T + C_TN λ + C_TT τ,   Δs = s − s_start
//! free:   λ = 0, τ = 0                        (gap ≥ 0)
//! stick:  gap = 0, Δs = 0                     (|τ| ≤ μλ)
//! slip+:  gap = 0, τ = −μλ                    (Δs > 0: master slides along +t; f1 = μp + q = 0)
//! slip−:  gap = 0, τ = +μλ                    (Δs < 0; f2 = μp − q = 0)
//! update: contact ⇔ λ − c_N gap > 0;  in contact, with θ = τ − c_T Δs:
//!         stick ⇔ |θ| ≤ μ(λ − c_N gap);  else slip with τ = μλ sign θ
//! ```
//!
//! With the paper's signs p = −λ/w, q = −τ/w (w the tributary length): the friction force on the
//! master opposes its slip, so the dissipation −τ Δs = q Δv_s w ≥ 0 (Q ≥ 0 in (5.1)).
//! The equations of a state are linear but not symmetric (the slip rows couple τ to λ); they are
//! solved densely (2 × pairs unknowns). Convergence is not guaranteed for large μ: the iteration
//! limit is then reported as [`ContactStatus::MaxIterations`]. On long interfaces the first step
//! follows a regularised stick law to the exact one (`stick_continuation.rs`), and a solve that
//! has not settled after 24 iterations goes on from coarser sets of the pairs
//! (`coarse_start.rs`), so that the stick–slip fronts do not move by one pair per iteration.
//!
//! # References
//! Hüeber, Stadler & Wohlmuth (2008), SIAM J. Sci. Comput. 30(2): a primal-dual active set
//! algorithm for three-dimensional contact problems with Coulomb friction.

use web_time::Instant;

use nalgebra::{DMatrix, DVector};

use crate::algorithms::coarse_start::{self, coarse_start};
use crate::algorithms::semi_smooth::{Iterate, VisitedStates, admissible, next_state, stick_reversals};
use crate::algorithms::sparse_active_set::solve_sparse_active_set;
use crate::algorithms::state_equations::{combine, solve_regularised_state_equations};
use crate::algorithms::stick_continuation::{
    IterationLimit, StartingStates, StickContinuation, StickStage, add_layer_slip, stage_limit,
};
use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::report::{RawSolution, finish_from_forces};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// Solves one frictional step to load factor `w` from the history `start`, starting from the
/// state guess `guess` (e.g. the previous step's states; `None`: all in contact and sticking),
/// with [`StickContinuation::Auto`]. On an interface of the sparse path ([`Interface::sparse`])
/// each state is solved on the full system (`sparse_active_set.rs`).
pub fn solve_frictional_active_set(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_iterations: usize,
) -> ContactSolution {
    solve_frictional_active_set_with(problem, interface, w, start, guess, max_iterations, StickContinuation::Auto)
}

/// [`solve_frictional_active_set`] with the choice of `continuation`: regularised stick stages
/// (`Δs_k + e_k τ_k = 0`, `e → 0`) before the exact law, each starting from the last one's state
/// (`algorithms/stick_continuation.rs`). `max_iterations` bounds all stages together.
pub fn solve_frictional_active_set_with(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    max_iterations: usize,
    continuation: StickContinuation,
) -> ContactSolution {
    let starting = StartingStates::of(guess.is_some(), false);
    solve_frictional_active_set_from(problem, interface, w, start, guess, starting, max_iterations, continuation)
}

/// [`solve_frictional_active_set_with`] told how far `guess` may be from the answer: from a
/// [`StartingStates::Far`] guess the regularised stages run as from the all-stick start
/// (`stick_continuation.rs`; a floating body's Newton step, `floating.rs`). From any start, a
/// long interface whose iteration has not settled after [`coarse_start::PLAIN_ITERATIONS`]
/// goes on from the states of coarser sets of its pairs (`coarse_start.rs`); the iterations and
/// trace count every level's.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_frictional_active_set_from(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    starting: StartingStates,
    max_iterations: usize,
    continuation: StickContinuation,
) -> ContactSolution {
    let whole = IterationLimit::whole(max_iterations);
    let coarse = coarse_start::applies(problem, continuation);
    if !coarse || max_iterations <= coarse_start::PLAIN_ITERATIONS {
        return solve_from_states(problem, interface, w, start, guess, starting, whole, continuation);
    }
    let clock = Instant::now();
    let plain_limit = IterationLimit { stop: coarse_start::PLAIN_ITERATIONS, ..whole };
    let plain = solve_from_states(problem, interface, w, start, guess, starting, plain_limit, continuation);
    if plain.status != ContactStatus::MaxIterations {
        return plain;
    }
    let solve = |level: &ContactProblem, interface: &Interface, guess: Option<&[PairState]>, limit| {
        solve_from_states(level, interface, w, start, guess, StartingStates::Close, limit, continuation)
    };
    // The coarse levels take at most half of what the plain iteration left.
    let left = max_iterations - plain.iterations;
    let Some(levels) = coarse_start(problem, interface, &plain.state, left / 2, solve) else {
        return plain;
    };
    let mut trace = plain.trace;
    let offset = trace.len();
    trace.extend(levels.trace.iter().map(|r| IterationRecord { iteration: offset + r.iteration, ..*r }));
    let used = trace.len();
    let limit = IterationLimit { stop: max_iterations.saturating_sub(used).max(1), ..whole };
    let guess = Some(levels.states.as_slice());
    let mut solution =
        solve_from_states(problem, interface, w, start, guess, StartingStates::Close, limit, continuation);
    trace.extend(solution.trace.iter().map(|r| IterationRecord { iteration: used + r.iteration, ..*r }));
    solution.trace = trace;
    solution.iterations += used;
    solution.time = clock.elapsed();
    solution
}

/// [`solve_frictional_active_set_from`] without coarse levels, stopping after `limit.stop`
/// iterations.
#[allow(clippy::too_many_arguments)]
fn solve_from_states(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    starting: StartingStates,
    limit: IterationLimit,
    continuation: StickContinuation,
) -> ContactSolution {
    if !interface.is_condensed() {
        return solve_sparse_active_set(problem, interface, w, start, guess, starting, limit, continuation);
    }
    let clock = Instant::now();
    let m = problem.num_pairs();
    let frictional = interface.c_tt.nrows() == m;
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => vec![PairState::Stick; m],
    };
    // A pair without a normal unknown (held along its normal by fixes) is left to the fixes.
    for (s, _) in state.iter_mut().zip(&problem.normal).filter(|(_, normal)| !**normal) {
        *s = PairState::Free;
    }
    let mean_diag = |c: &DMatrix<f64>| (0..c.nrows()).map(|k| c[(k, k)]).sum::<f64>() / c.nrows().max(1) as f64;
    let c_n = 1.0 / mean_diag(&interface.c_nn).max(f64::MIN_POSITIVE);
    let c_t = if frictional { 1.0 / mean_diag(&interface.c_tt).max(f64::MIN_POSITIVE) } else { 0.0 };
    let (mut lambda, mut tau) = (vec![0.0; m], vec![0.0; m]);
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let mut stage = StickStage::first(problem, continuation, c_t, frictional, starting);
    let mut compliances = stage.map(|s| s.compliances(problem)).unwrap_or_default();
    let mut stage_iterations = 0;
    // The state before the last (a two-state cycle is broken, `semi_smooth.rs`).
    let mut before: Option<Vec<PairState>> = None;
    // The exact law's states so far (longer cycles are broken, `semi_smooth.rs`).
    let mut visited = VisitedStates::default();
    for it in 1..=limit.stop {
        iterations = it;
        let Some((l, t)) = solve_state(problem, interface, w, start, &state, frictional, &compliances) else {
            status = ContactStatus::Numerical;
            break;
        };
        (lambda, tau) = (l, t);
        let (gap, mut slip) = interface_values(interface, w, &problem.gap, &lambda, &tau, frictional);
        add_layer_slip(&mut slip, &compliances, &tau);
        let iterate = Iterate { normal_force: &lambda, tangential_force: &tau, gap: &gap, slip: &slip };
        let mut next = next_state(problem, &iterate, start, (c_n, c_t), &compliances, frictional);
        if let Some(before) = &before {
            stick_reversals(before, &state, &mut next);
        }
        // Converged when the state repeats, or when the iterate already satisfies every
        // condition to round-off (a degenerate pair — λ = gap = 0 or |τ| = μλ with Δs = 0 —
        // may otherwise flip forever on round-off).
        let settled = next == state || admissible(problem, &state, &iterate, start);
        if stage.is_none() && !settled {
            visited.break_cycle(&state, &mut next);
        }
        trace.push(IterationRecord::of_states(it, &state, &next, 0.0));
        if let Some(current) = stage {
            // A regularised stage ends when its state settles or its share of the limit is
            // spent; its fixed point is a warm start, never the answer.
            stage_iterations += 1;
            if settled || stage_iterations >= stage_limit(limit.of_step) {
                stage = current.next();
                compliances = stage.map(|s| s.compliances(problem)).unwrap_or_default();
                stage_iterations = 0;
            }
        } else if settled {
            status = ContactStatus::Converged;
            break;
        }
        before = Some(std::mem::replace(&mut state, next));
    }
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: tau,
        status,
        iterations,
        time: clock.elapsed(),
    };
    let mut solution = finish_from_forces(problem, interface, raw, start);
    solution.trace = trace;
    solution
}

/// gap_k and s_k for given forces.
fn interface_values(
    interface: &Interface,
    w: f64,
    g0: &[f64],
    lambda: &[f64],
    tau: &[f64],
    frictional: bool,
) -> (Vec<f64>, Vec<f64>) {
    let m = lambda.len();
    let l = DVector::from_column_slice(lambda);
    let mut gap = &interface.c_nn * &l;
    let mut s = DVector::zeros(m);
    if frictional {
        let t = DVector::from_column_slice(tau);
        gap += &interface.c_nt * &t;
        s = &interface.c_tn * &l + &interface.c_tt * &t;
    }
    let gap = (0..m).map(|k| g0[k] + w * interface.h_normal[k] + gap[k]).collect();
    let s = (0..m).map(|k| if frictional { w * interface.h_tangent[k] + s[k] } else { 0.0 }).collect();
    (gap, s)
}

/// Solves the linear equations of a given state at load `w`, with the stick rows' regularising
/// compliances (empty: the exact law): `(λ, τ)`.
fn solve_state(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    state: &[PairState],
    frictional: bool,
    compliances: &[f64],
) -> Option<(Vec<f64>, Vec<f64>)> {
    let x = solve_regularised_state_equations(problem, interface, start, state, frictional, compliances)?;
    Some(combine(&x, w))
}

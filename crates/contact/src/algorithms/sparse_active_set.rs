//! The primal-dual active set of `frictional_active_set.rs` on the sparse path: each state's
//! equations solved on the full system (`crate::kkt`) instead of the condensed interface, so no
//! dense block of the size of the interface is ever formed.
//!
//! ```text
//! state → [u_f, λ, τ] from the sparse state system (crate::kkt)
//! gap = ĝ + B_N,f u_f,   s = ŝ + B_T,f u_f,   Δs = s − s_start
//! update: contact ⇔ λ − c_N gap > 0;  in contact, with θ = τ − c_T Δs:
//!         stick ⇔ |θ| ≤ μ(λ − c_N gap);  else slip with τ = μλ sign θ
//! c_N = 1 / mean_k C_NN,kk,   c_T = 1 / mean_k C_TT,kk,   C_kk = b_k · K⁻¹ b_k
//! ```
//!
//! The same update and constants as the condensed path, which reads `C_kk` off the compliances:
//! here they come from one multi-RHS solve with the state system's factor with every row
//! switched off (`[K 0; 0 I]`, so no factor of `K` alone is made), over every pair up to 64
//! pairs (the same constants up to round-off, so the same iterates) and over 8 pairs evenly
//! spread beyond (an estimate of the same mean; `c` sets the path of the iteration, not its
//! fixed point). A state that repeats
//! is the solution on either path, and the answers agree to round-off (`tests/integration/sparse_path.rs`).

use web_time::Instant;

use crate::algorithms::full_system::{contact_stiffness, dot_free, row_offsets};
use crate::algorithms::semi_smooth::{Iterate, VisitedStates, admissible, next_state, stick_reversals};
use crate::algorithms::stick_continuation::{
    IterationLimit, StartingStates, StickContinuation, StickStage, add_layer_slip, stage_limit,
};
use crate::interface::Interface;
use crate::kkt::{Accuracy, StateKkt};
use crate::problem::{ContactProblem, PairRow};
use crate::report::{RawSolution, finish_from_displacement};
use crate::solution::{ContactSolution, ContactStatus, IterationRecord, PairState, StepStart};

/// Pairs up to which the complementarity constants use every pair's compliance.
const COMPLIANCE_EXACT: usize = 64;

/// Pairs, evenly spread along the list, whose compliances estimate the constants above
/// [`COMPLIANCE_EXACT`] pairs (each costs two columns of one multi-RHS solve).
const COMPLIANCE_SAMPLES: usize = 8;

/// `(c_N, c_T)`: the condensed path's `1 / mean diag C_NN` and `1 / mean diag C_TT`
/// (`C_kk = b_k · K⁻¹ b_k`), from one multi-RHS solve with `kkt`'s factor with every row off
/// over every pair up to [`COMPLIANCE_EXACT`] pairs (the same constants, up to round-off) or
/// over [`COMPLIANCE_SAMPLES`] pairs evenly spread (an estimate of the same mean); `None` if
/// that factorisation fails.
fn complementarity_constants(problem: &ContactProblem, frictional: bool, kkt: &mut StateKkt) -> Option<(f64, f64)> {
    let m = problem.num_pairs();
    let picked: Vec<usize> = if m <= COMPLIANCE_EXACT {
        (0..m).collect()
    } else {
        (0..COMPLIANCE_SAMPLES).map(|i| i * (m - 1) / (COMPLIANCE_SAMPLES - 1)).collect()
    };
    let mut rows: Vec<&PairRow> = picked.iter().map(|&k| &problem.normal_rows[k]).collect();
    if frictional {
        rows.extend(picked.iter().map(|&k| &problem.tangent_rows[k]));
    }
    let mut z = faer::Mat::<f64>::zeros(kkt.dim(), rows.len());
    for (c, row) in rows.iter().enumerate() {
        row.free.iter().for_each(|&(i, v)| z[(i, c)] += v);
    }
    if !kkt.solve_stiffness_many(&mut z) {
        return None;
    }
    let diagonal: Vec<f64> =
        rows.iter().enumerate().map(|(c, row)| row.free.iter().map(|&(i, v)| v * z[(i, c)]).sum()).collect();
    let p = picked.len().max(1) as f64;
    let c_n = 1.0 / (diagonal[..picked.len()].iter().sum::<f64>() / p).max(f64::MIN_POSITIVE);
    let c_t =
        if frictional { 1.0 / (diagonal[picked.len()..].iter().sum::<f64>() / p).max(f64::MIN_POSITIVE) } else { 0.0 };
    Some((c_n, c_t))
}

/// Solves one step like [`crate::solve_frictional_active_set`], on the sparse path (`interface`
/// made by [`Interface::sparse`]), from `guess` as far from the answer as `starting` says.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_sparse_active_set(
    problem: &ContactProblem,
    interface: &Interface,
    w: f64,
    start: &StepStart,
    guess: Option<&[PairState]>,
    starting: StartingStates,
    limit: IterationLimit,
    continuation: StickContinuation,
) -> ContactSolution {
    let clock = Instant::now();
    let m = problem.num_pairs();
    let n = problem.system.dofs.num_free();
    let frictional = problem.is_frictional();
    let mut state: Vec<PairState> = match guess {
        Some(g) if g.len() == m => g.to_vec(),
        _ => vec![PairState::Stick; m],
    };
    for (s, _) in state.iter_mut().zip(&problem.normal).filter(|(_, normal)| !**normal) {
        *s = PairState::Free;
    }
    let mut cache = interface.kkt.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    if cache.as_ref().is_none_or(|kkt| kkt.is_frictional() != frictional) {
        *cache = StateKkt::new(problem, frictional, contact_stiffness(problem)).ok().and_then(|mut kkt| {
            kkt.constants = complementarity_constants(problem, frictional, &mut kkt)?;
            Some(kkt)
        });
    }
    let (c_n, c_t) = cache.as_ref().map_or((0.0, 0.0), |kkt| kkt.constants);
    let (mut lambda, mut tau, mut u) = (vec![0.0; m], vec![0.0; m], vec![0.0; n]);
    let mut status = ContactStatus::MaxIterations;
    let mut iterations = 0;
    let mut trace = Vec::new();
    let (g_hat, s_hat) = row_offsets(problem, w);
    let mut warm: Option<Vec<f64>> = None;
    let mut before: Option<Vec<PairState>> = None;
    // The exact law's states solved to round-off so far (longer cycles are broken,
    // `semi_smooth.rs`; a trial solution's cycle goes to the final accuracy first).
    let mut visited = VisitedStates::default();
    let mut stage = StickStage::first(problem, continuation, c_t, frictional, starting);
    // The exact law from a guess (a previous solve's states, or the stages' from one) resolves
    // the few pairs that change to round-off from its first iteration: a trial solution's
    // error (1e-4) flips pairs near the cone's edge, and the plain update then walks them back
    // one front pair per iteration (the floating pad at 3,001 pairs: 26 iterations from the
    // converged states; docs/benchmarks.md, "Floating bodies on long interfaces").
    let exact_accuracy = match starting {
        StartingStates::AllStick => Accuracy::Trial,
        StartingStates::Close | StartingStates::Far => Accuracy::Final,
    };
    let mut accuracy = if stage.is_some() { Accuracy::Trial } else { exact_accuracy };
    let mut compliances = stage.map(|s| s.compliances(problem)).unwrap_or_default();
    let mut stage_iterations = 0;
    // The state's solution to `accuracy` with the stick compliances `e`, its gaps and slips
    // (with the layer's, `stick_continuation.rs`), and the state the update picks.
    let mut evaluate = |state: &[PairState], accuracy: Accuracy, warm: Option<&[f64]>, e: &[f64]| {
        let solution = cache.as_mut()?.solve(problem, w, start, state, accuracy, warm, e)?;
        let u = &solution.displacement;
        let gap: Vec<f64> = (0..m).map(|k| g_hat[k] + dot_free(&problem.normal_rows[k], u)).collect();
        let mut slip: Vec<f64> =
            (0..m).map(|k| if frictional { s_hat[k] + dot_free(&problem.tangent_rows[k], u) } else { 0.0 }).collect();
        add_layer_slip(&mut slip, e, &solution.tangential_force);
        let iterate = Iterate {
            normal_force: &solution.normal_force,
            tangential_force: &solution.tangential_force,
            gap: &gap,
            slip: &slip,
        };
        let next = next_state(problem, &iterate, start, (c_n, c_t), e, frictional);
        let settled = next == state || admissible(problem, state, &iterate, start);
        Some((solution, next, settled))
    };
    for it in 1..=limit.stop {
        iterations = it;
        let Some((mut solution, mut next, mut settled)) = evaluate(&state, accuracy, warm.as_deref(), &compliances)
        else {
            status = ContactStatus::Numerical;
            break;
        };
        if let Some(current) = stage {
            // A regularised stage: its trial solutions only choose the next state; it ends when
            // its state settles or its share of the limit is spent (a warm start, never the
            // answer).
            if let Some(before) = &before {
                stick_reversals(before, &state, &mut next);
            }
            trace.push(IterationRecord::of_states(it, &state, &next, 0.0));
            stage_iterations += 1;
            if settled || stage_iterations >= stage_limit(limit.of_step) {
                stage = current.next();
                compliances = stage.map(|s| s.compliances(problem)).unwrap_or_default();
                stage_iterations = 0;
                if stage.is_none() {
                    accuracy = exact_accuracy;
                }
            }
            warm = Some(solution.unknowns);
            before = Some(std::mem::replace(&mut state, next));
            continue;
        }
        if settled && accuracy == Accuracy::Trial {
            // The state repeats on a trial solution: the answer is its solution to round-off,
            // and the state must repeat on that too.
            let Some(fine) = evaluate(&state, Accuracy::Final, Some(&solution.unknowns), &[]) else {
                status = ContactStatus::Numerical;
                break;
            };
            (solution, next, settled) = fine;
            // A trial solution that misjudged its state: the rest of the step is solved to
            // round-off (a trial error could otherwise send the iteration round a cycle).
            if !settled {
                accuracy = Accuracy::Final;
            }
        }
        // Back to the state before: a cycle (its round-off needs the final accuracy, below).
        // A pair back to its slip of the state before, reversed twice, sticks (`semi_smooth.rs`).
        let cycle = before.as_ref() == Some(&next);
        if let Some(before) = &before {
            stick_reversals(before, &state, &mut next);
        }
        if accuracy == Accuracy::Final && !settled {
            visited.break_cycle(&state, &mut next);
        }
        trace.push(IterationRecord::of_states(it, &state, &next, 0.0));
        warm = Some(solution.unknowns);
        (lambda, tau, u) = (solution.normal_force, solution.tangential_force, solution.displacement);
        if settled {
            status = ContactStatus::Converged;
            break;
        }
        // A cycle, which the condensed path ends by the round-off test of `admissible` (a pair
        // on the cone's edge) where no pair reverses; that test needs round-off accuracy.
        if cycle {
            accuracy = Accuracy::Final;
        }
        before = Some(std::mem::replace(&mut state, next));
    }
    drop(cache);
    let raw = RawSolution {
        load_factor: w,
        normal_force: lambda,
        tangential_force: tau,
        status,
        iterations,
        time: clock.elapsed(),
    };
    let mut solution = finish_from_displacement(problem, &u, raw, start);
    solution.trace = trace;
    solution
}

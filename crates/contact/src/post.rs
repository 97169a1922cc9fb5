//! Post-processing along the master contour: η, pressure p and shear q, contact end l.
//!
//! ```text
//! p_k = −λ_k / w_k,  q_k = −τ_k / w_k     (w_k: tributary length ∫ N_k ds of the master node;
//!                                          for Line3 edges ∫N ds = L/6, 2L/3, L/6, so a uniform
//!                                          pressure is recovered exactly)
//! l: bracketed by the last contact node η_c and the first free node η_f. Near a smooth receding
//!    contact end the gap opens like (η − l)^{3/2}, so g^{2/3} is linear on the free side:
//!        l = η_f − g_f^{2/3} (η_f2 − η_f)/(g_f2^{2/3} − g_f^{2/3})     (η_f2: the next free node)
//!    clamped to [η_c, η_f]. The gap side is used because it is smooth, whereas nodal pressures
//!    of quadratic edges alternate between corner and mid nodes. (The pressure side, p ∝ √(l − η),
//!    is [`contact_end_from_pressure`].)
//! b: bracketed by the last stick node and the first slipping node beyond it; the slip opens
//!    like the gap, |Δs| ∝ (η − b)^{3/2}, so |Δs|^{2/3} is interpolated over the first two
//!    slipping nodes, clamped to the bracket.
//! ```

use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, PairState};

/// Pressure and shear per pair, in the paper's convention (`p < 0` in compression).
pub fn pair_tractions(problem: &ContactProblem, solution: &ContactSolution) -> (Vec<f64>, Vec<f64>) {
    let p = problem.pairs.iter().zip(&solution.normal_force).map(|(pair, l)| -l / pair.weight).collect();
    let q = problem.pairs.iter().zip(&solution.tangential_force).map(|(pair, t)| -t / pair.weight).collect();
    (p, q)
}

/// Pair indices sorted by η.
fn sorted_by_eta(eta: &[f64]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..eta.len()).collect();
    order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
    order
}

/// The zone end from a quantity that opens like `(η − end)^{3/2}` beyond it: `v^{2/3}` is
/// interpolated linearly over the first two pairs past the end (`after`, in η order) and
/// clamped to the bracket; without a second pair, the bracket's lower end.
fn three_halves_end(eta: &[f64], v: &[f64], after: &[usize], bracket: [f64; 2]) -> f64 {
    let [f, f2] = match after {
        [f, f2, ..] => [*f, *f2],
        _ => return bracket[0],
    };
    let (d1, d2) = (v[f].abs().powf(2.0 / 3.0), v[f2].abs().powf(2.0 / 3.0));
    let end = if d2 > d1 { eta[f] - d1 * (eta[f2] - eta[f]) / (d2 - d1) } else { eta[f] };
    end.clamp(bracket[0], bracket[1])
}

/// The last contact and first free positions in η order, `None` if there is no such pair.
fn free_transition(order: &[usize], state: &[PairState]) -> Option<usize> {
    let first_free = order.iter().position(|&k| state[k] == PairState::Free)?;
    (first_free > 0).then_some(first_free)
}

/// The contact end on a coordinate `eta` per pair (contact growing from small η), from the gaps
/// of the first two free pairs (see the module docs).
///
/// Returns `(l, bracket)` with `bracket = [last contact η, first free η]`; `None` when no pair
/// or every pair is in contact, or nothing is in contact.
pub fn contact_end(eta: &[f64], gap: &[f64], state: &[PairState]) -> Option<(f64, [f64; 2])> {
    let order = sorted_by_eta(eta);
    let first_free = free_transition(&order, state)?;
    let bracket = [eta[order[first_free - 1]], eta[order[first_free]]];
    let gaps: Vec<f64> = gap.iter().map(|g| g.max(0.0)).collect();
    Some((three_halves_end(eta, &gaps, &order[first_free..], bracket), bracket))
}

/// The contact end from the pressures of the last two contact pairs, `p ∝ √(l − η)`.
///
/// Returns `(l, bracket)` as [`contact_end`].
pub fn contact_end_from_pressure(eta: &[f64], pressure: &[f64], state: &[PairState]) -> Option<(f64, [f64; 2])> {
    let order = sorted_by_eta(eta);
    let first_free = free_transition(&order, state)?;
    let (c, f) = (order[first_free - 1], order[first_free]);
    let bracket = [eta[c], eta[f]];
    if first_free < 2 {
        return Some((eta[c], bracket));
    }
    let prev = order[first_free - 2];
    let (pc2, pp2) = (pressure[c].powi(2), pressure[prev].powi(2));
    let l = if pp2 > pc2 { eta[c] + pc2 * (eta[c] - eta[prev]) / (pp2 - pc2) } else { eta[c] };
    Some((l.clamp(bracket[0], bracket[1]), bracket))
}

/// The end of the stick zone on `eta` (stick from small η, then slip): `(b, bracket)` from the
/// slip increments of the first two slipping pairs (see the module docs). `None` without a
/// stick-to-slip transition; without slip, use the contact end instead.
pub fn stick_end(eta: &[f64], slip_increment: &[f64], state: &[PairState]) -> Option<(f64, [f64; 2])> {
    let order = sorted_by_eta(eta);
    let slipping = |k: usize| matches!(state[k], PairState::SlipPositive | PairState::SlipNegative);
    let last_stick = order.iter().rposition(|&k| state[k] == PairState::Stick)?;
    let first_slip = last_stick + 1 + order[last_stick + 1..].iter().position(|&k| slipping(k))?;
    let bracket = [eta[order[last_stick]], eta[order[first_slip]]];
    let run = order[first_slip..].iter().take_while(|&&k| slipping(k)).count();
    let after = &order[first_slip..first_slip + run];
    Some((three_halves_end(eta, slip_increment, after, bracket), bracket))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_root_profile_gives_its_end_exactly() {
        // p = -√(0.47 − η) on nodes 0, 0.1, ..., 0.4 in contact; 0.5 free.
        let eta: Vec<f64> = (0..=5).map(|k| 0.1 * k as f64).collect();
        let p: Vec<f64> = eta.iter().map(|e| if *e < 0.47 { -(0.47 - e).sqrt() } else { 0.0 }).collect();
        let state: Vec<PairState> =
            eta.iter().map(|e| if *e < 0.47 { PairState::Stick } else { PairState::Free }).collect();
        let (l, bracket) = contact_end_from_pressure(&eta, &p, &state).unwrap_or((f64::NAN, [0.0; 2]));
        assert!((l - 0.47).abs() < 1e-12);
        assert_eq!(bracket, [eta[4], eta[5]]);
    }

    #[test]
    fn three_halves_gap_profile_gives_its_end_exactly() {
        // gap = (η − 0.47)^{3/2} beyond 0.47.
        let eta: Vec<f64> = (0..=7).map(|k| 0.1 * k as f64).collect();
        let g: Vec<f64> = eta.iter().map(|e| (e - 0.47).max(0.0).powf(1.5)).collect();
        let state: Vec<PairState> =
            eta.iter().map(|e| if *e < 0.47 { PairState::Stick } else { PairState::Free }).collect();
        let (l, _) = contact_end(&eta, &g, &state).unwrap_or((f64::NAN, [0.0; 2]));
        assert!((l - 0.47).abs() < 1e-12);
    }
}

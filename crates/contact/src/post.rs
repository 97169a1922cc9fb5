//! Post-processing along the master contour: η, pressure p and shear q, contact end l.
//!
//! ```text
//! p_k = −λ_k / w_k,  q_k = −τ_k / w_k     (w_k: tributary length ∫ N_k ds of the master node;
//!                                          for Line3 edges ∫N ds = L/6, 2L/3, L/6, so a uniform
//!                                          pressure is recovered exactly)
//! l: between the last contact node η_c and the first free node, the pressure of a smooth receding
//!    contact behaves like √(l − η), so p² is linear:  l = η_c + p_c² (η_c − η_p)/(p_p² − p_c²)
//!    with η_p the contact node before η_c; clamped to the bracket [η_c, η_free].
//! ```

use crate::problem::ContactProblem;
use crate::solution::{ContactSolution, PairState};

/// Pressure and shear per pair, in the paper's convention (`p < 0` in compression).
pub fn pair_tractions(problem: &ContactProblem, solution: &ContactSolution) -> (Vec<f64>, Vec<f64>) {
    let p = problem.pairs.iter().zip(&solution.normal_force).map(|(pair, l)| -l / pair.weight).collect();
    let q = problem.pairs.iter().zip(&solution.tangential_force).map(|(pair, t)| -t / pair.weight).collect();
    (p, q)
}

/// The contact end on a coordinate `eta` per pair (contact growing from small η).
///
/// Returns `(l, bracket)`: the square-root interpolation and `[last contact η, first free η]`;
/// `None` when no pair or every pair is in contact.
pub fn contact_end(eta: &[f64], pressure: &[f64], state: &[PairState]) -> Option<(f64, [f64; 2])> {
    let mut order: Vec<usize> = (0..eta.len()).collect();
    order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
    let first_free = order.iter().position(|&k| state[k] == PairState::Free)?;
    if first_free == 0 {
        return None;
    }
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
        let (l, bracket) = contact_end(&eta, &p, &state).unwrap_or((f64::NAN, [0.0; 2]));
        assert!((l - 0.47).abs() < 1e-12);
        assert_eq!(bracket, [eta[4], eta[5]]);
    }
}

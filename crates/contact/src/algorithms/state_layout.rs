//! Which unknowns a contact state leaves open on the condensed interface, and how the others
//! follow from them: the layout read by the state's equations (`state_equations`) and by their
//! low-rank update (`state_update`).
//!
//! ```text
//! A = {k : state_k ≠ free}                   (their λ are the first unknowns, in order)
//! S = {k ∈ A : stick, tangential unknown, μ_k > 0}   (their τ follow, in order)
//! τ_k = 0 (free, frictionless),  τ_k unknown (k ∈ S),  τ_k = σ_k μ_k λ_k (slip±, σ = ∓1)
//! ```

use faer::Mat;

use crate::interface::Interface;
use crate::problem::ContactProblem;
use crate::solution::{PairState, StepStart};

/// How pair `k`'s tangential force follows from its state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Tangential {
    /// `τ_k = 0` (free, no tangential unknown, or μ = 0).
    Zero,
    /// `τ_k` is an unknown of the reduced system at this position (stick).
    Unknown(usize),
    /// `τ_k = factor · λ_k` (slip: −μ for slip+, +μ for slip−).
    Slip(f64),
}

/// Which unknowns a state leaves open and how the others follow from them (module docs).
pub(crate) struct Layout {
    /// The pairs in contact: their `λ` are the first unknowns of the reduced system, in order.
    pub(crate) contact: Vec<usize>,
    /// The sticking pairs with a tangential unknown: their `τ` follow, in order.
    pub(crate) stick: Vec<usize>,
    /// Per pair, how its `τ` follows.
    pub(crate) tangential: Vec<Tangential>,
}

impl Layout {
    /// The layout of `state`; `frictional` says whether the interface has tangential compliances.
    pub(crate) fn of(problem: &ContactProblem, state: &[PairState], frictional: bool) -> Layout {
        let m = state.len();
        let contact: Vec<usize> = (0..m).filter(|&k| state[k] != PairState::Free).collect();
        let mut tangential = vec![Tangential::Zero; m];
        let mut stick = Vec::new();
        for &k in &contact {
            let mu = problem.friction[k];
            if !frictional || !problem.tangential[k] || mu == 0.0 {
                continue;
            }
            tangential[k] = match state[k] {
                PairState::Stick => {
                    stick.push(k);
                    Tangential::Unknown(contact.len() + stick.len() - 1)
                }
                PairState::SlipPositive => Tangential::Slip(-mu),
                PairState::SlipNegative => Tangential::Slip(mu),
                PairState::Free => Tangential::Zero,
            };
        }
        Layout { contact, stick, tangential }
    }

    /// The size of the reduced system.
    pub(crate) fn size(&self) -> usize {
        self.contact.len() + self.stick.len()
    }

    /// Row `i` of the reduced system as `(pair, normal)`: the gap row of `contact[i]` (`i < na`)
    /// or the slip row of `stick[i − na]`.
    pub(crate) fn rows(&self) -> Vec<(usize, bool)> {
        self.contact.iter().map(|&k| (k, true)).chain(self.stick.iter().map(|&k| (k, false))).collect()
    }

    /// The right-hand sides of the full `2m × 2` system (A1: unit load, A2: gaps and history):
    /// nonzero on the gap rows of the pairs in contact and the slip rows of the sticking ones.
    pub(crate) fn full_rhs(&self, problem: &ContactProblem, interface: &Interface, start: &StepStart) -> Mat<f64> {
        let m = self.tangential.len();
        let mut b = Mat::<f64>::zeros(2 * m, 2);
        for &k in &self.contact {
            b[(k, 0)] = -interface.h_normal[k];
            b[(k, 1)] = -problem.gap[k];
        }
        for &k in &self.stick {
            b[(m + k, 0)] = -interface.h_tangent[k];
            b[(m + k, 1)] = start.slip[k];
        }
        b
    }
}

//! What every contact algorithm returns.

use std::time::Duration;

/// The state of one pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PairState {
    /// Not in contact (λ = 0, gap ≥ 0).
    Free,
    /// In contact, tangentially stuck (or frictionless contact).
    Stick,
    /// In contact, slipping with q = +μ|p| direction (f1 = 0).
    SlipPositive,
    /// In contact, slipping with q = −μ|p| direction (f2 = 0).
    SlipNegative,
}

impl PairState {
    /// Every state, in declaration order.
    pub const ALL: [PairState; 4] =
        [PairState::Free, PairState::Stick, PairState::SlipPositive, PairState::SlipNegative];

    /// The state a semi-smooth (active-set) update gives a pair from its trial forces: free when
    /// the trial normal force `σ ≤ 0`; stuck when it has no tangential law (`frictional` false)
    /// or `|θ| ≤ μ σ`; else slipping against the trial tangential force `θ`.
    pub fn from_trial(sigma: f64, theta: f64, mu: f64, frictional: bool) -> PairState {
        if sigma <= 0.0 {
            PairState::Free
        } else if !frictional || theta.abs() <= mu * sigma {
            PairState::Stick
        } else if theta > 0.0 {
            PairState::SlipNegative
        } else {
            PairState::SlipPositive
        }
    }
}

/// How an algorithm ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactStatus {
    /// Converged to the requested tolerance.
    Converged,
    /// Stopped at the iteration limit; the last iterate is returned.
    MaxIterations,
    /// The problem has no feasible point.
    Infeasible,
    /// A numerical failure (singular interface matrix, solver breakdown), or an answer the
    /// algorithm took for converged that fails [`crate::certify::certify`] (a KKT residual
    /// above its tolerance, or a non-finite number).
    Numerical,
    /// The algorithm's assumed structure gave a solution that violates an inequality of the
    /// contact conditions (the offending pairs are reported by the algorithm).
    Inadmissible,
    /// A regularised method (the penalty method) reached the fixed point of its own law, whose
    /// residuals hold to round-off, but the exact contact conditions fail
    /// [`crate::certify::certify`]: the penetration it allows (`kkt.max_penetration`) is part of
    /// the method. Never reported for an answer that passes the certificate.
    Penalised,
    /// A body held only by contact whose load the contact cannot hold: its closed pairs slip at
    /// the friction cone along a free rigid motion and the load along that motion exceeds what
    /// friction carries (gross slip; [`crate::NotHeld`]). The run ends at this step.
    NotHeld,
}

impl ContactStatus {
    /// Whether the algorithm solved its equations: [`ContactStatus::Converged`], or
    /// [`ContactStatus::Penalised`] (solved the regularised law). A history goes on after such a
    /// step.
    pub fn is_solved(self) -> bool {
        matches!(self, ContactStatus::Converged | ContactStatus::Penalised)
    }
}

/// Residuals of the discrete KKT conditions, in force and length units of the problem.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KktResiduals {
    /// max(−gap, 0).
    pub max_penetration: f64,
    /// max |λ · gap|.
    pub max_complementarity: f64,
    /// max(|τ| − μ λ, 0) (friction cone).
    pub max_cone_violation: f64,
    /// min over slipping pairs of τ · slip increment (≥ 0 when friction dissipates).
    pub min_dissipation: f64,
    /// max(−λ, 0) (tension in contact).
    pub max_tension: f64,
    /// Friction complementarity, dimensionless: max over frictional contact pairs of
    /// `(μλ − |τ|)⁺/λ_max · |Δs|/U` (λ_max: the largest contact force, U: the solution's length
    /// scale). Zero when every
    /// pair that slips is on the cone; a pair inside the cone that slips breaks Coulomb's law
    /// although `max_cone_violation` is zero.
    pub max_slip_inside_cone: f64,
}

/// The state at the start of a load step: the history a frictional step needs.
#[derive(Debug, Clone, PartialEq)]
pub struct StepStart {
    /// Relative tangential displacement `s` per pair.
    pub slip: Vec<f64>,
    /// Tangential force `τ` per pair.
    pub tangential_force: Vec<f64>,
}

impl StepStart {
    /// The virgin state: no slip, no force.
    pub fn initial(pairs: usize) -> StepStart {
        StepStart { slip: vec![0.0; pairs], tangential_force: vec![0.0; pairs] }
    }

    /// The state at the end of a solved step.
    pub fn after(solution: &ContactSolution) -> StepStart {
        StepStart { slip: solution.slip.clone(), tangential_force: solution.tangential_force.clone() }
    }
}

/// A solution of a [`crate::ContactProblem`].
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSolution {
    /// How the algorithm ended.
    pub status: ContactStatus,
    /// Load factor w.
    pub load_factor: f64,
    /// Displacements in global DOF order.
    pub displacement: Vec<f64>,
    /// Normal force λ per pair (on the master node along n; positive = compression).
    pub normal_force: Vec<f64>,
    /// Tangential force τ per pair (on the master node along t).
    pub tangential_force: Vec<f64>,
    /// Gap per pair at the solution.
    pub gap: Vec<f64>,
    /// State per pair.
    pub state: Vec<PairState>,
    /// Relative tangential displacement per pair, `s = B_T u` (master minus slave along t).
    pub slip: Vec<f64>,
    /// Its increment over the step, `Δs = s − s_start`.
    pub slip_increment: Vec<f64>,
    /// Energy dissipated by friction in the step: `Σ −½(τ_start + τ) Δs` over the pairs slipping at
    /// the end of the step (trapezoid rule; exact for forces varying linearly over the step, e.g.
    /// proportional loading; a pair that opens or sticks does no friction work).
    pub dissipation: f64,
    /// KKT residuals.
    pub kkt: KktResiduals,
    /// Iterations of the algorithm.
    pub iterations: usize,
    /// Wall time of the algorithm (setup of the shared problem excluded).
    pub time: Duration,
    /// One record per iteration (what changed and the residual), for logs.
    pub trace: Vec<IterationRecord>,
    /// Inequalities of the contact conditions (5.1) that the answer violates, checked by
    /// algorithms that assume a structure (the Boussinesq zones); empty otherwise. The status
    /// is then [`ContactStatus::Inadmissible`].
    pub violations: Vec<Violation>,
}

/// A violated inequality of the contact conditions (5.1), reported by an algorithm that assumes
/// a structure of the zones (the Boussinesq algorithm) instead of solving for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Violation {
    /// The pair.
    pub pair: usize,
    /// Which condition.
    pub condition: &'static str,
}

/// One iteration of an algorithm, as logged by `contact2d run -v`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IterationRecord {
    /// Iteration number (from 1).
    pub iteration: usize,
    /// Pairs whose state the iteration changes (active sets), or whose zone moved (Boussinesq).
    pub changed: usize,
    /// Pairs in contact in the iterate.
    pub in_contact: usize,
    /// Pairs slipping in the iterate.
    pub slipping: usize,
    /// The algorithm's own residual: for the Tresca fixed point the largest change of λ
    /// relative to the largest λ; for the active sets and the Boussinesq iteration 0 (they stop
    /// when the state repeats).
    pub residual: f64,
}

impl IterationRecord {
    /// The record of iteration `iteration` of a state iteration: the pairs in contact and
    /// slipping in `state`, how many pairs `next` changes, and the algorithm's `residual`.
    pub fn of_states(iteration: usize, state: &[PairState], next: &[PairState], residual: f64) -> IterationRecord {
        IterationRecord {
            iteration,
            changed: next.iter().zip(state).filter(|(a, b)| a != b).count(),
            in_contact: state.iter().filter(|s| **s != PairState::Free).count(),
            slipping: state.iter().filter(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative)).count(),
            residual,
        }
    }
}

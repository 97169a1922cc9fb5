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

/// How an algorithm ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactStatus {
    /// Converged to the requested tolerance.
    Converged,
    /// Stopped at the iteration limit; the last iterate is returned.
    MaxIterations,
    /// The problem has no feasible point.
    Infeasible,
    /// A numerical failure (singular interface matrix, solver breakdown).
    Numerical,
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
    /// KKT residuals.
    pub kkt: KktResiduals,
    /// Iterations of the algorithm.
    pub iterations: usize,
    /// Wall time of the algorithm (setup of the shared problem excluded).
    pub time: Duration,
}

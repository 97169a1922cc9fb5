//! Running a scene: build the problem, solve with the chosen algorithm, report the paper's
//! quantities.
//!
//! The no-gap frictionless case is linear in w: it is solved once at w = 1 and scaled (the
//! displacements and forces; the quantities follow), which is exact for that case.

use std::time::Instant;

use serde::Serialize;

use contact2d_contact::{
    ContactError, ContactSolution, ContactStatus, Interface, solve_frictionless_active_set, solve_frictionless_qp,
};

use crate::scene::{ContactAlgorithm, Scene};

/// KKT residuals as reported in JSON.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct KktReport {
    /// max(−gap, 0).
    pub max_penetration: f64,
    /// max |λ gap|.
    pub max_complementarity: f64,
    /// max(|τ| − μλ, 0).
    pub max_cone_violation: f64,
    /// Smallest dissipation τ·Δslip over slipping pairs (0 without friction).
    pub min_dissipation: f64,
}

/// The summary of one run (the `--json` object).
#[allow(non_snake_case)]
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunReport {
    /// Scene name.
    pub scene: String,
    /// Contact end on the hole-edge angle η = 1 − φ/π.
    pub l: Option<f64>,
    /// The mesh bracket of l.
    pub l_bracket: Option<[f64; 2]>,
    /// Contact end on the master's own coordinate.
    pub l_master: Option<f64>,
    /// End of the stick zone (equal to l without friction: no slip).
    pub b: Option<f64>,
    /// Pulling force.
    pub P: f64,
    /// Strain energy of the plate.
    pub Phi_E1: f64,
    /// Strain energy of the insert.
    pub Phi_E2: f64,
    /// Dissipated energy.
    pub Phi_f: f64,
    /// Largest hoop stress on the hole edge.
    pub sigma_star: f64,
    /// K = H σ* / P.
    pub K: f64,
    /// Largest hoop stress of the insert on its edge.
    pub insert_hoop_max: f64,
    /// Load w.
    pub w: f64,
    /// Free DOFs.
    pub dofs: usize,
    /// Contact pairs.
    pub pairs: usize,
    /// Algorithm.
    pub algorithm: ContactAlgorithm,
    /// Outcome.
    pub status: String,
    /// Iterations of the algorithm.
    pub iterations: usize,
    /// KKT residuals.
    pub kkt: KktReport,
    /// Wall time of the whole run (mesh reading to quantities), seconds.
    pub time_s: f64,
    /// Wall time of the contact algorithm alone, seconds.
    pub solve_time_s: f64,
}

/// Runs a scene.
///
/// # Errors
/// Problem set-up failures; an unsupported combination (friction before its algorithm lands)
/// is [`ContactError::InvalidInput`].
pub fn run_scene(scene: &Scene) -> Result<RunReport, ContactError> {
    let start = Instant::now();
    let p = &scene.plate_insert;
    if p.friction != 0.0 {
        return Err(ContactError::InvalidInput(format!(
            "friction = {} requested: frictional contact is not available yet in this version",
            p.friction
        )));
    }
    if !p.load.is_finite() || p.load < 0.0 {
        return Err(ContactError::InvalidInput(format!("load w = {} must be finite and non-negative", p.load)));
    }
    let case = scene.plate_insert().build()?;
    let problem = &case.problem;
    // Linear in w without gap and friction: solve at w = 1 and scale.
    let scaled = problem.is_gapless();
    let w_solve = if scaled { 1.0 } else { p.load };
    let mut solution = match scene.solver.algorithm {
        ContactAlgorithm::ActiveSet => {
            let interface = Interface::new(problem);
            solve_frictionless_active_set(problem, &interface, w_solve, scene.solver.max_iterations)
        }
        ContactAlgorithm::Clarabel => solve_frictionless_qp(problem, w_solve),
    };
    if scaled {
        scale_solution(&mut solution, p.load);
    }
    let q = case.results(&solution)?;
    Ok(RunReport {
        scene: scene.name.clone(),
        l: q.contact_end,
        l_bracket: q.contact_bracket,
        l_master: q.contact_end_master,
        b: q.contact_end,
        P: q.pull,
        Phi_E1: q.energy_plate,
        Phi_E2: q.energy_insert,
        Phi_f: 0.0,
        sigma_star: q.sigma_star,
        K: q.stress_concentration,
        insert_hoop_max: q.insert_hoop_max,
        w: p.load,
        dofs: problem.system.dofs.num_free(),
        pairs: problem.num_pairs(),
        algorithm: scene.solver.algorithm,
        status: status_name(solution.status).into(),
        iterations: solution.iterations,
        kkt: KktReport {
            max_penetration: solution.kkt.max_penetration,
            max_complementarity: solution.kkt.max_complementarity,
            max_cone_violation: solution.kkt.max_cone_violation,
            min_dissipation: solution.kkt.min_dissipation,
        },
        time_s: start.elapsed().as_secs_f64(),
        solve_time_s: solution.time.as_secs_f64(),
    })
}

fn status_name(status: ContactStatus) -> &'static str {
    match status {
        ContactStatus::Converged => "converged",
        ContactStatus::MaxIterations => "max_iterations",
        ContactStatus::Infeasible => "infeasible",
        ContactStatus::Numerical => "numerical",
    }
}

/// Scales a solution of a problem that is linear in the load (no gap, no friction).
fn scale_solution(s: &mut ContactSolution, w: f64) {
    s.load_factor = w;
    for v in s.displacement.iter_mut().chain(&mut s.normal_force).chain(&mut s.tangential_force).chain(&mut s.gap) {
        *v *= w;
    }
    s.kkt.max_penetration *= w;
    s.kkt.max_complementarity *= w * w;
    s.kkt.max_tension *= w;
    s.kkt.max_cone_violation *= w;
}

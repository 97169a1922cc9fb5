//! One cell of the stress grid: the flagship problem with one set of extreme parameters, solved
//! by every algorithm, checked for NaN, KKT residuals, agreement, and its conditioning measured.
//!
//! ```text
//! KKT residuals, relative (u_s = max |u|, f_s = max(|λ|, |τ|) over the pairs, P if no pair carries force):
//!   penetration / u_s,  |λ gap| / (f_s u_s),  cone violation / f_s,  tension / f_s,
//!   max(−dissipation, 0) / (f_s u_s), and two friction residuals the solution's own KKT report
//!   does not carry, over the pairs with a tangential unknown, μ > 0 and λ > 0:
//!   min(|Δs| / u_s, (μλ − |τ|)⁺ / f_s)  (slip only on the cone)  and  (τ Δs)⁺ / (f_s u_s)
//!   (slip against the friction force, τ Δs ≤ 0)
//! agreement (converged algorithms against the first converged one, normally the active set):
//!   |ΔP| / |P|, |ΔΦ_E| / Φ_E, |Δσ*| / |σ*| ≤ 1e-5   and   |Δl|, |Δb| ≤ 1e-3 (η units)
//! conditioning: cond₂(C_NN) = λ_max / λ_min of the condensed normal compliance (symmetric),
//!               max diag K_ff / min diag K_ff
//! ```

use std::path::Path;

use contact2d_contact::{ContactAlgorithm, ContactProblem, ContactSolution, Interface};
use contact2d_element::PlaneCondition;

use crate::run::{RunOutcome, solve_scene};

use crate::plate_insert::PlateInsertScene;

/// Agreement tolerance on P, Φ_E and σ* (relative): Clarabel's interior-point tolerance is
/// 1e-8 on its residuals and the flagship runs agree to 1e-7 (docs/verification.md); 1e-5
/// leaves two decades for ill-conditioning before a difference counts.
pub const AGREE_RELATIVE: f64 = 1e-5;
/// Agreement tolerance on l and b (η units): 1/30 of the pair spacing 1/32 at N = 16, so a
/// different contact or stick set is always caught, round-off in the interpolated end never.
pub const AGREE_ETA: f64 = 1e-3;
/// A converged result whose largest relative KKT residual exceeds this is a failure.
pub const KKT_TOLERANCE: f64 = 1e-6;

/// The parameters of one cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressCell {
    /// E2 / E1.
    pub ratio: f64,
    /// μ.
    pub mu: f64,
    /// ε of the mesh (c = 1 when ε > 0, the paper's gap; neat fit when ε = 0).
    pub eps: f64,
    /// ν of both bodies.
    pub nu: f64,
    /// Plane stress or strain.
    pub plane: PlaneCondition,
    /// Distortion amplitude of the interior nodes (0: the mesh as generated).
    pub distortion: f64,
}

/// What one algorithm gave on a cell.
#[derive(Debug, Clone, PartialEq)]
pub struct AlgorithmResult {
    /// The algorithm.
    pub algorithm: ContactAlgorithm,
    /// "converged", another status, or "error".
    pub status: String,
    /// Iterations summed over the load steps.
    pub iterations: usize,
    /// P, Φ_E, l, b, σ* (NaN where undefined).
    pub values: [f64; 5],
    /// Largest relative KKT residual (see the module documentation).
    pub kkt: f64,
    /// Whether any value or displacement is NaN or infinite.
    pub non_finite: bool,
    /// The error message of a failed run.
    pub error: Option<String>,
    /// Wall time, seconds.
    pub time_s: f64,
}

/// The outcome of a cell.
#[derive(Debug, Clone, PartialEq)]
pub struct CellResult {
    /// The parameters.
    pub cell: StressCell,
    /// Per algorithm.
    pub results: Vec<AlgorithmResult>,
    /// cond₂(C_NN).
    pub cond_cnn: Option<f64>,
    /// max / min diagonal of K_ff.
    pub diag_ratio: Option<f64>,
    /// Mesh quality min det J / max det J of the worst cell (after distortion).
    pub jacobian_quality: Option<f64>,
    /// The largest disagreement: (relative on P, Φ_E, σ*; absolute on l, b).
    pub disagreement: (f64, f64),
    /// "ok", "not converged: …" or "FAIL: …".
    pub verdict: String,
}

impl CellResult {
    /// Whether the cell failed (NaN, disagreement, a converged result with large residuals, or
    /// an invalid mesh).
    pub fn failed(&self) -> bool {
        self.verdict.starts_with("FAIL")
    }
}

/// The `--set` overrides of the base scene for `cell` with `mesh` and `algorithm`.
pub fn overrides(cell: &StressCell, mesh: &str, algorithm: ContactAlgorithm) -> Vec<String> {
    let gap = cell.eps > 0.0;
    vec![
        format!("plate_insert.mesh={mesh:?}"),
        format!("plate_insert.stiffness_ratio={:e}", cell.ratio),
        format!("plate_insert.poissons_ratio={}", cell.nu),
        format!(
            "plate_insert.plane_condition=\"{}\"",
            if cell.plane == PlaneCondition::Strain { "strain" } else { "stress" }
        ),
        format!("plate_insert.eps={:e}", cell.eps),
        format!("plate_insert.clearance={}", if gap { 1.0 } else { 0.0 }),
        "plate_insert.gap=\"paper\"".into(),
        "plate_insert.variant=\"hole_master\"".into(),
        format!("plate_insert.friction={}", cell.mu),
        // Table 2's load in three steps with a gap; without one the problem is linear in w.
        format!("plate_insert.load={}", if gap { 0.3838 } else { 1.0 }),
        format!("plate_insert.steps={}", if gap { 3 } else { 1 }),
        format!("solver.algorithm=\"{}\"", algorithm.key()),
        "solver.max_iterations=200".into(),
        // The algorithms are compared on the same discrete problem: the Boussinesq algorithm on
        // the generated mesh (its zone ends at the nodes), not on a mesh adjusted to l* and b*.
        "solver.place_zone_ends=false".into(),
    ]
}

/// Runs `cell` on `mesh` (a path relative to the base scene's directory, or absolute) with each
/// algorithm, and measures the conditioning once.
pub fn run_cell(
    base_scene: &Path,
    mesh: &str,
    cell: StressCell,
    algorithms: &[ContactAlgorithm],
    jacobian_quality: Option<f64>,
) -> CellResult {
    let mut results = Vec::new();
    let mut conditioning = None;
    for &algorithm in algorithms {
        let outcome = PlateInsertScene::load(base_scene, &overrides(&cell, mesh, algorithm))
            .map_err(|e| e.to_string())
            .and_then(|scene| solve_scene(&scene).map_err(|e| e.to_string()));
        let result = match outcome {
            Ok(o) => {
                if conditioning.is_none() {
                    conditioning = Some(measure_conditioning(&o));
                }
                summarise(algorithm, &o)
            }
            Err(e) => AlgorithmResult {
                algorithm,
                status: "error".into(),
                iterations: 0,
                values: [f64::NAN; 5],
                kkt: f64::NAN,
                non_finite: false,
                error: Some(e),
                time_s: 0.0,
            },
        };
        results.push(result);
    }
    let (cond_cnn, diag_ratio) = conditioning.unwrap_or((None, None));
    let disagreement = disagreement(&results);
    let verdict = verdict(&results, disagreement, jacobian_quality);
    CellResult { cell, results, cond_cnn, diag_ratio, jacobian_quality, disagreement, verdict }
}

fn summarise(algorithm: ContactAlgorithm, o: &RunOutcome) -> AlgorithmResult {
    let (r, status) = (&o.paper, o.report.status);
    let values = [r.P, r.Phi_E1 + r.Phi_E2, r.l.unwrap_or(f64::NAN), r.b.unwrap_or(f64::NAN), r.sigma_star];
    let non_finite = [r.P, r.Phi_E1, r.Phi_E2, r.sigma_star, r.Phi_f, r.W].iter().any(|v| !v.is_finite())
        || r.l.is_some_and(|v| !v.is_finite())
        || r.b.is_some_and(|v| !v.is_finite())
        || o.steps.iter().any(|s| s.solution.displacement.iter().any(|v| !v.is_finite()));
    let kkt = o
        .steps
        .iter()
        .map(|s| relative_kkt(&s.solution, r.P).max(friction_residual(&s.case.problem, &s.solution, r.P)))
        .fold(0.0, f64::max);
    AlgorithmResult {
        algorithm,
        status: status.into(),
        iterations: o.report.iterations,
        values,
        kkt,
        non_finite,
        error: None,
        time_s: o.report.time_s.total,
    }
}

/// The largest relative KKT residual of a step (see the module documentation).
pub fn relative_kkt(s: &ContactSolution, pull: f64) -> f64 {
    let (u_s, f_s) = scales(s, pull);
    if u_s == 0.0 || f_s == 0.0 {
        return 0.0;
    }
    let k = &s.kkt;
    [
        k.max_penetration / u_s,
        k.max_complementarity / (f_s * u_s),
        k.max_cone_violation / f_s,
        k.max_tension / f_s,
        (-k.min_dissipation).max(0.0) / (f_s * u_s),
    ]
    .into_iter()
    .fold(0.0, |m, v| if v.is_nan() { f64::NAN } else { m.max(v) })
}

/// The relative friction residuals of a step (see the module documentation).
pub fn friction_residual(problem: &ContactProblem, s: &ContactSolution, pull: f64) -> f64 {
    let (u_s, f_s) = scales(s, pull);
    if u_s == 0.0 || f_s == 0.0 {
        return 0.0;
    }
    let mut worst = 0.0f64;
    for k in 0..s.normal_force.len() {
        let (mu, lambda, tau, ds) =
            (problem.friction[k], s.normal_force[k], s.tangential_force[k], s.slip_increment[k]);
        if !(problem.tangential[k] && mu > 0.0 && lambda > 0.0) {
            continue;
        }
        let inside = (ds.abs() / u_s).min((mu * lambda - tau.abs()).max(0.0) / f_s);
        let against = (tau * ds).max(0.0) / (f_s * u_s);
        worst = worst.max(inside).max(against);
        if inside.is_nan() || against.is_nan() {
            return f64::NAN;
        }
    }
    worst
}

/// The displacement and force scales u_s, f_s of a step.
fn scales(s: &ContactSolution, pull: f64) -> (f64, f64) {
    let u_s = s.displacement.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let f_s = s.normal_force.iter().chain(&s.tangential_force).fold(0.0f64, |m, v| m.max(v.abs()));
    (u_s, if f_s > 0.0 { f_s } else { pull.abs() })
}

fn measure_conditioning(o: &RunOutcome) -> (Option<f64>, Option<f64>) {
    let Some(step) = o.steps.first() else { return (None, None) };
    let problem = &step.case.problem;
    let k = &problem.system.stiffness;
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for j in 0..k.ncols() {
        let d = k.row_idx_of_col(j).zip(k.val_of_col(j)).find(|(r, _)| *r == j).map_or(0.0, |(_, v)| *v);
        lo = lo.min(d);
        hi = hi.max(d);
    }
    let diag = (lo > 0.0).then_some(hi / lo);
    let c = Interface::new(problem).c_nn;
    let cond = if c.nrows() == 0 {
        None
    } else {
        let eig = nalgebra::SymmetricEigen::new(c).eigenvalues;
        let (min, max) = eig.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(*v), b.max(*v)));
        // A non-positive smallest eigenvalue is reported as an infinite condition number.
        Some(if min > 0.0 { max / min } else { f64::INFINITY })
    };
    (cond, diag)
}

/// The difference of two results: (largest relative difference of P, Φ_E, σ*; largest absolute
/// difference of l, b, infinite when only one of them defines it).
pub fn difference(first: &AlgorithmResult, other: &AlgorithmResult) -> (f64, f64) {
    let (mut rel, mut eta) = (0.0f64, 0.0f64);
    for i in [0, 1, 4] {
        let (a, b) = (first.values[i], other.values[i]);
        rel = rel.max(if a == b { 0.0 } else { (a - b).abs() / a.abs().max(b.abs()) });
    }
    for i in [2, 3] {
        let (a, b) = (first.values[i], other.values[i]);
        if a.is_nan() != b.is_nan() {
            eta = f64::INFINITY;
        } else if !a.is_nan() {
            eta = eta.max((a - b).abs());
        }
    }
    (rel, eta)
}

/// Whether a difference exceeds the agreement tolerances.
pub fn disagrees((rel, eta): (f64, f64)) -> bool {
    rel > AGREE_RELATIVE || eta > AGREE_ETA
}

/// The largest difference of the converged results from the first converged one.
fn disagreement(results: &[AlgorithmResult]) -> (f64, f64) {
    let converged: Vec<&AlgorithmResult> = results.iter().filter(|r| r.status == "converged").collect();
    let Some(first) = converged.first() else { return (0.0, 0.0) };
    converged[1..].iter().map(|o| difference(first, o)).fold((0.0, 0.0), |(a, b), (c, d)| (a.max(c), b.max(d)))
}

fn verdict(results: &[AlgorithmResult], (rel, eta): (f64, f64), quality: Option<f64>) -> String {
    let mut fails = Vec::new();
    if quality.is_some_and(|q| q <= 0.0) {
        fails.push("inverted cell in the distorted mesh".to_string());
    }
    for r in results {
        let name = r.algorithm.key();
        if r.non_finite {
            fails.push(format!("{name}: NaN or infinite value"));
        }
        // NaN residuals count as large.
        if r.status == "converged" && (r.kkt.is_nan() || r.kkt > KKT_TOLERANCE) {
            fails.push(format!("{name}: converged with relative KKT residual {:.1e}", r.kkt));
        }
    }
    if disagrees((rel, eta)) {
        fails.push(format!("algorithms disagree (P/Φ_E/σ* {rel:.1e} relative, l/b {eta:.1e})"));
    }
    if !fails.is_empty() {
        return format!("FAIL: {}", fails.join("; "));
    }
    let other: Vec<String> = results
        .iter()
        .filter(|r| r.status != "converged")
        .map(|r| match &r.error {
            Some(e) => format!("{}: error: {e}", r.algorithm.key()),
            None => format!("{}: {}", r.algorithm.key(), r.status),
        })
        .collect();
    if other.is_empty() { "ok".into() } else { format!("not converged: {}", other.join("; ")) }
}

//! The contact end resolved finer than the mesh by placing a node at l* (the paper's way,
//! spec §6: "the contour nodes at η = l* ... are placed there (the mesh is adjusted)").
//!
//! ```text
//! r(l*) = p at the master node placed at η = l*, from problem A with the contact zone ending
//!         there and the load w given (BoussinesqLoading::Fixed)
//! l*:     the root of r by bisection in a bracket where r changes sign; each evaluation moves the
//!         master corner node nearest to l* onto the master circle at l* (mid nodes re-centred,
//!         interior relaxed), pairs node-to-node again, and solves.
//! ```
//!
//! One load step from the virgin state (proportional loading without gap, or the first step
//! with one). Each evaluation re-assembles and re-factors the bodies.

use contact2d_contact::{
    BoussinesqLoading, ContactError, ContactSolution, Interface, StepStart, solve_boussinesq_step,
};

use super::{PlateInsert, PlateInsertProblem};

/// A contact end found by node placement.
#[derive(Debug, Clone)]
pub struct PlacedContactEnd {
    /// l* on the master's own coordinate.
    pub contact_end: f64,
    /// The pressure left at l* (→ 0).
    pub residual_pressure: f64,
    /// Evaluations (meshes solved).
    pub evaluations: usize,
    /// The problem on the adjusted mesh.
    pub case: PlateInsertProblem,
    /// Its solution.
    pub solution: ContactSolution,
}

/// Finds l* in `bracket` (η on the master's own coordinate) for load `w`, to `tolerance` in η.
///
/// # Errors
/// Set-up failures, a bracket in which the pressure at the placed node does not change sign, or a
/// step that does not solve.
pub fn contact_end_by_placement(
    template: &PlateInsert,
    w: f64,
    bracket: [f64; 2],
    tolerance: f64,
) -> Result<PlacedContactEnd, ContactError> {
    let evaluate = |l: f64| -> Result<(f64, PlateInsertProblem, ContactSolution), ContactError> {
        let case = PlateInsert { placed_nodes: vec![l], ..template.clone() }.build()?;
        let interface = Interface::new(&case.problem);
        let eta = case.eta_master();
        let mut order: Vec<usize> = (0..eta.len()).collect();
        order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
        let position = order
            .iter()
            .position(|&k| (eta[k] - l).abs() < 1e-9)
            .ok_or_else(|| ContactError::InvalidInput(format!("no node was placed at η = {l}")))?;
        let start = StepStart::initial(case.problem.num_pairs());
        let loading = BoussinesqLoading::Fixed { contact_end: position, load: w };
        let step = solve_boussinesq_step(&case.problem, &interface, &order, loading, &start, 4 * order.len());
        let k = order[position];
        let pressure = -step.solution.normal_force[k] / case.problem.pairs[k].weight;
        Ok((pressure, case, step.solution))
    };
    let (mut a, mut b) = (bracket[0], bracket[1]);
    let (mut pa, _, _) = evaluate(a)?;
    let (pb, _, _) = evaluate(b)?;
    if pa.signum() == pb.signum() {
        return Err(ContactError::InvalidInput(format!(
            "p(l*) does not change sign in [{a}, {b}] ({pa:.3e}, {pb:.3e})"
        )));
    }
    let mut evaluations = 2;
    loop {
        let m = 0.5 * (a + b);
        let (pm, case, solution) = evaluate(m)?;
        evaluations += 1;
        if b - a <= 2.0 * tolerance {
            return Ok(PlacedContactEnd { contact_end: m, residual_pressure: pm, evaluations, case, solution });
        }
        if pm.signum() == pa.signum() {
            (a, pa) = (m, pm);
        } else {
            b = m;
        }
    }
}

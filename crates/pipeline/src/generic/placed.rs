//! The Boussinesq algorithm with zone ends placed on the mesh (`solver.place_zone_ends = true`)
//! on a generic scene: its one contact's master curve, straight or circular, is a
//! [`PlaceableContact`] whose corners the zone-end search (`contact2d_contact::placement`) moves.
//!
//! ```text
//! refuse    before solving, with ContactError::NotApplicable: a pairing without node pairs
//!           (segment_to_segment), a linear master contour (no mid nodes to re-centre), a master
//!           curve neither straight nor circular (placement::curve::TOLERANCE), and what the
//!           Boussinesq algorithm refuses anyway (solve::boussinesq_zone_order)
//! orient    c = 0 at the end where the zone starts (the algorithm's order along the curve)
//! load      the schedule's proportional direction d (t = 1 at the last step) is the unit load;
//!           step i is PlacedLoading::Load(t_i), the slips carried on the curve between steps
//! report    the generic summary of the steps, each on its own adjusted mesh; the contact and
//!           stick zones end at the placed nodes: s = the placed pair's arc length
//! ```

use web_time::Instant;

use contact2d_contact::builder::{Pairing, ProblemDescription};
use contact2d_contact::solve::boussinesq_zone_order;
use contact2d_contact::{BuiltProblem, ContactAlgorithm, ContactError, Interface, SolvedStep};
use contact2d_mesh::morph::move_nodes;
use contact2d_mesh::{Mesh, NodeId};

use super::{GenericReport, GenericScene, SummaryInput, SummaryRows, Times, summarise};
use contact2d_contact::placement::curve::MasterCurve;
use contact2d_contact::placement::{
    NodePlacement, PlaceableContact, PlacedLoading, PlacedStep, ZoneEndSearch, pair_coordinates, solve_placed_history,
};

pub use super::placed_ends::GenericCase;

/// The meshes of a generic scene's generated mesh with master corners moved along its one
/// contact's straight or circular master curve.
#[derive(Debug, Clone)]
pub struct GenericFamily {
    description: ProblemDescription,
    curve: MasterCurve,
    direction: Vec<f64>,
}

/// The refusal of placed zone ends (the Boussinesq algorithm's) for `reason`.
fn not_applicable(reason: String) -> ContactError {
    ContactError::NotApplicable { algorithm: ContactAlgorithm::Boussinesq.key(), reason }
}

impl GenericFamily {
    /// The family of `description` loaded along `direction` (one factor per pattern): the
    /// master curve detected and oriented (see the module docs).
    ///
    /// # Errors
    /// [`ContactError::NotApplicable`] for the cases the module docs refuse; build errors.
    pub fn new(description: ProblemDescription, direction: Vec<f64>) -> Result<GenericFamily, ContactError> {
        let mut built = description.build()?;
        let [interface] = built.interfaces.as_slice() else {
            return Err(not_applicable("placed zone ends need exactly one contact".into()));
        };
        if interface.pairing == Pairing::SegmentToSegment {
            return Err(not_applicable(format!(
                "placed zone ends move the master nodes of node pairs; contact \"{}\" is paired segment to segment \
                 (set pairing = \"node_to_node\" or \"node_to_segment\")",
                interface.name
            )));
        }
        let contour = &interface.master_contour;
        if contour.nodes.len() < 5 || !contour.edges.iter().all(|e| e.quadratic) {
            return Err(not_applicable(format!(
                "placed zone ends need a quadratic master curve of at least two edges (\"{}\" has linear edges or \
                 one edge)",
                interface.master
            )));
        }
        let points: Vec<[f64; 2]> = contour.nodes.iter().map(|v| built.problem.model.mesh.points[v.0]).collect();
        let curve = MasterCurve::detect(&points)
            .map_err(|why| not_applicable(format!("placed zone ends on \"{}\": {why}", interface.master)))?;
        built.problem.apply_load(&direction, None)?;
        let order = boussinesq_zone_order(&built.problem, &Interface::new(&built.problem))?;
        let case = GenericCase { built, curve };
        let c = pair_coordinates(&case);
        let curve = match (order.first(), order.last()) {
            (Some(&first), Some(&last)) if c[first] > c[last] => curve.reversed(),
            _ => curve,
        };
        Ok(GenericFamily { description, curve, direction })
    }

    /// The new positions of the placed corners on the curve and of their edges' mid nodes,
    /// re-centred in c between the corners once every corner is placed.
    fn placement_targets(&self, mesh: &Mesh, nodes: &[NodeId], placed: &[NodePlacement]) -> PlacementTargets {
        let n = nodes.len();
        let generated: Vec<f64> = nodes.iter().map(|v| self.curve.coordinate(mesh.points[v.0])).collect();
        let mut c = generated.clone();
        let mut corners: Vec<usize> = vec![];
        for &NodePlacement { eta, corner } in placed {
            if corner % 2 != 0 || corner < 2 || corner + 2 >= n || corners.contains(&corner) {
                return Err(ContactError::InvalidInput(format!(
                    "placed node: {corner} is not an interior corner of the {n}-node master contour, or is placed twice"
                )));
            }
            let (a, b) = (generated[corner - 2], generated[corner + 2]);
            let (lo, hi) = (a.min(b), a.max(b));
            if !(eta > lo && eta < hi) {
                return Err(ContactError::InvalidInput(format!(
                    "placed node at c = {eta} is outside the range of corner {corner} (c {lo:.5} to {hi:.5})"
                )));
            }
            c[corner] = eta;
            corners.push(corner);
        }
        // The contour may run against c; either way its corners keep their order.
        let ascending = generated[n - 1] > generated[0];
        if !(0..n / 2).all(|i| (c[2 * i + 2] > c[2 * i]) == ascending) {
            return Err(ContactError::InvalidInput(format!(
                "placed nodes would reorder the master contour's corners ({placed:?})"
            )));
        }
        let mut moved: Vec<usize> = corners.iter().flat_map(|&k| [k - 1, k, k + 1]).collect();
        moved.sort_unstable();
        moved.dedup();
        for &i in &moved {
            if i % 2 == 1 {
                c[i] = 0.5 * (c[i - 1] + c[i + 1]);
            }
        }
        Ok(moved.into_iter().map(|i| (nodes[i], self.curve.point(c[i]))).collect())
    }

    /// The master curve's group.
    fn master_group(&self) -> String {
        self.description.contacts.first().map(|c| c.master.clone()).unwrap_or_default()
    }

    /// The built problem on `description`'s mesh (moved), loaded along the direction.
    fn build_with(
        &self,
        description: &ProblemDescription,
        base: Option<&contact2d_contact::ContactProblem>,
    ) -> Result<GenericCase, ContactError> {
        let mut built = description.build_reusing(base)?;
        built.problem.apply_load(&self.direction, None)?;
        Ok(GenericCase { built, curve: self.curve })
    }
}

/// Node moves, or why not.
type PlacementTargets = Result<Vec<(NodeId, [f64; 2])>, ContactError>;

impl PlaceableContact for GenericFamily {
    type Case = GenericCase;

    fn build_generated(&self) -> Result<GenericCase, ContactError> {
        self.build_with(&self.description, None)
    }

    fn build_placed(
        &self,
        placed: &[NodePlacement],
        base: &contact2d_contact::ContactProblem,
    ) -> Result<GenericCase, ContactError> {
        let mut mesh = self.description.mesh.clone();
        let master = contact2d_mesh::Contour::from_group(&mesh, &self.master_group())?;
        let targets = self.placement_targets(&mesh, &master.nodes, placed)?;
        move_nodes(&mut mesh, &targets, 2)?;
        let description = ProblemDescription { mesh, ..self.description.clone() };
        self.build_with(&description, Some(base))
    }
}

/// The generic scene `scene` on `mesh` by the Boussinesq algorithm with placed zone ends (see
/// the module docs): its summary, and each step's problem and solution.
///
/// # Errors
/// [`ContactError::NotApplicable`] as the module docs say; a schedule that is not proportional;
/// set-up failures.
pub(super) fn solve_placed(
    scene: &GenericScene,
    mesh: Mesh,
    clock: Instant,
    on_step: &mut dyn FnMut(usize, usize),
) -> Result<(GenericReport, Vec<(BuiltProblem, SolvedStep)>), ContactError> {
    let read = clock.elapsed().as_secs_f64();
    let groups = super::group_reports(scene, &mesh)?;
    let schedule = scene.schedule().map_err(|e| ContactError::InvalidInput(e.to_string()))?;
    let description = scene.description(mesh).map_err(|e| ContactError::InvalidInput(e.to_string()))?;
    let names = scene.pattern_names();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let factors: Vec<Vec<f64>> =
        (0..schedule.steps().len()).map(|i| schedule.factors_for(i, &names)).collect::<Result<_, _>>()?;
    let steady = contact2d_contact::LoadSchedule::new(names.iter().map(|n| n.to_string()).collect(), factors)?;
    let Some((direction, multipliers)) = steady.proportional() else {
        return Err(not_applicable(
            "it needs proportional loads that only grow (its contact zone grows from one point); use the active set \
             or Clarabel for other schedules"
                .into(),
        ));
    };
    let family = GenericFamily::new(description, direction.clone())?;
    let loadings: Vec<PlacedLoading> = multipliers.iter().map(|t| PlacedLoading::Load(*t)).collect();
    let total = loadings.len();
    let mut done = 0;
    let steps = solve_placed_history(&family, &loadings, ZoneEndSearch::default(), &mut |_| {
        done += 1;
        on_step(done, total);
    })?;
    summary_of_steps(scene, &steps, &direction, groups, clock, read)
}

/// The generic summary of the placed steps, each on its own adjusted mesh, the zone ends at the
/// placed nodes.
fn summary_of_steps(
    scene: &GenericScene,
    steps: &[(PlacedStep<GenericCase>, f64)],
    direction: &[f64],
    groups: std::collections::BTreeMap<String, super::GroupReport>,
    clock: Instant,
    read: f64,
) -> Result<(GenericReport, Vec<(BuiltProblem, SolvedStep)>), ContactError> {
    let solved: Vec<SolvedStep> = steps
        .iter()
        .map(|(s, dissipated)| {
            let mut solution = s.step.solution.clone();
            // The factors carry the load, as in every generic step.
            solution.load_factor = 1.0;
            SolvedStep {
                factors: direction.iter().map(|d| d * s.load).collect(),
                solution,
                dissipated: *dissipated,
                floating_iterations: 0,
                floating_residual: 0.0,
                repairings: 0,
                unstable_pairing: None,
                not_held: None,
            }
        })
        .collect();
    let (Some((first, _)), Some((last, _)), Some(last_step)) = (steps.first(), steps.last(), solved.last()) else {
        return Err(ContactError::InvalidInput("no load step".into()));
    };
    let fixed = super::fixed_groups(scene);
    let mut rows = SummaryRows::new(&first.case.built, &fixed, scene.every_profile)
        .without_sliding_check()
        .about(scene.moment_centre);
    for ((step, _), solved) in steps.iter().zip(&solved) {
        rows.push(&step.case.built, solved)?;
    }
    let built = &last.case.built;
    let times = Times {
        read,
        assemble: built.problem.build_times.assemble.as_secs_f64(),
        factor: built.problem.build_times.factor.as_secs_f64(),
        solve: steps.iter().map(|(s, _)| s.step.solution.time.as_secs_f64()).sum(),
        ..Times::default()
    };
    let input = SummaryInput {
        scene,
        built,
        initial: built,
        last: last_step,
        groups,
        scaled: false,
        total_steps: steps.len(),
        times,
        clock,
    };
    let mut report = summarise(input, rows)?;
    for (i, (step, _)) in steps.iter().enumerate() {
        super::placed_ends::set_placed_ends(&mut report, i, step);
    }
    let solved = steps.iter().map(|(s, _)| s.case.built.clone()).zip(solved.iter().cloned()).collect();
    Ok((report, solved))
}

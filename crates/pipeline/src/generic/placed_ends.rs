//! The zone ends of a step with placed nodes, written into the generic summary: the contact
//! zone ends exactly at the node placed at l*, the stick zone at the node placed at b* (or at b*
//! interpolated between pairs when no node could be placed there), instead of the 3/2-power
//! interpolation between pairs that `zones.rs` applies to a mesh whose nodes were not placed.
//!
//! ```text
//! s(c)   the arc length of the pair whose master node is at c (a placed node), else linear in c
//!        between the pairs around c
//! zone   [s(c_start), s(l*)] sorted, c_start the coordinate of the pair where the zone starts
//! ```

use contact2d_contact::BuiltProblem;
use contact2d_mesh::NodeId;

use super::GenericReport;
use super::zones::ZoneEnds;
use contact2d_contact::placement::curve::MasterCurve;
use contact2d_contact::placement::{PlacedCase, PlacedStep, pair_coordinates};

/// A generic scene's built problem with its master curve.
#[derive(Debug, Clone)]
pub struct GenericCase {
    /// The problem, its load the schedule's direction.
    pub built: BuiltProblem,
    /// The master curve, oriented from the end where the zone starts.
    pub curve: MasterCurve,
}

impl PlacedCase for GenericCase {
    fn problem(&self) -> &contact2d_contact::ContactProblem {
        &self.built.problem
    }

    fn master_nodes(&self) -> &[NodeId] {
        self.built.interfaces.first().map_or(&[], |i| &i.master_contour.nodes)
    }

    fn coordinate_of(&self, x: [f64; 2]) -> f64 {
        self.curve.coordinate(x)
    }
}

/// Writes step `i`'s placed zone ends into its row of `report` (and into the last step's
/// `contacts` when `i` is the last), and a note when the step's search failed.
pub(super) fn set_placed_ends(report: &mut GenericReport, i: usize, step: &PlacedStep<GenericCase>) {
    let case = &step.case;
    let Some(name) = case.built.interfaces.first().map(|f| f.name.clone()) else { return };
    if !step.contact_end_placed {
        let why = step.placement_failure.clone().unwrap_or_default();
        report.notes.push(format!(
            "step {}: zone ends not placed ({why}); solved on the generated mesh, the zone ends interpolated",
            i + 1
        ));
        return;
    }
    let c = pair_coordinates(case);
    let arc: Vec<f64> = case.problem().pairs.iter().map(|p| p.master_arc_length).collect();
    let Some(start) = (0..c.len()).min_by(|a, b| c[*a].total_cmp(&c[*b])) else { return };
    let zone = |end: f64| zone_ends(case, &c, &arc, c[start], end);
    let contact = zone(step.contact_end);
    let stick = zone(step.stick_end);
    let frictional = case.problem().friction.iter().any(|mu| *mu > 0.0);
    let thickness = case
        .built
        .interfaces
        .first()
        .and_then(|f| case.problem().model.body(&f.master_region).map(|(_, b)| b.kinematics.pair_area_factor()))
        .unwrap_or(1.0);
    let last = i + 1 == report.steps.len();
    let place = |result: &mut super::results::ContactResult| {
        result.contact_length = (contact.s[1] - contact.s[0]).abs();
        result.mean_pressure = super::results::mean_pressure(result.normal_force, result.contact_length, thickness);
        result.zones = contact.clone();
        if frictional {
            result.stick_length = (stick.s[1] - stick.s[0]).abs();
            result.stick_zones = stick.clone();
        }
    };
    report.steps.modify(i, |row| row.contacts.get_mut(&name).into_iter().for_each(&place));
    if last && let Some(result) = report.contacts.get_mut(&name) {
        place(result);
    }
}

/// The zone from coordinate `from` to `to`: its two ends' arc lengths (ascending), points and,
/// on an arc, angles.
fn zone_ends(case: &GenericCase, c: &[f64], arc: &[f64], from: f64, to: f64) -> ZoneEnds {
    let mut ends = [(arc_length_at(c, arc, from), from), (arc_length_at(c, arc, to), to)];
    ends.sort_by(|a, b| a.0.total_cmp(&b.0));
    let points: Vec<[f64; 2]> = ends.iter().map(|e| case.curve.point(e.1)).collect();
    let angles_deg =
        case.curve.centre().map(|[cx, cy]| points.iter().map(|p| (p[1] - cy).atan2(p[0] - cx).to_degrees()).collect());
    ZoneEnds { s: ends.iter().map(|e| e.0).collect(), points, angles_deg, all_round: false }
}

/// s(at): the arc length of the pair at coordinate `at`, else linear between the pairs around it
/// (constant beyond the ends).
fn arc_length_at(c: &[f64], arc: &[f64], at: f64) -> f64 {
    if let Some(k) = c.iter().position(|x| *x == at) {
        return arc[k];
    }
    let mut order: Vec<usize> = (0..c.len()).collect();
    order.sort_by(|a, b| c[*a].total_cmp(&c[*b]));
    let i = order.partition_point(|&k| c[k] < at);
    match i {
        0 => order.first().map_or(0.0, |&k| arc[k]),
        i if i >= order.len() => order.last().map_or(0.0, |&k| arc[k]),
        i => {
            let (k0, k1) = (order[i - 1], order[i]);
            let t = (at - c[k0]) / (c[k1] - c[k0]);
            arc[k0] + t * (arc[k1] - arc[k0])
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_length_is_exact_at_a_pair_and_linear_between() {
        let (c, arc) = ([0.5, 0.0, 1.0], [1.0, 0.0, 4.0]);
        assert_eq!(arc_length_at(&c, &arc, 0.5), 1.0);
        assert_eq!(arc_length_at(&c, &arc, 0.75), 2.5);
        assert_eq!(arc_length_at(&c, &arc, 2.0), 4.0);
    }
}

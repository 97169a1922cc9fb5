//! One interface's results at a step: its forces, zones, moments, largest and mean pressure and,
//! if asked, its profile (the formulas in [`super`]'s docs).

use contact2d_contact::{BuiltProblem, ContactSolution, InterfaceInfo, PairState};

use super::super::zones::{PairCurve, ZoneEnds, ZoneMarks, zone_ends, zones_length, zones_span};
use super::{ContactResult, Profile};
use crate::output::step_view::state_label;

/// The interface's pairs sorted by arc length along the master.
fn sorted_pairs(built: &BuiltProblem, iface: &InterfaceInfo) -> Vec<usize> {
    let pairs = &built.problem.pairs;
    let mut order: Vec<usize> = iface.pairs.clone().collect();
    order.sort_by(|a, b| pairs[*a].master_arc_length.total_cmp(&pairs[*b].master_arc_length).then(a.cmp(b)));
    order
}

/// One interface's results for the solution `s` of a step: forces, zone lengths, the largest
/// pressure, the given accumulated dissipation, moments about the given centre and, if asked,
/// the profile
/// (`p_k = λ_k / (w_k t_h)`, `q_k = τ_k / (w_k t_h)` with `w_k` the master node's tributary
/// length and `t_h` the thickness).
pub fn contact_result(
    built: &BuiltProblem,
    iface: &InterfaceInfo,
    s: &ContactSolution,
    dissipation: f64,
    with_profile: bool,
) -> ContactResult {
    contact_result_about(built, iface, s, (dissipation, [0.0; 2]), with_profile)
}

/// [`contact_result`] with the moments about `centre`.
pub fn contact_result_about(
    built: &BuiltProblem,
    iface: &InterfaceInfo,
    s: &ContactSolution,
    (dissipation, centre): (f64, [f64; 2]),
    with_profile: bool,
) -> ContactResult {
    let problem = &built.problem;
    let order = sorted_pairs(built, iface);
    let kinematics = problem.model.body(&iface.master_region).map(|(_, b)| b.kinematics);
    let thickness = kinematics.map_or(1.0, |k| k.pair_area_factor());
    let area = |k: usize| problem.pairs[k].weight * thickness;
    let arc: Vec<f64> = order.iter().map(|&k| problem.pairs[k].master_arc_length).collect();
    let in_contact: Vec<bool> = order.iter().map(|&k| s.state[k] != PairState::Free).collect();
    let sticks: Vec<bool> = order.iter().map(|&k| s.state[k] == PairState::Stick).collect();
    let gap: Vec<f64> = order.iter().map(|&k| s.gap[k].max(0.0)).collect();
    let slip: Vec<f64> = order.iter().map(|&k| s.slip_increment[k].abs()).collect();
    let points: Vec<[f64; 2]> = order.iter().map(|&k| problem.model.mesh.points[problem.pairs[k].master.0]).collect();
    let master = &iface.master_contour;
    let curve = PairCurve { arc: &arc, points: &points, period: master.closed.then(|| master.length()) };
    let contact = ZoneMarks { inside: &in_contact, opening: &gap, in_contact: &in_contact };
    let stick = ZoneMarks { inside: &sticks, opening: &slip, in_contact: &in_contact };
    let contact_length = zones_span(&curve, &contact);
    // The stick zones lie inside the contact zones; their ends are interpolated from different
    // profiles (slip against gap), which must not make the part longer than the whole.
    let stick_length = if iface.friction > 0.0 { zones_length(&curve, &stick).min(contact_length) } else { 0.0 };
    let zones = zone_ends(&curve, &contact);
    let stick_zones = if iface.friction > 0.0 { zone_ends(&curve, &stick) } else { ZoneEnds::default() };
    let normal_force = order.iter().map(|&k| s.normal_force[k]).sum();
    let rigid_moment = iface.rigid_slave.then(|| interface_moment(built, iface, s, centre, |_| true));
    let profile = with_profile.then(|| {
        Box::new(Profile {
            s: arc.clone(),
            x: order.iter().map(|&k| problem.model.mesh.points[problem.pairs[k].master.0][0]).collect(),
            y: order.iter().map(|&k| problem.model.mesh.points[problem.pairs[k].master.0][1]).collect(),
            pressure: order.iter().map(|&k| s.normal_force[k] / area(k)).collect(),
            shear: order.iter().map(|&k| s.tangential_force[k] / area(k)).collect(),
            gap: order.iter().map(|&k| s.gap[k]).collect(),
            slip: order.iter().map(|&k| s.slip[k]).collect(),
            state: order.iter().map(|&k| state_label(s.state[k], problem.friction[k])).collect(),
        })
    });
    ContactResult {
        normal_force,
        tangential_force: order.iter().map(|&k| s.tangential_force[k]).sum(),
        contact_length,
        stick_length,
        mean_pressure: mean_pressure(normal_force, contact_length, zone_width(problem, iface, &order, s, kinematics)),
        max_pressure: order.iter().map(|&k| s.normal_force[k] / area(k)).fold(0.0, f64::max),
        dissipation,
        resultant: slave_resultant(built, iface, s),
        rigid_resultant: iface.rigid_slave.then(|| rigid_resultant(built, iface, s)),
        moment: rigid_moment.map_or_else(|| slave_moment(built, iface, s, centre), |m| -m),
        rigid_moment,
        couple: (!iface.rigid_slave).then(|| interface_moment(built, iface, s, centre, |_| true)),
        closed: master.closed,
        zones,
        stick_zones,
        profile,
        fretting: None,
    }
}

/// What turns the contact length into the contact area: the thickness `t` in the plane; for a
/// body of revolution the circumference `2π r̄` at the arc-length centroid of the master nodes in
/// contact, `r̄ = Σ ds_a r_a / Σ ds_a` (`ds_a` their tributary lengths on the master curve), so
/// that `2π r̄ L` is Pappus' area of the zone: `π a²` for a disc 0 ≤ r ≤ a, `2π b L` on a bore
/// of radius b. (Weighing by the ring areas, `ds_a 2π r_a`, would give the area centroid, 2a/3
/// on a disc, and a mean pressure 3/4 of the force over the disc's area.)
fn zone_width(
    problem: &contact2d_contact::ContactProblem,
    iface: &InterfaceInfo,
    order: &[usize],
    s: &ContactSolution,
    kinematics: Option<contact2d_element::Kinematics>,
) -> f64 {
    let Some(kinematics) = kinematics.filter(|k| k.thickness().is_none()) else {
        return kinematics.map_or(1.0, |k| k.pair_area_factor());
    };
    let points = &problem.model.mesh.points;
    let mut touching = vec![false; points.len()];
    for &k in order.iter().filter(|&&k| s.state[k] != PairState::Free) {
        touching[problem.pairs[k].master.0] = true;
    }
    let master = &iface.master_contour;
    let lengths = contact2d_contact::tributary_weights(master);
    let (sum_ds, sum_ds_r) = master
        .nodes
        .iter()
        .zip(&lengths)
        .filter(|(n, _)| touching[n.0])
        .fold((0.0, 0.0), |(l, lr), (n, ds)| (l + ds, lr + ds * points[n.0][0]));
    if sum_ds > 0.0 { kinematics.pairing_measure([sum_ds_r / sum_ds, 0.0]) } else { 1.0 }
}

/// `normal_force / (contact_length t)`, the mean pressure over the contact length (`None` where
/// the length is 0: no length to spread the force over).
pub(crate) fn mean_pressure(normal_force: f64, contact_length: f64, thickness: f64) -> Option<f64> {
    (contact_length > 0.0).then(|| normal_force / (contact_length * thickness))
}

/// The moment about `centre` of the interface's pair forces on the nodes `on` selects
/// ([`contact2d_contact::ContactProblem::pair_moment_on`]; NaN, caught as a non-finite summary,
/// if a pair were out of range).
fn interface_moment(
    built: &BuiltProblem,
    iface: &InterfaceInfo,
    s: &ContactSolution,
    centre: [f64; 2],
    on: impl Fn(usize) -> bool + Copy,
) -> f64 {
    iface
        .pairs
        .clone()
        .map(|k| {
            let forces = (s.normal_force[k], s.tangential_force[k]);
            built.problem.pair_moment_on(k, forces, centre, on).unwrap_or(f64::NAN)
        })
        .sum()
}

/// The moment about `centre` of the contact forces on the slave curve's nodes (an interface
/// with a deformable slave).
fn slave_moment(built: &BuiltProblem, iface: &InterfaceInfo, s: &ContactSolution, centre: [f64; 2]) -> f64 {
    let mut on_slave = vec![false; built.problem.model.mesh.num_nodes()];
    for node in iface.slave_contour.nodes.iter() {
        on_slave[node.0] = true;
    }
    interface_moment(built, iface, s, centre, |n| on_slave.get(n).copied().unwrap_or(false))
}

/// The force on the slave side of the interface: on the nodes of the slave curve, or, for a
/// rigid obstacle (no DOFs), the opposite of its force on the bodies.
fn slave_resultant(built: &BuiltProblem, iface: &InterfaceInfo, s: &ContactSolution) -> [f64; 2] {
    if iface.rigid_slave {
        let r = rigid_resultant(built, iface, s);
        return [-r[0], -r[1]];
    }
    let mut on_slave = vec![false; built.problem.model.mesh.num_nodes()];
    for node in iface.slave_contour.nodes.iter() {
        on_slave[node.0] = true;
    }
    iface.pairs.clone().fold([0.0; 2], |a, k| {
        let f = built
            .problem
            .pair_force_on(k, s.normal_force[k], s.tangential_force[k], |n| on_slave.get(n).copied().unwrap_or(false))
            .unwrap_or([f64::NAN; 2]);
        [a[0] + f[0], a[1] + f[1]]
    })
}

/// The force a rigid obstacle exerts on the bodies through the interface's pairs, `Σ_k R_k`
/// ([`contact2d_contact::ContactProblem::pair_resultant`]; NaN, caught as a non-finite summary,
/// if a pair were out of range).
fn rigid_resultant(built: &BuiltProblem, iface: &InterfaceInfo, s: &ContactSolution) -> [f64; 2] {
    iface.pairs.clone().fold([0.0; 2], |a, k| {
        let r = built.problem.pair_resultant(k, s.normal_force[k], s.tangential_force[k]).unwrap_or([f64::NAN; 2]);
        [a[0] + r[0], a[1] + r[1]]
    })
}

/// The friction work of the interface's slipping pairs in one step (trapezoid rule; `previous`:
/// the tangential forces the step started from).
pub(super) fn interface_dissipation(iface: &InterfaceInfo, s: &ContactSolution, previous: Option<&[f64]>) -> f64 {
    iface
        .pairs
        .clone()
        .filter(|&k| matches!(s.state[k], PairState::SlipPositive | PairState::SlipNegative))
        .map(|k| {
            let start = previous.map_or(0.0, |p| p[k]);
            -0.5 * (start + s.tangential_force[k]) * s.slip_increment[k]
        })
        .sum()
}

//! What the zone-end search does on the generated mesh (no node moved): the first estimate of
//! the contact end, and the step itself when the search cannot place the zone ends.

use crate::{
    BoussinesqLoading, ContactError, ContactStatus, Interface, contact_end, solve_boussinesq_step,
    solve_frictional_active_set, stick_end,
};

use super::history::ContourHistory;
use super::step::{PlacedLoading, PlacedStep};
use super::{PlacedCase, coordinate_order, pair_coordinates};

/// The contact end of the active-set solution at load `w` on the generated mesh.
pub(super) fn estimate_contact_end<C: PlacedCase>(
    base: &C,
    w: f64,
    history: &ContourHistory,
) -> Result<f64, ContactError> {
    let interface = Interface::new(base.problem());
    let start = history.start_for(base);
    let s = solve_frictional_active_set(base.problem(), &interface, w, &start, None, 500);
    if s.status != ContactStatus::Converged {
        return Err(ContactError::InvalidInput(format!("estimate of the zones at w = {w}: {:?}", s.status)));
    }
    contact_end(&pair_coordinates(base), &s.gap, &s.state).map(|(l, _)| l).ok_or_else(|| {
        ContactError::InvalidInput(format!("at w = {w} nothing or everything is in contact: no contact end to place"))
    })
}

/// The step by the Boussinesq algorithm on the generated mesh, when the zone-end search failed
/// (e.g. a singular problem A on a coarse mesh): zone ends at the nodes, l and b interpolated
/// (the 3/2-power laws of contact::post), the failure kept in the step.
pub(super) fn on_generated_mesh<C: PlacedCase>(
    base: C,
    loading: PlacedLoading,
    history: &ContourHistory,
    failure: String,
    evaluations: usize,
    clock: web_time::Instant,
) -> Result<PlacedStep<C>, ContactError> {
    let interface = Interface::new(base.problem());
    let start = history.start_for(&base);
    let order = coordinate_order(&base);
    let (eta, reported) = (pair_coordinates(&base), base.report_coordinates());
    let nodes = match loading {
        PlacedLoading::Load(w) => BoussinesqLoading::Load(w),
        PlacedLoading::ContactEnd(l) => {
            let nearest =
                (0..order.len()).min_by(|a, b| (eta[order[*a]] - l).abs().total_cmp(&(eta[order[*b]] - l).abs()));
            BoussinesqLoading::ContactEnd(nearest.unwrap_or(0))
        }
    };
    let mut step = solve_boussinesq_step(base.problem(), &interface, &order, nodes, &start, 4 * order.len());
    step.solution.time = clock.elapsed();
    let s = &step.solution;
    let end = |eta: &[f64]| contact_end(eta, &s.gap, &s.state).map(|(l, _)| l);
    let last = eta[order[step.zones.contact_end.min(order.len() - 1)]];
    let (l, l_reported) = (end(&eta).unwrap_or(last), end(&reported).unwrap_or(last));
    let stick = |eta: &[f64], l: f64| stick_end(eta, &s.slip_increment, &s.state).map_or(l, |(b, _)| b);
    let (b, b_reported) = (stick(&eta, l), stick(&reported, l_reported));
    Ok(PlacedStep {
        contact_end: l,
        stick_end: b,
        stick_end_placed: false,
        contact_end_placed: false,
        placement_failure: Some(failure),
        contact_end_reported: l_reported,
        stick_end_reported: b_reported,
        load: s.load_factor,
        residual_pressure: 0.0,
        residual_cone: 0.0,
        evaluations: evaluations + 1,
        start,
        case: base,
        step,
    })
}

//! The zone-end search: the paper's nodes at c = l* and c = b* (spec §6: "the contour nodes at
//! η = b* and η = l* are placed there (the mesh is adjusted)"), on any [`PlaceableContact`]
//! (c the master curve's coordinate, η on the preset's circles).
//!
//! ```text
//! estimate   l₀, b₀ and the slip direction from a solve on the generated mesh (active set for a
//!            given load; the Boussinesq b iteration for a given contact end)
//! place      the master corner nearest to l₀ (and another nearest to b₀) slides along the master
//!            curve; mid nodes re-centred, interior relaxed, pairs formed again
//! residuals  r_l(l, b) = p at the node at l*, from problem A at the given load   (Load)
//!            r_b(l, b) = σ q − μ|p| at the node at b* (last stick node; σ the slip direction)
//! roots      Load(w):        r_l = 0 in l and r_b = 0 in b, alternately, each by the Illinois
//!                            method (secant until the root is bracketed), until both settle
//!            ContactEnd(l):  l is placed as given, w from the Boussinesq condition λ(l*) = 0,
//!                            and r_b = 0 in b
//! history    the slips v_s and tangential tractions at the start of a step are functions of c
//!            on the master contour, interpolated linearly onto the pairs of the adjusted mesh
//! ```
//!
//! Each evaluation builds the adjusted mesh's problem (same topology) and solves problem A with
//! the zones given, so both conditions of the paper hold at their nodes: at b*, v − vh = v_s_τ
//! and f = 0; at l*, f = 0 (or stick) and p = 0.

use std::rc::Rc;

use crate::{BoussinesqLoading, ContactProblem};
use crate::{
    ContactError, ContactStatus, Interface, IterationRecord, PairState, StepStart, Zones, finish_zones,
    solve_boussinesq_step, solve_given_zones, stick_end,
};

use super::corners::{above, assign_corners, below, placement_limits};
use super::generated_mesh::{estimate_contact_end, on_generated_mesh};
use super::history::ContourHistory;
use super::roots::{Miss, find_root};
use super::step::{PlacedLoading, PlacedStep, ZoneEndSearch};
use super::{
    NodePlacement, PlaceableContact, PlacedCase, coordinate_order, corner_range, nearest_corner, pair_coordinates,
};

/// A mesh evaluation during the search.
#[derive(Clone)]
struct Evaluation<C> {
    case: C,
    interface: Interface,
    order: Vec<usize>,
    start: StepStart,
    zones: Zones,
    load: f64,
    normal_force: Vec<f64>,
    tangential_force: Vec<f64>,
    /// Pairs of the placed l and b nodes.
    l_pair: usize,
    b_pair: Option<usize>,
}

impl<C: PlacedCase> Evaluation<C> {
    fn pressure(&self, k: usize) -> f64 {
        self.normal_force[k] / self.case.problem().pairs[k].weight
    }

    fn pressure_scale(&self) -> f64 {
        (0..self.normal_force.len()).map(|k| self.pressure(k).abs()).fold(f64::MIN_POSITIVE, f64::max)
    }

    /// σ q − μ|p| at pair k for the slip direction σ of the zones (negative inside the cone).
    fn cone(&self, k: usize) -> f64 {
        let sigma = if self.zones.slip == Some(PairState::SlipPositive) { -1.0 } else { 1.0 };
        let (lambda, tau) = (self.normal_force[k], self.tangential_force[k]);
        (sigma * tau - self.case.problem().friction[k] * lambda) / self.case.problem().pairs[k].weight
    }
}

/// The search's fixed data: the family of meshes, the corners moved, the loading.
struct Search<'a, F: PlaceableContact> {
    family: &'a F,
    /// The generated mesh's problem: its symbolic factorisation serves every adjusted mesh.
    base: &'a F::Case,
    loading: PlacedLoading,
    history: &'a ContourHistory,
    l_corner: usize,
    evaluations: usize,
    limit: usize,
    /// One record per residual evaluated by the root finders.
    trace: Vec<IterationRecord>,
    /// The last few meshes solved, by their placement (see [`Placement`]).
    recent: Vec<(Placement, Shared<F::Case>)>,
}

/// An evaluation shared between the search and its kept evaluations.
type Shared<C> = Rc<Evaluation<C>>;

/// What an evaluation depends on within one search (the loading and history being fixed):
/// the l corner and the bits of l, and the b corner, the bits of b and the slip direction.
///
/// The root finders start where the previous one stopped (each returns a point it evaluated:
/// the l root at the b just found, then the b root at that l), the polish starts at the
/// alternating roots' answer and ends at its best iterate, and the step is finished there: each
/// such point is asked for twice. An evaluation is a deterministic function of its placement,
/// so the one kept is bit for bit the one a new mesh would give.
type Placement = (usize, u64, Option<(u64, usize, PairState)>);

/// Evaluations kept: the polish's best iterate is at most four evaluations back (its own, the
/// two difference quotients', and the next iterate's that did not improve).
const RECENT_EVALUATIONS: usize = 4;

impl<F: PlaceableContact> Search<'_, F> {
    /// Logs an evaluation: its zones and the residual the root finder sees.
    fn record(&mut self, e: &Evaluation<F::Case>, residual: f64) {
        self.trace.push(IterationRecord {
            iteration: self.evaluations,
            changed: 0,
            in_contact: e.zones.contact_end + 1,
            slipping: (e.zones.contact_end + 1).saturating_sub(e.zones.stick),
            residual,
        });
    }

    /// Solves the adjusted mesh with l (and b, if given) placed; without b, the stick zone comes
    /// from the Boussinesq b iteration on the nodes. A placement solved a few evaluations ago
    /// is not solved again ([`Placement`]).
    fn evaluate(&mut self, l: f64, b: Option<(f64, usize, PairState)>) -> Result<Shared<F::Case>, ContactError> {
        let placement: Placement =
            (self.l_corner, l.to_bits(), b.map(|(eta, corner, slip)| (eta.to_bits(), corner, slip)));
        if let Some((_, e)) = self.recent.iter().find(|(p, _)| *p == placement) {
            return Ok(Rc::clone(e));
        }
        let e = Rc::new(self.solve_mesh(l, b)?);
        if self.recent.len() == RECENT_EVALUATIONS {
            self.recent.remove(0);
        }
        self.recent.push((placement, Rc::clone(&e)));
        Ok(e)
    }

    /// [`Search::evaluate`] on a new mesh.
    fn solve_mesh(&mut self, l: f64, b: Option<(f64, usize, PairState)>) -> Result<Evaluation<F::Case>, ContactError> {
        self.evaluations += 1;
        if self.evaluations > self.limit {
            return Err(ContactError::InvalidInput(format!(
                "zone-end search: no convergence within {} meshes",
                self.limit
            )));
        }
        let mut placed_nodes = vec![NodePlacement { eta: l, corner: self.l_corner }];
        placed_nodes.extend(b.map(|(eta, corner, _)| NodePlacement { eta, corner }));
        let case = self.family.build_placed(&placed_nodes, self.base.problem())?;
        let interface = Interface::new(case.problem());
        let start = self.history.start_for(&case);
        let order = coordinate_order(&case);
        let pair_of = |corner: usize| -> Result<usize, ContactError> {
            let node = case.master_nodes()[corner];
            let k = case.problem().pairs.iter().position(|p| p.master == node);
            k.ok_or_else(|| ContactError::InvalidInput(format!("no pair at master corner {corner}")))
        };
        let l_pair = pair_of(self.l_corner)?;
        let position = |k: usize| order.iter().position(|&j| j == k).unwrap_or(0);
        let given = match self.loading {
            PlacedLoading::Load(w) => Some(w),
            PlacedLoading::ContactEnd(_) => None,
        };
        let (zones, forces, b_pair) = match b {
            Some((_, corner, slip)) => {
                let b_pair = pair_of(corner)?;
                let zones = Zones { stick: position(b_pair) + 1, contact_end: position(l_pair), slip: Some(slip) };
                let forces = solve_given_zones(case.problem(), &interface, &order, zones, given, &start)
                    .ok_or_else(|| singular(l))?;
                (zones, forces, Some(b_pair))
            }
            None => {
                let loading = match given {
                    Some(w) => BoussinesqLoading::Fixed { contact_end: position(l_pair), load: w },
                    None => BoussinesqLoading::ContactEnd(position(l_pair)),
                };
                let step = solve_boussinesq_step(case.problem(), &interface, &order, loading, &start, 4 * order.len());
                if step.solution.status == ContactStatus::Numerical {
                    return Err(singular(l));
                }
                let s = step.solution;
                let forces = crate::ZoneForces {
                    load: s.load_factor,
                    normal_force: s.normal_force,
                    tangential_force: s.tangential_force,
                };
                (step.zones, forces, None)
            }
        };
        Ok(Evaluation {
            case,
            interface,
            order,
            start,
            zones,
            load: forces.load,
            normal_force: forces.normal_force,
            tangential_force: forces.tangential_force,
            l_pair,
            b_pair,
        })
    }
}

fn singular(l: f64) -> ContactError {
    ContactError::InvalidInput(format!("problem A is singular with the contact zone ending at η = {l}"))
}

/// Solves one step with nodes placed at l* and b* from `history` (see the module docs).
///
/// A search that cannot place the zone ends (an estimate without a contact end, a zone end no
/// corner can reach, a singular problem A, no convergence within `search.max_evaluations`) is
/// not an error: the step is then solved by the Boussinesq algorithm on the generated mesh, with
/// l and b interpolated, and [`PlacedStep::placement_failure`] says why.
///
/// # Errors
/// Set-up failures (model, pairing, factorisation) on the generated mesh.
pub fn place_zone_ends<F: PlaceableContact>(
    family: &F,
    loading: PlacedLoading,
    history: &ContourHistory,
    search: ZoneEndSearch,
) -> Result<PlacedStep<F::Case>, ContactError> {
    let clock = web_time::Instant::now();
    let base = family.build_generated()?;
    match search_placed(family, &base, loading, history, search, clock) {
        Ok(step) => Ok(step),
        Err((e, evaluations)) => on_generated_mesh(base, loading, history, e.to_string(), evaluations, clock),
    }
}

/// The zone-end search with its retries; on failure, the error and the meshes it solved.
fn search_placed<F: PlaceableContact>(
    family: &F,
    base: &F::Case,
    loading: PlacedLoading,
    history: &ContourHistory,
    search: ZoneEndSearch,
    clock: web_time::Instant,
) -> Result<PlacedStep<F::Case>, (ContactError, usize)> {
    let mut l_estimate = match loading {
        PlacedLoading::ContactEnd(l) => l,
        PlacedLoading::Load(w) => estimate_contact_end(base, w, history).map_err(|e| (e, 0))?,
    };
    let mut b_estimate = None;
    let mut run = Search {
        family,
        base,
        loading,
        history,
        l_corner: 0,
        evaluations: 0,
        limit: search.max_evaluations,
        trace: vec![],
        recent: vec![],
    };
    // A zone end beyond the range of the corner chosen for it moves the search to the corner
    // the root finder points at.
    for _attempt in 0..8 {
        match search_zone_ends(&mut run, base, l_estimate, b_estimate, search.tolerance) {
            Ok((last, stick_end)) => {
                // The last evaluation, owned once the kept ones are let go.
                run.recent.clear();
                let last = Rc::try_unwrap(last).unwrap_or_else(|shared| (*shared).clone());
                let residual_cone = last.b_pair.map_or(0.0, |k| last.cone(k).abs() / last.pressure_scale());
                return finish((run.evaluations, clock.elapsed()), last, stick_end, residual_cone, run.trace)
                    .map_err(|e| (e, run.evaluations));
            }
            Err(Miss::Contact(e)) => return Err((e, run.evaluations)),
            Err(Miss::ContactEnd(towards)) => (l_estimate, b_estimate) = (towards, None),
            Err(Miss::StickEnd { towards, slip, contact_end }) => {
                (l_estimate, b_estimate) = (contact_end, Some((towards, slip)));
            }
        }
    }
    let e = ContactError::InvalidInput(format!(
        "zone-end search: no corner holds the zone ends (last l ≈ {l_estimate:.5})"
    ));
    Err((e, run.evaluations))
}

/// How the stick end of a step was found.
#[derive(Debug, Clone, Copy, PartialEq)]
enum StickEnd {
    /// Nothing slips: the stick zone is the whole contact zone.
    Whole,
    /// A node placed at b*.
    Placed(f64),
    /// b* closer to l* than two corners can be placed (a few hundredths of the corner spacing):
    /// the b iteration on the nodes, b interpolated like the slip (the 3/2-power law).
    Interpolated(f64),
}

/// One pass of the search with corners chosen for the estimates: the final evaluation and b*.
fn search_zone_ends<F: PlaceableContact>(
    run: &mut Search<'_, F>,
    base: &F::Case,
    l_estimate: f64,
    b_estimate: Option<(f64, PairState)>,
    tol: f64,
) -> Result<(Shared<F::Case>, StickEnd), Miss> {
    let loading = run.loading;
    let (mut l, mut b, slip) = match b_estimate {
        Some((b, slip)) => (l_estimate, b, slip),
        None => {
            run.l_corner = nearest_corner(base, l_estimate, &[])
                .ok_or_else(|| ContactError::InvalidInput("the master contour has no interior corner".into()))?;
            let l_range = placement_limits(corner_range(base, run.l_corner).unwrap_or([l_estimate; 2]));
            // l with the stick zone from the b iteration on the nodes.
            let l = match loading {
                PlacedLoading::ContactEnd(l) => l,
                PlacedLoading::Load(_) => find_root(|x| run_pressure(run, x, None), l_estimate, l_range, tol)
                    .map_err(|m| m.into_miss(Miss::ContactEnd))?,
            };
            let first = run.evaluate(l, None)?;
            let Some((b, slip)) = stick_estimate(&first) else {
                return Ok((first, StickEnd::Whole));
            };
            (l, b, slip)
        }
    };
    let Some((l_corner, b_corner)) = assign_corners(base, l, b, run.l_corner) else {
        let first = run.evaluate(l, None)?;
        let b = stick_estimate(&first).map_or(b, |(b, _)| b);
        return Ok((first, StickEnd::Interpolated(b)));
    };
    run.l_corner = l_corner;
    let l_range = placement_limits(corner_range(base, l_corner).unwrap_or([l, l]));
    let b_range = placement_limits(corner_range(base, b_corner).unwrap_or([b, b]));
    // Alternate 1D roots to a coarse tolerance, then polish (l, b) together by Newton's method.
    let coarse = tol.max(1e-6);
    for _round in 0..8 {
        let b_limits = below(b_range, l);
        let b_new =
            find_root(|x| run_cone(run, l, (x, b_corner, slip)), b.clamp(b_limits[0], b_limits[1]), b_limits, coarse)
                .map_err(|m| m.into_miss(|towards| Miss::StickEnd { towards, slip, contact_end: l }))?;
        let l_new = match loading {
            PlacedLoading::ContactEnd(_) => l,
            PlacedLoading::Load(_) => {
                let l_limits = above(l_range, b_new);
                find_root(|x| run_pressure(run, x, Some((b_new, b_corner, slip))), l, l_limits, coarse)
                    .map_err(|m| m.into_miss(|towards| Miss::StickEnd { towards: b_new, slip, contact_end: towards }))?
            }
        };
        let settled = (b_new - b).abs() <= coarse && (l_new - l).abs() <= coarse;
        (b, l) = (b_new, l_new);
        if settled || matches!(loading, PlacedLoading::ContactEnd(_)) {
            break;
        }
    }
    let b_node = (b_corner, slip);
    (l, b) = polish(run, (l, b), b_node, [l_range, b_range], tol)?;
    let last = run.evaluate(l, Some((b, b_corner, slip)))?;
    Ok((last, StickEnd::Placed(b)))
}

/// Newton's method on both residuals from one evaluation, `F(l, b) = (r_l, r_b)` (only r_b,
/// in b, when l is given), with a forward-difference Jacobian: from the alternating roots'
/// coarse answer to `tol`. A step that would leave the corners' ranges, or grow, stops the
/// polish at the last iterate.
fn polish<F: PlaceableContact>(
    run: &mut Search<'_, F>,
    (mut l, mut b): (f64, f64),
    (b_corner, slip): (usize, PairState),
    [l_range, b_range]: [[f64; 2]; 2],
    tol: f64,
) -> Result<(f64, f64), ContactError> {
    let load_given = matches!(run.loading, PlacedLoading::Load(_));
    let both = |run: &mut Search<'_, F>, l: f64, b: f64| -> Result<[f64; 2], ContactError> {
        let e = run.evaluate(l, Some((b, b_corner, slip)))?;
        let scale = e.pressure_scale();
        let k = e.b_pair.ok_or_else(|| singular(l))?;
        let r = [if load_given { e.pressure(e.l_pair) / scale } else { 0.0 }, e.cone(k) / scale];
        run.record(&e, r[0].abs().max(r[1].abs()));
        Ok(r)
    };
    let h = 1e-7;
    let norm = |f: [f64; 2]| f[0].abs().max(f[1].abs());
    let mut best = (l, b, f64::INFINITY);
    for _ in 0..4 {
        let f = both(run, l, b)?;
        if norm(f) >= best.2 {
            break; // the last step did not reduce the residuals: keep the best iterate
        }
        best = (l, b, norm(f));
        let fb = both(run, l, b + h)?;
        let (dl, db) = if load_given {
            let fl = both(run, l + h, b)?;
            let j = [[(fl[0] - f[0]) / h, (fb[0] - f[0]) / h], [(fl[1] - f[1]) / h, (fb[1] - f[1]) / h]];
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if det == 0.0 || !det.is_finite() {
                break;
            }
            ((-f[0] * j[1][1] + f[1] * j[0][1]) / det, (-f[1] * j[0][0] + f[0] * j[1][0]) / det)
        } else {
            let slope = (fb[1] - f[1]) / h;
            (0.0, if slope != 0.0 { -f[1] / slope } else { 0.0 })
        };
        let step = dl.abs().max(db.abs());
        let inside = |x: f64, [lo, hi]: [f64; 2]| x > lo && x < hi;
        if !step.is_finite() || step > 1e-3 || !inside(l + dl, l_range) || !inside(b + db, b_range) {
            break;
        }
        (l, b) = (l + dl, b + db);
        if step <= tol {
            return Ok((l, b)); // a Newton step this small only improves
        }
    }
    Ok((best.0, best.1))
}

/// p at the l node (compression positive), relative to the largest pressure.
fn run_pressure<F: PlaceableContact>(
    run: &mut Search<'_, F>,
    l: f64,
    b: Option<(f64, usize, PairState)>,
) -> Result<f64, ContactError> {
    let e = run.evaluate(l, b)?;
    let r = e.pressure(e.l_pair) / e.pressure_scale();
    run.record(&e, r);
    Ok(r)
}

/// The cone function at the b node, relative to the largest pressure.
fn run_cone<F: PlaceableContact>(
    run: &mut Search<'_, F>,
    l: f64,
    b: (f64, usize, PairState),
) -> Result<f64, ContactError> {
    let e = run.evaluate(l, Some(b))?;
    let k = e.b_pair.ok_or_else(|| singular(l))?;
    let r = e.cone(k) / e.pressure_scale();
    run.record(&e, r);
    Ok(r)
}

/// b₀ and the slip direction from an evaluation with the node-based b iteration; `None` when
/// nothing slips.
fn stick_estimate<C: PlacedCase>(e: &Evaluation<C>) -> Option<(f64, PairState)> {
    let slip = e.zones.slip?;
    if e.zones.stick > e.zones.contact_end {
        return None;
    }
    let eta = pair_coordinates(&e.case);
    let problem: &ContactProblem = e.case.problem();
    // The slips of the step from the forces, as the final solution would give them.
    let raw = crate::RawSolution {
        load_factor: e.load,
        normal_force: e.normal_force.clone(),
        tangential_force: e.tangential_force.clone(),
        status: ContactStatus::Converged,
        iterations: 0,
        time: std::time::Duration::ZERO,
    };
    let s = crate::finish_from_forces(problem, &e.interface, raw, &e.start);
    let b = stick_end(&eta, &s.slip_increment, &s.state).map(|(b, _)| b);
    let bracket = [eta[e.order[e.zones.stick.saturating_sub(1)]], eta[e.order[e.zones.stick]]];
    Some((b.unwrap_or(0.5 * (bracket[0] + bracket[1])), slip))
}

/// The final step: the displacement field, the (5.1) checks with the search's residuals as
/// slack at the two placed nodes.
fn finish<C: PlacedCase>(
    (evaluations, elapsed): (usize, std::time::Duration),
    e: Evaluation<C>,
    stick_end: StickEnd,
    residual_cone: f64,
    trace: Vec<IterationRecord>,
) -> Result<PlacedStep<C>, ContactError> {
    let residual_pressure = e.pressure(e.l_pair).abs() / e.pressure_scale();
    let by_condition = residual_pressure == 0.0;
    let (eta, reported) = (pair_coordinates(&e.case), e.case.report_coordinates());
    let contact_end = eta[e.l_pair];
    // b on both coordinates: a placed node's, l's, or interpolated between pairs.
    let on_reported = |b: f64| {
        let i = e.order.partition_point(|&k| eta[k] < b).clamp(1, e.order.len().saturating_sub(1));
        let (k0, k1) = (e.order[i - 1], e.order[i]);
        let t = (b - eta[k0]) / (eta[k1] - eta[k0]);
        if t.is_finite() { reported[k0] + t * (reported[k1] - reported[k0]) } else { reported[k0] }
    };
    let (stick_master, stick_reported) = match stick_end {
        StickEnd::Whole => (contact_end, reported[e.l_pair]),
        StickEnd::Placed(_) => e.b_pair.map_or((contact_end, reported[e.l_pair]), |k| (eta[k], reported[k])),
        StickEnd::Interpolated(b) => (b, on_reported(b)),
    };
    let forces = crate::ZoneForces { load: e.load, normal_force: e.normal_force, tangential_force: e.tangential_force };
    let slack = 10.0 * residual_pressure.max(residual_cone);
    let mut step = finish_zones(
        e.case.problem(),
        &e.interface,
        &e.order,
        e.zones,
        forces,
        by_condition,
        &e.start,
        (evaluations, elapsed),
        slack,
    );
    step.solution.trace = trace;
    Ok(PlacedStep {
        contact_end,
        stick_end: stick_master,
        stick_end_placed: matches!(stick_end, StickEnd::Placed(_)),
        contact_end_placed: true,
        placement_failure: None,
        contact_end_reported: reported[e.l_pair],
        stick_end_reported: stick_reported,
        load: e.load,
        residual_pressure,
        residual_cone,
        evaluations,
        start: e.start,
        case: e.case,
        step,
    })
}

/// The steps of a history with placed zone ends, each with the energy dissipated up to it.
pub type PlacedHistory<C> = Vec<(PlacedStep<C>, f64)>;

/// A loading history with zone ends placed at every step, the slips carried over on the
/// contour (the first step from the virgin state).
///
/// # Errors
/// As [`place_zone_ends`]; a decreasing load or contact end (the algorithm assumes a growing
/// contact zone).
pub fn solve_placed_history<F: PlaceableContact>(
    family: &F,
    loadings: &[PlacedLoading],
    search: ZoneEndSearch,
    on_step: &mut dyn FnMut(&PlacedStep<F::Case>),
) -> Result<PlacedHistory<F::Case>, ContactError> {
    let mut history = ContourHistory::virgin();
    let mut dissipated = 0.0;
    let mut steps = Vec::with_capacity(loadings.len());
    let mut last = f64::NEG_INFINITY;
    for &loading in loadings {
        let value = match loading {
            PlacedLoading::Load(w) | PlacedLoading::ContactEnd(w) => w,
        };
        if value < last {
            return Err(ContactError::InvalidInput(format!(
                "the Boussinesq algorithm assumes a growing contact zone and cannot unload ({value} after {last}); \
                 use the active set or Clarabel"
            )));
        }
        last = value;
        let step = place_zone_ends(family, loading, &history, search)?;
        dissipated += step.step.solution.dissipation;
        history = ContourHistory::after(&step.case, &step.step.solution);
        on_step(&step);
        steps.push((step, dissipated));
    }
    Ok(steps)
}

//! Generic results of a solved scene: per interface the resultants, zone lengths and the profile
//! along the master curve; reactions per fixed group and in total; strain energy per body; KKT
//! residuals.
//!
//! ```text
//! pressure_k = λ_k / (w_k t)     shear_k = τ_k / (w_k t)        (stresses; ≥ 0 in compression)
//!     w_k: tributary length of master node k, t: thickness of the master body
//! normal_force = Σ λ_k,  tangential_force = Σ τ_k                (forces; per unit thickness
//!                                                                 where the thickness is 1)
//! contact_length: along the master, from where contact starts to where it ends (the gaps
//!     between contact zones included); each end between the last pair in contact and the next
//!     free one, where the gap opens like (s − end)^{3/2}: gap^{2/3} is interpolated linearly
//!     over the next two free pairs; on a closed master curve (a full circle) the shortest arc
//!     holding every zone, up to the whole perimeter, a zone across the curve's start one zone
//!     (generic/zones.rs)
//! stick_length: likewise the stick zones' lengths summed, with |Δs|^{2/3} of the next
//!     slipping pairs (0 without friction)
//! dissipation = Σ_steps Σ_k −½(τ_k,start + τ_k) Δs_k over the interface's slipping pairs
//!
//! reactions.<group>[c] = Σ_{nodes of group} r_(node, c)  where the group's own [[fix]] entries
//!     prescribe c (null where they do not: another group's support is not this group's)
//! reactions_total[c]   = Σ_{constrained DOFs in c} r      (every constrained DOF once)
//! points.<name>: u_p, θ, R = Σ r over the point's nodes, M_R = Σ (x − p) × r  (super::points)
//! rigid_resultant      = Σ_k R_k over a rigid obstacle's pairs (its force on the bodies)
//! Σ loads + reactions_total + Σ rigid_resultant = 0       (global equilibrium)
//!
//! Moments about the run's centre c (`moment_centre`, default the origin; `run --about x,y`),
//! counter-clockwise positive, at the nodes' undeformed positions x_a (small strain):
//!
//! a × b = a_1 b_2 − a_2 b_1
//! reaction_moments.<group> = Σ_{nodes of group} Σ_{c prescribed} (x_a − c) × r_(a, c) e_c
//!     (the moment of the components the group's own fixes prescribe, as reactions.<group>:
//!      a group fixing u2 only has the moment of its vertical reactions)
//! reaction_moment_total    = Σ_{constrained DOFs} (x_a − c) × r e_c   (every DOF once)
//! contacts.<n>.moment      = Σ_k Σ_{a on the slave} (x_a − c) × f_ka  (the force `resultant`
//!     is; a rigid obstacle's: −rigid_moment)
//! contacts.<n>.rigid_moment = Σ_k Σ_a (x_a − c) × f_ka  (a rigid obstacle's force on the bodies,
//!     the moment of rigid_resultant)
//! contacts.<n>.couple = Σ_k Σ_a (x_a − c) × f_ka   (between two bodies: both sides' pair forces,
//!     which sum to zero, so the same about any centre)
//! Σ (x_a − c) × f_loads,a + reaction_moment_total + Σ rigid_moment + Σ couple = 0
//!                                                          (moment balance, any centre c)
//! ```
//!
//! The balance follows from `K u = f + B_Nᵀ λ + B_Tᵀ τ + r`: `K` annihilates each body's
//! infinitesimal rotation about c, `(−(y − c_2), x − c_1)`, as it does its translations. An
//! interface between two bodies applies its pair forces at undeformed points on both sides: a
//! normal force acts along the line through the pair's two points (it carries no couple), but a
//! tangential force τ_k transmitted across an initial gap g_k acts at two points g_k apart, the
//! couple ≈ g_k τ_k (0 where the sides touch or without friction): a small-strain model's
//! artefact of the order of the clearance times the friction force, reported so that the
//! balance closes.
//!
//! mean_pressure = normal_force / (contact_length t)   (null where contact_length = 0), the
//! mean of `pressure` over the contact length, with the same thickness t.
//!
//! The reactions `r` include the contact forces on constrained DOFs
//! ([`contact2d_contact::ContactProblem::reactions`]).

use std::collections::BTreeMap;

use serde::Serialize;

use contact2d_contact::{
    BuiltProblem, ContactError, ContactSolution, EnergyAllowance, History, InterfaceInfo, PairState, SolvedStep,
};

use super::points::{PointResult, ResolvedPoint};
use super::zones::{PairCurve, ZoneEnds, ZoneMarks, zone_ends, zones_length, zones_span};
use crate::output::step_view::state_label;

/// The profile of one interface along its master curve, pair by pair in order of `s`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Profile {
    /// Arc length along the master curve.
    pub s: Vec<f64>,
    /// Master node x.
    pub x: Vec<f64>,
    /// Master node y.
    pub y: Vec<f64>,
    /// Contact pressure (stress, ≥ 0 in compression).
    pub pressure: Vec<f64>,
    /// Shear traction (stress, along the pair tangent).
    pub shear: Vec<f64>,
    /// Gap.
    pub gap: Vec<f64>,
    /// Relative tangential displacement.
    pub slip: Vec<f64>,
    /// `free`, `contact` (frictionless), `stick`, `slip+`, `slip-`.
    pub state: Vec<&'static str>,
}

/// One interface's results at one step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactResult {
    /// Σ λ (force).
    pub normal_force: f64,
    /// Σ τ (force).
    pub tangential_force: f64,
    /// Length in contact along the master curve: from where contact starts to where it ends
    /// (on a closed curve up to its whole perimeter).
    pub contact_length: f64,
    /// Length of the stick zones, summed (0 without friction).
    pub stick_length: f64,
    /// `normal_force / (contact_length t)`: the mean contact pressure over the contact length
    /// (a stress, as `pressure`; `None`, JSON `null`, where the contact length is 0).
    pub mean_pressure: Option<f64>,
    /// The largest pressure.
    pub max_pressure: f64,
    /// Friction dissipation accumulated up to this step.
    pub dissipation: f64,
    /// The force the interface transmits, `[F1, F2]`: the resultant of the contact forces on
    /// the slave side (the slave curve's body, or the rigid obstacle), `Σ_k Σ_{a on the slave}
    /// (B_N)_ka λ_k + (B_T)_ka τ_k`; the master side receives its opposite.
    pub resultant: [f64; 2],
    /// A rigid obstacle's force on the bodies, `[R1, R2]` (the interfaces with a deformable
    /// slave have none: their pair forces are internal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rigid_resultant: Option<[f64; 2]>,
    /// The moment of `resultant`'s forces about the run's centre, `Σ_k Σ_{a on the slave}
    /// (x_a − c) × f_ka` at the undeformed positions (counter-clockwise positive).
    pub moment: f64,
    /// A rigid obstacle's moment about the run's centre of its force on the bodies (the
    /// moment of `rigid_resultant`; the interfaces with a deformable slave have none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rigid_moment: Option<f64>,
    /// Between two bodies: the moment of the pair forces on both sides together, which sum to
    /// zero (the same about any centre): a tangential force across an initial gap `g_k` acts at
    /// two points `g_k` apart, ≈ `Σ_k g_k τ_k` (0 where the sides touch or without friction);
    /// with the loads', reactions' and rigid obstacles' moments it sums to zero. None for a
    /// rigid obstacle (its moment is `rigid_moment`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub couple: Option<f64>,
    /// Whether the master curve closes on itself (a full circle): its zones are measured round
    /// it, a zone across the curve's start being one zone.
    pub closed: bool,
    /// Where the contact zones lie: each zone's two ends (in order along the master curve).
    pub zones: ZoneEnds,
    /// Where the stick zones lie (none without friction).
    pub stick_zones: ZoneEnds,
    /// The profile (top level only; omitted in the per-step entries). Boxed: every step's row
    /// holds this field, and a profile's room in each would grow a long history's memory.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profile: Option<Box<Profile>>,
    /// The fretting numbers over the last load cycle (top level only, with a `[loading]
    /// cycle`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fretting: Option<Box<super::fretting::Fretting>>,
}

/// KKT residuals of a step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Kkt {
    /// max(−gap, 0).
    pub max_penetration: f64,
    /// max |λ gap|.
    pub max_complementarity: f64,
    /// max(|τ| − μλ, 0).
    pub max_cone_violation: f64,
    /// Smallest −τ Δs over slipping pairs (≥ 0 when friction dissipates).
    pub min_dissipation: f64,
    /// A slipping pair inside the cone (dimensionless).
    pub max_slip_inside_cone: f64,
    /// The force the floating bodies' stabilising springs still carry (0 without floating bodies).
    pub floating_residual: f64,
    /// Proximal iterations of the floating bodies in the step (0 without floating bodies).
    pub floating_iterations: usize,
}

/// One step's results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepResult {
    /// Factor of each load pattern.
    pub factors: BTreeMap<String, f64>,
    /// The step's status.
    pub status: &'static str,
    /// The check that failed, for every status but `converged` (none there).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failed_check: Option<String>,
    /// Iterations of the algorithm (summed over a floating body's proximal iterations, and over
    /// finite sliding's solves of the step on its re-formed pairs).
    pub iterations: usize,
    /// Finite sliding (`sliding = "finite"` on some contact): how many times the step's pairs
    /// were formed again on its answer and the step solved again before the pairing was stable
    /// (0: the pairs formed at the step's start held). Absent with small sliding only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repairings: Option<usize>,
    /// Adaptive stepping (`[loading] adaptive`): how many steps of its path this user step took
    /// (absent without it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub substeps: Option<usize>,
    /// Per interface.
    pub contacts: BTreeMap<String, ContactResult>,
    /// Per fixed group: `[f1, f2]`, a component `None` (JSON `null`) where the group's own
    /// fixes do not prescribe it.
    pub reactions: BTreeMap<String, [Option<f64>; 2]>,
    /// `[R1, R2]`: the reactions of every constrained DOF, each counted once; with the loads and
    /// the rigid obstacles' resultants it sums to zero.
    pub reactions_total: [f64; 2],
    /// Per fixed group: the moment about the run's centre of the reactions in the components
    /// its own fixes prescribe, `Σ_a (x_a − c) × r_a` (counter-clockwise positive).
    pub reaction_moments: BTreeMap<String, f64>,
    /// The moment about the run's centre of every constrained DOF's reaction, each once; with
    /// the loads' and the rigid obstacles' moments it sums to zero.
    pub reaction_moment_total: f64,
    /// Per body: strain energy.
    pub energies: BTreeMap<String, f64>,
    /// Per `[[point]]`: its displacement, rotation and reactions (none without points).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub points: BTreeMap<String, PointResult>,
    /// Work of the loads and prescribed displacements up to this step, `W = Σ ½ (f_{i−1} + f_i) ·
    /// (u_i − u_{i−1})` with `f` the nodal loads plus the reactions (trapezoid rule; exact for
    /// a history solved once and scaled).
    pub work: f64,
    /// Friction dissipation of every interface up to this step.
    pub dissipated: f64,
    /// KKT residuals.
    pub kkt: Kkt,
    /// What the energy balance of the history up to this step may miss by: the trapezoid rule's
    /// bound and the round-off of `W` and `Φ_E` ([`contact2d_contact::check_energy_balance`]);
    /// not in the JSON.
    #[serde(skip)]
    pub energy_allowance: EnergyAllowance,
    /// For status `not_held`: what the contact could not hold (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_held: Option<NotHeldResult>,
    /// The error the step size causes at this step, relative ([`super::path_error`]: the
    /// contact resultants against the largest each carried, the dissipation against the work):
    /// 0 for a path-independent run, `None` (absent from the JSON) where it was not estimated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path_error: Option<f64>,
}

/// A load that the friction of a contact cannot hold (status `not_held`): a body held only by
/// contact slides away, every closed pair of its contact slipping along the same rigid motion.
///
/// ```text
/// ratio = demanded / available
///       = | dᵀ Rᵀ (f + B_Nᵀ λ) | / Σ_i μ_i λ_i |(B_T R d)_i|     (d the free rigid motion)
/// ```
/// For a block pressed by N on a flat base and pushed sideways by F: `ratio = F / (μ N)`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NotHeldResult {
    /// The contact (interface name) that lets go.
    pub contact: String,
    /// The body that slides away.
    pub body: String,
    /// The step (from 1) whose load is not held.
    pub step: usize,
    /// The load factors of the last step held (the previous converged step's; all zero when
    /// the first step is not held).
    pub last_held_factors: BTreeMap<String, f64>,
    /// Demanded over available friction force (above 1).
    pub ratio: f64,
    /// The tangential force demanded along the motion.
    pub demanded: f64,
    /// The friction force available along it, `Σ μ λ`.
    pub available: f64,
}

/// Why a step did not converge ([`contact2d_contact::status_reason`]), with the floating
/// bodies' proximal iteration where it ran.
fn failed_check(problem: &contact2d_contact::ContactProblem, step: &SolvedStep) -> Option<String> {
    if let Some(why) = &step.unstable_pairing {
        return Some(why.clone());
    }
    let reason = contact2d_contact::status_reason(problem, &step.solution)?;
    Some(if step.floating_iterations > 0 {
        format!(
            "{reason}; floating bodies: {} proximal iterations, the pins still carry {:.3e}",
            step.floating_iterations, step.floating_residual
        )
    } else {
        reason
    })
}

/// The name of a contact status.
pub fn status_name(status: contact2d_contact::ContactStatus) -> &'static str {
    use contact2d_contact::ContactStatus as S;
    match status {
        S::Converged => "converged",
        S::MaxIterations => "max_iterations",
        S::Infeasible => "infeasible",
        S::Numerical => "numerical",
        S::Inadmissible => "inadmissible",
        S::Penalised => "penalised",
        S::NotHeld => "not_held",
    }
}

/// A group that `[[fix]]` entries name, with the components they prescribe on it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FixedGroup {
    /// The physical group.
    pub name: String,
    /// Whether u1 and u2 are prescribed (by any of the group's entries).
    pub components: [bool; 2],
    /// For a group of staged fixes (`from_step`, `until_step`): the components its active
    /// entries prescribe in each step (index from 0); `None` when every entry holds in every
    /// step.
    pub components_by_step: Option<Vec<[bool; 2]>>,
}

impl FixedGroup {
    /// The components the group's entries prescribe in step `step` (from 0).
    pub fn components_at(&self, step: usize) -> [bool; 2] {
        self.components_by_step.as_ref().map_or(self.components, |c| c.get(step).copied().unwrap_or([false; 2]))
    }
}

/// The results of every step of `history`, the profile kept at the last.
///
/// # Errors
/// [`ContactError::InvalidInput`] when a step's solution does not fit the problem (reactions).
pub fn step_results(
    built: &BuiltProblem,
    history: &History,
    fixed_groups: &[FixedGroup],
) -> Result<Vec<StepResult>, ContactError> {
    let mut results = StepResults::new(built, fixed_groups);
    let n = history.steps.len();
    history.steps.iter().enumerate().map(|(i, step)| results.push(step, i + 1 == n)).collect()
}

/// The results of a history computed one step at a time, as each step is solved: it keeps of
/// the steps before only what the next one needs (the previous displacement, tangential forces
/// and external force, and the dissipation and work accumulated), so that its memory does not
/// grow with the number of steps.
#[derive(Debug, Clone)]
pub struct StepResults<'a> {
    built: &'a BuiltProblem,
    fixed_groups: &'a [FixedGroup],
    centre: [f64; 2],
    points: Vec<ResolvedPoint>,
    names: Vec<String>,
    owner: Vec<usize>,
    dissipated: Vec<f64>,
    work: f64,
    /// Σ ½ |Δf Δu| and Σ ½ (|f_prev| + |f| + (|K||u|)_prev + |K||u|) |Δu| so far.
    work_bounds: (f64, f64),
    previous_force: Vec<f64>,
    /// |K||u| of the previous step, per global DOF.
    previous_abs_ku: Vec<f64>,
    previous: Option<(Vec<f64>, Vec<f64>)>,
    /// The index of the next step (from 0).
    step: usize,
    /// The factors of the last step held (zeros before the first).
    held_factors: Vec<f64>,
}

impl<'a> StepResults<'a> {
    /// Before the first step of a history of `built`.
    pub fn new(built: &'a BuiltProblem, fixed_groups: &'a [FixedGroup]) -> Self {
        let problem = &built.problem;
        StepResults {
            built,
            fixed_groups,
            centre: [0.0; 2],
            points: vec![],
            names: problem.patterns().iter().map(|p| p.name.clone()).collect(),
            owner: dof_owners(problem),
            dissipated: vec![0.0; built.interfaces.len()],
            work: 0.0,
            work_bounds: (0.0, 0.0),
            previous_force: vec![0.0; problem.system.dofs.num_global()],
            previous_abs_ku: vec![0.0; problem.system.dofs.num_global()],
            previous: None,
            step: 0,
            held_factors: vec![0.0; problem.patterns().len()],
        }
    }

    /// The same results with moments about `centre` instead of the origin.
    pub fn about(self, centre: [f64; 2]) -> Self {
        StepResults { centre, ..self }
    }

    /// The same results reporting the motion and reactions of `points` too.
    pub fn with_points(self, points: Vec<ResolvedPoint>) -> Self {
        StepResults { points, ..self }
    }

    /// The next steps are solved on `built`: a problem of the same topology as the one before,
    /// whose nodes may have moved (the placed zone ends of the Boussinesq algorithm).
    pub fn rebase(&mut self, built: &'a BuiltProblem) {
        self.built = built;
    }

    /// The results of the next step of the history (with the interfaces' profiles if
    /// `with_profile`).
    ///
    /// # Errors
    /// [`ContactError::InvalidInput`] when the step's solution does not fit the problem
    /// (reactions).
    pub fn push(&mut self, step: &SolvedStep, with_profile: bool) -> Result<StepResult, ContactError> {
        self.push_on(self.built, step, with_profile)
    }

    /// [`StepResults::push`] of a step solved on `built`, a problem of the same bodies and
    /// interfaces whose pairs may differ (finite sliding), which these results do not keep.
    ///
    /// # Errors
    /// As [`StepResults::push`].
    pub fn push_on(
        &mut self,
        built: &BuiltProblem,
        step: &SolvedStep,
        with_profile: bool,
    ) -> Result<StepResult, ContactError> {
        let problem = &built.problem;
        let s = &step.solution;
        let before_tangential = self.previous.as_ref().map(|(_, t)| t.as_slice());
        let mut contacts = BTreeMap::new();
        for (k, iface) in built.interfaces.iter().enumerate() {
            self.dissipated[k] += interface_dissipation(iface, s, before_tangential);
            contacts.insert(
                iface.name.clone(),
                contact_result_about(built, iface, s, (self.dissipated[k], self.centre), with_profile),
            );
        }
        let reactions = reactions_at_dofs(built, s, &step.factors)?;
        let force = external_force(built, &reactions, &step.factors);
        let before = self.previous.as_ref().map(|(u, _)| u.as_slice());
        let previous_force = &self.previous_force;
        self.work += s
            .displacement
            .iter()
            .enumerate()
            .map(|(d, u)| 0.5 * (previous_force[d] + force[d]) * (u - before.map_or(0.0, |b| b[d])))
            .sum::<f64>();
        let (per_body, abs_ku, abs_energy) = body_energies(problem, &self.owner, &s.displacement);
        for (d, u) in s.displacement.iter().enumerate() {
            let du = (u - before.map_or(0.0, |b| b[d])).abs();
            let (f0, f1) = (previous_force[d], force[d]);
            self.work_bounds.0 += 0.5 * ((f1 - f0) * du).abs();
            self.work_bounds.1 += 0.5 * (f0.abs() + f1.abs() + self.previous_abs_ku[d] + abs_ku[d]) * du;
        }
        self.previous_force = force;
        self.previous_abs_ku = abs_ku;
        // γ_n = n ε / (1 − n ε) for sums of n terms (Higham 2002, §3.1), n the DOFs plus the
        // longest stiffness row (≤ 100 for Q9 neighbourhoods).
        let n = s.displacement.len() as f64 + 100.0;
        let gamma = n * f64::EPSILON / (1.0 - n * f64::EPSILON).max(0.5);
        let energy_allowance =
            EnergyAllowance { trapezoid: self.work_bounds.0, round_off: gamma * (self.work_bounds.1 + abs_energy) };
        let energies: BTreeMap<String, f64> =
            problem.model.bodies.iter().zip(per_body).map(|(body, e)| (body.name.clone(), e)).collect();
        let result = StepResult {
            factors: self.names.iter().cloned().zip(step.factors.iter().copied()).collect(),
            status: status_name(s.status),
            failed_check: failed_check(problem, step),
            iterations: s.iterations,
            repairings: None,
            substeps: None,
            contacts,
            reactions: group_reactions(built, &reactions, self.fixed_groups, self.step),
            points: self.points.iter().map(|p| (p.name.clone(), p.result(&s.displacement, &reactions))).collect(),
            reactions_total: reactions_total(built, &reactions),
            reaction_moments: group_reaction_moments(built, &reactions, self.fixed_groups, self.centre, self.step),
            reaction_moment_total: reaction_moment_total(built, &reactions, self.centre),
            energies,
            work: self.work,
            dissipated: step.dissipated,
            energy_allowance,
            kkt: Kkt {
                max_penetration: s.kkt.max_penetration,
                max_complementarity: s.kkt.max_complementarity,
                max_cone_violation: s.kkt.max_cone_violation,
                min_dissipation: s.kkt.min_dissipation,
                max_slip_inside_cone: s.kkt.max_slip_inside_cone,
                floating_residual: step.floating_residual,
                floating_iterations: step.floating_iterations,
            },
            not_held: step.not_held.as_ref().map(|n| NotHeldResult {
                contact: built
                    .interfaces
                    .iter()
                    .find(|i| n.pairs.first().is_some_and(|k| i.pairs.contains(k)))
                    .map_or_else(String::new, |i| i.name.clone()),
                body: n.body.clone(),
                step: n.step,
                last_held_factors: self.names.iter().cloned().zip(self.held_factors.iter().copied()).collect(),
                ratio: n.ratio(),
                demanded: n.demanded,
                available: n.available,
            }),
            path_error: None,
        };
        if s.status.is_solved() {
            self.held_factors.clone_from(&step.factors);
        }
        self.previous = Some((s.displacement.clone(), s.tangential_force.clone()));
        self.step += 1;
        Ok(result)
    }

    /// The interfaces' results, with profiles, at `solution`, the last step pushed (the
    /// dissipation accumulated up to it).
    pub fn contacts_with_profiles(&self, solution: &ContactSolution) -> BTreeMap<String, ContactResult> {
        let built = self.built;
        built
            .interfaces
            .iter()
            .zip(&self.dissipated)
            .map(|(iface, d)| {
                (iface.name.clone(), contact_result_about(built, iface, solution, (*d, self.centre), true))
            })
            .collect()
    }
}

/// The body owning each global DOF (`usize::MAX`: none, e.g. a rigid obstacle's node).
fn dof_owners(problem: &contact2d_contact::ContactProblem) -> Vec<usize> {
    let mut owner = vec![usize::MAX; problem.system.dofs.num_global()];
    for (b, body) in problem.model.bodies.iter().enumerate() {
        for i in 0..body.num_cells() {
            for d in body.cell_dofs(i) {
                owner[d.0] = b;
            }
        }
    }
    owner
}

/// The strain energy of every body, `½ uᵀ K u` summed over the DOFs it owns, from the assembled
/// blocks instead of the element matrices (the bodies share no DOF, so `K` is block diagonal by
/// body; `K_ff` is stored as its lower triangle and carries the floating pieces' springs `D`,
/// which are no strain energy):
///
/// ```text
/// U_b = ½ u_fᵀ (K_ff − D) u_f + u_fᵀ K_fc u_c + ½ u_cᵀ K_cc u_c     (rows of body b)
/// ```
///
/// The same energy as the sum over the cells of `½ u_eᵀ K_e u_e` up to round-off, at the cost
/// of one pass over the matrix per step instead of every element's stiffness. Also returns what
/// bounds the round-off of these sums: `|K||u|` per global DOF and `½ |u|ᵀ|K||u|` over all
/// bodies (with the springs `D`, whose `K u` terms are rounded as well).
fn body_energies(problem: &contact2d_contact::ContactProblem, owner: &[usize], u: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let dofs = &problem.system.dofs;
    // The blocks are in the DOFs `u' = Tᵀ u` at framed nodes (`u` itself without frames).
    let u = &*dofs.to_local(u);
    let (free, fixed) = (dofs.free_dofs(), dofs.constrained_dofs());
    // `K u` row by row first (each row's rigid-motion terms cancel there, to ε |K_i| |u|, as in
    // `K_e u_e`), then `½ Σ u_g (K u)_g` per body: summing the products `u_i K_ij u_j` one by
    // one instead loses the cancellation (1e-7 relative on a sliding block).
    let mut ku = vec![0.0; dofs.num_global()];
    let mut abs_ku = vec![0.0; dofs.num_global()];
    let kff = problem.system.stiffness.as_ref();
    for (j, dj) in free.iter().enumerate() {
        for (i, v) in kff.row_idx_of_col(j).zip(kff.val_of_col(j)) {
            let di = free[i];
            ku[di.0] += v * u[dj.0];
            abs_ku[di.0] += (v * u[dj.0]).abs();
            if i != j {
                ku[dj.0] += v * u[di.0];
                abs_ku[dj.0] += (v * u[di.0]).abs();
            }
        }
    }
    for &(i, k) in &problem.system.stabilisation {
        ku[free[i].0] -= k * u[free[i].0];
        abs_ku[free[i].0] += (k * u[free[i].0]).abs();
    }
    let kfc = problem.system.coupling.as_ref();
    let kcc = problem.system.constrained.as_ref();
    for (j, dj) in fixed.iter().enumerate() {
        for (i, v) in kfc.row_idx_of_col(j).zip(kfc.val_of_col(j)) {
            ku[free[i].0] += v * u[dj.0];
            ku[dj.0] += v * u[free[i].0];
            abs_ku[free[i].0] += (v * u[dj.0]).abs();
            abs_ku[dj.0] += (v * u[free[i].0]).abs();
        }
        for (i, v) in kcc.row_idx_of_col(j).zip(kcc.val_of_col(j)) {
            ku[fixed[i].0] += v * u[dj.0];
            abs_ku[fixed[i].0] += (v * u[dj.0]).abs();
        }
    }
    let mut energy = vec![0.0; problem.model.bodies.len()];
    for (g, (kug, ug)) in ku.iter().zip(u).enumerate() {
        if let Some(e) = energy.get_mut(owner[g]) {
            *e += 0.5 * ug * kug;
        }
    }
    let abs_energy = abs_ku.iter().zip(u).map(|(k, v)| 0.5 * k * v.abs()).sum();
    (energy, abs_ku, abs_energy)
}

/// The reactions of a step in global DOF order (zero at free DOFs).
fn reactions_at_dofs(built: &BuiltProblem, s: &ContactSolution, factors: &[f64]) -> Result<Vec<f64>, ContactError> {
    let problem = &built.problem;
    let mut at_dof = vec![0.0; problem.system.dofs.num_global()];
    let r = problem.reactions(s, factors)?;
    for (j, d) in problem.system.dofs.constrained_dofs().iter().enumerate() {
        at_dof[d.0] = r[j];
    }
    // `r = T r'` at framed nodes.
    problem.system.dofs.to_global_in_place(&mut at_dof);
    Ok(at_dof)
}

/// `[R1, R2]`: the reactions (global DOF order) of every constrained DOF, each once (both
/// components of a framed node's).
fn reactions_total(built: &BuiltProblem, at_dof: &[f64]) -> [f64; 2] {
    built.problem.system.dofs.reaction_dofs().iter().fold([0.0; 2], |mut a, d| {
        a[d.0 % 2] += at_dof[d.0];
        a
    })
}

/// The external nodal forces of a step in global DOF order: the loads of its pattern factors plus
/// the reactions.
fn external_force(built: &BuiltProblem, reactions: &[f64], factors: &[f64]) -> Vec<f64> {
    let mut f = reactions.to_vec();
    for (pattern, factor) in built.problem.patterns().iter().zip(factors) {
        f.iter_mut().zip(&pattern.nodal).for_each(|(f, v)| *f += factor * v);
    }
    f
}

/// `[f1, f2]` summed over the reactions (global DOF order) of each group's nodes, in the
/// components the group's own fixes prescribe in step `step` (`None` in the others: a node
/// there may be held by another group, whose reaction that is; and a staged fix that does not
/// hold in the step exerts no force of its own).
fn group_reactions(
    built: &BuiltProblem,
    at_dof: &[f64],
    groups: &[FixedGroup],
    step: usize,
) -> BTreeMap<String, [Option<f64>; 2]> {
    groups
        .iter()
        .filter_map(|g| {
            let nodes = built.problem.model.mesh.group_nodes(&g.name).ok()?;
            let components = g.components_at(step);
            let sum = |c: usize| components[c].then(|| nodes.iter().map(|n| at_dof[2 * n.0 + c]).sum::<f64>());
            Some((g.name.clone(), [sum(0), sum(1)]))
        })
        .collect()
}

/// `(x − c) × f` for the force `f` in component `component` (0: x1, 1: x2) at `x`.
fn moment_of(x: [f64; 2], centre: [f64; 2], component: usize, f: f64) -> f64 {
    if component == 0 { -(x[1] - centre[1]) * f } else { (x[0] - centre[0]) * f }
}

/// The moment about `centre` of the reactions (global DOF order) of every constrained DOF.
fn reaction_moment_total(built: &BuiltProblem, at_dof: &[f64], centre: [f64; 2]) -> f64 {
    let points = &built.problem.model.mesh.points;
    built
        .problem
        .system
        .dofs
        .reaction_dofs()
        .iter()
        .map(|d| points.get(d.0 / 2).map_or(f64::NAN, |x| moment_of(*x, centre, d.0 % 2, at_dof[d.0])))
        .sum()
}

/// The moment about `centre` of each group's reactions in the components its own fixes
/// prescribe (as [`group_reactions`]).
fn group_reaction_moments(
    built: &BuiltProblem,
    at_dof: &[f64],
    groups: &[FixedGroup],
    centre: [f64; 2],
    step: usize,
) -> BTreeMap<String, f64> {
    let points = &built.problem.model.mesh.points;
    groups
        .iter()
        .filter_map(|g| {
            let nodes = built.problem.model.mesh.group_nodes(&g.name).ok()?;
            // A staged group that holds nothing in this step has no moment (as its reactions
            // are null).
            let components = g.components_at(step);
            if components == [false; 2] {
                return None;
            }
            let moment = nodes
                .iter()
                .flat_map(|n| (0..2).filter(|c| components[*c]).map(move |c| (n.0, c)))
                .map(|(n, c)| points.get(n).map_or(f64::NAN, |x| moment_of(*x, centre, c, at_dof[2 * n + c])))
                .sum();
            Some((g.name.clone(), moment))
        })
        .collect()
}

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
fn interface_dissipation(iface: &InterfaceInfo, s: &ContactSolution, previous: Option<&[f64]>) -> f64 {
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

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
use std::sync::Arc;

use serde::Serialize;

use contact2d_contact::{BuiltProblem, ContactError, ContactSolution, EnergyAllowance, History, SolvedStep};

mod energies;
mod interface;
mod reactions;

pub(crate) use interface::mean_pressure;
pub use interface::{contact_result, contact_result_about};

use super::named_map::NamedMap;
use super::points::{PointResult, ResolvedPoint};
use super::zones::ZoneEnds;
use energies::{body_energies, dof_owners};
use interface::interface_dissipation;
use reactions::{
    external_force, group_reaction_moments, group_reactions, reaction_moment_total, reactions_at_dofs, reactions_total,
};

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
    pub factors: NamedMap<f64>,
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
    pub contacts: NamedMap<ContactResult>,
    /// Per fixed group: `[f1, f2]`, a component `None` (JSON `null`) where the group's own
    /// fixes do not prescribe it.
    pub reactions: NamedMap<[Option<f64>; 2]>,
    /// `[R1, R2]`: the reactions of every constrained DOF, each counted once; with the loads and
    /// the rigid obstacles' resultants it sums to zero.
    pub reactions_total: [f64; 2],
    /// Per fixed group: the moment about the run's centre of the reactions in the components
    /// its own fixes prescribe, `Σ_a (x_a − c) × r_a` (counter-clockwise positive).
    pub reaction_moments: NamedMap<f64>,
    /// The moment about the run's centre of every constrained DOF's reaction, each once; with
    /// the loads' and the rigid obstacles' moments it sums to zero.
    pub reaction_moment_total: f64,
    /// Per body: strain energy.
    pub energies: NamedMap<f64>,
    /// Per `[[point]]`: its displacement, rotation and reactions (none without points).
    #[serde(skip_serializing_if = "NamedMap::is_empty")]
    pub points: NamedMap<PointResult>,
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
    /// For status `not_held`: what the contact could not hold (absent otherwise). Boxed: every
    /// row holds this field, rarely filled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub not_held: Option<Box<NotHeldResult>>,
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
    /// The names every row's maps are keyed by, made once and shared by the rows: the load
    /// patterns', the interfaces', the bodies', the fixed groups' and the points'.
    names: Names,
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
            names: Names::new(built, fixed_groups),
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
        let names = Names { points: points.iter().map(|p| Arc::from(p.name.as_str())).collect(), ..self.names };
        StepResults { points, names, ..self }
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
        let mut contacts = Vec::with_capacity(built.interfaces.len());
        for (k, iface) in built.interfaces.iter().enumerate() {
            self.dissipated[k] += interface_dissipation(iface, s, before_tangential);
            contacts.push((
                Names::shared(&self.names.interfaces, k, &iface.name),
                contact_result_about(built, iface, s, (self.dissipated[k], self.centre), with_profile),
            ));
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
        let energies: NamedMap<f64> = problem
            .model
            .bodies
            .iter()
            .zip(per_body)
            .enumerate()
            .map(|(b, (body, e))| (Names::shared(&self.names.bodies, b, &body.name), e))
            .collect();
        let result = StepResult {
            factors: self.names.patterns.iter().cloned().zip(step.factors.iter().copied()).collect(),
            status: status_name(s.status),
            failed_check: failed_check(problem, step),
            iterations: s.iterations,
            repairings: None,
            substeps: None,
            contacts: contacts.into_iter().collect(),
            reactions: group_reactions(built, &reactions, (self.fixed_groups, &self.names.groups), self.step),
            points: self
                .names
                .points
                .iter()
                .zip(&self.points)
                .map(|(name, p)| (name.clone(), p.result(&s.displacement, &reactions)))
                .collect(),
            reactions_total: reactions_total(built, &reactions),
            reaction_moments: group_reaction_moments(
                built,
                &reactions,
                (self.fixed_groups, &self.names.groups),
                self.centre,
                self.step,
            ),
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
            not_held: step.not_held.as_ref().map(|n| {
                Box::new(NotHeldResult {
                    contact: built
                        .interfaces
                        .iter()
                        .find(|i| n.pairs.first().is_some_and(|k| i.pairs.contains(k)))
                        .map_or_else(String::new, |i| i.name.clone()),
                    body: n.body.clone(),
                    step: n.step,
                    last_held_factors: self
                        .names
                        .patterns
                        .iter()
                        .map(|k| k.to_string())
                        .zip(self.held_factors.iter().copied())
                        .collect(),
                    ratio: n.ratio(),
                    demanded: n.demanded,
                    available: n.available,
                })
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
    pub fn contacts_with_profiles(&self, solution: &ContactSolution) -> NamedMap<ContactResult> {
        let built = self.built;
        built
            .interfaces
            .iter()
            .zip(&self.dissipated)
            .enumerate()
            .map(|(k, (iface, d))| {
                (
                    Names::shared(&self.names.interfaces, k, &iface.name),
                    contact_result_about(built, iface, solution, (*d, self.centre), true),
                )
            })
            .collect()
    }
}

/// The names a history's rows are keyed by, each made once ([`Arc<str>`] shared by every row).
#[derive(Debug, Clone)]
struct Names {
    patterns: Vec<Arc<str>>,
    interfaces: Vec<Arc<str>>,
    bodies: Vec<Arc<str>>,
    groups: Vec<Arc<str>>,
    points: Vec<Arc<str>>,
}

impl Names {
    fn new(built: &BuiltProblem, groups: &[FixedGroup]) -> Self {
        let problem = &built.problem;
        Names {
            patterns: problem.patterns().iter().map(|p| Arc::from(p.name.as_str())).collect(),
            interfaces: built.interfaces.iter().map(|i| Arc::from(i.name.as_str())).collect(),
            bodies: problem.model.bodies.iter().map(|b| Arc::from(b.name.as_str())).collect(),
            groups: groups.iter().map(|g| Arc::from(g.name.as_str())).collect(),
            points: vec![],
        }
    }

    /// The shared name `names[i]` where it is `name` (it is, but for a problem rebased on
    /// another), else a new one.
    pub(super) fn shared(names: &[Arc<str>], i: usize, name: &str) -> Arc<str> {
        names.get(i).filter(|n| &***n == name).cloned().unwrap_or_else(|| Arc::from(name))
    }
}

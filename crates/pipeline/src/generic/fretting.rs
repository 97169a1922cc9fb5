//! Fretting numbers of each contact over the last load cycle (`[loading] cycle`), made step by
//! step as the history is solved ([`FrettingWatch`]), reported as `contacts.<name>.fretting`.
//!
//! ```text
//! pair k (master node at arc length s_k, tributary length w_k), steps i of the last cycle,
//! i0 the step before it (the virgin state when the cycle is the whole schedule):
//!   slip_amplitude_k = ½ (max_i s_k,i − min_i s_k,i),  i ∈ {i0} ∪ cycle     s = B_T u
//!                      (0 for a pair free at every step of the cycle: no slip, only the
//!                      bodies' deformation outside the contact)
//!   energy_k         = Σ_i |τ_k,i| |Δs_k,i|  over the steps where k slips    (force × length)
//!   dissipation_k    = energy_k / w_k          (energy per cycle per unit length of contact)
//!   dissipated       = Σ_k energy_k             (energy per cycle)
//!   shear_max_k      = max_i |τ_k,i| / w_k      (stress)
//!   sigma_tt_k       = max_i σ_tt at the paired point on the slave curve, σ_tt = tᵀσt, recovered
//!                      (Gauss points extrapolated to the nodes, averaged per body; interpolated
//!                      with the pair's shape-function weights); 0 for a rigid slave
//!   ruiz_k           = max(sigma_tt_k, 0) · shear_max_k · slip_amplitude_k  (Ruiz 1984, F2)
//!   loop             = (δ_i, Q_i): Q = Σ_k τ_k, δ = t̄ · (ū_A − ū_B) of the contact's
//!                      reference_groups A, B (mean displacements; t̄ the pairs' mean tangent)
//! ```
//!
//! `|τ| |Δs|` takes the slipping pair's end-of-step force, on the friction cone: exact while
//! the normal force of a slipping pair holds still over the step (a constant press), unlike the
//! trapezoid `−½(τ_start + τ) Δs` of the step's dissipation, which loses the work of a step where
//! the pair's slip reverses. Ruiz, Boddington & Chen (1984), Exp. Mech. 24, 208–217.

use serde::Serialize;

use contact2d_contact::{BuiltProblem, ContactError, ContactSolution, PairState};
use contact2d_fem::{StressRecovery, nodal_stresses};

/// The hysteresis loop of a contact over the last cycle.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HysteresisLoop {
    /// The two reference groups `[A, B]`.
    pub groups: [String; 2],
    /// δ per step (the step before the cycle first).
    pub displacement: Vec<f64>,
    /// Q = Σ τ per step.
    pub tangential_force: Vec<f64>,
}

/// One contact's fretting numbers over the last cycle.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fretting {
    /// The last cycle's first and last step (from 1).
    pub steps: [usize; 2],
    /// Arc length of each pair's master node.
    pub s: Vec<f64>,
    /// Half the peak-to-peak relative tangential displacement per pair (length).
    pub slip_amplitude: Vec<f64>,
    /// Energy dissipated per cycle per unit length of contact, per pair.
    pub dissipation: Vec<f64>,
    /// Energy dissipated per cycle by the whole contact.
    pub dissipated: f64,
    /// The largest |shear traction| over the cycle, per pair (stress).
    pub shear_max: Vec<f64>,
    /// The largest tangential surface stress σ_tt over the cycle on the slave side, per pair.
    pub sigma_tt: Vec<f64>,
    /// The Ruiz parameter max(σ_tt, 0) · shear_max · slip_amplitude per pair.
    pub ruiz: Vec<f64>,
    /// Its largest value and where: `[value, s, x, y]` (the master node's undeformed position).
    pub ruiz_max: [f64; 4],
    /// The hysteresis loop (only with the contact's `reference_groups`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hysteresis: Option<HysteresisLoop>,
}

/// A contact's reference groups A, B: their names, their nodes and the pairs' mean tangent.
type Reference = ([String; 2], [Vec<usize>; 2], [f64; 2]);

/// One contact's running sums.
#[derive(Debug, Clone)]
struct Running {
    first: usize,
    weight: Vec<f64>,
    s: Vec<f64>,
    lo: Vec<f64>,
    hi: Vec<f64>,
    /// Whether the pair was in contact at a step of the cycle.
    touched: Vec<bool>,
    energy: Vec<f64>,
    shear: Vec<f64>,
    sigma: Vec<f64>,
    /// The slave body, where the slave is deformable.
    slave_body: Option<contact2d_fem::BodyId>,
    /// The reference groups, if given.
    reference: Option<Reference>,
    delta: Vec<f64>,
    force: Vec<f64>,
}

/// The fretting numbers of every contact, followed over the last cycle of a history.
#[derive(Debug, Clone)]
pub struct FrettingWatch {
    cycle: std::ops::Range<usize>,
    contacts: Vec<Running>,
    step: usize,
}

impl FrettingWatch {
    /// Before the first step of a history of `built` whose last cycle is the steps `cycle`
    /// (from 0); `references[c]`: the reference groups of contact `c`, if given.
    ///
    /// # Errors
    /// [`ContactError`] naming an unknown reference group.
    pub fn new(
        built: &BuiltProblem,
        cycle: std::ops::Range<usize>,
        references: &[Option<[String; 2]>],
    ) -> Result<FrettingWatch, ContactError> {
        let pairs = &built.problem.pairs;
        let model = &built.problem.model;
        let mut contacts = vec![];
        for (c, info) in built.interfaces.iter().enumerate() {
            let range = info.pairs.clone();
            let n = range.len();
            let reference = match references.get(c).cloned().flatten() {
                Some(groups) => {
                    let nodes = [model.mesh.group_nodes(&groups[0])?, model.mesh.group_nodes(&groups[1])?];
                    let nodes = nodes.map(|g| g.iter().map(|n| n.0).collect::<Vec<usize>>());
                    let sum = pairs[range.clone()]
                        .iter()
                        .fold([0.0, 0.0], |acc, p| [acc[0] + p.tangent[0], acc[1] + p.tangent[1]]);
                    let norm = sum[0].hypot(sum[1]);
                    let tangent = if norm > 0.0 { [sum[0] / norm, sum[1] / norm] } else { [1.0, 0.0] };
                    Some((groups, nodes, tangent))
                }
                None => None,
            };
            contacts.push(Running {
                first: range.start,
                weight: pairs[range.clone()].iter().map(|p| p.weight).collect(),
                s: pairs[range.clone()].iter().map(|p| p.master_arc_length).collect(),
                lo: vec![0.0; n],
                hi: vec![0.0; n],
                touched: vec![false; n],
                energy: vec![0.0; n],
                shear: vec![0.0; n],
                sigma: vec![f64::NEG_INFINITY; n],
                slave_body: if info.rigid_slave { None } else { model.body(&info.slave_region).map(|(id, _)| id) },
                reference,
                delta: vec![],
                force: vec![],
            });
        }
        Ok(FrettingWatch { cycle, contacts, step: 0 })
    }

    /// Takes the next step's solution.
    ///
    /// # Errors
    /// A failed stress recovery.
    pub fn observe(&mut self, built: &BuiltProblem, solution: &ContactSolution) -> Result<(), ContactError> {
        let i = self.step;
        self.step += 1;
        let start = self.cycle.start.checked_sub(1);
        let before = start == Some(i);
        let inside = self.cycle.contains(&i);
        if !before && !inside {
            return Ok(());
        }
        let pairs = &built.problem.pairs;
        let u = &solution.displacement;
        for c in &mut self.contacts {
            let range = c.first..c.first + c.weight.len();
            let (slip, tau) = (&solution.slip[range.clone()], &solution.tangential_force[range.clone()]);
            if before || (start.is_none() && i == self.cycle.start) {
                // The state the cycle starts from (the virgin state when nothing came before).
                let (s0, q0) = if before { (slip.to_vec(), tau.iter().sum()) } else { (vec![0.0; slip.len()], 0.0) };
                c.lo.clone_from(&s0);
                c.hi = s0;
                c.delta = vec![c.reference.as_ref().map_or(0.0, |r| relative(r, if before { u } else { &[] }))];
                c.force = vec![q0];
                if before {
                    continue;
                }
            }
            for (j, &s) in slip.iter().enumerate() {
                c.lo[j] = c.lo[j].min(s);
                c.hi[j] = c.hi[j].max(s);
                let k = c.first + j;
                c.touched[j] |= solution.state[k] != PairState::Free;
                if matches!(solution.state[k], PairState::SlipPositive | PairState::SlipNegative) {
                    c.energy[j] += tau[j].abs() * solution.slip_increment[k].abs();
                }
                if c.weight[j] > 0.0 {
                    c.shear[j] = c.shear[j].max(tau[j].abs() / c.weight[j]);
                }
            }
            if let Some(body) = c.slave_body {
                let nodal = nodal_stresses(&built.problem.model, body, u, StressRecovery::Extrapolated)?;
                for (j, pair) in pairs[range].iter().enumerate() {
                    let mut sigma = [0.0; 3];
                    for (node, w) in &pair.slave {
                        let at = nodal.get(node.0).copied().flatten().unwrap_or([0.0; 3]);
                        for (a, b) in sigma.iter_mut().zip(at) {
                            *a += w * b;
                        }
                    }
                    let [t1, t2] = pair.tangent;
                    let tt = sigma[0] * t1 * t1 + 2.0 * sigma[2] * t1 * t2 + sigma[1] * t2 * t2;
                    c.sigma[j] = c.sigma[j].max(tt);
                }
            }
            c.delta.push(c.reference.as_ref().map_or(0.0, |r| relative(r, u)));
            c.force.push(tau.iter().sum());
        }
        Ok(())
    }

    /// The fretting numbers of each contact (in the problem's order), once the last cycle was
    /// seen; `None` before.
    pub fn results(&self, built: &BuiltProblem) -> Option<Vec<Fretting>> {
        if self.step < self.cycle.end || self.cycle.is_empty() {
            return None;
        }
        let points = &built.problem.model.mesh.points;
        let out = self
            .contacts
            .iter()
            .map(|c| {
                let amplitude: Vec<f64> =
                    (0..c.lo.len()).map(|j| if c.touched[j] { 0.5 * (c.hi[j] - c.lo[j]) } else { 0.0 }).collect();
                let sigma: Vec<f64> = c.sigma.iter().map(|s| if s.is_finite() { *s } else { 0.0 }).collect();
                let ruiz: Vec<f64> =
                    (0..amplitude.len()).map(|j| sigma[j].max(0.0) * c.shear[j] * amplitude[j]).collect();
                let at = (0..ruiz.len()).fold(0, |b, j| if ruiz[j] > ruiz[b] { j } else { b });
                let ruiz_max = match (ruiz.get(at), built.problem.pairs.get(c.first + at)) {
                    (Some(r), Some(p)) => [*r, c.s[at], points[p.master.0][0], points[p.master.0][1]],
                    _ => [0.0; 4],
                };
                Fretting {
                    steps: [self.cycle.start + 1, self.cycle.end],
                    s: c.s.clone(),
                    slip_amplitude: amplitude,
                    dissipation: c
                        .energy
                        .iter()
                        .zip(&c.weight)
                        .map(|(e, w)| if *w > 0.0 { e / w } else { 0.0 })
                        .collect(),
                    dissipated: c.energy.iter().sum(),
                    shear_max: c.shear.clone(),
                    sigma_tt: sigma,
                    ruiz,
                    ruiz_max,
                    hysteresis: c.reference.as_ref().map(|(groups, _, _)| HysteresisLoop {
                        groups: groups.clone(),
                        displacement: c.delta.clone(),
                        tangential_force: c.force.clone(),
                    }),
                }
            })
            .collect();
        Some(out)
    }
}

/// `t̄ · (ū_A − ū_B)`: the mean displacements of the two groups' nodes along the tangent (0 for
/// no displacement, `u` empty).
fn relative((_, nodes, t): &Reference, u: &[f64]) -> f64 {
    let mean = |g: &[usize], c: usize| {
        let sum: f64 = g.iter().map(|n| u.get(2 * n + c).copied().unwrap_or(0.0)).sum();
        if g.is_empty() { 0.0 } else { sum / g.len() as f64 }
    };
    let d = [mean(&nodes[0], 0) - mean(&nodes[1], 0), mean(&nodes[0], 1) - mean(&nodes[1], 1)];
    t[0] * d[0] + t[1] * d[1]
}

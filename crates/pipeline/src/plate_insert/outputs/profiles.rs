//! The contour profiles of one solved step as data: hole edge Γ_p and insert edge Γ_c, node by node.
//!
//! ```text
//! hole edge (plate), per node:   η = 1 − φ/π, φ about the hole centre (0, 0)
//!   s_φφ  = tᵀ σ t, σ the plate's nodal stress (Gauss points extrapolated, averaged; as σ*)
//!   T     = F / w: the traction the insert exerts on the plate (force F on the node, w its
//!           tributary length ∫ N ds on the hole edge)
//!   p = −T·n, q = −T·l   the paper's plate tractions (p < 0 in compression), n the pair normal
//!           pointing from the insert into the plate (n_c in variant 1, n_p in variant 2), l = (−n2, n1)
//! insert edge (insert), per node: η = 1 − θ/π, θ about the insert centre (−ε, 0)
//!   s_θθ  = the insert's hoop stress (none for a rigid insert)
//!   p̂ = T̂·n, q̂ = T̂·l    the insert's tractions (p̂ = s_ρρ, q̂ = s_ρθ), T̂ = F̂ / ŵ, F̂ = −F
//! ```
//! Forces are those the discrete system applies: a pair's master node carries `f = λ n + τ t` (the
//! contact crate's convention), the slave nodes `−N_j f` (N_j their shape weights at the paired
//! point), gathered per node; `w` is the node's tributary length on its own contour, and n, l, gap,
//! slip and state are those of the node's dominant pair (largest shape weight there). Nodes no pair
//! reaches have no contact values. Σ F over the hole edge then balances the pulling force P in x1,
//! the plate's other supports being rollers (x2 reactions only).

use contact2d_contact::{ContactPair, PairState, tributary_weights};
use contact2d_fem::{BodyId, StressRecovery, stresses_along_curve};
use contact2d_mesh::{Contour, NodeId};

use crate::output::OutputError;
use crate::output::step_view::{NodeValues, StepView};
use crate::plate_insert::report::PaperStep as SolvedStep;
use crate::plate_insert::{PairingVariant, PlateInsertProblem};

/// The contact values of one contour node (from its pair).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeContact {
    /// Normal traction in the paper's sign (p < 0 in compression on the hole edge; p̂ = s_ρρ on
    /// the insert edge).
    pub pressure: f64,
    /// Tangential traction (q on the hole edge, q̂ = s_ρθ on the insert edge).
    pub shear: f64,
    /// Traction vector (x1, x2) exerted on this contour's body by the other body.
    pub traction: [f64; 2],
    /// Tributary length ∫ N ds of the node on its contour (force = traction × weight).
    pub weight: f64,
    /// The pair's unit normal, pointing from the insert into the plate.
    pub normal: [f64; 2],
    /// The pair's gap at the solution.
    pub gap: f64,
    /// The pair's relative tangential displacement.
    pub slip: f64,
    /// The pair's state.
    pub state: PairState,
}

/// One node of a contour profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileRow {
    /// The node.
    pub node: NodeId,
    /// η = 1 − angle/π (0 where the plate bears on the insert, 1 on the far side).
    pub eta: f64,
    /// The polar angle (radians): φ about the hole centre, θ about the insert centre.
    pub angle: f64,
    /// Undeformed position.
    pub x: [f64; 2],
    /// Hoop stress (σ along the contour's tangent); `None` on a rigid insert.
    pub hoop_stress: Option<f64>,
    /// Contact values, `None` for a node without a pair.
    pub contact: Option<NodeContact>,
}

/// The two contour profiles of one step.
#[derive(Debug, Clone, PartialEq)]
pub struct Profiles {
    /// The hole edge Γ_p, ordered from φ = 0 (η = 1) to φ = π (η = 0).
    pub hole: Vec<ProfileRow>,
    /// The insert edge Γ_c, ordered likewise.
    pub insert: Vec<ProfileRow>,
}

/// A short name of a pair state (as written in CSV files).
pub fn state_name(state: PairState) -> &'static str {
    match state {
        PairState::Free => "free",
        PairState::Stick => "stick",
        PairState::SlipPositive => "slip+",
        PairState::SlipNegative => "slip-",
    }
}

pub use crate::output::step_view::state_code;

/// The writers' view of a flagship step: its problem and solution, the rigid insert's edge as
/// an obstacle, the contact values of its profiles, and the non-dimensional labels.
pub fn flagship_view<'a>(step: &'a SolvedStep, profiles: &Profiles) -> StepView<'a> {
    let problem = &step.case.problem;
    let mut node_contact = vec![None; problem.model.mesh.num_nodes()];
    for row in profiles.hole.iter().chain(&profiles.insert) {
        if let Some(c) = row.contact {
            node_contact[row.node.0] =
                Some(NodeValues { pressure: c.pressure, shear: c.shear, state: state_code(c.state) });
        }
    }
    let rigid_insert = problem.model.body("insert").is_none();
    StepView {
        problem,
        solution: &step.solution,
        obstacles: if rigid_insert { vec![&step.case.insert] } else { vec![] },
        node_contact,
        axes: ["x1 / R (non-dimensional)".into(), "x2 / R".into()],
        stress_label: "σ_vM / E1".into(),
    }
}

/// The profiles of a solved step.
///
/// # Errors
/// [`OutputError::Fem`] if the stresses cannot be recovered.
pub fn contour_profiles(step: &SolvedStep) -> Result<Profiles, OutputError> {
    let case: &PlateInsertProblem = &step.case;
    let model = &case.problem.model;
    let u = &step.solution.displacement;
    let hole_hoop = stresses_along_curve(model, BodyId(0), &case.hole, u, StressRecovery::Extrapolated)?;
    let insert_hoop = match model.body("insert") {
        Some((id, _)) => Some(stresses_along_curve(model, id, &case.insert, u, StressRecovery::Extrapolated)?),
        None => None,
    };
    let (hole_contact, insert_contact) = node_contacts(step);
    let eps = case.eps;
    let rows = |contour: &Contour, centre: f64, hoop: Option<Vec<f64>>, contact: Vec<Option<NodeContact>>| {
        contour
            .nodes
            .iter()
            .enumerate()
            .map(|(k, &node)| {
                let x = model.mesh.points[node.0];
                let angle = x[1].atan2(x[0] - centre);
                ProfileRow {
                    node,
                    eta: 1.0 - angle / std::f64::consts::PI,
                    angle,
                    x,
                    hoop_stress: hoop.as_ref().map(|h| h[k]),
                    contact: contact[k],
                }
            })
            .collect::<Vec<_>>()
    };
    let hoop = |samples: Vec<contact2d_fem::CurveSample>| samples.iter().map(|s| s.tangential_stress()).collect();
    Ok(Profiles {
        hole: rows(&case.hole, 0.0, Some(hoop(hole_hoop)), hole_contact),
        insert: rows(&case.insert, -eps, insert_hoop.map(hoop), insert_contact),
    })
}

/// The contact values at the nodes of the hole edge and of the insert edge (see the module docs).
fn node_contacts(step: &SolvedStep) -> (Vec<Option<NodeContact>>, Vec<Option<NodeContact>>) {
    let case = &step.case;
    let hole_is_master = case.variant == PairingVariant::HoleMaster;
    let (mut hole, mut insert) = (NodeForces::new(&case.hole), NodeForces::new(&case.insert));
    let (master, slave) = if hole_is_master { (&mut hole, &mut insert) } else { (&mut insert, &mut hole) };
    for (k, pair) in case.problem.pairs.iter().enumerate() {
        let f = master_force(pair, step.solution.normal_force[k], step.solution.tangential_force[k]);
        master.add(pair.master, f, k, 1.0);
        for &(node, shape) in &pair.slave {
            slave.add(node, [-shape * f[0], -shape * f[1]], k, shape.abs());
        }
    }
    (hole.finish(step, true), insert.finish(step, false))
}

/// The force `λ n + τ t` of a pair on its master node.
fn master_force(pair: &ContactPair, lambda: f64, tau: f64) -> [f64; 2] {
    [lambda * pair.normal[0] + tau * pair.tangent[0], lambda * pair.normal[1] + tau * pair.tangent[1]]
}

/// Contact forces gathered at the nodes of one contour, with the pair that dominates each node.
struct NodeForces<'c> {
    contour: &'c Contour,
    force: Vec<[f64; 2]>,
    /// (pair, shape weight) of the pair with the largest shape weight at the node.
    dominant: Vec<Option<(usize, f64)>>,
}

impl<'c> NodeForces<'c> {
    fn new(contour: &'c Contour) -> Self {
        let n = contour.nodes.len();
        NodeForces { contour, force: vec![[0.0; 2]; n], dominant: vec![None; n] }
    }

    fn add(&mut self, node: NodeId, f: [f64; 2], pair: usize, shape: f64) {
        let Some(i) = self.contour.nodes.iter().position(|n| *n == node) else { return };
        self.force[i][0] += f[0];
        self.force[i][1] += f[1];
        if self.dominant[i].is_none_or(|(_, s)| shape > s) {
            self.dominant[i] = Some((pair, shape));
        }
    }

    /// Tractions in the frame of each node's dominant pair; `plate` selects the sign convention.
    fn finish(self, step: &SolvedStep, plate: bool) -> Vec<Option<NodeContact>> {
        let case = &step.case;
        let s = &step.solution;
        let weights = tributary_weights(self.contour);
        self.force
            .iter()
            .zip(&self.dominant)
            .zip(weights)
            .map(|((force, dominant), weight)| {
                let (k, _) = (*dominant)?;
                let pair = &case.problem.pairs[k];
                // The pair normal points out of the slave body: into the plate in variant 1, into
                // the hole in variant 2.
                let normal = match case.variant {
                    PairingVariant::HoleMaster => pair.normal,
                    PairingVariant::InsertMaster => [-pair.normal[0], -pair.normal[1]],
                };
                let l = [-normal[1], normal[0]];
                let traction = [force[0] / weight, force[1] / weight];
                let dot = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
                // The plate's stress vector on n is −T (n points into the plate); the insert's is T.
                let sign = if plate { -1.0 } else { 1.0 };
                Some(NodeContact {
                    pressure: sign * dot(traction, normal),
                    shear: sign * dot(traction, l),
                    traction,
                    weight,
                    normal,
                    gap: s.gap[k],
                    slip: s.slip[k],
                    state: s.state[k],
                })
            })
            .collect()
    }
}

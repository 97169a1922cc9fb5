//! What the page draws of any solved step: the mesh as element edges, the nodal displacements,
//! and the pairs' states at their master nodes.
//!
//! ```text
//! points        [x1, y1, x2, y2, ...]          undeformed node positions (after pairing's morphing)
//! edges         [a, m, b, a, m, b, ...]        element edges, each once: end nodes a, b and the
//!                                              mid node m (m = a on linear edges)
//! displacement  [u1, v1, u2, v2, ...]          per node; the page draws X = x + β u
//! pairs         master node, state, λ, tangent state: free, contact (frictionless), stick, slip+, slip-
//!                                              (slip± along ±tangent, the pair's global unit tangent)
//! ```

use std::collections::BTreeSet;

use serde::Serialize;

use contact2d_contact::{ContactProblem, ContactSolution};
use contact2d_pipeline::output::step_view::state_label;

/// The mesh of a solved step as the page draws it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeshView {
    /// Undeformed node positions, two numbers per node.
    pub points: Vec<f64>,
    /// Element edges, three node indices each (ends a, b and mid node m, in the order a, m, b).
    pub edges: Vec<usize>,
    /// The body of each edge (index into `bodies`), for colouring.
    pub edge_body: Vec<usize>,
    /// Body names, in model order.
    pub bodies: Vec<String>,
    /// Nodal displacements, two numbers per node (0 at nodes of no body).
    pub displacement: Vec<f64>,
}

/// The pairs of a solved step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairsView {
    /// The master node of each pair.
    pub master: Vec<usize>,
    /// Each pair's state: `free`, `contact` (frictionless), `stick`, `slip+`, `slip-`.
    pub state: Vec<&'static str>,
    /// Each pair's normal force λ (≥ 0 in compression).
    pub normal_force: Vec<f64>,
    /// Each pair's unit tangent `t = (−n_y, n_x)` in the global frame (`n` out of the slave
    /// body): `slip+` is the master node sliding along `+t` relative to the slave surface, so
    /// the page names the slip by the global direction `±t` (e.g. "slip → +x").
    pub tangent: Vec<[f64; 2]>,
}

impl PairsView {
    /// No pairs (a run with no solved step).
    pub fn empty() -> Self {
        Self { master: vec![], state: vec![], normal_force: vec![], tangent: vec![] }
    }
}

/// The mesh view of `problem` displaced by `solution`.
pub fn mesh_view(problem: &ContactProblem, solution: &ContactSolution) -> MeshView {
    let model = &problem.model;
    let mut seen = BTreeSet::new();
    let (mut edges, mut edge_body) = (vec![], vec![]);
    for (k, body) in model.bodies.iter().enumerate() {
        for c in 0..body.num_cells() {
            let element = body.elements[c];
            let nodes = body.cell_nodes(c);
            for edge in element.edges() {
                let (a, b) = (nodes[edge[0]].0, nodes[edge[1]].0);
                if !seen.insert((a.min(b), a.max(b))) {
                    continue;
                }
                let mid = if element.degree() > 1 { nodes[edge[2]].0 } else { a };
                edges.extend([a, mid, b]);
                edge_body.push(k);
            }
        }
    }
    let n = model.mesh.num_nodes();
    let u = &solution.displacement;
    MeshView {
        points: model.mesh.points.iter().flatten().copied().collect(),
        edges,
        edge_body,
        bodies: model.bodies.iter().map(|b| b.name.clone()).collect(),
        displacement: (0..2 * n).map(|k| u.get(k).copied().unwrap_or(0.0)).collect(),
    }
}

/// The pairs view of `solution`; `friction` decides the label of pairs in contact (`contact`
/// without friction, `stick` with).
pub fn pairs_view(problem: &ContactProblem, solution: &ContactSolution, friction: f64) -> PairsView {
    PairsView {
        master: problem.pairs.iter().map(|p| p.master.0).collect(),
        state: solution.state.iter().map(|s| state_label(*s, friction)).collect(),
        normal_force: solution.normal_force.clone(),
        tangent: problem.pairs.iter().map(|p| p.tangent).collect(),
    }
}

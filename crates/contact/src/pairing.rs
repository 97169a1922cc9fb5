//! Contact pairs between a master and a slave contour.
//!
//! For each master node `x_m` the closest point `y` of the slave curve is found (node-to-segment
//! with the slave edge's shape functions; it is node-to-node where a slave node is there):
//!
//! ```text
//! y = Σ_j N_j(ξ*) y_j,   ξ* = argmin |x(ξ) - x_m|  over every slave edge (Newton, ξ ∈ [-1, 1])
//! n = unit normal of the slave curve at y, pointing out of the slave body (towards the master)
//! t = (-n_y, n_x)                       (n turned counter-clockwise; the paper's l_c for n_c)
//! g0 = (x_m - y) · n                    (initial gap, ≥ 0 when apart; geometric; |x_m − y| off
//!                                        the slave curve's ends and behind a curve of the
//!                                        master's own body: crate::side)
//! gap(u) = g0 + n · (u_m - Σ_j N_j u_j) ≥ 0                            (non-penetration)
//! w_m = Σ_edges ∫ N_m ds                (tributary length of the master node: p = -λ / w_m)
//! γ   = ds_master / ds_slave            (force-transfer ratio of paired arc elements, (4.x))
//! ```
//!
//! With the master on the hole this is the paper's variant 1 (n = n_c, the insert normal); with
//! the master on the insert, variant 2 (n = -n_p in our outward convention, so the same
//! inequality reads u - uh ≥ u_s). The paper's γ is always ds_plate/ds_insert: γ1 = γ in
//! variant 1 and γ2 = 1/γ in variant 2.

use contact2d_element::Kinematics;
use contact2d_fem::Model;
use contact2d_mesh::{Contour, ContourEdge, NodeId};
use rayon::prelude::*;

use crate::error::ContactError;
use crate::side::{Projection, SlaveBody};

/// One contact pair: a master node and its closest point on the slave curve.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    /// Master node.
    pub master: NodeId,
    /// Slave nodes and their shape-function weights at the paired point.
    pub slave: Vec<(NodeId, f64)>,
    /// Paired point on the slave curve.
    pub slave_point: [f64; 2],
    /// Unit normal (out of the slave body).
    pub normal: [f64; 2],
    /// Unit tangent `(-n_y, n_x)`.
    pub tangent: [f64; 2],
    /// Initial gap `(x_m - y) · n`.
    pub gap: f64,
    /// Tributary length of the master node on the master contour.
    pub weight: f64,
    /// Force-transfer ratio `ds_master / ds_slave`.
    pub gamma: f64,
    /// Arc length of the master node along the master contour.
    pub master_arc_length: f64,
    /// Arc length of the paired point along the slave contour.
    pub slave_arc_length: f64,
    /// The rows integrated over the master segments (segment-to-segment pairing,
    /// [`crate::segment_to_segment`]); `None` for node-to-segment, whose rows are
    /// `n · (u_master − Σ_j N_j u_slave_j)`.
    pub integrated: Option<IntegratedRows>,
}

/// One node's coefficients in an integrated pair row: the row is `Σ_a c_a · u_a` over nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowCoefficient {
    /// The node.
    pub node: NodeId,
    /// Its coefficient vector in the normal row, `(1/w_k) ∫ φ_k N_a n ds` (negated on the slave).
    pub normal: [f64; 2],
    /// Its coefficient vector in the tangential row (with `t` for `n`).
    pub tangent: [f64; 2],
}

/// The integrated rows of a segment-to-segment pair (`crate::segment_to_segment`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct IntegratedRows {
    /// Master-side nodes (the integration side), in order of first appearance.
    pub master: Vec<RowCoefficient>,
    /// Slave-side nodes, in order of first appearance.
    pub slave: Vec<RowCoefficient>,
    /// The slave nodes and shape-function weights at the master node's own closest point (the
    /// node-to-segment data the integrated weights replace): whether the node itself can move
    /// tangentially against the slave is judged on them ([`crate::ContactProblem::tangential`]).
    pub point_slave: Vec<(NodeId, f64)>,
    /// The unit tangent of the slave curve at that point (the node-to-segment tangent the
    /// integrated mean replaces).
    pub point_tangent: [f64; 2],
}

/// Builds the pairs of every node of `master` with the closest point of `slave`.
///
/// `slave_region` names the 2D physical group the slave contour bounds — a body's region, or a
/// rigid obstacle's — to orient the normals outward.
///
/// # Errors
/// [`ContactError::Pairing`] if the slave body is unknown, a contour is degenerate, or the normal
/// cannot be oriented.
pub fn pair_contours(
    model: &Model,
    master: &Contour,
    slave: &Contour,
    slave_region: &str,
) -> Result<Vec<ContactPair>, ContactError> {
    let err = |reason: String| ContactError::Pairing { master: master.name.clone(), slave: slave.name.clone(), reason };
    let body = SlaveBody::new(model, slave_region, slave).map_err(err)?;
    Ok(pair_contours_with(model, master, slave, &body, &EdgeBoxes::of(slave)))
}

/// [`pair_contours`] with the slave side's body and edge boxes already built (segment-to-segment
/// pairing reuses them for its quadrature points).
pub(crate) fn pair_contours_with(
    model: &Model,
    master: &Contour,
    slave: &Contour,
    body: &SlaveBody,
    boxes: &EdgeBoxes,
) -> Vec<ContactPair> {
    let weights = tributary_weights_in(master, &model.pairing_kinematics());
    // Each master node's closest point is independent: in parallel, collected in node order.
    let mut pairs: Vec<ContactPair> = master
        .nodes
        .par_iter()
        .enumerate()
        .map(|(k, &m)| {
            let x = model.mesh.points[m.0];
            let (edge_index, xi) = closest_point(slave, boxes, &model.mesh.points, x);
            let edge = &slave.edges[edge_index];
            let (y, t, _) = slave.edge_frame(edge, xi);
            let projection = Projection { edge: edge_index, xi, point: y, tangent: t, own: &[m] };
            let (normal, gap) = body.normal_and_gap(slave, x, &projection);
            let shape = edge_shape(edge.quadratic, xi);
            let count = if edge.quadratic { 3 } else { 2 };
            let slave_nodes: Vec<(NodeId, f64)> =
                (0..count).map(|a| (edge.nodes[a], shape[a])).filter(|(_, w)| w.abs() > 1e-14).collect();
            ContactPair {
                master: m,
                slave: slave_nodes,
                slave_point: y,
                normal,
                tangent: [-normal[1], normal[0]],
                gap,
                weight: weights[k],
                gamma: 1.0,
                master_arc_length: master.arc_length[k],
                slave_arc_length: slave.arc_length[edge.first] + slave.edge_length(edge, xi),
                integrated: None,
            }
        })
        .collect();
    set_gamma(&mut pairs);
    pairs
}

pub(crate) fn edge_shape(quadratic: bool, xi: f64) -> [f64; 3] {
    if quadratic {
        [0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi]
    } else {
        [0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0]
    }
}

/// The edge of `slave` and the reference coordinate of the point closest to `x`, rounded to a
/// node where it is there to round-off.
fn closest_point(slave: &Contour, boxes: &EdgeBoxes, points: &[[f64; 2]], x: [f64; 2]) -> (usize, f64) {
    let (edge, xi) = boxes.closest_point_unsnapped(slave, points, x);
    (edge, snap(xi))
}

/// The bounding boxes of a contour's edges (quadratic edges: of their control points), computed
/// once for the many closest-point searches on one contour (a contour's pairing asks one per
/// master node or integration point).
pub(crate) struct EdgeBoxes(Vec<[f64; 4]>);

impl EdgeBoxes {
    /// The boxes of `contour`'s edges, on its own points.
    pub(crate) fn of(contour: &Contour) -> EdgeBoxes {
        let own = contour.points();
        EdgeBoxes(contour.edges.iter().map(|e| edge_box(e, own)).collect())
    }

    /// The edge of `slave` and the reference coordinate of the point closest to `x`: of the
    /// candidates of [`edge_candidates`], edge by edge, the first that is closer than the best so far
    /// by more than 1e-15.
    ///
    /// Edges are skipped unsolved when their bounding box lies farther than a candidate already
    /// found (`U`, from the edge of the nearest box) plus a margin `1e-9 (U + its box's size)`: all of
    /// their candidates are then farther than the closest one by more than the margin, so they can be
    /// neither the answer nor, as a passing best, decide between candidates within 1e-15 of each
    /// other — the same answer as solving every edge. `self` must be the boxes of `slave`.
    pub(crate) fn closest_point_unsnapped(&self, slave: &Contour, points: &[[f64; 2]], x: [f64; 2]) -> (usize, f64) {
        // (Distances are those of `Contour::edge_point`, on the contour's own points.)
        let boxes = &self.0;
        let box_distance =
            |[x0, y0, x1, y1]: [f64; 4]| (x0 - x[0]).max(x[0] - x1).max(0.0).hypot((y0 - x[1]).max(x[1] - y1).max(0.0));
        let lower: Vec<f64> = boxes.iter().map(|b| box_distance(*b)).collect();
        let Some(nearest) = (0..lower.len()).min_by(|&a, &b| lower[a].total_cmp(&lower[b])) else { return (0, 0.0) };
        let upper = edge_candidates(slave, points, nearest, x).iter().map(|c| c.1).fold(f64::INFINITY, f64::min);
        let [x0, y0, x1, y1] = boxes[nearest];
        let cutoff = upper + 1e-9 * (upper + (x1 - x0).hypot(y1 - y0));
        let mut best = (0, 0.0, f64::INFINITY);
        for i in (0..slave.edges.len()).filter(|&i| lower[i] <= cutoff) {
            for (xi, dist) in edge_candidates(slave, points, i, x) {
                if dist < best.2 - 1e-15 {
                    best = (i, xi, dist);
                }
            }
        }
        (best.0, best.1)
    }
}

/// `(ξ, distance)` of Newton's method on `f(ξ) = (x(ξ) − x) · x'(ξ) = 0` from the starts −0.5, 0,
/// 0.5 on edge `i` of `slave`, clamped to the edge.
fn edge_candidates(slave: &Contour, points: &[[f64; 2]], i: usize, x: [f64; 2]) -> [(f64, f64); 3] {
    let edge = &slave.edges[i];
    // x''(ξ) is constant: Σ N''_a y_a with N'' = (1, 1, -2) for Line3, zero for Line2.
    let dd = if edge.quadratic {
        let [a, b, m] = edge.nodes.map(|n| points[n.0]);
        [a[0] + b[0] - 2.0 * m[0], a[1] + b[1] - 2.0 * m[1]]
    } else {
        [0.0, 0.0]
    };
    [-0.5, 0.0, 0.5].map(|start: f64| {
        let mut xi = start;
        for _ in 0..30 {
            let (p, d) = slave.edge_point(edge, xi);
            let r = [p[0] - x[0], p[1] - x[1]];
            let f = r[0] * d[0] + r[1] * d[1];
            let df = d[0] * d[0] + d[1] * d[1] + r[0] * dd[0] + r[1] * dd[1];
            let step = if df > 0.0 { f / df } else { f / (d[0] * d[0] + d[1] * d[1]) };
            let next = (xi - step).clamp(-1.0, 1.0);
            let converged = (next - xi).abs() < 1e-15;
            xi = next;
            if converged {
                break;
            }
        }
        let (p, _) = slave.edge_point(edge, xi);
        (xi, (p[0] - x[0]).hypot(p[1] - x[1]))
    })
}

/// A box holding the edge: its end nodes, and for a Line3 the control point `2 m − (a + b)/2`
/// of its Bézier form (the curve lies in the convex hull of those).
fn edge_box(edge: &ContourEdge, points: &[[f64; 2]]) -> [f64; 4] {
    let (a, b) = (points[edge.nodes[0].0], points[edge.nodes[1].0]);
    let mut pts = vec![a, b];
    if edge.quadratic {
        let m = points[edge.nodes[2].0];
        pts.push([2.0 * m[0] - 0.5 * (a[0] + b[0]), 2.0 * m[1] - 0.5 * (a[1] + b[1])]);
    }
    pts.iter().fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |[x0, y0, x1, y1], p| {
        [x0.min(p[0]), y0.min(p[1]), x1.max(p[0]), y1.max(p[1])]
    })
}

/// Whether the nodes of the curves `a` and `b` face each other one to one: the closest point of
/// every node of each curve on the other is a node, to `|Δξ| ≤ 1e-6` of the edge's reference
/// coordinate (mesh generators write the two copies of a shared arc with differences far above
/// round-off), so the meshes match along the interface (nodes beyond the other curve's end
/// project onto its end node). Node-to-segment pairs are then node-to-node.
pub fn nodes_face_each_other(points: &[[f64; 2]], a: &Contour, b: &Contour) -> bool {
    const TOLERANCE: f64 = 1e-6;
    let onto = |from: &Contour, to: &Contour| {
        let boxes = EdgeBoxes::of(to);
        from.nodes.iter().all(|n| {
            let (e, xi) = boxes.closest_point_unsnapped(to, points, points[n.0]);
            (xi.abs() - 1.0).abs() <= TOLERANCE || (xi.abs() <= TOLERANCE && to.edges[e].quadratic)
        })
    };
    onto(a, b) && onto(b, a)
}

/// Rounds ξ to a node where it is there to round-off, so node-to-node pairs are exact.
fn snap(xi: f64) -> f64 {
    for node in [-1.0, 0.0, 1.0] {
        if (xi - node).abs() < 1e-10 {
            return node;
        }
    }
    xi
}

/// `w_a = Σ_edges ∫ N_a ds` for every node of the contour (5-point Gauss per edge).
pub fn tributary_weights(contour: &Contour) -> Vec<f64> {
    tributary_weights_in(contour, &Kinematics::PlaneStress { thickness: 1.0 })
}

/// `w_a = Σ_edges ∫ N_a m ds` for every node of the contour, `m` the kinematics'
/// [`Kinematics::pairing_measure`] (1 in the plane: [`tributary_weights`]; `2πr` for a body of
/// revolution, the area of the node's ring).
pub fn tributary_weights_in(contour: &Contour, kinematics: &Kinematics) -> Vec<f64> {
    const G: [(f64, f64); 5] = contact2d_mesh::GAUSS5;
    let mut w = vec![0.0; contour.nodes.len()];
    for e in &contour.edges {
        // Contour indices of start, end and mid in `nodes`.
        let (start, mid, end) =
            if e.quadratic { (e.first, e.first + 1, e.first + 2) } else { (e.first, e.first, e.first + 1) };
        let end = if contour.closed && end == contour.nodes.len() { 0 } else { end };
        for (g, wg) in G {
            let (x, _, ds) = contour.edge_frame(e, g);
            // × 1.0 exactly in the plane.
            let ds = ds * kinematics.pairing_measure(x);
            let n = edge_shape(e.quadratic, g);
            w[start] += wg * ds * n[0];
            w[end] += wg * ds * n[1];
            if e.quadratic {
                w[mid] += wg * ds * n[2];
            }
        }
    }
    w
}

/// γ = ds_master / ds_slave by central differences of the paired arc lengths (one-sided at ends).
fn set_gamma(pairs: &mut [ContactPair]) {
    let n = pairs.len();
    if n < 2 {
        return;
    }
    let s: Vec<(f64, f64)> = pairs.iter().map(|p| (p.master_arc_length, p.slave_arc_length)).collect();
    for (k, p) in pairs.iter_mut().enumerate() {
        let (a, b) = (k.saturating_sub(1), (k + 1).min(n - 1));
        let ds_slave = (s[b].1 - s[a].1).abs();
        if ds_slave > 0.0 {
            p.gamma = (s[b].0 - s[a].0).abs() / ds_slave;
        }
    }
}

/// Where the slave contour's nodes must go for every pair to become node-to-node: the paired
/// points, in order of their arc length along the slave curve, are given to the slave contour's
/// nodes in their order (the paper's node sets of pairs). The mesh can then be morphed with
/// `contact2d_mesh::morph::move_nodes` and pairing repeated.
///
/// # Errors
/// [`ContactError::Pairing`] when the slave contour does not have one node per pair.
pub fn node_to_node_targets(pairs: &[ContactPair], slave: &Contour) -> Result<Vec<(NodeId, [f64; 2])>, ContactError> {
    if slave.nodes.len() != pairs.len() {
        return Err(ContactError::Pairing {
            master: String::new(),
            slave: slave.name.clone(),
            reason: format!(
                "node-to-node pairs need one slave node per pair: {} slave nodes, {} pairs",
                slave.nodes.len(),
                pairs.len()
            ),
        });
    }
    let mut order: Vec<&ContactPair> = pairs.iter().collect();
    order.sort_by(|a, b| a.slave_arc_length.total_cmp(&b.slave_arc_length));
    Ok(slave.nodes.iter().zip(order).map(|(n, pair)| (*n, pair.slave_point)).collect())
}

/// The gaps and normals [`crate::side`] gives the pairs (nodes beyond the slave curve, a node
/// behind a curve of its own body).
#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod side_tests {
    use super::*;
    use crate::test_fixtures::facing_blocks;
    use contact2d_mesh::CellKind;

    /// Block a = [0, 1] × [−1, 0] and block b = [0.5, 2] × [g, 1] (b's bottom runs past a's end).
    fn blocks(kind: CellKind, g: f64) -> (Model, Contour, Contour) {
        facing_blocks(kind, [0.5, 2.0], g, 4, 6, 2)
    }

    #[test]
    fn nodes_beyond_the_slave_curve_are_at_their_distance_from_its_end() {
        // Over a's top (x ≤ 1) b's bottom is at y = g: the gap is g (an interference for g < 0,
        // b's nodes then lying inside a); beyond it the closest point is the corner (1, 0) and
        // the node, outside a, is at the distance hypot(x − 1, g). Round-off: 1e-13.
        for kind in [CellKind::Quad4, CellKind::Quad9] {
            for g in [0.1, 0.0, -0.1] {
                let (model, master, slave) = blocks(kind, g);
                let pairs = pair_contours(&model, &master, &slave, "a_domain").unwrap();
                for p in &pairs {
                    let x = model.mesh.points[p.master.0][0];
                    let expected = if x <= 1.0 { g } else { (x - 1.0).hypot(g) };
                    assert!((p.gap - expected).abs() < 1e-13, "{kind:?}, g = {g}, x = {x}: gap {}", p.gap);
                    assert!((p.normal[1] - 1.0).abs() < 1e-13, "out of a: +y");
                }
            }
        }
    }

    #[test]
    fn a_node_behind_a_curve_of_its_own_body_is_open() {
        // b's top (y = 1) against b's bottom (y = g) through the block: the distance 1 − g, not
        // the interference −(1 − g) along the bottom's outward normal −y. Round-off: 1e-13.
        let (model, _, _) = blocks(CellKind::Quad9, 0.1);
        let master = Contour::from_group(&model.mesh, "b_top").unwrap();
        let slave = Contour::from_group(&model.mesh, "b_bottom").unwrap();
        for p in pair_contours(&model, &master, &slave, "b_domain").unwrap() {
            assert!((p.gap - 0.9).abs() < 1e-13 && (p.normal[1] + 1.0).abs() < 1e-13, "gap {}", p.gap);
        }
    }
}

//! Segment-to-segment (mortar-type) contact pairs: the gap and the traction integrated over the
//! master contour's segments.
//!
//! One constraint per node `k` of the master contour (the integration side; the same nodes as
//! node-to-segment, so `λ_k` stays the normal force on master node `k`). With `N_j(s)` the
//! master edge's shape functions (linear or quadratic), `φ_k(s)` the multiplier basis of node
//! `k` (below), `π(s)` the closest point of the slave curve to the master point `x(s)`, and
//! `n(s)`, `t(s)` the slave curve's unit normal (out of the slave body) and tangent `(−n_y, n_x)`
//! at `π(s)`:
//!
//! ```text
//! w_k  = ∫_Γ φ_k(s) ds                                         (tributary length)
//! g̃_k  = (1/w_k) ∫_Γ φ_k(s) [g0(s) + n(s)·(u_master(s) − u_slave(π(s)))] ds ≥ 0
//! g0(s) = (x(s) − π(s)) · n(s)                                 (geometric gap; |x(s) − π(s)|
//!                                     off the slave curve's ends and behind a curve of the
//!                                     master's own body: crate::side)
//! (B_N u)_k = Σ_j M_kj·u_j − Σ_l D_kl·u_l,
//!   M_kj = (1/w_k) ∫ φ_k N_j n ds   (master nodes j),   D_kl = (1/w_k) ∫ φ_k N_l(π(s)) n ds   (slave nodes l)
//! (B_T u)_k likewise with t(s)
//! ```
//!
//! The integral runs segment by segment over the master contour, each segment split at the
//! points whose projection is a slave segment's end (where the slave normal line through that
//! end crosses the master segment) and at a Line3 edge's mid node, so that the integrand is
//! smooth on every sub-interval; each sub-interval takes 5-point Gauss (exact to degree 9: on
//! straight interfaces with uniformly placed mid nodes the integrand `φ_k N_j N_l(π)` has degree
//! ≤ 5, so the rows are exact).
//!
//! Multiplier basis: on Line2 edges `φ_k = N_k`. On Line3 edges `φ_k` is the piecewise-linear hat
//! on the two halves of the edge (`φ_start = max(−ξ, 0)`, `φ_end = max(ξ, 0)`, `φ_mid = 1 − |ξ|`;
//! `∫ φ_corner = L/4`, `∫ φ_mid = L/2` per edge): one multiplier per node as with the Lagrange
//! functions, but `λ_k ≥ 0` is then exactly `p(s) ≥ 0` along the whole curve (a quadratic field
//! can dip below zero between non-negative nodal values, and does so at the contact edge). On
//! the coarsest Hertz mesh the profile error is 0.98 % of p0 with the hats and 2.43 % with the
//! Lagrange `φ_k = N_k` (admissible too, `∫ N_corner = L/6 > 0`), and the half-width converges
//! monotonically with the hats only; both pass the patch test (docs/verification.md).
//!
//! The force on the bodies is `B_Nᵀ λ`: the traction field `p(s) = Σ_k (λ_k / w_k) φ_k(s)` on the
//! master side, with its consistent nodal forces `Σ_k (λ_k/w_k) ∫ φ_k N_j ds` on the master nodes
//! and the same field carried by the slave's shape functions to the slave nodes. So `λ_k` is a
//! force, the pressure is recovered on the master side as `p_k = λ_k / w_k` (the nodal value of
//! the pressure field), and a uniform pressure `p` is reproduced exactly: `λ_k = p w_k` gives,
//! as `Σ_k φ_k = 1`, the consistent nodal forces `p ∫ N_j ds` on both sides (the patch test).
//!
//! # References
//! Puso & Laursen (2004), CMAME 193, "A mortar segment-to-segment contact method for large
//! deformation solid mechanics"; Popp, Gee & Wall (2009), IJNME 79 (the weighted gap);
//! Wohlmuth (2000), SINUM 38 (the mortar method); Taylor & Papadopoulos (1991), in Wriggers &
//! Wagner (eds.), Computational Methods in Nonlinear Mechanics (the contact patch test).

use contact2d_element::gauss_legendre;
use contact2d_fem::Model;
use contact2d_mesh::{Contour, ContourEdge, NodeId};
use rayon::prelude::*;

use crate::error::ContactError;
use crate::pairing::{ContactPair, EdgeBoxes, IntegratedRows, RowCoefficient, edge_shape, pair_contours_with};
use crate::side::{Projection, SlaveBody};

/// One quadrature point of a master edge: what [`pair_segments`] adds to its nodes' integrals.
struct EdgeSample {
    /// Gauss weight, the sub-interval's half length in ξ, and `ds/dξ`.
    weight: [f64; 3],
    /// The multiplier basis and the master edge's shape functions at the point.
    phi: [f64; 3],
    n_master: [f64; 3],
    /// The slave normal and geometric gap at the closest point.
    normal: [f64; 2],
    g0: f64,
    /// The slave edge of the closest point and its shape functions there.
    slave_edge: usize,
    n_slave: [f64; 3],
}

/// The per-node sums of the integrals, before the division by `w_k`.
#[derive(Debug, Clone, Default)]
struct NodeIntegrals {
    weight: f64,
    gap: f64,
    normal: [f64; 2],
    rows: IntegratedRows,
    slave_weights: Vec<(NodeId, f64)>,
}

/// Builds one segment-to-segment pair per node of `master` against the curve `slave` (see the
/// module docs). The pairs keep node-to-segment's node data (the closest slave point of the
/// master node, its arc lengths, γ) and replace the gap, the normal and tangent (the
/// `φ_k`-weighted means), the tributary length and the slave weights (`(1/w_k) ∫ φ_k N_l(π) ds`,
/// summing to one) by the integrated ones; [`ContactPair::integrated`] holds the rows.
///
/// # Errors
/// As [`pair_contours`](crate::pairing::pair_contours), and [`ContactError::Pairing`] if a master node's tributary length is
/// not positive.
pub fn pair_segments(
    model: &Model,
    master: &Contour,
    slave: &Contour,
    slave_region: &str,
) -> Result<Vec<ContactPair>, ContactError> {
    let err = |reason: String| ContactError::Pairing { master: master.name.clone(), slave: slave.name.clone(), reason };
    let body = SlaveBody::new(model, slave_region, slave).map_err(err)?;
    let boxes = EdgeBoxes::of(slave);
    let kinematics = model.pairing_kinematics();
    let mut pairs = pair_contours_with(model, master, slave, &body, &boxes);
    let (gx, gw) = gauss_legendre(5).map_err(|e| err(e.to_string()))?;
    let points = &model.mesh.points;
    let mut sums = vec![NodeIntegrals::default(); master.nodes.len()];
    // The quadrature points of each master edge, sampled in parallel (each edge's closest
    // points and gaps are independent), then summed edge by edge in contour order: the same
    // additions in the same order as one sequential pass, so the same bits on any number of
    // threads.
    let sampled: Vec<Vec<EdgeSample>> = master
        .edges
        .par_iter()
        .map(|edge| {
            let local = contour_indices(master, edge);
            let count = if edge.quadratic { 3 } else { 2 };
            let reach = local[..count].iter().map(|&k| pairs[k].gap.abs()).fold(0.0, f64::max);
            let cuts = breakpoints(master, edge, slave, reach);
            let mut samples = Vec::with_capacity(gx.len() * (cuts.len() - 1));
            for span in cuts.windows(2) {
                let (mid, half) = (0.5 * (span[0] + span[1]), 0.5 * (span[1] - span[0]));
                for (g, &wg) in gx.iter().zip(&gw) {
                    let xi = mid + half * g;
                    let (x, _, ds) = master.edge_frame(edge, xi);
                    // × 1.0 exactly in the plane; 2πr for a body of revolution.
                    let ds = ds * kinematics.pairing_measure(x);
                    let (e, eta) = boxes.closest_point_unsnapped(slave, points, x);
                    let slave_edge = &slave.edges[e];
                    let (y, t, _) = slave.edge_frame(slave_edge, eta);
                    let projection = Projection { edge: e, xi: eta, point: y, tangent: t, own: &edge.nodes[..count] };
                    let (normal, g0) = body.normal_and_gap(slave, x, &projection);
                    samples.push(EdgeSample {
                        weight: [wg, half, ds],
                        phi: multiplier_shape(edge.quadratic, xi),
                        n_master: edge_shape(edge.quadratic, xi),
                        normal,
                        g0,
                        slave_edge: e,
                        n_slave: edge_shape(slave_edge.quadratic, eta),
                    });
                }
            }
            samples
        })
        .collect();
    for (edge, samples) in master.edges.iter().zip(&sampled) {
        let local = contour_indices(master, edge);
        let count = if edge.quadratic { 3 } else { 2 };
        for sample in samples {
            let [wg, half, ds] = sample.weight;
            let (normal, g0, phi) = (sample.normal, sample.g0, sample.phi);
            let tangent = [-normal[1], normal[0]];
            let slave_edge = &slave.edges[sample.slave_edge];
            let slave_count = if slave_edge.quadratic { 3 } else { 2 };
            for a in 0..count {
                let f = wg * half * ds * phi[a];
                let s = &mut sums[local[a]];
                s.weight += f;
                s.gap += f * g0;
                s.normal = [s.normal[0] + f * normal[0], s.normal[1] + f * normal[1]];
                for (node, shape) in edge.nodes.iter().zip(sample.n_master).take(count) {
                    add(&mut s.rows.master, *node, f * shape, normal, tangent);
                }
                for (node, shape) in slave_edge.nodes.iter().zip(sample.n_slave).take(slave_count) {
                    add(&mut s.rows.slave, *node, -f * shape, normal, tangent);
                    add_weight(&mut s.slave_weights, *node, f * shape);
                }
            }
        }
    }
    for (k, (pair, s)) in pairs.iter_mut().zip(sums).enumerate() {
        if s.weight.is_nan() || s.weight <= 0.0 {
            return Err(err(format!("master node {k} has tributary length {} (not positive)", s.weight)));
        }
        let w = s.weight;
        let scale = |c: RowCoefficient| RowCoefficient {
            node: c.node,
            normal: [c.normal[0] / w, c.normal[1] / w],
            tangent: [c.tangent[0] / w, c.tangent[1] / w],
        };
        let point_tangent = pair.tangent;
        let length = s.normal[0].hypot(s.normal[1]);
        if length > 0.0 {
            pair.normal = [s.normal[0] / length, s.normal[1] / length];
            pair.tangent = [-pair.normal[1], pair.normal[0]];
        }
        pair.gap = s.gap / w;
        pair.weight = w;
        let point_slave = std::mem::take(&mut pair.slave);
        pair.slave = s.slave_weights.into_iter().map(|(n, v)| (n, v / w)).filter(|(_, v)| v.abs() > 1e-14).collect();
        pair.integrated = Some(IntegratedRows {
            master: s.rows.master.into_iter().map(scale).collect(),
            slave: s.rows.slave.into_iter().map(scale).collect(),
            point_slave,
            point_tangent,
        });
    }
    Ok(pairs)
}

/// The multiplier basis `φ_a(ξ)` in the order of [`ContourEdge::nodes`] (start, end, mid): the
/// edge's shape functions on Line2, the piecewise-linear hats on the halves `[-1, 0]`, `[0, 1]`
/// of a Line3 edge (see the module docs).
fn multiplier_shape(quadratic: bool, xi: f64) -> [f64; 3] {
    if quadratic { [(-xi).max(0.0), xi.max(0.0), 1.0 - xi.abs()] } else { edge_shape(quadratic, xi) }
}

/// Indices into `contour.nodes` of the edge's start, end and mid node (the order of
/// [`ContourEdge::nodes`]).
fn contour_indices(contour: &Contour, edge: &ContourEdge) -> [usize; 3] {
    let (start, mid, end) = if edge.quadratic {
        (edge.first, edge.first + 1, edge.first + 2)
    } else {
        (edge.first, edge.first, edge.first + 1)
    };
    let end = if contour.closed && end == contour.nodes.len() { 0 } else { end };
    [start, end, mid]
}

/// Adds `f · (n, t)` to `node`'s coefficients (appended on first appearance).
fn add(list: &mut Vec<RowCoefficient>, node: NodeId, f: f64, n: [f64; 2], t: [f64; 2]) {
    let at = match list.iter().position(|c| c.node == node) {
        Some(at) => at,
        None => {
            list.push(RowCoefficient { node, normal: [0.0; 2], tangent: [0.0; 2] });
            list.len() - 1
        }
    };
    let c = &mut list[at];
    c.normal = [c.normal[0] + f * n[0], c.normal[1] + f * n[1]];
    c.tangent = [c.tangent[0] + f * t[0], c.tangent[1] + f * t[1]];
}

fn add_weight(list: &mut Vec<(NodeId, f64)>, node: NodeId, f: f64) {
    match list.iter_mut().find(|(n, _)| *n == node) {
        Some((_, v)) => *v += f,
        None => list.push((node, f)),
    }
}

/// The master edge's reference coordinates `-1 = ξ_0 < … < ξ_m = 1` split where the normal line
/// of a slave edge through one of its ends crosses the edge (where the projection `π` passes a
/// slave segment end): `(x(ξ) − v) · t_E(v) = 0`, a quadratic in ξ. Crossings farther than the two
/// edges' lengths plus `reach` (the largest gap of the edge's nodes) from `v` are not projections
/// and are skipped; a spurious split would only add quadrature points.
fn breakpoints(master: &Contour, edge: &ContourEdge, slave: &Contour, reach: f64) -> Vec<f64> {
    let (c0, c1, c2) = edge_polynomial(master, edge);
    let master_length = master.edge_length(edge, 1.0);
    let mut cuts = if edge.quadratic { vec![-1.0, 0.0, 1.0] } else { vec![-1.0, 1.0] };
    for slave_edge in &slave.edges {
        let slave_length = slave.edge_length(slave_edge, 1.0);
        let limit = 2.0 * (master_length + slave_length) + reach;
        for end in [-1.0, 1.0] {
            let (v, t, _) = slave.edge_frame(slave_edge, end);
            let dot = |p: [f64; 2]| p[0] * t[0] + p[1] * t[1];
            let (a, b, c) = (dot(c2), dot(c1), dot([c0[0] - v[0], c0[1] - v[1]]));
            for xi in quadratic_roots(a, b, c) {
                if xi > -1.0 + 1e-12 && xi < 1.0 - 1e-12 {
                    let x = [c0[0] + xi * (c1[0] + xi * c2[0]), c0[1] + xi * (c1[1] + xi * c2[1])];
                    if (x[0] - v[0]).hypot(x[1] - v[1]) <= limit {
                        cuts.push(xi);
                    }
                }
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup_by(|b, a| (*b - *a).abs() < 1e-12);
    if let Some(last) = cuts.last_mut() {
        *last = 1.0;
    }
    cuts
}

/// `x(ξ) = c0 + c1 ξ + c2 ξ²` of an edge (Line2: `c2 = 0`).
fn edge_polynomial(contour: &Contour, edge: &ContourEdge) -> ([f64; 2], [f64; 2], [f64; 2]) {
    let (x0, _) = contour.edge_point(edge, -1.0);
    let (x1, _) = contour.edge_point(edge, 1.0);
    let (xm, _) = contour.edge_point(edge, 0.0);
    let c1 = [0.5 * (x1[0] - x0[0]), 0.5 * (x1[1] - x0[1])];
    if edge.quadratic {
        (xm, c1, [0.5 * (x0[0] + x1[0]) - xm[0], 0.5 * (x0[1] + x1[1]) - xm[1]])
    } else {
        (xm, c1, [0.0, 0.0])
    }
}

/// Real roots of `a ξ² + b ξ + c = 0` (the linear root where `a` is negligible), by the
/// cancellation-free formula.
fn quadratic_roots(a: f64, b: f64, c: f64) -> Vec<f64> {
    if a.abs() <= 1e-14 * b.abs() || a == 0.0 {
        return if b != 0.0 { vec![-c / b] } else { vec![] };
    }
    let d = b * b - 4.0 * a * c;
    if d < 0.0 {
        return vec![];
    }
    let q = -0.5 * (b + b.signum() * d.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    vec![q / a, c / q]
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::test_fixtures::facing_blocks;

    use contact2d_mesh::CellKind;

    /// Two blocks facing each other across a straight gap `g`, 5 and 7 cells along x.
    fn two_blocks(kind: CellKind, g: f64) -> (Model, Contour, Contour) {
        facing_blocks(kind, [0.0, 1.0], g, 5, 7, 1)
    }

    #[test]
    fn straight_gap_weights_and_rows_are_exact() {
        // A straight gap g: every weighted gap is g, the tributary lengths sum to the length 1,
        // each pair's slave weights sum to one (Σ N_l = 1), and a rigid translation u = c of both
        // bodies leaves every row at zero (Σ_j M_kj = Σ_l D_kl = n). Round-off: 1e-13.
        for kind in [CellKind::Quad4, CellKind::Quad9] {
            let (model, master, slave) = two_blocks(kind, 0.1);
            let pairs = pair_segments(&model, &master, &slave, "a_domain").unwrap();
            assert_eq!(pairs.len(), master.nodes.len());
            let total: f64 = pairs.iter().map(|p| p.weight).sum();
            assert!((total - 1.0).abs() < 1e-13, "{kind:?}: Σ w = {total}");
            for p in &pairs {
                assert!((p.gap - 0.1).abs() < 1e-13, "{kind:?}: gap {}", p.gap);
                assert!((p.normal[1] - 1.0).abs() < 1e-13);
                let sum: f64 = p.slave.iter().map(|(_, w)| w).sum();
                assert!((sum - 1.0).abs() < 1e-13, "{kind:?}: Σ slave weights {sum}");
                let rows = p.integrated.as_ref().unwrap();
                let side =
                    |c: &[RowCoefficient]| c.iter().fold([0.0, 0.0], |a, c| [a[0] + c.normal[0], a[1] + c.normal[1]]);
                let (m, d) = (side(&rows.master), side(&rows.slave));
                assert!((m[1] - 1.0).abs() < 1e-13 && (m[1] + d[1]).abs() < 1e-13 && m[0].abs() < 1e-13);
            }
        }
    }

    #[test]
    fn line3_edges_split_at_the_mid_node_and_the_slave_ends() {
        let (_, master, slave) = two_blocks(CellKind::Quad9, 0.0);
        let cuts = breakpoints(&master, &master.edges[0], &slave, 0.0);
        // Master edge [0, 1/7] against slave edges of length 1/5: the mid node and no slave end.
        assert_eq!(cuts, vec![-1.0, 0.0, 1.0]);
        let cuts = breakpoints(&master, &master.edges[1], &slave, 0.0);
        // Master edge [1/7, 2/7] holds the slave end x = 1/5 at ξ = 2·(1/5 − 1/7)·7 − 1 = −0.2.
        assert_eq!(cuts.len(), 4);
        assert!((cuts[1] + 0.2).abs() < 1e-12, "{cuts:?}");
    }

    #[test]
    fn quadratic_roots_are_exact_on_known_polynomials() {
        let mut r = quadratic_roots(1.0, -0.5, -0.5);
        r.sort_by(f64::total_cmp);
        assert_eq!(r, vec![-0.5, 1.0]);
        assert_eq!(quadratic_roots(0.0, 2.0, -1.0), vec![0.5]);
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
        assert!(quadratic_roots(0.0, 0.0, 1.0).is_empty());
    }
}

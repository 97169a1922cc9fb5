//! Local directions on a curve: the unit normal and tangent at each node of a 1D physical group,
//! the frame of a support given as normal and tangential components (`un`, `ut`) node by node.
//!
//! ```text
//!   n_e(ξ) = (t_y, −t_x) of edge e at the node (its end, start or mid: ξ = 1, −1, 0)
//!   n_a    = (n_e + n_e') / |n_e + n_e'|    at a node shared by edges e, e'   (an end: n_e)
//!   n_a · (x_c − x_e) < 0                   n points out of the body (x_c: centroid of the
//!                                           2D cell on the curve's first edge, x_e its midpoint)
//!   t_a    = e3 × n_a = (−n_y, n_x)         the body is on the left going along t
//!   u = un n + ut t,    un = n · u,  ut = t · u
//! ```
//!
//! A node where the adjacent normals cancel (`|n_e + n_e'| < 1e-8`: a cusp, the curve folding back
//! on itself) has no normal and is an error; so is a group that is not a curve (points or cells).

use crate::contour::Contour;
use crate::error::MeshError;
use crate::mesh::{Mesh, NodeId};

/// The smallest `|n_e + n_e'|` (of two unit normals) that still defines a direction: below it the
/// two edges fold back on each other within 1e-8 rad.
const CUSP: f64 = 1e-8;

/// Unit normal (out of the body) and tangent per node of a curve, in the curve's node order.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeFrames {
    /// The curve's nodes (each once; mid nodes of quadratic edges included).
    pub nodes: Vec<NodeId>,
    /// Unit normal per node, pointing out of the body that owns the curve's first edge.
    pub normals: Vec<[f64; 2]>,
    /// Unit tangent per node, `e3 × n` (the body is on its left).
    pub tangents: Vec<[f64; 2]>,
}

/// The local frames of the 1D physical group `name`.
///
/// # Errors
/// [`MeshError::UnknownPhysicalGroup`]; [`MeshError::Geometry`] naming the group if it is not a
/// curve (not 1D, branching, several chains), if no 2D cell borders its first edge (the outward
/// side is then undefined), or at a cusp, naming the node.
pub fn node_frames(mesh: &Mesh, name: &str) -> Result<NodeFrames, MeshError> {
    let group = mesh.group(name)?;
    if group.dim != 1 {
        return Err(MeshError::Geometry(format!(
            "local directions (un, ut) on \"{name}\": the group has dimension {}; un / ut need a curve (a 1D group \
             of edges)",
            group.dim
        )));
    }
    let contour = Contour::from_group(mesh, name)?;
    let count = contour.nodes.len();
    let mut sums = vec![[0.0f64; 2]; count];
    let normal = |t: [f64; 2]| [t[1], -t[0]];
    for edge in &contour.edges {
        let step = if edge.quadratic { 2 } else { 1 };
        let end = (edge.first + step) % count;
        for (idx, xi) in [(edge.first, -1.0), (end, 1.0)] {
            let n = normal(contour.edge_frame(edge, xi).1);
            sums[idx] = [sums[idx][0] + n[0], sums[idx][1] + n[1]];
        }
        if edge.quadratic {
            sums[edge.first + 1] = normal(contour.edge_frame(edge, 0.0).1);
        }
    }
    let mut normals = Vec::with_capacity(count);
    for (a, s) in sums.iter().enumerate() {
        let len = s[0].hypot(s[1]);
        if len < CUSP {
            let p = mesh.points[contour.nodes[a].0];
            return Err(MeshError::Geometry(format!(
                "local directions (un, ut) on \"{name}\": the normal at node index {} ({}, {}) is undefined (the \
                 adjacent edges fold back: a cusp)",
                contour.nodes[a].0, p[0], p[1]
            )));
        }
        normals.push([s[0] / len, s[1] / len]);
    }
    if inward(mesh, &contour, &normals).ok_or_else(|| {
        MeshError::Geometry(format!("local directions (un, ut) on \"{name}\": no 2D cell borders the curve"))
    })? {
        normals.iter_mut().for_each(|n| *n = [-n[0], -n[1]]);
    }
    let tangents = normals.iter().map(|n| [-n[1], n[0]]).collect();
    Ok(NodeFrames { nodes: contour.nodes.clone(), normals, tangents })
}

/// Whether the normals point into the 2D cell on the first edge (`None` if there is none).
fn inward(mesh: &Mesh, contour: &Contour, normals: &[[f64; 2]]) -> Option<bool> {
    let edge = contour.edges.first()?;
    let (a, b) = (edge.nodes[0], edge.nodes[1]);
    let cell = mesh
        .blocks
        .iter()
        .filter(|block| block.kind.dim() == 2)
        .flat_map(|block| block.cells())
        .find(|cell| cell.contains(&a) && cell.contains(&b))?;
    let centroid = cell.iter().fold([0.0, 0.0], |c, n| {
        let p = mesh.points[n.0];
        [c[0] + p[0] / cell.len() as f64, c[1] + p[1] / cell.len() as f64]
    });
    let (pa, pb) = (mesh.points[a.0], mesh.points[b.0]);
    let mid = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])];
    let n = [normals[edge.first][0] + normals[edge.first + 1][0], normals[edge.first][1] + normals[edge.first + 1][1]];
    Some(n[0] * (centroid[0] - mid[0]) + n[1] * (centroid[1] - mid[1]) > 0.0)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::generate::{annulus_sector, rectangle};
    use crate::mesh::{CellBlock, CellKind, PhysicalGroup};

    /// On the arcs of an annulus sector the normal is radial (independent truth: the circle's
    /// normal is x/|x|): outward on the outer arc, inward (towards the centre) on the inner one.
    /// The nodes lie on the circle and the averaged chord normals of equal chords are the bisector,
    /// i.e. exactly radial up to round-off (1e-12); at the ends the chord's normal is off by half
    /// the chord angle, (π/2)/8/2 ≈ 0.098 rad, so only interior nodes are compared.
    #[test]
    fn the_normal_on_an_arc_is_radial_and_points_out_of_the_body() {
        for kind in [CellKind::Quad4, CellKind::Quad8] {
            let mesh = annulus_sector(kind, [1.0, 2.0], [0.0, std::f64::consts::FRAC_PI_2], 3, 8);
            for (group, sign) in [("outer", 1.0), ("inner", -1.0)] {
                let f = node_frames(&mesh, group).unwrap();
                assert_eq!(f.nodes.len(), if kind == CellKind::Quad4 { 9 } else { 17 });
                for (k, (node, n)) in f.nodes.iter().zip(&f.normals).enumerate() {
                    let p = mesh.points[node.0];
                    let r = p[0].hypot(p[1]);
                    let radial = [sign * p[0] / r, sign * p[1] / r];
                    let interior = k > 0 && k + 1 < f.nodes.len();
                    let tol = if interior || kind == CellKind::Quad8 { 1e-12 } else { 0.1 };
                    if kind == CellKind::Quad4 || interior {
                        assert!((n[0] - radial[0]).abs() < tol && (n[1] - radial[1]).abs() < tol, "{group} {k}: {n:?}");
                    }
                }
                for (n, t) in f.normals.iter().zip(&f.tangents) {
                    assert!((n[0] * t[0] + n[1] * t[1]).abs() < 1e-15);
                    assert!((n[0] * t[1] - n[1] * t[0] - 1.0).abs() < 1e-15, "t = e3 × n");
                }
            }
        }
    }

    /// The straight cut edges of a 30° sector: the normal is the edge's, out of the body:
    /// (sin 0, −cos 0) = (0, −1) on θ = 0 and (−sin 30°, cos 30°) on θ = 30°.
    #[test]
    fn the_normal_of_a_straight_rotated_edge_is_the_edges_outward_normal() {
        let phi = std::f64::consts::PI / 6.0;
        let mesh = annulus_sector(CellKind::Tri3, [1.0, 2.0], [0.0, phi], 4, 3);
        for (group, expected) in [("start", [0.0, -1.0]), ("end", [-phi.sin(), phi.cos()])] {
            let f = node_frames(&mesh, group).unwrap();
            for n in &f.normals {
                assert!((n[0] - expected[0]).abs() < 1e-14 && (n[1] - expected[1]).abs() < 1e-14, "{group}: {n:?}");
            }
        }
    }

    /// A cell group and a node group are not curves; a V folded back on itself has no normal at
    /// its tip.
    #[test]
    fn a_group_that_is_not_a_curve_or_a_cusp_is_an_error_naming_it() {
        let mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
        let e = node_frames(&mesh, "domain").unwrap_err().to_string();
        assert!(e.contains("\"domain\"") && e.contains("dimension 2"), "{e}");
        let mut mesh = rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2);
        mesh.groups.push(PhysicalGroup { name: "corner".into(), dim: 0, tag: 90 });
        mesh.blocks.push(CellBlock {
            kind: CellKind::Point1,
            entity_dim: 0,
            entity_tag: 90,
            physical_tags: vec![90],
            nodes: vec![NodeId(0)],
            element_tags: vec![],
        });
        let e = node_frames(&mesh, "corner").unwrap_err().to_string();
        assert!(e.contains("\"corner\"") && e.contains("need a curve"), "{e}");
        // A cusp: 0 → 1 → 2 with node 2 back on node 0's side along the same line.
        let mut mesh = Mesh { points: vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.0]], ..Mesh::default() };
        mesh.groups.push(PhysicalGroup { name: "fold".into(), dim: 1, tag: 7 });
        mesh.blocks.push(CellBlock {
            kind: CellKind::Line2,
            entity_dim: 1,
            entity_tag: 7,
            physical_tags: vec![7],
            nodes: vec![NodeId(0), NodeId(1), NodeId(1), NodeId(2)],
            element_tags: vec![],
        });
        let e = node_frames(&mesh, "fold").unwrap_err().to_string();
        assert!(e.contains("\"fold\"") && e.contains("cusp") && e.contains("node index 1"), "{e}");
    }
}

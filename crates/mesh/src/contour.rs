//! Contours: ordered node chains along a named 1D physical group, with arc length, tangents and
//! normals from the isoparametric edge geometry.
//!
//! ```text
//!   x(ξ) = Σ_a N_a(ξ) x_a        Line2: N = ((1-ξ)/2, (1+ξ)/2)
//!                                Line3: N = (ξ(ξ-1)/2, ξ(ξ+1)/2, 1-ξ²)   (ends first, mid last)
//!   s(ξ) = ∫_{-1}^{ξ} |dx/dξ'| dξ'    (5-point Gauss; exact for Line2, ~1e-10 for curved Line3)
//!   t = (dx/dξ)/|dx/dξ|,   n = (t_y, -t_x)   (n points to the right of the direction of travel)
//! ```
//!
//! The chain is oriented by the cells where they agree (the first node is an end that starts its
//! edge); [`Contour::reversed`] flips it. For a quadratic edge the tangent is that of the
//! parabola through its three nodes, which is exact wherever the mesh's edge is.

use crate::error::MeshError;
use crate::mesh::{CellKind, Mesh, NodeId};

/// The length of a line cell (Line2 end to end; Line3 by 5-point Gauss on `|dx/dξ|`, exact to
/// round-off for straight and parabolic edges) from its nodes in Gmsh order (ends, then mid);
/// 0 for other kinds.
pub fn line_cell_length(kind: CellKind, points: &[[f64; 2]]) -> f64 {
    match (kind, points) {
        (CellKind::Line2, [a, b, ..]) => (b[0] - a[0]).hypot(b[1] - a[1]),
        (CellKind::Line3, [a, b, m, ..]) => GAUSS5
            .iter()
            .map(|(xi, w)| {
                // dN/dξ of (ξ(ξ−1)/2, ξ(ξ+1)/2, 1 − ξ²).
                let d = [xi - 0.5, xi + 0.5, -2.0 * xi];
                let dx = d[0] * a[0] + d[1] * b[0] + d[2] * m[0];
                let dy = d[0] * a[1] + d[1] * b[1] + d[2] * m[1];
                w * dx.hypot(dy)
            })
            .sum(),
        _ => 0.0,
    }
}

/// One edge of a contour, traversed in the contour's direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContourEdge {
    /// Start, end and (for Line3) mid node, in the contour's direction.
    pub nodes: [NodeId; 3],
    /// Whether the edge is quadratic (Line3).
    pub quadratic: bool,
    /// Index into [`Contour::nodes`] of the edge's start node.
    pub first: usize,
}

/// An ordered chain of line cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// Name of the physical group.
    pub name: String,
    /// Nodes in order along the chain (mid nodes of quadratic edges between their ends).
    pub nodes: Vec<NodeId>,
    /// Arc length from the first node, per entry of `nodes`.
    pub arc_length: Vec<f64>,
    /// Unit tangent (direction of travel) per node; at a node between two edges, the normalised mean.
    pub tangents: Vec<[f64; 2]>,
    /// Edges in order.
    pub edges: Vec<ContourEdge>,
    /// Whether the chain closes on itself.
    pub closed: bool,
    points: Vec<[f64; 2]>,
}

/// Five-point Gauss–Legendre rule on [−1, 1] as (point, weight) pairs: exact for polynomials up
/// to degree 9 (the arc lengths and tributary weights of quadratic edges; shared with the
/// contact crate's weights and the verification gallery's integrals).
pub const GAUSS5: [(f64, f64); 5] = [
    (-0.906_179_845_938_664, 0.236_926_885_056_189),
    (-0.538_469_310_105_683, 0.478_628_670_499_366),
    (0.0, 0.568_888_888_888_889),
    (0.538_469_310_105_683, 0.478_628_670_499_366),
    (0.906_179_845_938_664, 0.236_926_885_056_189),
];

impl Contour {
    /// The node coordinates the contour's geometry ([`Contour::edge_point`]) is evaluated on.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Builds the contour of the 1D physical group `name` of `mesh`.
    ///
    /// # Errors
    /// [`MeshError::UnknownPhysicalGroup`]; [`MeshError::Geometry`] if the group is not 1D, is
    /// empty, mixes linear and quadratic lines, branches, or falls apart into several chains.
    pub fn from_group(mesh: &Mesh, name: &str) -> Result<Contour, MeshError> {
        let group = mesh.group(name)?;
        if group.dim != 1 {
            return Err(MeshError::Geometry(format!(
                "contour \"{name}\": physical group has dimension {}, not 1",
                group.dim
            )));
        }
        let mut raw: Vec<([NodeId; 3], bool)> = vec![];
        for block in mesh.blocks_in_group(name)? {
            let quadratic = match block.kind {
                CellKind::Line2 => false,
                CellKind::Line3 => true,
                other => {
                    return Err(MeshError::Geometry(format!(
                        "contour \"{name}\": cell kind {} is not a line",
                        other.name()
                    )));
                }
            };
            for cell in block.cells() {
                let mid = if quadratic { cell[2] } else { cell[0] };
                raw.push(([cell[0], cell[1], mid], quadratic));
            }
        }
        if raw.is_empty() {
            return Err(MeshError::Geometry(format!("contour \"{name}\" has no line cells")));
        }
        if raw.iter().any(|e| e.1 != raw[0].1) {
            return Err(MeshError::Geometry(format!("contour \"{name}\" mixes linear and quadratic lines")));
        }
        let ordered = order_chain(name, &raw)?;
        Ok(Contour::from_ordered(mesh, name, &ordered, raw[0].1))
    }

    fn from_ordered(mesh: &Mesh, name: &str, ordered: &[[NodeId; 3]], quadratic: bool) -> Contour {
        let closed = ordered.first().map(|e| e[0]) == ordered.last().map(|e| e[1]);
        let points = mesh.points.clone();
        let mut c = Contour {
            name: name.to_string(),
            nodes: vec![],
            arc_length: vec![],
            tangents: vec![],
            edges: vec![],
            closed,
            points,
        };
        let mut s = 0.0;
        for (k, e) in ordered.iter().enumerate() {
            let edge = ContourEdge { nodes: *e, quadratic, first: c.nodes.len().saturating_sub(1) };
            if k == 0 {
                c.push_node(e[0], s, c.edge_frame(&edge, -1.0).1);
            }
            if quadratic {
                c.push_node(e[2], s + c.edge_length(&edge, 0.0), c.edge_frame(&edge, 0.0).1);
            }
            s += c.edge_length(&edge, 1.0);
            let t_end = c.edge_frame(&edge, 1.0).1;
            let is_closing = closed && k + 1 == ordered.len();
            if !is_closing {
                c.push_node(e[1], s, t_end);
            }
            // A node between two edges: average the tangents of both sides.
            if k + 1 < ordered.len() || is_closing {
                let next = ContourEdge { nodes: ordered[(k + 1) % ordered.len()], quadratic, first: 0 };
                let t_next = c.edge_frame(&next, -1.0).1;
                let idx = if is_closing { 0 } else { c.nodes.len() - 1 };
                let m = [t_end[0] + t_next[0], t_end[1] + t_next[1]];
                let len = m[0].hypot(m[1]);
                if len > 0.0 {
                    c.tangents[idx] = [m[0] / len, m[1] / len];
                }
            }
            c.edges.push(edge);
        }
        c
    }

    fn push_node(&mut self, node: NodeId, s: f64, t: [f64; 2]) {
        self.nodes.push(node);
        self.arc_length.push(s);
        self.tangents.push(t);
    }

    /// Position and unit tangent of edge `edge` at `xi ∈ [-1, 1]`, plus `|dx/dξ|`.
    pub fn edge_frame(&self, edge: &ContourEdge, xi: f64) -> ([f64; 2], [f64; 2], f64) {
        let (x, dx) = self.edge_point(edge, xi);
        let len = dx[0].hypot(dx[1]);
        let t = if len > 0.0 { [dx[0] / len, dx[1] / len] } else { [0.0, 0.0] };
        (x, t, len)
    }

    /// Position `x(ξ)` and derivative `dx/dξ` on an edge.
    pub fn edge_point(&self, edge: &ContourEdge, xi: f64) -> ([f64; 2], [f64; 2]) {
        let (n, dn): ([f64; 3], [f64; 3]) = if edge.quadratic {
            ([0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi], [xi - 0.5, xi + 0.5, -2.0 * xi])
        } else {
            ([0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0], [-0.5, 0.5, 0.0])
        };
        let mut x = [0.0; 2];
        let mut dx = [0.0; 2];
        let count = if edge.quadratic { 3 } else { 2 };
        for a in 0..count {
            let p = self.points[edge.nodes[a].0];
            for i in 0..2 {
                x[i] += n[a] * p[i];
                dx[i] += dn[a] * p[i];
            }
        }
        (x, dx)
    }

    /// Arc length along `edge` from its start (ξ = -1) to `xi`.
    pub fn edge_length(&self, edge: &ContourEdge, xi: f64) -> f64 {
        let half = 0.5 * (xi + 1.0);
        GAUSS5
            .iter()
            .map(|&(g, w)| {
                let t = -1.0 + half * (g + 1.0);
                let (_, dx) = self.edge_point(edge, t);
                w * half * dx[0].hypot(dx[1])
            })
            .sum()
    }

    /// Total length of the chain.
    pub fn length(&self) -> f64 {
        let last = self.edges.last().map(|e| self.edge_length(e, 1.0)).unwrap_or(0.0);
        match self.edges.last() {
            Some(e) => self.arc_length[e.first] + last,
            None => 0.0,
        }
    }

    /// Unit normal per node, the tangent turned clockwise: `n = (t_y, -t_x)`.
    pub fn normals(&self) -> Vec<[f64; 2]> {
        self.tangents.iter().map(|t| [t[1], -t[0]]).collect()
    }

    /// Coordinates of the contour's nodes, in order.
    pub fn node_points(&self) -> Vec<[f64; 2]> {
        self.nodes.iter().map(|n| self.points[n.0]).collect()
    }

    /// The same chain traversed the other way.
    pub fn reversed(&self) -> Contour {
        let ordered: Vec<[NodeId; 3]> = self.edges.iter().rev().map(|e| [e.nodes[1], e.nodes[0], e.nodes[2]]).collect();
        let quadratic = self.edges.first().is_some_and(|e| e.quadratic);
        let mesh = Mesh { points: self.points.clone(), ..Mesh::default() };
        Contour::from_ordered(&mesh, &self.name, &ordered, quadratic)
    }
}

/// Orders the edges into one chain, flipping edges where needed.
fn order_chain(name: &str, raw: &[([NodeId; 3], bool)]) -> Result<Vec<[NodeId; 3]>, MeshError> {
    use std::collections::HashMap;
    let mut incident: HashMap<NodeId, Vec<usize>> = HashMap::new();
    for (i, (e, _)) in raw.iter().enumerate() {
        incident.entry(e[0]).or_default().push(i);
        incident.entry(e[1]).or_default().push(i);
    }
    // The smallest branching node, so the message does not depend on the hash order.
    if let Some(node) = incident.iter().filter(|(_, v)| v.len() > 2).map(|(n, _)| *n).min() {
        return Err(MeshError::Geometry(format!("contour \"{name}\" branches at node index {}", node.0)));
    }
    let mut ends: Vec<NodeId> = incident.iter().filter(|(_, v)| v.len() == 1).map(|(n, _)| *n).collect();
    ends.sort();
    // Prefer the end that starts its own edge, so the cells' orientation is kept.
    let start = match ends.as_slice() {
        [] => raw[0].0[0],
        [a, b] => {
            let starts = |n: &NodeId| incident[n].iter().any(|&i| raw[i].0[0] == *n);
            if starts(a) || !starts(b) { *a } else { *b }
        }
        _ => {
            return Err(MeshError::Geometry(format!(
                "contour \"{name}\" is not one connected chain ({} ends)",
                ends.len()
            )));
        }
    };
    let mut used = vec![false; raw.len()];
    let mut ordered = Vec::with_capacity(raw.len());
    let mut current = start;
    while let Some(&i) = incident.get(&current).and_then(|v| v.iter().find(|&&i| !used[i])) {
        used[i] = true;
        let e = raw[i].0;
        let oriented = if e[0] == current { e } else { [e[1], e[0], e[2]] };
        ordered.push(oriented);
        current = oriented[1];
    }
    if ordered.len() != raw.len() {
        return Err(MeshError::Geometry(format!(
            "contour \"{name}\" is not one connected chain: {} of {} edges reached",
            ordered.len(),
            raw.len()
        )));
    }
    Ok(ordered)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use crate::mesh::{CellBlock, PhysicalGroup};

    /// A half circle of radius 1 in `n` quadratic edges, listed out of order and with flipped cells.
    fn half_circle(n: usize) -> Mesh {
        let mut points = vec![];
        for k in 0..=2 * n {
            let phi = std::f64::consts::PI * k as f64 / (2 * n) as f64;
            points.push([phi.cos(), phi.sin()]);
        }
        let mut nodes = vec![];
        for e in (0..n).rev() {
            let (a, m, b) = (2 * e, 2 * e + 1, 2 * e + 2);
            if e % 2 == 0 { nodes.extend([a, b, m]) } else { nodes.extend([b, a, m]) }
        }
        Mesh {
            node_tags: (1..=points.len() as u64).collect(),
            points,
            blocks: vec![CellBlock {
                kind: CellKind::Line3,
                entity_dim: 1,
                entity_tag: 1,
                physical_tags: vec![7],
                nodes: nodes.into_iter().map(NodeId).collect(),
                element_tags: (1..=n as u64).collect(),
            }],
            groups: vec![PhysicalGroup { name: "arc".into(), dim: 1, tag: 7 }],
        }
    }

    #[test]
    fn orders_a_shuffled_half_circle_and_measures_it() {
        let mesh = half_circle(8);
        let c = Contour::from_group(&mesh, "arc").unwrap();
        assert_eq!(c.nodes.len(), 17);
        assert!(!c.closed);
        // Arc length of a piecewise parabola through points of the circle: within 1e-4 of π.
        assert!((c.length() - std::f64::consts::PI).abs() < 1e-4, "{} {:?}", c.length(), c.arc_length);
        let s: Vec<f64> = c.arc_length.clone();
        assert!(s.windows(2).all(|w| w[1] > w[0]));
        // Tangent at every node is perpendicular to the radius to within the parabola's error.
        for (p, t) in c.node_points().iter().zip(&c.tangents) {
            let dot = (p[0] * t[0] + p[1] * t[1]).abs();
            assert!(dot < 2e-3, "{dot}");
        }
        let r = c.reversed();
        assert_eq!(r.nodes.first(), c.nodes.last());
        assert!((r.length() - c.length()).abs() < 1e-12);
    }

    #[test]
    fn errors_name_the_problem() {
        let mut mesh = half_circle(4);
        assert!(matches!(Contour::from_group(&mesh, "nope"), Err(MeshError::UnknownPhysicalGroup(_))));
        // Remove a middle edge: two chains.
        mesh.blocks[0].nodes.drain(3..6);
        mesh.blocks[0].element_tags.pop();
        assert!(matches!(Contour::from_group(&mesh, "arc"), Err(MeshError::Geometry(_))));
    }
}

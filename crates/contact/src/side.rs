//! Which side of the slave body a paired point lies on: the outward normal of the slave curve and
//! the initial gap, both from the geometry of the slave body's cells.
//!
//! ```text
//! n   = ± (t_y, −t_x)          t the slave curve's tangent at the paired point y; the sign makes
//!                              n point out of the slave body: the owning cell's boundary, run in
//!                              its node order, has the body on its left when its signed area is
//!                              positive (exact for any cell shape and any curvature)
//! d   = x − y                  x the master point, y its closest point on the slave curve
//! g0  = d · n                  where x faces the curve (y inside the curve, or d ∥ n at an end),
//!                              in front (g0 ≥ 0) or behind it inside the slave body (g0 < 0: an
//!                              interference)
//! g0  = |d|                    where x lies off an end of an open slave curve outside the slave
//!                              body, or behind a curve of its own body (self-contact: the body's
//!                              material lies between, a valid mesh does not overlap itself)
//! ```
//! The second case is what a node of a longer master curve meets beyond the slave curve's end
//! (a hole's whole arc against the part of a pin's arc that faces it): measured along the end
//! node's normal, `d · n` reads an interference of the curve's radius times `1 − cos θ` that
//! does not exist; the distance to the curve is the true gap.
//!
//! A point is inside the slave body when it lies strictly inside the polygon through the
//! boundary nodes of one of the body's cells (corners and mid nodes in order; a quadratic edge
//! is replaced by its two chords, which is used only off the curve's ends) other than the cells
//! that hold the master node itself.

use std::collections::HashMap;

use contact2d_fem::Model;
use contact2d_mesh::{CellKind, Contour, ContourEdge, NodeId};

/// Tolerance of `|d · t| ≤ TOLERANCE |d|`: the master point faces an end of the slave curve
/// along the end's normal (the closest-point search converges to round-off).
const FACING: f64 = 1e-6;

/// One cell of the slave body: its nodes, its boundary polygon and the polygon's box.
#[derive(Debug, Clone)]
struct Cell {
    nodes: Vec<NodeId>,
    polygon: Vec<[f64; 2]>,
    bounds: [f64; 4],
}

/// The slave body's cells and the outward sign of each slave edge (see the module docs).
#[derive(Debug, Clone)]
pub(crate) struct SlaveBody {
    cells: Vec<Cell>,
    /// The cells that hold each node.
    cells_of: HashMap<NodeId, Vec<usize>>,
    /// Per slave edge: `+1` when `(t_y, −t_x)` points out of the body, `−1` when it points in.
    signs: Vec<f64>,
}

/// Where the master point's closest point lies on the slave curve.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Projection<'a> {
    /// The slave edge's index in the contour.
    pub edge: usize,
    /// Its reference coordinate, clamped to [−1, 1].
    pub xi: f64,
    /// The closest point.
    pub point: [f64; 2],
    /// The unit tangent there (the contour's direction).
    pub tangent: [f64; 2],
    /// The master nodes whose cells do not count as the slave body (the master node; for a
    /// point on a master edge, the edge's nodes).
    pub own: &'a [NodeId],
}

impl SlaveBody {
    /// The cells of `region` and the outward sign of every edge of `slave`.
    ///
    /// # Errors
    /// An unknown region, or a slave edge that bounds no cell of it.
    pub(crate) fn new(model: &Model, region: &str, slave: &Contour) -> Result<SlaveBody, String> {
        let points = &model.mesh.points;
        let blocks = model.mesh.blocks_in_group(region).map_err(|e| e.to_string())?;
        let mut cells = vec![];
        for block in blocks.iter().filter(|b| b.kind.dim() == 2) {
            let order = boundary_order(block.kind);
            for cell in block.cells() {
                let polygon: Vec<[f64; 2]> = order.iter().map(|&a| points[cell[a].0]).collect();
                let bounds = polygon.iter().fold(
                    [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY],
                    |[x0, y0, x1, y1], p| [x0.min(p[0]), y0.min(p[1]), x1.max(p[0]), y1.max(p[1])],
                );
                let nodes = order.iter().map(|&a| cell[a]).collect();
                cells.push(Cell { nodes, polygon, bounds });
            }
        }
        let mut cells_of: HashMap<NodeId, Vec<usize>> = HashMap::new();
        for (i, cell) in cells.iter().enumerate() {
            for n in &cell.nodes {
                cells_of.entry(*n).or_default().push(i);
            }
        }
        let signs = slave
            .edges
            .iter()
            .map(|e| {
                let cell = cells_of
                    .get(&e.nodes[0])
                    .and_then(|cs| cs.iter().find(|&&c| cells[c].nodes.contains(&e.nodes[1])))
                    .ok_or_else(|| {
                        format!("slave edge at node index {} does not bound region \"{region}\"", e.nodes[0].0)
                    })?;
                Ok(outward_sign(&cells[*cell], e))
            })
            .collect::<Result<_, String>>()?;
        Ok(SlaveBody { cells, cells_of, signs })
    }

    /// The unit normal out of the slave body and the initial gap of the master point `x` (see
    /// the module docs).
    pub(crate) fn normal_and_gap(&self, slave: &Contour, x: [f64; 2], p: &Projection) -> ([f64; 2], f64) {
        let t = p.tangent;
        let s = self.signs[p.edge];
        let n = [s * t[1], -s * t[0]];
        let d = [x[0] - p.point[0], x[1] - p.point[1]];
        let along = d[0] * n[0] + d[1] * n[1];
        let distance = d[0].hypot(d[1]);
        let at_end =
            !slave.closed && ((p.edge == 0 && p.xi <= -1.0) || (p.edge + 1 == slave.edges.len() && p.xi >= 1.0));
        let facing = !at_end || (d[0] * t[0] + d[1] * t[1]).abs() <= FACING * distance;
        let own_body = p.own.iter().any(|m| self.cells_of.contains_key(m));
        let gap = if along >= 0.0 {
            if facing { along } else { distance }
        } else if own_body {
            distance
        } else if facing || self.contains(x, p.own) {
            along
        } else {
            distance
        };
        (n, gap)
    }

    /// Whether `x` lies strictly inside a cell that holds none of `own`.
    fn contains(&self, x: [f64; 2], own: &[NodeId]) -> bool {
        self.cells.iter().any(|c| {
            let [x0, y0, x1, y1] = c.bounds;
            x[0] > x0 && x[0] < x1 && x[1] > y0 && x[1] < y1 && !own.iter().any(|m| c.nodes.contains(m)) && {
                winding_inside(&c.polygon, x)
            }
        })
    }
}

/// The cell's local node indices around its boundary (corners and mid nodes in turn, Gmsh order).
fn boundary_order(kind: CellKind) -> &'static [usize] {
    match kind {
        CellKind::Tri3 => &[0, 1, 2],
        CellKind::Tri6 => &[0, 3, 1, 4, 2, 5],
        CellKind::Quad4 => &[0, 1, 2, 3],
        CellKind::Quad8 | CellKind::Quad9 => &[0, 4, 1, 5, 2, 6, 3, 7],
        _ => &[],
    }
}

/// `+1` when the contour runs along the edge the way the cell's boundary does and the cell is
/// counter-clockwise (or both the other way): the body is then on the left of the contour's
/// direction and `(t_y, −t_x)` points out of it; else `−1`.
fn outward_sign(cell: &Cell, edge: &ContourEdge) -> f64 {
    let k = cell.nodes.len();
    let area: f64 = (0..k)
        .map(|i| {
            let (a, b) = (cell.polygon[i], cell.polygon[(i + 1) % k]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum();
    let at = |n: NodeId| cell.nodes.iter().position(|&m| m == n);
    let along = match (at(edge.nodes[0]), at(edge.nodes[1])) {
        // Start to end in the boundary's order: one step (linear) or two (via the mid node).
        (Some(i), Some(j)) => {
            let forward = (j + k - i) % k;
            forward <= k / 2
        }
        _ => true,
    };
    if (area > 0.0) == along { 1.0 } else { -1.0 }
}

/// Whether `x` is inside the closed polygon (non-zero winding number).
fn winding_inside(polygon: &[[f64; 2]], x: [f64; 2]) -> bool {
    let k = polygon.len();
    let mut winding = 0i32;
    for i in 0..k {
        let (a, b) = (polygon[i], polygon[(i + 1) % k]);
        let cross = (b[0] - a[0]) * (x[1] - a[1]) - (x[0] - a[0]) * (b[1] - a[1]);
        if a[1] <= x[1] {
            if b[1] > x[1] && cross > 0.0 {
                winding += 1;
            }
        } else if b[1] <= x[1] && cross < 0.0 {
            winding -= 1;
        }
    }
    winding != 0
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn winding_finds_the_inside_of_both_orientations() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let reversed = [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]];
        for polygon in [&square[..], &reversed[..]] {
            assert!(winding_inside(polygon, [0.5, 0.5]));
            assert!(!winding_inside(polygon, [1.5, 0.5]));
            assert!(!winding_inside(polygon, [0.5, -0.1]));
        }
    }

    #[test]
    fn the_outward_sign_follows_the_cell_and_the_contour_direction() {
        // A counter-clockwise unit square; its bottom edge run left to right has the body on
        // its left, so (t_y, −t_x) = (0, −1) is outward: +1; run right to left: −1.
        let polygon = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let nodes: Vec<NodeId> = (0..4).map(NodeId).collect();
        let cell = Cell { nodes, polygon, bounds: [0.0, 0.0, 1.0, 1.0] };
        let edge = |a, b| ContourEdge { nodes: [NodeId(a), NodeId(b), NodeId(a)], quadratic: false, first: 0 };
        assert_eq!(outward_sign(&cell, &edge(0, 1)), 1.0);
        assert_eq!(outward_sign(&cell, &edge(1, 0)), -1.0);
        // The top edge, run right to left, is in the boundary's direction: +1 ((0, 1) outward).
        assert_eq!(outward_sign(&cell, &edge(2, 3)), 1.0);
        assert_eq!(outward_sign(&cell, &edge(3, 0)), 1.0);
    }
}

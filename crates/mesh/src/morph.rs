//! Moving nodes with the topology unchanged: contour nodes slid along their curve to given
//! positions, neighbouring interior nodes relaxed.
//!
//! ```text
//! 1. every target node n gets its new position (callers give points on the node's own curve)
//! 2. d = displacement of the moved nodes; every other node on any 1D physical group is fixed
//!    (d = 0), as are nodes more than `layers` cells away from a moved node
//! 3. the remaining nodes get d by Gauss–Seidel smoothing in ascending node order, d_i ← mean of d
//!    over the nodes sharing a cell with i (discrete Laplace equation, 200 sweeps or until the
//!    update is < 1e-14 |d|max)
//! ```
//!
//! The move is meant to be small compared with the cells (a fraction of an edge), so that the
//! smoothed field keeps the cells valid. That is checked: every 2D cell with a node that moved
//! must keep its orientation (counter-clockwise stays counter-clockwise, see
//! [`crate::orientation`]); otherwise the move is refused with [`MeshError::MorphInvertsElement`]
//! naming the cell and the moved node, and the mesh is left unchanged. (A cell that was already
//! tangled is not judged here; building a model on the mesh reports it.)

use crate::error::MeshError;
use crate::mesh::{Mesh, NodeId};
use crate::orientation::{Orientation, cell_orientation};

/// Moves `targets` (node, new position) and relaxes the interior nodes within `layers` cells.
///
/// Deterministic: the relaxed nodes are swept in ascending index order and every neighbour sum
/// runs in ascending index order, so the result does not depend on hashing or threads.
///
/// # Errors
/// [`MeshError::Geometry`] for an unknown node, a non-finite position, or a node given twice;
/// [`MeshError::MorphInvertsElement`] if the move would invert a cell (the mesh is then unchanged).
pub fn move_nodes(mesh: &mut Mesh, targets: &[(NodeId, [f64; 2])], layers: usize) -> Result<(), MeshError> {
    let num_nodes = mesh.points.len();
    // field[n]: the displacement of node n (zero for fixed and untouched nodes).
    let mut field = vec![[0.0f64; 2]; num_nodes];
    let mut moved = vec![false; num_nodes];
    for (node, p) in targets {
        let old = mesh
            .points
            .get(node.0)
            .ok_or_else(|| MeshError::Geometry(format!("move_nodes: no node index {}", node.0)))?;
        if !p.iter().all(|v| v.is_finite()) {
            return Err(MeshError::Geometry(format!("move_nodes: non-finite target for node index {}", node.0)));
        }
        if moved[node.0] {
            return Err(MeshError::Geometry(format!("move_nodes: node index {} given twice", node.0)));
        }
        moved[node.0] = true;
        field[node.0] = [p[0] - old[0], p[1] - old[1]];
    }
    let neighbours = node_neighbours(mesh);
    let on_boundary = boundary_nodes(mesh);
    let seeds: Vec<usize> = (0..num_nodes).filter(|&n| moved[n]).collect();
    let near = nodes_within(&neighbours, &seeds, layers);
    let free: Vec<usize> = (0..num_nodes).filter(|&n| near[n] && !moved[n] && !on_boundary[n]).collect();
    let scale = seeds.iter().fold(0.0f64, |a, &n| a.max(field[n][0].hypot(field[n][1])));
    for _ in 0..200 {
        let mut change = 0.0f64;
        for &n in &free {
            let nb = &neighbours[n];
            let mut mean = [0.0; 2];
            for &m in nb {
                mean[0] += field[m][0];
                mean[1] += field[m][1];
            }
            let k = nb.len().max(1) as f64;
            let new = [mean[0] / k, mean[1] / k];
            let old = field[n];
            change = change.max((new[0] - old[0]).hypot(new[1] - old[1]));
            field[n] = new;
        }
        if change <= 1e-14 * scale {
            break;
        }
    }
    let mut moved_points = mesh.points.clone();
    for n in seeds.iter().chain(&free) {
        moved_points[*n][0] += field[*n][0];
        moved_points[*n][1] += field[*n][1];
    }
    check_orientations(mesh, &moved_points, targets)?;
    mesh.points = moved_points;
    Ok(())
}

/// Refuses a move that changes the orientation of a cell with a moved node (see the module doc).
fn check_orientations(mesh: &Mesh, moved: &[[f64; 2]], targets: &[(NodeId, [f64; 2])]) -> Result<(), MeshError> {
    let changed = |n: NodeId| mesh.points[n.0] != moved[n.0];
    for block in mesh.blocks.iter().filter(|b| b.kind.dim() == 2) {
        for (cell, &tag) in block.cells().zip(&block.element_tags) {
            if !cell.iter().any(|&n| changed(n)) {
                continue;
            }
            let before: Vec<[f64; 2]> = cell.iter().map(|n| mesh.points[n.0]).collect();
            let after: Vec<[f64; 2]> = cell.iter().map(|n| moved[n.0]).collect();
            let was = cell_orientation(block.kind, &before);
            if was == Some(Orientation::Tangled) || cell_orientation(block.kind, &after) == was {
                continue;
            }
            let (node, to) = culprit(mesh, cell, &before, targets);
            return Err(MeshError::MorphInvertsElement {
                cell: tag,
                node: mesh.node_tags.get(node.0).copied().unwrap_or(node.0 as u64),
                from: mesh.points[node.0],
                to,
            });
        }
    }
    Ok(())
}

/// The moved node to blame for a cell: among the targets in the cell the one moved farthest, else
/// the target nearest the cell's first node.
fn culprit(mesh: &Mesh, cell: &[NodeId], coords: &[[f64; 2]], targets: &[(NodeId, [f64; 2])]) -> (NodeId, [f64; 2]) {
    let dist = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]);
    let in_cell = targets
        .iter()
        .filter(|(n, _)| cell.contains(n))
        .max_by(|a, b| dist(mesh.points[a.0.0], a.1).total_cmp(&dist(mesh.points[b.0.0], b.1)));
    let nearest = || {
        targets
            .iter()
            .min_by(|a, b| dist(mesh.points[a.0.0], coords[0]).total_cmp(&dist(mesh.points[b.0.0], coords[0])))
    };
    in_cell.or_else(nearest).copied().unwrap_or((cell[0], coords[0]))
}

/// Nodes sharing a 2D cell with each node, in ascending order.
fn node_neighbours(mesh: &Mesh) -> Vec<Vec<usize>> {
    let len = mesh.points.len();
    // Each list allocated once at its largest length (before the duplicates go): growing them
    // was most of a morph's time on the flagship's meshes.
    let mut capacity = vec![0usize; len];
    for block in mesh.blocks.iter().filter(|b| b.kind.dim() == 2) {
        for cell in block.cells() {
            for a in cell {
                if let Some(c) = capacity.get_mut(a.0) {
                    *c += cell.len();
                }
            }
        }
    }
    let mut nb: Vec<Vec<usize>> = capacity.into_iter().map(Vec::with_capacity).collect();
    for block in mesh.blocks.iter().filter(|b| b.kind.dim() == 2) {
        for cell in block.cells() {
            for a in cell {
                if let Some(list) = nb.get_mut(a.0) {
                    list.extend(cell.iter().map(|n| n.0).filter(|&n| n != a.0 && n < len));
                }
            }
        }
    }
    for list in &mut nb {
        list.sort_unstable();
        list.dedup();
    }
    nb
}

/// Whether each node lies on a 1D cell that belongs to a physical group.
fn boundary_nodes(mesh: &Mesh) -> Vec<bool> {
    let mut on = vec![false; mesh.points.len()];
    for block in mesh.blocks.iter().filter(|b| b.kind.dim() == 1 && !b.physical_tags.is_empty()) {
        for n in &block.nodes {
            if let Some(flag) = on.get_mut(n.0) {
                *flag = true;
            }
        }
    }
    on
}

/// Whether each node lies within `layers` neighbour steps of the seeds.
fn nodes_within(neighbours: &[Vec<usize>], seeds: &[usize], layers: usize) -> Vec<bool> {
    let mut seen = vec![false; neighbours.len()];
    for &n in seeds {
        seen[n] = true;
    }
    let mut front: Vec<usize> = seeds.to_vec();
    for _ in 0..layers {
        let mut next = vec![];
        for n in front {
            for &m in &neighbours[n] {
                if !seen[m] {
                    seen[m] = true;
                    next.push(m);
                }
            }
        }
        front = next;
    }
    seen
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::generate::rectangle;
    use crate::mesh::CellKind;

    #[test]
    fn moves_targets_keeps_other_boundaries_and_relaxes_the_inside() {
        let mut mesh = rectangle(CellKind::Quad4, [0.0, 4.0], [0.0, 4.0], 4, 4);
        let original = mesh.clone();
        // Slide the middle node of the bottom edge (x = 2, y = 0) by 0.1 along the edge.
        let bottom_mid = (0..mesh.points.len()).find(|&i| mesh.points[i] == [2.0, 0.0]).unwrap();
        move_nodes(&mut mesh, &[(NodeId(bottom_mid), [2.1, 0.0])], 2).unwrap();
        assert_eq!(mesh.points[bottom_mid], [2.1, 0.0]);
        // Other boundary nodes do not move; the interior node above moves by less than the target.
        for i in 0..mesh.points.len() {
            let p = original.points[i];
            let on_boundary = p[0] == 0.0 || p[0] == 4.0 || p[1] == 0.0 || p[1] == 4.0;
            if on_boundary && i != bottom_mid {
                assert_eq!(mesh.points[i], p);
            }
        }
        let above = (0..mesh.points.len()).find(|&i| original.points[i] == [2.0, 1.0]).unwrap();
        let dx = mesh.points[above][0] - 2.0;
        assert!(dx > 0.0 && dx < 0.1, "{dx}");
        assert!(move_nodes(&mut mesh, &[(NodeId(0), [f64::NAN, 0.0])], 1).is_err());
        assert!(move_nodes(&mut mesh, &[(NodeId(0), [0.0, 0.0]), (NodeId(0), [0.0, 0.0])], 1).is_err());
    }

    #[test]
    fn a_move_that_inverts_a_cell_is_refused_and_names_the_node() {
        for kind in [CellKind::Quad4, CellKind::Quad9, CellKind::Tri6] {
            let mut mesh = rectangle(kind, [0.0, 4.0], [0.0, 4.0], 4, 4);
            let original = mesh.clone();
            // Slide the bottom node at x = 2 along its edge past its neighbour at x = 3: the
            // cells between them fold over.
            let node = (0..mesh.points.len()).find(|&i| mesh.points[i] == [2.0, 0.0]).unwrap();
            match move_nodes(&mut mesh, &[(NodeId(node), [3.3, 0.0])], 2) {
                Err(MeshError::MorphInvertsElement { node: tag, from, to, .. }) => {
                    assert_eq!(tag, mesh.node_tags[node], "{kind:?}");
                    assert_eq!((from, to), ([2.0, 0.0], [3.3, 0.0]));
                }
                other => panic!("{kind:?}: expected MorphInvertsElement, got {other:?}"),
            }
            assert_eq!(mesh, original, "{kind:?}: the mesh must be unchanged");
            let message = move_nodes(&mut mesh, &[(NodeId(node), [3.3, 0.0])], 2).unwrap_err().to_string();
            assert!(message.contains("would invert cell"), "{message}");
        }
    }
}

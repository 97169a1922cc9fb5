//! Detection of bodies that Dirichlet conditions do not hold against rigid motion.
//!
//! ```text
//! rigid motions of a plane body:  u(x) = (a - θ x2, b + θ x1)
//! a constrained u1 at x imposes  [1, 0, -x2]·(a, b, θ) = 0,  a constrained u2:  [0, 1, x1]·(a, b, θ) = 0
//! the piece is held iff these rows have rank 3
//! ```
//!
//! Each connected piece of each body is checked on its own (coordinates centred and scaled so
//! the rank test is independent of units), so an unconstrained body is reported by name before
//! any factorisation could produce NaN or a meaningless pivot.

use nalgebra::Matrix3;

use crate::dof::{Component, Dof, DofKind, DofMap};
use crate::error::FemError;
use crate::model::Model;

/// Checks that every connected piece of every body is held against all three rigid modes.
///
/// # Errors
/// [`FemError::UnconstrainedBody`] naming the body, the number of free modes and one node.
pub fn check_rigid_modes(model: &Model, dofs: &DofMap) -> Result<(), FemError> {
    for body in &model.bodies {
        for piece in connected_pieces(body) {
            let free_modes = 3 - constraint_rank(model, dofs, &piece);
            if free_modes > 0 {
                let node = piece.first().copied().unwrap_or(0);
                return Err(FemError::UnconstrainedBody {
                    body: body.name.clone(),
                    free_modes,
                    node_tag: model.mesh.node_tags.get(node).copied().unwrap_or(node as u64),
                });
            }
        }
    }
    Ok(())
}

fn constraint_rank(model: &Model, dofs: &DofMap, nodes: &[usize]) -> usize {
    let pts: Vec<[f64; 2]> = nodes.iter().map(|&n| model.mesh.points[n]).collect();
    let count = pts.len().max(1) as f64;
    let centre = [pts.iter().map(|p| p[0]).sum::<f64>() / count, pts.iter().map(|p| p[1]).sum::<f64>() / count];
    let scale =
        pts.iter().map(|p| (p[0] - centre[0]).hypot(p[1] - centre[1])).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let mut normal = Matrix3::<f64>::zeros();
    for (&n, p) in nodes.iter().zip(&pts) {
        let (x, y) = ((p[0] - centre[0]) / scale, (p[1] - centre[1]) / scale);
        for (c, row) in [(Component::X, [1.0, 0.0, -y]), (Component::Y, [0.0, 1.0, x])] {
            if matches!(dofs.kind(Dof::of(n, c)), DofKind::Constrained(_)) {
                let r = nalgebra::Vector3::from(row);
                normal += r * r.transpose();
            }
        }
    }
    let eig = normal.symmetric_eigenvalues();
    let largest = eig.max().max(f64::MIN_POSITIVE);
    eig.iter().filter(|&&e| e > 1e-10 * largest && e > 1e-14).count()
}

/// Connected pieces of a body (nodes linked by sharing a cell), by union-find over a dense
/// parent array (union by size, path halving): linear in the mesh size.
fn connected_pieces(body: &crate::model::Body) -> Vec<Vec<usize>> {
    let n = body.nodes.iter().map(|v| v.0 + 1).max().unwrap_or(0);
    let mut parent: Vec<usize> = (0..n).collect();
    let mut size = vec![1usize; n];
    let find = |parent: &mut Vec<usize>, mut x: usize| {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    };
    for i in 0..body.num_cells() {
        let nodes = body.cell_nodes(i);
        let first = nodes[0].0;
        for v in &nodes[1..] {
            let (mut a, mut b) = (find(&mut parent, first), find(&mut parent, v.0));
            if a != b {
                if size[a] < size[b] {
                    std::mem::swap(&mut a, &mut b);
                }
                parent[b] = a;
                size[a] += size[b];
            }
        }
    }
    let mut in_body = vec![false; n];
    for v in &body.nodes {
        in_body[v.0] = true;
    }
    let mut piece_of_root: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    let mut pieces: Vec<Vec<usize>> = vec![];
    for node in (0..n).filter(|&v| in_body[v]) {
        let root = find(&mut parent, node);
        let index = *piece_of_root.entry(root).or_insert_with(|| {
            pieces.push(vec![]);
            pieces.len() - 1
        });
        pieces[index].push(node);
    }
    pieces
}

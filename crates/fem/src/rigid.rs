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
//!
//! Only the body's own rigid motions count ([`contact2d_element::Kinematics::rigid_motions`]):
//! all three in the plane, the axial translation `(0, 1, 0)` alone for a body of revolution. With
//! `P` the projector on their span, the test runs on `P N P + (I − P) c` (`N = Σ r rᵀ`, `c` above
//! every eigenvalue of `N`), so motions outside the span never count as free; in the plane
//! `P = I` and the matrix is `N` itself, bit for bit.

use nalgebra::Matrix3;

use crate::dof::{Component, Dof, DofKind, DofMap};
use crate::error::FemError;
use crate::model::{Body, Model};

/// A connected piece of a body that the Dirichlet conditions leave free to move rigidly: a body
/// held only by contact (a pin pushed by a force, a roller pressed on a block).
///
/// ```text
/// rigid motion u(x) = (a − θ (x2 − c2)/L, b + θ (x1 − c1)/L)   (c: the piece's centroid, L: its radius)
/// free modes: a basis of the (a, b, θ) that no constrained DOF of the piece sees
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FloatingPiece {
    /// The body's name.
    pub body: String,
    /// The piece's nodes.
    pub nodes: Vec<usize>,
    /// Unit vectors `(a, b, θ)` spanning the free rigid motions, in the centred and scaled
    /// coordinates above.
    pub free_modes: Vec<[f64; 3]>,
    /// The centroid `c` and radius `L` that scale the modes.
    pub centre: [f64; 2],
    /// The radius `L`.
    pub scale: f64,
}

impl FloatingPiece {
    /// The displacement at `x` of free mode `mode` with unit amplitude:
    /// `(a − θ (x2 − c2)/L, b + θ (x1 − c1)/L)` for the mode's `(a, b, θ)`.
    pub fn mode_displacement(&self, mode: usize, x: [f64; 2]) -> [f64; 2] {
        let [a, b, theta] = self.free_modes[mode];
        let (dx, dy) = ((x[0] - self.centre[0]) / self.scale, (x[1] - self.centre[1]) / self.scale);
        [a - theta * dy, b + theta * dx]
    }

    /// Names of the free modes for people: "u1 translation", "u2 translation", "rotation", or
    /// a mixture written as its components.
    pub fn mode_names(&self) -> Vec<String> {
        self.free_modes
            .iter()
            .map(|m| {
                let largest = m.iter().fold(0.0f64, |a, v| a.max(v.abs()));
                let pure =
                    |k: usize| m[k].abs() > (1.0 - 1e-9) * largest && m.iter().filter(|v| v.abs() > 1e-6).count() == 1;
                match (0..3).find(|&k| pure(k)) {
                    Some(0) => "u1 translation".to_string(),
                    Some(1) => "u2 translation".to_string(),
                    Some(_) => "rotation".to_string(),
                    None => format!("rigid motion (a, b, θ) = ({:.3}, {:.3}, {:.3})", m[0], m[1], m[2]),
                }
            })
            .collect()
    }
}

/// Every connected piece of every body that the Dirichlet conditions do not hold against all
/// three rigid modes, with its free modes.
pub fn floating_pieces(model: &Model, dofs: &DofMap) -> Vec<FloatingPiece> {
    let mut out = vec![];
    for body in &model.bodies {
        for piece in connected_pieces(body) {
            let (normal, centre, scale) = constraint_normal_matrix(model, dofs, &piece);
            let eig = within_motions(normal, body).symmetric_eigen();
            let largest = eig.eigenvalues.iter().fold(0.0f64, |a, e| a.max(*e)).max(f64::MIN_POSITIVE);
            let mut order: Vec<usize> = (0..3).collect();
            order.sort_by(|a, b| eig.eigenvalues[*a].total_cmp(&eig.eigenvalues[*b]));
            let free_modes: Vec<[f64; 3]> = order
                .into_iter()
                .filter(|&k| !(eig.eigenvalues[k] > 1e-10 * largest && eig.eigenvalues[k] > 1e-14))
                .map(|k| {
                    let v = eig.eigenvectors.column(k);
                    // A sign convention for bit-reproducible output: the largest component positive.
                    let big = (0..3).max_by(|a, b| v[*a].abs().total_cmp(&v[*b].abs())).unwrap_or(0);
                    let s = if v[big] < 0.0 { -1.0 } else { 1.0 };
                    let snap = |x: f64| if x.abs() < 1e-12 { 0.0 } else { s * x };
                    [snap(v[0]), snap(v[1]), snap(v[2])]
                })
                .collect();
            if !free_modes.is_empty() {
                out.push(FloatingPiece { body: body.name.clone(), nodes: piece, free_modes, centre, scale });
            }
        }
    }
    out
}

/// Checks that every connected piece of every body is held against all three rigid modes.
///
/// # Errors
/// [`FemError::UnconstrainedBody`] naming the body, the number of free modes and one node.
pub fn check_rigid_modes(model: &Model, dofs: &DofMap) -> Result<(), FemError> {
    for body in &model.bodies {
        for piece in connected_pieces(body) {
            let free_modes = 3 - constraint_rank(model, dofs, &piece, body);
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

fn constraint_rank(model: &Model, dofs: &DofMap, nodes: &[usize], body: &Body) -> usize {
    let (normal, _, _) = constraint_normal_matrix(model, dofs, nodes);
    let eig = within_motions(normal, body).symmetric_eigenvalues();
    let largest = eig.max().max(f64::MIN_POSITIVE);
    eig.iter().filter(|&&e| e > 1e-10 * largest && e > 1e-14).count()
}

/// `P N P + (I − P) c` (module docs): the constraint matrix `N` seen only along the body's rigid
/// motions; `N` itself in the plane.
fn within_motions(normal: Matrix3<f64>, body: &Body) -> Matrix3<f64> {
    let mut projector = Matrix3::<f64>::zeros();
    for m in body.kinematics.rigid_motions() {
        let v = nalgebra::Vector3::from(m);
        projector += v * v.transpose();
    }
    let held = normal.trace() + 1.0;
    projector * normal * projector + (Matrix3::identity() - projector) * held
}

/// `Σ r rᵀ` over the constraint rows `r` of the piece's constrained DOFs, in centred and scaled
/// coordinates, with the centre and scale.
fn constraint_normal_matrix(model: &Model, dofs: &DofMap, nodes: &[usize]) -> (Matrix3<f64>, [f64; 2], f64) {
    let pts: Vec<[f64; 2]> = nodes.iter().map(|&n| model.mesh.points[n]).collect();
    let count = pts.len().max(1) as f64;
    let centre = [pts.iter().map(|p| p[0]).sum::<f64>() / count, pts.iter().map(|p| p[1]).sum::<f64>() / count];
    let scale =
        pts.iter().map(|p| (p[0] - centre[0]).hypot(p[1] - centre[1])).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let mut normal = Matrix3::<f64>::zeros();
    for (&n, p) in nodes.iter().zip(&pts) {
        let (x, y) = ((p[0] - centre[0]) / scale, (p[1] - centre[1]) / scale);
        // The row of a constrained DOF along the unit direction e (e_1, e_2, or a framed node's
        // n, t): (e_1, e_2, x e_2 − y e_1).
        let directions = dofs.frame(n).map_or([[1.0, 0.0], [0.0, 1.0]], |f| [f.n, f.t]);
        for (c, e) in [Component::X, Component::Y].into_iter().zip(directions) {
            if matches!(dofs.kind(Dof::of(n, c)), DofKind::Constrained(_)) {
                let r = nalgebra::Vector3::new(e[0], e[1], x * e[1] - y * e[0]);
                normal += r * r.transpose();
            }
        }
    }
    (normal, centre, scale)
}

/// Connected pieces of a body (nodes linked by sharing a cell), by union-find over a dense
/// parent array (union by size, path halving): linear in the mesh size.
fn connected_pieces(body: &Body) -> Vec<Vec<usize>> {
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

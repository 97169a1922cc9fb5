//! Parallel assembly of the linear system with Dirichlet conditions eliminated.
//!
//! ```text
//! K = Σ_e Aₑᵀ K_e Aₑ,   split by DOF role (f = free, c = constrained):
//!
//!   [ K_ff  K_fc ] [u_f]   [f_f]            K_ff u_f = f_f - K_fc u_c     (solved)
//!   [ K_cf  K_cc ] [u_c] = [f_c + r_c]      r_c = K_cf u_f + K_cc u_c - f_c (reactions)
//! ```
//!
//! `K_ff` is assembled in place into its compressed-column pattern, built from the node graph
//! (the `pattern` module, parallel over column blocks); the few cells with a constrained DOF are
//! scattered into triplets for `K_fc` and `K_cc`. Only the lower triangle of `K_ff` is stored:
//! the Cholesky factorisation reads that side. `K_fc` and `K_cc` are kept so that the right-hand side and the
//! reactions can be formed for any prescribed values without assembling again.

use contact2d_element::{EdgeType, body_force_load, edge_traction_load};
use std::collections::HashMap;

use contact2d_mesh::{CellKind, NodeId};
use faer::sparse::Triplet;
use nalgebra::DMatrix;
use rayon::prelude::*;

use crate::cell_matrix::{cell_kinds, element_matrix};
use crate::dof::{Component, Dof, DofKind, DofMap};
use crate::error::FemError;
use crate::model::{EdgeLoad, Model};
use crate::ordering::NodeGraph;
use crate::pattern::assemble_free_free;
use crate::rigid::{FloatingPiece, check_rigid_modes, floating_pieces};

pub use crate::sparse::Csc;

/// The assembled, Dirichlet-reduced linear system of a model.
#[derive(Debug, Clone)]
pub struct LinearSystem {
    /// The DOF numbering.
    pub dofs: DofMap,
    /// `K_ff`, lower triangle only.
    pub stiffness: Csc,
    /// `K_fc` (free rows, constrained columns).
    pub coupling: Csc,
    /// `K_cc`.
    pub constrained: Csc,
    /// External nodal loads in global DOF order.
    pub load: Vec<f64>,
    /// The body pieces held by no Dirichlet condition (only with [`Model::allow_floating`]).
    pub floating: Vec<FloatingPiece>,
    /// `(free index, k)`: the pins of the floating pieces, springs to ground added to the
    /// diagonal of `K_ff` on as many DOFs of each piece as it has free rigid modes, chosen so that
    /// they see every free mode (`Rᵀ H` invertible, `R` the modes, `H` the pinned DOFs):
    ///
    /// ```text
    /// k = FLOATING_PIN_STIFFNESS · mean diag(K_ff) over the piece's free DOFs
    /// ```
    ///
    /// `K_ff + D` is then positive definite, and for a load `h` that the piece balances
    /// (`Rᵀ h = 0`) `u = (K_ff + D)⁻¹ h` solves `K_ff u = h` exactly with `Hᵀ u = 0`: the pins carry
    /// no force (Farhat and Roux's generalised inverse of a floating subdomain). The contact
    /// solve makes the rigid motion `R α` an unknown and finds it by asking the pins' forces to
    /// vanish (`contact2d_contact::solve`).
    pub stabilisation: Vec<(usize, f64)>,
}

/// The relative stiffness of the pins of a floating piece (see [`LinearSystem::stabilisation`]):
/// any positive value gives the same answer; the mean diagonal keeps `K_ff + D` as well
/// conditioned as `K_ff` with Dirichlet conditions.
pub const FLOATING_PIN_STIFFNESS: f64 = 1.0;

/// The `K_fc` and `K_cc` entries, in the order they are scattered.
#[derive(Default)]
pub(crate) struct Triplets {
    pub(crate) fc: Vec<Triplet<usize, usize, f64>>,
    pub(crate) cc: Vec<Triplet<usize, usize, f64>>,
}

impl Triplets {
    fn append(mut self, mut other: Triplets) -> Triplets {
        self.fc.append(&mut other.fc);
        self.cc.append(&mut other.cc);
        self
    }
}

/// Assembles the model: DOF map, rigid-mode check, stiffness blocks and loads.
///
/// # Errors
/// Conflicting Dirichlet conditions, an unconstrained body, element failures, or a sparse
/// construction failure.
pub fn assemble(model: &Model) -> Result<LinearSystem, FemError> {
    let dofs = model.dof_map()?;
    let floating = floating_of(model, &dofs)?;
    let cells = model_cells(model);
    let triplets = cells
        .par_chunks(256)
        .map(|chunk| {
            let mut t = Triplets::default();
            for &(b, i) in chunk {
                scatter_cell(model, &dofs, b, i, &mut t)?;
            }
            Ok::<_, FemError>(t)
        })
        .try_reduce(Triplets::default, |a, b| Ok(a.append(b)))?;
    // K_fc and K_cc from the cells with a constrained DOF; K_ff in place in its pattern.
    let graph = NodeGraph::of_model(model);
    let stiffness = assemble_free_free(model, &dofs, &graph)?;
    system_of(model, dofs, floating, stiffness, &triplets)
}

/// The linear system of `model` from its assembled `K_ff` and the constrained blocks' triplets:
/// `K_ff` stabilised for the floating bodies, `K_fc` and `K_cc` built, the edge loads assembled.
///
/// # Errors
/// A sparse construction failure or an invalid edge load.
pub(crate) fn system_of(
    model: &Model,
    dofs: DofMap,
    floating: Vec<FloatingPiece>,
    mut stiffness: Csc,
    triplets: &Triplets,
) -> Result<LinearSystem, FemError> {
    let (nf, nc) = (dofs.num_free(), dofs.num_constrained());
    let stabilisation = stabilise(&mut stiffness, model, &dofs, &floating);
    Ok(LinearSystem {
        stiffness,
        coupling: sparse_from_triplets(nf, nc, &triplets.fc)?,
        constrained: sparse_from_triplets(nc, nc, &triplets.cc)?,
        load: assemble_edge_loads(model, &model.edge_loads)?,
        dofs,
        floating,
        stabilisation,
    })
}

/// Every cell of the model as `(body, cell)`, bodies in order: the order the entries of `K` are
/// summed in.
pub(crate) fn model_cells(model: &Model) -> Vec<(usize, usize)> {
    model.bodies.iter().enumerate().flat_map(|(b, body)| (0..body.num_cells()).map(move |i| (b, i))).collect()
}

/// The floating pieces (with [`Model::allow_floating`]), or the rigid-mode check.
pub(crate) fn floating_of(model: &Model, dofs: &DofMap) -> Result<Vec<FloatingPiece>, FemError> {
    if model.allow_floating {
        Ok(floating_pieces(model, dofs))
    } else {
        check_rigid_modes(model, dofs)?;
        Ok(vec![])
    }
}

/// An `n × m` sparse matrix from triplets (duplicates summed in their order).
pub(crate) fn sparse_from_triplets(n: usize, m: usize, t: &[Triplet<usize, usize, f64>]) -> Result<Csc, FemError> {
    Csc::try_new_from_triplets(n, m, t).map_err(|e| FemError::Factorization(format!("sparse assembly: {e:?}")))
}

/// Adds the pins of [`LinearSystem::stabilisation`] to the diagonal of `K_ff` (lower
/// triangle, sorted rows: the diagonal is the first entry of its column).
pub(crate) fn stabilise(
    stiffness: &mut Csc,
    model: &Model,
    dofs: &DofMap,
    floating: &[FloatingPiece],
) -> Vec<(usize, f64)> {
    let mut springs = vec![];
    for piece in floating {
        let free: Vec<(usize, Dof)> = piece
            .nodes
            .iter()
            .flat_map(|&n| [Dof::of(n, Component::X), Dof::of(n, Component::Y)])
            .filter_map(|d| match dofs.kind(d) {
                DofKind::Free(i) => Some((i, d)),
                _ => None,
            })
            .collect();
        let diagonal = |k: &Csc, i: usize| {
            let k = k.as_ref();
            k.row_idx_of_col(i).zip(k.val_of_col(i)).find(|(r, _)| *r == i).map_or(0.0, |(_, v)| *v)
        };
        let mean = free.iter().map(|&(i, _)| diagonal(stiffness, i)).sum::<f64>() / free.len().max(1) as f64;
        let k = FLOATING_PIN_STIFFNESS * mean;
        springs.extend(pin_dofs(model, dofs, piece, &free).into_iter().map(|i| (i, k)));
    }
    if springs.is_empty() {
        return springs;
    }
    let (col_ptr, row_idx) = (stiffness.symbolic().col_ptr().to_vec(), stiffness.symbolic().row_idx().to_vec());
    let values = stiffness.val_mut();
    for &(i, k) in &springs {
        if let Some(at) = (col_ptr[i]..col_ptr[i + 1]).find(|&at| row_idx[at] == i) {
            values[at] += k;
        }
    }
    springs
}

/// One free DOF per free mode of `piece`, chosen greedily so that the pinned DOFs see every
/// mode: each pick maximises the part of its row `(r_1(d), …, r_m(d))` (the modes' values at
/// DOF `d`) orthogonal to the rows picked before (a column-pivoted QR of `Rᵀ`; ties go to the
/// first DOF, so the choice is reproducible).
fn pin_dofs(model: &Model, dofs: &DofMap, piece: &FloatingPiece, free: &[(usize, Dof)]) -> Vec<usize> {
    let modes = piece.free_modes.len();
    let rows: Vec<Vec<f64>> = free
        .iter()
        .map(|&(_, d)| {
            let x = model.mesh.points[d.node()];
            let c = d.0 % 2;
            let local = |v: [f64; 2]| dofs.frame(d.node()).map_or(v, |f| f.to_local(v));
            (0..modes).map(|m| local(piece.mode_displacement(m, x))[c]).collect()
        })
        .collect();
    let mut basis: Vec<Vec<f64>> = vec![];
    let mut pins = vec![];
    for _ in 0..modes {
        let residual = |row: &[f64]| {
            let mut r = row.to_vec();
            for q in &basis {
                let dot: f64 = r.iter().zip(q).map(|(a, b)| a * b).sum();
                r.iter_mut().zip(q).for_each(|(a, b)| *a -= dot * b);
            }
            r
        };
        let mut best: Option<(f64, usize, Vec<f64>)> = None;
        for (k, row) in rows.iter().enumerate() {
            let r = residual(row);
            let norm = r.iter().map(|v| v * v).sum::<f64>().sqrt();
            if best.as_ref().is_none_or(|b| norm > b.0) {
                best = Some((norm, k, r));
            }
        }
        let Some((norm, k, r)) = best.filter(|b| b.0 > 0.0) else { break };
        basis.push(r.iter().map(|v| v / norm).collect());
        pins.push(free[k].0);
    }
    pins
}

fn scatter_cell(model: &Model, dofs: &DofMap, b: usize, i: usize, t: &mut Triplets) -> Result<(), FemError> {
    let kinds = cell_kinds(model, dofs, b, i);
    if !kinds.iter().any(|k| matches!(k, DofKind::Constrained(_))) {
        return Ok(());
    }
    let k = element_matrix(model, dofs, b, i)?;
    scatter_constrained(&kinds, &k, t);
    Ok(())
}

/// The `K_fc` and `K_cc` entries of a cell's matrix `k` as triplets, column by column.
pub(crate) fn scatter_constrained(kinds: &[DofKind], k: &DMatrix<f64>, t: &mut Triplets) {
    for (col, kc) in kinds.iter().enumerate() {
        for (row, kr) in kinds.iter().enumerate() {
            let v = k[(row, col)];
            match (kr, kc) {
                (DofKind::Free(r), DofKind::Constrained(c)) => t.fc.push(Triplet::new(*r, *c, v)),
                (DofKind::Constrained(r), DofKind::Constrained(c)) => t.cc.push(Triplet::new(*r, *c, v)),
                _ => {}
            }
        }
    }
}

/// Consistent nodal forces of `loads` (edge loads on `model`'s mesh), in global DOF order: the
/// traction (per unit length and thickness) times the thickness of the body that owns the edge.
///
/// # Errors
/// An unknown group, or an edge that bounds no body.
pub fn assemble_edge_loads(model: &Model, loads: &[EdgeLoad]) -> Result<Vec<f64>, FemError> {
    let mut f = vec![0.0; 2 * model.mesh.num_nodes()];
    if loads.is_empty() {
        return Ok(f);
    }
    let owners = edge_owners(model);
    for load in loads {
        let (group, traction, pressure) = match load {
            EdgeLoad::Traction { group, traction } => (group, *traction, 0.0),
            EdgeLoad::Pressure { group, pressure } => (group, [0.0; 2], *pressure),
        };
        for block in model.mesh.blocks_in_group(group)? {
            let edge = match block.kind {
                CellKind::Line2 => EdgeType::Line2,
                CellKind::Line3 => EdgeType::Line3,
                _ => continue,
            };
            for (cell, tag) in block.cells().zip(&block.element_tags) {
                let coords: Vec<[f64; 2]> = cell.iter().map(|n| model.mesh.points[n.0]).collect();
                let &(body, owner) = owners.get(&edge_key(cell[0], cell[1])).ok_or_else(|| {
                    FemError::InvalidInput(format!("edge load on \"{group}\": edge {tag} bounds no body"))
                })?;
                let body = &model.bodies[body];
                let sign = outward_sign(&body.cell_coords(&model.mesh, owner), &coords);
                let fe = edge_traction_load(edge, &coords, &body.kinematics, 3, |_, n| {
                    [traction[0] - sign * pressure * n[0], traction[1] - sign * pressure * n[1]]
                })
                .map_err(|source| FemError::Element { body: group.clone(), cell: *tag, source })?;
                for (a, node) in cell.iter().enumerate() {
                    f[2 * node.0] += fe[2 * a];
                    f[2 * node.0 + 1] += fe[2 * a + 1];
                }
            }
        }
    }
    Ok(f)
}

/// Consistent nodal forces of constant body forces `b` (force per unit volume, e.g. the weight
/// `ρ g`) on whole bodies, in global DOF order:
///
/// ```text
/// f_a = Σ_e ∫_Ωe N_a b t_h dΩ      (every cell of the body named by the region, thickness t_h)
/// ```
///
/// The total of a body's forces is `b t_h |Ω|` (the shape functions sum to one), whatever its
/// element types.
///
/// # Errors
/// [`FemError::InvalidInput`] for a region that is no body or a non-finite force; an element
/// error for a degenerate cell.
pub fn assemble_body_forces(model: &Model, forces: &[(String, [f64; 2])]) -> Result<Vec<f64>, FemError> {
    let mut f = vec![0.0; 2 * model.mesh.num_nodes()];
    for (region, b) in forces {
        if !b.iter().all(|v| v.is_finite()) {
            return Err(FemError::InvalidInput(format!("body force on \"{region}\" is not finite")));
        }
        let (_, body) = model
            .body(region)
            .ok_or_else(|| FemError::InvalidInput(format!("body force on \"{region}\": no body has that region")))?;
        for i in 0..body.num_cells() {
            let element = body.elements[i];
            let rule = body.kinematics.stiffness_rule(element);
            let fe = body_force_load(element, &body.cell_coords(&model.mesh, i), &body.kinematics, *b, &rule)
                .map_err(|source| FemError::Element { body: body.name.clone(), cell: body.cell_tags[i], source })?;
            for (a, node) in body.cell_nodes(i).iter().enumerate() {
                f[2 * node.0] += fe[2 * a];
                f[2 * node.0 + 1] += fe[2 * a + 1];
            }
        }
    }
    Ok(f)
}

/// An undirected edge, by its end nodes.
fn edge_key(a: NodeId, b: NodeId) -> (NodeId, NodeId) {
    if a < b { (a, b) } else { (b, a) }
}

/// For every cell edge of every body: the owning `(body, cell)` (built once per assembly).
fn edge_owners(model: &Model) -> HashMap<(NodeId, NodeId), (usize, usize)> {
    let mut owners = HashMap::new();
    for (b, body) in model.bodies.iter().enumerate() {
        for i in 0..body.num_cells() {
            let nodes = body.cell_nodes(i);
            for e in body.elements[i].edges() {
                owners.insert(edge_key(nodes[e[0]], nodes[e[1]]), (b, i));
            }
        }
    }
    owners
}

/// +1 if the edge normal `(t_y, -t_x)` points out of the cell with nodal coordinates `cell`.
fn outward_sign(cell: &[[f64; 2]], edge: &[[f64; 2]]) -> f64 {
    let mid = [0.5 * (edge[0][0] + edge[1][0]), 0.5 * (edge[0][1] + edge[1][1])];
    let n = [edge[1][1] - edge[0][1], edge[0][0] - edge[1][0]];
    let k = cell.len() as f64;
    let centroid = [cell.iter().map(|p| p[0]).sum::<f64>() / k, cell.iter().map(|p| p[1]).sum::<f64>() / k];
    if n[0] * (mid[0] - centroid[0]) + n[1] * (mid[1] - centroid[1]) >= 0.0 { 1.0 } else { -1.0 }
}

impl LinearSystem {
    /// The right-hand side `f_f - K_fc u_c` for prescribed values `u_c` (per constrained index).
    pub fn rhs(&self, prescribed: &[f64]) -> Vec<f64> {
        self.rhs_with(&self.load, prescribed)
    }

    /// The right-hand side `f_f - K_fc u_c` for nodal loads `load` (global DOF order and
    /// components, e.g. one load pattern's from [`assemble_edge_loads`]; `f' = Tᵀ f` at framed
    /// nodes) and prescribed values `u_c`.
    pub fn rhs_with(&self, load: &[f64], prescribed: &[f64]) -> Vec<f64> {
        let mut rhs: Vec<f64> = self.dofs.restrict_free(load);
        for (j, &uc) in prescribed.iter().enumerate() {
            if uc == 0.0 {
                continue;
            }
            let col = self.coupling.as_ref();
            for (r, v) in col.row_idx_of_col(j).zip(col.val_of_col(j)) {
                rhs[r] -= v * uc;
            }
        }
        rhs
    }

    /// Reactions `r_c = K_cf u_f + K_cc u_c - f_c`, per constrained index (in the local frame
    /// at a framed node: [`DofMap::reactions_global`] turns them into global components).
    pub fn reactions(&self, u_free: &[f64], prescribed: &[f64]) -> Vec<f64> {
        let (fc, cc) = (self.coupling.as_ref(), self.constrained.as_ref());
        let load = self.dofs.restrict_constrained(&self.load);
        (0..self.dofs.num_constrained())
            .map(|j| {
                let from_free: f64 = fc.row_idx_of_col(j).zip(fc.val_of_col(j)).map(|(r, v)| v * u_free[r]).sum();
                let from_fixed: f64 = cc.row_idx_of_col(j).zip(cc.val_of_col(j)).map(|(r, v)| v * prescribed[r]).sum();
                from_free + from_fixed - load[j]
            })
            .collect()
    }
}

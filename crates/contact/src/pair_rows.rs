//! The rows of one contact problem: each pair's normal and tangential row `B_N`, `B_T` over the
//! bodies' DOFs, split into free and constrained parts, and the rows factored with `K`.
//!
//! ```text
//! (B_N u)_k = n_k · (u_master − Σ_j N_j u_slave_j),   (B_T u)_k likewise with t_k
//! row = free part (over K_ff's unknowns) + constrained part (prescribed DOFs, × the load factor)
//! ```

use contact2d_fem::{Component, Dof, DofKind, LinearSystem};

use crate::error::ContactError;
use crate::pairing::ContactPair;
use crate::pairing::{IntegratedRows, RowCoefficient};

/// A sparse row over free DOFs plus its part over constrained DOFs.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PairRow {
    /// `(free index, coefficient)`.
    pub free: Vec<(usize, f64)>,
    /// `(constrained index, coefficient)`.
    pub constrained: Vec<(usize, f64)>,
}

impl PairRow {
    /// `row · u` for free values `u_f` and constrained values `u_c`.
    pub fn dot(&self, u_free: &[f64], u_constrained: &[f64]) -> f64 {
        self.free.iter().map(|(i, v)| v * u_free[*i]).sum::<f64>()
            + self.constrained.iter().map(|(j, v)| v * u_constrained[*j]).sum::<f64>()
    }
}

/// The normal and tangential rows of `pairs`.
pub(crate) fn pair_rows(
    system: &LinearSystem,
    pairs: &[ContactPair],
    slave: &[SlaveKind],
) -> Result<(Vec<PairRow>, Vec<PairRow>), ContactError> {
    let mut normal_rows = Vec::with_capacity(pairs.len());
    let mut tangent_rows = Vec::with_capacity(pairs.len());
    for (p, slave) in pairs.iter().zip(slave) {
        match &p.integrated {
            None => {
                normal_rows.push(pair_row(system, p, p.normal, *slave)?);
                tangent_rows.push(pair_row(system, p, p.tangent, *slave)?);
            }
            Some(rows) => {
                normal_rows.push(integrated_row(system, rows, |c| c.normal, *slave)?);
                tangent_rows.push(integrated_row(system, rows, |c| c.tangent, *slave)?);
            }
        }
    }
    Ok((normal_rows, tangent_rows))
}

/// A row's free part: `(free index, coefficient)`.
pub type SparseRow<'a> = &'a [(usize, f64)];

/// The rows factored with `K` (their free parts): every normal row, then every tangential row,
/// except rows whose free part is negligible (`|free|² ≤ 1e-4 |row|²`): a row along a Dirichlet
/// direction up to round-off would make the bordered factor's last block singular
/// ([`crate::Interface`] solves for those rows instead). Returns their indices in
/// `normal ++ tangent` and the rows.
pub fn condensed_rows<'a>(normal: &'a [PairRow], tangent: &'a [PairRow]) -> (Vec<usize>, Vec<SparseRow<'a>>) {
    normal
        .iter()
        .chain(tangent)
        .enumerate()
        .filter(|(_, r)| has_free_part(r))
        .map(|(i, r)| (i, r.free.as_slice()))
        .unzip()
}

/// Whether a row has a free part worth an unknown: `|free|² > 1e-4 |row|²`, i.e. more than 1 %
/// of the row. A row along constrained directions up to the edge geometry's error (the tangent
/// at a symmetry end point: 2.5e-3 of the row on a coarse, morphed N = 16 flagship mesh) has
/// none: an unknown there is all but unconstrained by the bodies (its compliance ~1e-5 of the
/// others), and the stick equation then returns a tangential force of round-off size over that
/// compliance (τ = −99 against λ = 0.18 at η = 0 in the placed Boussinesq search of U(1),
/// N = 16, which made the search's answer depend on round-off).
pub(crate) fn has_free_part(row: &PairRow) -> bool {
    let norm = |v: &[(usize, f64)]| v.iter().map(|(_, c)| c * c).sum::<f64>();
    let free = norm(&row.free);
    free > 0.0 && free > 1e-4 * (free + norm(&row.constrained))
}

/// Whether the master node of a segment-to-segment pair can move tangentially against its own
/// closest slave point: its node-to-segment tangential row has a free part (always true for a
/// node-to-segment pair, whose row is that one).
pub(crate) fn point_tangent_moves(system: &LinearSystem, pair: &ContactPair, slave: SlaveKind) -> bool {
    let Some(rows) = &pair.integrated else { return true };
    let point = ContactPair { slave: rows.point_slave.clone(), integrated: None, ..pair.clone() };
    pair_row(system, &point, rows.point_tangent, slave).is_ok_and(|row| has_free_part(&row))
}

/// Whether the slave side deforms or is a rigid obstacle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SlaveKind {
    Deformable,
    Rigid,
}

/// Adds a node's coefficient vector `v` (global components: the row reads `v · u_node`) to `row`.
/// At a node with a local frame (a `[[fix]]` with `un` / `ut`, `u = T u'`) the row reads
/// `(Tᵀ v) · u'`: `B' = B T`, so that the gap and the contact forces `B'ᵀλ` are those of the
/// rotated unknowns; without a frame `v` is used as it is (the same bits as before frames).
fn push_node(system: &LinearSystem, row: &mut PairRow, node: usize, v: [f64; 2]) -> Result<(), ContactError> {
    let v = system.dofs.frame(node).map_or(v, |frame| frame.to_local(v));
    for c in [Component::X, Component::Y] {
        let value = v[c.index()];
        if value == 0.0 {
            continue;
        }
        match system.dofs.kind(Dof::of(node, c)) {
            DofKind::Free(i) => row.free.push((i, value)),
            DofKind::Constrained(j) => row.constrained.push((j, value)),
            DofKind::Inactive => {
                return Err(ContactError::InvalidInput(format!("contact node index {node} belongs to no body")));
            }
        }
    }
    Ok(())
}

fn pair_row(
    system: &LinearSystem,
    pair: &ContactPair,
    dir: [f64; 2],
    slave: SlaveKind,
) -> Result<PairRow, ContactError> {
    let mut row = PairRow::default();
    let mut push = |node: usize, scale: f64| push_node(system, &mut row, node, [scale * dir[0], scale * dir[1]]);
    push(pair.master.0, 1.0)?;
    for (n, w) in &pair.slave {
        let active = !matches!(system.dofs.kind(Dof::of(n.0, Component::X)), DofKind::Inactive);
        match (slave, active) {
            (SlaveKind::Deformable, _) => push(n.0, -w)?,
            (SlaveKind::Rigid, false) => {}
            (SlaveKind::Rigid, true) => {
                return Err(ContactError::InvalidInput(format!(
                    "rigid slave contour: node index {} belongs to a body",
                    n.0
                )));
            }
        }
    }
    Ok(row)
}

/// The row `Σ_a c_a · u_a` of a segment-to-segment pair ([`crate::segment_to_segment`]): every
/// node's coefficient vector `c_a` picked by `part` (normal or tangential); a rigid slave's nodes
/// (no DOFs) drop out.
fn integrated_row(
    system: &LinearSystem,
    rows: &IntegratedRows,
    part: impl Fn(&RowCoefficient) -> [f64; 2],
    slave: SlaveKind,
) -> Result<PairRow, ContactError> {
    let mut row = PairRow::default();
    let sides = rows.master.iter().map(|c| (c, true)).chain(rows.slave.iter().map(|c| (c, false)));
    for (c, on_master) in sides {
        let n = c.node.0;
        let active = !matches!(system.dofs.kind(Dof::of(n, Component::X)), DofKind::Inactive);
        match (on_master, slave, active) {
            (false, SlaveKind::Rigid, false) => continue,
            (false, SlaveKind::Rigid, true) => {
                return Err(ContactError::InvalidInput(format!(
                    "rigid slave contour: node index {n} belongs to a body"
                )));
            }
            _ => {}
        }
        push_node(system, &mut row, n, part(c))?;
    }
    Ok(row)
}

//! Assembly of `K_ff` (lower triangle) straight into its compressed-column pattern, without
//! triplets or sorting.
//!
//! ```text
//! 1. pattern: the column of free DOF (n, c) holds the free DOFs (m, c') ≥ (n, c) with m = n or m
//!    a neighbour of n in the node graph; rows come out sorted because free indices grow with
//!    the global DOF 2 m + c'
//! 2. values: the columns are split into blocks of about equal nnz; each block (in parallel,
//!    owning its slice of the values) computes the matrices of the cells touching its columns and
//!    adds them in place, finding each row by binary search in its column
//! ```
//! The node graph comes from the cells, so a model with the same topology has the same pattern.

use faer::sparse::SymbolicSparseColMat;
use rayon::prelude::*;

use crate::dof::{Dof, DofKind, DofMap};
use crate::error::FemError;
use crate::model::Model;
use crate::ordering::NodeGraph;
use crate::sparse::Csc;

/// Free index of global DOF `g`, if it is free.
fn free_index(dofs: &DofMap, g: usize) -> Option<usize> {
    match dofs.kind(Dof(g)) {
        DofKind::Free(i) => Some(i),
        _ => None,
    }
}

/// `K_ff`, lower triangle, of `model` with the node graph `graph`.
pub(crate) fn assemble_free_free(model: &Model, dofs: &DofMap, graph: &NodeGraph) -> Result<Csc, FemError> {
    let num_nodes = model.mesh.num_nodes();
    let rows_of = |n: usize, c: usize| {
        std::iter::once(n)
            .chain(graph.neighbours(n).iter().copied().filter(move |&m| m > n))
            .flat_map(|m| [2 * m, 2 * m + 1])
            .filter(move |&g| g >= 2 * n + c)
            .filter_map(|g| free_index(dofs, g))
    };
    let nf = dofs.num_free();
    let mut col_ptr = vec![0usize; nf + 1];
    for n in 0..num_nodes {
        for c in 0..2 {
            if let Some(j) = free_index(dofs, 2 * n + c) {
                col_ptr[j + 1] = rows_of(n, c).count();
            }
        }
    }
    for j in 0..nf {
        col_ptr[j + 1] += col_ptr[j];
    }
    let nnz = col_ptr[nf];
    let mut row_idx = vec![0usize; nnz];
    let mut per_node: Vec<(usize, &mut [usize])> = Vec::with_capacity(num_nodes);
    let mut rest = row_idx.as_mut_slice();
    for n in 0..num_nodes {
        let len: usize = (0..2).filter_map(|c| free_index(dofs, 2 * n + c)).map(|j| col_ptr[j + 1] - col_ptr[j]).sum();
        let (head, tail) = rest.split_at_mut(len);
        per_node.push((n, head));
        rest = tail;
    }
    per_node.into_par_iter().for_each(|(n, out)| {
        let rows = (0..2).filter(|&c| free_index(dofs, 2 * n + c).is_some()).flat_map(|c| rows_of(n, c));
        for (slot, r) in out.iter_mut().zip(rows) {
            *slot = r;
        }
    });

    // Values, by column blocks of roughly equal nnz.
    let cells: Vec<(usize, usize)> =
        model.bodies.iter().enumerate().flat_map(|(b, body)| (0..body.num_cells()).map(move |i| (b, i))).collect();
    let cell_dofs = |b: usize, i: usize| -> Vec<Option<usize>> {
        model.bodies[b].cell_nodes(i).iter().flat_map(|n| [2 * n.0, 2 * n.0 + 1]).map(|g| free_index(dofs, g)).collect()
    };
    let blocks = 8 * rayon::current_num_threads();
    let mut bounds: Vec<usize> =
        (0..blocks).map(|b| col_ptr.partition_point(|&p| p < nnz * b / blocks).min(nf)).collect();
    bounds.push(nf);
    bounds.dedup();
    let block_of = |j: usize| bounds.partition_point(|&s| s <= j) - 1;
    let mut block_cells: Vec<Vec<usize>> = vec![vec![]; bounds.len().saturating_sub(1)];
    for (c, &(b, i)) in cells.iter().enumerate() {
        let mut touched: Vec<usize> = cell_dofs(b, i).into_iter().flatten().map(block_of).collect();
        touched.sort_unstable();
        touched.dedup();
        for t in touched {
            block_cells[t].push(c);
        }
    }
    let mut values = vec![0.0; nnz];
    let mut work: Vec<(usize, &mut [f64])> = vec![];
    let mut rest = values.as_mut_slice();
    for w in 0..block_cells.len() {
        let (head, tail) = rest.split_at_mut(col_ptr[bounds[w + 1]] - col_ptr[bounds[w]]);
        work.push((w, head));
        rest = tail;
    }
    work.into_par_iter().try_for_each(|(w, vals)| -> Result<(), FemError> {
        let (first, last, base) = (bounds[w], bounds[w + 1], col_ptr[bounds[w]]);
        for &c in &block_cells[w] {
            let (b, i) = cells[c];
            let k_e = crate::cell_matrix::element_matrix(model, dofs, b, i)?;
            let idx = cell_dofs(b, i);
            for (a, col) in idx.iter().enumerate() {
                let Some(col) = *col else { continue };
                if col < first || col >= last {
                    continue;
                }
                let rows = &row_idx[col_ptr[col]..col_ptr[col + 1]];
                let v = &mut vals[col_ptr[col] - base..col_ptr[col + 1] - base];
                for (bb, row) in idx.iter().enumerate() {
                    let Some(row) = *row else { continue };
                    if row >= col {
                        let pos = rows.binary_search(&row).map_err(|_| {
                            FemError::Factorization(format!("assembly: ({row}, {col}) not in the pattern"))
                        })?;
                        v[pos] += k_e[(bb, a)];
                    }
                }
            }
        }
        Ok(())
    })?;
    let symbolic = SymbolicSparseColMat::new_checked(nf, nf, col_ptr, None, row_idx);
    Ok(Csc::new(symbolic, values))
}

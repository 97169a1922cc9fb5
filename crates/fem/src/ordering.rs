//! Fill-reducing orderings of the free DOFs for the Cholesky factorisation.
//!
//! ```text
//! Amd:               faer's approximate minimum degree on the DOF graph of K_ff
//! NodeAmd:           the same on the node graph (nodes with a free DOF, ~ if they share a cell),
//!                    each node's DOFs then together: a quarter of the entries for AMD to read
//! NestedDissection:  geometric nested dissection of the node graph (nodes ~ if they share a cell):
//!   dissect(V): |V| ≤ 128 → minimum degree on V's graph (the surrounding separators counted)
//!               else for both axes: split V at the median coordinate into A | B, separator S =
//!               the nodes of one side with a neighbour on the other (the smaller side's set);
//!               keep the axis with the smaller S;  order dissect(A∖S), dissect(B∖S), then S
//! both DOFs of a node stay together; DOFs listed as `last` (e.g. the contact DOFs) are ordered
//! after all others, so that L's trailing block holds the Schur complement on them.
//! ```
//!
//! A permutation is `forward[new] = old` over the free indices.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::AtomicU8;
use std::sync::atomic::Ordering::Relaxed;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::SymbolicSparseColMat;
use faer::sparse::linalg::amd;
use rayon::prelude::*;

use crate::dof::{Dof, DofKind, DofMap};
use crate::error::FemError;
use crate::model::Model;
use crate::sparse::Csc;

/// The fill-reducing ordering used by [`crate::CholeskySolver`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ordering {
    /// Approximate minimum degree on the DOF graph (faer's). The default: it fills least on the
    /// graded, unstructured meshes of the contact problems (docs/benchmarks.md).
    #[default]
    Amd,
    /// Geometric nested dissection on the node graph (needs the node coordinates): 7–12 % less
    /// fill and 20 % fewer flops than AMD on large structured meshes.
    NestedDissection,
    /// Approximate minimum degree (faer's) on the node graph, both DOFs of a node together: the
    /// graph AMD reads has a quarter of the DOF graph's entries (docs/benchmarks.md, "10⁶ DOFs").
    NodeAmd,
}

/// Node sets of at most this many nodes are ordered by minimum degree instead of dissected.
const LEAF: usize = 128;

/// The node graph in compressed form: the neighbours of node `n` (itself excluded) are
/// `adj[ptr[n]..ptr[n + 1]]`, sorted.
#[derive(Debug, Clone)]
pub(crate) struct NodeGraph {
    pub(crate) ptr: Vec<usize>,
    pub(crate) adj: Vec<usize>,
}

impl NodeGraph {
    /// Nodes that share a cell of any body are neighbours.
    pub(crate) fn of_model(model: &Model) -> NodeGraph {
        let num_nodes = model.mesh.num_nodes();
        let cells: Vec<(usize, usize)> =
            model.bodies.iter().enumerate().flat_map(|(b, body)| (0..body.num_cells()).map(move |i| (b, i))).collect();
        let mut cell_ptr = vec![0usize; num_nodes + 1];
        for &(b, i) in &cells {
            for n in model.bodies[b].cell_nodes(i) {
                cell_ptr[n.0 + 1] += 1;
            }
        }
        for i in 0..num_nodes {
            cell_ptr[i + 1] += cell_ptr[i];
        }
        let mut next = cell_ptr.clone();
        let mut node_cells = vec![0usize; cell_ptr[num_nodes]];
        for (c, &(b, i)) in cells.iter().enumerate() {
            for n in model.bodies[b].cell_nodes(i) {
                node_cells[next[n.0]] = c;
                next[n.0] += 1;
            }
        }
        let lists: Vec<Vec<usize>> = (0..num_nodes)
            .into_par_iter()
            .map(|n| {
                let mut v: Vec<usize> = node_cells[cell_ptr[n]..cell_ptr[n + 1]]
                    .iter()
                    .flat_map(|&c| model.bodies[cells[c].0].cell_nodes(cells[c].1).iter().map(|m| m.0))
                    .filter(|&m| m != n)
                    .collect();
                v.sort_unstable();
                v.dedup();
                v
            })
            .collect();
        let mut ptr = Vec::with_capacity(num_nodes + 1);
        ptr.push(0);
        let mut adj = Vec::with_capacity(lists.iter().map(Vec::len).sum());
        for v in lists {
            adj.extend_from_slice(&v);
            ptr.push(adj.len());
        }
        NodeGraph { ptr, adj }
    }

    /// The neighbours of node `n`.
    pub(crate) fn neighbours(&self, n: usize) -> &[usize] {
        &self.adj[self.ptr[n]..self.ptr[n + 1]]
    }
}

/// A fill-reducing permutation of the free DOFs of `model` (`forward[new] = old`), with the free
/// DOFs `last` (and the other free DOF of their nodes, for nested dissection) at the end in the
/// order given.
///
/// # Errors
/// [`FemError::InvalidInput`] for an index in `last` that is not a free DOF;
/// [`FemError::Factorization`] if AMD fails (out of memory).
pub fn fill_reducing_permutation(
    model: &Model,
    dofs: &DofMap,
    stiffness: &Csc,
    ordering: Ordering,
    last: &[usize],
) -> Result<Vec<usize>, FemError> {
    let nf = dofs.num_free();
    if let Some(bad) = last.iter().find(|&&i| i >= nf) {
        return Err(FemError::InvalidInput(format!("ordering: free index {bad} out of range ({nf} free DOFs)")));
    }
    match ordering {
        Ordering::Amd => amd_with_last(stiffness, last),
        Ordering::NestedDissection | Ordering::NodeAmd => {
            let mut tail: Vec<usize> = vec![];
            let mut seen = HashSet::new();
            for &i in last {
                let node = dofs.free_dofs()[i].node();
                if seen.insert(node) {
                    tail.push(node);
                }
            }
            if ordering == Ordering::NodeAmd {
                node_amd(model, dofs, &tail)
            } else {
                Ok(nested_dissection(model, dofs, &tail))
            }
        }
    }
}

/// faer's AMD on the graph of the nodes with a free DOF (the nodes `tail` left out and ordered
/// last), each node's free DOFs together.
fn node_amd(model: &Model, dofs: &DofMap, tail: &[usize]) -> Result<Vec<usize>, FemError> {
    let graph = NodeGraph::of_model(model);
    let num_nodes = model.mesh.num_nodes();
    let mut index = vec![usize::MAX; num_nodes];
    let mut nodes = Vec::new();
    let in_tail: HashSet<usize> = tail.iter().copied().collect();
    for (n, slot) in index.iter_mut().enumerate() {
        let free = free_index(dofs, 2 * n).is_some() || free_index(dofs, 2 * n + 1).is_some();
        if free && !in_tail.contains(&n) {
            *slot = nodes.len();
            nodes.push(n);
        }
    }
    let mut col_ptr = Vec::with_capacity(nodes.len() + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::with_capacity(graph.adj.len());
    for &n in &nodes {
        row_idx.extend(graph.neighbours(n).iter().map(|&m| index[m]).filter(|&i| i != usize::MAX));
        col_ptr.push(row_idx.len());
    }
    let m = nodes.len();
    let fwd = amd_order(m, col_ptr, row_idx)?;
    let mut order: Vec<usize> = fwd.iter().map(|&i| nodes[i]).collect();
    order.extend_from_slice(tail);
    Ok(dofs_of_nodes(&order, dofs))
}

/// Free index of global DOF `g`, if it is free.
fn free_index(dofs: &DofMap, g: usize) -> Option<usize> {
    match dofs.kind(Dof(g)) {
        DofKind::Free(i) => Some(i),
        _ => None,
    }
}

/// The free DOFs of the nodes in `order`, each node's together.
fn dofs_of_nodes(order: &[usize], dofs: &DofMap) -> Vec<usize> {
    order.iter().flat_map(|&n| [2 * n, 2 * n + 1]).filter_map(|g| free_index(dofs, g)).collect()
}

/// Nested dissection of the nodes with free DOFs, the nodes `tail` ordered last.
fn nested_dissection(model: &Model, dofs: &DofMap, tail: &[usize]) -> Vec<usize> {
    let graph = NodeGraph::of_model(model);
    let points = &model.mesh.points;
    let num_nodes = points.len();
    let mut excluded = vec![false; num_nodes];
    for &n in tail {
        excluded[n] = true;
    }
    let nodes: Vec<usize> = (0..num_nodes)
        .filter(|&n| !excluded[n] && (free_index(dofs, 2 * n).is_some() || free_index(dofs, 2 * n + 1).is_some()))
        .collect();
    // mark[n]: 0 = not in a set being split, 1 / 2 = side A / B of the current split. Sets split
    // at the same time (in parallel) are disjoint and not adjacent, so they never read each
    // other's marks.
    let mark: Vec<AtomicU8> = (0..num_nodes).map(|_| AtomicU8::new(0)).collect();
    let mut order = dissect(&graph, points, nodes, &mark);
    order.extend_from_slice(tail);
    dofs_of_nodes(&order, dofs)
}

/// Sets larger than this are dissected with their two halves in parallel.
const PARALLEL: usize = 20_000;

/// The nested-dissection order of `nodes`: `dissect(first) dissect(second) separator`.
fn dissect(graph: &NodeGraph, points: &[[f64; 2]], nodes: Vec<usize>, mark: &[AtomicU8]) -> Vec<usize> {
    if nodes.len() <= LEAF {
        return minimum_degree(graph, &nodes);
    }
    let best = [0, 1].into_iter().filter_map(|axis| split(graph, points, &nodes, axis, mark)).min_by_key(|s| s.2.len());
    let Some((first, second, sep)) = best else {
        // All nodes at one point (not a valid mesh): any order.
        return nodes;
    };
    let (mut order, rest) = if nodes.len() > PARALLEL {
        rayon::join(|| dissect(graph, points, first, mark), || dissect(graph, points, second, mark))
    } else {
        (dissect(graph, points, first, mark), dissect(graph, points, second, mark))
    };
    order.extend(rest);
    order.extend(sep);
    order
}

/// Splits `nodes` at the median of coordinate `axis`: `(first part, second part, separator)`, or
/// `None` if all nodes share the median coordinate.
fn split(
    graph: &NodeGraph,
    points: &[[f64; 2]],
    nodes: &[usize],
    axis: usize,
    mark: &[AtomicU8],
) -> Option<(Vec<usize>, Vec<usize>, Vec<usize>)> {
    let mut sorted = nodes.to_vec();
    let mid = sorted.len() / 2;
    sorted.select_nth_unstable_by(mid, |&a, &b| points[a][axis].total_cmp(&points[b][axis]));
    let cut = points[sorted[mid]][axis];
    let (a, b): (Vec<usize>, Vec<usize>) = nodes.iter().partition(|&&n| points[n][axis] < cut);
    if a.is_empty() || b.is_empty() {
        return None;
    }
    let set = |n: usize, v: u8| mark[n].store(v, Relaxed);
    a.iter().for_each(|&n| set(n, 1));
    b.iter().for_each(|&n| set(n, 2));
    let touches = |n: usize, other: u8| graph.neighbours(n).iter().any(|&m| mark[m].load(Relaxed) == other);
    let (sep_a, inner_a): (Vec<usize>, Vec<usize>) = a.iter().partition(|&&n| touches(n, 2));
    let (sep_b, inner_b): (Vec<usize>, Vec<usize>) = b.iter().partition(|&&n| touches(n, 1));
    nodes.iter().for_each(|&n| set(n, 0));
    Some(if sep_a.len() <= sep_b.len() { (inner_a, b, sep_a) } else { (a, inner_b, sep_b) })
}

/// Exact minimum degree on the nodes `nodes` (at most a few hundred): eliminate the node of least
/// degree, join its neighbours into a clique, repeat. Neighbours outside `nodes` (the separators
/// around them, ordered later) count in the degrees and receive fill but are not eliminated.
fn minimum_degree(graph: &NodeGraph, nodes: &[usize]) -> Vec<usize> {
    let k = nodes.len();
    if k <= 2 {
        return nodes.to_vec();
    }
    // Local indices: the nodes first, then their outside neighbours.
    let mut index = HashMap::with_capacity(2 * k);
    for (i, &n) in nodes.iter().enumerate() {
        index.insert(n, i);
    }
    let mut all = nodes.to_vec();
    for &n in nodes {
        for &m in graph.neighbours(n) {
            if let std::collections::hash_map::Entry::Vacant(e) = index.entry(m) {
                e.insert(all.len());
                all.push(m);
            }
        }
    }
    let total = all.len();
    let words = total.div_ceil(64);
    let mut adj = vec![0u64; total * words];
    for (i, &n) in all.iter().enumerate() {
        for m in graph.neighbours(n) {
            if let Some(&j) = index.get(m) {
                adj[i * words + j / 64] |= 1 << (j % 64);
            }
        }
    }
    let mut alive = vec![true; total];
    let mut order = Vec::with_capacity(k);
    for _ in 0..k {
        let degree = |i: usize| adj[i * words..(i + 1) * words].iter().map(|w| w.count_ones()).sum::<u32>();
        let Some(v) = (0..k).filter(|&i| alive[i]).min_by_key(|&i| degree(i)) else { break };
        alive[v] = false;
        order.push(nodes[v]);
        let row: Vec<u64> = adj[v * words..(v + 1) * words].to_vec();
        for (u, live) in alive.iter().enumerate() {
            if *live && row[u / 64] >> (u % 64) & 1 == 1 {
                for w in 0..words {
                    adj[u * words + w] |= row[w];
                }
                adj[u * words + u / 64] &= !(1 << (u % 64));
                adj[u * words + v / 64] &= !(1 << (v % 64));
            }
        }
    }
    order
}

/// Unknowns from which [`crate::CholeskySolver`] orders `K` with each pair of twin columns
/// merged ([`twin_compressed_amd`]): AMD on the DOF graph takes 0.65 s at 10⁶ DOFs, and the
/// merged graph has a quarter of its entries (the same `L`, docs/benchmarks.md). Below, AMD
/// costs under 0.1 s and the plain DOF graph's order is kept (every factor of the flagship and
/// of the verification cases is the one their tables were produced with). The bordered and
/// saddle-point patterns keep plain AMD at every size: merged, the 5,001-pair press's state
/// factorisations took 5 % longer (measured).
pub const COMPRESS_FROM: usize = 200_000;

/// faer's AMD on the pattern of `k` (`forward[new] = old`).
///
/// # Errors
/// [`FemError::Factorization`] if AMD fails (out of memory).
pub(crate) fn fill_reducing_permutation_of_pattern(k: &Csc) -> Result<Vec<usize>, FemError> {
    amd_with_last(k, &[])
}

/// faer's AMD on the pattern of `k` (lower triangle, columns sorted) with each pair of twin
/// columns `j, j + 1` merged into one vertex, the pair then kept together:
///
/// ```text
/// twins(j, j+1):  rows(col j) = {j} ∪ rows(col j+1)  and  cols(row j+1) = {j} ∪ cols(row j)
///                 (both DOFs of a node: the same neighbours; the columns above a row
///                 compared by count and a 64-bit hash)
/// quotient:       vertex per twin pair or single column, edges of the pattern mapped onto them
/// ```
///
/// Any order is a valid elimination order; the merge only changes what AMD reads (a quarter of
/// the entries of a 2D mesh's DOF graph) and keeps a node's DOFs together, as
/// [`Ordering::NodeAmd`] does from the mesh. A hash collision could merge two columns that are
/// not twins: that may cost fill, never correctness.
///
/// # Errors
/// [`FemError::Factorization`] if AMD fails (out of memory).
pub fn twin_compressed_amd(k: &Csc) -> Result<Vec<usize>, FemError> {
    let (n, k) = (k.nrows(), k.as_ref());
    let rows = |j: usize| k.row_idx_of_col(j);
    // The columns above each row's diagonal, as a count and an order-free hash (the upper
    // triangle is not stored): twins' upper parts must agree but for the twin itself.
    let mix = |i: usize| {
        let mut z = (i as u64).wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let mut above = vec![(0usize, 0u64); n];
    for j in 0..n {
        for i in rows(j).filter(|&i| i > j) {
            above[i] = (above[i].0 + 1, above[i].1.wrapping_add(mix(j)));
        }
    }
    let twins = |j: usize| {
        let (mut a, b) = (rows(j), rows(j + 1));
        let (upper, next) = (above[j], above[j + 1]);
        a.next() == Some(j) && a.eq(b) && next.0 == upper.0 + 1 && next.1.wrapping_sub(mix(j)) == upper.1
    };
    // group[j]: the vertex of column j; members: the first column of each vertex, and its size.
    let mut group = vec![0usize; n];
    let mut first = Vec::with_capacity(n);
    let mut j = 0;
    while j < n {
        let size = if j + 1 < n && twins(j) { 2 } else { 1 };
        group[j..j + size].iter_mut().for_each(|g| *g = first.len());
        first.push(j);
        j += size;
    }
    let m = first.len();
    let mut col_ptr = Vec::with_capacity(m + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::with_capacity(k.compute_nnz() / 2);
    // A twin's second column is its first's rows less one: the first's rows give the vertex's.
    let mut seen_by = vec![usize::MAX; m];
    for (v, &j) in first.iter().enumerate() {
        for i in rows(j) {
            let g = group[i];
            if seen_by[g] != v {
                seen_by[g] = v;
                row_idx.push(g);
            }
        }
        col_ptr.push(row_idx.len());
    }
    let order = amd_order(m, col_ptr, row_idx)?;
    let mut forward = Vec::with_capacity(n);
    for g in order {
        let j = first[g];
        forward.push(j);
        if group.get(j + 1) == Some(&g) {
            forward.push(j + 1);
        }
    }
    Ok(forward)
}

/// faer's AMD on the DOF graph of `K_ff` without the DOFs `last`, then `last`.
fn amd_with_last(stiffness: &Csc, last: &[usize]) -> Result<Vec<usize>, FemError> {
    let n = stiffness.nrows();
    let mut is_last = vec![false; n];
    for &i in last {
        is_last[i] = true;
    }
    // Sub-matrix pattern of the remaining DOFs, renumbered 0..n_rest.
    let mut new_index = vec![usize::MAX; n];
    let mut rest = Vec::with_capacity(n);
    for (i, l) in is_last.iter().enumerate() {
        if !l {
            new_index[i] = rest.len();
            rest.push(i);
        }
    }
    let k = stiffness.as_ref();
    let mut col_ptr = Vec::with_capacity(rest.len() + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::with_capacity(k.compute_nnz());
    for &j in &rest {
        row_idx.extend(k.row_idx_of_col(j).map(|i| new_index[i]).filter(|&i| i != usize::MAX));
        col_ptr.push(row_idx.len());
    }
    let m = rest.len();
    let fwd = amd_order(m, col_ptr, row_idx)?;
    let mut seen = vec![false; n];
    let mut forward: Vec<usize> = fwd.iter().map(|&i| rest[i]).collect();
    for &i in last {
        if !std::mem::replace(&mut seen[i], true) {
            forward.push(i);
        }
    }
    Ok(forward)
}

/// faer's AMD order (`forward[new] = old`) of the `m × m` pattern given by columns.
fn amd_order(m: usize, col_ptr: Vec<usize>, row_idx: Vec<usize>) -> Result<Vec<usize>, FemError> {
    let pattern = SymbolicSparseColMat::new_checked(m, m, col_ptr, None, row_idx);
    let (mut fwd, mut inv) = (vec![0usize; m], vec![0usize; m]);
    let mut mem = MemBuffer::try_new(amd::order_maybe_unsorted_scratch::<usize>(m, pattern.compute_nnz()))
        .map_err(|e| FemError::Factorization(format!("AMD workspace: {e:?}")))?;
    amd::order_maybe_unsorted(&mut fwd, &mut inv, pattern.as_ref(), Default::default(), MemStack::new(&mut mem))
        .map_err(|e| FemError::Factorization(format!("AMD: {e:?}")))?;
    Ok(fwd)
}

/// Whether `forward` is a permutation of `0..n`.
pub(crate) fn is_permutation(forward: &[usize], n: usize) -> bool {
    let mut seen = vec![false; n];
    forward.len() == n && forward.iter().all(|&i| i < n && !std::mem::replace(&mut seen[i], true))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use faer::sparse::{SparseColMat, Triplet};

    use super::*;
    use crate::test_matrices::grid_laplacian;

    /// The grid's pattern with two unknowns per grid point (`2p`, `2p + 1`, coupled to each
    /// other and to both of every neighbour's): a 2D mesh's DOF graph.
    fn two_per_node(grid: &Csc) -> Csc {
        let g = grid.as_ref();
        let mut t = vec![];
        for j in 0..g.ncols() {
            for i in g.row_idx_of_col(j) {
                for (a, b) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                    let (r, c) = (2 * i + a, 2 * j + b);
                    if r >= c {
                        t.push(Triplet::new(r, c, 1.0));
                    }
                }
            }
        }
        SparseColMat::try_new_from_triplets(2 * g.nrows(), 2 * g.ncols(), &t).expect("valid triplets")
    }

    /// Without twins the merged pattern is the pattern itself: the same order as plain AMD. With
    /// two unknowns per point the merged pattern is the grid's: its AMD order, each point's two
    /// unknowns together (exact: the same graph handed to the same AMD).
    #[test]
    fn twin_columns_are_ordered_as_their_shared_vertex() {
        let grid = grid_laplacian(9, 0.0);
        assert_eq!(twin_compressed_amd(&grid).unwrap(), amd_with_last(&grid, &[]).unwrap());
        let points = amd_with_last(&grid, &[]).unwrap();
        let expected: Vec<usize> = points.iter().flat_map(|&p| [2 * p, 2 * p + 1]).collect();
        assert_eq!(twin_compressed_amd(&two_per_node(&grid)).unwrap(), expected);
    }
}

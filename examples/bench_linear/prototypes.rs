//! Prototypes for `bench_linear`: what a change in `contact2d-fem` would gain, measured on the
//! same model. Nothing here is library code; each item names the library function it stands in for.

use std::collections::HashMap;
use std::time::Instant;

use anyhow::{Result, anyhow, bail};
use contact2d_element::{EdgeType, ElementType, GaussRule, edge_traction_load, element_stiffness};
use contact2d_fem::{Body, Csc, Dof, DofKind, DofMap, Model, assemble, check_rigid_modes};
use contact2d_mesh::NodeId;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::amd;
use faer::sparse::{Pair, SymbolicSparseColMat, Triplet};
use nalgebra::{Matrix3, Vector3};
use rayon::prelude::*;

/// The free part of the consistent load of the unit downward traction on "right"
/// (the prototype handles zero prescribed values only, which is this model's case).
pub(crate) fn tip_load(model: &Model, dofs: &DofMap) -> Result<Vec<f64>> {
    if dofs.prescribed_values().iter().any(|v| *v != 0.0) {
        bail!("the prototype assembly assumes zero prescribed values");
    }
    let mut f = vec![0.0; dofs.num_global()];
    for block in model.mesh.blocks_in_group("right")? {
        let edge = if block.kind == contact2d_mesh::CellKind::Line2 { EdgeType::Line2 } else { EdgeType::Line3 };
        for cell in block.cells() {
            let coords: Vec<[f64; 2]> = cell.iter().map(|n| model.mesh.points[n.0]).collect();
            let fe = edge_traction_load(edge, &coords, 1.0, 3, |_, _| [0.0, -1.0])?;
            for (a, node) in cell.iter().enumerate() {
                f[2 * node.0] += fe[2 * a];
                f[2 * node.0 + 1] += fe[2 * a + 1];
            }
        }
    }
    Ok(dofs.restrict_free(&f))
}

/// `(body, cell)` of every cell of every body.
fn all_cells(model: &Model) -> Vec<(usize, usize)> {
    model.bodies.iter().enumerate().flat_map(|(b, body)| (0..body.num_cells()).map(move |i| (b, i))).collect()
}

/// Free index of global DOF `g`, if it is free.
fn free_index(dofs: &DofMap, g: usize) -> Option<usize> {
    match dofs.kind(Dof(g)) {
        DofKind::Free(i) => Some(i),
        _ => None,
    }
}

/// Free index of each DOF of a cell, in element order.
fn cell_free_indices(dofs: &DofMap, nodes: &[NodeId]) -> Vec<Option<usize>> {
    nodes.iter().flat_map(|n| [2 * n.0, 2 * n.0 + 1]).map(|g| free_index(dofs, g)).collect()
}

/// The sorted neighbours of each node: the nodes sharing a cell with it, itself included.
fn node_graph(model: &Model, cells: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let num_nodes = model.mesh.num_nodes();
    let mut cell_ptr = vec![0usize; num_nodes + 1];
    for &(b, i) in cells {
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
    (0..num_nodes)
        .into_par_iter()
        .map(|n| {
            let mut v: Vec<usize> = node_cells[cell_ptr[n]..cell_ptr[n + 1]]
                .iter()
                .flat_map(|&c| model.bodies[cells[c].0].cell_nodes(cells[c].1).iter().map(|m| m.0))
                .collect();
            v.sort_unstable();
            v.dedup();
            v
        })
        .collect()
}

/// Prototype assembly of `K_ff` (lower triangle) without triplets.
///
/// ```text
/// 1. node graph: nodes m ~ n iff they share a cell
/// 2. pattern: column of free DOF (n, c) holds the free DOFs (m, c') ≥ (n, c) with m ~ n; rows come
///    out sorted because free indices grow with the global DOF 2 m + c'
/// 3. values: columns split into blocks of equal nnz; each block (in parallel, owning its slice of
///    values) computes the matrices of the cells touching its columns and adds them in place,
///    finding each row by binary search in its column
/// ```
pub(crate) fn assemble_pattern(model: &Model, dofs: &DofMap) -> Result<Csc> {
    let cells = all_cells(model);
    let num_nodes = model.mesh.num_nodes();
    let neighbours = node_graph(model, &cells);

    // 2. Column pattern, node by node (a node's free DOFs are consecutive columns).
    let rows_of = |n: usize, c: usize| {
        neighbours[n]
            .iter()
            .filter(move |&&m| m >= n)
            .flat_map(|&m| [2 * m, 2 * m + 1])
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
    drop(neighbours);

    // 3. Values, by column blocks of roughly equal nnz.
    let blocks = 8 * rayon::current_num_threads();
    let mut bounds: Vec<usize> =
        (0..blocks).map(|b| col_ptr.partition_point(|&p| p < nnz * b / blocks).min(nf)).collect();
    bounds.push(nf);
    bounds.dedup();
    let block_of = |j: usize| bounds.partition_point(|&s| s <= j) - 1;
    let mut block_cells: Vec<Vec<usize>> = vec![vec![]; bounds.len() - 1];
    for (c, &(b, i)) in cells.iter().enumerate() {
        let mut touched: Vec<usize> =
            cell_free_indices(dofs, model.bodies[b].cell_nodes(i)).into_iter().flatten().map(block_of).collect();
        touched.sort_unstable();
        touched.dedup();
        for t in touched {
            block_cells[t].push(c);
        }
    }
    let rules: Vec<GaussRule> = ElementType::ALL.iter().map(|&t| GaussRule::stiffness_rule(t)).collect();
    let mut values = vec![0.0; nnz];
    let mut work: Vec<(usize, &mut [f64])> = vec![];
    let mut rest = values.as_mut_slice();
    for w in 0..bounds.len() - 1 {
        let (head, tail) = rest.split_at_mut(col_ptr[bounds[w + 1]] - col_ptr[bounds[w]]);
        work.push((w, head));
        rest = tail;
    }
    work.into_par_iter().try_for_each(|(w, vals)| -> Result<()> {
        let (first, last, base) = (bounds[w], bounds[w + 1], col_ptr[bounds[w]]);
        for &c in &block_cells[w] {
            let (b, i) = cells[c];
            let body = &model.bodies[b];
            let element = body.elements[i];
            let rule = &rules[ElementType::ALL.iter().position(|&t| t == element).unwrap_or(0)];
            let coords = body.cell_coords(&model.mesh, i);
            let k_e = element_stiffness(element, &coords, &body.material, body.thickness, rule)?;
            let idx = cell_free_indices(dofs, body.cell_nodes(i));
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
                        let pos = rows.binary_search(&row).map_err(|_| anyhow!("({row}, {col}) not in pattern"))?;
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

/// Prototype fill-reducing ordering: geometric nested dissection of the node graph.
///
/// ```text
/// split the nodes at the median coordinate of the longer side of their bounding box into A | B;
/// separator S = the nodes of one side that have a neighbour on the other (the smaller such set);
/// order: dissect(A \ S), dissect(B), then S;  below 8 nodes: as they come.
/// Each node's free DOFs stay together. Returns (forward, inverse): forward[new] = old.
/// ```
pub(crate) fn nested_dissection(model: &Model, dofs: &DofMap) -> (Vec<usize>, Vec<usize>) {
    let neighbours = node_graph(model, &all_cells(model));
    let points = &model.mesh.points;
    let mut side = vec![0u8; points.len()];
    let mut order = Vec::with_capacity(points.len());
    // Work stack: a node set to dissect, or a separator to emit once both halves are done.
    let mut stack: Vec<(Vec<usize>, bool)> = vec![((0..points.len()).collect(), false)];
    while let Some((mut nodes, is_separator)) = stack.pop() {
        if is_separator || nodes.len() <= 8 {
            order.extend(nodes);
            continue;
        }
        let extent = |k: usize| {
            let (lo, hi) =
                nodes.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &n| (lo.min(points[n][k]), hi.max(points[n][k])));
            hi - lo
        };
        let axis = if extent(0) >= extent(1) { 0 } else { 1 };
        let mid = nodes.len() / 2;
        nodes.select_nth_unstable_by(mid, |&a, &b| points[a][axis].total_cmp(&points[b][axis]));
        let cut = points[nodes[mid]][axis];
        let (a, b): (Vec<usize>, Vec<usize>) = nodes.iter().partition(|&&n| points[n][axis] < cut);
        if a.is_empty() || b.is_empty() {
            order.extend(nodes);
            continue;
        }
        for &n in &a {
            side[n] = 1;
        }
        for &n in &b {
            side[n] = 2;
        }
        let touches = |n: usize, other: u8| neighbours[n].iter().any(|&m| side[m] == other);
        let (sep_a, inner_a): (Vec<usize>, Vec<usize>) = a.iter().partition(|&&n| touches(n, 2));
        let (sep_b, inner_b): (Vec<usize>, Vec<usize>) = b.iter().partition(|&&n| touches(n, 1));
        for &n in &nodes {
            side[n] = 0;
        }
        let (first, second, sep) = if sep_a.len() <= sep_b.len() { (inner_a, b, sep_a) } else { (a, inner_b, sep_b) };
        stack.push((sep, true));
        stack.push((second, false));
        stack.push((first, false));
    }
    dof_permutation(&order, dofs)
}

/// The permutation of the free DOFs `(forward, inverse)`, `forward[new] = old`, that takes the
/// nodes in `order` and each node's free DOFs together.
fn dof_permutation(order: &[usize], dofs: &DofMap) -> (Vec<usize>, Vec<usize>) {
    let forward: Vec<usize> =
        order.iter().flat_map(|&n| [2 * n, 2 * n + 1]).filter_map(|g| free_index(dofs, g)).collect();
    let mut inverse = vec![0; forward.len()];
    for (new, &old) in forward.iter().enumerate() {
        inverse[old] = new;
    }
    (forward, inverse)
}

/// Prototype ordering: faer's AMD on the node graph (half the vertices and a quarter of the
/// edges of the DOF graph), each node's free DOFs kept together.
pub(crate) fn node_amd(model: &Model, dofs: &DofMap) -> Result<(Vec<usize>, Vec<usize>)> {
    let neighbours = node_graph(model, &all_cells(model));
    let n = neighbours.len();
    let mut col_ptr = Vec::with_capacity(n + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::with_capacity(neighbours.iter().map(Vec::len).sum());
    for v in &neighbours {
        row_idx.extend_from_slice(v);
        col_ptr.push(row_idx.len());
    }
    let graph = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
    let (mut order, mut inverse) = (vec![0usize; n], vec![0usize; n]);
    let mut mem = MemBuffer::try_new(amd::order_scratch::<usize>(n, graph.compute_nnz()))
        .map_err(|e| anyhow!("AMD workspace: {e:?}"))?;
    amd::order(&mut order, &mut inverse, graph.as_ref(), Default::default(), MemStack::new(&mut mem))
        .map_err(|e| anyhow!("AMD: {e:?}"))?;
    Ok(dof_permutation(&order, dofs))
}

/// Times the pieces of `assemble` one by one, then the triplet sort and a refill of a kept pattern.
pub(crate) fn breakdown(model: &Model) -> Result<()> {
    let time = |name: &str, start: Instant| println!("{name:<52} {:>8.3} s", start.elapsed().as_secs_f64());
    let t = Instant::now();
    let dofs = model.dof_map()?;
    time("dof_map", t);
    let t = Instant::now();
    check_rigid_modes(model, &dofs)?;
    time("check_rigid_modes", t);
    let t = Instant::now();
    check_rigid_modes_fast(model, &dofs)?;
    time("  prototype check_rigid_modes_fast (Vec union-find)", t);
    // The free-free triplets exactly as `assemble` makes them (chunks of 256 cells in parallel).
    let t = Instant::now();
    let cells = all_cells(model);
    let chunks: Vec<Vec<Triplet<usize, usize, f64>>> = cells
        .par_chunks(256)
        .map(|chunk| -> Result<_> {
            let mut out = vec![];
            for &(b, i) in chunk {
                let body = &model.bodies[b];
                let element = body.elements[i];
                let rule = GaussRule::stiffness_rule(element);
                let k_e = element_stiffness(
                    element,
                    &body.cell_coords(&model.mesh, i),
                    &body.material,
                    body.thickness,
                    &rule,
                )?;
                let idx = cell_free_indices(&dofs, body.cell_nodes(i));
                for (col, c) in idx.iter().enumerate() {
                    for (row, r) in idx.iter().enumerate() {
                        if let (Some(r), Some(c)) = (r, c)
                            && r >= c
                        {
                            out.push(Triplet::new(*r, *c, k_e[(row, col)]));
                        }
                    }
                }
            }
            Ok(out)
        })
        .collect::<Result<_>>()?;
    let triplets: Vec<Triplet<usize, usize, f64>> = chunks.concat();
    time("element matrices + K_ff triplets (parallel)", t);
    let nf = dofs.num_free();
    let t = Instant::now();
    let k = Csc::try_new_from_triplets(nf, nf, &triplets).map_err(|e| anyhow!("{e:?}"))?;
    time(&format!("try_new_from_triplets ({} triplets → {} nnz)", triplets.len(), k.compute_nnz()), t);
    let t = Instant::now();
    let pairs: Vec<Pair<usize, usize>> = triplets.iter().map(|t| Pair::new(t.row, t.col)).collect();
    let (pattern, argsort) =
        SymbolicSparseColMat::try_new_from_indices(nf, nf, &pairs).map_err(|e| anyhow!("{e:?}"))?;
    time("  of which symbolic (try_new_from_indices)", t);
    let values: Vec<f64> = triplets.iter().map(|t| t.val).collect();
    let t = Instant::now();
    let refill = Csc::new_from_argsort(pattern, &argsort, &values).map_err(|e| anyhow!("{e:?}"))?;
    time("refill of the kept pattern (new_from_argsort)", t);
    debug_assert_eq!(refill.compute_nnz(), k.compute_nnz());
    let t = Instant::now();
    let system = assemble(model)?;
    time("assemble (all of the above, K_fc, K_cc, edge loads)", t);
    drop(system);
    let t = Instant::now();
    let k = assemble_pattern(model, &dofs)?;
    time("prototype assemble_pattern (K_ff only)", t);
    drop(k);
    Ok(())
}

/// Connected pieces of one body's nodes: union-find on a `Vec` indexed by node (union by size,
/// path halving), where `check_rigid_modes` walks `HashMap` chains that grow with the mesh.
/// Returns the root of each node (`usize::MAX` for nodes outside the body).
fn connected_pieces(body: &Body, num_nodes: usize) -> Vec<usize> {
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    let (mut parent, mut size): (Vec<usize>, Vec<usize>) = ((0..num_nodes).collect(), vec![1; num_nodes]);
    let mut active = vec![false; num_nodes];
    for i in 0..body.num_cells() {
        let nodes = body.cell_nodes(i);
        for m in nodes {
            active[m.0] = true;
            let (a, b) = (find(&mut parent, nodes[0].0), find(&mut parent, m.0));
            if a != b {
                let (big, small) = if size[a] >= size[b] { (a, b) } else { (b, a) };
                parent[small] = big;
                size[big] += size[small];
            }
        }
    }
    (0..num_nodes).map(|x| if active[x] { find(&mut parent, x) } else { usize::MAX }).collect()
}

/// Prototype of `check_rigid_modes` with [`connected_pieces`]; the same rank test per piece.
///
/// ```text
/// constrained u1 at x: row [1, 0, -y];  constrained u2: row [0, 1, x]   (x, y centred and scaled)
/// the piece is held iff Σ rowᵀ row has rank 3
/// ```
pub(crate) fn check_rigid_modes_fast(model: &Model, dofs: &DofMap) -> Result<()> {
    let points = &model.mesh.points;
    for body in &model.bodies {
        let root = connected_pieces(body, points.len());
        // Centre and scale of each piece, then its normal matrix.
        let mut centre: HashMap<usize, ([f64; 2], f64, f64)> = HashMap::new();
        for (n, &r) in root.iter().enumerate().filter(|(_, r)| **r != usize::MAX) {
            let e = centre.entry(r).or_insert(([0.0; 2], 0.0, 0.0));
            e.0 = [e.0[0] + points[n][0], e.0[1] + points[n][1]];
            e.1 += 1.0;
        }
        for e in centre.values_mut() {
            e.0 = [e.0[0] / e.1, e.0[1] / e.1];
        }
        for (n, &r) in root.iter().enumerate().filter(|(_, r)| **r != usize::MAX) {
            let Some(e) = centre.get_mut(&r) else { continue };
            e.2 = e.2.max((points[n][0] - e.0[0]).hypot(points[n][1] - e.0[1]));
        }
        let mut normal: HashMap<usize, Matrix3<f64>> = centre.keys().map(|&r| (r, Matrix3::zeros())).collect();
        for (n, &r) in root.iter().enumerate().filter(|(_, r)| **r != usize::MAX) {
            let (Some((c, _, scale)), Some(m)) = (centre.get(&r), normal.get_mut(&r)) else { continue };
            let scale = scale.max(f64::MIN_POSITIVE);
            let (x, y) = ((points[n][0] - c[0]) / scale, (points[n][1] - c[1]) / scale);
            for (g, row) in [(2 * n, [1.0, 0.0, -y]), (2 * n + 1, [0.0, 1.0, x])] {
                if matches!(dofs.kind(Dof(g)), DofKind::Constrained(_)) {
                    let v = Vector3::from(row);
                    *m += v * v.transpose();
                }
            }
        }
        for (r, m) in normal {
            let eig = m.symmetric_eigenvalues();
            let largest = eig.max().max(f64::MIN_POSITIVE);
            let rank = eig.iter().filter(|&&e| e > 1e-10 * largest && e > 1e-14).count();
            if rank < 3 {
                bail!("body \"{}\": piece of node {r} has {} free rigid mode(s)", body.name, 3 - rank);
            }
        }
    }
    Ok(())
}

/// Compares the prototype's `K_ff` with `assemble`'s, entry by entry.
pub(crate) fn verify_against_crate(model: &Model, k: &Csc) -> Result<()> {
    let reference = assemble(model)?.stiffness;
    let (a, b) = (k.as_ref(), reference.as_ref());
    if a.compute_nnz() != b.compute_nnz() {
        bail!("nnz differs: {} vs {}", a.compute_nnz(), b.compute_nnz());
    }
    let (mut max_diff, mut max_val) = (0f64, 0f64);
    for j in 0..a.ncols() {
        if !a.row_idx_of_col(j).eq(b.row_idx_of_col(j)) {
            bail!("pattern of column {j} differs");
        }
        for (x, y) in a.val_of_col(j).iter().zip(b.val_of_col(j)) {
            max_diff = max_diff.max((x - y).abs());
            max_val = max_val.max(y.abs());
        }
    }
    println!("verify: same pattern, max |ΔK| / max |K| = {:.1e}", max_diff / max_val);
    Ok(())
}

//! Structured meshes generated from a parametric map, for tests, benchmarks and examples.
//!
//! ```text
//!   (ξ, η) ∈ [0,1]²  ──map──▶  (x, y)         nξ × nη cells, each of the chosen kind;
//!   η=1 ┌───────────┐                        quadratic kinds place their extra nodes at the
//!       │           │                        mapped mid-parameters, so a curved side of the
//!   ξ=0 │           │ ξ=1                    map (an arc) is followed exactly by every node.
//!       └───────────┘ η=0                    Triangles split each quad cell along its diagonal.
//! ```
//!
//! Boundary lines get the physical group that `side_group(side, t)` names, with `t` the
//! parameter along the side at the edge's middle; the cells form the 2D group `region`.

use crate::mesh::{CellBlock, CellKind, Mesh, NodeId, PhysicalGroup};

/// A side of the parameter square.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// η = 0.
    Bottom,
    /// ξ = 1.
    Right,
    /// η = 1.
    Top,
    /// ξ = 0.
    Left,
}

/// What to generate.
#[derive(Debug, Clone)]
pub struct MappedGrid<'a> {
    /// Cell kind (a 2D kind).
    pub kind: CellKind,
    /// Cells along ξ.
    pub nx: usize,
    /// Cells along η.
    pub ny: usize,
    /// Name of the 2D physical group of all cells.
    pub region: &'a str,
}

fn quadratic(kind: CellKind) -> bool {
    matches!(kind, CellKind::Tri6 | CellKind::Quad8 | CellKind::Quad9)
}

/// Generates the mesh of `grid` under `map`, naming boundary groups with `side_group`
/// (return `None` to leave an edge out of every group).
///
/// Returns an empty mesh for a non-2D kind or zero cell counts.
pub fn mapped_grid(
    grid: &MappedGrid<'_>,
    map: impl Fn(f64, f64) -> [f64; 2],
    side_group: impl Fn(Side, f64) -> Option<String>,
) -> Mesh {
    if grid.kind.dim() != 2 || grid.nx == 0 || grid.ny == 0 {
        return Mesh::default();
    }
    let q = quadratic(grid.kind);
    let step = if q { 2 } else { 1 };
    let (mx, my) = (step * grid.nx + 1, step * grid.ny + 1);
    let lattice = |i: usize, j: usize| NodeId(j * mx + i);
    let mut points = Vec::with_capacity(mx * my);
    for j in 0..my {
        for i in 0..mx {
            points.push(map(i as f64 / (mx - 1) as f64, j as f64 / (my - 1) as f64));
        }
    }
    let mut cells: Vec<NodeId> = vec![];
    let mut count = 0;
    for cj in 0..grid.ny {
        for ci in 0..grid.nx {
            let (i, j) = (step * ci, step * cj);
            let p = |di: usize, dj: usize| lattice(i + di, j + dj);
            let (s, h) = (step, step / 2);
            match grid.kind {
                CellKind::Quad4 => cells.extend([p(0, 0), p(1, 0), p(1, 1), p(0, 1)]),
                CellKind::Quad8 => {
                    cells.extend([p(0, 0), p(s, 0), p(s, s), p(0, s), p(h, 0), p(s, h), p(h, s), p(0, h)])
                }
                CellKind::Quad9 => {
                    cells.extend([p(0, 0), p(s, 0), p(s, s), p(0, s), p(h, 0), p(s, h), p(h, s), p(0, h), p(h, h)])
                }
                CellKind::Tri3 => {
                    cells.extend([p(0, 0), p(1, 0), p(1, 1), p(0, 0), p(1, 1), p(0, 1)]);
                    count += 1;
                }
                CellKind::Tri6 => {
                    cells.extend([p(0, 0), p(s, 0), p(s, s), p(h, 0), p(s, h), p(h, h)]);
                    cells.extend([p(0, 0), p(s, s), p(0, s), p(h, h), p(h, s), p(0, h)]);
                    count += 1;
                }
                _ => {}
            }
            count += 1;
        }
    }
    let mut mesh = Mesh {
        node_tags: (1..=points.len() as u64).collect(),
        points,
        blocks: vec![CellBlock {
            kind: grid.kind,
            entity_dim: 2,
            entity_tag: 1,
            physical_tags: vec![1],
            nodes: cells,
            element_tags: (1..=count as u64).collect(),
        }],
        groups: vec![PhysicalGroup { name: grid.region.to_string(), dim: 2, tag: 1 }],
    };
    add_boundary_groups(&mut mesh, grid, mx, my, side_group);
    mesh
}

fn add_boundary_groups(
    mesh: &mut Mesh,
    grid: &MappedGrid<'_>,
    mx: usize,
    my: usize,
    side_group: impl Fn(Side, f64) -> Option<String>,
) {
    let q = quadratic(grid.kind);
    let step = if q { 2 } else { 1 };
    let mut next_tag = mesh.blocks[0].len() as u64 + 1;
    // Each side as a list of lattice points in counter-clockwise order around the domain.
    let sides = [
        (Side::Bottom, (0..mx).collect::<Vec<_>>()),
        (Side::Right, (0..my).map(|j| j * mx + mx - 1).collect()),
        (Side::Top, (0..mx).rev().map(|i| (my - 1) * mx + i).collect()),
        (Side::Left, (0..my).rev().map(|j| j * mx).collect()),
    ];
    for (side, pts) in sides {
        let edges = (pts.len() - 1) / step;
        for e in 0..edges {
            let t_mid = (e as f64 + 0.5) / edges as f64;
            let t = if matches!(side, Side::Top | Side::Left) { 1.0 - t_mid } else { t_mid };
            let Some(name) = side_group(side, t) else { continue };
            let tag = match mesh.groups.iter().find(|g| g.name == name && g.dim == 1) {
                Some(g) => g.tag,
                None => {
                    let tag = mesh.groups.len() as i32 + 1;
                    mesh.groups.push(PhysicalGroup { name: name.clone(), dim: 1, tag });
                    tag
                }
            };
            let nodes: Vec<NodeId> = if q {
                vec![NodeId(pts[2 * e]), NodeId(pts[2 * e + 2]), NodeId(pts[2 * e + 1])]
            } else {
                vec![NodeId(pts[e]), NodeId(pts[e + 1])]
            };
            let kind = if q { CellKind::Line3 } else { CellKind::Line2 };
            let block = match mesh.blocks.iter_mut().find(|b| b.kind == kind && b.physical_tags == [tag]) {
                Some(b) => b,
                None => {
                    mesh.blocks.push(CellBlock {
                        kind,
                        entity_dim: 1,
                        entity_tag: tag,
                        physical_tags: vec![tag],
                        nodes: vec![],
                        element_tags: vec![],
                    });
                    let last = mesh.blocks.len() - 1;
                    &mut mesh.blocks[last]
                }
            };
            block.nodes.extend(nodes);
            block.element_tags.push(next_tag);
            next_tag += 1;
        }
    }
}

/// A rectangle `[x0, x1] × [y0, y1]` with boundary groups `bottom`, `right`, `top`, `left`.
pub fn rectangle(kind: CellKind, x: [f64; 2], y: [f64; 2], nx: usize, ny: usize) -> Mesh {
    let grid = MappedGrid { kind, nx, ny, region: "domain" };
    mapped_grid(
        &grid,
        |u, v| [x[0] + u * (x[1] - x[0]), y[0] + v * (y[1] - y[0])],
        |side, _| Some(side_name(side).to_string()),
    )
}

/// An annular sector `r ∈ [r_in, r_out]`, `θ ∈ [θ0, θ1]` (ξ along r, η along θ) with groups
/// `inner`, `outer`, `start` (θ = θ0) and `end` (θ = θ1); every node lies on its exact circle.
pub fn annulus_sector(kind: CellKind, r: [f64; 2], theta: [f64; 2], nr: usize, nt: usize) -> Mesh {
    let grid = MappedGrid { kind, nx: nr, ny: nt, region: "domain" };
    let names = |side: Side, _| {
        Some(
            match side {
                Side::Left => "inner",
                Side::Right => "outer",
                Side::Bottom => "start",
                Side::Top => "end",
            }
            .to_string(),
        )
    };
    mapped_grid(
        &grid,
        |u, v| {
            let (rr, t) = (r[0] + u * (r[1] - r[0]), theta[0] + v * (theta[1] - theta[0]));
            [rr * t.cos(), rr * t.sin()]
        },
        names,
    )
}

/// The boundary group name [`rectangle`] gives a side: `bottom`, `right`, `top`, `left` (for
/// [`mapped_grid`]'s naming closure: `|side, _| Some(side_name(side).to_string())`).
pub fn side_name(side: Side) -> &'static str {
    match side {
        Side::Bottom => "bottom",
        Side::Right => "right",
        Side::Top => "top",
        Side::Left => "left",
    }
}

/// Appends `other` to `mesh` as separate nodes and cells, prefixing all of `other`'s group
/// names with `prefix` (bodies side by side, for contact tests and examples).
pub fn append_prefixed(mesh: &mut Mesh, other: &Mesh, prefix: &str) {
    let node_offset = mesh.points.len();
    let tag_offset = mesh.node_tags.iter().copied().max().unwrap_or(0);
    let element_offset = mesh.blocks.iter().flat_map(|b| b.element_tags.iter().copied()).max().unwrap_or(0);
    let group_offset = mesh.groups.iter().map(|g| g.tag).max().unwrap_or(0);
    let entity_offset = mesh.blocks.iter().map(|b| b.entity_tag).max().unwrap_or(0);
    mesh.points.extend_from_slice(&other.points);
    mesh.node_tags.extend(other.node_tags.iter().map(|t| t + tag_offset));
    for b in &other.blocks {
        mesh.blocks.push(CellBlock {
            kind: b.kind,
            entity_dim: b.entity_dim,
            entity_tag: b.entity_tag + entity_offset,
            physical_tags: b.physical_tags.iter().map(|t| t + group_offset).collect(),
            nodes: b.nodes.iter().map(|n| NodeId(n.0 + node_offset)).collect(),
            element_tags: b.element_tags.iter().map(|t| t + element_offset).collect(),
        });
    }
    for g in &other.groups {
        mesh.groups.push(PhysicalGroup { name: format!("{prefix}{}", g.name), dim: g.dim, tag: g.tag + group_offset });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rectangle_counts_and_groups() {
        for (kind, nodes, cells) in [
            (CellKind::Quad4, 4 * 3, 6),
            (CellKind::Quad9, 7 * 5, 6),
            (CellKind::Quad8, 7 * 5, 6),
            (CellKind::Tri3, 4 * 3, 12),
            (CellKind::Tri6, 7 * 5, 12),
        ] {
            let m = rectangle(kind, [0.0, 3.0], [0.0, 2.0], 3, 2);
            assert_eq!(m.points.len(), nodes, "{kind:?}");
            assert_eq!(m.group_cell_count("domain").ok(), Some(cells));
            assert_eq!(m.group_cell_count("left").ok(), Some(2));
            assert_eq!(m.group_cell_count("top").ok(), Some(3));
        }
    }

    #[test]
    fn annulus_nodes_lie_on_circles() {
        let m = annulus_sector(CellKind::Quad9, [1.0, 2.0], [0.0, 1.5], 3, 5);
        for n in m.group_nodes("inner").unwrap_or_default() {
            let p = m.points[n.0];
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15);
        }
    }
}

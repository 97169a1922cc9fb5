//! The in-memory mesh, in meshio's model: points, cell blocks by kind, named physical groups.
//!
//! ```text
//!   Mesh
//!   ├── points      [x, y] per node, indexed by NodeId (dense, 0-based)
//!   ├── node_tags   the file's node tag of each point (tags may be non-contiguous)
//!   ├── blocks      CellBlock: one cell kind of one geometric entity, flat connectivity
//!   └── groups      PhysicalGroup: name, dimension, tag; a block belongs to the groups
//!                   whose tags it lists in `physical_tags`
//! ```
//!
//! A physical group of dimension 2 is a *region* (a body); of dimension 1 a *boundary curve*.

use crate::error::MeshError;

/// Index of a node (a point of the mesh), dense and 0-based.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NodeId(pub usize);

/// The cell kinds contact2d reads, with their Gmsh element type numbers.
///
/// Node order within a cell is Gmsh's (see the element crate's docs for the drawings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CellKind {
    /// 1-node point (Gmsh type 15).
    Point1,
    /// 2-node line (Gmsh type 1).
    Line2,
    /// 3-node line (Gmsh type 8): ends first, then the mid node.
    Line3,
    /// 3-node triangle (Gmsh type 2).
    Tri3,
    /// 6-node triangle (Gmsh type 9).
    Tri6,
    /// 4-node quadrangle (Gmsh type 3).
    Quad4,
    /// 8-node serendipity quadrangle (Gmsh type 16).
    Quad8,
    /// 9-node Lagrange quadrangle (Gmsh type 10).
    Quad9,
}

impl CellKind {
    /// All kinds, for iteration in tests and summaries.
    pub const ALL: [CellKind; 8] = [
        CellKind::Point1,
        CellKind::Line2,
        CellKind::Line3,
        CellKind::Tri3,
        CellKind::Tri6,
        CellKind::Quad4,
        CellKind::Quad8,
        CellKind::Quad9,
    ];

    /// The kind of a Gmsh element type number, `None` for types contact2d does not read.
    pub fn from_gmsh_type(gmsh_type: i32) -> Option<CellKind> {
        Some(match gmsh_type {
            15 => CellKind::Point1,
            1 => CellKind::Line2,
            8 => CellKind::Line3,
            2 => CellKind::Tri3,
            9 => CellKind::Tri6,
            3 => CellKind::Quad4,
            16 => CellKind::Quad8,
            10 => CellKind::Quad9,
            _ => return None,
        })
    }

    /// The Gmsh element type number.
    pub fn gmsh_type(self) -> i32 {
        match self {
            CellKind::Point1 => 15,
            CellKind::Line2 => 1,
            CellKind::Line3 => 8,
            CellKind::Tri3 => 2,
            CellKind::Tri6 => 9,
            CellKind::Quad4 => 3,
            CellKind::Quad8 => 16,
            CellKind::Quad9 => 10,
        }
    }

    /// Number of nodes of one cell.
    pub fn nodes_per_cell(self) -> usize {
        match self {
            CellKind::Point1 => 1,
            CellKind::Line2 => 2,
            CellKind::Line3 => 3,
            CellKind::Tri3 => 3,
            CellKind::Tri6 => 6,
            CellKind::Quad4 => 4,
            CellKind::Quad8 => 8,
            CellKind::Quad9 => 9,
        }
    }

    /// Topological dimension (0 point, 1 line, 2 surface).
    pub fn dim(self) -> usize {
        match self {
            CellKind::Point1 => 0,
            CellKind::Line2 | CellKind::Line3 => 1,
            _ => 2,
        }
    }

    /// Short lowercase name, as meshio spells it (`line3`, `quad9`, ...).
    pub fn name(self) -> &'static str {
        match self {
            CellKind::Point1 => "vertex",
            CellKind::Line2 => "line",
            CellKind::Line3 => "line3",
            CellKind::Tri3 => "triangle",
            CellKind::Tri6 => "triangle6",
            CellKind::Quad4 => "quad",
            CellKind::Quad8 => "quad8",
            CellKind::Quad9 => "quad9",
        }
    }
}

/// The cells of one kind that belong to one geometric entity.
#[derive(Debug, Clone, PartialEq)]
pub struct CellBlock {
    /// Kind of every cell in the block.
    pub kind: CellKind,
    /// Dimension of the geometric entity (Gmsh "elementary" entity).
    pub entity_dim: usize,
    /// Tag of the geometric entity.
    pub entity_tag: i32,
    /// Tags of the physical groups this block belongs to (may be empty).
    pub physical_tags: Vec<i32>,
    /// Connectivity, flat: cell `i` is `nodes[i * n .. (i + 1) * n]` with `n = kind.nodes_per_cell()`.
    pub nodes: Vec<NodeId>,
    /// The file's element tag of each cell.
    pub element_tags: Vec<u64>,
}

impl CellBlock {
    /// Number of cells.
    pub fn len(&self) -> usize {
        self.element_tags.len()
    }

    /// Whether the block has no cells.
    pub fn is_empty(&self) -> bool {
        self.element_tags.is_empty()
    }

    /// The nodes of cell `i`, in Gmsh order. Panics in debug if `i` is out of range.
    pub fn cell(&self, i: usize) -> &[NodeId] {
        let n = self.kind.nodes_per_cell();
        &self.nodes[i * n..(i + 1) * n]
    }

    /// Iterator over the cells' node lists.
    pub fn cells(&self) -> impl Iterator<Item = &[NodeId]> + '_ {
        self.nodes.chunks_exact(self.kind.nodes_per_cell())
    }
}

/// A named physical group: a region (dim 2), a boundary curve (dim 1) or a point set (dim 0).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PhysicalGroup {
    /// Name from `$PhysicalNames`.
    pub name: String,
    /// Dimension of the group.
    pub dim: usize,
    /// Physical tag.
    pub tag: i32,
}

/// A 2D mesh: points, cell blocks, physical groups.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Mesh {
    /// Coordinates of each node (z dropped; the reader checks that it is zero).
    pub points: Vec<[f64; 2]>,
    /// The file's node tag of each point.
    pub node_tags: Vec<u64>,
    /// Cell blocks in file order.
    pub blocks: Vec<CellBlock>,
    /// Physical groups, in `$PhysicalNames` order.
    pub groups: Vec<PhysicalGroup>,
}

impl Mesh {
    /// Number of nodes.
    pub fn num_nodes(&self) -> usize {
        self.points.len()
    }

    /// The physical group called `name`.
    ///
    /// # Errors
    /// [`MeshError::UnknownPhysicalGroup`] if no group has that name.
    pub fn group(&self, name: &str) -> Result<&PhysicalGroup, MeshError> {
        self.groups.iter().find(|g| g.name == name).ok_or_else(|| MeshError::UnknownPhysicalGroup(name.to_string()))
    }

    /// The blocks that belong to the physical group called `name` (same dimension, tag listed).
    ///
    /// # Errors
    /// [`MeshError::UnknownPhysicalGroup`] if no group has that name.
    pub fn blocks_in_group(&self, name: &str) -> Result<Vec<&CellBlock>, MeshError> {
        let group = self.group(name)?;
        Ok(self.blocks.iter().filter(|b| b.kind.dim() == group.dim && b.physical_tags.contains(&group.tag)).collect())
    }

    /// Number of cells in the physical group called `name`.
    ///
    /// # Errors
    /// [`MeshError::UnknownPhysicalGroup`] if no group has that name.
    pub fn group_cell_count(&self, name: &str) -> Result<usize, MeshError> {
        Ok(self.blocks_in_group(name)?.iter().map(|b| b.len()).sum())
    }

    /// The sorted, deduplicated nodes of all cells of the group called `name`.
    ///
    /// # Errors
    /// [`MeshError::UnknownPhysicalGroup`] if no group has that name.
    pub fn group_nodes(&self, name: &str) -> Result<Vec<NodeId>, MeshError> {
        let mut nodes: Vec<NodeId> = self.blocks_in_group(name)?.iter().flat_map(|b| b.nodes.iter().copied()).collect();
        nodes.sort_unstable();
        nodes.dedup();
        Ok(nodes)
    }

    /// Axis-aligned bounding box `[[xmin, ymin], [xmax, ymax]]`; `None` for an empty mesh.
    pub fn bounding_box(&self) -> Option<[[f64; 2]; 2]> {
        let first = *self.points.first()?;
        let mut bbox = [first, first];
        for p in &self.points {
            for k in 0..2 {
                bbox[0][k] = bbox[0][k].min(p[k]);
                bbox[1][k] = bbox[1][k].max(p[k]);
            }
        }
        Some(bbox)
    }
}

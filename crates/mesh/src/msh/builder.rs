//! Collects what the section parsers read into a [`Mesh`] and checks the cross-section rules.
//!
//! ```text
//!   $Nodes     add_node(tag) -> NodeId, set_coords(id, x, y, z)      duplicate tags, NaN/inf
//!              finish_nodes()                                         planarity: |z| <= tol
//!   $Elements  node(tag), add_element_tag(tag), push_block(...)       missing nodes, duplicates
//!   (any)      require_name(dim, tag)                                 deferred name check
//!   end        finish(names) -> Mesh                                  duplicated elements
//! ```
//!
//! A duplicated element is a line or surface cell whose node set (in any order) is that of
//! another cell of the same dimension in the same physical group (or with no physical group on
//! either): it would be assembled twice and silently double that element's stiffness or load.
//! The same element in two *different* physical groups is legitimate (MSH 2.2 writes such an
//! element once per group, under two element tags) and passes.
//!
//! Planarity: every node must satisfy
//!
//! ```text
//!   |z| <= 1e-12 · (1 + d),    d = diagonal of the bounding box of (x, y)
//! ```
//!
//! so that rounding noise in a planar mesh passes and a genuinely 3D mesh is rejected.

use super::cursor::{msh_error, unsupported};
use super::physical::PhysicalNames;
use super::tags::TagMap;
use crate::error::{Location, MeshError};
use crate::mesh::{CellBlock, CellKind, Mesh, NodeId};

/// Relative tolerance on z, see the module doc.
const Z_TOLERANCE: f64 = 1e-12;

/// A physical tag that must be named in `$PhysicalNames`, and who uses it.
#[derive(Debug)]
struct NameUse {
    dim: usize,
    tag: i32,
    at: Location,
    user: String,
}

/// The largest |z| seen so far, with where it was.
#[derive(Debug)]
struct ZRecord {
    z: f64,
    tag: u64,
    at: Location,
}

/// A mesh under construction.
#[derive(Debug, Default)]
pub(crate) struct MeshBuilder {
    points: Vec<[f64; 2]>,
    node_tags: Vec<u64>,
    node_index: TagMap,
    max_z: Option<ZRecord>,
    blocks: Vec<CellBlock>,
    /// File element tag -> index into `element_at` (the order the elements were read in).
    element_index: TagMap,
    /// Where each element was read.
    element_at: Vec<Location>,
    name_uses: Vec<NameUse>,
}

impl MeshBuilder {
    /// An empty builder.
    pub(crate) fn new() -> Self {
        MeshBuilder {
            node_index: TagMap::with_expected(0),
            element_index: TagMap::with_expected(0),
            ..MeshBuilder::default()
        }
    }

    /// Prepares for `n` more nodes (`n` already checked against the file size).
    pub(crate) fn reserve_nodes(&mut self, n: usize) {
        self.points.reserve(n);
        self.node_tags.reserve(n);
        self.node_index.expect(self.points.len().saturating_add(n));
    }

    /// Prepares for `n` more elements (`n` already checked against the file size).
    pub(crate) fn reserve_elements(&mut self, n: usize) {
        self.element_at.reserve(n);
        self.element_index.expect(self.element_at.len().saturating_add(n));
    }

    /// Adds a node with file tag `tag` at the origin; its coordinates follow with
    /// [`MeshBuilder::set_coords`].
    ///
    /// # Errors
    /// [`MeshError::Msh`] at `at` if the tag was used before.
    pub(crate) fn add_node(&mut self, tag: u64, at: Location) -> Result<NodeId, MeshError> {
        let id = self.points.len();
        self.node_index
            .insert(tag, id)
            .map_err(|first| msh_error(at, format!("node tag {tag} appears twice (first as node #{})", first + 1)))?;
        self.points.push([0.0, 0.0]);
        self.node_tags.push(tag);
        Ok(NodeId(id))
    }

    /// Number of nodes added so far.
    pub(crate) fn num_nodes(&self) -> usize {
        self.points.len()
    }

    /// Sets the coordinates of node `id`.
    ///
    /// # Errors
    /// [`MeshError::Msh`] at `at` if a coordinate is NaN or infinite.
    pub(crate) fn set_coords(&mut self, id: NodeId, xyz: [f64; 3], at: Location) -> Result<(), MeshError> {
        let tag = self.node_tags.get(id.0).copied().unwrap_or_default();
        if !xyz.iter().all(|v| v.is_finite()) {
            return Err(msh_error(
                at,
                format!("node {tag} has a coordinate that is not finite ({}, {}, {})", xyz[0], xyz[1], xyz[2]),
            ));
        }
        if let Some(p) = self.points.get_mut(id.0) {
            *p = [xyz[0], xyz[1]];
        }
        let z = xyz[2].abs();
        if z > 0.0 && self.max_z.as_ref().is_none_or(|m| z > m.z) {
            self.max_z = Some(ZRecord { z, tag, at });
        }
        Ok(())
    }

    /// Checks planarity once all nodes are in (see the module doc).
    ///
    /// # Errors
    /// [`MeshError::Msh`] at the node with the largest |z| if it exceeds the tolerance.
    pub(crate) fn finish_nodes(&mut self) -> Result<(), MeshError> {
        let Some(worst) = &self.max_z else {
            return Ok(());
        };
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in &self.points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let diagonal = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
        let tolerance = Z_TOLERANCE * (1.0 + diagonal);
        if worst.z > tolerance {
            return Err(msh_error(
                worst.at,
                format!(
                    "node {} has z = {:e}; contact2d reads planar meshes (|z| <= {tolerance:e})",
                    worst.tag, worst.z
                ),
            ));
        }
        Ok(())
    }

    /// The node with file tag `tag`, if any (see [`missing_node`] for the error).
    #[inline]
    pub(crate) fn node(&self, tag: u64) -> Option<NodeId> {
        self.node_index.get(tag).map(NodeId)
    }

    /// Registers an element tag, read at `at`.
    ///
    /// # Errors
    /// [`MeshError::Msh`] at `at` if the tag was used before.
    #[inline]
    pub(crate) fn add_element_tag(&mut self, tag: u64, at: Location) -> Result<(), MeshError> {
        match self.element_index.insert(tag, self.element_at.len()) {
            Ok(()) => {
                self.element_at.push(at);
                Ok(())
            }
            Err(_) => Err(msh_error(at, format!("element tag {tag} appears twice"))),
        }
    }

    /// Where element `tag` was read (the start of the file if it was never registered).
    fn element_location(&self, tag: u64) -> (usize, Location) {
        self.element_index
            .get(tag)
            .and_then(|i| self.element_at.get(i).map(|&at| (i, at)))
            .unwrap_or((0, Location::Line(1)))
    }

    /// Checks that no line or surface cell is written twice (see the module doc).
    ///
    /// Sorts one key per cell (dimension, sorted node ids), so it costs O(n log n) for n cells
    /// and no allocation per cell.
    ///
    /// # Errors
    /// [`MeshError::Msh`] at the later-read element of the first duplicated pair, naming both
    /// element tags.
    fn check_duplicate_elements(&self) -> Result<(), MeshError> {
        /// (dimension, sorted node ids padded with `usize::MAX`, block, element tag)
        type Key = (usize, [usize; 9], usize, u64);
        let mut keys: Vec<Key> = Vec::with_capacity(self.blocks.iter().map(CellBlock::len).sum());
        for (b, block) in self.blocks.iter().enumerate() {
            let dim = block.kind.dim();
            let per = block.kind.nodes_per_cell();
            if dim == 0 || per == 0 || per > 9 {
                continue;
            }
            for (cell, &tag) in block.nodes.chunks_exact(per).zip(&block.element_tags) {
                let mut sorted = [usize::MAX; 9];
                for (slot, node) in sorted.iter_mut().zip(cell) {
                    *slot = node.0;
                }
                sorted.sort_unstable();
                keys.push((dim, sorted, b, tag));
            }
        }
        keys.sort_unstable();
        let same_group = |a: usize, b: usize| match (self.blocks.get(a), self.blocks.get(b)) {
            (Some(a), Some(b)) => {
                (a.physical_tags.is_empty() && b.physical_tags.is_empty())
                    || a.physical_tags.iter().any(|t| b.physical_tags.contains(t))
            }
            _ => false,
        };
        // Cells with equal node sets are adjacent after the sort; a run of them is short, so
        // comparing every pair within a run is cheap.
        let mut start = 0;
        while start < keys.len() {
            let mut end = start + 1;
            while keys.get(end).is_some_and(|k| keys.get(start).is_some_and(|s| k.0 == s.0 && k.1 == s.1)) {
                end += 1;
            }
            let run = keys.get(start..end).unwrap_or_default();
            for (i, a) in run.iter().enumerate() {
                for b in run.iter().skip(i + 1) {
                    if same_group(a.2, b.2) {
                        let (ia, at_a) = self.element_location(a.3);
                        let (ib, at_b) = self.element_location(b.3);
                        let ((first, _), (second, at)) =
                            if ia <= ib { ((a.3, at_a), (b.3, at_b)) } else { ((b.3, at_b), (a.3, at_a)) };
                        return Err(msh_error(
                            at,
                            format!(
                                "element {second} has the nodes of element {first} (an element written twice \
                                 would be assembled twice; remove one of them)"
                            ),
                        ));
                    }
                }
            }
            start = end;
        }
        Ok(())
    }

    /// Appends a block.
    pub(crate) fn push_block(&mut self, block: CellBlock) {
        self.blocks.push(block);
    }

    /// Records that `user` (found at `at`) uses physical tag `tag` of dimension `dim`, which
    /// must therefore be named in `$PhysicalNames` (checked in [`MeshBuilder::finish`]).
    pub(crate) fn require_name(&mut self, dim: usize, tag: i32, at: Location, user: String) {
        self.name_uses.push(NameUse { dim, tag, at, user });
    }

    /// The finished mesh.
    ///
    /// # Errors
    /// [`MeshError::Msh`] at the later one if an element is written twice (see the module doc);
    /// at its first use if a physical tag has no name.
    pub(crate) fn finish(self, names: PhysicalNames) -> Result<Mesh, MeshError> {
        self.check_duplicate_elements()?;
        if let Some(u) = self.name_uses.iter().find(|u| !names.contains(u.dim, u.tag)) {
            return Err(msh_error(
                u.at,
                format!(
                    "{} uses physical tag {} of dimension {}, which $PhysicalNames does not name \
                     (give the group a name, e.g. Physical {}(\"name\", {}) = {{...}}; in the .geo file)",
                    u.user,
                    u.tag,
                    u.dim,
                    ["Point", "Curve", "Surface", "Volume"].get(u.dim).copied().unwrap_or("Surface"),
                    u.tag
                ),
            ));
        }
        Ok(Mesh { points: self.points, node_tags: self.node_tags, blocks: self.blocks, groups: names.groups })
    }
}

/// The cell kind of Gmsh element type `gmsh_type`.
///
/// # Errors
/// [`MeshError::Unsupported`] at `at`, naming the type, for types contact2d does not read.
pub(crate) fn cell_kind(gmsh_type: i32, at: Location) -> Result<CellKind, MeshError> {
    CellKind::from_gmsh_type(gmsh_type).ok_or_else(|| {
        let known = match gmsh_type {
            4 => " (4-node tetrahedron)",
            5 => " (8-node hexahedron)",
            6 => " (6-node prism)",
            7 => " (5-node pyramid)",
            11 => " (10-node tetrahedron)",
            20 => " (9-node incomplete triangle)",
            21 => " (10-node triangle)",
            26 => " (4-node line)",
            36 => " (16-node quadrangle)",
            _ => "",
        };
        unsupported(at, format!("element type {gmsh_type}{known}; contact2d reads types 15, 1, 8, 2, 9, 3, 16 and 10"))
    })
}

/// The error for element `element` referring to node tag `node`, absent from `$Nodes`.
pub(crate) fn missing_node(at: Location, element: u64, node: u64) -> MeshError {
    msh_error(at, format!("element {element} refers to node {node}, which is not in $Nodes"))
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::mesh::PhysicalGroup;

    const AT: Location = Location::Line(3);

    #[test]
    fn nodes_get_dense_ids() {
        let mut b = MeshBuilder::new();
        assert_eq!(b.add_node(10, AT).unwrap(), NodeId(0));
        assert_eq!(b.add_node(3, AT).unwrap(), NodeId(1));
        b.set_coords(NodeId(1), [1.0, 2.0, 0.0], AT).unwrap();
        assert_eq!(b.node(3), Some(NodeId(1)));
        assert_eq!(b.node(4), None);
        let e = missing_node(AT, 1, 4);
        assert!(matches!(e, MeshError::Msh { at: AT, .. }), "{e}");
        assert!(b.add_node(10, Location::Line(9)).is_err());
        b.finish_nodes().unwrap();
        let mesh = b.finish(PhysicalNames::default()).unwrap();
        assert_eq!(mesh.points, vec![[0.0, 0.0], [1.0, 2.0]]);
        assert_eq!(mesh.node_tags, vec![10, 3]);
    }

    #[test]
    fn non_finite_coordinates() {
        let mut b = MeshBuilder::new();
        let id = b.add_node(1, AT).unwrap();
        let e = b.set_coords(id, [f64::NAN, 0.0, 0.0], AT).unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: AT, .. }), "{e}");
        assert!(b.set_coords(id, [0.0, f64::INFINITY, 0.0], AT).is_err());
    }

    #[test]
    fn planarity_tolerance_scales_with_the_mesh() {
        let mut b = MeshBuilder::new();
        let a = b.add_node(1, AT).unwrap();
        let c = b.add_node(2, Location::Line(4)).unwrap();
        b.set_coords(a, [0.0, 0.0, 1e-13], AT).unwrap();
        b.set_coords(c, [3.0, 4.0, -5e-12], Location::Line(4)).unwrap();
        b.finish_nodes().unwrap();

        let mut b = MeshBuilder::new();
        let a = b.add_node(1, AT).unwrap();
        let c = b.add_node(2, Location::Line(4)).unwrap();
        b.set_coords(a, [0.0, 0.0, 1e-13], AT).unwrap();
        b.set_coords(c, [3.0, 4.0, -7e-12], Location::Line(4)).unwrap();
        let e = b.finish_nodes().unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(4), .. }), "{e}");
    }

    #[test]
    fn element_types() {
        assert_eq!(cell_kind(10, AT).unwrap(), CellKind::Quad9);
        let e = cell_kind(4, AT).unwrap_err();
        assert!(matches!(e, MeshError::Unsupported { at: AT, .. }), "{e}");
        assert!(e.to_string().contains("element type 4 (4-node tetrahedron)"), "{e}");
        assert!(cell_kind(-1, AT).is_err());
    }

    #[test]
    fn duplicate_element_tags() {
        let mut b = MeshBuilder::new();
        b.add_element_tag(5, AT).unwrap();
        let e = b.add_element_tag(5, Location::Line(7)).unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(7), .. }), "{e}");
    }

    /// A builder with four nodes and the triangles `cells` (element tag, nodes, physical tag),
    /// each triangle in a block of its own, read on lines 10, 11, ...
    fn triangles(cells: &[(u64, [usize; 3], i32)]) -> MeshBuilder {
        let mut b = MeshBuilder::new();
        for tag in 1..=4 {
            b.add_node(tag, AT).unwrap();
        }
        for (i, &(tag, nodes, physical)) in cells.iter().enumerate() {
            b.add_element_tag(tag, Location::Line(10 + i)).unwrap();
            b.push_block(CellBlock {
                kind: CellKind::Tri3,
                entity_dim: 2,
                entity_tag: 1,
                physical_tags: vec![physical],
                nodes: nodes.iter().map(|&n| NodeId(n)).collect(),
                element_tags: vec![tag],
            });
        }
        b
    }

    fn named() -> PhysicalNames {
        PhysicalNames {
            groups: vec![
                PhysicalGroup { name: "a".into(), dim: 2, tag: 1 },
                PhysicalGroup { name: "b".into(), dim: 2, tag: 2 },
            ],
        }
    }

    #[test]
    fn an_element_written_twice_is_refused_naming_both_tags() {
        // The same triangle with its nodes rotated, second read on line 12.
        let e = triangles(&[(7, [0, 1, 2], 1), (8, [1, 2, 3], 1), (9, [2, 0, 1], 1)]).finish(named()).unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(12), .. }), "{e}");
        assert!(e.to_string().contains("element 9 has the nodes of element 7"), "{e}");
        // Read in the other order, the later one (on line 11) is named as the copy.
        let e = triangles(&[(9, [2, 0, 1], 1), (7, [0, 1, 2], 1)]).finish(named()).unwrap_err();
        assert!(e.to_string().contains("element 7 has the nodes of element 9"), "{e}");
    }

    #[test]
    fn the_same_element_in_two_physical_groups_passes() {
        // MSH 2.2 writes an element of two groups once per group.
        triangles(&[(7, [0, 1, 2], 1), (8, [0, 1, 2], 2), (9, [1, 2, 3], 1)]).finish(named()).unwrap();
        // Neighbours sharing an edge are not duplicates.
        triangles(&[(7, [0, 1, 2], 1), (8, [0, 2, 3], 1)]).finish(named()).unwrap();
    }

    #[test]
    fn unnamed_physical_tags_are_errors() {
        let mut b = MeshBuilder::new();
        b.push_block(CellBlock {
            kind: CellKind::Line2,
            entity_dim: 1,
            entity_tag: 1,
            physical_tags: vec![4],
            nodes: vec![],
            element_tags: vec![],
        });
        b.require_name(1, 4, Location::Line(12), "curve 1".into());
        let names = PhysicalNames { groups: vec![PhysicalGroup { name: "a".into(), dim: 2, tag: 4 }] };
        let e = b.finish(names).unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(12), .. }), "{e}");
        assert!(e.to_string().contains("Physical Curve(\"name\", 4)"), "{e}");
    }
}

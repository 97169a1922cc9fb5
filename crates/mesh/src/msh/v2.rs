//! The MSH 2.2 sections `$Nodes` and `$Elements`, ASCII and binary.
//!
//! ```text
//!   ASCII                                   binary (counts stay text)
//!   $Nodes                                  $Nodes
//!   numNodes                                numNodes\n
//!   nodeTag x y z          (numNodes lines) {int tag, double x, y, z} x numNodes
//!   $EndNodes                               \n$EndNodes
//!   $Elements                               $Elements
//!   numElements                             numElements\n
//!   tag type numTags t1..tn node...         groups: {int type, int count, int numTags}
//!                                                   then count x {int tag, int t1..tn, int node...}
//!   $EndElements                            \n$EndElements
//! ```
//!
//! Tag `t1` is the physical tag (0: none) and `t2` the elementary (entity) tag; further tags
//! (partitions) are read and ignored. Elements are grouped into blocks by
//! (type, elementary tag, physical tag), blocks in order of first appearance. An element in two
//! physical groups appears twice in an MSH 2.2 file (Gmsh writes it once per group, with two
//! element tags), and so lands in two blocks.

use std::collections::HashMap;

use super::builder::{MeshBuilder, cell_kind, missing_node};
use super::cursor::{Cursor, msh_error};
use crate::error::{Location, MeshError};
use crate::mesh::{CellBlock, CellKind};

/// A block key: (Gmsh type, elementary tag, physical tag).
type BlockKey = (i32, i32, i32);

/// Reads a tag: text `u64` in ASCII, a non-negative `int` in binary.
fn read_tag(c: &mut Cursor<'_>, what: &str) -> Result<u64, MeshError> {
    if c.is_binary() {
        let v = c.bin_i32(what)?;
        u64::try_from(v).map_err(|_| msh_error(c.field_loc(), format!("{what} is negative ({v})")))
    } else {
        c.text_u64(what)
    }
}

/// Reads the body of `$Nodes`.
pub(crate) fn read_nodes(c: &mut Cursor<'_>, b: &mut MeshBuilder) -> Result<(), MeshError> {
    let n = c.text_count("the number of nodes", 4, 28)?;
    c.text_end_line()?;
    b.reserve_nodes(n);
    for _ in 0..n {
        let tag = read_tag(c, "a node tag")?;
        let at = c.field_loc();
        let id = b.add_node(tag, at)?;
        let x = c.double("x")?;
        let x_at = c.field_loc();
        let y = c.double("y")?;
        let z = c.double("z")?;
        b.set_coords(id, [x, y, z], x_at)?;
        c.end_record()?;
    }
    b.finish_nodes()
}

/// The blocks of an MSH 2.2 file as they are filled.
#[derive(Debug, Default)]
struct Blocks {
    blocks: Vec<CellBlock>,
    index: HashMap<BlockKey, usize>,
    last: Option<(BlockKey, usize)>,
}

impl Blocks {
    /// The block for `key`, created (and its physical tag registered for the name check)
    /// on first use, by the element at `at`.
    fn get(
        &mut self,
        b: &mut MeshBuilder,
        kind: CellKind,
        key: BlockKey,
        element: u64,
        at: Location,
    ) -> Option<&mut CellBlock> {
        let index = match self.last {
            Some((k, i)) if k == key => i,
            _ => {
                let i = *self.index.entry(key).or_insert_with(|| {
                    let (_, entity, physical) = key;
                    if physical != 0 {
                        b.require_name(kind.dim(), physical, at, format!("element {element}"));
                    }
                    self.blocks.push(CellBlock {
                        kind,
                        entity_dim: kind.dim(),
                        entity_tag: entity,
                        physical_tags: if physical == 0 { vec![] } else { vec![physical] },
                        nodes: Vec::new(),
                        element_tags: Vec::new(),
                    });
                    self.blocks.len() - 1
                });
                self.last = Some((key, i));
                i
            }
        };
        self.blocks.get_mut(index)
    }
}

/// Reads one element after its type, with `num_tags` tags, into its block.
fn read_element(
    c: &mut Cursor<'_>,
    b: &mut MeshBuilder,
    blocks: &mut Blocks,
    kind: CellKind,
    num_tags: u64,
    tag: u64,
    at: Location,
) -> Result<(), MeshError> {
    let (mut physical, mut entity) = (0, 0);
    for k in 0..num_tags {
        let v = c.int("an element tag value (physical, elementary, ...)")?;
        match k {
            0 => physical = v,
            1 => entity = v,
            _ => {}
        }
    }
    let mut nodes = [crate::mesh::NodeId(0); 9];
    let per = kind.nodes_per_cell();
    for slot in nodes.iter_mut().take(per) {
        let node = read_tag(c, "a node tag")?;
        *slot = b.node(node).ok_or_else(|| missing_node(c.field_loc(), tag, node))?;
    }
    let block = blocks
        .get(b, kind, (kind.gmsh_type(), entity, physical), tag, at)
        .ok_or_else(|| msh_error(at, "internal: block index out of range"))?;
    block.nodes.extend_from_slice(nodes.get(..per).unwrap_or_default());
    block.element_tags.push(tag);
    Ok(())
}

/// Reads the body of `$Elements`.
pub(crate) fn read_elements(c: &mut Cursor<'_>, b: &mut MeshBuilder) -> Result<(), MeshError> {
    let count_at = c.loc();
    let n = c.text_count("the number of elements", 4, 12)?;
    c.text_end_line()?;
    b.reserve_elements(n);
    let mut blocks = Blocks::default();
    if c.is_binary() {
        read_binary_groups(c, b, &mut blocks, n, count_at)?;
    } else {
        for _ in 0..n {
            let at = c.loc();
            let tag = c.text_u64("an element tag")?;
            b.add_element_tag(tag, at)?;
            let kind = cell_kind(c.text_i32("an element type")?, at)?;
            let num_tags = c.text_u64("the number of tags")?;
            read_element(c, b, &mut blocks, kind, num_tags, tag, at)?;
            c.text_end_line()?;
        }
    }
    for block in blocks.blocks {
        b.push_block(block);
    }
    Ok(())
}

/// Reads the header-grouped binary elements: `n` elements in groups of one type.
fn read_binary_groups(
    c: &mut Cursor<'_>,
    b: &mut MeshBuilder,
    blocks: &mut Blocks,
    n: usize,
    count_at: Location,
) -> Result<(), MeshError> {
    let mut read = 0usize;
    while read < n {
        let group_at = c.loc();
        let kind = cell_kind(c.bin_i32("an element type")?, group_at)?;
        let follow = c.bin_i32("the number of elements in the group")?;
        let num_tags = c.bin_i32("the number of tags")?;
        let (Ok(follow), Ok(num_tags)) = (usize::try_from(follow), usize::try_from(num_tags)) else {
            return Err(msh_error(group_at, format!("element group with {follow} elements and {num_tags} tags")));
        };
        let need = (1 + num_tags + kind.nodes_per_cell()).checked_mul(4).and_then(|per| per.checked_mul(follow));
        if need.is_none_or(|need| need > c.remaining()) {
            return Err(msh_error(
                group_at,
                format!(
                    "element group of {follow} elements does not fit in the {} bytes left (truncated file?)",
                    c.remaining()
                ),
            ));
        }
        read = read.saturating_add(follow);
        if read > n {
            return Err(msh_error(
                group_at,
                format!("the element groups hold more than the {n} elements declared at {count_at}"),
            ));
        }
        for _ in 0..follow {
            let at = c.loc();
            let tag = read_tag(c, "an element tag")?;
            b.add_element_tag(tag, at)?;
            read_element(c, b, blocks, kind, num_tags as u64, tag, at)?;
        }
    }
    Ok(())
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::mesh::NodeId;

    const NODES: &[u8] = b"4\n10 0 0 0\n20 1 0 0\n30 1 1 0\n40 0 1 0\n";

    fn line(e: MeshError) -> usize {
        match e {
            MeshError::Msh { at: Location::Line(n), .. } | MeshError::Unsupported { at: Location::Line(n), .. } => n,
            other => panic!("unexpected error {other:?}"),
        }
    }

    #[test]
    fn blocks_by_type_entity_physical_in_first_appearance_order() {
        let mut b = MeshBuilder::new();
        read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
        let elements = b"5\n\
            1 2 2 0 1 10 20 30\n\
            2 1 2 5 3 10 20\n\
            3 2 2 0 1 10 30 40\n\
            4 1 0 20 30\n\
            5 1 3 5 3 0 40 10\n";
        read_elements(&mut Cursor::new(elements), &mut b).unwrap();
        let mut names = super::super::physical::PhysicalNames::default();
        names.groups.push(crate::mesh::PhysicalGroup { name: "edge".into(), dim: 1, tag: 5 });
        let mesh = b.finish(names).unwrap();
        assert_eq!(mesh.blocks.len(), 3);
        let tri = &mesh.blocks[0];
        assert_eq!((tri.kind, tri.entity_tag, tri.physical_tags.len()), (CellKind::Tri3, 1, 0));
        assert_eq!(tri.element_tags, vec![1, 3]);
        assert_eq!(tri.nodes, [0, 1, 2, 0, 2, 3].map(NodeId).to_vec());
        let edge = &mesh.blocks[1];
        assert_eq!((edge.entity_dim, edge.entity_tag), (1, 3));
        assert_eq!(edge.physical_tags, vec![5]);
        assert_eq!(edge.element_tags, vec![2, 5]);
        let untagged = &mesh.blocks[2];
        assert_eq!((untagged.entity_tag, untagged.element_tags.clone()), (0, vec![4]));
    }

    #[test]
    fn unnamed_physical_tag_reported_at_first_element() {
        let mut b = MeshBuilder::new();
        read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
        read_elements(&mut Cursor::new(b"2\n1 1 2 0 3 10 20\n2 1 2 7 3 20 30\n"), &mut b).unwrap();
        assert_eq!(line(b.finish(Default::default()).unwrap_err()), 3);
    }

    #[test]
    fn errors() {
        let cases: [(&[u8], usize); 6] = [
            (b"2\n1 2 2 0 1 10 20 30\n1 2 2 0 1 10 30 40\n", 3),
            (b"1\n1 4 2 0 1 10 20 30 40\n", 2),
            (b"1\n1 2 2 0 1 10 20 31\n", 2),
            (b"1\n1 2 2 0 1 10 20 30 40\n", 2),
            (b"2\n1 2 2 0 1 10 20 30\n$EndElements\n", 3),
            (b"1\n1 2 2 0 1 10 20\n", 2),
        ];
        for (text, expected) in cases {
            let mut b = MeshBuilder::new();
            read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
            let e = read_elements(&mut Cursor::new(text), &mut b).unwrap_err();
            assert_eq!(line(e), expected, "{}", String::from_utf8_lossy(text));
        }
        let node_cases: [(&[u8], usize); 4] =
            [(b"2\n1 0 0 0\n1 0 0 0\n", 3), (b"1\n1 0 inf 0\n", 2), (b"1\n1 0 0  \n", 2), (b"9\n1 0 0 0\n", 1)];
        for (text, expected) in node_cases {
            let e = read_nodes(&mut Cursor::new(text), &mut MeshBuilder::new()).unwrap_err();
            assert_eq!(line(e), expected, "{}", String::from_utf8_lossy(text));
        }
    }
}

//! The MSH 4.1 sections `$Entities`, `$Nodes` and `$Elements`, ASCII and binary.
//!
//! ```text
//!   $Entities
//!   numPoints numCurves numSurfaces numVolumes                              size_t x4
//!   pointTag X Y Z numPhysicalTags physicalTag...                           int, double x3, size_t, int...
//!   curveTag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTag...
//!            numBoundingPoints pointTag...                                  (same for surfaces, volumes)
//!   $Nodes
//!   numEntityBlocks numNodes minNodeTag maxNodeTag                          size_t x4
//!   entityDim entityTag parametric numNodesInBlock                          int x3, size_t
//!   nodeTag                                  (numNodesInBlock lines)        size_t
//!   x y z [u [v [w]]]                        (numNodesInBlock lines)        double x (3 + entityDim if parametric)
//!   $Elements
//!   numEntityBlocks numElements minElementTag maxElementTag                 size_t x4
//!   entityDim entityTag elementType numElementsInBlock                      int x3, size_t
//!   elementTag nodeTag...                    (numElementsInBlock lines)     size_t x (1 + nodes)
//! ```
//!
//! The right column is the binary layout; the field order is the same in both encodings, so
//! one parser reads both through the cursor's field methods. Each element block becomes one
//! [`CellBlock`] whose physical tags are those of its entity in `$Entities` (none if the file
//! has no `$Entities`). The min/max tags in the headers are hints and are not checked; the
//! total counts are.

use std::collections::HashMap;

use super::builder::{MeshBuilder, cell_kind, missing_node};
use super::cursor::{Cursor, msh_error};
use crate::error::{Location, MeshError};
use crate::mesh::{CellBlock, NodeId};

/// Names of the entity dimensions, for messages.
const ENTITY_NAMES: [&str; 4] = ["point", "curve", "surface", "volume"];

/// The physical tags of each geometric entity, keyed by (dimension, entity tag).
#[derive(Debug, Default)]
pub(crate) struct Entities {
    physical: HashMap<(usize, i32), Vec<i32>>,
}

/// Reads an entity dimension field (0 to 3).
fn entity_dim(c: &mut Cursor<'_>) -> Result<usize, MeshError> {
    let dim = c.int("an entity dimension")?;
    usize::try_from(dim)
        .ok()
        .filter(|&d| d <= 3)
        .ok_or_else(|| msh_error(c.field_loc(), format!("entity dimension {dim} is not 0, 1, 2 or 3")))
}

/// Reads the body of `$Entities`.
pub(crate) fn read_entities(c: &mut Cursor<'_>, b: &mut MeshBuilder) -> Result<Entities, MeshError> {
    let mut counts = [0usize; 4];
    for (dim, count) in counts.iter_mut().enumerate() {
        let (tokens, bytes) = if dim == 0 { (5, 36) } else { (9, 68) };
        *count = c.count(&format!("the number of {} entities", ENTITY_NAMES[dim]), tokens, bytes)?;
    }
    c.end_record()?;
    let mut entities = Entities::default();
    for (dim, &count) in counts.iter().enumerate() {
        let name = ENTITY_NAMES[dim];
        for _ in 0..count {
            let at = c.loc();
            let tag = c.int(&format!("a {name} tag"))?;
            let coordinates = if dim == 0 { 3 } else { 6 };
            for _ in 0..coordinates {
                c.double(&format!("a coordinate of {name} {tag}"))?;
            }
            let n = c.count("the number of physical tags", 1, 4)?;
            let mut physical = Vec::with_capacity(n);
            for _ in 0..n {
                physical.push(c.int("a physical tag")?);
            }
            if dim > 0 {
                let n = c.count("the number of bounding entities", 1, 4)?;
                for _ in 0..n {
                    c.int("a bounding entity tag")?;
                }
            }
            c.end_record()?;
            for &p in &physical {
                b.require_name(dim, p, at, format!("{name} entity {tag}"));
            }
            if entities.physical.insert((dim, tag), physical).is_some() {
                return Err(msh_error(at, format!("{name} entity {tag} is listed twice")));
            }
        }
    }
    Ok(entities)
}

/// Reads the body of `$Nodes`.
pub(crate) fn read_nodes(c: &mut Cursor<'_>, b: &mut MeshBuilder) -> Result<(), MeshError> {
    let at = c.loc();
    let blocks = c.count("the number of node blocks", 4, 20)?;
    let total = c.count("the number of nodes", 4, 32)?;
    c.size("the smallest node tag")?;
    c.size("the largest node tag")?;
    c.end_record()?;
    b.reserve_nodes(total);
    let mut read = 0usize;
    for _ in 0..blocks {
        let dim = entity_dim(c)?;
        let entity = c.int("an entity tag")?;
        let parametric = match c.int("the parametric flag")? {
            0 => 0,
            1 => dim,
            other => {
                return Err(msh_error(c.field_loc(), format!("the parametric flag must be 0 or 1, found {other}")));
            }
        };
        let n = c.count(&format!("the number of nodes of {} {entity}", ENTITY_NAMES[dim]), 4, 32)?;
        c.end_record()?;
        let first = b.num_nodes();
        for _ in 0..n {
            let tag = c.size("a node tag")?;
            b.add_node(tag, c.field_loc())?;
            c.end_record()?;
        }
        for i in 0..n {
            let x = c.double("x")?;
            let at = c.field_loc();
            let y = c.double("y")?;
            let z = c.double("z")?;
            for _ in 0..parametric {
                c.double("a parametric coordinate")?;
            }
            b.set_coords(NodeId(first + i), [x, y, z], at)?;
            c.end_record()?;
        }
        read = read.saturating_add(n);
    }
    if read != total {
        return Err(msh_error(at, format!("the $Nodes header declares {total} nodes but its blocks hold {read}")));
    }
    b.finish_nodes()
}

/// Reads the body of `$Elements`; `entities` gives the blocks' physical tags.
pub(crate) fn read_elements(
    c: &mut Cursor<'_>,
    b: &mut MeshBuilder,
    entities: Option<&Entities>,
) -> Result<(), MeshError> {
    let at = c.loc();
    let blocks = c.count("the number of element blocks", 4, 20)?;
    let total = c.count("the number of elements", 2, 16)?;
    c.size("the smallest element tag")?;
    c.size("the largest element tag")?;
    c.end_record()?;
    b.reserve_elements(total);
    let mut read = 0usize;
    for _ in 0..blocks {
        let block_at = c.loc();
        let dim = entity_dim(c)?;
        let entity = c.int("an entity tag")?;
        let kind = {
            let ty = c.int("an element type")?;
            cell_kind(ty, c.field_loc())?
        };
        let per = kind.nodes_per_cell();
        let n = c.count("the number of elements in the block", 1 + per, 8 * (1 + per))?;
        c.end_record()?;
        let physical_tags = physical_tags(entities, dim, entity, block_at)?;
        let mut block = CellBlock {
            kind,
            entity_dim: dim,
            entity_tag: entity,
            physical_tags,
            nodes: Vec::with_capacity(n * per),
            element_tags: Vec::with_capacity(n),
        };
        for _ in 0..n {
            let tag = c.size("an element tag")?;
            b.add_element_tag(tag, c.field_loc())?;
            for _ in 0..per {
                let node = c.size("a node tag")?;
                let id = b.node(node).ok_or_else(|| missing_node(c.field_loc(), tag, node))?;
                block.nodes.push(id);
            }
            c.end_record()?;
            block.element_tags.push(tag);
        }
        read = read.saturating_add(n);
        b.push_block(block);
    }
    if read != total {
        return Err(msh_error(
            at,
            format!("the $Elements header declares {total} elements but its blocks hold {read}"),
        ));
    }
    Ok(())
}

/// The physical tags of entity (`dim`, `tag`): none without `$Entities`, an error if
/// `$Entities` does not list it.
fn physical_tags(entities: Option<&Entities>, dim: usize, tag: i32, at: Location) -> Result<Vec<i32>, MeshError> {
    let Some(entities) = entities else {
        return Ok(Vec::new());
    };
    entities.physical.get(&(dim, tag)).cloned().ok_or_else(|| {
        msh_error(
            at,
            format!(
                "the element block is on {} {tag}, which $Entities does not list",
                ENTITY_NAMES.get(dim).copied().unwrap_or("entity")
            ),
        )
    })
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::mesh::CellKind;

    fn line(e: MeshError) -> usize {
        match e {
            MeshError::Msh { at: Location::Line(n), .. } | MeshError::Unsupported { at: Location::Line(n), .. } => n,
            other => panic!("unexpected error {other:?}"),
        }
    }

    const ENTITIES: &[u8] = b"1 1 1 0\n\
        1 0 0 0 1 7\n\
        2 0 0 0 1 1 0 1 8 2 1 -1\n\
        3 0 0 0 1 1 0 0 1 2\n";

    const NODES: &[u8] = b"2 3 1 30\n\
        0 1 0 1\n\
        10\n\
        0 0 0\n\
        2 3 1 2\n\
        30\n\
        20\n\
        1 0 0 0.5 0.5\n\
        0 1 0 0.1 0.2\n";

    #[test]
    fn entities_nodes_elements() {
        let mut b = MeshBuilder::new();
        let entities = read_entities(&mut Cursor::new(ENTITIES), &mut b).unwrap();
        assert_eq!(entities.physical.get(&(0, 1)), Some(&vec![7]));
        assert_eq!(entities.physical.get(&(1, 2)), Some(&vec![8]));
        assert_eq!(entities.physical.get(&(2, 3)), Some(&vec![]));
        read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
        let elements = b"2 2 5 6\n2 3 2 1\n5 10 30 20\n1 2 1 1\n6 30 20\n";
        read_elements(&mut Cursor::new(elements), &mut b, Some(&entities)).unwrap();
        let mesh = b.finish(Default::default());
        // Names are missing for tags 7 and 8.
        assert!(mesh.is_err());
    }

    #[test]
    fn blocks_take_entity_physical_tags() {
        let mut b = MeshBuilder::new();
        read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
        let elements = b"1 1 5 5\n2 3 2 1\n5 10 30 20\n";
        read_elements(&mut Cursor::new(elements), &mut b, None).unwrap();
        let mesh = b.finish(Default::default()).unwrap();
        assert_eq!(mesh.node_tags, vec![10, 30, 20]);
        assert_eq!(mesh.points, vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        assert_eq!(mesh.blocks.len(), 1);
        assert_eq!(mesh.blocks[0].kind, CellKind::Tri3);
        assert_eq!(mesh.blocks[0].nodes, vec![NodeId(0), NodeId(1), NodeId(2)]);
        assert_eq!(mesh.blocks[0].element_tags, vec![5]);
        assert!(mesh.blocks[0].physical_tags.is_empty());
    }

    #[test]
    fn node_errors() {
        let cases: [(&[u8], usize); 6] = [
            (b"1 2 1 2\n0 1 0 1\n1\n0 0 0\n", 1),
            (b"1 1 1 1\n0 1 2 1\n1\n0 0 0\n", 2),
            (b"1 1 1 1\n4 1 0 1\n1\n0 0 0\n", 2),
            (b"1 2 1 2\n0 1 0 2\n1\n1\n0 0 0\n0 0 0\n", 4),
            (b"1 1 1 1\n0 1 0 1\n1\n0 nan 0\n", 4),
            (b"1 1 1 1\n2 1 1 1\n1\n0 0 0 0.5\n", 4),
        ];
        for (text, expected) in cases {
            let e = read_nodes(&mut Cursor::new(text), &mut MeshBuilder::new()).unwrap_err();
            assert_eq!(line(e), expected, "{}", String::from_utf8_lossy(text));
        }
    }

    #[test]
    fn element_errors() {
        let cases: [(&[u8], usize); 5] = [
            (b"1 1 1 1\n2 3 4 1\n1 10 30 20 20\n", 2),
            (b"1 1 1 1\n2 3 2 1\n1 10 30 21\n", 3),
            (b"1 2 1 2\n2 3 2 2\n1 10 30 20\n1 10 30 20\n", 4),
            (b"1 2 1 2\n2 3 2 1\n1 10 30 20\n", 1),
            (b"1 1 1 1\n2 9 2 1\n1 10 30 20\n", 2),
        ];
        let mut nodes = MeshBuilder::new();
        let entities = read_entities(&mut Cursor::new(ENTITIES), &mut nodes).unwrap();
        for (text, expected) in cases {
            let mut b = MeshBuilder::new();
            read_nodes(&mut Cursor::new(NODES), &mut b).unwrap();
            let e = read_elements(&mut Cursor::new(text), &mut b, Some(&entities)).unwrap_err();
            assert_eq!(line(e), expected, "{}", String::from_utf8_lossy(text));
        }
    }

    #[test]
    fn entity_errors() {
        let cases: [(&[u8], usize); 3] = [
            (b"2 0 0 0\n1 0 0 0 0\n1 0 0 0 0\n", 3),
            (b"1 0 0 0\n1 0 0 0 2 5\n", 2),
            (b"0 1 0 0\n1 0 0 0 1 1 0 0\n", 2),
        ];
        for (text, expected) in cases {
            let e = read_entities(&mut Cursor::new(text), &mut MeshBuilder::new()).unwrap_err();
            assert_eq!(line(e), expected, "{}", String::from_utf8_lossy(text));
        }
    }
}

//! Writing a [`Mesh`] as MSH 4.1 or 2.2, ASCII or binary.
//!
//! ```text
//!   Mesh ──check──▶ entities (from the blocks) ──▶ $MeshFormat $PhysicalNames
//!                   node runs (by entity)            [$Entities] $Nodes $Elements
//! ```
//!
//! What the files hold:
//! * MSH 4.1: one `$Entities` entry per (entity dimension, entity tag) of the blocks, with the
//!   blocks' physical tags and the bounding box of their nodes (no bounding entities); nodes in
//!   file order, split into runs classified on the lowest-dimensional entity that uses them
//!   (unused nodes join the previous run), so that reading the file back gives the same
//!   `NodeId`s; one element block per [`CellBlock`].
//! * MSH 2.2: nodes in order; elements block by block with two tags (physical, elementary);
//!   the binary file writes one element group per block. Empty blocks are not written.
//!
//! Reading the written file back gives an equal [`Mesh`] (points bit for bit: reals are written
//! in shortest round-trip form). MSH 2.2 has limits the writer checks instead of losing data:
//! one physical tag per block, tags that fit an `int`, and the entity dimension is implied by
//! the cell kind.

use std::borrow::Cow;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

use super::emit::Emitter;
use super::tags::TagSet;
use crate::error::MeshError;
use crate::mesh::{CellBlock, Mesh};

/// An MSH version and encoding: the format to write, or the one a file was read in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MshFormat {
    /// MSH 4.1, text.
    V41Ascii,
    /// MSH 4.1, binary (little-endian).
    V41Binary,
    /// MSH 2.2, text.
    V22Ascii,
    /// MSH 2.2, binary (little-endian).
    V22Binary,
}

impl MshFormat {
    /// All formats, for iteration in tests.
    pub const ALL: [MshFormat; 4] =
        [MshFormat::V41Ascii, MshFormat::V41Binary, MshFormat::V22Ascii, MshFormat::V22Binary];

    /// Whether the data sections are binary.
    pub fn is_binary(self) -> bool {
        matches!(self, MshFormat::V41Binary | MshFormat::V22Binary)
    }

    fn is_v22(self) -> bool {
        matches!(self, MshFormat::V22Ascii | MshFormat::V22Binary)
    }
}

/// Writes `mesh` to the file at `path` in `format`.
///
/// # Errors
/// [`MeshError::CannotWrite`] as for [`encode_msh`]; [`MeshError::Io`] if the file cannot
/// be written.
pub fn write_msh(mesh: &Mesh, path: impl AsRef<Path>, format: MshFormat) -> Result<(), MeshError> {
    let path = path.as_ref();
    let bytes = encode_msh(mesh, format)?;
    std::fs::write(path, bytes).map_err(|source| MeshError::Io { path: path.display().to_string(), source })
}

/// The bytes of `mesh` as an MSH file in `format`.
///
/// An empty [`Mesh::node_tags`] means tags 1, 2, 3, ...
///
/// # Errors
/// [`MeshError::CannotWrite`] if the mesh is inconsistent (node tags and points of different
/// lengths, duplicate node or element tags, a cell referring to a node that does not exist, a
/// block whose connectivity length is not cells × nodes per cell, non-finite coordinates, a
/// physical tag with no group, a group name with a double quote or newline, two blocks of
/// one entity with different physical tags) or if MSH 2.2 cannot store it (more than one
/// physical tag or physical tag 0 on a block, a tag above `i32::MAX`).
///
/// # Examples
/// ```
/// use contact2d_mesh::msh::{MshFormat, encode_msh, parse_msh};
/// use contact2d_mesh::{CellBlock, CellKind, Mesh, NodeId};
/// let mesh = Mesh {
///     points: vec![[0.0, 0.0], [1.0, 0.0]],
///     node_tags: vec![1, 2],
///     blocks: vec![CellBlock {
///         kind: CellKind::Line2,
///         entity_dim: 1,
///         entity_tag: 1,
///         physical_tags: vec![],
///         nodes: vec![NodeId(0), NodeId(1)],
///         element_tags: vec![1],
///     }],
///     groups: vec![],
/// };
/// let bytes = encode_msh(&mesh, MshFormat::V41Ascii).unwrap();
/// assert_eq!(parse_msh(&bytes).unwrap(), mesh);
/// ```
pub fn encode_msh(mesh: &Mesh, format: MshFormat) -> Result<Vec<u8>, MeshError> {
    encode_with_byte_order(mesh, format, false)
}

/// [`encode_msh`] with a chosen byte order for the binary formats (tests of big-endian input).
pub(crate) fn encode_with_byte_order(mesh: &Mesh, format: MshFormat, big_endian: bool) -> Result<Vec<u8>, MeshError> {
    let node_tags = check(mesh, format)?;
    let mut e = Emitter::new(format.is_binary(), big_endian);
    let version = if format.is_v22() { "2.2" } else { "4.1" };
    e.text(&format!("$MeshFormat\n{version} {} 8\n", u8::from(format.is_binary())));
    if e.is_binary() {
        e.endianness_marker();
        e.text("\n");
    }
    e.text("$EndMeshFormat\n");
    if !mesh.groups.is_empty() {
        e.text(&format!("$PhysicalNames\n{}\n", mesh.groups.len()));
        for g in &mesh.groups {
            e.text(&format!("{} {} \"{}\"\n", g.dim, g.tag, g.name));
        }
        e.text("$EndPhysicalNames\n");
    }
    if format.is_v22() {
        write_v22(&mut e, mesh, &node_tags);
    } else {
        write_v41(&mut e, mesh, &node_tags);
    }
    Ok(e.out)
}

fn cannot(reason: String) -> MeshError {
    MeshError::CannotWrite { reason }
}

/// Checks that `mesh` can be written in `format`; returns the node tags to write.
fn check(mesh: &Mesh, format: MshFormat) -> Result<Cow<'_, [u64]>, MeshError> {
    let n = mesh.points.len();
    let v22 = format.is_v22();
    let int_limit = u64::try_from(i32::MAX).unwrap_or(u64::MAX);
    let node_tags: Cow<'_, [u64]> = if mesh.node_tags.len() == n {
        Cow::Borrowed(&mesh.node_tags)
    } else if mesh.node_tags.is_empty() {
        Cow::Owned((1..=n as u64).collect())
    } else {
        return Err(cannot(format!("{} node tags for {n} points", mesh.node_tags.len())));
    };
    let mut seen = TagSet::with_expected(n);
    for (&tag, p) in node_tags.iter().zip(&mesh.points) {
        if !seen.insert(tag) {
            return Err(cannot(format!("node tag {tag} is used twice")));
        }
        if v22 && tag > int_limit {
            return Err(cannot(format!("node tag {tag} does not fit MSH 2.2's int")));
        }
        if !p.iter().all(|v| v.is_finite()) {
            return Err(cannot(format!("node {tag} has a non-finite coordinate")));
        }
    }
    let mut seen = TagSet::with_expected(mesh.blocks.iter().map(CellBlock::len).sum());
    let mut entity_physical: HashMap<(usize, i32), &Vec<i32>> = HashMap::new();
    for (i, block) in mesh.blocks.iter().enumerate() {
        let what = format!("block {i} ({} on entity {})", block.kind.name(), block.entity_tag);
        if block.nodes.len() != block.len() * block.kind.nodes_per_cell() {
            return Err(cannot(format!("{what} has {} node references for {} cells", block.nodes.len(), block.len())));
        }
        if let Some(id) = block.nodes.iter().find(|id| id.0 >= n) {
            return Err(cannot(format!("{what} refers to node #{} of {n}", id.0)));
        }
        for &tag in &block.element_tags {
            if !seen.insert(tag) {
                return Err(cannot(format!("element tag {tag} is used twice")));
            }
            if v22 && tag > int_limit {
                return Err(cannot(format!("element tag {tag} does not fit MSH 2.2's int")));
            }
        }
        if block.entity_dim > 3 {
            return Err(cannot(format!("{what} has entity dimension {}", block.entity_dim)));
        }
        if v22 && (block.physical_tags.len() > 1 || block.physical_tags == [0]) {
            return Err(cannot(format!(
                "{what} has physical tags {:?}; MSH 2.2 stores one non-zero physical tag per \
                 element (write MSH 4.1)",
                block.physical_tags
            )));
        }
        let dim = if v22 { block.kind.dim() } else { block.entity_dim };
        if let Some(tag) =
            block.physical_tags.iter().find(|&&t| !mesh.groups.iter().any(|g| g.dim == dim && g.tag == t))
        {
            return Err(cannot(format!("{what} has physical tag {tag}, but no group of dimension {dim} has that tag")));
        }
        let key = (block.entity_dim, block.entity_tag);
        if !v22 {
            match entity_physical.get(&key) {
                Some(&other) if other != &block.physical_tags => {
                    return Err(cannot(format!(
                        "{what} has physical tags {:?}, another block of the same entity {:?}",
                        block.physical_tags, other
                    )));
                }
                Some(_) => {}
                None => {
                    entity_physical.insert(key, &block.physical_tags);
                }
            }
        }
    }
    if let Some(g) = mesh.groups.iter().find(|g| g.name.contains(['"', '\n', '\r']) || g.dim > 3) {
        return Err(cannot(format!(
            "group \"{}\" of dimension {} cannot be written (dimension above 3, or a quote or \
             line break in the name)",
            g.name, g.dim
        )));
    }
    Ok(node_tags)
}

/// A geometric entity as written in `$Entities`.
#[derive(Debug)]
struct Entity {
    physical: Vec<i32>,
    lo: [f64; 2],
    hi: [f64; 2],
    point: Option<[f64; 2]>,
}

/// The entities of the blocks, keyed and sorted by (dimension, tag).
fn entities(mesh: &Mesh) -> BTreeMap<(usize, i32), Entity> {
    let mut entities = BTreeMap::new();
    for block in &mesh.blocks {
        let entity = entities.entry((block.entity_dim, block.entity_tag)).or_insert_with(|| Entity {
            physical: block.physical_tags.clone(),
            lo: [f64::INFINITY; 2],
            hi: [f64::NEG_INFINITY; 2],
            point: None,
        });
        for id in &block.nodes {
            if let Some(p) = mesh.points.get(id.0) {
                entity.point.get_or_insert(*p);
                entity.lo = [entity.lo[0].min(p[0]), entity.lo[1].min(p[1])];
                entity.hi = [entity.hi[0].max(p[0]), entity.hi[1].max(p[1])];
            }
        }
    }
    for entity in entities.values_mut() {
        if entity.point.is_none() {
            entity.lo = [0.0; 2];
            entity.hi = [0.0; 2];
        }
    }
    entities
}

/// Consecutive nodes on one entity: (first, end, entity dimension, entity tag).
type NodeRun = (usize, usize, usize, i32);

/// Splits the nodes into runs classified on the lowest-dimensional entity that uses them.
fn node_runs(mesh: &Mesh, fallback: (usize, i32)) -> Vec<NodeRun> {
    let mut class: Vec<Option<(usize, i32)>> = vec![None; mesh.points.len()];
    for block in &mesh.blocks {
        for id in &block.nodes {
            if let Some(c) = class.get_mut(id.0) {
                if c.is_none_or(|(dim, _)| block.entity_dim < dim) {
                    *c = Some((block.entity_dim, block.entity_tag));
                }
            }
        }
    }
    let mut current = class.iter().flatten().next().copied().unwrap_or(fallback);
    let mut runs: Vec<NodeRun> = Vec::new();
    for (i, c) in class.iter().enumerate() {
        let entity = c.unwrap_or(current);
        current = entity;
        match runs.last_mut() {
            Some(run) if (run.2, run.3) == entity => run.1 = i + 1,
            _ => runs.push((i, i + 1, entity.0, entity.1)),
        }
    }
    runs
}

fn min_max(tags: impl Iterator<Item = u64>) -> (u64, u64) {
    tags.fold(None, |acc: Option<(u64, u64)>, t| Some(acc.map_or((t, t), |(lo, hi)| (lo.min(t), hi.max(t)))))
        .unwrap_or((0, 0))
}

fn write_v41(e: &mut Emitter, mesh: &Mesh, node_tags: &[u64]) {
    let mut entities = entities(mesh);
    let fallback = entities.keys().next().copied().unwrap_or((2, 1));
    if entities.is_empty() && !mesh.points.is_empty() {
        entities.insert(fallback, Entity { physical: Vec::new(), lo: [0.0; 2], hi: [0.0; 2], point: None });
    }
    let runs = node_runs(mesh, fallback);

    e.text("$Entities\n");
    for dim in 0..4 {
        e.size(entities.keys().filter(|k| k.0 == dim).count() as u64);
    }
    e.end_record();
    for (&(dim, tag), entity) in &entities {
        e.int(tag);
        if dim == 0 {
            let p = entity.point.unwrap_or([0.0; 2]);
            for v in [p[0], p[1], 0.0] {
                e.double(v);
            }
        } else {
            let (lo, hi) = (entity.lo, entity.hi);
            for v in [lo[0], lo[1], 0.0, hi[0], hi[1], 0.0] {
                e.double(v);
            }
        }
        e.size(entity.physical.len() as u64);
        entity.physical.iter().for_each(|&p| e.int(p));
        if dim > 0 {
            e.size(0);
        }
        e.end_record();
    }
    e.end_data();
    e.text("$EndEntities\n");

    e.text("$Nodes\n");
    let (lo, hi) = min_max(node_tags.iter().copied());
    for v in [runs.len() as u64, node_tags.len() as u64, lo, hi] {
        e.size(v);
    }
    e.end_record();
    for &(first, end, dim, tag) in &runs {
        e.int(dim as i32);
        e.int(tag);
        e.int(0);
        e.size((end - first) as u64);
        e.end_record();
        for &t in node_tags.get(first..end).unwrap_or_default() {
            e.size(t);
            e.end_record();
        }
        for p in mesh.points.get(first..end).unwrap_or_default() {
            for v in [p[0], p[1], 0.0] {
                e.double(v);
            }
            e.end_record();
        }
    }
    e.end_data();
    e.text("$EndNodes\n");

    e.text("$Elements\n");
    let all = mesh.blocks.iter().flat_map(|b| b.element_tags.iter().copied());
    let (lo, hi) = min_max(all);
    let total: usize = mesh.blocks.iter().map(CellBlock::len).sum();
    for v in [mesh.blocks.len() as u64, total as u64, lo, hi] {
        e.size(v);
    }
    e.end_record();
    for block in &mesh.blocks {
        e.int(block.entity_dim as i32);
        e.int(block.entity_tag);
        e.int(block.kind.gmsh_type());
        e.size(block.len() as u64);
        e.end_record();
        for (cell, &tag) in block.cells().zip(&block.element_tags) {
            e.size(tag);
            for id in cell {
                e.size(node_tags.get(id.0).copied().unwrap_or_default());
            }
            e.end_record();
        }
    }
    e.end_data();
    e.text("$EndElements\n");
}

/// A tag as an `int` (range checked before writing).
fn int(tag: u64) -> i32 {
    i32::try_from(tag).unwrap_or(i32::MAX)
}

fn write_v22(e: &mut Emitter, mesh: &Mesh, node_tags: &[u64]) {
    e.text(&format!("$Nodes\n{}\n", node_tags.len()));
    for (&tag, p) in node_tags.iter().zip(&mesh.points) {
        e.int(int(tag));
        for v in [p[0], p[1], 0.0] {
            e.double(v);
        }
        e.end_record();
    }
    e.end_data();
    e.text("$EndNodes\n");

    let total: usize = mesh.blocks.iter().map(CellBlock::len).sum();
    e.text(&format!("$Elements\n{total}\n"));
    for block in mesh.blocks.iter().filter(|b| !b.is_empty()) {
        let ty = block.kind.gmsh_type();
        let physical = block.physical_tags.first().copied().unwrap_or(0);
        if e.is_binary() {
            for v in [ty, int(block.len() as u64), 2] {
                e.int(v);
            }
        }
        for (cell, &tag) in block.cells().zip(&block.element_tags) {
            e.int(int(tag));
            if !e.is_binary() {
                e.int(ty);
                e.int(2);
            }
            e.int(physical);
            e.int(block.entity_tag);
            for id in cell {
                e.int(int(node_tags.get(id.0).copied().unwrap_or_default()));
            }
            e.end_record();
        }
    }
    e.end_data();
    e.text("$EndElements\n");
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::mesh::{CellKind, NodeId};
    use crate::msh::parse_msh_with_report;

    fn fixture(name: &str) -> Mesh {
        let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes/fixtures").join(name);
        crate::msh::read_msh(path).unwrap()
    }

    #[test]
    fn big_endian_files_of_the_fixtures_read_back() {
        for name in ["plate_hole_v41_bin.msh", "two_blocks_v22_ascii.msh", "strip_q8_v41_ascii.msh"] {
            let mesh = fixture(name);
            for format in [MshFormat::V41Binary, MshFormat::V22Binary] {
                let bytes = encode_with_byte_order(&mesh, format, true).unwrap();
                let (again, report) = parse_msh_with_report(&bytes).unwrap();
                assert!(report.big_endian);
                assert_eq!(report.format, format);
                assert_eq!(again, mesh, "{name} {format:?}");
                // Differs from the little-endian file in the words only.
                let le = encode_msh(&mesh, format).unwrap();
                assert_eq!(le.len(), bytes.len());
                assert_ne!(le, bytes);
            }
        }
    }

    fn block(kind: CellKind, dim: usize, tag: i32, nodes: &[usize], first: u64) -> CellBlock {
        let per = kind.nodes_per_cell();
        CellBlock {
            kind,
            entity_dim: dim,
            entity_tag: tag,
            physical_tags: vec![],
            nodes: nodes.iter().map(|&i| NodeId(i)).collect(),
            element_tags: (first..first + (nodes.len() / per) as u64).collect(),
        }
    }

    #[test]
    fn nodes_are_classified_on_the_lowest_entity_in_runs() {
        let mesh = Mesh {
            points: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [2.0, 2.0]],
            node_tags: vec![1, 2, 3, 4, 5],
            blocks: vec![
                block(CellKind::Tri3, 2, 7, &[0, 1, 2, 0, 2, 3], 1),
                block(CellKind::Line2, 1, 3, &[1, 2], 3),
                block(CellKind::Point1, 0, 9, &[3], 4),
            ],
            groups: vec![],
        };
        let runs = node_runs(&mesh, (2, 1));
        assert_eq!(runs, vec![(0, 1, 2, 7), (1, 3, 1, 3), (3, 5, 0, 9)], "node 4 is unused and joins the previous run");
        let entities = entities(&mesh);
        assert_eq!(entities.len(), 3);
        let point = &entities[&(0, 9)];
        assert_eq!(point.point, Some([0.0, 1.0]));
        let surface = &entities[&(2, 7)];
        assert_eq!((surface.lo, surface.hi), ([0.0, 0.0], [1.0, 1.0]));
    }

    #[test]
    fn ascii_layout_is_gmsh_like() {
        let mesh = Mesh {
            points: vec![[0.0, 0.0], [0.5, 0.0]],
            node_tags: vec![3, 8],
            blocks: vec![block(CellKind::Line2, 1, 2, &[0, 1], 5)],
            groups: vec![],
        };
        let text = String::from_utf8(encode_msh(&mesh, MshFormat::V41Ascii).unwrap()).unwrap();
        let expected = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n\
            $Entities\n0 1 0 0\n2 0 0 0 0.5 0 0 0 0\n$EndEntities\n\
            $Nodes\n1 2 3 8\n1 2 0 2\n3\n8\n0 0 0\n0.5 0 0\n$EndNodes\n\
            $Elements\n1 1 5 5\n1 2 1 1\n5 3 8\n$EndElements\n";
        assert_eq!(text, expected);
        let text = String::from_utf8(encode_msh(&mesh, MshFormat::V22Ascii).unwrap()).unwrap();
        let expected = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n\
            $Nodes\n2\n3 0 0 0\n8 0.5 0 0\n$EndNodes\n\
            $Elements\n1\n5 1 2 0 2 3 8\n$EndElements\n";
        assert_eq!(text, expected);
    }
}

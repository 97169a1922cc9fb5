//! Binary MSH files written by hand in both byte orders: they load to the expected mesh, and
//! each corruption is reported at the byte offset of the offending word.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_mesh::{
    CellBlock, CellKind, Location, Mesh, MeshError, MshFormat, NodeId, PhysicalGroup, parse_msh, parse_msh_with_report,
};

/// A binary file under construction; each write returns the offset of what it wrote.
struct Bin {
    out: Vec<u8>,
    big_endian: bool,
}

impl Bin {
    fn new(big_endian: bool) -> Self {
        Bin { out: Vec::new(), big_endian }
    }
    fn put(&mut self, le: &[u8], be: &[u8]) -> usize {
        let at = self.out.len();
        self.out.extend_from_slice(if self.big_endian { be } else { le });
        at
    }
    fn text(&mut self, s: &str) -> usize {
        self.put(s.as_bytes(), s.as_bytes())
    }
    fn int(&mut self, v: i32) -> usize {
        self.put(&v.to_le_bytes(), &v.to_be_bytes())
    }
    fn size(&mut self, v: u64) -> usize {
        self.put(&v.to_le_bytes(), &v.to_be_bytes())
    }
    fn double(&mut self, v: f64) -> usize {
        self.put(&v.to_le_bytes(), &v.to_be_bytes())
    }
}

/// Offsets of interesting words in a hand-written file.
#[derive(Default)]
struct Marks {
    marker: usize,
    nodes_count: usize,
    node_tag: Vec<usize>,
    node_x: Vec<usize>,
    element_type: Vec<usize>,
    element_tag: Vec<usize>,
    element_node: Vec<Vec<usize>>,
    end_nodes: usize,
    last_bounding_count: usize,
}

const POINTS: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
const TAGS: [u64; 4] = [10, 20, 30, 40];
const NAMES: &str = "$PhysicalNames\n2\n1 10 \"edge\"\n2 20 \"body\"\n$EndPhysicalNames\n";

/// The mesh both files hold: a unit square of two triangles and one named edge.
fn expected() -> Mesh {
    Mesh {
        points: POINTS.to_vec(),
        node_tags: TAGS.to_vec(),
        blocks: vec![
            CellBlock {
                kind: CellKind::Line2,
                entity_dim: 1,
                entity_tag: 1,
                physical_tags: vec![10],
                nodes: vec![NodeId(0), NodeId(1)],
                element_tags: vec![1],
            },
            CellBlock {
                kind: CellKind::Tri3,
                entity_dim: 2,
                entity_tag: 1,
                physical_tags: vec![20],
                nodes: [0, 1, 2, 0, 2, 3].map(NodeId).to_vec(),
                element_tags: vec![2, 3],
            },
        ],
        groups: vec![
            PhysicalGroup { name: "edge".into(), dim: 1, tag: 10 },
            PhysicalGroup { name: "body".into(), dim: 2, tag: 20 },
        ],
    }
}

fn v41(big_endian: bool) -> (Vec<u8>, Marks) {
    let mut b = Bin::new(big_endian);
    let mut m = Marks::default();
    b.text("$MeshFormat\n4.1 1 8\n");
    m.marker = b.int(1);
    b.text("\n$EndMeshFormat\n");
    b.text(NAMES);
    b.text("$Entities\n");
    for n in [0, 1, 1, 0] {
        b.size(n);
    }
    for (tag, physical, hi) in [(1, 10, [1.0, 0.0]), (1, 20, [1.0, 1.0])] {
        b.int(tag);
        for v in [0.0, 0.0, 0.0, hi[0], hi[1], 0.0] {
            b.double(v);
        }
        b.size(1);
        b.int(physical);
        m.last_bounding_count = b.size(0);
    }
    b.text("\n$EndEntities\n$Nodes\n");
    b.size(1);
    m.nodes_count = b.size(4);
    b.size(10);
    b.size(40);
    for v in [2, 1, 0] {
        b.int(v);
    }
    b.size(4);
    for t in TAGS {
        m.node_tag.push(b.size(t));
    }
    for p in POINTS {
        m.node_x.push(b.double(p[0]));
        b.double(p[1]);
        b.double(0.0);
    }
    m.end_nodes = b.text("\n$EndNodes\n") + 1;
    b.text("$Elements\n");
    for v in [2, 3, 1, 3] {
        b.size(v);
    }
    let blocks: [(i32, i32, &[[u64; 4]]); 2] = [(1, 1, &[[1, 10, 20, 0]]), (2, 2, &[[2, 10, 20, 30], [3, 10, 30, 40]])];
    for (dim, ty, cells) in blocks {
        b.int(dim);
        b.int(1);
        m.element_type.push(b.int(ty));
        b.size(cells.len() as u64);
        for cell in cells {
            m.element_tag.push(b.size(cell[0]));
            let nodes = if ty == 1 { &cell[1..3] } else { &cell[1..4] };
            m.element_node.push(nodes.iter().map(|&n| b.size(n)).collect());
        }
    }
    b.text("\n$EndElements\n");
    (b.out, m)
}

fn v22(big_endian: bool) -> (Vec<u8>, Marks) {
    let mut b = Bin::new(big_endian);
    let mut m = Marks::default();
    b.text("$MeshFormat\n2.2 1 8\n");
    m.marker = b.int(1);
    b.text("\n$EndMeshFormat\n");
    b.text(NAMES);
    m.nodes_count = b.text("$Nodes\n4\n") + 7;
    for (t, p) in TAGS.iter().zip(POINTS) {
        m.node_tag.push(b.int(*t as i32));
        m.node_x.push(b.double(p[0]));
        b.double(p[1]);
        b.double(0.0);
    }
    m.end_nodes = b.text("\n$EndNodes\n") + 1;
    b.text("$Elements\n3\n");
    let groups: [(i32, i32, i32, &[[i32; 4]]); 2] =
        [(1, 10, 1, &[[1, 10, 20, 0]]), (2, 20, 1, &[[2, 10, 20, 30], [3, 10, 30, 40]])];
    for (ty, physical, entity, cells) in groups {
        m.element_type.push(b.int(ty));
        b.int(cells.len() as i32);
        b.int(2);
        for cell in cells {
            m.element_tag.push(b.int(cell[0]));
            b.int(physical);
            b.int(entity);
            let nodes = if ty == 1 { &cell[1..3] } else { &cell[1..4] };
            m.element_node.push(nodes.iter().map(|&n| b.int(n)).collect());
        }
    }
    b.text("\n$EndElements\n");
    (b.out, m)
}

type Writer = fn(bool) -> (Vec<u8>, Marks);
const WRITERS: [(&str, Writer); 2] = [("4.1", v41), ("2.2", v22)];

fn patch(bytes: &[u8], at: usize, new: &[u8]) -> Vec<u8> {
    let mut out = bytes.to_vec();
    out[at..at + new.len()].copy_from_slice(new);
    out
}

fn word32(v: i32, big_endian: bool) -> [u8; 4] {
    if big_endian { v.to_be_bytes() } else { v.to_le_bytes() }
}

/// A tag word: `size_t` in 4.1, `int` in 2.2.
fn tag_word(version: &str, v: u64, big_endian: bool) -> Vec<u8> {
    match (version, big_endian) {
        ("4.1", false) => v.to_le_bytes().to_vec(),
        ("4.1", true) => v.to_be_bytes().to_vec(),
        (_, be) => word32(v as i32, be).to_vec(),
    }
}

fn f64_word(v: f64, big_endian: bool) -> [u8; 8] {
    if big_endian { v.to_be_bytes() } else { v.to_le_bytes() }
}

fn assert_msh_at(bytes: &[u8], offset: usize, needle: &str) {
    match parse_msh(bytes) {
        Err(MeshError::Msh { at, reason }) => {
            assert_eq!(at, Location::Byte(offset), "{reason}");
            assert!(reason.contains(needle), "'{reason}' lacks '{needle}'");
        }
        other => panic!("expected an Msh error at byte {offset}, got {other:?}"),
    }
}

#[test]
fn both_byte_orders_of_both_versions_load() {
    for (version, write) in WRITERS {
        for big_endian in [false, true] {
            let (bytes, _) = write(big_endian);
            let (mesh, report) = parse_msh_with_report(&bytes).unwrap();
            assert_eq!(mesh, expected(), "{version} big-endian {big_endian}");
            assert_eq!(report.big_endian, big_endian);
            let format = if version == "4.1" { MshFormat::V41Binary } else { MshFormat::V22Binary };
            assert_eq!(report.format, format);
        }
    }
}

#[test]
fn corrupt_words_are_reported_at_their_offset() {
    for (version, write) in WRITERS {
        for be in [false, true] {
            let (bytes, m) = write(be);
            let nan = f64_word(f64::NAN, be);
            assert_msh_at(&patch(&bytes, m.node_x[1], &nan), m.node_x[1], "not finite");
            let z = f64_word(1e-3, be);
            assert_msh_at(&patch(&bytes, m.node_x[2] + 16, &z), m.node_x[2], "z = 1e-3");
            let dup = tag_word(version, 10, be);
            assert_msh_at(&patch(&bytes, m.node_tag[1], &dup), m.node_tag[1], "appears twice");
            let missing = tag_word(version, 99, be);
            let at = m.element_node[1][2];
            assert_msh_at(&patch(&bytes, at, &missing), at, "refers to node 99");
            let dup = tag_word(version, 2, be);
            let at = m.element_tag[2];
            assert_msh_at(&patch(&bytes, at, &dup), at, "element tag 2 appears twice");
            assert_msh_at(&patch(&bytes, m.marker, &[2, 0, 0, 2]), m.marker, "endianness");
            assert_msh_at(&patch(&bytes, m.end_nodes, b"$EndNodez"), m.end_nodes, "$EndNodes");
            let at = m.element_type[1];
            match parse_msh(&patch(&bytes, at, &word32(4, be))) {
                Err(MeshError::Unsupported { at: a, what }) => {
                    assert_eq!(a, Location::Byte(at));
                    assert!(what.contains("element type 4"), "{what}");
                }
                other => panic!("{other:?}"),
            }
        }
    }
}

#[test]
fn counts_beyond_the_file_are_reported_at_the_count() {
    for be in [false, true] {
        let (bytes, m) = v41(be);
        let big = if be { 1_000_000u64.to_be_bytes() } else { 1_000_000u64.to_le_bytes() };
        assert_msh_at(&patch(&bytes, m.nodes_count, &big), m.nodes_count, "bytes remain");
        let (bytes, m) = v22(be);
        assert_msh_at(&patch(&bytes, m.nodes_count, b"9"), m.nodes_count, "bytes remain");
        // A group of 3 elements where 2 follow.
        let at = m.element_type[1];
        assert_msh_at(&patch(&bytes, at + 4, &word32(3, be)), at, "element group");
        let at = m.node_tag[0];
        assert_msh_at(&patch(&bytes, at, &word32(-1, be)), at, "negative");
    }
}

#[test]
fn every_truncation_is_an_error_inside_the_file() {
    for (_, write) in WRITERS {
        for be in [false, true] {
            let (bytes, _) = write(be);
            // Cutting anywhere before the final end marker is fully written must fail.
            for len in 0..bytes.len() - 2 {
                match parse_msh(&bytes[..len]) {
                    Err(MeshError::Msh { at: Location::Byte(b), .. }) => assert!(b <= len),
                    Err(MeshError::Msh { at: Location::Line(l), .. }) => assert!(l <= 3, "{len}"),
                    Err(MeshError::Unsupported { at: Location::Line(2), .. }) => assert!(len < 20),
                    other => panic!("cut at {len}: {other:?}"),
                }
            }
        }
    }
    // A word cut in the middle is reported at the word.
    let (bytes, m) = v41(false);
    let at = m.last_bounding_count;
    let cut = &bytes[..at + 3];
    match parse_msh(cut) {
        Err(MeshError::Msh { at: a, reason }) => {
            assert_eq!(a, Location::Byte(at), "{reason}");
            assert!(reason.contains("file ends inside the number of bounding entities"), "{reason}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn binary_data_size_other_than_8_is_unsupported() {
    let (bytes, _) = v41(false);
    let text = String::from_utf8_lossy(&bytes[..20]).replace("4.1 1 8", "4.1 1 4");
    let patched = patch(&bytes, 0, text.as_bytes());
    match parse_msh(&patched) {
        Err(MeshError::Unsupported { at, what }) => {
            assert_eq!(at, Location::Line(2));
            assert!(what.contains("data-size 4"), "{what}");
        }
        other => panic!("{other:?}"),
    }
}

//! Writer round trips: read -> write (every format) -> read gives an equal mesh, for the
//! committed fixtures and for random meshes (non-contiguous tags, every cell kind, exotic reals).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;

use contact2d_mesh::{
    CellBlock, CellKind, Mesh, MeshError, MshFormat, NodeId, PhysicalGroup, encode_msh, parse_msh, read_msh, write_msh,
};
use proptest::prelude::*;

fn fixtures() -> Vec<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes/fixtures");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "msh"))
        .collect();
    paths.sort();
    assert_eq!(paths.len(), 16, "four formats of plate_hole, two_blocks, strip_q8, clockwise_square");
    paths
}

#[test]
fn fixtures_round_trip_through_every_format() {
    for path in fixtures() {
        let mesh = read_msh(&path).unwrap();
        for format in MshFormat::ALL {
            let bytes = encode_msh(&mesh, format).unwrap();
            let again = parse_msh(&bytes).unwrap_or_else(|e| panic!("{}: {format:?}: {e}", path.display()));
            assert_eq!(again, mesh, "{}: {format:?}", path.display());
        }
    }
}

#[test]
fn write_msh_writes_a_file() {
    let mesh = read_msh(&fixtures()[0]).unwrap();
    let path = std::env::temp_dir().join(format!("contact2d-roundtrip-{}.msh", std::process::id()));
    write_msh(&mesh, &path, MshFormat::V41Ascii).unwrap();
    let again = read_msh(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(again, mesh);
    let missing = std::env::temp_dir().join("no-such-dir-contact2d/x.msh");
    assert!(matches!(write_msh(&mesh, &missing, MshFormat::V22Ascii), Err(MeshError::Io { .. })));
    assert!(matches!(read_msh(&missing), Err(MeshError::Io { .. })));
}

fn line(nodes: [usize; 2], tag: u64) -> CellBlock {
    CellBlock {
        kind: CellKind::Line2,
        entity_dim: 1,
        entity_tag: 1,
        physical_tags: vec![],
        nodes: nodes.map(NodeId).to_vec(),
        element_tags: vec![tag],
    }
}

fn two_nodes() -> Mesh {
    Mesh { points: vec![[0.0, 0.0], [1.0, 0.0]], node_tags: vec![1, 2], blocks: vec![line([0, 1], 1)], groups: vec![] }
}

#[test]
fn inconsistent_meshes_are_refused() {
    let cases: Vec<(Mesh, &str)> = vec![
        (Mesh { node_tags: vec![1], ..two_nodes() }, "1 node tags for 2 points"),
        (Mesh { node_tags: vec![3, 3], ..two_nodes() }, "node tag 3 is used twice"),
        (Mesh { points: vec![[0.0, f64::NAN], [1.0, 0.0]], ..two_nodes() }, "non-finite"),
        (Mesh { blocks: vec![line([0, 2], 1)], ..two_nodes() }, "refers to node #2"),
        (Mesh { blocks: vec![line([0, 1], 1), line([1, 0], 1)], ..two_nodes() }, "element tag 1"),
        (
            Mesh { blocks: vec![CellBlock { nodes: vec![NodeId(0)], ..line([0, 1], 1) }], ..two_nodes() },
            "1 node references for 1 cells",
        ),
        (
            Mesh { blocks: vec![CellBlock { physical_tags: vec![5], ..line([0, 1], 1) }], ..two_nodes() },
            "physical tag 5",
        ),
        (Mesh { groups: vec![PhysicalGroup { name: "a\"b".into(), dim: 1, tag: 5 }], ..two_nodes() }, "quote"),
    ];
    for (mesh, needle) in cases {
        for format in MshFormat::ALL {
            match encode_msh(&mesh, format) {
                Err(MeshError::CannotWrite { reason }) => {
                    assert!(reason.contains(needle), "'{reason}' lacks '{needle}'")
                }
                other => panic!("{format:?} {needle}: {other:?}"),
            }
        }
    }
}

#[test]
fn msh22_limits_are_checked() {
    let groups =
        vec![PhysicalGroup { name: "a".into(), dim: 1, tag: 5 }, PhysicalGroup { name: "b".into(), dim: 1, tag: 6 }];
    let two_groups =
        Mesh { blocks: vec![CellBlock { physical_tags: vec![5, 6], ..line([0, 1], 1) }], groups, ..two_nodes() };
    let big_tag = Mesh { node_tags: vec![1, 1 << 40], ..two_nodes() };
    for mesh in [&two_groups, &big_tag] {
        assert!(parse_msh(&encode_msh(mesh, MshFormat::V41Ascii).unwrap()).unwrap() == *mesh);
        for format in [MshFormat::V22Ascii, MshFormat::V22Binary] {
            assert!(matches!(encode_msh(mesh, format), Err(MeshError::CannotWrite { .. })));
        }
    }
    // Two blocks of one entity must agree on the physical tags in MSH 4.1.
    let disagree = Mesh {
        blocks: vec![
            CellBlock { physical_tags: vec![5], ..line([0, 1], 1) },
            CellBlock { physical_tags: vec![6], ..line([1, 0], 2) },
        ],
        ..two_groups.clone()
    };
    assert!(matches!(encode_msh(&disagree, MshFormat::V41Ascii), Err(MeshError::CannotWrite { .. })));
}

#[test]
fn empty_node_tags_mean_one_based_numbering() {
    let mesh = Mesh { node_tags: vec![], ..two_nodes() };
    let again = parse_msh(&encode_msh(&mesh, MshFormat::V22Ascii).unwrap()).unwrap();
    assert_eq!(again.node_tags, vec![1, 2]);
    let empty = Mesh::default();
    for format in MshFormat::ALL {
        assert_eq!(parse_msh(&encode_msh(&empty, format).unwrap()).unwrap(), empty);
    }
    // Nodes without cells survive a 4.1 round trip.
    let lonely = Mesh { blocks: vec![], ..two_nodes() };
    assert_eq!(parse_msh(&encode_msh(&lonely, MshFormat::V41Binary).unwrap()).unwrap(), lonely);
}

/// Reals of every magnitude, sign and subnormal.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![-10.0..10.0f64, prop::num::f64::NORMAL | prop::num::f64::SUBNORMAL | prop::num::f64::ZERO,]
}

/// A random mesh that every format can store: blocks of distinct (kind, entity), physical
/// tags a function of the entity, non-contiguous node and element tags below `i32::MAX`, no two
/// cells of one dimension on the same node set (the reader refuses an element written twice).
fn arb_mesh() -> impl Strategy<Value = Mesh> {
    (1usize..25)
        .prop_flat_map(|n| {
            let points = prop::collection::vec([coordinate(), coordinate()], n);
            let tags = prop::collection::hash_set(1u64..2_000_000_000, n);
            let block = (0usize..8, 1i32..5, prop::collection::vec(prop::collection::vec(0..n, 9), 1..5));
            let blocks = prop::collection::vec(block, 0..6);
            let element_tags = prop::collection::hash_set(1u64..2_000_000_000, 30);
            (points, tags, blocks, element_tags)
        })
        .prop_map(|(points, tags, raw, element_tags)| {
            let mut element_tags = element_tags.into_iter();
            let mut blocks: Vec<CellBlock> = Vec::new();
            let mut node_sets = std::collections::HashSet::new();
            for (k, entity, cells) in raw {
                let kind = CellKind::ALL[k];
                if blocks.iter().any(|b| b.kind == kind && b.entity_tag == entity) {
                    continue;
                }
                let per = kind.nodes_per_cell();
                let cells: Vec<Vec<usize>> = cells
                    .into_iter()
                    .filter(|c| {
                        let mut set = c[..per].to_vec();
                        set.sort_unstable();
                        kind.dim() == 0 || node_sets.insert((kind.dim(), set))
                    })
                    .collect();
                if cells.is_empty() {
                    continue;
                }
                blocks.push(CellBlock {
                    kind,
                    entity_dim: kind.dim(),
                    entity_tag: entity,
                    physical_tags: if entity % 3 == 0 { vec![] } else { vec![1 + entity % 2] },
                    nodes: cells.iter().flat_map(|c| c[..per].iter().map(|&i| NodeId(i))).collect(),
                    element_tags: cells.iter().map(|_| element_tags.next().unwrap()).collect(),
                });
            }
            let groups = (0..3)
                .flat_map(|dim| (1..3).map(move |tag| PhysicalGroup { name: format!("d{dim} t{tag}"), dim, tag }))
                .collect();
            Mesh { points, node_tags: tags.into_iter().collect(), blocks, groups }
        })
}

proptest! {
    #[test]
    fn random_meshes_round_trip(mesh in arb_mesh()) {
        for format in MshFormat::ALL {
            let bytes = encode_msh(&mesh, format).unwrap();
            let again = parse_msh(&bytes).unwrap();
            prop_assert_eq!(&again, &mesh, "{:?}", format);
            // Bit-for-bit points, signs of zero included.
            for (p, q) in again.points.iter().zip(&mesh.points) {
                prop_assert_eq!(p.map(f64::to_bits), q.map(f64::to_bits));
            }
        }
    }
}

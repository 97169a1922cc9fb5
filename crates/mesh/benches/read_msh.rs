//! Reading speed of `read_msh` on a generated multi-megabyte structured Q9 mesh, written by our
//! own writer to a temporary directory in each of the four formats. Throughput is reported in
//! MB/s (10^6 bytes per second) of file read.
//!
//! ```text
//!   1 ┌───┬───┬── ... ┐     N x N Quad9 cells on the unit square, (2N+1)^2 nodes,
//!     │ 9 │ 9 │       │     Line3 blocks on the four sides, named groups
//!     ├───┼───┤       │     "bottom", "right", "top", "left", "body"
//!   0 └───┴───┴── ... ┘
//!     0               1
//! ```
//!
//! Run with `cargo bench -p contact2d-mesh --bench read_msh`; set `READ_MSH_N` to change N.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use std::hint::black_box;
use std::path::PathBuf;

use contact2d_mesh::{CellBlock, CellKind, Mesh, MshFormat, NodeId, PhysicalGroup, read_msh, write_msh};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

/// N x N Quad9 cells with Gmsh node order (corners counter-clockwise, mid-sides, centre).
fn structured_q9(n: usize) -> Mesh {
    let m = 2 * n + 1;
    let h = 1.0 / (2 * n) as f64;
    let id = |i: usize, j: usize| NodeId(j * m + i);
    // Perturbed by a fraction of h so that coordinates have the 16-17 significant digits of
    // a real (unstructured) Gmsh mesh rather than short decimal fractions.
    let points = (0..m * m)
        .map(|k| {
            let wobble = 1e-3 * h * (k as f64).sin();
            [(k % m) as f64 * h + wobble, (k / m) as f64 * h - wobble]
        })
        .collect();
    let mut tag = 0u64;
    let mut next_tag = || {
        tag += 1;
        tag
    };
    let mut body = Vec::with_capacity(9 * n * n);
    let mut body_tags = Vec::with_capacity(n * n);
    for cj in 0..n {
        for ci in 0..n {
            let (i, j) = (2 * ci, 2 * cj);
            body.extend([
                id(i, j),
                id(i + 2, j),
                id(i + 2, j + 2),
                id(i, j + 2),
                id(i + 1, j),
                id(i + 2, j + 1),
                id(i + 1, j + 2),
                id(i, j + 1),
                id(i + 1, j + 1),
            ]);
            body_tags.push(next_tag());
        }
    }
    let side = |nodes: &dyn Fn(usize) -> [NodeId; 3], tag: i32, next: &mut dyn FnMut() -> u64| CellBlock {
        kind: CellKind::Line3,
        entity_dim: 1,
        entity_tag: tag,
        physical_tags: vec![tag],
        nodes: (0..n).flat_map(nodes).collect(),
        element_tags: (0..n).map(|_| next()).collect(),
    };
    let blocks = vec![
        side(&|c| [id(2 * c, 0), id(2 * c + 2, 0), id(2 * c + 1, 0)], 1, &mut next_tag),
        side(&|c| [id(m - 1, 2 * c), id(m - 1, 2 * c + 2), id(m - 1, 2 * c + 1)], 2, &mut next_tag),
        side(&|c| [id(2 * c + 2, m - 1), id(2 * c, m - 1), id(2 * c + 1, m - 1)], 3, &mut next_tag),
        side(&|c| [id(0, 2 * c + 2), id(0, 2 * c), id(0, 2 * c + 1)], 4, &mut next_tag),
        CellBlock {
            kind: CellKind::Quad9,
            entity_dim: 2,
            entity_tag: 1,
            physical_tags: vec![5],
            nodes: body,
            element_tags: body_tags,
        },
    ];
    let groups = ["bottom", "right", "top", "left", "body"]
        .iter()
        .zip(1..)
        .map(|(name, tag)| PhysicalGroup { name: name.to_string(), dim: if tag == 5 { 2 } else { 1 }, tag })
        .collect();
    Mesh { points, node_tags: (1..=(m * m) as u64).collect(), blocks, groups }
}

fn bench_read(c: &mut Criterion) {
    let n: usize = std::env::var("READ_MSH_N").ok().and_then(|s| s.parse().ok()).unwrap_or(250);
    let mesh = structured_q9(n);
    let dir = std::env::temp_dir().join(format!("contact2d-bench-read-msh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut group = c.benchmark_group("read_msh");
    group.sample_size(10);
    for (name, format) in [
        ("v41_ascii", MshFormat::V41Ascii),
        ("v41_binary", MshFormat::V41Binary),
        ("v22_ascii", MshFormat::V22Ascii),
        ("v22_binary", MshFormat::V22Binary),
    ] {
        let path: PathBuf = dir.join(format!("q9_{n}_{name}.msh"));
        write_msh(&mesh, &path, format).unwrap();
        let bytes = std::fs::metadata(&path).unwrap().len();
        assert_eq!(read_msh(&path).unwrap(), mesh);
        eprintln!("{name}: {n}x{n} Quad9, {} nodes, {:.1} MB", mesh.num_nodes(), bytes as f64 / 1e6);
        group.throughput(Throughput::BytesDecimal(bytes));
        group.bench_function(name, |b| b.iter(|| read_msh(black_box(&path)).unwrap()));
    }
    group.finish();
    std::fs::remove_dir_all(&dir).unwrap();
}

criterion_group!(benches, bench_read);
criterion_main!(benches);

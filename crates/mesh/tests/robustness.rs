//! No input makes the reader panic: arbitrary bytes, valid headers followed by garbage, and
//! random mutations (truncations, byte flips, line deletions, duplications and swaps) of the
//! committed fixtures all give `Ok` or a typed error.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;
use std::sync::OnceLock;

use contact2d_mesh::{Location, MeshError, parse_msh};
use proptest::prelude::*;

fn fixtures() -> &'static [Vec<u8>] {
    static FIXTURES: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    FIXTURES.get_or_init(|| {
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes/fixtures");
        let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "msh"))
            .collect();
        paths.sort();
        paths.iter().map(|p| std::fs::read(p).unwrap()).collect()
    })
}

/// Parses and checks that an error's location lies inside the input.
fn parse_checked(bytes: &[u8]) {
    match parse_msh(bytes) {
        Ok(_) | Err(MeshError::UnknownPhysicalGroup(_)) => {}
        Err(MeshError::Msh { at, .. }) | Err(MeshError::Unsupported { at, .. }) => match at {
            Location::Byte(b) => assert!(b <= bytes.len(), "byte {b} of {}", bytes.len()),
            Location::Line(l) => {
                let lines = bytes.iter().filter(|&&b| b == b'\n').count() + 1;
                assert!(l <= lines, "line {l} of {lines}");
            }
        },
        Err(other) => panic!("unexpected error kind: {other:?}"),
    }
}

/// One edit of a file.
#[derive(Debug, Clone)]
enum Mutation {
    Truncate(prop::sample::Index),
    Flip(prop::sample::Index, u8),
    DeleteLine(prop::sample::Index),
    DuplicateLine(prop::sample::Index),
    SwapLines(prop::sample::Index, prop::sample::Index),
    InsertToken(prop::sample::Index, &'static str),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let token = prop::sample::select(vec![
        " ",
        "\n",
        "0",
        "-1",
        "99999999999999999999",
        "nan",
        "1e400",
        "$EndNodes",
        "\"",
        "$",
    ]);
    prop_oneof![
        any::<prop::sample::Index>().prop_map(Mutation::Truncate),
        (any::<prop::sample::Index>(), any::<u8>()).prop_map(|(i, b)| Mutation::Flip(i, b)),
        any::<prop::sample::Index>().prop_map(Mutation::DeleteLine),
        any::<prop::sample::Index>().prop_map(Mutation::DuplicateLine),
        (any::<prop::sample::Index>(), any::<prop::sample::Index>()).prop_map(|(a, b)| Mutation::SwapLines(a, b)),
        (any::<prop::sample::Index>(), token).prop_map(|(i, t)| Mutation::InsertToken(i, t)),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    if bytes.is_empty() {
        return;
    }
    let mut lines: Vec<Vec<u8>> = bytes.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    match m {
        Mutation::Truncate(i) => bytes.truncate(i.index(bytes.len())),
        Mutation::Flip(i, b) => {
            let i = i.index(bytes.len());
            bytes[i] = *b;
        }
        Mutation::InsertToken(i, t) => {
            let i = i.index(bytes.len());
            bytes.splice(i..i, t.bytes());
        }
        Mutation::DeleteLine(i) => {
            lines.remove(i.index(lines.len()));
            *bytes = lines.join(&b'\n');
        }
        Mutation::DuplicateLine(i) => {
            let i = i.index(lines.len());
            lines.insert(i, lines[i].clone());
            *bytes = lines.join(&b'\n');
        }
        Mutation::SwapLines(a, b) => {
            let (a, b) = (a.index(lines.len()), b.index(lines.len()));
            lines.swap(a, b);
            *bytes = lines.join(&b'\n');
        }
    }
}

const HEADERS: [&[u8]; 4] = [
    b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n",
    b"$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n",
    b"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n",
    b"$MeshFormat\n2.2 1 8\n\0\0\0\x01\n$EndMeshFormat\n",
];

const SECTIONS: [&[u8]; 5] = [
    b"$Nodes\n",
    b"$Elements\n",
    b"$Entities\n",
    b"$PhysicalNames\n",
    b"$Nodes\n1 1 1 1\n0 1 0 1\n1\n0 0 0\n$EndNodes\n$Elements\n",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        parse_checked(&bytes);
    }

    #[test]
    fn garbage_after_valid_headers_never_panics(
        header in prop::sample::select(HEADERS.to_vec()),
        section in prop::sample::select(SECTIONS.to_vec()),
        tail in prop::collection::vec(any::<u8>(), 0..256),
    ) {
        let mut bytes = header.to_vec();
        bytes.extend_from_slice(section);
        bytes.extend_from_slice(&tail);
        parse_checked(&bytes);
    }

    #[test]
    fn garbage_words_in_binary_sections_never_panic(
        header in prop::sample::select(vec![HEADERS[1], HEADERS[3]]),
        section in prop::sample::select(SECTIONS[..3].to_vec()),
        words in prop::collection::vec(prop_oneof![Just(0u64), Just(1), Just(u64::MAX), 0u64..64, any::<u64>()], 0..40),
    ) {
        let mut bytes = header.to_vec();
        bytes.extend_from_slice(section);
        for w in words {
            bytes.extend_from_slice(&w.to_le_bytes());
        }
        parse_checked(&bytes);
    }

    #[test]
    fn mutated_fixtures_never_panic(
        which in any::<prop::sample::Index>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let fixtures = fixtures();
        let mut bytes = fixtures[which.index(fixtures.len())].clone();
        for m in &mutations {
            apply(&mut bytes, m);
        }
        parse_checked(&bytes);
    }
}

#[test]
fn every_prefix_of_every_fixture_is_handled() {
    for bytes in fixtures() {
        for len in (0..bytes.len()).step_by(7) {
            parse_checked(&bytes[..len]);
        }
    }
}

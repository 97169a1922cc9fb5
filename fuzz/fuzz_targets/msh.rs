//! The Gmsh reader on arbitrary bytes (ASCII and binary: the format line decides): any input
//! gives a mesh or a typed error, never a panic, and an error's location lies inside the input.
#![no_main]

use contact2d_mesh::{Location, MeshError, parse_msh};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    if let Err(MeshError::Msh { at, .. } | MeshError::Unsupported { at, .. }) = parse_msh(bytes) {
        match at {
            Location::Byte(b) => assert!(b <= bytes.len(), "byte {b} of {}", bytes.len()),
            Location::Line(l) => assert!(l <= bytes.iter().filter(|&&b| b == b'\n').count() + 1, "line {l}"),
        }
    }
});

//! Our own Gmsh `.msh` reader and writer: MSH 4.1 and 2.2, ASCII and binary.
//!
//! ```text
//!   read_msh(path) ─┐
//!   parse_msh(bytes) ┴─▶ $MeshFormat ─▶ sections... ─▶ Mesh
//!                        version, ASCII/binary,        $PhysicalNames  -> groups
//!                        byte order                    $Entities (4.1) -> physical tags of blocks
//!                                                      $Nodes          -> points, node_tags
//!                                                      $Elements       -> blocks
//!   write_msh(mesh, path, MshFormat) / encode_msh(mesh, MshFormat)
//! ```
//!
//! # What is read
//! * Versions 4.1 and 2.2, ASCII (file-type 0) and binary (file-type 1) with either byte order
//!   (from the endianness marker) and data-size 8. Other versions, data-sizes: `Unsupported`.
//! * Element types 15, 1, 8, 2, 9, 3, 16, 10 ([`CellKind`](crate::CellKind)); any other
//!   type is [`MeshError::Unsupported`] naming the type and where it is.
//! * Node tags may be any non-contiguous set; nodes get dense [`NodeId`](crate::NodeId)s in
//!   order of appearance and [`Mesh::node_tags`] keeps the file's tags.
//! * Blocks: MSH 4.1 gives one block per element block of the file (entity, type), with the
//!   physical tags of its entity in `$Entities`. MSH 2.2 groups elements by
//!   (type, elementary tag, physical tag) in order of first appearance; physical tag 0 is none.
//! * The z coordinate must vanish: `|z| <= 1e-12 · (1 + bounding-box diagonal)`.
//!
//! # Sections
//! `$MeshFormat` must come first, then any order the format allows, each section at most once;
//! `$Nodes` and `$Elements` are required, `$Entities` (4.1 only) must precede `$Elements` and
//! `$Nodes` must precede `$Elements`. `$PartitionedEntities`, `$GhostElements` and
//! `$Parametrizations` are refused with [`MeshError::Unsupported`]; any other section
//! (`$Periodic`, `$NodeData`, `$ElementData`, `$ElementNodeData`, `$InterpolationScheme`,
//! `$Comments`, user sections) is skipped, as the MSH specification prescribes, and its name is
//! listed in [`MshReport::skipped_sections`].
//!
//! # Errors
//! Malformed input is [`MeshError::Msh`] with the [`Location`](crate::Location): the 1-based line in an ASCII
//! file, the 0-based byte offset from the start of the file in a binary one. Among the checks:
//! bad numbers, wrong counts, truncated files, missing `$End...` markers, duplicate node or
//! element tags, elements referring to missing nodes, NaN or infinite coordinates, non-zero z,
//! and physical tags that `$PhysicalNames` does not name. The last is an error rather than a
//! group with an invented name, because contact2d finds regions and boundaries by name: an
//! unnamed group could never be referred to, and silently dropping it hides a mistake in the
//! `.geo` file (the message says how to name it). No input makes the reader panic.
//!
//! # Examples
//! ```
//! use contact2d_mesh::msh::parse_msh;
//! let text = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n\
//! $Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n\
//! $Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
//! let mesh = parse_msh(text).unwrap();
//! assert_eq!(mesh.num_nodes(), 3);
//! assert_eq!(mesh.blocks[0].len(), 1);
//! ```
//!
//! # References
//! Gmsh reference manual, section "MSH file format" (versions 4.1 and 2.2),
//! <https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format>.

mod ascii;
mod binary;
mod builder;
mod cursor;
mod emit;
mod format;
mod physical;
mod sections;
mod tags;
mod v2;
mod v4;
mod write;

pub use write::{MshFormat, encode_msh, write_msh};

use std::path::Path;

use builder::MeshBuilder;
use cursor::{Cursor, msh_error, unsupported};
use format::Version;
use sections::Section;

use crate::error::MeshError;
use crate::mesh::Mesh;

/// What the reader learnt about a file besides the mesh.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MshReport {
    /// Version and encoding of the file.
    pub format: MshFormat,
    /// Whether a binary file was big-endian (always `false` for ASCII).
    pub big_endian: bool,
    /// Names (without `$`) of the sections skipped, in file order.
    pub skipped_sections: Vec<String>,
}

/// Reads the MSH file at `path`.
///
/// # Errors
/// [`MeshError::Io`] if the file cannot be read; otherwise as [`parse_msh`].
pub fn read_msh(path: impl AsRef<Path>) -> Result<Mesh, MeshError> {
    let path = path.as_ref();
    let bytes = std::fs::read(path).map_err(|source| MeshError::Io { path: path.display().to_string(), source })?;
    parse_msh(&bytes)
}

/// Parses an MSH file held in memory.
///
/// # Errors
/// [`MeshError::Msh`] for malformed input, [`MeshError::Unsupported`] for valid MSH content
/// contact2d does not read (see the module doc).
pub fn parse_msh(bytes: &[u8]) -> Result<Mesh, MeshError> {
    parse_msh_with_report(bytes).map(|(mesh, _)| mesh)
}

/// Parses an MSH file held in memory and reports its format and the sections skipped.
///
/// # Errors
/// As [`parse_msh`].
pub fn parse_msh_with_report(bytes: &[u8]) -> Result<(Mesh, MshReport), MeshError> {
    let mut c = Cursor::new(bytes);
    let version = format::read_mesh_format(&mut c)?;
    let big_endian = matches!(c.encoding, cursor::Encoding::Binary { big_endian: true });
    let format = match (version, c.is_binary()) {
        (Version::V41, false) => MshFormat::V41Ascii,
        (Version::V41, true) => MshFormat::V41Binary,
        (Version::V22, false) => MshFormat::V22Ascii,
        (Version::V22, true) => MshFormat::V22Binary,
    };
    let mut builder = MeshBuilder::new();
    let mut names = None;
    let mut entities = None;
    let mut nodes_read = false;
    let mut elements_read = false;
    let mut skipped_sections = Vec::new();

    while let Some((name, at)) = c.next_section()? {
        let twice = || msh_error(at, format!("a second ${name} section"));
        match sections::classify(name) {
            Section::MeshFormat => return Err(twice()),
            Section::PhysicalNames => {
                if names.is_some() {
                    return Err(twice());
                }
                names = Some(physical::read_physical_names(&mut c)?);
            }
            Section::Entities => {
                if version == Version::V22 {
                    return Err(msh_error(at, "$Entities is not part of MSH 2.2"));
                }
                if entities.is_some() {
                    return Err(twice());
                }
                if elements_read {
                    return Err(msh_error(at, "$Entities must come before $Elements"));
                }
                entities = Some(v4::read_entities(&mut c, &mut builder)?);
            }
            Section::Nodes => {
                if nodes_read {
                    return Err(twice());
                }
                match version {
                    Version::V41 => v4::read_nodes(&mut c, &mut builder)?,
                    Version::V22 => v2::read_nodes(&mut c, &mut builder)?,
                }
                nodes_read = true;
            }
            Section::Elements => {
                if elements_read {
                    return Err(twice());
                }
                if !nodes_read {
                    return Err(msh_error(at, "$Elements must come after $Nodes"));
                }
                match version {
                    Version::V41 => v4::read_elements(&mut c, &mut builder, entities.as_ref())?,
                    Version::V22 => v2::read_elements(&mut c, &mut builder)?,
                }
                elements_read = true;
            }
            Section::Unsupported => {
                return Err(unsupported(
                    at,
                    format!("section ${name} (partitioned or parametrized meshes are not read)"),
                ));
            }
            Section::Skipped => {
                c.skip_section(name, at)?;
                skipped_sections.push(name.to_string());
                continue;
            }
        }
        c.expect_end(name)?;
    }
    for (read, name) in [(nodes_read, "$Nodes"), (elements_read, "$Elements")] {
        if !read {
            return Err(msh_error(c.loc(), format!("the file has no {name} section")));
        }
    }
    let mesh = builder.finish(names.unwrap_or_default())?;
    Ok((mesh, MshReport { format, big_endian, skipped_sections }))
}

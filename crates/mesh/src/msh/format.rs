//! The `$MeshFormat` header: version, file type, data size and byte order.
//!
//! ```text
//!   $MeshFormat
//!   4.1 0 8            version (4.1 or 2.2), file-type (0 ASCII, 1 binary), data-size
//!   $EndMeshFormat
//!
//!   $MeshFormat
//!   4.1 1 8\n          binary: the line is followed by the int 1 (4 bytes), so the
//!   <01 00 00 00>\n    reader learns the writer's byte order
//!   $EndMeshFormat
//! ```
//!
//! The data-size is the size of `size_t` in binary files; contact2d reads data-size 8 only
//! (every 64-bit Gmsh writes 8). ASCII files ignore it.

use super::cursor::{Cursor, Encoding, msh_error, show, unsupported};
use crate::error::MeshError;

/// The MSH versions contact2d reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Version {
    /// MSH 4.1 (Gmsh 4's default).
    V41,
    /// MSH 2.2 (the legacy format many tools still write).
    V22,
}

/// Reads the `$MeshFormat` section, which must open the file, and sets the cursor's encoding.
///
/// # Errors
/// [`MeshError::Msh`] if the file does not start with a valid header;
/// [`MeshError::Unsupported`] for another MSH version or a binary data-size other than 8.
pub(crate) fn read_mesh_format(c: &mut Cursor<'_>) -> Result<Version, MeshError> {
    c.skip_space();
    let at = c.loc();
    match c.text_token() {
        Some(b"$MeshFormat") => {}
        Some(b"$NOD") | Some(b"$NOE") => {
            return Err(unsupported(
                at,
                "MSH version 1 (contact2d reads 4.1 and 2.2; re-save with gmsh -format msh41)",
            ));
        }
        Some(token) => {
            return Err(msh_error(at, format!("not an MSH file: expected $MeshFormat, found '{}'", show(token))));
        }
        None => return Err(msh_error(at, "empty file: expected $MeshFormat")),
    }
    c.text_end_line()?;

    let token = c.text_field("the MSH version")?;
    let version = match token {
        b"4.1" => Version::V41,
        b"2.2" => Version::V22,
        other => {
            let text = show(other);
            return Err(if text.parse::<f64>().is_ok() {
                unsupported(
                    c.field_loc(),
                    format!("MSH version {text} (contact2d reads 4.1 and 2.2; re-save with gmsh -format msh41)"),
                )
            } else {
                msh_error(c.field_loc(), format!("expected the MSH version, found '{text}'"))
            });
        }
    };
    let binary = match c.text_u64("the file type (0 ASCII, 1 binary)")? {
        0 => false,
        1 => true,
        other => {
            return Err(msh_error(
                c.field_loc(),
                format!("the file type must be 0 (ASCII) or 1 (binary), found {other}"),
            ));
        }
    };
    let data_size = c.text_u64("the data size")?;
    if binary && data_size != 8 {
        return Err(unsupported(
            c.field_loc(),
            format!("binary data-size {data_size} (the size of size_t in the writer); contact2d reads data-size 8"),
        ));
    }
    if binary {
        // Exactly one newline may separate the line from the endianness marker.
        c.encoding = Encoding::Binary { big_endian: false };
        c.text_end_line()?;
        c.start_binary()?;
    } else {
        c.text_end_line()?;
    }
    c.expect_end("MeshFormat")?;
    Ok(version)
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::error::Location;

    fn read(bytes: &[u8]) -> Result<(Version, bool, Cursor<'_>), MeshError> {
        let mut c = Cursor::new(bytes);
        let v = read_mesh_format(&mut c)?;
        Ok((v, c.is_binary(), c))
    }

    #[test]
    fn ascii_and_binary_headers() {
        let (v, bin, _) = read(b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n").unwrap();
        assert_eq!((v, bin), (Version::V41, false));
        let (v, bin, _) = read(b"\n$MeshFormat\r\n2.2 0 8\r\n$EndMeshFormat\r\n").unwrap();
        assert_eq!((v, bin), (Version::V22, false));
        let (v, bin, c) = read(b"$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n").unwrap();
        assert_eq!((v, bin), (Version::V41, true));
        assert_eq!(c.encoding, Encoding::Binary { big_endian: false });
        let (_, _, c) = read(b"$MeshFormat\n2.2 1 8\n\0\0\0\x01\n$EndMeshFormat\n").unwrap();
        assert_eq!(c.encoding, Encoding::Binary { big_endian: true });
    }

    #[test]
    fn header_errors() {
        let cases: [(&[u8], bool, Location); 10] = [
            (b"", false, Location::Line(1)),
            (b"\n\nhello\n", false, Location::Line(3)),
            (b"$NOD\n3\n", true, Location::Line(1)),
            (b"$MeshFormat\n4.0 0 8\n$EndMeshFormat\n", true, Location::Line(2)),
            (b"$MeshFormat\nfour 0 8\n$EndMeshFormat\n", false, Location::Line(2)),
            (b"$MeshFormat\n4.1 2 8\n$EndMeshFormat\n", false, Location::Line(2)),
            (b"$MeshFormat\n4.1 1 4\n\x01\0\0\0\n$EndMeshFormat\n", true, Location::Line(2)),
            (b"$MeshFormat\n4.1 1 8\n\x02\0\0\0\n$EndMeshFormat\n", false, Location::Byte(20)),
            (b"$MeshFormat\n4.1 0 8\n$EndNodes\n", false, Location::Line(3)),
            (b"$MeshFormat\n4.1 0 8 7\n$EndMeshFormat\n", false, Location::Line(2)),
        ];
        for (bytes, is_unsupported, at) in cases {
            let e = read(bytes).err().unwrap();
            match e {
                MeshError::Unsupported { at: a, .. } if is_unsupported => assert_eq!(a, at),
                MeshError::Msh { at: a, .. } if !is_unsupported => assert_eq!(a, at, "{e}"),
                other => panic!("{:?}: unexpected {other}", show(bytes)),
            }
        }
    }

    #[test]
    fn ascii_data_size_is_ignored() {
        assert!(read(b"$MeshFormat\n4.1 0 4\n$EndMeshFormat\n").is_ok());
    }
}

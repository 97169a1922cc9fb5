//! The read position in an MSH file: byte offset, line number, encoding, and the field readers
//! that the section parsers share.
//!
//! ```text
//!   buf ─────────────────────────────────────────────────────────────▶
//!        $Nodes\n  <fields: text tokens or binary words>  \n$EndNodes\n
//!                  ▲ pos (0-based byte offset), line (1-based, text only)
//! ```
//!
//! An MSH file is a sequence of sections opened by a `$Name` line and closed by `$EndName`.
//! Section markers and a few sections (`$PhysicalNames`, the counts of MSH 2.2) are always text;
//! the data of the other sections is text in an ASCII file and machine words in a binary file.
//! The section parsers read that data through the *field* methods ([`Cursor::size`],
//! [`Cursor::int`], [`Cursor::double`], [`Cursor::end_record`]) which read a text token or a
//! binary word depending on the file, so one parser serves both encodings of MSH 4.1.
//!
//! Error locations are [`Location::Line`] (1-based) in ASCII files and [`Location::Byte`]
//! (0-based offset from the start of the file) in binary files.

use crate::error::{Location, MeshError};

/// How the data of the non-text sections is encoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Encoding {
    /// Whitespace-separated text tokens, one record per line.
    Ascii,
    /// Machine words in the given byte order.
    Binary {
        /// Whether the file was written on a big-endian machine.
        big_endian: bool,
    },
}

/// A read position in an MSH file held in memory.
#[derive(Debug)]
pub(crate) struct Cursor<'a> {
    /// The whole file.
    pub(crate) buf: &'a [u8],
    /// Offset of the next unread byte.
    pub(crate) pos: usize,
    /// 1-based line number of `pos` (meaningful while the file is read as text).
    pub(crate) line: usize,
    /// Offset where the last field started (for errors found after reading it).
    pub(crate) field_start: usize,
    /// Encoding of the section data.
    pub(crate) encoding: Encoding,
}

impl<'a> Cursor<'a> {
    /// A cursor at the start of `buf`, reading text until told otherwise.
    pub(crate) fn new(buf: &'a [u8]) -> Self {
        Cursor { buf, pos: 0, line: 1, field_start: 0, encoding: Encoding::Ascii }
    }

    /// Whether the section data is binary.
    pub(crate) fn is_binary(&self) -> bool {
        matches!(self.encoding, Encoding::Binary { .. })
    }

    /// Where the cursor is: the line in an ASCII file, the byte offset in a binary one.
    pub(crate) fn loc(&self) -> Location {
        self.loc_at(self.pos)
    }

    /// Where the last field read started.
    pub(crate) fn field_loc(&self) -> Location {
        self.loc_at(self.field_start)
    }

    fn loc_at(&self, offset: usize) -> Location {
        if self.is_binary() { Location::Byte(offset) } else { Location::Line(self.line) }
    }

    /// Bytes not read yet.
    pub(crate) fn remaining(&self) -> usize {
        self.buf.len().saturating_sub(self.pos)
    }

    /// A [`MeshError::Msh`] at the cursor.
    pub(crate) fn error(&self, reason: impl Into<String>) -> MeshError {
        msh_error(self.loc(), reason)
    }

    /// Reads a count (a size field) and checks that the rest of the file can hold that many
    /// records of at least `tokens` text tokens or `bytes` binary bytes each, so that a corrupt
    /// count fails here, with its location, instead of allocating without bound.
    pub(crate) fn count(&mut self, what: &str, tokens: usize, bytes: usize) -> Result<usize, MeshError> {
        let n = self.size(what)?;
        self.bounded(n, what, tokens, bytes)
    }

    /// Like [`Cursor::count`] for a count written as text in any file (MSH 2.2 counts).
    pub(crate) fn text_count(&mut self, what: &str, tokens: usize, bytes: usize) -> Result<usize, MeshError> {
        let n = self.text_u64(what)?;
        self.bounded(n, what, tokens, bytes)
    }

    /// Checks the count `n` just read (see [`Cursor::count`]).
    fn bounded(&self, n: u64, what: &str, tokens: usize, bytes: usize) -> Result<usize, MeshError> {
        let per_record = if self.is_binary() { bytes } else { 2 * tokens };
        let fits = usize::try_from(n)
            .ok()
            .filter(|&n| n.checked_mul(per_record.max(1)).is_some_and(|need| need <= self.remaining()));
        fits.ok_or_else(|| {
            msh_error(
                self.field_loc(),
                format!(
                    "{what} is {n}, but only {} bytes remain in the file (truncated file or wrong count)",
                    self.remaining()
                ),
            )
        })
    }

    /// Reads a size field: an unsigned text token, or a binary `size_t` (8 bytes).
    pub(crate) fn size(&mut self, what: &str) -> Result<u64, MeshError> {
        match self.encoding {
            Encoding::Ascii => self.text_u64(what),
            Encoding::Binary { .. } => self.bin_u64(what),
        }
    }

    /// Reads an int field: a signed text token, or a binary `int` (4 bytes).
    pub(crate) fn int(&mut self, what: &str) -> Result<i32, MeshError> {
        match self.encoding {
            Encoding::Ascii => self.text_i32(what),
            Encoding::Binary { .. } => self.bin_i32(what),
        }
    }

    /// Reads a double field: a text number, or a binary `double` (8 bytes).
    pub(crate) fn double(&mut self, what: &str) -> Result<f64, MeshError> {
        match self.encoding {
            Encoding::Ascii => self.text_f64(what),
            Encoding::Binary { .. } => self.bin_f64(what),
        }
    }

    /// Ends a record: in ASCII the rest of the line must be blank; in binary there is nothing to do.
    pub(crate) fn end_record(&mut self) -> Result<(), MeshError> {
        match self.encoding {
            Encoding::Ascii => self.text_end_line(),
            Encoding::Binary { .. } => Ok(()),
        }
    }
}

/// A [`MeshError::Msh`] at `at`.
pub(crate) fn msh_error(at: Location, reason: impl Into<String>) -> MeshError {
    MeshError::Msh { at, reason: reason.into() }
}

/// A [`MeshError::Unsupported`] at `at`.
pub(crate) fn unsupported(at: Location, what: impl Into<String>) -> MeshError {
    MeshError::Unsupported { at, what: what.into() }
}

/// A token for an error message: lossy UTF-8, at most 40 characters.
pub(crate) fn show(token: &[u8]) -> String {
    let text = String::from_utf8_lossy(token);
    let mut shown: String = text.chars().take(40).collect();
    if text.chars().count() > 40 {
        shown.push_str("...");
    }
    shown
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;

    #[test]
    fn ascii_locations_are_lines() {
        let mut c = Cursor::new(b"1\n2 3\n");
        assert_eq!(c.loc(), Location::Line(1));
        c.size("a").unwrap();
        c.end_record().unwrap();
        assert_eq!(c.loc(), Location::Line(2));
        assert_eq!(c.int("b").unwrap(), 2);
        assert_eq!(c.field_loc(), Location::Line(2));
    }

    #[test]
    fn binary_locations_are_offsets() {
        let mut c = Cursor::new(&[1, 0, 0, 0, 2, 0, 0, 0]);
        c.encoding = Encoding::Binary { big_endian: false };
        assert_eq!(c.int("a").unwrap(), 1);
        assert_eq!(c.loc(), Location::Byte(4));
        assert_eq!(c.field_loc(), Location::Byte(0));
        c.end_record().unwrap();
        assert_eq!(c.loc(), Location::Byte(4));
    }

    #[test]
    fn count_rejects_what_the_file_cannot_hold() {
        let mut c = Cursor::new(b"1000\n1\n2\n");
        let err = c.count("number of nodes", 4, 32).unwrap_err();
        assert!(matches!(err, MeshError::Msh { at: Location::Line(1), .. }), "{err}");

        let mut c = Cursor::new(b"2 1 2\n");
        assert_eq!(c.count("number of nodes", 1, 8).unwrap(), 2);
    }

    #[test]
    fn count_overflow_is_an_error() {
        let mut c = Cursor::new(&[0xff; 8]);
        c.encoding = Encoding::Binary { big_endian: false };
        let err = c.count("number of nodes", 1, 8).unwrap_err();
        assert!(matches!(err, MeshError::Msh { at: Location::Byte(0), .. }), "{err}");
    }

    #[test]
    fn show_truncates_long_tokens() {
        assert_eq!(show(b"abc"), "abc");
        assert_eq!(show(&[b'x'; 50]).len(), 43);
        assert_eq!(show(&[0xff]), "\u{fffd}");
    }
}

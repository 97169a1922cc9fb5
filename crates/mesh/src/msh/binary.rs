//! The binary word reader: `int` (4 bytes), `size_t` (8 bytes) and `double` (8 bytes) in the
//! byte order announced by the file.
//!
//! ```text
//!   $MeshFormat\n4.1 1 8\n 01 00 00 00 \n$EndMeshFormat      little-endian writer
//!                          00 00 00 01                       big-endian writer
//! ```
//!
//! Gmsh writes the `int` 1 after the format line; reading it back as 1 in little-endian order
//! means the file is little-endian, as `0x01000000` means big-endian. Every read is bounds
//! checked: running past the end of the file is an error at the offset of the word.

use super::cursor::{Cursor, Encoding};
use crate::error::MeshError;

impl<'a> Cursor<'a> {
    /// The next `N` bytes, as written (not yet swapped).
    fn take<const N: usize>(&mut self, what: &str) -> Result<[u8; N], MeshError> {
        self.field_start = self.pos;
        let bytes = self
            .pos
            .checked_add(N)
            .and_then(|end| self.buf.get(self.pos..end))
            .and_then(|s| <[u8; N]>::try_from(s).ok());
        match bytes {
            Some(bytes) => {
                self.pos += N;
                Ok(bytes)
            }
            None => Err(self.error(format!("file ends inside {what} ({N} bytes needed, {} left)", self.remaining()))),
        }
    }

    fn big_endian(&self) -> bool {
        matches!(self.encoding, Encoding::Binary { big_endian: true })
    }

    /// A binary `size_t` (the file's data-size is 8).
    pub(crate) fn bin_u64(&mut self, what: &str) -> Result<u64, MeshError> {
        let b = self.take::<8>(what)?;
        Ok(if self.big_endian() { u64::from_be_bytes(b) } else { u64::from_le_bytes(b) })
    }

    /// A binary `int`.
    pub(crate) fn bin_i32(&mut self, what: &str) -> Result<i32, MeshError> {
        let b = self.take::<4>(what)?;
        Ok(if self.big_endian() { i32::from_be_bytes(b) } else { i32::from_le_bytes(b) })
    }

    /// A binary `double`.
    pub(crate) fn bin_f64(&mut self, what: &str) -> Result<f64, MeshError> {
        let b = self.take::<8>(what)?;
        Ok(if self.big_endian() { f64::from_be_bytes(b) } else { f64::from_le_bytes(b) })
    }

    /// Reads the endianness marker (the `int` 1) and switches the cursor to binary data.
    ///
    /// # Errors
    /// [`MeshError::Msh`] if the four bytes are neither 1 in little- nor in big-endian order.
    pub(crate) fn start_binary(&mut self) -> Result<(), MeshError> {
        self.encoding = Encoding::Binary { big_endian: false };
        let b = self.take::<4>("the endianness marker (the int 1)")?;
        if i32::from_le_bytes(b) == 1 {
            Ok(())
        } else if i32::from_be_bytes(b) == 1 {
            self.encoding = Encoding::Binary { big_endian: true };
            Ok(())
        } else {
            self.pos = self.field_start;
            Err(self.error(format!(
                "the endianness marker should be the int 1, found bytes {:02x} {:02x} {:02x} {:02x}",
                b[0], b[1], b[2], b[3]
            )))
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::error::Location;

    #[test]
    fn both_byte_orders() {
        let mut bytes = vec![1, 0, 0, 0];
        bytes.extend_from_slice(&7u64.to_le_bytes());
        bytes.extend_from_slice(&(-3i32).to_le_bytes());
        bytes.extend_from_slice(&0.25f64.to_le_bytes());
        let mut c = Cursor::new(&bytes);
        c.start_binary().unwrap();
        assert_eq!(c.bin_u64("a").unwrap(), 7);
        assert_eq!(c.bin_i32("b").unwrap(), -3);
        assert_eq!(c.bin_f64("c").unwrap(), 0.25);

        let mut bytes = vec![0, 0, 0, 1];
        bytes.extend_from_slice(&7u64.to_be_bytes());
        bytes.extend_from_slice(&(-3i32).to_be_bytes());
        bytes.extend_from_slice(&0.25f64.to_be_bytes());
        let mut c = Cursor::new(&bytes);
        c.start_binary().unwrap();
        assert_eq!(c.bin_u64("a").unwrap(), 7);
        assert_eq!(c.bin_i32("b").unwrap(), -3);
        assert_eq!(c.bin_f64("c").unwrap(), 0.25);
    }

    #[test]
    fn bad_marker() {
        let mut c = Cursor::new(&[0, 0, 0, 0]);
        let e = c.start_binary().unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Byte(0), .. }), "{e}");
    }

    #[test]
    fn truncated_word_reports_its_offset() {
        let mut c = Cursor::new(&[1, 0, 0, 0, 9, 9, 9]);
        c.start_binary().unwrap();
        let e = c.bin_u64("a node tag").unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Byte(4), .. }), "{e}");
        assert!(e.to_string().contains("a node tag"), "{e}");
    }
}

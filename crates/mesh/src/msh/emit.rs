//! The writer's field encoder: the mirror image of the cursor's field readers.
//!
//! ```text
//!   ASCII:   size/int/double -> decimal text separated by single spaces; end_record -> "\n"
//!   binary:  size -> 8 bytes, int -> 4 bytes, double -> 8 bytes, little-endian unless asked
//!            otherwise; end_record -> nothing
//! ```
//!
//! Reals are written in the shortest form that reads back to the same `f64` (Rust's `Display`
//! and `LowerExp` without precision), in positional notation for magnitudes in
//! `[1e-5, 1e16)` and zero, in exponent notation otherwise, so an ASCII round trip is exact.

use std::io::Write as _;

/// An MSH file being written in memory.
#[derive(Debug)]
pub(crate) struct Emitter {
    /// The bytes written so far.
    pub(crate) out: Vec<u8>,
    binary: bool,
    big_endian: bool,
    at_record_start: bool,
}

impl Emitter {
    /// An empty file; `binary` selects the data encoding, `big_endian` its byte order.
    pub(crate) fn new(binary: bool, big_endian: bool) -> Self {
        Emitter { out: Vec::new(), binary, big_endian, at_record_start: true }
    }

    /// Whether the data is binary.
    pub(crate) fn is_binary(&self) -> bool {
        self.binary
    }

    /// Writes text as is (section markers, `$PhysicalNames`, MSH 2.2 counts).
    pub(crate) fn text(&mut self, s: &str) {
        self.out.extend_from_slice(s.as_bytes());
    }

    /// The endianness marker of a binary header: the `int` 1.
    pub(crate) fn endianness_marker(&mut self) {
        self.raw_i32(1);
    }

    /// Ends the data of a section: binary data is followed by a newline before the end marker.
    pub(crate) fn end_data(&mut self) {
        if self.binary {
            self.out.push(b'\n');
        }
    }

    fn separate(&mut self) {
        if !self.at_record_start {
            self.out.push(b' ');
        }
        self.at_record_start = false;
    }

    fn raw_i32(&mut self, v: i32) {
        let bytes = if self.big_endian { v.to_be_bytes() } else { v.to_le_bytes() };
        self.out.extend_from_slice(&bytes);
    }

    /// A size field (`size_t` in binary).
    pub(crate) fn size(&mut self, v: u64) {
        if self.binary {
            let bytes = if self.big_endian { v.to_be_bytes() } else { v.to_le_bytes() };
            self.out.extend_from_slice(&bytes);
        } else {
            self.separate();
            push_u64(&mut self.out, v);
        }
    }

    /// An int field (`int` in binary).
    pub(crate) fn int(&mut self, v: i32) {
        if self.binary {
            self.raw_i32(v);
        } else {
            self.separate();
            if v < 0 {
                self.out.push(b'-');
            }
            push_u64(&mut self.out, u64::from(v.unsigned_abs()));
        }
    }

    /// A double field.
    pub(crate) fn double(&mut self, v: f64) {
        if self.binary {
            let bytes = if self.big_endian { v.to_be_bytes() } else { v.to_le_bytes() };
            self.out.extend_from_slice(&bytes);
        } else {
            self.separate();
            let magnitude = v.abs();
            // Writing into a Vec cannot fail.
            let _ = if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) {
                write!(self.out, "{v}")
            } else {
                write!(self.out, "{v:e}")
            };
        }
    }

    /// Ends a record (a line in ASCII).
    pub(crate) fn end_record(&mut self) {
        if !self.binary {
            self.out.push(b'\n');
        }
        self.at_record_start = true;
    }
}

/// Appends the decimal digits of `v`.
fn push_u64(out: &mut Vec<u8>, mut v: u64) {
    let mut digits = [0u8; 20];
    let mut start = digits.len();
    loop {
        start -= 1;
        if let Some(d) = digits.get_mut(start) {
            *d = b'0' + (v % 10) as u8;
        }
        v /= 10;
        if v == 0 || start == 0 {
            break;
        }
    }
    out.extend_from_slice(digits.get(start..).unwrap_or_default());
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;

    #[test]
    fn ascii_fields() {
        let mut e = Emitter::new(false, false);
        e.size(0);
        e.size(u64::MAX);
        e.int(i32::MIN);
        e.int(7);
        e.end_record();
        e.double(0.1);
        e.double(-0.0);
        e.double(1e-7);
        e.double(2.5e300);
        e.double(12345.5);
        e.end_record();
        assert_eq!(
            String::from_utf8(e.out).unwrap(),
            "0 18446744073709551615 -2147483648 7\n0.1 -0 1e-7 2.5e300 12345.5\n"
        );
    }

    #[test]
    fn reals_round_trip() {
        for v in [0.1, 1.0 / 3.0, 1e-300, f64::MAX, f64::MIN_POSITIVE, 5e-324, -7.25e15, 0.30000000000000004] {
            let mut e = Emitter::new(false, false);
            e.double(v);
            let text = String::from_utf8(e.out).unwrap();
            assert_eq!(text.parse::<f64>().unwrap(), v, "{text}");
        }
    }

    #[test]
    fn binary_fields() {
        let mut e = Emitter::new(true, true);
        e.endianness_marker();
        e.size(2);
        e.int(-1);
        e.double(1.0);
        e.end_record();
        e.end_data();
        let mut expected = vec![0, 0, 0, 1];
        expected.extend_from_slice(&2u64.to_be_bytes());
        expected.extend_from_slice(&(-1i32).to_be_bytes());
        expected.extend_from_slice(&1f64.to_be_bytes());
        expected.push(b'\n');
        assert_eq!(e.out, expected);
        assert!(e.is_binary());
    }
}

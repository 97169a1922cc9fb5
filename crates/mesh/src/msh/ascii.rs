//! The text tokeniser: whitespace-separated tokens on lines, numbers parsed from byte slices.
//!
//! ```text
//!   "12 0.5 -1e-3\n"     tokens are maximal runs of bytes other than ' ', '\t', '\r', '\n'
//!    ^^ ^^^ ^^^^^        a record is one line; text_end_line() checks that nothing follows
//! ```
//!
//! Tokens are borrowed slices of the file (no allocation per token). Integers are parsed by
//! hand with overflow checks; reals with `str::parse::<f64>` on the token. Lines are counted as
//! newlines are consumed, so every error carries the 1-based line of the offending token.

use super::cursor::{Cursor, Encoding, msh_error, show};
use crate::error::MeshError;

/// Whether `b` separates tokens.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

impl<'a> Cursor<'a> {
    /// Skips spaces, tabs and carriage returns (not newlines).
    fn skip_inline_space(&mut self) {
        while let Some(&b) = self.buf.get(self.pos) {
            if b == b' ' || b == b'\t' || b == b'\r' {
                self.pos += 1;
            } else {
                break;
            }
        }
    }

    /// Skips all whitespace, counting lines.
    pub(crate) fn skip_space(&mut self) {
        while let Some(&b) = self.buf.get(self.pos) {
            if !is_space(b) {
                break;
            }
            if b == b'\n' {
                self.line += 1;
            }
            self.pos += 1;
        }
    }

    /// The next token on the current line.
    ///
    /// # Errors
    /// [`MeshError::Msh`] if the line (or the file) ends first.
    pub(crate) fn text_field(&mut self, what: &str) -> Result<&'a [u8], MeshError> {
        self.skip_inline_space();
        let start = self.pos;
        self.field_start = start;
        while let Some(&b) = self.buf.get(self.pos) {
            if is_space(b) {
                break;
            }
            self.pos += 1;
        }
        if self.pos == start {
            let found = if self.pos >= self.buf.len() { "end of file" } else { "end of line" };
            return Err(self.error(format!("expected {what}, found {found}")));
        }
        Ok(self.buf.get(start..self.pos).unwrap_or_default())
    }

    /// The next token after any whitespace, newlines included; `None` at the end of the file.
    pub(crate) fn text_token(&mut self) -> Option<&'a [u8]> {
        self.skip_space();
        if self.pos >= self.buf.len() {
            return None;
        }
        self.text_field("token").ok()
    }

    /// The rest of the current line, without the newline (which stays unread).
    pub(crate) fn rest_of_line(&mut self) -> &'a [u8] {
        let start = self.pos;
        while let Some(&b) = self.buf.get(self.pos) {
            if b == b'\n' {
                break;
            }
            self.pos += 1;
        }
        self.buf.get(start..self.pos).unwrap_or_default()
    }

    /// An error for a token that is not the number expected.
    fn bad_token(&self, what: &str, token: &[u8]) -> MeshError {
        let hint = if token.first() == Some(&b'$') {
            " (the section ends before all the entries its counts declare)"
        } else {
            ""
        };
        self.error(format!("expected {what}, found '{}'{hint}", show(token)))
    }

    /// The next token on the line as an unsigned integer.
    pub(crate) fn text_u64(&mut self, what: &str) -> Result<u64, MeshError> {
        let token = self.text_field(what)?;
        parse_u64(token).ok_or_else(|| self.bad_token(what, token))
    }

    /// The next token on the line as an `i32`.
    pub(crate) fn text_i32(&mut self, what: &str) -> Result<i32, MeshError> {
        let token = self.text_field(what)?;
        parse_i64(token).and_then(|v| i32::try_from(v).ok()).ok_or_else(|| self.bad_token(what, token))
    }

    /// The next token on the line as an `f64` (finite or not; callers decide).
    pub(crate) fn text_f64(&mut self, what: &str) -> Result<f64, MeshError> {
        let token = self.text_field(what)?;
        std::str::from_utf8(token).ok().and_then(|s| s.parse::<f64>().ok()).ok_or_else(|| self.bad_token(what, token))
    }

    /// Checks that only blanks remain on the line and moves to the next one. In an ASCII file,
    /// blank lines that follow are skipped too; in a binary file exactly one newline is
    /// consumed, because binary data may start right after it.
    ///
    /// # Errors
    /// [`MeshError::Msh`] if a token follows on the same line.
    pub(crate) fn text_end_line(&mut self) -> Result<(), MeshError> {
        self.skip_inline_space();
        match self.buf.get(self.pos) {
            None => return Ok(()),
            Some(b'\n') => {
                self.pos += 1;
                self.line += 1;
            }
            Some(_) => {
                let token = self.text_field("end of line").unwrap_or_default();
                return Err(msh_error(
                    self.field_loc(),
                    format!("unexpected '{}' where the line should end", show(token)),
                ));
            }
        }
        if self.encoding == Encoding::Ascii {
            self.skip_blank_lines();
        }
        Ok(())
    }

    /// Skips lines that hold only blanks; leaves the cursor at the start of the next
    /// non-blank line (or after its leading blanks).
    fn skip_blank_lines(&mut self) {
        loop {
            self.skip_inline_space();
            if self.buf.get(self.pos) == Some(&b'\n') {
                self.pos += 1;
                self.line += 1;
            } else {
                return;
            }
        }
    }
}

/// Parses an unsigned decimal integer (optional `+`), `None` on anything else or overflow.
pub(crate) fn parse_u64(token: &[u8]) -> Option<u64> {
    let digits = token.strip_prefix(b"+").unwrap_or(token);
    if digits.is_empty() {
        return None;
    }
    let mut value: u64 = 0;
    for &b in digits {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            return None;
        }
        value = value.checked_mul(10)?.checked_add(u64::from(d))?;
    }
    Some(value)
}

/// Parses a signed decimal integer, `None` on anything else or overflow.
pub(crate) fn parse_i64(token: &[u8]) -> Option<i64> {
    match token.strip_prefix(b"-") {
        Some(digits) if !digits.starts_with(b"+") => {
            let magnitude = parse_u64(digits)?;
            0i64.checked_sub_unsigned(magnitude)
        }
        Some(_) => None,
        None => i64::try_from(parse_u64(token)?).ok(),
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;
    use crate::error::Location;

    fn at(e: &MeshError) -> Location {
        match e {
            MeshError::Msh { at, .. } => *at,
            other => panic!("not an Msh error: {other}"),
        }
    }

    #[test]
    fn integers() {
        assert_eq!(parse_u64(b"0"), Some(0));
        assert_eq!(parse_u64(b"+17"), Some(17));
        assert_eq!(parse_u64(b"18446744073709551615"), Some(u64::MAX));
        assert_eq!(parse_u64(b"18446744073709551616"), None);
        assert_eq!(parse_u64(b""), None);
        assert_eq!(parse_u64(b"+"), None);
        assert_eq!(parse_u64(b"1x"), None);
        assert_eq!(parse_u64(b"-1"), None);
        assert_eq!(parse_i64(b"-1"), Some(-1));
        assert_eq!(parse_i64(b"-9223372036854775808"), Some(i64::MIN));
        assert_eq!(parse_i64(b"-9223372036854775809"), None);
        assert_eq!(parse_i64(b"9223372036854775808"), None);
        assert_eq!(parse_i64(b"-+1"), None);
        assert_eq!(parse_i64(b"-"), None);
    }

    #[test]
    fn fields_on_lines() {
        let mut c = Cursor::new(b"  1 -2\t3.5 \r\n\n  \n4\n");
        assert_eq!(c.text_u64("a").unwrap(), 1);
        assert_eq!(c.text_i32("b").unwrap(), -2);
        assert_eq!(c.text_f64("c").unwrap(), 3.5);
        c.text_end_line().unwrap();
        assert_eq!(c.line, 4);
        assert_eq!(c.text_u64("d").unwrap(), 4);
        c.text_end_line().unwrap();
        c.text_end_line().unwrap();
        assert_eq!(c.text_token(), None);
    }

    #[test]
    fn missing_field_reports_the_line() {
        let mut c = Cursor::new(b"1\n2\n");
        c.text_u64("a").unwrap();
        let e = c.text_u64("b").unwrap_err();
        assert_eq!(at(&e), Location::Line(1));
        assert!(e.to_string().contains("found end of line"), "{e}");
        let mut c = Cursor::new(b"1");
        c.text_u64("a").unwrap();
        let e = c.text_u64("b").unwrap_err();
        assert!(e.to_string().contains("end of file"), "{e}");
    }

    #[test]
    fn extra_token_reports_the_line() {
        let mut c = Cursor::new(b"\n1 2\n");
        c.skip_space();
        c.text_u64("a").unwrap();
        let e = c.text_end_line().unwrap_err();
        assert_eq!(at(&e), Location::Line(2));
        assert!(e.to_string().contains("'2'"), "{e}");
    }

    #[test]
    fn bad_numbers() {
        let mut c = Cursor::new(b"x 1.2.3 3000000000 $EndNodes");
        assert!(c.text_u64("a").is_err());
        assert!(c.text_f64("b").is_err());
        assert!(c.text_i32("c").is_err());
        let e = c.text_u64("d").unwrap_err();
        assert!(e.to_string().contains("section ends"), "{e}");
    }

    #[test]
    fn rest_of_line_stops_at_newline() {
        let mut c = Cursor::new(b"1 \"a b\"\nnext");
        c.text_u64("a").unwrap();
        assert_eq!(c.rest_of_line(), b" \"a b\"");
        c.text_end_line().unwrap();
        assert_eq!(c.text_token(), Some(&b"next"[..]));
    }
}

//! The `$PhysicalNames` section: named physical groups.
//!
//! ```text
//!   $PhysicalNames
//!   3                      number of names
//!   1 11 "bottom"          dimension, physical tag, name in double quotes
//!   1 15 "hole"
//!   2 1 "plate"
//!   $EndPhysicalNames
//! ```
//!
//! The section is text in ASCII and binary files alike. The name is everything between the
//! first and the last double quote of the line (it may contain spaces). A `(dim, tag)` pair or a
//! name may appear only once per dimension.

use super::cursor::{Cursor, msh_error, show};
use crate::error::{Location, MeshError};
use crate::mesh::PhysicalGroup;

/// The physical names of a file, in file order.
#[derive(Debug, Default)]
pub(crate) struct PhysicalNames {
    /// The groups, in `$PhysicalNames` order.
    pub(crate) groups: Vec<PhysicalGroup>,
}

impl PhysicalNames {
    /// Whether a group of dimension `dim` has physical tag `tag`.
    pub(crate) fn contains(&self, dim: usize, tag: i32) -> bool {
        self.groups.iter().any(|g| g.dim == dim && g.tag == tag)
    }
}

/// Reads the body of `$PhysicalNames` (after its header line, up to the end marker).
pub(crate) fn read_physical_names(c: &mut Cursor<'_>) -> Result<PhysicalNames, MeshError> {
    let n = c.text_u64("the number of physical names")?;
    let count_at = c.field_loc();
    let n = usize::try_from(n)
        .ok()
        .filter(|&n| n.saturating_mul(6) <= c.remaining())
        .ok_or_else(|| msh_error(count_at, format!("{n} physical names cannot fit in the rest of the file")))?;
    c.text_end_line()?;
    let mut names = PhysicalNames { groups: Vec::with_capacity(n) };
    for _ in 0..n {
        let dim = c.text_u64("the dimension of a physical name")?;
        let dim = match usize::try_from(dim) {
            Ok(d) if d <= 3 => d,
            _ => return Err(c.error(format!("physical name dimension {dim} is not 0, 1, 2 or 3"))),
        };
        let tag = c.text_i32("a physical tag")?;
        let at = c.field_loc();
        let name = quoted_name(c, at)?;
        if names.contains(dim, tag) {
            return Err(msh_error(at, format!("physical tag {tag} of dimension {dim} is named twice")));
        }
        if names.groups.iter().any(|g| g.dim == dim && g.name == name) {
            return Err(msh_error(at, format!("physical name \"{name}\" is used twice for dimension {dim}")));
        }
        names.groups.push(PhysicalGroup { name, dim, tag });
        c.text_end_line()?;
    }
    Ok(names)
}

/// The double-quoted name that ends the line.
fn quoted_name(c: &mut Cursor<'_>, at: Location) -> Result<String, MeshError> {
    let rest = c.rest_of_line();
    let trimmed = rest.trim_ascii();
    let inner = trimmed.strip_prefix(b"\"").and_then(|r| r.strip_suffix(b"\"")).ok_or_else(|| {
        msh_error(at, format!("expected a physical name in double quotes, found '{}'", show(trimmed)))
    })?;
    String::from_utf8(inner.to_vec()).map_err(|_| msh_error(at, "the physical name is not valid UTF-8"))
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;

    fn read(text: &[u8]) -> Result<PhysicalNames, MeshError> {
        read_physical_names(&mut Cursor::new(text))
    }

    fn line_of(e: MeshError) -> usize {
        match e {
            MeshError::Msh { at: Location::Line(n), .. } => n,
            other => panic!("unexpected error {other}"),
        }
    }

    #[test]
    fn names_with_spaces_and_quotes() {
        let names = read(b"2\n1 11 \"left edge\"\r\n2 1 \"say \"hi\"\"\n").unwrap();
        assert_eq!(names.groups.len(), 2);
        assert_eq!(names.groups[0].name, "left edge");
        assert_eq!(names.groups[0].dim, 1);
        assert_eq!(names.groups[0].tag, 11);
        assert_eq!(names.groups[1].name, "say \"hi\"");
        assert!(names.contains(2, 1));
        assert!(!names.contains(1, 1));
    }

    #[test]
    fn errors_carry_lines() {
        assert_eq!(line_of(read(b"1\n1 2 name\n").unwrap_err()), 2);
        assert_eq!(line_of(read(b"1\n1 2 \"a\n").unwrap_err()), 2);
        assert_eq!(line_of(read(b"1\n4 2 \"a\"\n").unwrap_err()), 2);
        assert_eq!(line_of(read(b"2\n1 2 \"a\"\n1 2 \"b\"\n").unwrap_err()), 3);
        assert_eq!(line_of(read(b"2\n1 2 \"a\"\n1 3 \"a\"\n").unwrap_err()), 3);
        assert_eq!(line_of(read(b"99\n1 2 \"a\"\n").unwrap_err()), 1);
        assert_eq!(line_of(read(b"1\n1 x \"a\"\n").unwrap_err()), 2);
        assert_eq!(line_of(read(b"1\n1 2 \"\xff\"\n").unwrap_err()), 2);
    }

    #[test]
    fn same_name_in_two_dimensions_is_allowed() {
        let names = read(b"2\n1 2 \"a\"\n0 2 \"a\"\n").unwrap();
        assert_eq!(names.groups.len(), 2);
    }
}

//! Section markers and the policy for sections contact2d does not read.
//!
//! ```text
//!   $Name          a section opens with its name alone on a line
//!   ...            its data (text or binary)
//!   $EndName       and closes with the matching end marker alone on a line
//! ```
//!
//! | section                                   | treatment                                  |
//! |-------------------------------------------|--------------------------------------------|
//! | `$MeshFormat` `$PhysicalNames` `$Entities` `$Nodes` `$Elements` | read                 |
//! | `$PartitionedEntities` `$GhostElements` `$Parametrizations` | [`MeshError::Unsupported`] |
//! | anything else (`$Periodic`, `$NodeData`, `$ElementData`, `$ElementNodeData`, `$InterpolationScheme`, `$Comments`, user sections) | skipped, name reported |
//!
//! The MSH specification says a reader ignores sections it does not recognise, and the skipped
//! ones carry data *about* the mesh (periodic node pairs, post-processing fields, comments)
//! which do not change the nodes, cells or groups read here. Partitioned meshes are refused:
//! their element blocks live on partition entities whose physical tags are in
//! `$PartitionedEntities`, so reading them as a plain mesh would silently lose the groups.
//! Parametrizations are refused because contact2d has no use for them and they signal a
//! mesh exported for re-meshing, not for analysis.
//!
//! A skipped section ends at the first line that starts with `$EndName` (in binary data too).

use super::cursor::{Cursor, msh_error, show};
use crate::error::{Location, MeshError};

/// What to do with a section.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Section {
    /// `$MeshFormat`.
    MeshFormat,
    /// `$PhysicalNames`.
    PhysicalNames,
    /// `$Entities`.
    Entities,
    /// `$Nodes`.
    Nodes,
    /// `$Elements`.
    Elements,
    /// Skipped (see the module doc).
    Skipped,
    /// Refused with [`MeshError::Unsupported`] (see the module doc).
    Unsupported,
}

/// The treatment of the section called `name` (without the `$`).
pub(crate) fn classify(name: &str) -> Section {
    match name {
        "MeshFormat" => Section::MeshFormat,
        "PhysicalNames" => Section::PhysicalNames,
        "Entities" => Section::Entities,
        "Nodes" => Section::Nodes,
        "Elements" => Section::Elements,
        "PartitionedEntities" | "GhostElements" | "Parametrizations" => Section::Unsupported,
        _ => Section::Skipped,
    }
}

impl<'a> Cursor<'a> {
    /// The name (without `$`) and location of the next section; `None` at the end of the file.
    ///
    /// # Errors
    /// [`MeshError::Msh`] if something other than a section marker comes next.
    pub(crate) fn next_section(&mut self) -> Result<Option<(&'a str, Location)>, MeshError> {
        self.skip_space();
        let at = self.loc();
        let Some(token) = self.text_token() else {
            return Ok(None);
        };
        let name = token
            .strip_prefix(b"$")
            .filter(|n| !n.is_empty() && !n.starts_with(b"End"))
            .and_then(|n| std::str::from_utf8(n).ok())
            .ok_or_else(|| {
                msh_error(
                    at,
                    format!(
                        "expected a section such as $Nodes, found '{}' (more entries than a count declares?)",
                        show(token)
                    ),
                )
            })?;
        self.text_end_line()?;
        Ok(Some((name, at)))
    }

    /// Reads the `$End{name}` marker that must come next.
    ///
    /// # Errors
    /// [`MeshError::Msh`] if the file ends or anything else comes first.
    pub(crate) fn expect_end(&mut self, name: &str) -> Result<(), MeshError> {
        self.skip_space();
        let at = self.loc();
        let marker = format!("$End{name}");
        match self.text_token() {
            Some(token) if token == marker.as_bytes() => self.text_end_line(),
            Some(token) => Err(msh_error(
                at,
                format!(
                    "expected {marker}, found '{}' (more entries than the counts declare, or a missing end marker)",
                    show(token)
                ),
            )),
            None => Err(msh_error(at, format!("the file ends before {marker}"))),
        }
    }

    /// Skips the rest of section `name` (opened at `at`), end marker included.
    ///
    /// # Errors
    /// [`MeshError::Msh`] at `at` if no end marker follows.
    pub(crate) fn skip_section(&mut self, name: &str, at: Location) -> Result<(), MeshError> {
        let marker = format!("$End{name}");
        let rest = self.buf.get(self.pos..).unwrap_or_default();
        let found = rest.iter().enumerate().find_map(|(i, &b)| {
            let at_line_start = i == 0 || rest.get(i - 1) == Some(&b'\n');
            let here = rest.get(i..)?;
            let ends = here.get(marker.len()).is_none_or(|&next| next.is_ascii_whitespace());
            (b == b'$' && at_line_start && here.starts_with(marker.as_bytes()) && ends).then_some(i)
        });
        let Some(offset) = found else {
            return Err(msh_error(at, format!("section ${name} has no {marker}")));
        };
        let skipped = rest.get(..offset).unwrap_or_default();
        self.line += skipped.iter().filter(|&&b| b == b'\n').count();
        self.pos += offset;
        self.expect_end(name)
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
mod tests {
    use super::*;

    #[test]
    fn policy() {
        assert_eq!(classify("Nodes"), Section::Nodes);
        assert_eq!(classify("Periodic"), Section::Skipped);
        assert_eq!(classify("NodeData"), Section::Skipped);
        assert_eq!(classify("MyOwnSection"), Section::Skipped);
        assert_eq!(classify("PartitionedEntities"), Section::Unsupported);
        assert_eq!(classify("Parametrizations"), Section::Unsupported);
    }

    #[test]
    fn markers_and_skipping() {
        let text = b"\n$Comments\nhello $EndComments\n$EndCommentsX\n$EndComments\n$Nodes\n";
        let mut c = Cursor::new(text);
        let (name, at) = c.next_section().unwrap().unwrap();
        assert_eq!((name, at), ("Comments", Location::Line(2)));
        c.skip_section(name, at).unwrap();
        assert_eq!(c.line, 6);
        let (name, _) = c.next_section().unwrap().unwrap();
        assert_eq!(name, "Nodes");
        assert_eq!(c.next_section().unwrap(), None);
    }

    #[test]
    fn empty_skipped_section() {
        let mut c = Cursor::new(b"$Periodic\n$EndPeriodic");
        let (name, at) = c.next_section().unwrap().unwrap();
        c.skip_section(name, at).unwrap();
        assert_eq!(c.next_section().unwrap(), None);
    }

    #[test]
    fn marker_errors() {
        let mut c = Cursor::new(b"$Periodic\n1 2\n");
        let (name, at) = c.next_section().unwrap().unwrap();
        let e = c.skip_section(name, at).unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(1), .. }), "{e}");

        let mut c = Cursor::new(b"\n12\n");
        let e = c.next_section().unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(2), .. }), "{e}");

        let mut c = Cursor::new(b"$EndNodes\n");
        assert!(c.next_section().is_err());

        let mut c = Cursor::new(b"1\n\n");
        let e = c.expect_end("Nodes").unwrap_err();
        assert!(matches!(e, MeshError::Msh { at: Location::Line(1), .. }), "{e}");
        let mut c = Cursor::new(b"\n\n");
        let e = c.expect_end("Nodes").unwrap_err();
        assert!(e.to_string().contains("ends before $EndNodes"), "{e}");
        assert!(matches!(e, MeshError::Msh { at: Location::Line(3), .. }), "{e}");
    }
}

//! Writing generated tables into the Markdown docs between named markers, so the numbers in
//! `docs/` come from the code paths of the tests and are never typed by hand.
//!
//! ```text
//! <!-- BEGIN name -->
//! ...generated...
//! <!-- END name -->
//! ```

use std::path::{Path, PathBuf};

/// Writes `body` as section `name` of `docs/<doc>` in this repository (title `title` if the
/// file is new), unless the program was started with `--print` (a dry run). Returns the path
/// written.
///
/// # Errors
/// I/O errors reading or writing the file.
pub fn publish_section(doc: &str, title: &str, name: &str, body: &str) -> std::io::Result<Option<PathBuf>> {
    if std::env::args().any(|a| a == "--print") {
        return Ok(None);
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs").join(doc);
    write_section(&path, title, name, body)?;
    Ok(Some(path))
}

/// Replaces the section `name` of the Markdown file at `path` by `body` (appending the section
/// if the markers are missing; creating the file with `title` if it does not exist).
///
/// # Errors
/// I/O errors reading or writing the file.
pub fn write_section(path: &Path, title: &str, name: &str, body: &str) -> std::io::Result<()> {
    let (begin, end) = (format!("<!-- BEGIN {name} -->"), format!("<!-- END {name} -->"));
    let old = std::fs::read_to_string(path).unwrap_or_else(|_| format!("# {title}\n"));
    let block = format!("{begin}\n{}\n{end}", body.trim_end());
    let new = match (old.find(&begin), old.find(&end)) {
        (Some(b), Some(e)) if e > b => format!("{}{block}{}", &old[..b], &old[e + end.len()..]),
        _ => format!("{}\n\n{block}\n", old.trim_end()),
    };
    std::fs::write(path, new)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn replaces_only_its_own_section() {
        let path = std::env::temp_dir().join(format!("contact2d-docsec-{}.md", std::process::id()));
        let _ = std::fs::remove_file(&path);
        write_section(&path, "T", "a", "one").unwrap();
        write_section(&path, "T", "b", "two").unwrap();
        write_section(&path, "T", "a", "three").unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.starts_with("# T\n"));
        assert!(text.contains("three") && text.contains("two") && !text.contains("one"));
        assert!(text.find("BEGIN a").unwrap() < text.find("BEGIN b").unwrap());
    }
}

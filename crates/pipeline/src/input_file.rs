//! Input files checked before they are read: a regular file (not a directory, FIFO, device or
//! socket, which would block or never end) no larger than a stated limit.
//!
//! ```text
//! scene file   ≤ MAX_SCENE_BYTES = 1 MiB    (the bundled scenes are under 2 kB)
//! mesh file    ≤ MAX_MESH_BYTES  = 1 GiB    (the finest bundled mesh, N = 128, is 2.9 MB; the
//!                                             reader holds the text and the mesh, about 3× the size)
//! ```

use std::io::Read as _;
use std::path::{Path, PathBuf};

/// The largest scene file read, in bytes.
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// The largest mesh file read, in bytes.
pub const MAX_MESH_BYTES: u64 = 1 << 30;

/// Why an input file is refused before reading.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum InputFileError {
    /// The path names no regular file.
    #[error("{path}: not a regular file ({kind}); give the path of a file")]
    NotRegular {
        /// The path.
        path: PathBuf,
        /// What it is instead.
        kind: &'static str,
    },
    /// The file exceeds the limit.
    #[error("{path}: {size} bytes exceed the limit of {limit} bytes for this kind of file")]
    TooLarge {
        /// The path.
        path: PathBuf,
        /// Its size (at least this much).
        size: u64,
        /// The limit.
        limit: u64,
    },
    /// The file's metadata or content cannot be read.
    #[error("{path}: {source}")]
    Io {
        /// The path.
        path: PathBuf,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },
}

impl InputFileError {
    /// Why the file is refused, without its path (for messages that name the file already).
    pub fn reason(&self) -> String {
        match self {
            InputFileError::NotRegular { kind, .. } => format!("not a regular file ({kind})"),
            InputFileError::TooLarge { size, limit, .. } => format!("{size} bytes exceed the limit of {limit} bytes"),
            InputFileError::Io { source, .. } => source.to_string(),
        }
    }
}

/// Checks that `path` is a regular file (symbolic links followed) of at most `limit` bytes;
/// returns its size. Nothing is read.
///
/// # Errors
/// [`InputFileError`] naming the path.
pub fn check_input_file(path: &Path, limit: u64) -> Result<u64, InputFileError> {
    let meta = std::fs::metadata(path).map_err(|source| InputFileError::Io { path: path.into(), source })?;
    if !meta.is_file() {
        return Err(InputFileError::NotRegular { path: path.into(), kind: kind_of(&meta) });
    }
    if meta.len() > limit {
        return Err(InputFileError::TooLarge { path: path.into(), size: meta.len(), limit });
    }
    Ok(meta.len())
}

/// Reads a file checked by [`check_input_file`], never more than `limit` bytes (a file that
/// grows meanwhile is refused too).
///
/// # Errors
/// [`InputFileError`] naming the path.
pub fn read_input_file(path: &Path, limit: u64) -> Result<Vec<u8>, InputFileError> {
    let size = check_input_file(path, limit)?;
    let io = |source| InputFileError::Io { path: path.into(), source };
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::with_capacity(usize::try_from(size).unwrap_or(0));
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(InputFileError::TooLarge { path: path.into(), size: bytes.len() as u64, limit });
    }
    Ok(bytes)
}

fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn devices_directories_and_large_files_are_refused() {
        assert!(matches!(check_input_file(Path::new("/dev/zero"), 10), Err(InputFileError::NotRegular { .. })));
        assert!(matches!(check_input_file(Path::new("."), 10), Err(InputFileError::NotRegular { .. })));
        assert!(matches!(check_input_file(Path::new("/no/such/file"), 10), Err(InputFileError::Io { .. })));
        let path = std::env::temp_dir().join(format!("contact2d_input_{}", std::process::id()));
        std::fs::write(&path, [0u8; 11]).unwrap();
        assert!(matches!(read_input_file(&path, 10), Err(InputFileError::TooLarge { size: 11, .. })));
        assert_eq!(read_input_file(&path, 11).unwrap().len(), 11);
        std::fs::remove_file(&path).unwrap();
    }
}

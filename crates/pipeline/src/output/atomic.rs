//! Output folders that are whole or absent: the one way every writer of the project puts files
//! into a folder.
//!
//! ```text
//! OutputDir::prepare(dir, manifest)   before any work: create dir, check it is a writable
//!                                     directory, take the lock file (create_new; stale lock of a
//!                                     dead process replaced, and the files it records removed),
//!                                     read the previous manifest
//! out.write_bytes(name, bytes)        each file: written to .contact2d-tmp-<pid>-<name> in the
//! out.write_with(name, |tmp| ...)     same folder, synced, renamed onto <name> (atomic on one
//!                                     file system); the first write removes the old manifest
//! out.stream(name)                    a file that grows while the work goes on (rows flushed as
//!                                     they finish) as <name>.partial, renamed by commit()
//! out.finish(manifest_bytes)          remove stale files (those the previous manifest listed)
//! out.close()                         not written now, then write the manifest (or, for a folder
//!                                     without one, the hidden record .contact2d-files.json) last,
//!                                     then release the lock
//! ```
//! Temporary and `.partial` files are created exclusively (`create_new`, and `O_NOFOLLOW` on
//! Linux): a file or symbolic link already at that name is removed (never followed) first, so a
//! link planted there cannot redirect the output onto another file. Cleanup removes only the
//! files the folder's own record lists (and their temporary and `.partial` leftovers): a file
//! that merely looks like an output (`step_007.vtu` of the user's) stays.
//! A folder therefore holds either a manifest and exactly the files it lists, or no manifest
//! (a run that failed or was killed while writing). Dropping an [`OutputDir`] without
//! [`OutputDir::finish`] removes the files this run wrote (except streamed `.partial` files,
//! which keep what was finished), those the previous manifest listed if writing had started,
//! and the lock. Nothing here knows what the files contain.
//!
//! The lock file records what its run has started writing, so that a run killed outright
//! (SIGKILL, power cut of the process) leaves no files another run would show as its own:
//!
//! ```text
//! .contact2d.lock    <pid>               line 1: the writer
//!                    <name>              one line per file, appended before the file is created
//!                    ...                 (and the previous manifest's files, before it is removed)
//! ```
//! A run that finds the lock of a dead process removes the regular files it records (and that
//! process's temporary files) before it takes the lock: the next run into the folder then never
//! leaves a killed run's `step_007.vtu` beside its own whole summary.
//!
//! A manifest is a JSON object with `"written_by"` (starting with `contact2d`) and `"files"` (the
//! file names of the run, the manifest last); [`manifest_json`] adds both to any JSON object.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use super::OutputError;

/// The lock file every writer creates in its folder while it writes.
pub const LOCK_FILE: &str = ".contact2d.lock";

/// The prefix of temporary files (`.contact2d-tmp-<pid>-<name>`: the extension stays the final
/// one, so writers that choose the format by extension work on the temporary path).
pub const TEMP_PREFIX: &str = ".contact2d-tmp-";

/// The suffix of a streamed file until [`StreamedFile::commit`].
pub const PARTIAL_SUFFIX: &str = ".partial";

/// The hidden record of a folder without a manifest of its own (sweep, stress, bench, verify):
/// the same JSON as a manifest, listing the files the run wrote, so that the next run removes
/// exactly those that it does not write again.
pub const RECORD_FILE: &str = ".contact2d-files.json";

/// An output folder being written: locked against other writers, every file atomic.
#[derive(Debug)]
pub struct OutputDir {
    dir: PathBuf,
    lock: PathBuf,
    manifest: String,
    previous: Vec<String>,
    written: Vec<String>,
    manifest_removed: bool,
    finished: bool,
}

impl OutputDir {
    /// Creates `dir` if missing, checks that it is a writable directory, takes its lock and reads
    /// the file list of a previous manifest named `manifest` (if any): call it before the work
    /// whose results go there, so that a bad folder fails fast.
    ///
    /// # Errors
    /// [`OutputError::NotADirectory`], [`OutputError::DanglingLink`] (a link to nothing, which
    /// cannot be created as a folder), [`OutputError::Io`] (cannot be created or written),
    /// [`OutputError::Locked`] when another live process holds the lock.
    pub fn prepare(dir: &Path, manifest: Option<&str>) -> Result<OutputDir, OutputError> {
        if dir.exists() && !dir.is_dir() {
            return Err(OutputError::NotADirectory { path: dir.to_path_buf() });
        }
        if !dir.exists() && std::fs::symlink_metadata(dir).is_ok_and(|m| m.file_type().is_symlink()) {
            let target = std::fs::read_link(dir).unwrap_or_default();
            return Err(OutputError::DanglingLink { path: dir.to_path_buf(), target });
        }
        std::fs::create_dir_all(dir).map_err(|e| OutputError::io(dir, e))?;
        let lock = dir.join(LOCK_FILE);
        if let Some(dead) = take_lock(dir, &lock)? {
            remove_dead_run_files(dir, &dead);
        }
        let record = manifest.unwrap_or(RECORD_FILE);
        let previous = previous_files(&dir.join(record));
        Ok(OutputDir {
            dir: dir.to_path_buf(),
            lock,
            manifest: record.to_string(),
            previous,
            written: vec![],
            manifest_removed: false,
            finished: false,
        })
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.dir
    }

    /// The file names written so far, in order.
    pub fn written(&self) -> &[String] {
        &self.written
    }

    /// Writes `bytes` to `name` atomically (temporary file, sync, rename); returns the final path.
    ///
    /// # Errors
    /// [`OutputError::Io`] naming the file (the temporary file is removed).
    pub fn write_bytes(&mut self, name: &str, bytes: &[u8]) -> Result<PathBuf, OutputError> {
        self.write_with(name, |tmp| {
            // write_with created `tmp` exclusively: open that regular file, never a link.
            let mut f = open_no_follow(tmp).map_err(|e| OutputError::io(tmp, e))?;
            f.write_all(bytes).map_err(|e| OutputError::io(tmp, e))
        })
    }

    /// Creates a temporary file in the folder exclusively (same extension as `name`; see the
    /// module docs), runs `write` on its path, then syncs and renames it onto `name`; returns the
    /// final path. On any error the temporary file is removed
    /// and `name` is left as it was; the error names `name`'s final path.
    ///
    /// # Errors
    /// `write`'s error, or [`OutputError::Io`] when syncing or renaming fails.
    pub fn write_with(
        &mut self,
        name: &str,
        write: impl FnOnce(&Path) -> Result<(), OutputError>,
    ) -> Result<PathBuf, OutputError> {
        let target = self.target(name)?;
        self.remove_old_manifest()?;
        self.note_start(&[name])?;
        let tmp = self.dir.join(format!("{TEMP_PREFIX}{}-{name}", std::process::id()));
        let created = create_exclusive(&tmp).map(drop).map_err(|e| OutputError::io(&tmp, e));
        if let Err(e) = created.and_then(|()| write(&tmp)).and_then(|()| commit(&tmp, &target)) {
            let _ = std::fs::remove_file(&tmp);
            return Err(e.at_path(&tmp, &target));
        }
        self.record(name);
        Ok(target)
    }

    /// Creates `name` + [`PARTIAL_SUFFIX`] exclusively (see the module docs) for a file written
    /// piece by piece (each
    /// [`StreamedFile::append`] is flushed, so an interrupted run keeps what was finished);
    /// [`StreamedFile::commit`] renames it onto `name`.
    ///
    /// # Errors
    /// [`OutputError::Io`] when the file cannot be created.
    pub fn stream(&mut self, name: &str) -> Result<StreamedFile, OutputError> {
        let target = self.target(name)?;
        self.remove_old_manifest()?;
        self.note_start(&[name])?;
        let partial = self.dir.join(format!("{name}{PARTIAL_SUFFIX}"));
        let file = create_exclusive(&partial).map_err(|e| OutputError::io(&partial, e))?;
        Ok(StreamedFile { file: std::io::BufWriter::new(file), partial, target })
    }

    /// Records a streamed file that was committed (so that it is kept and listed).
    pub fn record_streamed(&mut self, file: &Path) {
        if let Some(name) = file.file_name().and_then(|n| n.to_str()) {
            self.record(name);
        }
    }

    /// Ends the run: removes stale files — those the previous manifest listed, and temporary or
    /// `.partial` leftovers of a listed or written name — that this run did not write, then writes
    /// the manifest from `manifest(files)` with the run's file names (the manifest's own name
    /// last; make it with [`manifest_json`] so that the next run can read it), then releases the
    /// lock. Returns the paths of the run's files, the manifest last.
    ///
    /// # Errors
    /// [`OutputError::Io`] when a stale file cannot be removed or the manifest cannot be written.
    pub fn finish(
        mut self,
        manifest: impl FnOnce(&[String]) -> Result<Vec<u8>, OutputError>,
    ) -> Result<Vec<PathBuf>, OutputError> {
        self.remove_stale()?;
        let name = self.manifest.clone();
        let mut files = self.written.clone();
        files.push(name.clone());
        let bytes = manifest(&files)?;
        if name == RECORD_FILE {
            // The hidden record is written directly: write_bytes refuses reserved names.
            self.write_reserved(&name, &bytes)?;
        } else {
            self.write_bytes(&name, &bytes)?;
        }
        self.finished = true;
        let _ = std::fs::remove_file(&self.lock);
        Ok(self.written.iter().map(|n| self.dir.join(n)).filter(|p| !p.ends_with(RECORD_FILE)).collect())
    }

    /// [`OutputDir::finish`] with the manifest printed by `write(files, out)` straight into its
    /// temporary file instead of made in memory first: for a manifest that grows with the run
    /// (a summary with a row per load step). For a folder prepared with a manifest name of its
    /// own (the hidden record is written by [`OutputDir::finish`] only).
    ///
    /// # Errors
    /// As [`OutputDir::finish`]; `write`'s error; [`OutputError::MissingData`] for a folder
    /// without a manifest name.
    pub fn finish_with(
        mut self,
        write: impl FnOnce(&[String], &mut dyn std::io::Write) -> Result<(), OutputError>,
    ) -> Result<Vec<PathBuf>, OutputError> {
        self.remove_stale()?;
        let name = self.manifest.clone();
        let mut files = self.written.clone();
        files.push(name.clone());
        self.write_with(&name, |tmp| {
            let file = open_no_follow(tmp).map_err(|e| OutputError::io(tmp, e))?;
            let mut out = std::io::BufWriter::new(file);
            write(&files, &mut out)?;
            out.flush().map_err(|e| OutputError::io(tmp, e))
        })?;
        self.finished = true;
        let _ = std::fs::remove_file(&self.lock);
        Ok(self.written.iter().map(|n| self.dir.join(n)).collect())
    }

    /// [`OutputDir::finish`] for a folder without a manifest of its own: the record is
    /// [`RECORD_FILE`], a [`manifest_json`] of the run's files. Returns the paths of the run's
    /// files (the hidden record not among them).
    ///
    /// # Errors
    /// As [`OutputDir::finish`].
    pub fn close(self) -> Result<Vec<PathBuf>, OutputError> {
        let path = self.dir.join(&self.manifest);
        self.finish(|files| manifest_json(serde_json::json!({}), files, &path))
    }

    /// Writes a reserved name (the hidden record) atomically, like [`OutputDir::write_bytes`].
    fn write_reserved(&mut self, name: &str, bytes: &[u8]) -> Result<(), OutputError> {
        let target = self.dir.join(name);
        self.note_start(&[name])?;
        let tmp = self.dir.join(format!("{TEMP_PREFIX}{}-{name}", std::process::id()));
        let written = create_exclusive(&tmp)
            .and_then(|mut f| f.write_all(bytes))
            .map_err(|e| OutputError::io(&tmp, e))
            .and_then(|()| commit(&tmp, &target));
        if let Err(e) = written {
            let _ = std::fs::remove_file(&tmp);
            return Err(e.at_path(&tmp, &target));
        }
        self.record(name);
        Ok(())
    }

    fn target(&self, name: &str) -> Result<PathBuf, OutputError> {
        if !plain_name(name) || name == LOCK_FILE || name == RECORD_FILE {
            return Err(OutputError::MissingData {
                path: self.dir.join(name),
                reason: "an output name must be a plain file name".into(),
            });
        }
        Ok(self.dir.join(name))
    }

    fn record(&mut self, name: &str) {
        if !self.written.iter().any(|w| w == name) {
            self.written.push(name.to_string());
        }
    }

    /// The first write invalidates the previous run's manifest, so that an interrupted run
    /// leaves no manifest beside a mix of files.
    fn remove_old_manifest(&mut self) -> Result<(), OutputError> {
        if self.manifest_removed {
            return Ok(());
        }
        // Once the manifest is gone, only the lock says which files were the previous run's.
        let previous: Vec<&str> = self.previous.iter().map(String::as_str).collect();
        self.note_start(&previous)?;
        let path = self.dir.join(&self.manifest);
        match std::fs::remove_file(&path) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(OutputError::io(path, e)),
        }
        self.manifest_removed = true;
        Ok(())
    }

    /// Removes what the previous record listed and this run did not write, and the temporary
    /// (`.contact2d-tmp-<pid>-<name>`) and `.partial` leftovers of a listed or written name.
    /// Appends `names` to the lock file (see the module docs): written before the files are, so
    /// that a run killed at any moment leaves a record of them. A plain `write` (no sync): what
    /// a killed process wrote stays in the file system's cache for the next run to read.
    fn note_start(&self, names: &[&str]) -> Result<(), OutputError> {
        if names.is_empty() {
            return Ok(());
        }
        let text: String = names.iter().map(|n| format!("{n}\n")).collect();
        let mut options = std::fs::OpenOptions::new();
        options.append(true);
        no_follow(&mut options);
        options
            .open(&self.lock)
            .and_then(|mut f| f.write_all(text.as_bytes()))
            .map_err(|e| OutputError::io(&self.lock, e))
    }

    fn remove_stale(&self) -> Result<(), OutputError> {
        let entries = std::fs::read_dir(&self.dir).map_err(|e| OutputError::io(&self.dir, e))?;
        let known = |stem: &str| self.previous.iter().chain(&self.written).any(|p| p == stem);
        for entry in entries.flatten() {
            let Some(name) = entry.file_name().to_str().map(String::from) else { continue };
            if self.written.contains(&name) || name == LOCK_FILE || self.manifest == name {
                continue;
            }
            let temporary = name
                .strip_prefix(TEMP_PREFIX)
                .and_then(|rest| rest.split_once('-'))
                .is_some_and(|(pid, stem)| !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()) && known(stem));
            let leftover = temporary || name.strip_suffix(PARTIAL_SUFFIX).is_some_and(known);
            if !(leftover || self.previous.contains(&name)) {
                continue;
            }
            // Only regular files: a directory or link of the user's with an output's name stays.
            if entry.file_type().is_ok_and(|t| t.is_file()) {
                let path = entry.path();
                std::fs::remove_file(&path).map_err(|e| OutputError::io(path, e))?;
            }
        }
        Ok(())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if self.finished {
            return;
        }
        // A failed run leaves no half folder: its files go (streamed .partial files stay), and
        // once writing has started (the previous manifest removed) so do the previous run's.
        let previous = if self.manifest_removed { self.previous.as_slice() } else { &[] };
        for name in self.written.iter().chain(previous) {
            let path = self.dir.join(name);
            if std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
                let _ = std::fs::remove_file(path);
            }
        }
        let _ = std::fs::remove_file(&self.lock);
    }
}

/// A file growing while the work goes on, flushed after every piece: `<name>.partial` until
/// [`StreamedFile::commit`].
#[derive(Debug)]
pub struct StreamedFile {
    file: std::io::BufWriter<std::fs::File>,
    partial: PathBuf,
    target: PathBuf,
}

impl StreamedFile {
    /// Appends `text` and flushes it to the operating system.
    ///
    /// # Errors
    /// [`OutputError::Io`] naming the `.partial` file.
    pub fn append(&mut self, text: &str) -> Result<(), OutputError> {
        self.file
            .write_all(text.as_bytes())
            .and_then(|()| self.file.flush())
            .map_err(|e| OutputError::io(&self.partial, e))
    }

    /// The `.partial` path being written.
    pub fn partial_path(&self) -> &Path {
        &self.partial
    }

    /// Syncs the file and renames it onto its final name; returns the final path (pass it to
    /// [`OutputDir::record_streamed`]).
    ///
    /// # Errors
    /// [`OutputError::Io`].
    pub fn commit(mut self) -> Result<PathBuf, OutputError> {
        self.file.flush().map_err(|e| OutputError::io(&self.partial, e))?;
        commit(&self.partial, &self.target)?;
        Ok(self.target)
    }

    /// Discards the streamed file (e.g. when the whole file is written afresh in another order).
    pub fn discard(self) {
        let _ = std::fs::remove_file(&self.partial);
    }
}

/// A JSON manifest: `value` (an object; anything else is wrapped as `{"value": ...}`) with
/// `"written_by": "contact2d <version>"` and `"files"`, pretty-printed with a final newline.
///
/// # Errors
/// [`OutputError::Serialize`] if serde_json fails.
pub fn manifest_json(value: serde_json::Value, files: &[String], path: &Path) -> Result<Vec<u8>, OutputError> {
    pretty_json(&manifest_object(value, files), path)
}

/// The object of [`manifest_json`], before it is printed.
pub fn manifest_object(value: serde_json::Value, files: &[String]) -> serde_json::Map<String, serde_json::Value> {
    let mut object = match value {
        serde_json::Value::Object(o) => o,
        other => std::iter::once(("value".to_string(), other)).collect(),
    };
    object.insert("written_by".into(), format!("contact2d {}", env!("CARGO_PKG_VERSION")).into());
    object.insert("files".into(), files.iter().map(|f| serde_json::Value::from(f.as_str())).collect());
    object
}

/// `value` pretty-printed with a final newline, as [`manifest_json`] prints a manifest.
///
/// # Errors
/// [`OutputError::Serialize`] naming `path` if serde_json fails.
pub fn pretty_json(value: &impl serde::Serialize, path: &Path) -> Result<Vec<u8>, OutputError> {
    let text = serde_json::to_string_pretty(value)
        .map_err(|e| OutputError::Serialize { path: path.to_path_buf(), reason: e.to_string() })?;
    Ok((text + "\n").into_bytes())
}

/// Creates `path` exclusively for writing: whatever file or symbolic link is already there is
/// removed (a link is removed, never followed), then the file is created with `create_new`
/// (which refuses a name that exists, dangling links included) and, on Linux, `O_NOFOLLOW`.
///
/// # Errors
/// The I/O error (a directory at `path`, a race that recreated the name, permissions).
pub fn create_exclusive(path: &Path) -> std::io::Result<std::fs::File> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if !m.is_dir() => std::fs::remove_file(path)?,
        _ => {}
    }
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    no_follow(&mut options);
    options.open(path)
}

/// Opens an existing regular file for writing (truncated), refusing a symbolic link on Linux.
fn open_no_follow(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.write(true).truncate(true);
    no_follow(&mut options);
    options.open(path)
}

/// Adds `O_NOFOLLOW` (Linux's value per architecture; libc is no dependency of ours).
#[cfg(target_os = "linux")]
fn no_follow(options: &mut std::fs::OpenOptions) {
    use std::os::unix::fs::OpenOptionsExt as _;
    #[cfg(any(target_arch = "aarch64", target_arch = "arm", target_arch = "powerpc", target_arch = "powerpc64"))]
    const O_NOFOLLOW: i32 = 0o100_000;
    #[cfg(not(any(target_arch = "aarch64", target_arch = "arm", target_arch = "powerpc", target_arch = "powerpc64")))]
    const O_NOFOLLOW: i32 = 0o400_000;
    options.custom_flags(O_NOFOLLOW);
}

/// Elsewhere `create_new` alone refuses an existing name (links included).
#[cfg(not(target_os = "linux"))]
fn no_follow(_options: &mut std::fs::OpenOptions) {}

/// Syncs `tmp` to disk and renames it onto `target`.
fn commit(tmp: &Path, target: &Path) -> Result<(), OutputError> {
    let file = std::fs::File::open(tmp).map_err(|e| OutputError::io(tmp, e))?;
    file.sync_all().map_err(|e| OutputError::io(tmp, e))?;
    std::fs::rename(tmp, target).map_err(|e| OutputError::io(target, e))
}

/// A name without a directory part (no separator, not `.` or `..`, not empty, no NUL).
fn plain_name(name: &str) -> bool {
    !name.is_empty() && name != "." && name != ".." && !name.contains(['/', '\\', '\0'])
}

/// Creates the lock file with create_new; a lock left by a process that no longer runs is
/// replaced once.
/// What the lock of a dead writer recorded: its pid and the files it had started writing.
#[derive(Debug)]
struct DeadRun {
    pid: u32,
    files: Vec<String>,
}

/// Takes the lock; if it replaced the stale lock of a dead process, returns what that lock
/// recorded.
fn take_lock(dir: &Path, lock: &Path) -> Result<Option<DeadRun>, OutputError> {
    let mut dead_run = None;
    for attempt in 0..2 {
        match std::fs::OpenOptions::new().write(true).create_new(true).open(lock) {
            Ok(mut f) => {
                return f
                    .write_all(format!("{}\n", std::process::id()).as_bytes())
                    .and_then(|()| f.sync_all())
                    .map(|()| dead_run)
                    .map_err(|e| {
                        let _ = std::fs::remove_file(lock);
                        OutputError::io(lock, e)
                    });
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                // A lock is small; anything else at that name is read as no pid.
                let text = std::fs::symlink_metadata(lock)
                    .is_ok_and(|m| m.is_file() && m.len() < 16 << 20)
                    .then(|| std::fs::read_to_string(lock).ok())
                    .flatten()
                    .unwrap_or_default();
                let mut lines = text.lines();
                let pid = lines.next().and_then(|t| t.trim().parse::<u32>().ok());
                let dead = pid.is_some_and(|p| p != std::process::id() && process_is_gone(p));
                if attempt == 0 && dead {
                    let files = lines.map(str::to_string).filter(|f| plain_name(f) && *f != LOCK_FILE).collect();
                    dead_run = pid.map(|pid| DeadRun { pid, files });
                    let _ = std::fs::remove_file(lock);
                    continue;
                }
                return Err(OutputError::Locked { dir: dir.to_path_buf(), lock: lock.to_path_buf(), pid });
            }
            Err(e) => return Err(OutputError::io(dir, e)),
        }
    }
    Err(OutputError::Locked { dir: dir.to_path_buf(), lock: lock.to_path_buf(), pid: None })
}

/// Whether no process `pid` runs (known on systems with `/proc`; elsewhere a lock is never
/// taken for stale).
/// Removes what a dead run recorded in its lock: the regular files of those names (never a
/// directory or a link) and its temporary files; a streamed `.partial` file stays (it keeps
/// the rows that were finished). Best effort: a file that cannot be removed stays.
fn remove_dead_run_files(dir: &Path, dead: &DeadRun) {
    let temporary = format!("{TEMP_PREFIX}{}-", dead.pid);
    let temporaries = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .flatten()
                .filter_map(|e| e.file_name().to_str().map(String::from))
                .filter(|n| n.starts_with(&temporary))
                .collect::<Vec<_>>()
        })
        .unwrap_or_default();
    for name in dead.files.iter().chain(&temporaries) {
        let path = dir.join(name);
        if std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
            let _ = std::fs::remove_file(path);
        }
    }
}

fn process_is_gone(pid: u32) -> bool {
    Path::new("/proc/self").exists() && !Path::new(&format!("/proc/{pid}")).exists()
}

/// The file names a previous contact2d manifest lists (plain names only; empty when there is no
/// manifest or it is not ours).
fn previous_files(manifest: &Path) -> Vec<String> {
    // A manifest is small; a huge or unreadable file at that name is not one of ours.
    // A link at the record's name is no record of ours (it could list any file).
    let small = std::fs::symlink_metadata(manifest).is_ok_and(|m| m.is_file() && m.len() < 64 << 20);
    let value: Option<serde_json::Value> =
        small.then(|| std::fs::read(manifest).ok()).flatten().and_then(|b| serde_json::from_slice(&b).ok());
    let Some(value) = value else { return vec![] };
    let ours = value.get("written_by").and_then(|w| w.as_str()).is_some_and(|w| w.starts_with("contact2d"));
    let files = value.get("files").and_then(|f| f.as_array());
    match (ours, files) {
        (true, Some(files)) => files
            .iter()
            .filter_map(|f| f.as_str())
            .filter(|f| plain_name(f) && *f != LOCK_FILE)
            .map(String::from)
            .collect(),
        _ => vec![],
    }
}

#[cfg(test)]
#[path = "atomic_tests.rs"]
mod tests;

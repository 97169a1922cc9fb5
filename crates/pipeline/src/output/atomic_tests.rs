//! Tests of `atomic.rs`: whole files, exclusive creation, the folder's record.
#![allow(clippy::unwrap_used)]

use super::*;

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("contact2d_atomic_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    n.sort();
    n
}

fn manifest(files: &[String]) -> Result<Vec<u8>, OutputError> {
    manifest_json(serde_json::json!({}), files, Path::new("m.json"))
}

#[test]
fn a_second_writer_is_refused_and_the_lock_goes_with_the_first() {
    let dir = temp_dir("lock");
    let first = OutputDir::prepare(&dir, Some("m.json")).unwrap();
    assert!(matches!(OutputDir::prepare(&dir, Some("m.json")), Err(OutputError::Locked { .. })));
    drop(first);
    assert!(!dir.join(LOCK_FILE).exists());
    // A lock of a process that no longer runs (pid beyond Linux's pid_max) is replaced.
    std::fs::write(dir.join(LOCK_FILE), "4194305\n").unwrap();
    let out = OutputDir::prepare(&dir, None).unwrap();
    out.close().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_manifest_lists_exactly_the_files_and_stale_ones_go() {
    let dir = temp_dir("stale");
    let mut out = OutputDir::prepare(&dir, Some("m.json")).unwrap();
    for name in ["a.txt", "step_000.vtu", "step_001.vtu"] {
        out.write_bytes(name, b"x").unwrap();
    }
    out.finish(manifest).unwrap();
    std::fs::write(dir.join("user_notes.txt"), "mine").unwrap();
    // Named like an output but listed by no record: the user's.
    std::fs::write(dir.join("step_007.vtu"), "mine too").unwrap();
    // A shorter second run: a.txt and step_001.vtu are stale, the user's files stay.
    let mut out = OutputDir::prepare(&dir, Some("m.json")).unwrap();
    out.write_bytes("step_000.vtu", b"y").unwrap();
    let written = out.finish(manifest).unwrap();
    assert_eq!(written.len(), 2);
    assert_eq!(names(&dir), ["m.json", "step_000.vtu", "step_007.vtu", "user_notes.txt"]);
    let m: serde_json::Value = serde_json::from_slice(&std::fs::read(dir.join("m.json")).unwrap()).unwrap();
    assert_eq!(m["files"], serde_json::json!(["step_000.vtu", "m.json"]));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_failed_write_leaves_neither_the_file_nor_a_manifest() {
    let dir = temp_dir("fail");
    let mut out = OutputDir::prepare(&dir, Some("m.json")).unwrap();
    out.write_bytes("a.txt", b"old").unwrap();
    out.finish(manifest).unwrap();
    let mut out = OutputDir::prepare(&dir, Some("m.json")).unwrap();
    out.write_bytes("b.txt", b"new").unwrap();
    let failed: Result<PathBuf, OutputError> = out.write_with("a.txt", |tmp| {
        std::fs::write(tmp, "half").unwrap();
        Err(OutputError::io(tmp, std::io::Error::other("disk full")))
    });
    let message = failed.unwrap_err().to_string();
    assert!(message.contains("a.txt") && !message.contains(TEMP_PREFIX), "names the file: {message}");
    assert_eq!(std::fs::read_to_string(dir.join("a.txt")).unwrap(), "old", "the old file is untouched");
    drop(out);
    // The run's own files, the previous run's (its manifest already gone) and the lock are
    // gone: the folder is absent rather than half.
    assert!(names(&dir).is_empty(), "{:?}", names(&dir));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn streamed_rows_survive_until_commit() {
    let dir = temp_dir("stream");
    let mut out = OutputDir::prepare(&dir, None).unwrap();
    let mut s = out.stream("rows.csv").unwrap();
    s.append("a\n").unwrap();
    assert_eq!(std::fs::read_to_string(dir.join("rows.csv.partial")).unwrap(), "a\n");
    let path = s.commit().unwrap();
    out.record_streamed(&path);
    out.close().unwrap();
    assert_eq!(names(&dir), [RECORD_FILE, "rows.csv"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_where_the_folder_should_be_is_refused() {
    let file = temp_dir("notdir");
    std::fs::write(&file, "x").unwrap();
    assert!(matches!(OutputDir::prepare(&file, None), Err(OutputError::NotADirectory { .. })));
    assert!(matches!(OutputDir::prepare(&file.join("sub"), None), Err(OutputError::Io { .. })));
    std::fs::remove_file(&file).unwrap();
    let dir = temp_dir("names");
    let mut out = OutputDir::prepare(&dir, None).unwrap();
    assert!(out.write_bytes("../escape.txt", b"x").is_err());
    drop(out);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn a_link_planted_at_a_temporary_or_partial_name_is_not_followed() {
    let dir = temp_dir("link");
    std::fs::create_dir_all(&dir).unwrap();
    let victim = dir.join("victim.txt");
    std::fs::write(&victim, "keep").unwrap();
    let tmp = dir.join(format!("{TEMP_PREFIX}{}-a.txt", std::process::id()));
    std::os::unix::fs::symlink(&victim, &tmp).unwrap();
    std::os::unix::fs::symlink(&victim, dir.join("rows.csv.partial")).unwrap();
    let mut out = OutputDir::prepare(&dir, None).unwrap();
    out.write_bytes("a.txt", b"output").unwrap();
    let mut s = out.stream("rows.csv").unwrap();
    s.append("row\n").unwrap();
    out.record_streamed(&s.commit().unwrap());
    out.close().unwrap();
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep", "the link's target is untouched");
    assert_eq!(std::fs::read_to_string(dir.join("a.txt")).unwrap(), "output");
    assert_eq!(std::fs::read_to_string(dir.join("rows.csv")).unwrap(), "row\n");
    std::fs::remove_dir_all(&dir).unwrap();
}

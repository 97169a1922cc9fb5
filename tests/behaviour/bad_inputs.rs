//! The bad-input corpus (`tests/bad_inputs/`): every malformed mesh and scene there fails through
//! the command line with the error recorded in `tests/bad_inputs/expected.toml`: the expected
//! exit status, one line on stderr naming the file and containing the recorded substrings
//! (the line, byte or key at fault), and no panic; a file that is valid but poor (a sliver) may
//! instead exit 0 with recorded substrings on stdout (`stdout`). An entry may add arguments after the file
//! (`args`, e.g. a `--set` or `--vary`), and for a flag at fault the message names the flag
//! instead of the file (`names_file = false`).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;
use std::process::Command;

use serde::Deserialize;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Expected {
    command: String,
    exit: i32,
    stderr: Vec<String>,
    /// Substrings stdout must contain (a warning about a valid but poor file).
    #[serde(default)]
    stdout: Vec<String>,
    /// For a run that solves (exit 0): the `status` its `--json` summary must report.
    #[serde(default)]
    status: Option<String>,
    /// Substrings the `failed_check` of that summary must contain.
    #[serde(default)]
    failed_check: Vec<String>,
    #[allow(dead_code)]
    why: String,
    #[serde(default)]
    args: Vec<String>,
    #[serde(default = "yes")]
    names_file: bool,
}

fn yes() -> bool {
    true
}

#[test]
fn every_bad_input_fails_with_its_recorded_error() {
    let dir = Path::new("tests/bad_inputs");
    let text = std::fs::read_to_string(dir.join("expected.toml")).unwrap();
    let expected: std::collections::BTreeMap<String, Expected> = toml::from_str(&text).unwrap();
    // Every file of the corpus has an entry, and every entry a file.
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| (f.ends_with(".msh") || f.ends_with(".toml")) && f != "expected.toml")
        .collect();
    files.sort();
    assert_eq!(files, expected.keys().cloned().collect::<Vec<_>>(), "corpus and expected.toml differ");
    let mut failures = vec![];
    for (file, want) in &expected {
        let path = dir.join(file);
        let out_dir = std::env::temp_dir().join(format!("contact2d_bad_inputs_{}_{file}", std::process::id()));
        let args: Vec<String> = want.args.iter().map(|a| a.replace("{out}", &out_dir.display().to_string())).collect();
        let mut command = Command::new(env!("CARGO_BIN_EXE_contact2d"));
        command.arg(&want.command).arg(&path).args(&args);
        if want.status.is_some() {
            command.arg("--json");
        }
        let out = command.output().unwrap();
        let _ = std::fs::remove_dir_all(&out_dir);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let code = out.status.code();
        let mut wrong = vec![];
        if code != Some(want.exit) {
            wrong.push(format!("exit {code:?}, expected {}", want.exit));
        }
        if stderr.contains("panicked") {
            wrong.push("panicked".into());
        }
        if want.exit != 0 {
            if stderr.trim().lines().count() != 1 {
                wrong.push("not one line".into());
            }
            if want.names_file && !stderr.contains(&path.display().to_string()) {
                wrong.push("does not name the file".into());
            }
            wrong.extend(want.stderr.iter().filter(|s| !stderr.contains(s.as_str())).map(|s| format!("lacks {s:?}")));
        }
        let stdout = String::from_utf8_lossy(&out.stdout);
        wrong
            .extend(want.stdout.iter().filter(|s| !stdout.contains(s.as_str())).map(|s| format!("stdout lacks {s:?}")));
        if let Some(status) = &want.status {
            wrong.extend(check_summary(&out.stdout, status, &want.failed_check));
        }
        if !wrong.is_empty() {
            failures.push(format!("{file}: {} — stderr: {}", wrong.join(", "), stderr.trim()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// What is wrong with a `--json` summary that should report `status` and a `failed_check`
/// containing `check`.
fn check_summary(stdout: &[u8], status: &str, check: &[String]) -> Vec<String> {
    let Ok(summary) = serde_json::from_slice::<serde_json::Value>(stdout) else {
        return vec!["stdout is not one JSON summary".into()];
    };
    let mut wrong = vec![];
    if summary["status"] != status {
        wrong.push(format!("status {}, expected {status}", summary["status"]));
    }
    let failed = summary["failed_check"].as_str().unwrap_or("");
    wrong.extend(check.iter().filter(|c| !failed.contains(c.as_str())).map(|c| format!("failed_check lacks {c:?}")));
    wrong
}

//! `--set key.path=value` overrides applied to the TOML tree of a scene before it is checked.
//!
//! The value is parsed as TOML, falling back to a string (so `mesh=other.msh` needs no quotes);
//! a value spelled as a number that TOML cannot read (`.3`, `1e400`) is an error naming the
//! override, not a string that fails later as a wrong type.

use super::SceneError;

/// A value that is spelled as a number must be one TOML reads as a finite number: `.3` or
/// `1e400` would otherwise fall back to a string and fail later as a wrong type.
fn check_number_spelling(raw: &str, parsed: Option<&toml::Value>) -> Result<(), String> {
    let t = raw.trim();
    let numeric = t.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c))
        && t.chars().all(|c| c.is_ascii_digit() || "+-._eE".contains(c))
        && t.chars().any(|c| c.is_ascii_digit());
    match parsed {
        Some(toml::Value::Float(v)) if !v.is_finite() && numeric => {
            Err(format!("the number {t} is out of the range of a 64-bit float (|x| ≤ 1.8e308)"))
        }
        Some(_) => Ok(()),
        None if !numeric => Ok(()),
        None => match t.replace('_', "").parse::<f64>() {
            Ok(v) if !v.is_finite() => {
                Err(format!("the number {t} is out of the range of a 64-bit float (|x| ≤ 1.8e308)"))
            }
            Ok(v) => Err(format!("malformed number {t:?} (TOML needs a digit on both sides of the point: {v:?})")),
            Err(_) => Err(format!("malformed number {t:?}")),
        },
    }
}

/// The key that `key` in table `table` excludes (a scene gives one of them): `loading.steps`
/// and `loading.schedule`.
fn excluded_by(table: &[&str], key: &str) -> Option<&'static str> {
    match (table, key) {
        (["loading"], "steps") => Some("schedule"),
        (["loading"], "schedule") => Some("steps"),
        _ => None,
    }
}

/// The TOML text of a scene with `overrides` applied through the same engine as `--set`
/// (`apply_override`): what a caller holding a scene as text plus overrides (the Python
/// package) shows as the scene. Comments and layout are not kept.
///
/// # Errors
/// [`SceneError::Invalid`] naming `path` if `text` is not TOML; [`SceneError::Override`] for an
/// override that does not apply.
pub fn overridden_scene_text(text: &str, path: &std::path::Path, overrides: &[String]) -> Result<String, SceneError> {
    let invalid = |reason: String| SceneError::Invalid { path: path.display().to_string(), reason };
    let mut root = toml::Value::Table(toml::from_str::<toml::Table>(text).map_err(|e| invalid(e.to_string()))?);
    for assignment in overrides {
        apply_override(&mut root, assignment)?;
    }
    toml::to_string(&root).map_err(|e| invalid(e.to_string()))
}

/// Sets `a.b.c = value` in a TOML tree; the key must exist (unknown keys are errors). An array
/// of tables (`[[contact]]` of a generic scene) is entered by index (`contact.0.friction`) or by
/// the entry's `name`, `region` or `group` (`contact.hertz.friction`, `body.block.thickness`).
pub(crate) fn apply_override(root: &mut toml::Value, assignment: &str) -> Result<(), SceneError> {
    let err = |reason: String| SceneError::Override { assignment: assignment.to_string(), reason };
    let (key, raw) = assignment.split_once('=').ok_or_else(|| err("expected key.path=value".into()))?;
    let parsed = toml::from_str::<toml::Table>(&format!("v = {raw}")).ok().and_then(|mut t| t.remove("v"));
    check_number_spelling(raw, parsed.as_ref()).map_err(err)?;
    let parsed = parsed.unwrap_or_else(|| toml::Value::String(raw.to_string()));
    let mut node = root;
    let parts: Vec<&str> = key.trim().split('.').collect();
    for (i, part) in parts.iter().enumerate() {
        if let Some(array) = node.as_array() {
            let here = parts[..i].join(".");
            let len = array.len();
            let at = match part.parse::<usize>() {
                Ok(k) if k < len => k,
                Ok(k) => return Err(err(format!("\"{here}\" has {len} entries; index {k} is past its end"))),
                Err(_) => array
                    .iter()
                    .position(|entry| {
                        ["name", "region", "group"].iter().any(|k| entry.get(k).and_then(|v| v.as_str()) == Some(part))
                    })
                    .ok_or_else(|| err(format!("no entry of \"{here}\" has the name, region or group \"{part}\"")))?,
            };
            if i + 1 == parts.len() {
                return Err(err(format!("\"{here}.{part}\" is a whole entry; set one of its keys")));
            }
            node = node.get_mut(at).ok_or_else(|| err(format!("\"{here}\" has no entry {at}")))?;
            continue;
        }
        let table = node.as_table_mut().ok_or_else(|| err(format!("\"{}\" is not a table", parts[..i].join("."))))?;
        if i + 1 == parts.len() {
            // A key the file leaves at its default may be set; whether it exists at all is
            // decided when the scene is checked (unknown keys are errors there). Keys that
            // exclude each other replace each other: `--set loading.schedule=[…]` on a scene
            // with `steps` means the schedule.
            if let Some(other) = excluded_by(&parts[..i], part) {
                table.remove(other);
            }
            table.insert((*part).to_string(), parsed);
            return Ok(());
        }
        node =
            table.get_mut(*part).ok_or_else(|| err(format!("no table \"{}\" in the scene", parts[..=i].join("."))))?;
    }
    Err(err("empty key".into()))
}

//! `--set key.path=value` overrides applied to the TOML tree of a scene before it is checked,
//! and `--unset key.path`, which removes a key the file gives (so that a scene with `steps` can
//! be given a `schedule`, or a key can fall back to its default).
//!
//! Both travel in one list of override entries, applied in order: `key=value` sets, and
//! [`unset_override`]`(key)` (the key after [`UNSET_MARK`]) removes.
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

/// The first character of an override entry that removes a key rather than sets one.
pub const UNSET_MARK: char = '!';

/// The override entry that removes `key` (`--unset key`), for the override lists that
/// [`overridden_scene_text`] and the scene loaders take.
pub fn unset_override(key: &str) -> String {
    format!("{UNSET_MARK}{key}")
}

/// An override entry as the command-line flag that gives it: `--set key=value` or `--unset key`.
pub(crate) fn as_flag(entry: &str) -> String {
    match entry.strip_prefix(UNSET_MARK) {
        Some(key) => format!("--unset {key}"),
        None => format!("--set {entry}"),
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

/// Applies one override entry: sets `a.b.c = value` in a TOML tree (the tables on the way must
/// exist; whether the key may be given is decided when the scene is checked), or, for an entry
/// made by [`unset_override`], removes `a.b.c`, which the tree must hold (a whole entry of an
/// array of tables too: `contact.1`). An array of tables (`[[contact]]` of a generic scene) is
/// entered by index (`contact.0.friction`) or by the entry's `name`, `region` or `group`
/// (`contact.hertz.friction`, `body.block.thickness`).
pub(crate) fn apply_override(root: &mut toml::Value, assignment: &str) -> Result<(), SceneError> {
    let err = |reason: String| SceneError::Override { assignment: assignment.to_string(), reason };
    if let Some(key) = assignment.strip_prefix(UNSET_MARK) {
        return remove_key(root, key).map_err(err);
    }
    let (key, raw) = assignment.split_once('=').ok_or_else(|| err("expected key.path=value".into()))?;
    let parsed = toml::from_str::<toml::Table>(&format!("v = {raw}")).ok().and_then(|mut t| t.remove("v"));
    check_number_spelling(raw, parsed.as_ref()).map_err(err)?;
    let parsed = parsed.unwrap_or_else(|| toml::Value::String(raw.to_string()));
    let mut node = root;
    let parts: Vec<&str> = key.trim().split('.').collect();
    for (i, part) in parts.iter().enumerate() {
        if let Some(array) = node.as_array() {
            let here = parts[..i].join(".");
            let at = array_entry(array, &here, part).map_err(err)?;
            if i + 1 == parts.len() {
                return Err(err(format!(
                    "\"{here}.{part}\" is a whole entry; set one of its keys (or remove it with --unset {here}.{part})"
                )));
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
        // A table the file leaves out (`loading.adaptive`) is made: a misspelt one is an unknown
        // key when the scene is checked.
        node = table.entry((*part).to_string()).or_insert_with(|| toml::Value::Table(toml::Table::new()));
    }
    Err(err("empty key".into()))
}

/// The entry of array `array` (reached by `here`) that `part` names: an index, or the `name`,
/// `region` or `group` of an entry.
fn array_entry(array: &[toml::Value], here: &str, part: &str) -> Result<usize, String> {
    let len = array.len();
    match part.parse::<usize>() {
        Ok(k) if k < len => Ok(k),
        Ok(k) => Err(format!("\"{here}\" has {len} entries; index {k} is past its end")),
        Err(_) => array
            .iter()
            .position(|entry| {
                ["name", "region", "group"].iter().any(|k| entry.get(k).and_then(|v| v.as_str()) == Some(part))
            })
            .ok_or_else(|| format!("no entry of \"{here}\" has the name, region or group \"{part}\"")),
    }
}

/// Removes the key (or array entry) at the dotted path `key` from `root`.
fn remove_key(root: &mut toml::Value, key: &str) -> Result<(), String> {
    let parts: Vec<&str> = key.trim().split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err("expected a dotted key such as loading.steps".into());
    }
    let mut node = root;
    for (i, part) in parts.iter().enumerate() {
        let here = parts[..i].join(".");
        let last = i + 1 == parts.len();
        if let toml::Value::Array(array) = node {
            let at = array_entry(array, &here, part)?;
            if last {
                array.remove(at);
                return Ok(());
            }
            node = array.get_mut(at).ok_or_else(|| format!("\"{here}\" has no entry {at}"))?;
            continue;
        }
        let table = node.as_table_mut().ok_or_else(|| format!("\"{here}\" is not a table"))?;
        if last {
            return match table.remove(*part) {
                Some(_) => Ok(()),
                None => Err(format!("the scene gives no key \"{}\" to remove", parts.join("."))),
            };
        }
        node = table.get_mut(*part).ok_or_else(|| format!("no table \"{}\" in the scene", parts[..=i].join(".")))?;
    }
    Err("empty key".into())
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::expect_used)]
mod tests {
    use super::*;

    const SCENE: &str = "name = \"t\"\n[loading]\nsteps = 4\n[[contact]]\nname = \"a\"\nfriction = 0.1\n\
                         [[contact]]\nname = \"b\"\nfriction = 0.2\n";

    fn apply(entries: &[String]) -> Result<toml::Value, String> {
        let mut root = toml::Value::Table(toml::from_str(SCENE).unwrap());
        for e in entries {
            apply_override(&mut root, e).map_err(|e| e.to_string())?;
        }
        Ok(root)
    }

    #[test]
    fn unset_removes_a_key_and_an_entry_in_order() {
        let root = apply(&[unset_override("loading.steps"), "loading.schedule=[[1.0, 0.0]]".into()]).unwrap();
        assert!(root["loading"].get("steps").is_none());
        assert!(root["loading"].get("schedule").is_some());
        let root = apply(&[unset_override("contact.a")]).unwrap();
        assert_eq!(root["contact"].as_array().unwrap().len(), 1);
        assert_eq!(root["contact"][0]["name"].as_str(), Some("b"));
        let root = apply(&[unset_override("contact.1.friction")]).unwrap();
        assert!(root["contact"][1].get("friction").is_none() && root["contact"][0].get("friction").is_some());
        // A removed key may be set again afterwards.
        let root = apply(&[unset_override("loading.steps"), "loading.steps=2".into()]).unwrap();
        assert_eq!(root["loading"]["steps"].as_integer(), Some(2));
    }

    #[test]
    fn unset_of_a_key_the_scene_does_not_give_is_an_error_naming_the_flag() {
        for (key, expected) in [
            ("loading.stepz", "--unset loading.stepz: the scene gives no key \"loading.stepz\" to remove"),
            ("solver.algorithm", "--unset solver.algorithm: no table \"solver\" in the scene"),
            ("contact.c", "no entry of \"contact\" has the name, region or group \"c\""),
            ("contact.5", "\"contact\" has 2 entries; index 5 is past its end"),
            ("", "expected a dotted key"),
        ] {
            let e = apply(&[unset_override(key)]).unwrap_err();
            assert!(e.contains(expected), "{key}: {e}");
        }
    }
}

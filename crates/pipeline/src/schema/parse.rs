//! Reading scene files: the text (a regular, bounded UTF-8 file) and the TOML parse with the
//! `--set` overrides, shared by the flagship's scenes and the generic ones. Errors name the
//! file and the line (syntax) or the dotted key (types, unknown keys).

use std::path::Path;

use super::{SceneError, apply_override};

/// Parses scene TOML `text` (read from `path`, named in errors) into `T` after applying the
/// `--set` `overrides`: syntax errors with their line, unknown keys and wrong types with their
/// dotted key (and the line when the file itself is at fault).
///
/// # Errors
/// [`SceneError::Invalid`] or [`SceneError::Override`].
pub(crate) fn parse_scene_toml<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &Path,
    overrides: &[String],
    optional_tables: &[&str],
) -> Result<T, SceneError> {
    let shown = path.display().to_string();
    let invalid = |reason: String| SceneError::Invalid { path: shown.clone(), reason };
    let mut value: toml::Value = toml::from_str(text).map_err(|e| invalid(spanned_reason(text, &e)))?;
    // Sections the file may leave out (all their keys have defaults) exist for `--set`.
    if let Some(table) = value.as_table_mut() {
        for name in optional_tables {
            table.entry(*name).or_insert_with(|| toml::Value::Table(toml::Table::new()));
        }
    }
    for assignment in overrides {
        apply_override(&mut value, assignment)?;
    }
    value.try_into().map_err(|e: toml::de::Error| {
        let shown_error = e.to_string();
        let key = shown_error.rsplit_once("\nin `").map(|(_, k)| k.trim_end().trim_end_matches('`').to_string());
        let at = key.map_or(String::new(), |k| format!("{k}: "));
        // Without overrides the text itself is at fault: give its line too.
        invalid(match (overrides.is_empty(), toml::from_str::<T>(text)) {
            (true, Err(spanned)) if spanned.message() == e.message() => {
                format!("{}{at}{}", line_of(text, &spanned), e.message())
            }
            (true, _) => format!("{at}{}", e.message()),
            (false, _) => format!("{at}{} (after the --set overrides)", e.message()),
        })
    })
}

/// The text of a scene file: a regular file of at most [`crate::input_file::MAX_SCENE_BYTES`],
/// UTF-8.
///
/// # Errors
/// [`SceneError::Io`], [`SceneError::Unreadable`] (not a regular file, too large) or
/// [`SceneError::Invalid`] (not UTF-8), naming the file.
pub fn read_scene_text(path: &Path) -> Result<String, SceneError> {
    let shown = path.display().to_string();
    let bytes = crate::input_file::read_input_file(path, crate::input_file::MAX_SCENE_BYTES).map_err(|e| match e {
        crate::input_file::InputFileError::Io { source, .. } => SceneError::Io { path: shown.clone(), source },
        other => SceneError::Unreadable { path: shown.clone(), reason: other.reason() },
    })?;
    String::from_utf8(bytes).map_err(|e| SceneError::Invalid {
        path: shown,
        reason: format!("not UTF-8 text (invalid byte at offset {})", e.utf8_error().valid_up_to()),
    })
}

/// "line L, column C: message" of a TOML error with a span.
fn spanned_reason(text: &str, e: &toml::de::Error) -> String {
    format!("{}{}", line_of(text, e), e.message())
}

/// "line L, column C: " of an error's span in `text` (empty without a span).
fn line_of(text: &str, e: &toml::de::Error) -> String {
    e.span().map_or(String::new(), |span| {
        let before = text.get(..span.start).unwrap_or(text);
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        format!("line {line}, column {column}: ")
    })
}

//! Python values to TOML: a dict becomes a scene's text, a value an override's right-hand side.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// `value` as a TOML value: dict → table (string keys), list/tuple → array, str, bool, int,
/// float.
///
/// # Errors
/// `TypeError` naming the dotted key of a value of another type.
pub fn to_toml(value: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    // bool first: a Python bool is also an int.
    if let Ok(b) = value.cast::<PyBool>() {
        return Ok(toml::Value::Boolean(b.is_true()));
    }
    if value.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(value.extract::<i64>()?));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract::<f64>()?));
    }
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(toml::Value::String(s.to_str()?.to_string()));
    }
    if let Ok(d) = value.cast::<PyDict>() {
        return Ok(toml::Value::Table(to_table(d, key)?));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let mut items = vec![];
        for (i, item) in value.try_iter()?.enumerate() {
            items.push(to_toml(&item?, &format!("{key}.{i}"))?);
        }
        return Ok(toml::Value::Array(items));
    }
    let kind = value.get_type().name()?;
    Err(PyTypeError::new_err(format!("{key}: a {kind} has no TOML form (use dict, list, str, bool, int, float)")))
}

/// A dict with string keys as a TOML table.
///
/// # Errors
/// `TypeError` for a key that is not a string or a value [`to_toml`] refuses.
pub fn to_table(dict: &Bound<'_, PyDict>, key: &str) -> PyResult<toml::Table> {
    let mut table = toml::Table::new();
    for (k, v) in dict.iter() {
        let name: String =
            k.extract().map_err(|_| PyTypeError::new_err(format!("{key}: keys must be strings, not {k}")))?;
        let path = if key.is_empty() { name.clone() } else { format!("{key}.{name}") };
        table.insert(name, to_toml(&v, &path)?);
    }
    Ok(table)
}

//! `compare` and `verify`: the library functions behind `contact2d compare` and `contact2d
//! verify`, run with the GIL released; each returns plain rows (dicts) that the Python layer
//! turns into DataFrames. No file is written (the CLI's `--out` tables are the same rows).

use std::collections::BTreeMap;
use std::path::PathBuf;

use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::{Contact2dError, ContactError, MeshError, generic_error, scene_error};

/// A compared quantity's reference as compare.json's `reference` object: quantity, kind, from,
/// value, how, deviation.
type ReferenceRow<'py> = Bound<'py, PyDict>;

/// Table rows, one dict per row.
type Rows<'py> = Vec<Bound<'py, PyDict>>;

/// Each case's notes as (case, note).
type Notes = Vec<(String, String)>;

/// Runs `contact2d compare SCENE` (every algorithm × pairing × mesh level) and returns its rows
/// (the columns of compare.csv) and the reference of each quantity.
#[pyfunction]
#[pyo3(signature = (scene, sets, meshes, repeat, references, time_limit))]
pub fn compare<'py>(
    py: Python<'py>,
    scene: PathBuf,
    sets: Vec<String>,
    meshes: Vec<PathBuf>,
    repeat: usize,
    references: Vec<String>,
    time_limit: f64,
) -> PyResult<(Rows<'py>, BTreeMap<String, ReferenceRow<'py>>)> {
    let args =
        contact2d::compare::CompareArgs { scene, meshes, repeat, references, sets, out: PathBuf::new(), time_limit };
    let comparison = py.detach(|| contact2d::compare::compare(&args, &mut |_, _, _| {})).map_err(compare_error)?;
    let rows = comparison
        .rows
        .iter()
        .map(|r| {
            let d = PyDict::new(py);
            d.set_item("algorithm", r.algorithm)?;
            d.set_item("pairing", r.pairing)?;
            d.set_item("level", r.level)?;
            d.set_item("mesh", &r.mesh)?;
            d.set_item("pairs", r.pairs)?;
            d.set_item("status", &r.status)?;
            d.set_item("reason", r.reason.as_deref().unwrap_or(""))?;
            d.set_item("time_s", r.time)?;
            d.set_item("solve_time_s", r.solve_time)?;
            d.set_item("iterations", r.iterations)?;
            d.set_item("max_penetration", r.kkt[0])?;
            d.set_item("max_complementarity", r.kkt[1])?;
            d.set_item("max_cone_violation", r.kkt[2])?;
            // compare.csv's quantity columns: those with a reference, each value and its error
            // (`error_q`, or on one mesh `difference_q`).
            for (q, reference) in &comparison.references {
                d.set_item(q, r.values.get(q).copied())?;
                d.set_item(contact2d::compare::deviation_column(q, reference), r.errors.get(q).copied())?;
            }
            Ok(d)
        })
        .collect::<PyResult<Vec<_>>>()?;
    let references = comparison
        .references
        .iter()
        .map(|(q, r)| {
            let d = PyDict::new(py);
            d.set_item("quantity", &r.quantity)?;
            d.set_item("kind", r.kind.key())?;
            d.set_item("from", &r.from)?;
            d.set_item("value", r.value)?;
            d.set_item("how", &r.how)?;
            d.set_item("deviation", r.deviation.key())?;
            Ok((q.clone(), d))
        })
        .collect::<PyResult<_>>()?;
    Ok((rows, references))
}

fn compare_error(e: contact2d::compare::CompareError) -> PyErr {
    use contact2d::compare::CompareError as E;
    match e {
        E::Scene(s) => scene_error(s),
        E::Mesh { .. } => MeshError::new_err(e.to_string()),
        E::Flag { .. } => PyValueError::new_err(e.to_string()),
        other => PyOSError::new_err(other.to_string()),
    }
}

/// Runs the verification gallery's `cases` (all when empty) at `level` ("fast" or "full") from
/// the repository root `root`, as `contact2d verify` does; returns one dict per check and per
/// measurement, and the cases' notes.
#[pyfunction]
#[pyo3(signature = (cases, level, root))]
pub fn verify<'py>(py: Python<'py>, cases: Vec<String>, level: &str, root: PathBuf) -> PyResult<(Rows<'py>, Notes)> {
    use contact2d::verify::{CASES, Level, Tolerance};
    let level = match level {
        "fast" => Level::Fast,
        "full" => Level::Full,
        other => return Err(PyValueError::new_err(format!("level: expected \"fast\" or \"full\", not {other:?}"))),
    };
    let names: Vec<String> = if cases.is_empty() { CASES.iter().map(|c| c.to_string()).collect() } else { cases };
    let reports = py
        .detach(|| names.iter().map(|n| contact2d::verify::run_case(n, &root, level)).collect::<Result<Vec<_>, _>>())
        .map_err(verify_error)?;
    let mut rows = vec![];
    let mut notes = vec![];
    for r in &reports {
        for c in &r.checks {
            let d = PyDict::new(py);
            let (kind, tolerance) = match c.tolerance {
                Tolerance::Relative(t) => ("relative", t),
                Tolerance::Absolute(t) => ("absolute", t),
            };
            d.set_item("case", &r.name)?;
            d.set_item("quantity", &c.quantity)?;
            d.set_item("mesh", &c.mesh)?;
            d.set_item("measured", c.measured)?;
            d.set_item("reference", c.reference)?;
            d.set_item("error", c.error())?;
            d.set_item("tolerance", tolerance)?;
            d.set_item("tolerance_kind", kind)?;
            d.set_item("passed", c.passed())?;
            d.set_item("source", &r.source)?;
            rows.push(d);
        }
        for m in &r.measurements {
            let d = PyDict::new(py);
            d.set_item("case", &r.name)?;
            d.set_item("quantity", &m.quantity)?;
            d.set_item("mesh", &m.mesh)?;
            d.set_item("measured", m.value)?;
            d.set_item("source", &r.source)?;
            rows.push(d);
        }
        notes.extend(r.notes.iter().map(|n| (r.name.clone(), n.clone())));
    }
    Ok((rows, notes))
}

fn verify_error(e: contact2d::verify::VerifyError) -> PyErr {
    use contact2d::verify::VerifyError as E;
    match e {
        E::Scene(s) => scene_error(s),
        E::Generic(g) => generic_error(g),
        E::Contact(c) => ContactError::new_err(c.to_string()),
        other => Contact2dError::new_err(other.to_string()),
    }
}

//! The Python module `contact2d._core`: the scene (TOML text plus `--set` overrides, re-loaded
//! through the facade's parser), one solve through the CLI's pipeline with the GIL released, and
//! the solved outcome (the JSON summary exactly as `contact2d run --json` prints it, the mesh and
//! the displacement of every step as numpy arrays, the CLI's output files). The typed,
//! pandas-facing API is the pure-Python package `contact2d` around it.

use pyo3::prelude::*;

mod convert;
mod errors;
mod outcome;
mod scene;
mod studies;

/// The extension module.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("Contact2dError", py.get_type::<errors::Contact2dError>())?;
    m.add("SceneError", py.get_type::<errors::SceneError>())?;
    m.add("MeshError", py.get_type::<errors::MeshError>())?;
    m.add("ContactError", py.get_type::<errors::ContactError>())?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<outcome::Outcome>()?;
    m.add_function(wrap_pyfunction!(outcome::solve, m)?)?;
    m.add_function(wrap_pyfunction!(studies::compare, m)?)?;
    m.add_function(wrap_pyfunction!(studies::verify, m)?)?;
    Ok(())
}

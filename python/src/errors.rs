//! The exceptions: one base class and one per stage, each carrying the CLI's message.

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(contact2d, Contact2dError, PyException, "Base class of contact2d's errors.");
create_exception!(
    contact2d,
    SceneError,
    Contact2dError,
    "A scene that cannot be read, parsed or checked, or an override (`--set` path) that does not apply."
);
create_exception!(contact2d, MeshError, Contact2dError, "A mesh file that cannot be read.");
create_exception!(
    contact2d,
    ContactError,
    Contact2dError,
    "A problem that cannot be set up or solved (not a non-converged solve, which is a status)."
);

/// A scene error as a Python exception.
pub fn scene_error(e: contact2d::scene::SceneError) -> PyErr {
    SceneError::new_err(e.to_string())
}

/// A generic run's error as the Python exception of its stage.
pub fn generic_error(e: contact2d::generic::GenericError) -> PyErr {
    use contact2d::generic::GenericError as E;
    match e {
        E::Scene(s) => scene_error(s),
        E::Mesh { .. } => MeshError::new_err(e.to_string()),
        other => ContactError::new_err(other.to_string()),
    }
}

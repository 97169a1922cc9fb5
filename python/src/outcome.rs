//! `solve`: one run through the CLI's pipeline (`contact2d run`), the GIL released while it
//! solves; `Outcome`: what it returns — the JSON summary as the CLI prints it, numpy arrays of the
//! mesh and the displacements, and the CLI's output files.

use std::path::PathBuf;
use std::sync::Mutex;

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::exceptions::{PyIndexError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use crate::errors::{ContactError, generic_error, scene_error};
use crate::scene::Scene;

/// What the arrays are read from: a solved run of either kind.
trait Solved {
    /// The mesh of the first solved step.
    fn mesh(&self) -> &contact2d::mesh::Mesh;
    /// The model of solved step `k` (the paper's case builds one per step).
    fn model(&self, k: usize) -> Option<&contact2d::fem::Model>;
    /// Each solved step's displacement vector (DOF 2·node + component).
    fn displacements(&self) -> Vec<&[f64]>;
}

impl Solved for contact2d::scene::Outcome {
    fn mesh(&self) -> &contact2d::mesh::Mesh {
        match self {
            Self::Generic(o) => &o.built.problem.model.mesh,
            Self::Preset(o) => o.steps().first().map_or(&EMPTY_MESH, |(model, _)| &model.mesh),
        }
    }

    fn model(&self, k: usize) -> Option<&contact2d::fem::Model> {
        match self {
            Self::Generic(o) => o.history.steps.get(k).map(|_| &o.built.problem.model),
            Self::Preset(o) => o.steps().get(k).map(|(model, _)| *model),
        }
    }

    fn displacements(&self) -> Vec<&[f64]> {
        match self {
            Self::Generic(o) => o.history.steps.iter().map(|s| s.solution.displacement.as_slice()).collect(),
            Self::Preset(o) => o.steps().into_iter().map(|(_, s)| s.displacement.as_slice()).collect(),
        }
    }
}

static EMPTY_MESH: contact2d::mesh::Mesh =
    contact2d::mesh::Mesh { points: vec![], node_tags: vec![], blocks: vec![], groups: vec![] };

/// A solved scene (what `contact2d.solve` wraps in its `Result`).
#[pyclass(module = "contact2d._core", frozen)]
#[derive(Debug)]
pub struct Outcome {
    json: String,
    solved: Mutex<contact2d::scene::Outcome>,
}

/// Solves `scene` as `contact2d run SCENE --json` does and returns its outcome; the GIL is
/// released while solving, so threads solve concurrently. `profiles` is "last" (default) or
/// "all" (the CLI's `--profiles`). A non-converged solve is a status in the summary, not an
/// exception; SceneError, MeshError and ContactError carry the CLI's messages. `threads` (≥ 1)
/// runs the solve on a thread pool of that size (assembly, ordering and stress recovery are
/// parallel); `None` uses the global pool (one thread per core). `about` = `(x, y)` is the
/// centre the moments are taken about (the CLI's `--about x,y`; `None`: the origin).
#[pyfunction]
#[pyo3(signature = (scene, profiles = "last", threads = None, about = None))]
pub fn solve(
    py: Python<'_>,
    scene: &Scene,
    profiles: &str,
    threads: Option<usize>,
    about: Option<(f64, f64)>,
) -> PyResult<Outcome> {
    let every_profile = match profiles {
        "last" => false,
        "all" => true,
        other => return Err(PyValueError::new_err(format!("profiles: expected \"last\" or \"all\", not {other:?}"))),
    };
    let pool = match threads {
        None => None,
        Some(0) => return Err(PyValueError::new_err("threads: expected a number of threads >= 1, not 0")),
        Some(n) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| PyRuntimeError::new_err(format!("threads: {e}")))?,
        ),
    };
    if let Some((x, y)) = about
        && !(x.is_finite() && y.is_finite())
    {
        return Err(PyValueError::new_err(format!("about: expected two finite numbers (x, y), not ({x}, {y})")));
    }
    let mut loaded = scene.parse().map_err(scene_error)?;
    if let Some((x, y)) = about {
        loaded.set_moment_centre([x, y]);
    }
    py.detach(move || match pool {
        Some(pool) => pool.install(|| run(loaded, every_profile)),
        None => run(loaded, every_profile),
    })
}

/// The run of [`solve`], without the GIL: the CLI's (`contact2d run`), every step kept.
fn run(mut scene: contact2d::scene::Scene, every_profile: bool) -> PyResult<Outcome> {
    scene.set_every_profile(every_profile);
    scene.check_mesh_file().map_err(scene_error)?;
    let outcome = scene.solve(None, &mut contact2d::generic::Silent).map_err(generic_error)?;
    let json = serde_json::to_string_pretty(outcome.report()).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    Ok(Outcome { json, solved: Mutex::new(outcome) })
}

impl Outcome {
    fn with<T>(&self, f: impl FnOnce(&contact2d::scene::Outcome) -> T) -> PyResult<T> {
        let solved = self.solved.lock().map_err(|_| PyRuntimeError::new_err("outcome lock poisoned"))?;
        Ok(f(&solved))
    }
}

#[pymethods]
impl Outcome {
    /// The JSON summary, the exact text `contact2d run SCENE --json` prints.
    #[getter]
    fn json_text(&self) -> &str {
        &self.json
    }

    /// The number of solved steps whose displacement is kept.
    #[getter]
    fn n_steps(&self) -> PyResult<usize> {
        self.with(|s| s.displacements().len())
    }

    /// The displacement of solved step `step` (negative counts from the end), an
    /// (n_nodes, 2) float array of (u1, u2) per mesh node.
    #[pyo3(signature = (step = -1))]
    fn displacement<'py>(&self, py: Python<'py>, step: isize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let (u, n) = self.with(|s| {
            let all = s.displacements();
            let n = s.mesh().num_nodes();
            let k = if step < 0 { all.len() as isize + step } else { step };
            (usize::try_from(k).ok().and_then(|k| all.get(k)).map(|u| u.to_vec()), n)
        })?;
        let u = u.ok_or_else(|| PyIndexError::new_err(format!("step {step}: no such solved step")))?;
        let array = Array2::from_shape_vec((n, 2), u).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(array.into_pyarray(py))
    }

    /// The nodal stresses of solved step `step` (negative counts from the end), an (n_nodes, 4)
    /// float array of (σ11, σ22, σ12, σ33) per mesh node: Gauss-point stresses extrapolated to
    /// the nodes and averaged over each body's cells, as the VTU files' `stress`; σ33 is the
    /// out-of-plane stress (0 in plane stress). A node in no body is NaN; a node of two bodies
    /// holds the later body's value, as in the VTU files.
    #[pyo3(signature = (step = -1))]
    fn stress<'py>(&self, py: Python<'py>, step: isize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let values = py.detach(|| {
            self.with(|s| {
                let all = s.displacements();
                let k = if step < 0 { all.len() as isize + step } else { step };
                let Some((k, u)) = usize::try_from(k).ok().and_then(|k| all.get(k).map(|u| (k, *u))) else {
                    return Err(PyIndexError::new_err(format!("step {step}: no such solved step")));
                };
                let model = s.model(k).ok_or_else(|| PyIndexError::new_err(format!("step {step}: no model")))?;
                let n = model.mesh.num_nodes();
                let mut out = vec![f64::NAN; 4 * n];
                for b in 0..model.bodies.len() {
                    // σ33 in the plane, σθθ for a body of revolution.
                    let nodal = contact2d::fem::nodal_stress_states(
                        model,
                        contact2d::fem::BodyId(b),
                        u,
                        contact2d::fem::StressRecovery::Extrapolated,
                    )
                    .map_err(|e| ContactError::new_err(e.to_string()))?;
                    for (i, s) in nodal.iter().enumerate() {
                        if let Some(s) = s {
                            out[4 * i..4 * i + 4].copy_from_slice(s);
                        }
                    }
                }
                Ok((n, out))
            })?
        });
        let (n, values) = values?;
        let array = Array2::from_shape_vec((n, 4), values).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(array.into_pyarray(py))
    }

    /// The mesh nodes' coordinates, an (n_nodes, 2) float array.
    fn points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let points = self.with(|s| s.mesh().points.iter().flatten().copied().collect::<Vec<f64>>())?;
        let n = points.len() / 2;
        let array = Array2::from_shape_vec((n, 2), points).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
        Ok(array.into_pyarray(py))
    }

    /// The cell blocks in file order as (meshio cell type, (n_cells, nodes per cell) int64 array
    /// of node indices from 0, physical tags).
    #[allow(clippy::type_complexity)]
    fn cells<'py>(&self, py: Python<'py>) -> PyResult<Vec<(String, Bound<'py, PyArray2<i64>>, Vec<i32>)>> {
        let blocks = self.with(|s| {
            s.mesh()
                .blocks
                .iter()
                .map(|b| {
                    let nodes: Vec<i64> = b.nodes.iter().map(|n| n.0 as i64).collect();
                    (b.kind.name().to_string(), b.kind.nodes_per_cell(), nodes, b.physical_tags.clone())
                })
                .collect::<Vec<_>>()
        })?;
        blocks
            .into_iter()
            .map(|(kind, per, nodes, tags)| {
                let rows = nodes.len() / per.max(1);
                let array =
                    Array2::from_shape_vec((rows, per), nodes).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
                Ok((kind, array.into_pyarray(py), tags))
            })
            .collect()
    }

    /// The named physical groups as (name, dimension, tag).
    fn groups(&self) -> PyResult<Vec<(String, usize, i32)>> {
        self.with(|s| s.mesh().groups.iter().map(|g| (g.name.clone(), g.dim, g.tag)).collect())
    }

    /// Writes the CLI's outputs (`contact2d run --out DIR`: summary.json, figures, CSV, VTU)
    /// into `out_dir` and returns the paths written. Raises OSError naming the file at fault.
    fn write(&self, py: Python<'_>, out_dir: PathBuf) -> PyResult<Vec<PathBuf>> {
        py.detach(|| {
            let solved = self.solved.lock().map_err(|_| PyRuntimeError::new_err("outcome lock poisoned"))?;
            let folder = contact2d::output::OutputDir::prepare(&out_dir, Some(contact2d::output::SUMMARY_FILE))
                .map_err(|e| PyOSError::new_err(e.to_string()))?;
            solved.write_outputs_into(folder).map_err(|e| PyOSError::new_err(e.to_string()))
        })
    }
}

//! VTK XML unstructured grids (`.vtu`) of solved steps and their ParaView collection (`.pvd`).
//!
//! ```text
//! points      every mesh node (x1, x2, 0)
//! cells       the cells of every body; Quad9 → VTK_BIQUADRATIC_QUAD (28), Quad8 → VTK_QUADRATIC_QUAD
//!             (23), Quad4 → VTK_QUAD (9), Tri6 → VTK_QUADRATIC_TRIANGLE (22), Tri3 → VTK_TRIANGLE (5)
//! point data  displacement (u1, u2, 0); stress (3 × 3, nodal recovered: Gauss points extrapolated,
//!             averaged per body; σ33 from the plane condition); von_mises; on contour nodes with a
//!             pair contact_p, contact_q (see `profiles`) and contact_state (0 free, 1 stick,
//!             2 slip+, 3 slip−); NaN / −1 elsewhere
//! cell data   body (0 plate, 1 insert: the model's body index)
//! ```
//! Node order: Gmsh's and VTK's agree for all five kinds — corners counter-clockwise, then the
//! mid-side nodes of edges 0-1, 1-2, 2-3 (2-0), then the centre (Gmsh manual §9.2 "Node ordering";
//! VTK file formats, figure "Quadratic, isoparametric cells"), so connectivity is copied as is.

use std::fmt::Write as _;
use std::path::Path;

use contact2d_element::ElementType;
use contact2d_fem::{BodyId, StressRecovery, nodal_stress_states};
use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataSet, UnstructuredGridPiece, Version, VertexNumbers, Vtk,
};

use super::OutputError;
use super::step_view::StepView;

/// The VTK cell type of an element type.
///
/// # Errors
/// [`OutputError::MissingData`] for an element type without a VTK counterpart here.
pub fn vtk_cell_type(element: ElementType, path: &Path) -> Result<CellType, OutputError> {
    Ok(match element {
        ElementType::Tri3 => CellType::Triangle,
        ElementType::Tri6 => CellType::QuadraticTriangle,
        ElementType::Quad4 => CellType::Quad,
        ElementType::Quad8 => CellType::QuadraticQuad,
        ElementType::Quad9 => CellType::BiquadraticQuad,
        other => {
            return Err(OutputError::MissingData {
                path: path.to_path_buf(),
                reason: format!("no VTK cell type for {other:?}"),
            });
        }
    })
}

/// Writes one solved step with its contour profiles as a `.vtu` file.
///
/// # Errors
/// [`OutputError::Fem`] if stresses cannot be recovered, [`OutputError::Serialize`] if vtkio fails.
pub fn write_step_vtu(path: &Path, step: &StepView) -> Result<(), OutputError> {
    let model = &step.problem.model;
    let mesh = &model.mesh;
    let n = mesh.num_nodes();
    let u = &step.solution.displacement;
    if u.len() != 2 * n {
        return Err(OutputError::MissingData {
            path: path.to_path_buf(),
            reason: format!("{} displacement values for {n} nodes", u.len()),
        });
    }
    let points: Vec<f64> = mesh.points.iter().flat_map(|p| [p[0], p[1], 0.0]).collect();
    let displacement: Vec<f64> = (0..n).flat_map(|i| [u[2 * i], u[2 * i + 1], 0.0]).collect();

    let mut stress = vec![0.0; 9 * n];
    let mut von_mises = vec![0.0; n];
    let (mut connectivity, mut offsets, mut types, mut body_ids) = (vec![], vec![], vec![], vec![]);
    for (b, body) in model.bodies.iter().enumerate() {
        // The whole state: σ33 in the plane, σθθ for a body of revolution (its third axis).
        let nodal = nodal_stress_states(model, BodyId(b), u, StressRecovery::Extrapolated)?;
        for (i, s) in nodal.iter().enumerate() {
            if let Some(s) = s {
                stress[9 * i..9 * i + 9].copy_from_slice(&[s[0], s[2], 0.0, s[2], s[1], 0.0, 0.0, 0.0, s[3]]);
                von_mises[i] = contact2d_element::von_mises(s);
            }
        }
        for c in 0..body.num_cells() {
            connectivity.extend(body.cell_nodes(c).iter().map(|v| v.0 as u64));
            offsets.push(connectivity.len() as u64);
            types.push(vtk_cell_type(body.elements[c], path)?);
            body_ids.push(b as i32);
        }
    }

    let mut pressure = vec![f64::NAN; n];
    let mut shear = vec![f64::NAN; n];
    let mut state = vec![-1i32; n];
    for (i, c) in step.node_contact.iter().enumerate().take(n) {
        if let Some(c) = c {
            pressure[i] = c.pressure;
            shear[i] = c.shear;
            state[i] = c.state;
        }
    }

    let vtk = Vtk {
        version: Version::new_xml(1, 0),
        title: "contact2d step".to_string(),
        byte_order: ByteOrder::LittleEndian,
        file_path: None,
        data: DataSet::inline(UnstructuredGridPiece {
            points: points.into(),
            cells: Cells { cell_verts: VertexNumbers::XML { connectivity, offsets }, types },
            data: Attributes {
                point: vec![
                    Attribute::vectors("displacement").with_data(displacement),
                    Attribute::tensors("stress").with_data(stress),
                    Attribute::scalars("von_mises", 1).with_data(von_mises),
                    Attribute::scalars("contact_p", 1).with_data(pressure),
                    Attribute::scalars("contact_q", 1).with_data(shear),
                    Attribute::scalars("contact_state", 1).with_data(state),
                ],
                cell: vec![Attribute::scalars("body", 1).with_data(body_ids)],
            },
        }),
    };
    // Serialised in memory, then written: a write error (a full disk) is then reported as the
    // operating system's error, not as a formatting failure inside the XML writer.
    let mut bytes = Vec::new();
    vtk.write_xml(&mut bytes)
        .map_err(|e| OutputError::Serialize { path: path.to_path_buf(), reason: e.to_string() })?;
    std::fs::write(path, bytes).map_err(|e| OutputError::io(path, e))
}

/// Writes a ParaView collection listing `(time, file name)` entries (file names relative to the
/// collection's directory); the time is the load w of each step.
///
/// # Errors
/// [`OutputError::Io`] if the file cannot be written.
pub fn write_pvd(path: &Path, entries: &[(f64, String)]) -> Result<(), OutputError> {
    let mut text = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n",
    );
    for (time, file) in entries {
        let _ = writeln!(text, "    <DataSet timestep=\"{time:?}\" group=\"\" part=\"0\" file=\"{file}\"/>");
    }
    text.push_str("  </Collection>\n</VTKFile>\n");
    std::fs::write(path, text).map_err(|e| OutputError::io(path, e))
}

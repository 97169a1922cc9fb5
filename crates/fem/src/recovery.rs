//! Stress recovery: nodal stresses and stresses along a boundary curve.
//!
//! Two recoveries, because they differ measurably where stresses are steep (the paper's σ* at
//! a contact end):
//!
//! ```text
//! Extrapolated: σ at the Gauss points of each cell, extrapolated to its nodes (σ_n = E σ_g, see
//!               the element crate), then averaged over the body's cells sharing the node.
//! Direct:       σ = D B(ξ_a) u_e evaluated at the node's own reference point ξ_a in each cell
//!               sharing it, averaged over those cells.
//! ```
//!
//! Averaging is per body: a node is never averaged across a material interface. `D B` is the
//! body's formulation: with B-bar, `σ = D B̄ u` (the projected dilatation, as in the stiffness).
//!
//! The out-of-plane stress ([`nodal_stress_states`]) follows from the recovered in-plane stress
//! in the plane (`σ33 = 0` or `ν (σ11 + σ22)`); a body of revolution's σθθ needs the hoop strain
//! and is recovered like the in-plane components.

use contact2d_element::{ElementType, gauss_to_node_extrapolation, stress_state_at};
use contact2d_mesh::{Contour, NodeId};
use nalgebra::DMatrix;

use crate::error::FemError;
use crate::model::{BodyId, Model};

/// How nodal stresses are obtained from the displacement field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum StressRecovery {
    /// Gauss-point stresses extrapolated to the nodes, averaged per body.
    #[default]
    Extrapolated,
    /// Stresses evaluated at the nodes from each adjacent cell, averaged per body.
    Direct,
}

/// Nodal stresses `[σ11, σ22, σ12]` of one body, indexed by node (`None` outside the body).
///
/// # Errors
/// Element failures (not expected once the body was validated).
pub fn nodal_stresses(
    model: &Model,
    body: BodyId,
    u: &[f64],
    recovery: StressRecovery,
) -> Result<Vec<Option<[f64; 3]>>, FemError> {
    let states = nodal_stress_states_of_cells(model, body, u, recovery, |_| true)?;
    Ok(states.into_iter().map(|s| s.map(|[s11, s22, s12, _]| [s11, s22, s12])).collect())
}

/// Nodal stress states `[σ11, σ22, σ12, σ_out]` of one body, indexed by node (`None` outside the
/// body): the in-plane stresses of [`nodal_stresses`] and the out-of-plane stress σ33 (plane) or
/// σθθ (a body of revolution), see the module docs.
///
/// # Errors
/// Element failures (not expected once the body was validated).
pub fn nodal_stress_states(
    model: &Model,
    body: BodyId,
    u: &[f64],
    recovery: StressRecovery,
) -> Result<Vec<Option<[f64; 4]>>, FemError> {
    nodal_stress_states_of_cells(model, body, u, recovery, |_| true)
}

/// [`nodal_stress_states`] from the cells `i` of `body` where `keep(i)`: at a node all of whose
/// cells are kept, the same values bit for bit (the same cells, summed in the same order).
fn nodal_stress_states_of_cells(
    model: &Model,
    body: BodyId,
    u: &[f64],
    recovery: StressRecovery,
    keep: impl Fn(usize) -> bool,
) -> Result<Vec<Option<[f64; 4]>>, FemError> {
    let b = &model.bodies[body.0];
    let state = |element, coords: &[[f64; 2]], ue: &[f64], xi: &[f64; 2]| {
        stress_state_at(element, coords, &b.material, &b.kinematics, ue, *xi, b.formulation)
    };
    // [σ11, σ22, σ12, σ_out, cells]
    let mut sum = vec![[0.0; 5]; model.mesh.num_nodes()];
    // The Gauss-to-node matrix of each element type met (it depends on the type alone).
    let mut extrapolation: Vec<(ElementType, DMatrix<f64>)> = Vec::new();
    for i in (0..b.num_cells()).filter(|&i| keep(i)) {
        let element = b.elements[i];
        let coords = b.cell_coords(&model.mesh, i);
        let ue: Vec<f64> = b.cell_dofs(i).map(|d| u[d.0]).collect();
        let err = |source| FemError::Element { body: b.name.clone(), cell: b.cell_tags[i], source };
        let nodal: Vec<[f64; 4]> = match recovery {
            StressRecovery::Direct => element
                .reference_nodes()
                .iter()
                .map(|xi| state(element, &coords, &ue, xi))
                .collect::<Result<_, _>>()
                .map_err(err)?,
            StressRecovery::Extrapolated => {
                let rule = b.kinematics.stiffness_rule(element);
                let gauss: Vec<[f64; 4]> = rule
                    .points
                    .iter()
                    .map(|xi| state(element, &coords, &ue, xi))
                    .collect::<Result<_, _>>()
                    .map_err(err)?;
                let e = match extrapolation.iter().position(|(t, _)| *t == element) {
                    Some(k) => &extrapolation[k].1,
                    None => {
                        extrapolation.push((element, gauss_to_node_extrapolation(element, &rule).map_err(err)?));
                        &extrapolation[extrapolation.len() - 1].1
                    }
                };
                (0..element.num_nodes())
                    .map(|a| {
                        let mut s = [0.0; 4];
                        for (g, sg) in gauss.iter().enumerate() {
                            for k in 0..4 {
                                s[k] += e[(a, g)] * sg[k];
                            }
                        }
                        s
                    })
                    .collect()
            }
        };
        for (node, s) in b.cell_nodes(i).iter().zip(nodal) {
            let acc = &mut sum[node.0];
            for k in 0..4 {
                acc[k] += s[k];
            }
            acc[4] += 1.0;
        }
    }
    Ok(sum
        .into_iter()
        .map(|a| {
            (a[4] > 0.0).then(|| {
                let s = [a[0] / a[4], a[1] / a[4], a[2] / a[4]];
                // In the plane σ33 follows from the recovered in-plane stress itself.
                let out = b.kinematics.out_of_plane_stress(&b.material, &s).unwrap_or(a[3] / a[4]);
                [s[0], s[1], s[2], out]
            })
        })
        .collect())
}

/// Stress at one node of a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSample {
    /// The node.
    pub node: NodeId,
    /// Arc length along the contour.
    pub arc_length: f64,
    /// Position (undeformed).
    pub x: [f64; 2],
    /// Unit tangent of the contour.
    pub tangent: [f64; 2],
    /// Recovered stress `[σ11, σ22, σ12]`.
    pub stress: [f64; 3],
}

impl CurveSample {
    /// Normal stress along the tangent: `σ_tt = tᵀ σ t` (the hoop stress on a circle).
    pub fn tangential_stress(&self) -> f64 {
        let [s11, s22, s12] = self.stress;
        let [t1, t2] = self.tangent;
        s11 * t1 * t1 + 2.0 * s12 * t1 * t2 + s22 * t2 * t2
    }
}

/// Stresses of `body` at the nodes of `contour`, as functions of arc length.
///
/// # Errors
/// A contour node outside the body, or element failures.
pub fn stresses_along_curve(
    model: &Model,
    body: BodyId,
    contour: &Contour,
    u: &[f64],
    recovery: StressRecovery,
) -> Result<Vec<CurveSample>, FemError> {
    // Only the cells that touch the curve: its nodes' averages are the whole body's.
    let mut on_curve = vec![false; model.mesh.num_nodes()];
    contour.nodes.iter().for_each(|n| on_curve[n.0] = true);
    let b = &model.bodies[body.0];
    let touches = |i: usize| b.cell_nodes(i).iter().any(|n| on_curve[n.0]);
    let nodal = nodal_stress_states_of_cells(model, body, u, recovery, touches)?;
    contour
        .nodes
        .iter()
        .zip(&contour.arc_length)
        .zip(&contour.tangents)
        .map(|((n, s), t)| {
            let [s11, s22, s12, _] = nodal[n.0].ok_or_else(|| {
                FemError::InvalidInput(format!(
                    "curve \"{}\": node tag {} is not in body \"{}\"",
                    contour.name, model.mesh.node_tags[n.0], model.bodies[body.0].name
                ))
            })?;
            Ok(CurveSample {
                node: *n,
                arc_length: *s,
                x: model.mesh.points[n.0],
                tangent: *t,
                stress: [s11, s22, s12],
            })
        })
        .collect()
}

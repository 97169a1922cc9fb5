//! Shrink fit as bodies of revolution (Lamé): a solid shaft of radius b = 10 mm in a hub of outer
//! radius c = 20 mm, both 10 mm long with their ends held axially, E = 2e5 MPa, ν = 0.3, radial
//! interference δ = 0.01 mm given as a negative gap (`scenes/generic/shrink_fit_axisymmetric.toml`,
//! `kinematics = "axisymmetric"`).
//!
//! ```text
//! p = E δ / (b (1 + ν) [((1 − 2ν) b² + c²)/(c² − b²) + (1 − 2ν)]) = 82.418 MPa
//! normal force (over the circumference) N = p 2π b L,  hub bore hoop stress σθθ = p (c² + b²)/(c² − b²),
//! shaft: σ_rr = σθθ = −p everywhere
//! ```
//!
//! Source: thick-walled cylinders and shrink fits, Timoshenko & Goodier, *Theory of Elasticity*
//! §28–§30 (plane strain along the axis: the ends are held). Tolerance 0.5 % on each, as the plane
//! interference fit, checked at the extremes over the pairs, the bore nodes and the shaft nodes.

use std::path::Path;

use contact2d_fem::{StressRecovery, nodal_stress_states};

use super::{CaseReport, Check, Level, VerifyError, gallery_scene, scene_path};
use crate::generic::solve_generic;

const SCENE: &str = "scenes/generic/shrink_fit_axisymmetric.toml";

/// Runs the case (one mesh).
///
/// # Errors
/// A scene that cannot be read or solved, or stresses that cannot be recovered.
pub fn run(root: &Path, _level: Level) -> Result<CaseReport, VerifyError> {
    let (b, c, length, e, nu, delta) = (10.0f64, 20.0f64, 10.0f64, 2e5f64, 0.3f64, 0.01f64);
    let p = e * delta / (b * (1.0 + nu) * (((1.0 - 2.0 * nu) * b * b + c * c) / (c * c - b * b) + (1.0 - 2.0 * nu)));
    let hoop = p * (c * c + b * b) / (c * c - b * b);
    let out = solve_generic(&gallery_scene(&scene_path(root, SCENE), &[])?, &mut |_, _| {})?;
    let missing = |reason: String| VerifyError::Missing { case: "shrink_fit_axisymmetric".into(), reason };
    let fit = out.report.contacts.get("fit").ok_or_else(|| missing("no interface \"fit\"".into()))?;
    let profile = fit.profile.as_ref().ok_or_else(|| missing("no profile".into()))?;
    let model = &out.built.problem.model;
    let u = &out.history.steps.last().ok_or_else(|| missing("no step".into()))?.solution.displacement;
    let states = |name: &str| {
        let (body, _) = model.body(name).ok_or_else(|| missing(format!("no body {name}")))?;
        nodal_stress_states(model, body, u, StressRecovery::Extrapolated).map_err(|e| missing(e.to_string()))
    };
    let (hub, shaft) = (states("hub")?, states("shaft")?);
    let bore = model.mesh.group_nodes("hub_bore").map_err(|e| missing(e.to_string()))?;
    let hoops: Vec<f64> = bore.iter().filter_map(|n| hub[n.0].map(|s| s[3])).collect();
    let shaft_normal: Vec<f64> = shaft.iter().flatten().flat_map(|s| [-s[0], -s[3]]).collect();
    let check = |q: &str, values: &[f64], reference: f64| Check::worst_of(q, values, reference, 0.005);
    Ok(CaseReport {
        name: "shrink_fit_axisymmetric".into(),
        source: "Lamé thick-walled cylinders, shrink fits (Timoshenko & Goodier §28–§30)".into(),
        checks: vec![
            check("contact pressure p (MPa), worst pair", &profile.pressure, p),
            check(
                "normal force over the circumference (N)",
                &[fit.normal_force],
                p * 2.0 * std::f64::consts::PI * b * length,
            ),
            check("hub bore hoop stress σθθ (MPa), worst node", &hoops, hoop),
            check("shaft stress −σ_rr, −σθθ (MPa), worst node", &shaft_normal, p),
        ],
        ..CaseReport::default()
    })
}

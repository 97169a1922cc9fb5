//! Where every physical group the flagship uses must lie (spec §2, the upper half x2 ≥ 0), so
//! that a mesh with two group names swapped is refused instead of solved.
//!
//! ```text
//!   x2 = H  ┌──────────── top ─────────────────────┐
//!           │ plate (r ≥ R = 1)                     │
//!    left   │      hole_edge (r = 1)                │ right  (x1 = L2: u1 = w, u2 = 0)
//! (x1=−L1)  │    insert_edge (|x − (−ε,0)| = 1 − ε) │
//!           │    insert_inner (|x − (−ε,0)| = R2)   │
//!   x2 = 0  └ bottom_plate ┘ insert_symmetry └ bottom_plate ┘
//! ```
//!
//! `L1`, `L2` and `H` are read off the plate's own nodes (its bounding box), so any plate size
//! passes; what is checked is that each group sits where its boundary condition belongs. Every
//! node must be within `1e-6 · max(1, L1 + L2)` (the bundled meshes are exact to 1e-15). A group
//! absent from the mesh is not checked here: building the model reports it.

use contact2d_mesh::Mesh;

use crate::plate_insert::PlateInsertScene;
use crate::schema::SceneError;

impl PlateInsertScene {
    /// Checks that `mesh` has the geometry the scene's `eps` describes: the hole edge on the
    /// circle of radius 1 about the origin and the insert edge on the circle of radius 1 − ε
    /// about (−ε, 0), each node within 1e-6 (the bundled meshes are exact to 1e-15); then every
    /// other group where its boundary condition belongs
    /// ([`check_group_geometry`]). A missing group is left to the run,
    /// which reports it.
    ///
    /// # Errors
    /// [`SceneError::Value`] on `plate_insert.eps`, with the ε the mesh was made for;
    /// [`SceneError::Group`] naming a group out of place.
    pub fn check_mesh_geometry(&self, mesh: &contact2d_mesh::Mesh) -> Result<(), SceneError> {
        let eps = self.plate_insert.eps;
        let off_circle = |group: &str, centre: f64, radius: f64| {
            mesh.group_nodes(group).ok().and_then(|nodes| {
                nodes.iter().map(|v| mesh.points[v.0]).find(|x| ((x[0] - centre).hypot(x[1]) - radius).abs() > 1e-6)
            })
        };
        if let Some(x) = off_circle("hole_edge", 0.0, 1.0) {
            return Err(SceneError::Value {
                path: self.file.display().to_string(),
                key: "plate_insert.mesh".into(),
                reason: format!(
                    "the hole edge must be the circle of radius 1 about the origin; node ({}, {}) is not on it",
                    x[0], x[1]
                ),
            });
        }
        if off_circle("insert_edge", -eps, 1.0 - eps).is_some() {
            // The insert's rightmost point is at x1 = 1 − 2ε whatever ε (its leftmost at −1).
            let right = mesh
                .group_nodes("insert_edge")
                .map(|nodes| nodes.iter().map(|v| mesh.points[v.0][0]).fold(f64::NEG_INFINITY, f64::max))
                .unwrap_or(f64::NAN);
            return Err(SceneError::Value {
                path: self.file.display().to_string(),
                key: "plate_insert.eps".into(),
                reason: format!(
                    "{eps} does not match the mesh {}: its insert edge is not the circle of radius 1 − ε about \
                     (−ε, 0) (it reaches x1 = {right:.6}, which suggests eps = {:.6})",
                    self.mesh_path().display(),
                    (1.0 - right) / 2.0
                ),
            });
        }
        check_group_geometry(mesh, eps).map_err(|m| SceneError::Group {
            path: self.file.display().to_string(),
            mesh: self.mesh_path().display().to_string(),
            group: m.group.into(),
            reason: m.reason,
        })
    }
}

/// A group that is not where the flagship needs it.
#[derive(Debug, Clone, PartialEq)]
pub struct MisplacedGroup {
    /// The physical group's name.
    pub group: &'static str,
    /// Where it must lie, and the first node that does not.
    pub reason: String,
}

/// Checks the position of every group of the flagship mesh for clearance `eps` (module docs).
///
/// # Errors
/// The first group found out of place.
pub fn check_group_geometry(mesh: &Mesh, eps: f64) -> Result<(), MisplacedGroup> {
    // A mesh without the flagship's groups is not a flagship mesh: building the model names
    // the missing group, which says more than any position would.
    if REQUIRED.iter().any(|g| mesh.group(g).is_err()) {
        return Ok(());
    }
    let Some(plate) = points(mesh, "plate") else { return Ok(()) };
    let fold = |f: fn(&[f64; 2]) -> f64, init: f64, pick: fn(f64, f64) -> f64| plate.iter().map(f).fold(init, pick);
    let x_min = fold(|p| p[0], f64::INFINITY, f64::min);
    let x_max = fold(|p| p[0], f64::NEG_INFINITY, f64::max);
    let y_max = fold(|p| p[1], f64::NEG_INFINITY, f64::max);
    let tol = 1e-6 * (x_max - x_min).max(1.0);
    let centre = [-eps, 0.0];
    let radius = |p: &[f64; 2], c: [f64; 2]| (p[0] - c[0]).hypot(p[1] - c[1]);
    let outer = 1.0 - eps;
    type Rule<'a> = (&'static str, String, Box<dyn Fn(&[f64; 2]) -> bool + 'a>);
    let rules: Vec<Rule> = vec![
        (
            "plate",
            "outside the hole (r ≥ 1) in x2 ≥ 0".into(),
            Box::new(|p| radius(p, [0.0; 2]) >= 1.0 - tol && p[1] >= -tol),
        ),
        (
            "insert",
            format!("inside the insert's circle of radius {outer} about ({}, 0)", -eps),
            Box::new(|p| radius(p, centre) <= outer + tol && p[1] >= -tol),
        ),
        (
            "right",
            format!("on the pulled edge x1 = {x_max} (the plate's largest x1)"),
            Box::new(|p| (p[0] - x_max).abs() <= tol),
        ),
        (
            "left",
            format!("on the free edge x1 = {x_min} (the plate's smallest x1)"),
            Box::new(|p| (p[0] - x_min).abs() <= tol),
        ),
        (
            "top",
            format!("on the top edge x2 = {y_max} (the plate's largest x2)"),
            Box::new(|p| (p[1] - y_max).abs() <= tol),
        ),
        (
            "bottom_plate",
            "on the symmetry line x2 = 0 outside the hole (|x1| ≥ 1)".into(),
            Box::new(|p| p[1].abs() <= tol && radius(p, [0.0; 2]) >= 1.0 - tol),
        ),
        (
            "insert_symmetry",
            format!("on the symmetry line x2 = 0 within the insert (|x1 + {eps}| ≤ {outer})"),
            Box::new(|p| p[1].abs() <= tol && radius(p, centre) <= outer + tol),
        ),
    ];
    for (group, place, holds) in &rules {
        if let Some(nodes) = points(mesh, group)
            && let Some(p) = nodes.iter().find(|p| !holds(p))
        {
            return Err(misplaced(group, place, p));
        }
    }
    // The inner edge: one circle about the insert's centre, inside the insert.
    if let Some(nodes) = points(mesh, "insert_inner") {
        let r_in = nodes.first().map_or(0.0, |p| radius(p, centre));
        let place = format!("on one circle about ({}, 0) inside the insert (radius < {outer})", -eps);
        if let Some(p) = nodes.iter().find(|p| (radius(p, centre) - r_in).abs() > tol || r_in >= outer - tol) {
            return Err(misplaced("insert_inner", &place, p));
        }
    }
    Ok(())
}

/// The groups every flagship mesh has (the insert's own groups are absent for a rigid insert).
const REQUIRED: [&str; 6] = ["plate", "right", "top", "bottom_plate", "hole_edge", "insert_edge"];

/// The coordinates of the nodes of `group`, if the mesh has it.
fn points(mesh: &Mesh, group: &str) -> Option<Vec<[f64; 2]>> {
    let nodes = mesh.group_nodes(group).ok()?;
    Some(nodes.iter().filter_map(|v| mesh.points.get(v.0).copied()).collect())
}

fn misplaced(group: &'static str, place: &str, p: &[f64; 2]) -> MisplacedGroup {
    MisplacedGroup {
        group,
        reason: format!("must lie {place}, but node ({}, {}) does not (are two group names swapped?)", p[0], p[1]),
    }
}

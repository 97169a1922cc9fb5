//! Reference points (`[[point]]`) and their couplings to a group of nodes: the kernels of a
//! distributing (RBE3) coupling, and the points' fixes and loads as values and forces of single
//! nodes.
//!
//! ```text
//! weights w_i: tributary lengths of a 1D group's nodes (L/2 at each end of a Line2 cell; L/6,
//!              L/6, 2L/3 at the ends and middle of a Line3 cell), 1 on any other group
//! W = Σ w_i     c = Σ w_i x_i / W     r_i = x_i − c     J = Σ w_i |r_i|²     e3 × (a, b) = (−b, a)
//!
//! distributing, a force F and moment M at the point p:
//!     f_i = w_i F / W + w_i M_c e3 × r_i / J,     M_c = M + (p − c) × F
//!     (Σ f_i = F since Σ w_i r_i = 0;  Σ (x_i − p) × f_i = M_c + (c − p) × F = M)
//! the point's motion (the weighted least-squares rigid motion of the group's nodes):
//!     θ = Σ w_i r_i × u_i / J,     u_p = Σ w_i u_i / W + θ e3 × (p − c)
//!     (exact for a rigid motion u_i = a + θ0 e3 × (x_i − q): θ = θ0, u_p = a + θ0 e3 × (p − q))
//! kinematic, the point fixed (u_p, θ):   u_i = u_p + θ e3 × (x_i − p)   on every node of the group
//! a group turned rigidly:                u_i = (u1, u2) + θ e3 × (x_i − about)
//! the point's reaction:  R = Σ_i r_i,  M_R = Σ_i (x_i − p) × r_i   (the support reactions r_i on
//!                        the group's nodes, or on the point's node)
//! ```
//!
//! Angles in radians, counter-clockwise; moments counter-clockwise, per unit thickness where the
//! thickness is 1. A kinematic point that is loaded or not fixed in all of u1, u2 and rotation
//! would need its group's DOFs tied to three new unknowns (a multi-point constraint), and a fix
//! on a distributing point a constraint on the weighted mean: neither is built, and the scene is
//! refused saying so.

use contact2d_contact::{NodeFixDescription, NodeLoadDescription};
use contact2d_fem::Component;
use contact2d_mesh::{CellKind, Mesh, NodeId, line_cell_length};
use serde::Serialize;

use super::scene::{CouplingKey, FixEntry, GenericScene, LoadEntry, PointEntry};
use crate::schema::SceneError;

/// `a × b` of two plane vectors (the e3 component).
fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// `θ e3 × r` (the displacement of a small rotation θ at arm r).
pub fn turn(theta: f64, r: [f64; 2]) -> [f64; 2] {
    [-theta * r[1], theta * r[0]]
}

/// A group of nodes with the weights of a coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct WeightedNodes {
    /// The nodes.
    pub nodes: Vec<NodeId>,
    /// Their coordinates.
    pub points: Vec<[f64; 2]>,
    /// Their weights w_i (see the module docs).
    pub weights: Vec<f64>,
}

impl WeightedNodes {
    /// The weighted nodes of the physical group `group`: tributary lengths on a 1D group, 1 on
    /// any other.
    ///
    /// # Errors
    /// The reason, for a group the mesh does not have or one without nodes.
    pub fn of_group(mesh: &Mesh, group: &str) -> Result<WeightedNodes, String> {
        let g = mesh.group(group).map_err(|_| format!("\"{group}\" is no physical group of the mesh"))?;
        let nodes = mesh.group_nodes(group).map_err(|e| e.to_string())?;
        if nodes.is_empty() {
            return Err(format!("group \"{group}\" has no nodes"));
        }
        let mut weights = vec![if g.dim == 1 { 0.0 } else { 1.0 }; nodes.len()];
        if g.dim == 1 {
            let at = |n: NodeId| nodes.binary_search(&n).ok();
            for block in mesh.blocks_in_group(group).map_err(|e| e.to_string())? {
                for cell in block.cells() {
                    let points: Vec<[f64; 2]> = cell.iter().map(|n| mesh.points[n.0]).collect();
                    let length = line_cell_length(block.kind, &points);
                    let shares: &[f64] = match block.kind {
                        CellKind::Line3 => &[1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0],
                        _ => &[0.5, 0.5],
                    };
                    for (n, share) in cell.iter().zip(shares) {
                        if let Some(i) = at(*n) {
                            weights[i] += share * length;
                        }
                    }
                }
            }
        }
        let points = nodes.iter().map(|n| mesh.points[n.0]).collect();
        Ok(WeightedNodes { nodes, points, weights })
    }

    /// `(W, c, J)`: the total weight, the weighted centroid and the polar moment `Σ w |x − c|²`.
    pub fn centroid(&self) -> (f64, [f64; 2], f64) {
        let total: f64 = self.weights.iter().sum();
        let mut c = [0.0; 2];
        for (x, w) in self.points.iter().zip(&self.weights) {
            c = [c[0] + w * x[0] / total, c[1] + w * x[1] / total];
        }
        let polar =
            self.points.iter().zip(&self.weights).map(|(x, w)| w * ((x[0] - c[0]).powi(2) + (x[1] - c[1]).powi(2)));
        (total, c, polar.sum())
    }

    /// The nodal forces of a distributing coupling carrying `force` and `moment` at `at`
    /// (`f_i` of the module docs): their resultant is `force`, their moment about `at` is
    /// `moment`.
    pub fn distribute(&self, at: [f64; 2], force: [f64; 2], moment: f64) -> Vec<[f64; 2]> {
        let (total, c, polar) = self.centroid();
        let about_c = moment + cross([at[0] - c[0], at[1] - c[1]], force);
        let spin = if polar > 0.0 { about_c / polar } else { 0.0 };
        self.points
            .iter()
            .zip(&self.weights)
            .map(|(x, w)| {
                let t = turn(spin, [x[0] - c[0], x[1] - c[1]]);
                [w * (force[0] / total + t[0]), w * (force[1] / total + t[1])]
            })
            .collect()
    }

    /// `(u_p, θ)`: the motion of the point `at` coupled to these nodes, from the nodal
    /// displacements `u` (global DOF order `2 n + c`; the module docs' weighted rigid fit).
    pub fn motion(&self, at: [f64; 2], u: &[f64]) -> ([f64; 2], f64) {
        let (total, c, polar) = self.centroid();
        let (mut mean, mut spin) = ([0.0; 2], 0.0);
        for ((n, x), w) in self.nodes.iter().zip(&self.points).zip(&self.weights) {
            let ui = [u.get(2 * n.0).copied().unwrap_or(0.0), u.get(2 * n.0 + 1).copied().unwrap_or(0.0)];
            mean = [mean[0] + w * ui[0] / total, mean[1] + w * ui[1] / total];
            spin += w * cross([x[0] - c[0], x[1] - c[1]], ui);
        }
        let theta = if polar > 0.0 { spin / polar } else { 0.0 };
        let t = turn(theta, [at[0] - c[0], at[1] - c[1]]);
        ([mean[0] + t[0], mean[1] + t[1]], theta)
    }
}

/// What a point is attached to.
#[derive(Debug, Clone, PartialEq)]
pub enum PointKind {
    /// A mesh node (no coupling): no rotation, no moment.
    Node(NodeId),
    /// A group through a coupling.
    Coupled {
        /// The group's weighted nodes.
        group: WeightedNodes,
        /// How.
        coupling: CouplingKey,
    },
}

/// A `[[point]]` resolved on the mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolvedPoint {
    /// Its name.
    pub name: String,
    /// Where it is.
    pub at: [f64; 2],
    /// What it is attached to.
    pub kind: PointKind,
}

/// A point's results at one step (`points.NAME`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointResult {
    /// `[u1, u2]` of the point (its node's, or the coupled group's `u_p`).
    pub displacement: [f64; 2],
    /// θ (radians, counter-clockwise) of a coupled point; none for a node.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation: Option<f64>,
    /// `[R1, R2]`: the support reactions on the group's nodes (or on the node), summed.
    pub reaction: [f64; 2],
    /// `Σ (x_i − p) × r_i` about the point of a coupled point; none for a node.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reaction_moment: Option<f64>,
}

impl ResolvedPoint {
    /// The point's results from the displacements `u` and the reactions at every DOF (global
    /// order, zero at free DOFs).
    pub fn result(&self, u: &[f64], reactions: &[f64]) -> PointResult {
        let at_dof =
            |v: &[f64], n: NodeId| [v.get(2 * n.0).copied().unwrap_or(0.0), v.get(2 * n.0 + 1).copied().unwrap_or(0.0)];
        match &self.kind {
            PointKind::Node(n) => PointResult {
                displacement: at_dof(u, *n),
                rotation: None,
                reaction: at_dof(reactions, *n),
                reaction_moment: None,
            },
            PointKind::Coupled { group, .. } => {
                let (displacement, theta) = group.motion(self.at, u);
                let (mut reaction, mut moment) = ([0.0; 2], 0.0);
                for (n, x) in group.nodes.iter().zip(&group.points) {
                    let r = at_dof(reactions, *n);
                    reaction = [reaction[0] + r[0], reaction[1] + r[1]];
                    moment += cross([x[0] - self.at[0], x[1] - self.at[1]], r);
                }
                PointResult { displacement, rotation: Some(theta), reaction, reaction_moment: Some(moment) }
            }
        }
    }
}

/// The values `u_i = t + θ e3 × (x_i − c)` of both components of every node of `group`, in
/// `pattern`.
fn rigid_values(group: &WeightedNodes, t: [f64; 2], theta: f64, c: [f64; 2], pattern: &str) -> Vec<NodeFixDescription> {
    let mut out = Vec::with_capacity(2 * group.nodes.len());
    for (n, x) in group.nodes.iter().zip(&group.points) {
        let r = turn(theta, [x[0] - c[0], x[1] - c[1]]);
        for (component, value) in [(Component::X, t[0] + r[0]), (Component::Y, t[1] + r[1])] {
            out.push(NodeFixDescription { node: *n, component, value, pattern: pattern.to_string() });
        }
    }
    out
}

/// The mesh node at `at` (within 1e-9 of the mesh's extent), or the distance to the nearest.
fn node_at(mesh: &Mesh, at: [f64; 2]) -> Result<NodeId, f64> {
    let extent = mesh.bounding_box().map_or(1.0, |[lo, hi]| (hi[0] - lo[0]).max(hi[1] - lo[1]));
    let (best, distance) = mesh
        .points
        .iter()
        .enumerate()
        .map(|(i, x)| (i, (x[0] - at[0]).hypot(x[1] - at[1])))
        .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    if distance <= 1e-9 * extent { Ok(NodeId(best)) } else { Err(distance) }
}

impl GenericScene {
    /// The scene's points resolved on `mesh`.
    ///
    /// # Errors
    /// [`SceneError::Value`] at `point.i.group` for a group the mesh lacks, one without nodes,
    /// or (coupled) one whose nodes all lie at one place; at `point.i.at` for a point without
    /// coupling that is no mesh node.
    pub fn resolve_points(&self, mesh: &Mesh) -> Result<Vec<ResolvedPoint>, SceneError> {
        let mut out = Vec::with_capacity(self.point.len());
        for (i, p) in self.point.iter().enumerate() {
            let kind = match (&p.group, p.coupling) {
                (Some(group), Some(coupling)) => {
                    let nodes =
                        WeightedNodes::of_group(mesh, group).map_err(|r| self.fail(&format!("point.{i}.group"), r))?;
                    if nodes.centroid().2 <= 0.0 {
                        return Err(self.fail(
                            &format!("point.{i}.group"),
                            format!(
                                "the nodes of \"{group}\" all lie at one place: a coupling needs nodes apart to carry a \
                                 moment and to turn"
                            ),
                        ));
                    }
                    PointKind::Coupled { group: nodes, coupling }
                }
                _ => PointKind::Node(node_at(mesh, p.at).map_err(|d| {
                    self.fail(
                        &format!("point.{i}.at"),
                        format!(
                            "point \"{}\" has no coupling, so it must be a mesh node; the nearest node is {d:e} away \
                             (give group and coupling to couple it to a group)",
                            p.name
                        ),
                    )
                })?),
            };
            out.push(ResolvedPoint { name: p.name.clone(), at: p.at, kind });
        }
        Ok(out)
    }

    /// The points' and the rotations' fixes as values of single nodes, and the points' loads as
    /// forces on single nodes (see the module docs).
    ///
    /// # Errors
    /// As [`GenericScene::resolve_points`]; an unknown group of a `[[fix]]` with `rotation`.
    pub fn point_conditions(
        &self,
        mesh: &Mesh,
    ) -> Result<(Vec<NodeFixDescription>, Vec<NodeLoadDescription>), SceneError> {
        let points = self.resolve_points(mesh)?;
        let find = |name: &str| points.iter().find(|p| p.name == name);
        // In the order of the [[fix]] entries, so that the patterns appear in the order
        // [`GenericScene::pattern_names`] gives them.
        let mut fixes = vec![];
        for (i, f) in self.fix.iter().enumerate() {
            let t = [f.u1.unwrap_or(0.0), f.u2.unwrap_or(0.0)];
            match (&f.group, &f.point, f.rotation) {
                (Some(group), _, Some(theta)) => {
                    let nodes =
                        WeightedNodes::of_group(mesh, group).map_err(|r| self.fail(&format!("fix.{i}.group"), r))?;
                    fixes.extend(rigid_values(&nodes, t, theta, f.about.unwrap_or([0.0; 2]), &f.pattern));
                }
                (None, Some(name), _) => match find(name).map(|p| (&p.kind, p.at)) {
                    Some((PointKind::Coupled { group, coupling: CouplingKey::Kinematic }, at)) => {
                        fixes.extend(rigid_values(group, t, f.rotation.unwrap_or(0.0), at, &f.pattern));
                    }
                    Some((PointKind::Node(n), _)) => {
                        for (component, value) in [(Component::X, f.u1), (Component::Y, f.u2)] {
                            if let Some(value) = value {
                                fixes.push(NodeFixDescription {
                                    node: *n,
                                    component,
                                    value,
                                    pattern: f.pattern.clone(),
                                });
                            }
                        }
                    }
                    // Refused by the validation.
                    _ => return Err(self.fail(&format!("fix.{i}.point"), format!("point \"{name}\" cannot be fixed"))),
                },
                _ => {}
            }
        }
        let mut loads = vec![];
        for (i, l) in self.load.iter().enumerate() {
            let Some(name) = &l.point else { continue };
            let (force, moment) = (l.force.unwrap_or([0.0; 2]), l.moment.unwrap_or(0.0));
            let mut push = |node: NodeId, force: [f64; 2]| {
                loads.push(NodeLoadDescription { node, force, pattern: l.pattern.clone() });
            };
            match find(name).map(|p| (&p.kind, p.at)) {
                Some((PointKind::Node(n), _)) => push(*n, force),
                Some((PointKind::Coupled { group, coupling: CouplingKey::Distributing }, at)) => {
                    for (n, f) in group.nodes.iter().zip(group.distribute(at, force, moment)) {
                        push(*n, f);
                    }
                }
                // Refused by the validation.
                _ => return Err(self.fail(&format!("load.{i}.point"), format!("point \"{name}\" cannot be loaded"))),
            }
        }
        Ok((fixes, loads))
    }
}

/// The checks of the points, fixes and loads that need no mesh (called by
/// [`GenericScene::validate`]).
impl GenericScene {
    /// The `[[point]]` called `name`, with its index.
    fn point_named(&self, name: &str) -> Option<(usize, &PointEntry)> {
        self.point.iter().enumerate().find(|(_, p)| p.name == name)
    }

    /// # Errors
    /// [`SceneError::Value`] naming the first `point.*`, `fix.*` or `load.*` key at fault.
    pub(super) fn validate_points(&self) -> Result<(), SceneError> {
        for (i, p) in self.point.iter().enumerate() {
            self.validate_point(i, p)?;
        }
        for (i, f) in self.fix.iter().enumerate() {
            self.validate_fix(i, f)?;
        }
        for (i, l) in self.load.iter().enumerate() {
            self.validate_load(i, l)?;
        }
        Ok(())
    }

    fn validate_point(&self, i: usize, p: &PointEntry) -> Result<(), SceneError> {
        let key = |k: &str| format!("point.{i}.{k}");
        if p.name.is_empty() {
            return Err(self.fail(&key("name"), "an empty name".into()));
        }
        if self.point[..i].iter().any(|q| q.name == p.name) {
            return Err(self.fail(&key("name"), format!("\"{}\" names two points", p.name)));
        }
        if !(p.at[0].is_finite() && p.at[1].is_finite()) {
            return Err(self.fail(&key("at"), format!("{:?} is not finite", p.at)));
        }
        match (&p.group, p.coupling) {
            (Some(g), None) => {
                return Err(self.fail(
                    &key("coupling"),
                    format!(
                        "point \"{}\" names group \"{g}\" but no coupling: give \"distributing\" or \"kinematic\"",
                        p.name
                    ),
                ));
            }
            (None, Some(_)) => {
                return Err(
                    self.fail(&key("group"), format!("point \"{}\": a coupling needs the group it couples", p.name))
                );
            }
            _ => {}
        }
        if let (Some(group), Some(CouplingKey::Kinematic)) = (&p.group, p.coupling) {
            if let Some(j) = self.fix.iter().position(|f| f.group.as_deref() == Some(group)) {
                return Err(self.fail(
                    &key("group"),
                    format!(
                        "a kinematic coupling on group \"{group}\", which fix.{j} also fixes: the coupling moves the \
                         group with the point (fix the point instead)"
                    ),
                ));
            }
            let full = |f: &FixEntry| f.u1.is_some() && f.u2.is_some() && f.rotation.is_some();
            let mine: Vec<&FixEntry> =
                self.fix.iter().filter(|f| f.point.as_deref() == Some(p.name.as_str())).collect();
            if mine.is_empty() || !mine.iter().all(|f| full(f)) {
                return Err(self.fail(
                    &key("coupling"),
                    format!(
                        "kinematic point \"{}\" is supported fixed in all of u1, u2 and rotation by [[fix]] point = \
                         \"{}\" (its group's nodes are then prescribed); a loaded or partly free kinematic point needs a \
                         multi-point constraint, which is not built: use coupling = \"distributing\"",
                        p.name, p.name
                    ),
                ));
            }
        }
        Ok(())
    }

    fn validate_fix(&self, i: usize, f: &FixEntry) -> Result<(), SceneError> {
        let key = |k: &str| format!("fix.{i}.{k}");
        if f.group.is_some() == f.point.is_some() {
            return Err(self.fail(&format!("fix.{i}"), "give exactly one of group and point".into()));
        }
        if f.u1.is_none() && f.u2.is_none() && f.un.is_none() && f.ut.is_none() && f.rotation.is_none() {
            let (name, what) = match (&f.group, &f.point) {
                (Some(g), _) => (g, "u1, u2, un, ut (un / ut: on a curve) or several"),
                (_, p) => (p.as_ref().unwrap_or(&self.name), "u1, u2, rotation or several"),
            };
            return Err(self.fail(&format!("fix.{i}"), format!("fixes nothing on \"{name}\": give {what}")));
        }
        let about = f.about.iter().flatten();
        let values = f.u1.iter().chain(&f.u2).chain(&f.un).chain(&f.ut).chain(&f.rotation);
        if let Some(v) = values.chain(about).find(|v| !v.is_finite()) {
            return Err(self.fail(&format!("fix.{i}"), format!("value {v} is not finite")));
        }
        if let Some(local) = [("un", f.un), ("ut", f.ut)].iter().find(|(_, v)| v.is_some()).map(|(k, _)| *k) {
            let other = [("u1", f.u1.is_some()), ("u2", f.u2.is_some()), ("rotation", f.rotation.is_some())]
                .iter()
                .chain(&[("point", f.point.is_some())])
                .find(|(_, given)| *given)
                .map(|(k, _)| *k);
            if let Some(other) = other {
                return Err(self.fail(
                    &key(local),
                    format!(
                        "{local} (a direction of a curve's local frame, node by node) with {other} in one [[fix]]: a \
                         node's DOFs are in one frame (give un / ut on a curve group, u1 / u2 elsewhere)"
                    ),
                ));
            }
        }
        if let Some(name) = &f.point {
            let Some((_, p)) = self.point_named(name) else {
                return Err(self.fail(&key("point"), format!("\"{name}\" is no [[point]]")));
            };
            if f.about.is_some() {
                return Err(self.fail(&key("about"), format!("point \"{name}\" turns about itself: drop about")));
            }
            match p.coupling {
                None if f.rotation.is_some() => {
                    return Err(self.fail(
                        &key("rotation"),
                        format!("point \"{name}\" has no coupling: a node has no rotation (couple it to a group)"),
                    ));
                }
                Some(CouplingKey::Distributing) => {
                    return Err(self.fail(
                        &key("point"),
                        format!(
                            "a fix on the distributing point \"{name}\" (a constraint on its group's weighted mean \
                             motion) is not supported: fix a kinematic point (all of u1, u2, rotation), or the group"
                        ),
                    ));
                }
                _ => {}
            }
        } else if f.rotation.is_some() && f.about.is_none() {
            return Err(
                self.fail(&key("about"), format!("a rotation of {} needs its centre: about = [x, y]", f.target()))
            );
        } else if f.rotation.is_none() && f.about.is_some() {
            return Err(self.fail(&key("about"), "about without rotation: give the rotation θ (radians)".into()));
        }
        Ok(())
    }

    fn validate_load(&self, i: usize, l: &LoadEntry) -> Result<(), SceneError> {
        let key = |k: &str| format!("load.{i}.{k}");
        if l.group.is_some() == l.point.is_some() {
            return Err(self.fail(&format!("load.{i}"), "give exactly one of group and point".into()));
        }
        if let Some(name) = &l.point {
            let Some((_, p)) = self.point_named(name) else {
                return Err(self.fail(&key("point"), format!("\"{name}\" is no [[point]]")));
            };
            if l.traction.is_some() || l.pressure.is_some() || l.body_force.is_some() {
                return Err(self.fail(
                    &format!("load.{i}"),
                    format!("point \"{name}\" takes a force and a moment only (no traction, pressure or body_force)"),
                ));
            }
            if l.force.is_none() && l.moment.is_none() {
                return Err(self.fail(
                    &format!("load.{i}"),
                    format!("loads nothing on point \"{name}\": give force, moment or both"),
                ));
            }
            if let Some(v) = l.force.iter().flatten().chain(&l.moment).find(|v| !v.is_finite()) {
                return Err(self.fail(&format!("load.{i}"), format!("value {v} is not finite")));
            }
            match p.coupling {
                None if l.moment.is_some() => {
                    return Err(self.fail(
                        &key("moment"),
                        format!("point \"{name}\" has no coupling: a moment needs a group to act on (give group and coupling)"),
                    ));
                }
                Some(CouplingKey::Kinematic) => {
                    return Err(self.fail(
                        &key("point"),
                        format!(
                            "a load on the kinematic point \"{name}\" needs a multi-point constraint, which is not \
                             built: use coupling = \"distributing\""
                        ),
                    ));
                }
                _ => {}
            }
            return Ok(());
        }
        let group = l.group.as_deref().unwrap_or_default();
        if l.moment.is_some() {
            return Err(self.fail(
                &key("moment"),
                format!("a moment acts at a point, not on group \"{group}\": declare a [[point]] coupled to it"),
            ));
        }
        let given = usize::from(l.force.is_some())
            + usize::from(l.traction.is_some())
            + usize::from(l.pressure.is_some())
            + usize::from(l.body_force.is_some());
        if given != 1 {
            return Err(self.fail(
                &format!("load.{i}"),
                format!("give exactly one of force, traction, pressure, body_force on \"{group}\" ({given} given)"),
            ));
        }
        if l.body_force.is_some() && !self.body.iter().any(|b| b.region == group) {
            return Err(self
                .fail(&key("body_force"), format!("\"{group}\" is no [[body]] region: a body force acts on a body")));
        }
        Ok(())
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    /// Four nodes of unequal weights, off the point.
    fn nodes() -> WeightedNodes {
        WeightedNodes {
            nodes: (0..4).map(NodeId).collect(),
            points: vec![[0.0, 0.0], [1.0, 0.2], [2.5, -0.3], [3.0, 1.0]],
            weights: vec![0.5, 1.25, 0.75, 0.3],
        }
    }

    #[test]
    fn distributed_forces_reproduce_the_force_and_the_moment_about_the_point() {
        // Σ f_i = F and Σ (x_i − p) × f_i = M (module docs): exact up to round-off, 1e-12 of
        // the load's scale |F| |x| + |M| ~ 10.
        let g = nodes();
        let (p, force, moment) = ([4.0, -2.0], [3.0, -1.5], 2.5);
        let f = g.distribute(p, force, moment);
        let total = f.iter().fold([0.0; 2], |a, f| [a[0] + f[0], a[1] + f[1]]);
        let about_p: f64 = g.points.iter().zip(&f).map(|(x, f)| cross([x[0] - p[0], x[1] - p[1]], *f)).sum();
        assert!((total[0] - force[0]).abs() < 1e-12 && (total[1] - force[1]).abs() < 1e-12, "{total:?}");
        assert!((about_p - moment).abs() < 1e-12, "{about_p}");
    }

    #[test]
    fn the_motion_of_a_rigid_field_is_its_translation_and_rotation_at_the_point() {
        // u_i = a + θ0 e3 × (x_i − q): u_p = a + θ0 e3 × (p − q), θ = θ0 (module docs), to 1e-15.
        let g = nodes();
        let (a, theta0, q, p) = ([0.3, -0.1], 1e-3, [1.0, 1.0], [4.0, -2.0]);
        let mut u = vec![0.0; 8];
        for (n, x) in g.nodes.iter().zip(&g.points) {
            let r = turn(theta0, [x[0] - q[0], x[1] - q[1]]);
            u[2 * n.0] = a[0] + r[0];
            u[2 * n.0 + 1] = a[1] + r[1];
        }
        let (up, theta) = g.motion(p, &u);
        let expected = turn(theta0, [p[0] - q[0], p[1] - q[1]]);
        assert!((theta - theta0).abs() < 1e-15, "{theta}");
        assert!((up[0] - a[0] - expected[0]).abs() < 1e-15 && (up[1] - a[1] - expected[1]).abs() < 1e-15, "{up:?}");
    }
}

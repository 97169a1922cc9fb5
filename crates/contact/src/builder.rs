//! From a description of the problem to a [`ContactProblem`]: bodies by region, Dirichlet
//! conditions and edge loads by group, each in a named load pattern, and contact interfaces
//! between named curves.
//!
//! ```text
//! ProblemDescription { mesh, bodies, fixes, loads, node_fixes, node_loads, contacts }
//!   → Model (bodies, every fix, by group and node by node; floating bodies allowed)
//!   → pairs per interface (node-to-segment, segment-to-segment (mortar), or node-to-node after
//!     sliding the slave nodes; automatic: node-to-segment on matching meshes, else mortar)
//!   → ContactProblem (friction and gaps per interface, set before anything is condensed)
//!   → load patterns:  r_p = f_p − K_fc u_c,p   (f_p: edge loads, body forces and nodal forces)
//! force F on a group of length L:  traction t = F / L (uniform; per unit thickness)
//! ```
//!
//! The slave side of an interface is found from the mesh: the body whose cells own its edges,
//! or, with `rigid_slave`, the meshed 2D region of a fixed obstacle that is no body.

use std::ops::Range;

use contact2d_element::{Kinematics, Material};
use contact2d_fem::{Component, DofKind, EdgeLoad, Model, assemble_body_forces, assemble_edge_loads};
use contact2d_mesh::morph::move_nodes;
use contact2d_mesh::{Contour, Mesh, line_cell_length};

use crate::error::ContactError;
use crate::pairing::{ContactPair, node_to_node_targets, nodes_face_each_other, pair_contours};
use crate::problem::{ContactProblem, LoadPattern};
use crate::segment_to_segment::pair_segments;

pub use crate::description::{
    BodyDescription, ContactDescription, DEFAULT_PATTERN, EdgeLoadKind, FixDescription, GapDescription,
    LoadDescription, NodeFixDescription, NodeLoadDescription, Pairing, ProblemDescription,
};

/// Where an interface's pairs sit in the built problem.
#[derive(Debug, Clone, PartialEq)]
pub struct InterfaceInfo {
    /// The interface's name.
    pub name: String,
    /// Its pairs: `problem.pairs[pairs]`, in order along the master curve.
    pub pairs: Range<usize>,
    /// The master curve's group.
    pub master: String,
    /// The slave curve's group.
    pub slave: String,
    /// The region (body) that owns the master curve.
    pub master_region: String,
    /// The region that owns the slave curve (a body, or the obstacle's region).
    pub slave_region: String,
    /// Whether the slave is a rigid obstacle.
    pub rigid_slave: bool,
    /// The master curve (arc length `s` from its first node).
    pub master_contour: Contour,
    /// The slave curve.
    pub slave_contour: Contour,
    /// Its friction coefficient.
    pub friction: f64,
    /// The pairing used: as given, or what [`Pairing::Automatic`] chose (node to segment where
    /// the curves' nodes face each other one to one, else segment to segment).
    pub pairing: Pairing,
}

/// A built problem with what its outputs need.
#[derive(Debug, Clone)]
pub struct BuiltProblem {
    /// The contact problem, its load patterns set.
    pub problem: ContactProblem,
    /// The interfaces, in the order given.
    pub interfaces: Vec<InterfaceInfo>,
}

impl ProblemDescription {
    /// Builds the contact problem (see the module docs).
    ///
    /// # Errors
    /// Invalid values (non-positive moduli or thickness, ν out of range, non-finite values,
    /// μ < 0), unknown or misdimensioned groups, a curve no region owns, a rigid slave that is a
    /// body, a deformable slave that is none, a value prescribed twice in two patterns, and
    /// every error of the model, pairing and factorisation; [`ContactError::SameBody`] for an
    /// interface whose two curves bound one body without `self_contact`.
    pub fn build(&self) -> Result<BuiltProblem, ContactError> {
        self.build_reusing(None)
    }

    /// Like [`ProblemDescription::build`], reusing the symbolic factorisation of `previous`
    /// when given: a problem of the same mesh topology whose nodes were moved (mesh morphing),
    /// e.g. the generated mesh's before a zone end was placed. Only the numeric factorisation
    /// is redone ([`ContactProblem::rebuild_moved`]).
    ///
    /// # Errors
    /// As [`ProblemDescription::build`], or a DOF numbering or sparsity pattern that differs
    /// from `previous`'s.
    pub fn build_reusing(&self, previous: Option<&ContactProblem>) -> Result<BuiltProblem, ContactError> {
        self.build_with(previous, &vec![true; self.fixes.len()])
    }

    /// Like [`ProblemDescription::build`], with only the fixes where `active[i]` is true holding
    /// their DOFs (a stage of staged supports, [`crate::stages`]); the others' DOFs are free.
    /// The load patterns are those of every fix and load, so that every stage's problem has the
    /// same patterns in the same order (a pattern that only an inactive fix's value names is
    /// zero in the stage).
    ///
    /// # Errors
    /// As [`ProblemDescription::build`], or `active` not holding one flag per fix.
    pub fn build_stage(&self, active: &[bool]) -> Result<BuiltProblem, ContactError> {
        if active.len() != self.fixes.len() {
            return Err(ContactError::InvalidInput(format!(
                "{} activity flags given for {} fixes",
                active.len(),
                self.fixes.len()
            )));
        }
        self.build_with(None, active)
    }

    /// [`ProblemDescription::build_reusing`] with the fixes `active` selects.
    fn build_with(&self, previous: Option<&ContactProblem>, active: &[bool]) -> Result<BuiltProblem, ContactError> {
        self.check_values()?;
        let mut model = self.model(self.mesh.clone(), active)?;
        if self.contacts.iter().any(|c| c.pairing == Pairing::NodeToNode) {
            let mut mesh = self.mesh.clone();
            for c in self.contacts.iter().filter(|c| c.pairing == Pairing::NodeToNode) {
                let (pairs, slave, _) = self.pair(&model, c)?;
                let targets = node_to_node_targets(&pairs, &slave).map_err(|e| match e {
                    ContactError::Pairing { reason, .. } => ContactError::Pairing {
                        master: c.master.clone(),
                        slave: c.slave.clone(),
                        reason: format!("contact \"{}\": {reason} (use pairing = \"node_to_segment\")", c.name),
                    },
                    other => other,
                })?;
                move_nodes(&mut mesh, &targets, 2).map_err(|e| ContactError::Pairing {
                    master: c.master.clone(),
                    slave: c.slave.clone(),
                    reason: format!("node-to-node pairing of contact \"{}\": {e}", c.name),
                })?;
            }
            // The same model as built on the moved mesh.
            model.move_points(mesh.points)?;
        }
        let mut pairs = vec![];
        let mut rigid = vec![];
        let mut interfaces = vec![];
        let mut gaps = vec![];
        let mut friction = vec![];
        for c in &self.contacts {
            let (mut p, slave_contour, slave_region) = self.pair(&model, c)?;
            let master_contour = Contour::from_group(&model.mesh, &c.master)?;
            let pairing = Self::pairing_used(&model, c, &master_contour, &slave_contour);
            let start = pairs.len();
            gaps.extend(p.iter().map(|pair| match c.gap {
                GapDescription::Geometric => pair.gap,
                GapDescription::Given(g) => g,
            }));
            friction.extend(std::iter::repeat_n(c.friction, p.len()));
            rigid.extend(std::iter::repeat_n(c.rigid_slave, p.len()));
            pairs.append(&mut p);
            interfaces.push(InterfaceInfo {
                name: c.name.clone(),
                pairs: start..pairs.len(),
                master: c.master.clone(),
                slave: c.slave.clone(),
                master_region: owning_region(&model.mesh, &c.master, &self.regions())?,
                slave_region,
                rigid_slave: c.rigid_slave,
                master_contour,
                slave_contour,
                friction: c.friction,
                pairing,
            });
        }
        let patterns = self.pattern_names();
        let mut problem = match previous {
            Some(previous) if previous.num_pairs() == pairs.len() => previous.rebuild_moved(model, pairs)?,
            _ => ContactProblem::with_slave_kinds(model, pairs, &rigid)?,
        };
        problem.set_gaps(gaps)?;
        problem.friction = friction;
        let load_patterns = self.load_patterns(&problem, &patterns, active)?;
        problem.set_patterns(load_patterns)?;
        Ok(BuiltProblem { problem, interfaces })
    }

    /// The bodies' regions.
    fn regions(&self) -> Vec<&str> {
        self.bodies.iter().map(|b| b.region.as_str()).collect()
    }

    /// Values that no later stage would catch with a clear message.
    fn check_values(&self) -> Result<(), ContactError> {
        let fail = |what: String| Err(ContactError::InvalidInput(what));
        if self.bodies.is_empty() {
            return fail("no body: give at least one [[body]] region".into());
        }
        for b in &self.bodies {
            if let Some(t) = b.kinematics.thickness()
                && !(t.is_finite() && t > 0.0)
            {
                return fail(format!("body \"{}\": thickness {t} must be finite and > 0", b.region));
            }
        }
        for (i, c) in self.contacts.iter().enumerate() {
            if !(c.friction.is_finite() && c.friction >= 0.0) {
                return fail(format!("contact \"{}\": friction {} must be finite and ≥ 0", c.name, c.friction));
            }
            if let GapDescription::Given(g) = c.gap
                && !g.is_finite()
            {
                return fail(format!("contact \"{}\": gap {g} is not finite", c.name));
            }
            if c.master == c.slave {
                return fail(format!("contact \"{}\": master and slave are the same curve \"{}\"", c.name, c.master));
            }
            if self.contacts[..i].iter().any(|d| d.name == c.name) {
                return fail(format!("contact \"{}\" named twice", c.name));
            }
        }
        Ok(())
    }

    /// The model: every body, every fix; floating bodies allowed.
    fn model(&self, mesh: Mesh, active: &[bool]) -> Result<Model, ContactError> {
        let mut model = Model::new(mesh);
        model.allow_floating = true;
        for b in &self.bodies {
            let material = Material::new(b.youngs_modulus, b.poissons_ratio)
                .map_err(|e| ContactError::InvalidInput(format!("body \"{}\": {e}", b.region)))?;
            model.add_body_in(&b.region, material, b.kinematics, b.formulation)?;
        }
        // A body of revolution's axis nodes hold u_r = 0 (none in the plane).
        model.fix_axis_nodes();
        for f in self.fixes.iter().zip(active).filter(|(_, a)| **a).map(|(f, _)| f) {
            model.fix(&f.group, f.component, f.value)?;
        }
        for f in &self.node_fixes {
            model.fix_node(f.node, f.component, f.value)?;
        }
        Ok(model)
    }

    /// Pairs of one interface on `model`, with the slave contour and the slave's region.
    fn pair(&self, model: &Model, c: &ContactDescription) -> Result<(Vec<ContactPair>, Contour, String), ContactError> {
        let master = Contour::from_group(&model.mesh, &c.master)?;
        let slave = Contour::from_group(&model.mesh, &c.slave)?;
        let region = owning_region(&model.mesh, &c.slave, &self.regions())?;
        let is_body = model.body(&region).is_some();
        let err = |reason: String| ContactError::Pairing { master: c.master.clone(), slave: c.slave.clone(), reason };
        match (c.rigid_slave, is_body) {
            (true, true) => {
                return Err(err(format!(
                    "contact \"{}\": rigid = true, but the slave curve bounds the body \"{region}\" (a rigid obstacle \
                     must be a meshed region that is no [[body]])",
                    c.name
                )));
            }
            (false, false) => {
                return Err(err(format!(
                    "contact \"{}\": the slave curve bounds region \"{region}\", which is no [[body]] (add the body, \
                     or set rigid = true for a fixed obstacle)",
                    c.name
                )));
            }
            _ => {}
        }
        let master_region = owning_region(&model.mesh, &c.master, &self.regions())?;
        if master_region == region && !c.self_contact {
            return Err(ContactError::SameBody {
                contact: c.name.clone(),
                body: region,
                master: c.master.clone(),
                slave: c.slave.clone(),
            });
        }
        if model.body(&master_region).is_none() {
            return Err(err(format!(
                "contact \"{}\": the master curve bounds region \"{master_region}\", which is no [[body]]",
                c.name
            )));
        }
        let segments = Self::pairing_used(model, c, &master, &slave) == Pairing::SegmentToSegment;
        let pairs = if segments {
            pair_segments(model, &master, &slave, &region)?
        } else {
            pair_contours(model, &master, &slave, &region)?
        };
        Ok((pairs, slave, region))
    }

    /// The pairing of contact `c` between its curves: as given, or [`Pairing::Automatic`]'s choice.
    fn pairing_used(model: &Model, c: &ContactDescription, master: &Contour, slave: &Contour) -> Pairing {
        match c.pairing {
            Pairing::Automatic if nodes_face_each_other(&model.mesh.points, master, slave) => Pairing::NodeToSegment,
            Pairing::Automatic => Pairing::SegmentToSegment,
            given => given,
        }
    }

    /// The pattern names of the non-zero prescribed values and the loads ([`pattern_order`]).
    fn pattern_names(&self) -> Vec<String> {
        let values = self.fixes.iter().filter(|f| f.value != 0.0).map(|f| f.pattern.as_str());
        let node_values = self.node_fixes.iter().filter(|f| f.value != 0.0).map(|f| f.pattern.as_str());
        let loads = self.loads.iter().map(|l| l.pattern.as_str());
        pattern_order(values.chain(node_values).chain(loads).chain(self.node_loads.iter().map(|l| l.pattern.as_str())))
    }

    /// Every pattern's right-hand side and prescribed values on the built problem.
    fn load_patterns(
        &self,
        problem: &ContactProblem,
        names: &[String],
        active: &[bool],
    ) -> Result<Vec<LoadPattern>, ContactError> {
        let model = &problem.model;
        let dofs = &problem.system.dofs;
        let mut owner: Vec<Option<usize>> = vec![None; dofs.num_constrained()];
        let mut prescribed = vec![vec![0.0; dofs.num_constrained()]; names.len()];
        // Every non-zero value of the active fixes, group by group and then node by node: (where,
        // node, component, value, pattern).
        let mut values = vec![];
        for f in self.fixes.iter().zip(active).filter(|(f, a)| **a && f.value != 0.0).map(|(f, _)| f) {
            for node in model.mesh.group_nodes(&f.group)? {
                values.push((format!("group \"{}\"", f.group), node, f.component, f.value, f.pattern.as_str()));
            }
        }
        for f in self.node_fixes.iter().filter(|f| f.value != 0.0) {
            values.push(("a node's value".to_string(), f.node, f.component, f.value, f.pattern.as_str()));
        }
        for (at, node, component, value, pattern) in values {
            let p = names.iter().position(|n| n == pattern).unwrap_or(0);
            if let DofKind::Constrained(j) = dofs.kind(contact2d_fem::Dof::of(node.0, component)) {
                if owner[j].is_some_and(|q| q != p) {
                    return Err(ContactError::InvalidInput(format!(
                        "{at}: {} at node {} is prescribed in two load patterns (\"{}\" and \"{}\")",
                        component.name(),
                        model.mesh.node_tags.get(node.0).copied().unwrap_or(node.0 as u64),
                        names[owner[j].unwrap_or(0)],
                        names[p]
                    )));
                }
                owner[j] = Some(p);
                prescribed[p][j] = value;
            }
        }
        let mut patterns = Vec::with_capacity(names.len());
        for (p, name) in names.iter().enumerate() {
            let mine = || self.loads.iter().filter(|l| l.pattern == *name);
            let loads: Vec<EdgeLoad> = mine()
                .filter(|l| !matches!(l.kind, EdgeLoadKind::BodyForce(_)))
                .map(|l| edge_load(&model.mesh, l, &model.pairing_kinematics()))
                .collect::<Result<_, _>>()?;
            let body_forces: Vec<(String, [f64; 2])> = mine()
                .filter_map(|l| match l.kind {
                    EdgeLoadKind::BodyForce(b) => Some((l.group.clone(), b)),
                    _ => None,
                })
                .collect();
            let mut nodal = assemble_edge_loads(model, &loads)?;
            for (f, b) in nodal.iter_mut().zip(assemble_body_forces(model, &body_forces)?) {
                *f += b;
            }
            for l in self.node_loads.iter().filter(|l| l.pattern == *name) {
                for c in [Component::X, Component::Y] {
                    let force = l.force[c.index()];
                    if !force.is_finite() {
                        return Err(ContactError::InvalidInput(format!("a nodal force {force} is not finite")));
                    }
                    if let Some(f) = nodal.get_mut(contact2d_fem::Dof::of(l.node.0, c).0) {
                        *f += force;
                    }
                }
            }
            let rhs = problem.system.rhs_with(&nodal, &prescribed[p]);
            patterns.push(LoadPattern { name: name.clone(), rhs, prescribed: prescribed[p].clone(), nodal });
        }
        Ok(patterns)
    }
}

/// The order of the load patterns named by `used` (non-zero prescribed values and loads, in
/// order of appearance): `main` first when used, then the others as they first appear; `main`
/// alone when nothing names one. The factors of a schedule and of a [`crate::SolvedStep`] follow
/// this order.
pub fn pattern_order<'a>(used: impl Iterator<Item = &'a str>) -> Vec<String> {
    let mut names: Vec<String> = vec![];
    for name in used {
        if !names.iter().any(|n| n == name) {
            names.push(name.to_string());
        }
    }
    if let Some(at) = names.iter().position(|n| n == DEFAULT_PATTERN) {
        let main = names.remove(at);
        names.insert(0, main);
    }
    if names.is_empty() {
        names.push(DEFAULT_PATTERN.to_string());
    }
    names
}

/// The fem edge load of a description (a total force becomes a uniform traction: `F / L` per unit
/// thickness in the plane, `F / A` over the group's ring area `A = ∫ 2πr ds` for a body of
/// revolution, whose forces are totals over the circumference).
fn edge_load(mesh: &Mesh, load: &LoadDescription, kinematics: &Kinematics) -> Result<EdgeLoad, ContactError> {
    let group = load.group.clone();
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    let bad = || ContactError::InvalidInput(format!("load on \"{}\" is not finite", load.group));
    Ok(match load.kind {
        EdgeLoadKind::Force(f) => {
            if !finite(&f) {
                return Err(bad());
            }
            let length = if kinematics.thickness().is_some() {
                group_length(mesh, &load.group)?
            } else {
                group_area(mesh, &load.group, kinematics)?
            };
            if length.is_nan() || length <= 0.0 {
                return Err(ContactError::InvalidInput(format!(
                    "force on \"{}\": the group has no length (or, on a body of revolution, lies on the axis)",
                    load.group
                )));
            }
            EdgeLoad::Traction { group, traction: [f[0] / length, f[1] / length] }
        }
        EdgeLoadKind::Traction(t) => {
            if !finite(&t) {
                return Err(bad());
            }
            EdgeLoad::Traction { group, traction: t }
        }
        EdgeLoadKind::Pressure(p) => {
            if !p.is_finite() {
                return Err(bad());
            }
            EdgeLoad::Pressure { group, pressure: p }
        }
        EdgeLoadKind::BodyForce(_) => {
            return Err(ContactError::InvalidInput(format!("\"{}\": a body force is no edge load", load.group)));
        }
    })
}

/// The length of a 1D group: the sum of its line cells' lengths
/// ([`contact2d_mesh::line_cell_length`]).
///
/// # Errors
/// An unknown group, or one that is not 1D.
pub fn group_length(mesh: &Mesh, group: &str) -> Result<f64, ContactError> {
    if mesh.group(group)?.dim != 1 {
        return Err(ContactError::InvalidInput(format!("\"{group}\" is not a 1D group (a curve)")));
    }
    let mut length = 0.0;
    for block in mesh.blocks_in_group(group)? {
        for cell in block.cells() {
            let points: Vec<[f64; 2]> = cell.iter().map(|n| mesh.points[n.0]).collect();
            length += line_cell_length(block.kind, &points);
        }
    }
    Ok(length)
}

/// The surface of revolution a 1D group sweeps, `∫ m ds` with `m` the kinematics'
/// [`Kinematics::pairing_measure`] (`2πr`), by 5-point Gauss on each line cell.
///
/// # Errors
/// An unknown group, or one that is not 1D.
pub fn group_area(mesh: &Mesh, group: &str, kinematics: &Kinematics) -> Result<f64, ContactError> {
    if mesh.group(group)?.dim != 1 {
        return Err(ContactError::InvalidInput(format!("\"{group}\" is not a 1D group (a curve)")));
    }
    let mut area = 0.0;
    for block in mesh.blocks_in_group(group)? {
        for cell in block.cells() {
            let p: Vec<[f64; 2]> = cell.iter().map(|n| mesh.points[n.0]).collect();
            for (xi, w) in contact2d_mesh::GAUSS5 {
                // Line2: N = ((1 − ξ)/2, (1 + ξ)/2); Line3 (start, end, mid): (ξ(ξ−1)/2, ξ(ξ+1)/2, 1 − ξ²).
                let (n, dn): (Vec<f64>, Vec<f64>) = match (block.kind, p.len()) {
                    (contact2d_mesh::CellKind::Line3, 3..) => (
                        vec![0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi],
                        vec![xi - 0.5, xi + 0.5, -2.0 * xi],
                    ),
                    (contact2d_mesh::CellKind::Line2, 2..) => {
                        (vec![0.5 * (1.0 - xi), 0.5 * (1.0 + xi)], vec![-0.5, 0.5])
                    }
                    _ => continue,
                };
                let at = |d: &[f64], k: usize| d.iter().zip(&p).map(|(s, q)| s * q[k]).sum::<f64>();
                let ds = at(&dn, 0).hypot(at(&dn, 1));
                area += w * ds * kinematics.pairing_measure([at(&n, 0), at(&n, 1)]);
            }
        }
    }
    Ok(area)
}

/// The 2D physical group whose cells hold every node of the curve `group` (the body or
/// obstacle the curve bounds): the first of `preferred` (e.g. the bodies' regions) that does,
/// else the first other 2D group by name.
///
/// # Errors
/// No 2D group holds the whole curve.
pub fn owning_region(mesh: &Mesh, group: &str, preferred: &[&str]) -> Result<String, ContactError> {
    let nodes = mesh.group_nodes(group)?;
    let mut others: Vec<&str> = mesh
        .groups
        .iter()
        .filter(|g| g.dim == 2 && !preferred.contains(&g.name.as_str()))
        .map(|g| g.name.as_str())
        .collect();
    others.sort_unstable();
    let candidates = preferred.iter().copied().filter(|n| mesh.group(n).is_ok_and(|g| g.dim == 2)).chain(others);
    for name in candidates {
        let mut inside = vec![false; mesh.num_nodes()];
        for block in mesh.blocks_in_group(name)? {
            for cell in block.cells() {
                for n in cell {
                    inside[n.0] = true;
                }
            }
        }
        if nodes.iter().all(|n| inside[n.0]) {
            return Ok(name.to_string());
        }
    }
    Err(ContactError::InvalidInput(format!(
        "curve \"{group}\" bounds no 2D physical group (no body or obstacle owns it)"
    )))
}

//! The finite-element model: bodies (a physical region each, with its material), Dirichlet
//! conditions and edge loads, all named by physical group.
//!
//! Bodies must not share nodes with each other unless they are meant to be bonded; contact
//! between bodies is added by the contact crate on top of this model.

use contact2d_element::{
    ElementError, ElementType, Formulation, Kinematics, Material, element_stiffness_with, map_point,
};
use contact2d_mesh::frames::{NodeFrames, node_frames};
use contact2d_mesh::{CellKind, Mesh, NodeId};
use nalgebra::DMatrix;

use crate::dof::{Component, Dof};
use crate::error::FemError;

/// Index of a body in its model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BodyId(pub usize);

/// One elastic body: the cells of a 2D physical region, with one material.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Name (the physical group's name).
    pub name: String,
    /// Material.
    pub material: Material,
    /// The body's kinematics (plane stress or plane strain with the out-of-plane thickness, or a
    /// body of revolution): every integral over the body takes its weight, and the stiffness its
    /// strain rows and Gauss rule, from it.
    pub kinematics: Kinematics,
    /// Standard or B-bar (locking-free for nearly incompressible plane strain); used by the
    /// assembly, the strain energy and the stress recovery alike. Change it with
    /// [`Model::set_formulation`], which checks that every cell supports it.
    pub formulation: Formulation,
    /// Element type of each cell.
    pub elements: Vec<ElementType>,
    /// Nodes of each cell, flat; cell `i` spans `offsets[i]..offsets[i + 1]`.
    pub nodes: Vec<NodeId>,
    /// Start of each cell in `nodes` (length `cells + 1`).
    pub offsets: Vec<usize>,
    /// The mesh's element tag of each cell.
    pub cell_tags: Vec<u64>,
}

impl Body {
    /// Number of cells.
    pub fn num_cells(&self) -> usize {
        self.elements.len()
    }

    /// Nodes of cell `i`.
    pub fn cell_nodes(&self, i: usize) -> &[NodeId] {
        &self.nodes[self.offsets[i]..self.offsets[i + 1]]
    }

    /// Coordinates of cell `i`'s nodes.
    pub fn cell_coords(&self, mesh: &Mesh, i: usize) -> Vec<[f64; 2]> {
        self.cell_nodes(i).iter().map(|n| mesh.points[n.0]).collect()
    }

    /// Global DOFs of cell `i` in element order `[u_0x, u_0y, u_1x, ...]`.
    pub fn cell_dofs(&self, i: usize) -> impl Iterator<Item = Dof> + '_ {
        self.cell_nodes(i).iter().flat_map(|n| [Dof::of(n.0, Component::X), Dof::of(n.0, Component::Y)])
    }

    /// The stiffness matrix of cell `i` (`2n × 2n`, element order): the one place the element
    /// stiffness is called, with the body's material, [`Kinematics`] and [`Formulation`] and the
    /// element's stiffness rule; the assembly, the sparsity-pattern fill and the strain energy all
    /// ask it.
    ///
    /// # Errors
    /// [`FemError::Element`] naming the body and the cell's tag (not expected once the body was
    /// validated by [`Model::add_body_in`]).
    pub fn cell_stiffness(&self, mesh: &Mesh, i: usize) -> Result<DMatrix<f64>, FemError> {
        let element = self.elements[i];
        element_stiffness_with(
            element,
            &self.cell_coords(mesh, i),
            &self.material,
            &self.kinematics,
            &self.kinematics.stiffness_rule(element),
            self.formulation,
        )
        .map_err(|source| FemError::Element { body: self.name.clone(), cell: self.cell_tags[i], source })
    }
}

/// A prescribed displacement component on all nodes of a physical group.
#[derive(Debug, Clone, PartialEq)]
pub struct Dirichlet {
    /// Physical group name (any dimension).
    pub group: String,
    /// Which component.
    pub component: Component,
    /// The prescribed value.
    pub value: f64,
}

/// A traction (force per length and thickness) on the edges of a 1D physical group.
#[derive(Debug, Clone, PartialEq)]
pub enum EdgeLoad {
    /// Constant traction vector `[t1, t2]`.
    Traction {
        /// Physical group name (1D).
        group: String,
        /// Traction vector.
        traction: [f64; 2],
    },
    /// Normal pressure `p` (positive pushes against the body; the body's side of the edge is
    /// found from the cell that owns it).
    Pressure {
        /// Physical group name (1D).
        group: String,
        /// Pressure.
        pressure: f64,
    },
}

/// Bodies, boundary conditions and loads on a mesh.
#[derive(Debug, Clone)]
pub struct Model {
    /// The mesh.
    pub mesh: Mesh,
    /// Bodies in the order they were added.
    pub bodies: Vec<Body>,
    /// Dirichlet conditions.
    pub dirichlet: Vec<Dirichlet>,
    /// Prescribed values of single DOFs (a value that varies from node to node, such as a rigid
    /// rotation's `u = θ e3 × (x − c)`), resolved with [`Model::dirichlet`] by [`Model::dof_map`].
    pub node_dirichlet: Vec<(Dof, f64)>,
    /// Edge loads.
    pub edge_loads: Vec<EdgeLoad>,
    /// The node frames of the curves with a [`Component::Normal`] / [`Component::Tangent`]
    /// condition ([`contact2d_mesh::frames::node_frames`]), by group: those nodes' DOFs are
    /// `(un, ut)` ([`crate::dof`]).
    pub local_frames: Vec<(String, NodeFrames)>,
    /// Whether a body piece that the Dirichlet conditions leave free to move rigidly is
    /// accepted (held by contact; assembly then pins it at as many DOFs as it has free rigid modes,
    /// pins whose forces the contact solve drives to zero, see
    /// [`crate::assembly::LinearSystem::stabilisation`]) instead of rejected
    /// with [`FemError::UnconstrainedBody`].
    pub allow_floating: bool,
}

/// The element type of a 2D cell kind.
pub fn element_type(kind: CellKind) -> Option<ElementType> {
    Some(match kind {
        CellKind::Tri3 => ElementType::Tri3,
        CellKind::Tri6 => ElementType::Tri6,
        CellKind::Quad4 => ElementType::Quad4,
        CellKind::Quad8 => ElementType::Quad8,
        CellKind::Quad9 => ElementType::Quad9,
        _ => return None,
    })
}

impl Model {
    /// An empty model on `mesh`.
    pub fn new(mesh: Mesh) -> Model {
        Model {
            mesh,
            bodies: vec![],
            dirichlet: vec![],
            node_dirichlet: vec![],
            edge_loads: vec![],
            local_frames: vec![],
            allow_floating: false,
        }
    }

    /// Adds the 2D physical group `region` as a body of `material` with its [`Kinematics`]
    /// (plane stress or plane strain with a thickness, or a body of revolution), checking every
    /// cell's Jacobian at its nodes and stiffness Gauss points.
    ///
    /// Cells drawn clockwise (a Gmsh surface from a clockwise curve loop: det J < 0 throughout
    /// the cell) are first renumbered counter-clockwise in the model's mesh with
    /// [`Mesh::orient_cells_counter_clockwise`], which gives the same element as the
    /// counter-clockwise drawing. This is done here, where the cells become elements, so that
    /// every mesh source gets it (a `.msh` file of any format, a generated or hand-built mesh, a
    /// morphed one), while the reader stays a faithful parser (`parse(encode(mesh)) == mesh`).
    ///
    /// # Errors
    /// Unknown or non-2D group, unsupported cell kinds, a non-positive thickness, or an
    /// [`FemError::InvertedElement`] naming the first truly inverted or degenerate cell.
    pub fn add_body(&mut self, region: &str, material: Material, kinematics: Kinematics) -> Result<BodyId, FemError> {
        self.add_body_in(region, material, kinematics, Formulation::Standard)
    }

    /// As [`Model::add_body`], with the body's [`Formulation`]. A body of revolution
    /// ([`Kinematics::Axisymmetric`]) must have every node at `x = r ≥ 0`.
    ///
    /// # Errors
    /// As [`Model::add_body`]; [`FemError::Element`] (an [`ElementError::UnsupportedFormulation`])
    /// for a cell kind without that formulation (B-bar on Tri3); [`FemError::InvalidRegion`]
    /// naming the first node at `r < 0` of a body of revolution.
    pub fn add_body_in(
        &mut self,
        region: &str,
        material: Material,
        kinematics: Kinematics,
        formulation: Formulation,
    ) -> Result<BodyId, FemError> {
        if let Some(thickness) = kinematics.thickness().filter(|t| !(t.is_finite() && *t > 0.0)) {
            return Err(FemError::InvalidInput(format!(
                "body \"{region}\": thickness must be positive, got {thickness}"
            )));
        }
        if let Some(other) = self.bodies.iter().find(|b| b.kinematics.has_hoop_strain() != kinematics.has_hoop_strain())
        {
            return Err(FemError::InvalidInput(format!(
                "body \"{region}\" is {} but body \"{}\" is {}: a model's bodies are all bodies of revolution \
                 or all plane",
                kinematics.name(),
                other.name,
                other.kinematics.name()
            )));
        }
        let group = self.mesh.group(region)?;
        if group.dim != 2 {
            return Err(FemError::InvalidRegion {
                group: region.into(),
                reason: format!("dimension {} is not 2", group.dim),
            });
        }
        self.mesh.orient_cells_counter_clockwise();
        let mut body = Body {
            name: region.to_string(),
            material,
            kinematics,
            formulation,
            elements: vec![],
            nodes: vec![],
            offsets: vec![0],
            cell_tags: vec![],
        };
        for block in self.mesh.blocks_in_group(region)? {
            let element = element_type(block.kind).ok_or_else(|| FemError::InvalidRegion {
                group: region.into(),
                reason: format!("cell kind {} is not a 2D element", block.kind.name()),
            })?;
            for (cell, tag) in block.cells().zip(&block.element_tags) {
                body.elements.push(element);
                body.nodes.extend_from_slice(cell);
                body.offsets.push(body.nodes.len());
                body.cell_tags.push(*tag);
            }
        }
        if body.elements.is_empty() {
            return Err(FemError::InvalidRegion { group: region.into(), reason: "no cells".into() });
        }
        check_radii(&self.mesh, &body)?;
        check_jacobians(&self.mesh, &body)?;
        check_formulation(&body, formulation)?;
        self.bodies.push(body);
        Ok(BodyId(self.bodies.len() - 1))
    }

    /// The kinematics contact pairing integrates with ([`Kinematics::pairing_measure`]): the
    /// first body's, since a model's bodies are all plane or all of revolution
    /// ([`Model::add_body_in`]); plane stress of unit thickness in a model without bodies.
    pub fn pairing_kinematics(&self) -> Kinematics {
        self.bodies.first().map_or(Kinematics::PlaneStress { thickness: 1.0 }, |b| b.kinematics)
    }

    /// The nodes on the axis `r = x = 0` of the bodies of revolution (none in a plane model), in
    /// node order. "On the axis" is `|x| ≤ 1e-12 L` ([`AXIS_TOLERANCE`]), `L` the mesh's extent: a
    /// mesh generator writes the axis as zeros or at the round-off of its coordinates.
    pub fn axis_nodes(&self) -> Vec<NodeId> {
        let mut on_axis = vec![false; self.mesh.num_nodes()];
        let extent = self.mesh.points.iter().fold(0.0f64, |a, p| a.max(p[0].abs()).max(p[1].abs()));
        for body in self.bodies.iter().filter(|b| b.kinematics.has_hoop_strain()) {
            for n in &body.nodes {
                on_axis[n.0] |= self.mesh.points[n.0][0].abs() <= AXIS_TOLERANCE * extent;
            }
        }
        (0..on_axis.len()).filter(|&n| on_axis[n]).map(NodeId).collect()
    }

    /// Prescribes `u_r = u1 = 0` on [`Model::axis_nodes`]: a point of the axis cannot move off it
    /// (the hoop strain `u_r / r` would be infinite). Returns how many nodes that is.
    pub fn fix_axis_nodes(&mut self) -> usize {
        let nodes = self.axis_nodes();
        for n in &nodes {
            self.node_dirichlet.push((Dof::of(n.0, Component::X), 0.0));
        }
        nodes.len()
    }

    /// Sets the [`Formulation`] of body `id`.
    ///
    /// # Errors
    /// [`FemError::InvalidInput`] for an unknown body, [`FemError::Element`] for a cell kind
    /// without that formulation (B-bar on Tri3).
    pub fn set_formulation(&mut self, id: BodyId, formulation: Formulation) -> Result<(), FemError> {
        let count = self.bodies.len();
        let body = self
            .bodies
            .get_mut(id.0)
            .ok_or_else(|| FemError::InvalidInput(format!("no body {} (the model has {count})", id.0)))?;
        check_formulation(body, formulation)?;
        body.formulation = formulation;
        Ok(())
    }

    /// The same model on moved nodes (mesh morphing, e.g. `contact2d_mesh::morph::move_nodes`:
    /// the same cells): the mesh's points become `points`, and the cells with a moved node are
    /// checked as [`Model::add_body`] checks every cell. That is the model built anew on the
    /// moved mesh whenever no cell changes its orientation (which the morph refuses; a cell
    /// that did would be refused here as inverted, where building anew would renumber it), for
    /// a check of the moved cells only.
    ///
    /// # Errors
    /// [`FemError::InvalidInput`] for a number of points other than the mesh's or a non-finite
    /// point; [`FemError::InvertedElement`] (or [`FemError::Element`]) for a moved cell, the
    /// model then unchanged.
    pub fn move_points(&mut self, points: Vec<[f64; 2]>) -> Result<(), FemError> {
        if points.len() != self.mesh.points.len() || points.iter().any(|p| !(p[0].is_finite() && p[1].is_finite())) {
            return Err(FemError::InvalidInput(format!(
                "move_points: {} finite points needed for the mesh's {} nodes",
                points.len(),
                self.mesh.points.len()
            )));
        }
        let bits = |p: &[f64; 2]| [p[0].to_bits(), p[1].to_bits()];
        let moved: Vec<bool> = points.iter().zip(&self.mesh.points).map(|(p, q)| bits(p) != bits(q)).collect();
        let old = std::mem::replace(&mut self.mesh.points, points);
        for body in &self.bodies {
            let cells = (0..body.num_cells()).filter(|&i| body.cell_nodes(i).iter().any(|n| moved[n.0]));
            if let Err(e) = check_cell_jacobians(&self.mesh, body, cells) {
                self.mesh.points = old;
                return Err(e);
            }
        }
        Ok(())
    }

    /// Prescribes `component = value` on every node of the physical group `group`; a local
    /// component (`un`, `ut`) gives the group's nodes their curve frame
    /// ([`contact2d_mesh::frames::node_frames`]).
    ///
    /// # Errors
    /// Unknown group or a non-finite value; for `un` / `ut`, [`FemError::Mesh`] naming the group
    /// if it is not a curve or has a cusp.
    pub fn fix(&mut self, group: &str, component: Component, value: f64) -> Result<(), FemError> {
        self.mesh.group(group)?;
        if !value.is_finite() {
            return Err(FemError::InvalidInput(format!("Dirichlet value on \"{group}\" is not finite")));
        }
        if component.is_local() && !self.local_frames.iter().any(|(g, _)| g == group) {
            let frames = node_frames(&self.mesh, group)?;
            self.local_frames.push((group.to_string(), frames));
        }
        self.dirichlet.push(Dirichlet { group: group.to_string(), component, value });
        Ok(())
    }

    /// Prescribes `component = value` on the single node `node` (checked against the other
    /// conditions by [`Model::dof_map`], as a group's).
    ///
    /// # Errors
    /// A node out of range, a non-finite value or a local component (`un`, `ut` need a curve).
    pub fn fix_node(&mut self, node: NodeId, component: Component, value: f64) -> Result<(), FemError> {
        if component.is_local() {
            return Err(FemError::InvalidInput(format!(
                "{} on node index {}: local directions are given on a curve (a group)",
                component.name(),
                node.0
            )));
        }
        if node.0 >= self.mesh.num_nodes() {
            return Err(FemError::InvalidInput(format!(
                "Dirichlet value on node index {}: the mesh has {} nodes",
                node.0,
                self.mesh.num_nodes()
            )));
        }
        if !value.is_finite() {
            return Err(FemError::InvalidInput(format!(
                "Dirichlet value on node {} is not finite",
                self.mesh.node_tags.get(node.0).copied().unwrap_or(node.0 as u64)
            )));
        }
        self.node_dirichlet.push((Dof::of(node.0, component), value));
        Ok(())
    }

    /// Adds an edge load on a 1D group.
    ///
    /// # Errors
    /// Unknown group, a group that is not 1D, or a non-finite value.
    pub fn add_edge_load(&mut self, load: EdgeLoad) -> Result<(), FemError> {
        let (group, finite) = match &load {
            EdgeLoad::Traction { group, traction } => (group, traction.iter().all(|t| t.is_finite())),
            EdgeLoad::Pressure { group, pressure } => (group, pressure.is_finite()),
        };
        if self.mesh.group(group)?.dim != 1 {
            return Err(FemError::InvalidInput(format!("edge load on \"{group}\": group is not 1D")));
        }
        if !finite {
            return Err(FemError::InvalidInput(format!("edge load on \"{group}\" is not finite")));
        }
        self.edge_loads.push(load);
        Ok(())
    }

    /// The body called `name`.
    pub fn body(&self, name: &str) -> Option<(BodyId, &Body)> {
        self.bodies.iter().enumerate().find(|(_, b)| b.name == name).map(|(i, b)| (BodyId(i), b))
    }

    /// Which nodes belong to at least one body.
    pub fn active_nodes(&self) -> Vec<bool> {
        let mut active = vec![false; self.mesh.num_nodes()];
        for b in &self.bodies {
            for n in &b.nodes {
                active[n.0] = true;
            }
        }
        active
    }
}

/// Nodes of a body of revolution within this fraction of the mesh's extent of `x = 0` are on
/// the axis ([`Model::axis_nodes`]).
pub const AXIS_TOLERANCE: f64 = 1e-12;

fn check_formulation(body: &Body, formulation: Formulation) -> Result<(), FemError> {
    match body.elements.iter().position(|e| !formulation.supports(*e)) {
        None => Ok(()),
        Some(i) => Err(FemError::Element {
            body: body.name.clone(),
            cell: body.cell_tags[i],
            source: formulation.check(body.elements[i]).err().unwrap_or(ElementError::UnsupportedFormulation {
                element: format!("{:?}", body.elements[i]),
                formulation: format!("{formulation:?}"),
            }),
        }),
    }
}

/// A body of revolution lives at `r = x ≥ 0`: its first node at `r < 0` is refused by tag (a node
/// at `−1e-12 L` or above is on the axis, as [`Model::axis_nodes`] says).
fn check_radii(mesh: &Mesh, body: &Body) -> Result<(), FemError> {
    let extent = mesh.points.iter().fold(0.0f64, |a, p| a.max(p[0].abs()).max(p[1].abs()));
    if body.kinematics.has_hoop_strain()
        && let Some(n) = body.nodes.iter().find(|n| mesh.points[n.0][0] < -AXIS_TOLERANCE * extent)
    {
        return Err(FemError::InvalidRegion {
            group: body.name.clone(),
            reason: format!(
                "node {} lies at r = x = {} < 0; a body of revolution lives at r ≥ 0 (the axis is x = 0)",
                mesh.node_tags[n.0], mesh.points[n.0][0]
            ),
        });
    }
    Ok(())
}

fn check_jacobians(mesh: &Mesh, body: &Body) -> Result<(), FemError> {
    check_cell_jacobians(mesh, body, 0..body.num_cells())
}

/// [`check_jacobians`] on the given cells of `body`.
fn check_cell_jacobians(mesh: &Mesh, body: &Body, cells: impl Iterator<Item = usize>) -> Result<(), FemError> {
    for i in cells {
        let element = body.elements[i];
        let coords = body.cell_coords(mesh, i);
        let rule = body.kinematics.stiffness_rule(element);
        for xi in rule.points.iter().chain(element.reference_nodes()) {
            map_point(element, &coords, *xi).map_err(|e| match e {
                ElementError::NonPositiveJacobian { det_j, .. } => {
                    FemError::InvertedElement { body: body.name.clone(), cell: body.cell_tags[i], det_j }
                }
                other => FemError::Element { body: body.name.clone(), cell: body.cell_tags[i], source: other },
            })?;
        }
    }
    Ok(())
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use contact2d_mesh::generate::rectangle;

    #[test]
    fn formulation_is_stored_checked_and_defaults_to_standard() {
        let m = Material::new(1.0, 0.4999).unwrap();
        let mut model = Model::new(rectangle(CellKind::Quad9, [0.0, 1.0], [0.0, 1.0], 2, 2));
        let id = model.add_body("domain", m, Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
        assert_eq!(model.bodies[id.0].formulation, Formulation::Standard);
        model.set_formulation(id, Formulation::BBar).unwrap();
        assert_eq!(model.bodies[id.0].formulation, Formulation::BBar);
        assert!(matches!(model.set_formulation(BodyId(7), Formulation::BBar), Err(FemError::InvalidInput(_))));

        let mut tri3 = Model::new(rectangle(CellKind::Tri3, [0.0, 1.0], [0.0, 1.0], 2, 2));
        let e = tri3.add_body_in("domain", m, Kinematics::PlaneStrain { thickness: 1.0 }, Formulation::BBar);
        assert!(matches!(e, Err(FemError::Element { source: ElementError::UnsupportedFormulation { .. }, .. })));
        let id = tri3.add_body("domain", m, Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
        assert!(tri3.set_formulation(id, Formulation::BBar).is_err());
        assert_eq!(tri3.bodies[id.0].formulation, Formulation::Standard);
    }

    #[test]
    fn a_node_value_is_checked_against_the_groups_values() {
        let m = Material::new(1.0, 0.3).unwrap();
        let mut model = Model::new(rectangle(CellKind::Quad4, [0.0, 1.0], [0.0, 1.0], 2, 2));
        model.add_body("domain", m, Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
        model.fix("left", Component::X, 0.0).unwrap();
        let corner = NodeId((0..model.mesh.points.len()).find(|&i| model.mesh.points[i] == [0.0, 0.0]).unwrap());
        // The same value as the group's: consistent; a node of no group: a constrained DOF more.
        model.fix_node(corner, Component::X, 0.0).unwrap();
        model.fix_node(corner, Component::Y, 0.5).unwrap();
        let dofs = model.dof_map().unwrap();
        assert_eq!(dofs.num_constrained(), 3 + 1);
        model.fix_node(corner, Component::X, 0.1).unwrap();
        assert!(matches!(model.dof_map(), Err(FemError::ConflictingDirichlet { .. })));
        assert!(matches!(model.fix_node(NodeId(99), Component::X, 0.0), Err(FemError::InvalidInput(_))));
        assert!(matches!(model.fix_node(corner, Component::X, f64::NAN), Err(FemError::InvalidInput(_))));
    }

    #[test]
    fn moving_points_gives_the_model_built_on_the_moved_mesh() {
        let m = Material::new(1.0, 0.3).unwrap();
        let build = |mesh: Mesh| {
            let mut model = Model::new(mesh);
            model.add_body("domain", m, Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
            model
        };
        let mesh = rectangle(CellKind::Quad9, [0.0, 4.0], [0.0, 4.0], 4, 4);
        let node = (0..mesh.points.len()).find(|&i| mesh.points[i] == [2.0, 0.0]).unwrap();
        let mut moved = mesh.clone();
        contact2d_mesh::morph::move_nodes(&mut moved, &[(NodeId(node), [2.3, 0.0])], 2).unwrap();
        let mut model = build(mesh.clone());
        model.move_points(moved.points.clone()).unwrap();
        let anew = build(moved);
        assert_eq!((&model.mesh, &model.bodies), (&anew.mesh, &anew.bodies));
        // A point that inverts a cell is refused and leaves the model alone.
        let mut inverted = mesh.points.clone();
        inverted[node] = [3.3, 0.0];
        let before = model.mesh.points.clone();
        assert!(matches!(model.move_points(inverted), Err(FemError::InvertedElement { .. })));
        assert_eq!(model.mesh.points, before);
        assert!(matches!(model.move_points(vec![]), Err(FemError::InvalidInput(_))));
    }
}

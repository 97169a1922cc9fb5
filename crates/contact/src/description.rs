//! What a contact problem is made of, as the user describes it: bodies by region, Dirichlet
//! conditions and loads by group or node, each in a named load pattern, and contact interfaces
//! between named curves. [`crate::builder`] turns a [`ProblemDescription`] into a
//! [`crate::ContactProblem`].
//!
//! ```text
//! ProblemDescription { mesh, bodies, fixes, loads, node_fixes, node_loads, contacts }
//! value of a fix or load in pattern p at load factor w_p:  w_p · value
//! ```

use contact2d_element::{Formulation, Kinematics};
use contact2d_fem::Component;
use contact2d_mesh::{Mesh, NodeId};

/// The pattern of values and loads that name none.
pub const DEFAULT_PATTERN: &str = "main";

/// One elastic body: a 2D physical group with its material.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyDescription {
    /// The 2D physical group.
    pub region: String,
    /// Young's modulus E.
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poissons_ratio: f64,
    /// Plane stress or plane strain with the out-of-plane thickness, or a body of revolution
    /// (every body of a problem plane, or every one of revolution).
    pub kinematics: Kinematics,
    /// Standard displacement elements, or B-bar (locking-free for nearly incompressible
    /// materials in plane strain).
    pub formulation: Formulation,
}

/// A prescribed displacement component on every node of a group.
#[derive(Debug, Clone, PartialEq)]
pub struct FixDescription {
    /// A 1D or 0D physical group.
    pub group: String,
    /// The component.
    pub component: Component,
    /// Its value (0: a support, in no pattern).
    pub value: f64,
    /// The load pattern a non-zero value belongs to.
    pub pattern: String,
}

/// A prescribed value of one node's component: a value that varies from node to node (a rigid
/// motion `u = t + θ e3 × (x − c)` prescribed on a group, a kinematic coupling's point fixed).
#[derive(Debug, Clone, PartialEq)]
pub struct NodeFixDescription {
    /// The node.
    pub node: NodeId,
    /// The component.
    pub component: Component,
    /// Its value (0: a support, in no pattern).
    pub value: f64,
    /// The load pattern a non-zero value belongs to.
    pub pattern: String,
}

/// A force on one node (a distributing coupling's share of a point's force and moment).
#[derive(Debug, Clone, PartialEq)]
pub struct NodeLoadDescription {
    /// The node.
    pub node: NodeId,
    /// `[F1, F2]`, per unit thickness.
    pub force: [f64; 2],
    /// The load pattern it belongs to.
    pub pattern: String,
}

/// How an edge load is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EdgeLoadKind {
    /// The total force `[F1, F2]` on the group per unit thickness, spread as a uniform
    /// traction `F / L` over its length `L`.
    Force([f64; 2]),
    /// A traction vector (force per unit length and thickness).
    Traction([f64; 2]),
    /// A pressure, positive against the body.
    Pressure(f64),
    /// A constant body force `b` (force per unit volume, e.g. the weight `[0, -ρ g]`) on every
    /// cell of the body whose region the load's group names:
    /// `f_a = ∫_Ω N_a b t_h dΩ` ([`contact2d_fem::assemble_body_forces`]).
    BodyForce([f64; 2]),
}

/// A load on a group: an edge load on a 1D group, or a body force on a body's 2D region.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDescription {
    /// The 1D physical group (the body's 2D region for [`EdgeLoadKind::BodyForce`]).
    pub group: String,
    /// What is applied.
    pub kind: EdgeLoadKind,
    /// The load pattern it belongs to.
    pub pattern: String,
}

/// How an interface's pairs are made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pairing {
    /// Each master node against the closest point of the slave curve (the mesh as given).
    NodeToSegment,
    /// The slave nodes slid along their curve onto the paired points first (mesh morphing,
    /// topology unchanged), so that every pair is node-to-node; needs as many slave nodes as
    /// master nodes facing each other.
    NodeToNode,
    /// Gap and traction integrated over the master segments (mortar-type,
    /// [`crate::segment_to_segment`]): one weighted gap per master node; passes the patch test
    /// on non-matching meshes.
    SegmentToSegment,
    /// [`Pairing::NodeToSegment`] where the two curves' nodes face each other one to one (every
    /// node of each curve projects onto a node of the other: matching meshes), else
    /// [`Pairing::SegmentToSegment`] ([`crate::pairing::nodes_face_each_other`]).
    Automatic,
}

impl Pairing {
    /// Every concrete pairing (for comparisons that run them all; [`Pairing::Automatic`] only
    /// chooses between two of them). A new variant must be added here: [`Pairing::key`]'s
    /// exhaustive match reminds whoever adds one.
    pub const ALL: &'static [Pairing] = &[Pairing::NodeToSegment, Pairing::NodeToNode, Pairing::SegmentToSegment];

    /// The name scene files use (`contact.pairing`).
    pub fn key(self) -> &'static str {
        match self {
            Pairing::NodeToSegment => "node_to_segment",
            Pairing::NodeToNode => "node_to_node",
            Pairing::SegmentToSegment => "segment_to_segment",
            Pairing::Automatic => "automatic",
        }
    }
}

/// The initial gap of an interface's pairs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GapDescription {
    /// The geometric distance of the paired points along the normal.
    Geometric,
    /// The same given gap for every pair (negative: an interference).
    Given(f64),
}

/// A contact interface between two curves.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactDescription {
    /// Its name (outputs are keyed by it).
    pub name: String,
    /// The master curve (1D group): its nodes are paired.
    pub master: String,
    /// The slave curve (1D group).
    pub slave: String,
    /// Whether the slave curve is a fixed, rigid obstacle (its region is no body).
    pub rigid_slave: bool,
    /// How pairs are made.
    pub pairing: Pairing,
    /// The initial gap.
    pub gap: GapDescription,
    /// Coulomb's friction coefficient μ.
    pub friction: f64,
    /// Whether master and slave may bound the same body (a body touching itself); without it
    /// such a pair is [`crate::ContactError::SameBody`]. A master point behind a slave curve of its own
    /// body is then open (its gap is its distance to the curve), never an interference.
    pub self_contact: bool,
}

/// A whole problem.
#[derive(Debug, Clone)]
pub struct ProblemDescription {
    /// The mesh.
    pub mesh: Mesh,
    /// The bodies.
    pub bodies: Vec<BodyDescription>,
    /// Prescribed displacements.
    pub fixes: Vec<FixDescription>,
    /// Edge loads.
    pub loads: Vec<LoadDescription>,
    /// Prescribed values of single nodes (with [`ProblemDescription::fixes`]).
    pub node_fixes: Vec<NodeFixDescription>,
    /// Forces on single nodes (with [`ProblemDescription::loads`]).
    pub node_loads: Vec<NodeLoadDescription>,
    /// Contact interfaces.
    pub contacts: Vec<ContactDescription>,
}

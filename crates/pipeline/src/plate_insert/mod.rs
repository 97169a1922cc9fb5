//! The flagship case: the plate with an annular insert (Solodovnikov 1998), set up on a bundled
//! mesh with the boundary conditions of the specification's section 2.
//!
//! ```text
//!   x2 = H  ───────────────── u2 = 0 ─────────────────┐
//!   │ free                                             │ u1 = w, u2 = 0 (pulled edge)
//!   │ x1 = -L1     ╭──hole──╮  insert: clamped at ρ=R2 │
//!   └─ u2 = 0 ─────╯ ◠◠◠◠◠◠ ╰────── u2 = 0 ────────────┘ x1 = L2
//! ```
//!
//! Non-dimensional: E1 = 1, lengths by R, the load factor w multiplies the pulled-edge value 1.

use contact2d_contact::{
    BuiltProblem, ContactError, ContactProblem, HistoryStep, LoadSchedule, SolverSettings, node_to_node_targets,
    pair_contours, solve_with,
};
use contact2d_element::{Formulation, Kinematics, Material, PlaneCondition};
use contact2d_fem::{Component, Model};
use contact2d_mesh::morph::move_nodes;
use contact2d_mesh::{Contour, read_msh};

mod as_preset;
mod group_geometry;
pub mod outputs;
mod placement;
pub mod preset;
pub mod published;
pub mod report;
mod results;
pub mod run;
pub mod scene;
pub use as_preset::{PRESET, PlateInsertOutcome};
pub use contact2d_contact::placement::{ContourHistory, NodePlacement, PlacedLoading, ZoneEndSearch};
pub use group_geometry::{MisplacedGroup, check_group_geometry};
pub use placement::{PlacedStep, PlateInsertFamily, place_zone_ends, solve_placed_history};
pub use results::{PLATE_HALF_HEIGHT, PlateInsertResults};
pub use scene::PlateInsertScene;

/// Which contour is the master of the pairs (the paper's two variants).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairingVariant {
    /// Pairs from the hole edge Γ_p (master) to the insert edge Γ_c.
    HoleMaster,
    /// Pairs from the insert edge Γ_c (master) to the hole edge Γ_p.
    InsertMaster,
}

/// How the initial gap of each pair is set, in displacement units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GapModel {
    /// The geometric distance of the paired points (length units) times ω = c/ε.
    Geometric,
    /// The paper's stricter replacement: u_ρc = −c(1 + cos φ)/ρ_s (variant 1, φ of the hole
    /// node) or u_rc = −c(1 + cos φ̂) (variant 2, φ̂ of the paired hole point); gap = −u_s.
    Paper,
}

/// Parameters of the flagship case.
#[derive(Debug, Clone, PartialEq)]
pub struct PlateInsert {
    /// Path of the .msh file.
    pub mesh: String,
    /// E2 / E1 (ignored for a rigid insert).
    pub stiffness_ratio: f64,
    /// The insert as a rigid, fixed contour instead of an elastic body (the rigid-pin limit of
    /// Solodovnikov 1997).
    pub rigid_insert: bool,
    /// ν1 and ν2.
    pub poissons_ratio: f64,
    /// Plane stress (the paper's thin plate) or plane strain, for both bodies.
    pub plane: PlaneCondition,
    /// Standard or B-bar elements, for both bodies (B-bar: no volumetric locking as ν → ½ in
    /// plane strain; see [`contact2d_element::formulation`]).
    pub formulation: Formulation,
    /// Pairing variant.
    pub variant: PairingVariant,
    /// ε: the mesh's geometric clearance (insert radius 1 − ε, centred at (−ε, 0)).
    pub eps: f64,
    /// c: the clearance in displacement units (ω = c/ε converts lengths to displacements).
    pub clearance: f64,
    /// How gaps are computed.
    pub gap_model: GapModel,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Node-to-segment pairs on the mesh as given, or node-to-node pairs after sliding the
    /// slave nodes to the paired points (the paper's discretisation, spec §6).
    pub pairs: PairDiscretisation,
    /// Master corner nodes moved along the master circle to given η (the paper's nodes at l*
    /// and b*; empty: the mesh as generated).
    pub placed_nodes: Vec<NodePlacement>,
}

/// How pairs are discretised.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairDiscretisation {
    /// Closest points on the slave's quadratic edges (the mesh is used as given).
    NodeToSegment,
    /// The slave contour's nodes are moved along their curve onto the paired points (mesh
    /// morphing, topology unchanged), so every pair is node-to-node.
    NodeToNode,
}

/// The built problem plus the paper's contours (for η and stresses along them). It reads as
/// the [`BuiltProblem`] it holds (`case.problem`, `case.interfaces`): the generic results and
/// writers take it as they take any scene's.
#[derive(Debug, Clone)]
pub struct PlateInsertProblem {
    /// The contact problem (unit load pattern u1 = 1 on `right`) and its one interface
    /// ([`preset::INTERFACE`]).
    pub built: BuiltProblem,
    /// The hole edge, ordered from φ = 0 to φ = π.
    pub hole: Contour,
    /// The insert edge, ordered likewise.
    pub insert: Contour,
    /// Which contour is the master.
    pub variant: PairingVariant,
    /// The mesh's ε.
    pub eps: f64,
}

impl PlateInsert {
    /// The paper's case on the mesh at `mesh`: E2 = E1, ν = 0.3, plane stress, variant 1, neat fit (ε = c = 0),
    /// the paper's gap model, no friction, node-to-node pairs, elastic insert, no placed nodes.
    /// Change fields with struct update syntax: `PlateInsert { friction: 0.3, ..PlateInsert::paper(m) }`.
    pub fn paper(mesh: impl Into<String>) -> PlateInsert {
        PlateInsert {
            mesh: mesh.into(),
            stiffness_ratio: 1.0,
            rigid_insert: false,
            poissons_ratio: 0.3,
            plane: PlaneCondition::Stress,
            formulation: Formulation::Standard,
            variant: PairingVariant::HoleMaster,
            eps: 0.0,
            clearance: 0.0,
            gap_model: GapModel::Paper,
            friction: 0.0,
            pairs: PairDiscretisation::NodeToNode,
            placed_nodes: vec![],
        }
    }

    /// Builds the model, the pairs and the contact problem: through the generic description
    /// ([`PlateInsert::description`], the library's one builder) unless nodes are placed.
    ///
    /// # Errors
    /// Mesh, model or pairing errors.
    pub fn build(&self) -> Result<PlateInsertProblem, ContactError> {
        self.build_on(read_msh(&self.mesh)?)
    }

    /// Like [`PlateInsert::build`] on a mesh already read (`self.mesh` is not read again): a
    /// search that places nodes builds many problems from one generated mesh.
    ///
    /// # Errors
    /// Model or pairing errors, or a placement outside its corner's range.
    pub fn build_on(&self, mesh: contact2d_mesh::Mesh) -> Result<PlateInsertProblem, ContactError> {
        if self.placed_nodes.is_empty() {
            // The generic description, built by the library's one builder (preset.rs).
            return self.build_preset(mesh);
        }
        self.build_reusing(mesh, None)
    }

    /// Like [`PlateInsert::build_on`], reusing the symbolic factorisation of `previous` (a
    /// problem of the same mesh topology, e.g. before its nodes were moved): only the numeric
    /// factorisation is redone.
    ///
    /// # Errors
    /// As [`PlateInsert::build_on`], or a DOF numbering or sparsity pattern that differs from
    /// `previous`'s.
    pub fn build_reusing(
        &self,
        mut mesh: contact2d_mesh::Mesh,
        previous: Option<&ContactProblem>,
    ) -> Result<PlateInsertProblem, ContactError> {
        if !self.placed_nodes.is_empty() {
            // The master contour is read off the mesh; no model is needed to move its nodes.
            let group = match self.variant {
                PairingVariant::HoleMaster => "hole_edge",
                PairingVariant::InsertMaster => "insert_edge",
            };
            let master = Contour::from_group(&mesh, group)?;
            let targets = self.placement_targets(&mesh, &master)?;
            move_nodes(&mut mesh, &targets, 2)?;
        }
        let (mut model, mut hole, mut insert_edge) = self.model(mesh.clone())?;
        if self.pairs == PairDiscretisation::NodeToNode {
            // Pair once node-to-segment, slide the slave nodes to the paired points, pair again
            // (the model moved with them: the same model as built on the moved mesh).
            let targets = {
                let (pairs, slave) = self.pair(&model, &hole, &insert_edge)?;
                node_to_node_targets(&pairs, slave)?
            };
            move_nodes(&mut mesh, &targets, 2)?;
            model.move_points(mesh.points)?;
            hole = Contour::from_group(&model.mesh, "hole_edge")?;
            insert_edge = Contour::from_group(&model.mesh, "insert_edge")?;
        }
        let (pairs, _) = self.pair(&model, &hole, &insert_edge)?;
        let mut problem = if let Some(previous) = previous {
            previous.rebuild_moved(model, pairs)?
        } else if self.rigid_insert {
            ContactProblem::with_rigid_slave(model, pairs)?
        } else {
            ContactProblem::new(model, pairs)?
        };
        problem.set_gaps(self.gaps(&problem)?)?;
        problem.set_friction(self.friction)?;
        let interfaces = vec![self.interface_info(&problem, &hole, &insert_edge)];
        let built = BuiltProblem { problem, interfaces };
        Ok(PlateInsertProblem { built, hole, insert: insert_edge, variant: self.variant, eps: self.eps })
    }

    /// New positions of the placed master corners (on the master circle) and of the mid nodes
    /// of their edges, re-centred between the corners once every corner is placed.
    fn placement_targets(
        &self,
        mesh: &contact2d_mesh::Mesh,
        master: &Contour,
    ) -> Result<Vec<(contact2d_mesh::NodeId, [f64; 2])>, ContactError> {
        let (centre, radius) = self.master_circle();
        let at = |a: f64| [centre + radius * a.cos(), radius * a.sin()];
        let n = master.nodes.len();
        if n < 5 || !master.edges.iter().all(|e| e.quadratic) {
            return Err(ContactError::InvalidInput("node placement needs a quadratic master contour".into()));
        }
        let generated: Vec<f64> = master.nodes.iter().map(|v| polar_angle(mesh.points[v.0], centre)).collect();
        let mut angles = generated.clone();
        let mut corners: Vec<usize> = vec![];
        for placement in &self.placed_nodes {
            let (eta, c) = (placement.eta, placement.corner);
            if c % 2 != 0 || c < 2 || c + 2 >= n {
                return Err(ContactError::InvalidInput(format!(
                    "placed node: {c} is not an interior corner of the {n}-node master contour"
                )));
            }
            if corners.contains(&c) {
                return Err(ContactError::InvalidInput(format!("placed node: corner {c} placed twice")));
            }
            let target = std::f64::consts::PI * (1.0 - eta);
            let (lo, hi) = (generated[c - 2].min(generated[c + 2]), generated[c - 2].max(generated[c + 2]));
            if !(target > lo && target < hi) {
                return Err(ContactError::InvalidInput(format!(
                    "placed node at η = {eta} is outside the range of corner {c} (η {:.5} to {:.5})",
                    1.0 - hi / std::f64::consts::PI,
                    1.0 - lo / std::f64::consts::PI
                )));
            }
            angles[c] = target;
            corners.push(c);
        }
        // Corners must keep their order along the contour (two placed corners may be neighbours).
        let ascending = generated[n - 1] > generated[0];
        if !(0..n / 2).all(|i| (angles[2 * i + 2] > angles[2 * i]) == ascending) {
            return Err(ContactError::InvalidInput(format!(
                "placed nodes would reorder the master contour's corners ({:?})",
                self.placed_nodes
            )));
        }
        let mut moved: Vec<usize> = corners.iter().flat_map(|&c| [c - 1, c, c + 1]).collect();
        moved.sort_unstable();
        moved.dedup();
        for &i in &moved {
            if i % 2 == 1 {
                angles[i] = 0.5 * (angles[i - 1] + angles[i + 1]);
            }
        }
        Ok(moved.into_iter().map(|i| (master.nodes[i], at(angles[i]))).collect())
    }

    /// Centre (on the x1 axis) and radius of the master circle: the hole (0, 1) or the insert
    /// edge (−ε, 1 − ε).
    fn master_circle(&self) -> (f64, f64) {
        match self.variant {
            PairingVariant::HoleMaster => (0.0, 1.0),
            PairingVariant::InsertMaster => (-self.eps, 1.0 - self.eps),
        }
    }

    /// The model of the two bodies with the boundary conditions of spec §2, and both contours.
    fn model(&self, mesh: contact2d_mesh::Mesh) -> Result<(Model, Contour, Contour), ContactError> {
        let mut model = Model::new(mesh);
        let plate = Material::new(1.0, self.poissons_ratio).map_err(fem_input)?;
        let insert = Material::new(self.stiffness_ratio, self.poissons_ratio).map_err(fem_input)?;
        let kinematics = Kinematics::plane(self.plane, 1.0).map_err(fem_input)?;
        model.add_body_in("plate", plate, kinematics, self.formulation)?;
        for group in ["top", "bottom_plate", "right"] {
            model.fix(group, Component::Y, 0.0)?;
        }
        model.fix("right", Component::X, 1.0)?;
        if !self.rigid_insert {
            model.add_body_in("insert", insert, kinematics, self.formulation)?;
            model.fix("insert_inner", Component::X, 0.0)?;
            model.fix("insert_inner", Component::Y, 0.0)?;
            model.fix("insert_symmetry", Component::Y, 0.0)?;
        }
        let hole = Contour::from_group(&model.mesh, "hole_edge")?;
        let insert_edge = Contour::from_group(&model.mesh, "insert_edge")?;
        Ok((model, hole, insert_edge))
    }

    /// The pairs of the chosen variant and the slave contour.
    fn pair<'c>(
        &self,
        model: &Model,
        hole: &'c Contour,
        insert: &'c Contour,
    ) -> Result<(Vec<contact2d_contact::ContactPair>, &'c Contour), ContactError> {
        Ok(match self.variant {
            PairingVariant::HoleMaster => (pair_contours(model, hole, insert, "insert")?, insert),
            PairingVariant::InsertMaster => (pair_contours(model, insert, hole, "plate")?, hole),
        })
    }

    /// The gap of every pair under [`PlateInsert::gap_model`], in displacement units.
    fn gaps(&self, problem: &ContactProblem) -> Result<Vec<f64>, ContactError> {
        if !(self.eps >= 0.0 && self.clearance >= 0.0 && self.eps.is_finite() && self.clearance.is_finite()) {
            return Err(ContactError::InvalidInput(format!(
                "eps = {} and c = {} must be finite and non-negative",
                self.eps, self.clearance
            )));
        }
        if self.eps == 0.0 {
            // Neat fit: the contours coincide; any clearance would be a contradiction.
            return if self.clearance == 0.0 {
                Ok(vec![0.0; problem.num_pairs()])
            } else {
                Err(ContactError::InvalidInput("c > 0 needs a mesh with eps > 0".into()))
            };
        }
        let omega = self.clearance / self.eps;
        Ok(problem
            .pairs
            .iter()
            .zip(&problem.gap)
            .map(|(pair, geometric)| match (self.gap_model, self.variant) {
                (GapModel::Geometric, _) => geometric * omega,
                (GapModel::Paper, PairingVariant::HoleMaster) => {
                    let phi = angle(problem.model.mesh.points[pair.master.0]);
                    let rho_s = (1.0 + 2.0 * self.eps * phi.cos() + self.eps * self.eps).sqrt();
                    self.clearance * (1.0 + phi.cos()) / rho_s
                }
                (GapModel::Paper, PairingVariant::InsertMaster) => {
                    self.clearance * (1.0 + angle(pair.slave_point).cos())
                }
            })
            .collect())
    }
}

/// Polar angle about the hole centre.
fn angle(x: [f64; 2]) -> f64 {
    x[1].atan2(x[0])
}

/// Polar angle about the point (`centre`, 0).
fn polar_angle(x: [f64; 2], centre: f64) -> f64 {
    x[1].atan2(x[0] - centre)
}

impl std::ops::Deref for PlateInsertProblem {
    type Target = BuiltProblem;

    fn deref(&self) -> &BuiltProblem {
        &self.built
    }
}

impl PlateInsertProblem {
    /// The master contour (the hole edge in variant 1, the insert edge in variant 2).
    pub fn master(&self) -> &Contour {
        match self.variant {
            PairingVariant::HoleMaster => &self.hole,
            PairingVariant::InsertMaster => &self.insert,
        }
    }

    /// η of each master contour node on the master's own coordinate, in contour order.
    pub fn master_node_eta(&self) -> Vec<f64> {
        let points = &self.problem.model.mesh.points;
        self.master().nodes.iter().map(|v| self.eta_of_master_point(points[v.0])).collect()
    }

    /// η of a point on the master circle, on the master's own coordinate.
    pub(crate) fn eta_of_master_point(&self, x: [f64; 2]) -> f64 {
        match self.variant {
            PairingVariant::HoleMaster => eta_on_hole(x),
            PairingVariant::InsertMaster => eta_on_hole([x[0] + self.eps, x[1]]),
        }
    }

    /// η = 1 − φ/π on the hole edge of each pair: the master node's in variant 1, the paired
    /// hole point's in variant 2 (the paper reports l and b on this coordinate).
    pub fn eta_hole(&self) -> Vec<f64> {
        let p = &self.problem;
        p.pairs
            .iter()
            .map(|pair| match self.variant {
                PairingVariant::HoleMaster => eta_on_hole(p.model.mesh.points[pair.master.0]),
                PairingVariant::InsertMaster => eta_on_hole(pair.slave_point),
            })
            .collect()
    }

    /// η of each master node on its own contour: 1 − φ/π (variant 1) or 1 − θ̂/π with θ̂ the
    /// polar angle about the insert centre (−ε, 0) (variant 2).
    pub fn eta_master(&self) -> Vec<f64> {
        let p = &self.problem;
        p.pairs.iter().map(|pair| self.eta_of_master_point(p.model.mesh.points[pair.master.0])).collect()
    }

    /// Solves the loads `w_1, w_2, …` (the factors of the pulled edge's unit pattern) in order
    /// through the library's one entry [`contact2d_contact::solve_with`], with any algorithm;
    /// `on_step(w)` after each step. Each solution's load factor is its w (the library's is 1,
    /// the pattern factor carrying the load), as [`PlateInsertProblem::results`] expects.
    ///
    /// # Errors
    /// Those of [`contact2d_contact::solve_with`].
    pub fn solve_loads(
        &self,
        settings: &SolverSettings,
        loads: &[f64],
        on_step: &mut dyn FnMut(f64),
    ) -> Result<Vec<HistoryStep>, ContactError> {
        let pattern = self.problem.patterns()[0].name.clone();
        let schedule = LoadSchedule::new(vec![pattern], loads.iter().map(|w| vec![*w]).collect())?;
        let solved = solve_with(&self.problem, settings, &schedule, &mut |_, s| on_step(s.factors[0]))?;
        Ok(solved
            .steps
            .into_iter()
            .map(|s| {
                let mut solution = s.solution;
                solution.load_factor = s.factors[0];
                HistoryStep { solution, dissipated: s.dissipated }
            })
            .collect())
    }
}

fn fem_input(e: contact2d_element::ElementError) -> ContactError {
    ContactError::InvalidInput(e.to_string())
}

/// η = 1 − φ/π of a point about the hole centre (0 at (−R, 0), 1 at (R, 0)).
pub fn eta_on_hole(x: [f64; 2]) -> f64 {
    1.0 - x[1].atan2(x[0]) / std::f64::consts::PI
}

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

use contact2d_contact::{ContactError, ContactProblem, pair_contours};
use contact2d_element::{Material, PlaneCondition};
use contact2d_fem::{Component, Model};
use contact2d_mesh::{Contour, read_msh};

/// Which contour is the master of the pairs (the paper's two variants).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairingVariant {
    /// Pairs from the hole edge Γ_p (master) to the insert edge Γ_c.
    HoleMaster,
    /// Pairs from the insert edge Γ_c (master) to the hole edge Γ_p.
    InsertMaster,
}

/// Parameters of the flagship case.
#[derive(Debug, Clone, PartialEq)]
pub struct PlateInsert {
    /// Path of the .msh file.
    pub mesh: String,
    /// E2 / E1.
    pub stiffness_ratio: f64,
    /// ν1 and ν2.
    pub poissons_ratio: f64,
    /// Pairing variant.
    pub variant: PairingVariant,
}

/// The problem plus the master contour (for η and stresses along it).
#[derive(Debug, Clone)]
pub struct PlateInsertProblem {
    /// The contact problem (unit load pattern u1 = 1 on `right`).
    pub problem: ContactProblem,
    /// The hole edge, ordered from φ = 0 to φ = π.
    pub hole: Contour,
    /// The insert edge, ordered likewise.
    pub insert: Contour,
}

impl PlateInsert {
    /// Builds the model, the pairs and the contact problem.
    ///
    /// # Errors
    /// Mesh, model or pairing errors.
    pub fn build(&self) -> Result<PlateInsertProblem, ContactError> {
        let mesh = read_msh(&self.mesh)?;
        let mut model = Model::new(mesh);
        let plate = Material::new(1.0, self.poissons_ratio, PlaneCondition::Stress).map_err(fem_input)?;
        let insert =
            Material::new(self.stiffness_ratio, self.poissons_ratio, PlaneCondition::Stress).map_err(fem_input)?;
        model.add_body("plate", plate, 1.0)?;
        model.add_body("insert", insert, 1.0)?;
        for group in ["top", "bottom_plate", "right", "insert_inner", "insert_symmetry"] {
            model.fix(group, Component::Y, 0.0)?;
        }
        model.fix("right", Component::X, 1.0)?;
        model.fix("insert_inner", Component::X, 0.0)?;
        let hole = Contour::from_group(&model.mesh, "hole_edge")?;
        let insert_edge = Contour::from_group(&model.mesh, "insert_edge")?;
        let pairs = match self.variant {
            PairingVariant::HoleMaster => pair_contours(&model, &hole, &insert_edge, "insert")?,
            PairingVariant::InsertMaster => pair_contours(&model, &insert_edge, &hole, "plate")?,
        };
        Ok(PlateInsertProblem { problem: ContactProblem::new(model, pairs)?, hole, insert: insert_edge })
    }
}

fn fem_input(e: contact2d_element::ElementError) -> ContactError {
    ContactError::InvalidInput(e.to_string())
}

/// η = 1 − φ/π of a point about the hole centre (0 at (−R, 0), 1 at (R, 0)).
pub fn eta_on_hole(x: [f64; 2]) -> f64 {
    1.0 - x[1].atan2(x[0]) / std::f64::consts::PI
}

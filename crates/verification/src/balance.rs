//! Global equilibrium: the reactions and the applied loads of a solved model sum to zero.
//!
//! ```text
//! K u = f + r  (r nonzero only at constrained DOFs)   ⇒   Σ_i (f_i + r_i) = 1ᵀ K u = (K 1)ᵀ u = 0
//! for 1 = a rigid translation or rotation, which K annihilates:
//!   F = Σ_n (f_n + r_n)                      = 0     (both components)
//!   M = Σ_n (x_n - o) × (f_n + r_n)          = 0     (× the scalar 2D cross product)
//! ```
//!
//! Two models: the Lamé quarter cylinder of [`crate::lame`] under internal pressure
//! (resultant of the pressure `p a (1, 1)`, moment about the centre zero, both exact for any
//! chain of edges whose end nodes lie on the arc) and a cantilever with an end shear.

use contact2d_element::{Kinematics, Material, PlaneCondition};
use contact2d_fem::{Component, EdgeLoad, LinearSystem, Model, Solution, solve_linear};
use contact2d_mesh::CellKind;
use contact2d_mesh::generate::rectangle;

use crate::VerifyError;
use crate::lame::{LameSetup, lame_model};

/// Resultants of the applied loads and the reactions, about a reference point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Balance {
    /// `Σ f_n`: resultant of the consistent nodal loads.
    pub load: [f64; 2],
    /// `Σ (x_n - o) × f_n`.
    pub load_moment: f64,
    /// `Σ r_n`: resultant of the reactions.
    pub reaction: [f64; 2],
    /// `Σ (x_n - o) × r_n`.
    pub reaction_moment: f64,
}

impl Balance {
    /// `|load + reaction|` per component, relative to `|load|`.
    pub fn relative_force_residual(&self) -> [f64; 2] {
        let scale = self.load[0].hypot(self.load[1]);
        [(self.load[0] + self.reaction[0]).abs() / scale, (self.load[1] + self.reaction[1]).abs() / scale]
    }

    /// `|M_load + M_reaction|` relative to `|load| × length`.
    pub fn relative_moment_residual(&self, length: f64) -> f64 {
        (self.load_moment + self.reaction_moment).abs() / (self.load[0].hypot(self.load[1]) * length)
    }
}

/// Sums the loads and reactions of a solved model about `origin`.
pub fn global_balance(model: &Model, system: &LinearSystem, solution: &Solution, origin: [f64; 2]) -> Balance {
    let mut out = Balance { load: [0.0; 2], load_moment: 0.0, reaction: [0.0; 2], reaction_moment: 0.0 };
    for (n, x) in model.mesh.points.iter().enumerate() {
        let (dx, dy) = (x[0] - origin[0], x[1] - origin[1]);
        let f = [system.load[2 * n], system.load[2 * n + 1]];
        let r = [solution.reactions[2 * n], solution.reactions[2 * n + 1]];
        out.load[0] += f[0];
        out.load[1] += f[1];
        out.load_moment += dx * f[1] - dy * f[0];
        out.reaction[0] += r[0];
        out.reaction[1] += r[1];
        out.reaction_moment += dx * r[1] - dy * r[0];
    }
    out
}

/// The Lamé quarter cylinder of `setup` with `n_radial` cells radially, solved; balance about the
/// centre of the cylinder.
///
/// # Errors
/// Model or solver failures.
pub fn lame_balance(
    kind: CellKind,
    plane: PlaneCondition,
    n_radial: usize,
    setup: &LameSetup,
) -> Result<Balance, VerifyError> {
    let (model, _) = lame_model(kind, plane, n_radial, setup)?;
    let (system, _, solution) = solve_linear(&model)?;
    Ok(global_balance(&model, &system, &solution, [0.0, 0.0]))
}

/// The cantilever of the balance test: `[0, length] × [0, depth]`, clamped on `x1 = 0`
/// (`u1 = u2 = 0`), uniform shear traction `(0, -shear)` on `x1 = length`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cantilever {
    /// Length `L`.
    pub length: f64,
    /// Depth `c`.
    pub depth: f64,
    /// Shear traction `τ` on the free end (acting downward).
    pub shear: f64,
}

impl Cantilever {
    /// Resultant of the applied traction: `(0, -τ c)`.
    pub fn load(&self) -> [f64; 2] {
        [0.0, -self.shear * self.depth]
    }

    /// Moment of the applied traction about the origin: `∫ x1 t2 ds = -τ c L`.
    pub fn load_moment(&self) -> f64 {
        -self.shear * self.depth * self.length
    }
}

/// Solves the cantilever with `nx × ny` cells of `kind`; balance about the origin.
///
/// # Errors
/// Model or solver failures.
pub fn cantilever_balance(
    kind: CellKind,
    plane: PlaneCondition,
    beam: &Cantilever,
    nx: usize,
    ny: usize,
) -> Result<Balance, VerifyError> {
    let mut model = Model::new(rectangle(kind, [0.0, beam.length], [0.0, beam.depth], nx, ny));
    model.add_body("domain", Material::new(200e3, 0.3)?, Kinematics::plane(plane, 1.0)?)?;
    model.fix("left", Component::X, 0.0)?;
    model.fix("left", Component::Y, 0.0)?;
    model.add_edge_load(EdgeLoad::Traction { group: "right".into(), traction: [0.0, -beam.shear] })?;
    let (system, _, solution) = solve_linear(&model)?;
    Ok(global_balance(&model, &system, &solution, [0.0, 0.0]))
}

/// One solved model of the balance check, with the closed-form resultants of its loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BalanceCase {
    /// Which model: `"Lamé quarter"` or `"cantilever"`.
    pub model: &'static str,
    /// Cell kind.
    pub kind: CellKind,
    /// Plane condition.
    pub plane: PlaneCondition,
    /// The sums.
    pub balance: Balance,
    /// Length scale of the moment residual.
    pub length: f64,
    /// Closed-form resultant of the applied loads.
    pub expected_load: [f64; 2],
    /// Closed-form moment of the applied loads about the origin.
    pub expected_load_moment: f64,
}

/// The cantilever of [`balance_cases`].
pub const CANTILEVER: Cantilever = Cantilever { length: 5.0, depth: 1.0, shear: 10.0 };

/// The cell kinds of the standard studies.
pub const KINDS: [CellKind; 5] = [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9];

/// Both plane conditions.
pub const PLANES: [PlaneCondition; 2] = [PlaneCondition::Stress, PlaneCondition::Strain];

/// Every kind in both plane conditions on the Lamé quarter (4 × 8 cells) and the cantilever
/// (10 × 2 cells).
///
/// # Errors
/// Model or solver failures.
pub fn balance_cases() -> Result<Vec<BalanceCase>, VerifyError> {
    let setup = LameSetup::default();
    let (a, p) = (setup.inner_radius, setup.pressure);
    let mut cases = vec![];
    for kind in KINDS {
        for plane in PLANES {
            cases.push(BalanceCase {
                model: "Lamé quarter",
                kind,
                plane,
                balance: lame_balance(kind, plane, 4, &setup)?,
                length: setup.outer_radius,
                expected_load: [p * a, p * a],
                expected_load_moment: 0.0,
            });
            cases.push(BalanceCase {
                model: "cantilever",
                kind,
                plane,
                balance: cantilever_balance(kind, plane, &CANTILEVER, 10, 2)?,
                length: CANTILEVER.length,
                expected_load: CANTILEVER.load(),
                expected_load_moment: CANTILEVER.load_moment(),
            });
        }
    }
    Ok(cases)
}

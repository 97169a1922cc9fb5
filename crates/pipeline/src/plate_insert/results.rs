//! The paper's reported quantities of one contact solution of the plate with insert.
//!
//! ```text
//! P     = Σ reactions in x1 on the pulled edge x1 = L2       (= ∫_0^H σ11 dx2)
//! Φ_E1, Φ_E2 = strain energies of plate and insert (Φ_E2 = 0 for a rigid insert)
//! l     = contact end on η = 1 − φ/π of the hole edge (gap^{2/3} interpolation, see contact::post)
//! b     = stick end likewise (slip^{2/3} interpolation)
//! σ*    = max over the hole edge of σ_φφ (Gauss-point stresses extrapolated to the nodes, averaged)
//! K     = H σ* / P,  H = 2.5
//! ```

use contact2d_contact::{ContactError, ContactSolution, PairState, contact_end, fem_solution, stick_end};
use contact2d_fem::{BodyId, StressRecovery, strain_energy, stresses_along_curve};

use super::PlateInsertProblem;

/// Plate height H of the paper's geometry (non-dimensional).
pub const PLATE_HALF_HEIGHT: f64 = 2.5;

/// The paper's quantities of one solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateInsertResults {
    /// Pulling force P.
    pub pull: f64,
    /// Strain energy of the plate Φ_E1.
    pub energy_plate: f64,
    /// Strain energy of the insert Φ_E2.
    pub energy_insert: f64,
    /// Contact end l on the hole-edge angle (`None` if nothing or everything is in contact).
    pub contact_end: Option<f64>,
    /// The mesh bracket of l: last contact and first free η.
    pub contact_bracket: Option<[f64; 2]>,
    /// End b of the stick zone on the hole-edge angle (= l when nothing slips).
    pub stick_end: Option<f64>,
    /// The mesh bracket of b: last stick and first slipping η.
    pub stick_bracket: Option<[f64; 2]>,
    /// Energy dissipated in the solution's step (the whole loading for a one-step solve).
    pub dissipation: f64,
    /// Contact end on the master's own coordinate (differs from `contact_end` in variant 2).
    pub contact_end_master: Option<f64>,
    /// σ*: the largest hoop stress on the hole edge.
    pub sigma_star: f64,
    /// K = H σ* / P.
    pub stress_concentration: f64,
    /// Largest hoop stress of the insert on its outer edge (`None` for a rigid insert).
    pub insert_hoop_max: Option<f64>,
}

impl PlateInsertProblem {
    /// Evaluates the paper's quantities for `solution`.
    ///
    /// # Errors
    /// Mesh or element failures in the post-processing.
    pub fn results(&self, solution: &ContactSolution) -> Result<PlateInsertResults, ContactError> {
        let p = &self.problem;
        let u = &solution.displacement;
        let pull = fem_solution(p, solution).reaction_resultant(&p.model, "right")?[0];
        let energy_plate = strain_energy(&p.model, BodyId(0), u)?;
        let insert = p.model.body("insert").map(|(id, _)| id);
        let energy_insert = match insert {
            Some(id) => strain_energy(&p.model, id, u)?,
            None => 0.0,
        };
        let end = contact_end(&self.eta_hole(), &solution.gap, &solution.state);
        let end_master = contact_end(&self.eta_master(), &solution.gap, &solution.state);
        let slips = solution.state.iter().any(|s| matches!(s, PairState::SlipPositive | PairState::SlipNegative));
        let stick = if slips { stick_end(&self.eta_hole(), &solution.slip_increment, &solution.state) } else { end };
        let hoop_max = |body: BodyId, contour| -> Result<f64, ContactError> {
            let samples = stresses_along_curve(&p.model, body, contour, u, StressRecovery::Extrapolated)?;
            Ok(samples.iter().map(|s| s.tangential_stress()).fold(f64::NEG_INFINITY, f64::max))
        };
        let sigma_star = hoop_max(BodyId(0), &self.hole)?;
        Ok(PlateInsertResults {
            pull,
            energy_plate,
            energy_insert,
            contact_end: end.map(|e| e.0),
            contact_bracket: end.map(|e| e.1),
            stick_end: stick.map(|e| e.0),
            stick_bracket: stick.map(|e| e.1),
            dissipation: solution.dissipation,
            contact_end_master: end_master.map(|e| e.0),
            sigma_star,
            stress_concentration: PLATE_HALF_HEIGHT * sigma_star / pull,
            insert_hoop_max: match insert {
                Some(id) => Some(hoop_max(id, &self.insert)?),
                None => None,
            },
        })
    }
}

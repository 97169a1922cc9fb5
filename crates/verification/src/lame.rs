//! The Lamé thick-walled cylinder under internal pressure: h-convergence of the displacement.
//!
//! ```text
//!   x2
//!    ^  end (θ = 90°): u1 = 0
//!  b +-- _
//!    |     ~ .                   quarter annulus a ≤ r ≤ b, 0 ≤ θ ≤ 90°
//!  a +- .      .                 nr cells radially, 2 nr around (annulus_sector: the nodes of
//!    |    \      \               quadratic cells lie on the exact arcs)
//!    |  p  |  --> |  outer free  internal pressure p on the inner arc (pushes outward)
//!    +-----+------+--> x1
//!    0     a      b    start (θ = 0): u2 = 0
//!
//!   h = (b - a)/nr,  nr = 4, 8, 16, 32, 64 (T3, Q4) or 2, 4, 8, 16, 32 (T6, Q8, Q9)
//! ```
//!
//! Measured: relative L2 and energy-norm errors against [`LameCylinder`] (see
//! [`crate::norms`]) and the radial stress at the inner wall from the extrapolated
//! nodal stresses, which must tend to `-p`. A priori estimates for elements of degree `k`
//! reproducing the complete polynomials of degree `k` on a smooth (asymptotically affine) mesh
//! family: `‖e‖_L2 = O(h^{k+1})`, `‖e‖_E = O(h^k)`; the isoparametric boundary (chords for
//! degree 1, parabolas for degree 2) perturbs the domain by `O(h^{k+1})`, which keeps both rates
//! (Ciarlet & Raviart 1972; Strang & Fix 1973, ch. 4).

use contact2d_element::{Formulation, GaussRule, Kinematics, Material, PlaneCondition, map_point, stress_state_at};
use contact2d_fem::{BodyId, Component, EdgeLoad, Model, Solution, StressRecovery, nodal_stresses, solve_linear};
use contact2d_mesh::CellKind;
use contact2d_mesh::generate::annulus_sector;

use crate::VerifyError;
use crate::analytic::{LameCylinder, cartesian_to_polar};
use crate::norms::{ErrorNorms, convergence_rate, error_norms, error_rule};

/// Geometry, load and material of the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LameSetup {
    /// Inner radius `a`.
    pub inner_radius: f64,
    /// Outer radius `b`.
    pub outer_radius: f64,
    /// Internal pressure `p`.
    pub pressure: f64,
    /// Young's modulus `E`.
    pub youngs_modulus: f64,
    /// Poisson's ratio `ν`.
    pub poissons_ratio: f64,
    /// Circumferential cells per radial cell.
    pub cells_around_per_radial: usize,
    /// Standard or B-bar elements.
    pub formulation: Formulation,
}

impl Default for LameSetup {
    fn default() -> Self {
        LameSetup {
            inner_radius: 1.0,
            outer_radius: 2.0,
            pressure: 100.0,
            youngs_modulus: 200e3,
            poissons_ratio: 0.3,
            cells_around_per_radial: 2,
            formulation: Formulation::Standard,
        }
    }
}

impl LameSetup {
    /// The closed form for this setup.
    ///
    /// # Errors
    /// As [`LameCylinder::new`].
    pub fn exact(&self, plane: PlaneCondition) -> Result<LameCylinder, VerifyError> {
        LameCylinder::new(
            self.inner_radius,
            self.outer_radius,
            self.pressure,
            self.youngs_modulus,
            self.poissons_ratio,
            plane,
        )
    }
}

/// The radial cell counts of the standard study: four halvings of `h`, starting coarser for the
/// quadratic kinds so that the finest meshes stay small.
pub fn standard_levels(kind: CellKind) -> Vec<usize> {
    match kind {
        CellKind::Tri3 | CellKind::Quad4 => vec![4, 8, 16, 32, 64],
        _ => vec![2, 4, 8, 16, 32],
    }
}

/// The quarter-cylinder model of the module docs with `n_radial` cells radially.
///
/// # Errors
/// A non-2D kind, a zero cell count, or model failures.
pub fn lame_model(
    kind: CellKind,
    plane: PlaneCondition,
    n_radial: usize,
    setup: &LameSetup,
) -> Result<(Model, BodyId), VerifyError> {
    if n_radial == 0 || setup.cells_around_per_radial == 0 {
        return Err(VerifyError::InvalidParameter("the Lamé mesh needs at least one cell each way".into()));
    }
    let mesh = annulus_sector(
        kind,
        [setup.inner_radius, setup.outer_radius],
        [0.0, std::f64::consts::FRAC_PI_2],
        n_radial,
        setup.cells_around_per_radial * n_radial,
    );
    let mut model = Model::new(mesh);
    let material = Material::new(setup.youngs_modulus, setup.poissons_ratio)?;
    let body = model.add_body_in("domain", material, Kinematics::plane(plane, 1.0)?, setup.formulation)?;
    model.fix("start", Component::Y, 0.0)?;
    model.fix("end", Component::X, 0.0)?;
    model.add_edge_load(EdgeLoad::Pressure { group: "inner".into(), pressure: setup.pressure })?;
    Ok((model, body))
}

/// One mesh of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LameLevel {
    /// Cells radially.
    pub n_radial: usize,
    /// Cells circumferentially.
    pub n_around: usize,
    /// Mesh size `(b - a)/n_radial`.
    pub h: f64,
    /// Free DOFs.
    pub dofs: usize,
    /// Error norms.
    pub norms: ErrorNorms,
    /// `max |σ_rr + p| / p` over the inner-wall nodes (extrapolated nodal stresses).
    pub inner_radial_stress_error: f64,
    /// `max |σ_θθ − σ_θθ(a)| / σ_θθ(a)` over the inner-wall nodes (extrapolated nodal stresses).
    pub inner_hoop_stress_error: f64,
    /// `‖σ_h − σ‖_L2 / ‖σ‖_L2` of the element stresses (the body's formulation) over the domain.
    pub relative_stress_l2: f64,
}

/// Solves one mesh and measures it.
///
/// # Errors
/// Model, solver or element failures.
pub fn solve_lame(
    kind: CellKind,
    plane: PlaneCondition,
    n_radial: usize,
    setup: &LameSetup,
) -> Result<(LameLevel, Model, Solution), VerifyError> {
    let exact = setup.exact(plane)?;
    let (model, body) = lame_model(kind, plane, n_radial, setup)?;
    let (system, _, solution) = solve_linear(&model)?;
    let norms = error_norms(&model, body, &solution.displacement, &exact)?;
    let stresses = nodal_stresses(&model, body, &solution.displacement, StressRecovery::Extrapolated)?;
    let (mut wall_error, mut hoop_error) = (0.0f64, 0.0f64);
    let hoop_exact = exact.hoop_stress(setup.inner_radius);
    for n in model.mesh.group_nodes("inner").map_err(contact2d_fem::FemError::from)? {
        if let Some(s) = stresses[n.0] {
            let x = model.mesh.points[n.0];
            let r = x[0].hypot(x[1]);
            let (s_rr, s_tt, _) = cartesian_to_polar(s, x[0] / r, x[1] / r);
            wall_error = wall_error.max((s_rr + setup.pressure).abs() / setup.pressure.abs());
            hoop_error = hoop_error.max((s_tt - hoop_exact).abs() / hoop_exact.abs());
        }
    }
    let level = LameLevel {
        n_radial,
        n_around: setup.cells_around_per_radial * n_radial,
        h: (setup.outer_radius - setup.inner_radius) / n_radial as f64,
        dofs: system.dofs.num_free(),
        norms,
        inner_radial_stress_error: wall_error,
        inner_hoop_stress_error: hoop_error,
        relative_stress_l2: stress_l2_error(&model, body, &solution.displacement, &exact)?,
    };
    Ok((level, model, solution))
}

/// `‖σ_h − σ‖_L2 / ‖σ‖_L2` (Voigt components, unit weights) with the stresses of the body's
/// formulation, integrated with the error rule of [`crate::norms::error_rule`].
fn stress_l2_error(model: &Model, body: BodyId, u: &[f64], exact: &LameCylinder) -> Result<f64, VerifyError> {
    let b = &model.bodies[body.0];
    let (mut err, mut norm) = (0.0, 0.0);
    for i in 0..b.num_cells() {
        let element = b.elements[i];
        let coords = b.cell_coords(&model.mesh, i);
        let ue: Vec<f64> = b.cell_dofs(i).map(|d| u[d.0]).collect();
        let rule: GaussRule = error_rule(element)?;
        for (xi, w) in rule.points.iter().zip(&rule.weights) {
            let p = map_point(element, &coords, *xi)?;
            let [s11, s22, s12, _] =
                stress_state_at(element, &coords, &b.material, &b.kinematics, &ue, *xi, b.formulation)?;
            let sh = [s11, s22, s12];
            let se = exact.stress(p.x);
            let f = w * p.det_j;
            err += f * (0..3).map(|k| (sh[k] - se[k]).powi(2)).sum::<f64>();
            norm += f * se.iter().map(|v| v * v).sum::<f64>();
        }
    }
    Ok((err / norm).sqrt())
}

/// A sequence of meshes of one element kind and plane condition.
#[derive(Debug, Clone, PartialEq)]
pub struct LameStudy {
    /// Cell kind.
    pub kind: CellKind,
    /// Plane condition.
    pub plane: PlaneCondition,
    /// The meshes, coarse to fine.
    pub levels: Vec<LameLevel>,
}

impl LameStudy {
    /// Observed L2 rates between consecutive meshes.
    pub fn l2_rates(&self) -> Vec<f64> {
        self.rates(|l| l.norms.relative_l2())
    }

    /// Observed energy-norm rates between consecutive meshes.
    pub fn energy_rates(&self) -> Vec<f64> {
        self.rates(|l| l.norms.relative_energy())
    }

    /// Observed rates of the stress L2 error between consecutive meshes.
    pub fn stress_l2_rates(&self) -> Vec<f64> {
        self.rates(|l| l.relative_stress_l2)
    }

    /// Observed rates of the inner-wall radial stress error between consecutive meshes.
    pub fn wall_stress_rates(&self) -> Vec<f64> {
        self.rates(|l| l.inner_radial_stress_error)
    }

    /// Observed rates of any error measure between consecutive meshes:
    /// `q = ln(e1/e2) / ln(h1/h2)`.
    pub fn rates_of(&self, error: impl Fn(&LameLevel) -> f64) -> Vec<f64> {
        self.rates(error)
    }

    fn rates(&self, error: impl Fn(&LameLevel) -> f64) -> Vec<f64> {
        self.levels.windows(2).map(|w| convergence_rate(w[0].h, error(&w[0]), w[1].h, error(&w[1]))).collect()
    }

    /// The finest level.
    pub fn finest(&self) -> Option<&LameLevel> {
        self.levels.last()
    }
}

/// Runs the study on the given radial cell counts (coarse to fine).
///
/// # Errors
/// As [`solve_lame`].
pub fn lame_study(
    kind: CellKind,
    plane: PlaneCondition,
    levels: &[usize],
    setup: &LameSetup,
) -> Result<LameStudy, VerifyError> {
    let levels = levels.iter().map(|&n| solve_lame(kind, plane, n, setup).map(|r| r.0)).collect::<Result<_, _>>()?;
    Ok(LameStudy { kind, plane, levels })
}

/// The theoretical `(L2, energy)` rates of a kind: `(k + 1, k)` for degree `k`.
pub fn theoretical_rates(kind: CellKind) -> (f64, f64) {
    let k = contact2d_fem::element_type(kind).map_or(1, |e| e.degree()) as f64;
    (k + 1.0, k)
}

/// The kinds of the standard convergence study (every kind; the brief's Q4, Q8, Q9, T6 plus T3).
pub const STUDY_KINDS: [CellKind; 5] =
    [CellKind::Quad4, CellKind::Quad8, CellKind::Quad9, CellKind::Tri6, CellKind::Tri3];

/// The standard study: every kind of [`STUDY_KINDS`] in both plane conditions on
/// [`standard_levels`] with the default setup.
///
/// # Errors
/// As [`solve_lame`].
pub fn standard_studies() -> Result<Vec<LameStudy>, VerifyError> {
    let setup = LameSetup::default();
    let mut out = vec![];
    for kind in STUDY_KINDS {
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            out.push(lame_study(kind, plane, &standard_levels(kind), &setup)?);
        }
    }
    Ok(out)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn coarse_quad9_is_already_close_and_zero_cells_are_rejected() {
        let setup = LameSetup::default();
        let (level, _, _) = solve_lame(CellKind::Quad9, PlaneCondition::Strain, 2, &setup).unwrap();
        assert_eq!((level.n_radial, level.n_around), (2, 4));
        assert!(level.norms.relative_l2() < 1e-2 && level.inner_radial_stress_error < 0.2);
        assert!(lame_model(CellKind::Quad9, PlaneCondition::Strain, 0, &setup).is_err());
        assert_eq!(theoretical_rates(CellKind::Tri6), (3.0, 2.0));
        assert_eq!(theoretical_rates(CellKind::Quad4), (2.0, 1.0));
    }
}

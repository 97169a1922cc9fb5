//! A plate with a circular hole under uniaxial tension: O-grid mesh and stress concentration.
//!
//! ```text
//!  x2
//!   B +--------------- free ---------------+     quarter model: rollers on both symmetry lines,
//!     |sym_x                         . '   |     traction (σ, 0) on the loaded edge x1 = L,
//!     |u1 = 0                  . '         |--> σ     x2 = B and the hole free
//!     |                  . '    rays       |--> σ
//!   a +-.          . '                     |--> σ
//!     |  \   . '                   loaded  |
//!     +---+----------- sym_y: u2 = 0 ------+--> x1
//!     0   a                                L
//!
//!   (ξ, η) ∈ [0,1]²:  η picks a ray, θ(η) piecewise linear with θ(η_c) = atan2(B, L), so the
//!   ray to the corner (L, B) is a grid line and no cell straddles the corner; η_c = k/8 closest
//!   to θ_c/(π/2) keeps the angular spacing nearly uniform. Along a ray
//!   r = a + (R(θ) - a) s(ξ),  s(ξ) = (g^ξ - 1)/(g - 1),  R(θ) the distance to the outer boundary;
//!   g is chosen so that the first cell on the ray θ = 90° is as long radially as it is wide.
//!   n cells along ξ, 2n along η (n a multiple of 4).
//! ```
//!
//! The stress concentration factor is `SCF = σ_θθ(a, 90°)/σ = σ11(0, a)/σ`, with `σ` the
//! applied (gross) tension, read from the nodal stresses at the node `(0, a)`. For a strip of
//! width `D = 2B` the diameter ratio is `λ = d/D = a/B`.

use std::f64::consts::FRAC_PI_2;

use contact2d_element::{Kinematics, Material};
use contact2d_fem::{Component, EdgeLoad, Model, StressRecovery, nodal_stresses, solve_linear};
use contact2d_mesh::generate::{MappedGrid, Side, mapped_grid};
use contact2d_mesh::{CellKind, Mesh};

use crate::VerifyError;
use crate::analytic::{HOWLAND_KT_GROSS, heywood_kt_gross};

/// The quarter plate `[0, L] × [0, B]` minus the quarter hole `r < a`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlateWithHole {
    /// `L`: half-length along the load; the traction acts on `x1 = L`.
    pub half_length: f64,
    /// `B`: half-width across the load; `x2 = B` is free.
    pub half_width: f64,
    /// Hole radius `a`.
    pub radius: f64,
}

impl PlateWithHole {
    /// The diameter ratio `λ = d/D = a/B` of the strip.
    pub fn diameter_ratio(&self) -> f64 {
        self.radius / self.half_width
    }

    fn validate(&self) -> Result<(), VerifyError> {
        let (l, b, a) = (self.half_length, self.half_width, self.radius);
        if a > 0.0 && a < l.min(b) && l.is_finite() && b.is_finite() {
            Ok(())
        } else {
            Err(VerifyError::InvalidParameter(format!("plate with hole needs 0 < a < min(L, B): {self:?}")))
        }
    }
}

/// The grading ratio `g` with `ln g/(g - 1) = target` (`g = 1`, uniform, for `target ≥ 1`).
fn grading_ratio(target: f64) -> f64 {
    if target >= 1.0 {
        return 1.0;
    }
    // f(ln g) = ln g/(g - 1) decreases from 1 to 0 on ln g ∈ (0, ∞): bisection on ln g.
    let f = |lg: f64| lg / lg.exp_m1();
    let (mut lo, mut hi) = (1e-12, 60.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi)).exp()
}

/// The O-grid mesh of the module docs with `n` cells radially and `2n` around (`n % 4 == 0`).
/// Groups: region `plate`; curves `hole`, `loaded`, `free`, `sym_x` (x1 = 0), `sym_y` (x2 = 0).
///
/// # Errors
/// [`VerifyError::InvalidParameter`] for a bad geometry, `n` not a positive multiple of 4, or a
/// non-2D kind.
pub fn plate_with_hole_mesh(kind: CellKind, plate: &PlateWithHole, n: usize) -> Result<Mesh, VerifyError> {
    plate.validate()?;
    if n == 0 || n % 4 != 0 || contact2d_fem::element_type(kind).is_none() {
        return Err(VerifyError::InvalidParameter(format!("O-grid needs n a positive multiple of 4, got {n}")));
    }
    let (l, b, a) = (plate.half_length, plate.half_width, plate.radius);
    let theta_c = b.atan2(l);
    let eta_c = ((8.0 * theta_c / FRAC_PI_2).round() / 8.0).clamp(0.125, 0.875);
    let theta = move |eta: f64| {
        if eta <= eta_c {
            theta_c * eta / eta_c
        } else {
            theta_c + (FRAC_PI_2 - theta_c) * (eta - eta_c) / (1.0 - eta_c)
        }
    };
    // Square first cells on the ray θ = 90°: (B - a) s'(0)/n = a Δθ with s'(0) = ln g/(g - 1).
    let dtheta = (FRAC_PI_2 - theta_c) / ((1.0 - eta_c) * 2.0 * n as f64);
    let g = grading_ratio(a * dtheta * n as f64 / (b - a));
    let s = move |xi: f64| if g == 1.0 { xi } else { (g.powf(xi) - 1.0) / (g - 1.0) };
    let map = move |xi: f64, eta: f64| {
        // End points of the ray: exact at the symmetry line and at the corner.
        let (hole, outer) = if eta >= 1.0 {
            ([0.0, a], [0.0, b])
        } else if eta == eta_c {
            let t = theta_c;
            ([a * t.cos(), a * t.sin()], [l, b])
        } else {
            let t = theta(eta);
            let outer = if eta < eta_c { [l, l * t.tan()] } else { [b / t.tan(), b] };
            ([a * t.cos(), a * t.sin()], outer)
        };
        let sx = s(xi);
        [hole[0] + sx * (outer[0] - hole[0]), hole[1] + sx * (outer[1] - hole[1])]
    };
    let names = move |side: Side, t: f64| {
        Some(
            match side {
                Side::Left => "hole",
                Side::Bottom => "sym_y",
                Side::Top => "sym_x",
                Side::Right if t < eta_c => "loaded",
                Side::Right => "free",
            }
            .to_string(),
        )
    };
    Ok(mapped_grid(&MappedGrid { kind, nx: n, ny: 2 * n, region: "plate" }, map, names))
}

/// The stresses measured on one mesh of the plate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScfResult {
    /// Radial cells `n` (2n around).
    pub n: usize,
    /// Free DOFs.
    pub dofs: usize,
    /// `σ11(0, a)/σ` from the extrapolated nodal stresses.
    pub scf: f64,
    /// `σ11(0, a)/σ` from the directly evaluated nodal stresses.
    pub scf_direct: f64,
    /// `σ22(a, 0)/σ` (the hoop stress at θ = 0; Kirsch: -1), extrapolated.
    pub hoop_at_zero: f64,
}

/// Solves the plate under the gross tension `σ = 1` (plane stress; the in-plane stresses of this
/// traction problem do not depend on the elastic constants) and reads the stresses at the hole.
///
/// # Errors
/// Mesh, model or solver failures.
pub fn solve_scf(kind: CellKind, plate: &PlateWithHole, n: usize) -> Result<ScfResult, VerifyError> {
    let mesh = plate_with_hole_mesh(kind, plate, n)?;
    let mut model = Model::new(mesh);
    let body = model.add_body("plate", Material::new(1.0, 0.3)?, Kinematics::PlaneStress { thickness: 1.0 })?;
    model.fix("sym_x", Component::X, 0.0)?;
    model.fix("sym_y", Component::Y, 0.0)?;
    model.add_edge_load(EdgeLoad::Traction { group: "loaded".into(), traction: [1.0, 0.0] })?;
    let (system, _, solution) = solve_linear(&model)?;
    let tolerance = 1e-9 * plate.radius;
    let top = crate::node_at(&model.mesh, [0.0, plate.radius], tolerance)?;
    let side = crate::node_at(&model.mesh, [plate.radius, 0.0], tolerance)?;
    let extrapolated = nodal_stresses(&model, body, &solution.displacement, StressRecovery::Extrapolated)?;
    let direct = nodal_stresses(&model, body, &solution.displacement, StressRecovery::Direct)?;
    let missing = |p: [f64; 2]| VerifyError::MissingNode { x: p[0], y: p[1], tolerance };
    let at = |stresses: &[Option<[f64; 3]>], n: usize, p| stresses[n].ok_or_else(|| missing(p));
    Ok(ScfResult {
        n,
        dofs: system.dofs.num_free(),
        scf: at(&extrapolated, top, [0.0, plate.radius])?[0],
        scf_direct: at(&direct, top, [0.0, plate.radius])?[0],
        hoop_at_zero: at(&extrapolated, side, [plate.radius, 0.0])?[1],
    })
}

/// One geometry solved on a sequence of meshes, with its references.
#[derive(Debug, Clone, PartialEq)]
pub struct ScfStudy {
    /// The geometry.
    pub plate: PlateWithHole,
    /// Results coarse to fine.
    pub levels: Vec<ScfResult>,
    /// Howland's tabulated `Kt_gross` at this `λ`, where tabulated.
    pub howland: Option<f64>,
    /// Heywood's formula at this `λ`.
    pub heywood: f64,
}

impl ScfStudy {
    /// SCF on the finest mesh.
    pub fn scf(&self) -> f64 {
        self.levels.last().map_or(f64::NAN, |l| l.scf)
    }

    /// `|SCF_fine - SCF_coarse| / SCF_fine` between the two finest meshes.
    pub fn mesh_change(&self) -> f64 {
        match self.levels.as_slice() {
            [.., c, f] => (f.scf - c.scf).abs() / f.scf,
            _ => f64::NAN,
        }
    }
}

/// Solves `plate` on each of the radial cell counts `levels`.
///
/// # Errors
/// As [`solve_scf`].
pub fn scf_study(kind: CellKind, plate: PlateWithHole, levels: &[usize]) -> Result<ScfStudy, VerifyError> {
    let results = levels.iter().map(|&n| solve_scf(kind, &plate, n)).collect::<Result<_, _>>()?;
    let lambda = plate.diameter_ratio();
    let howland = HOWLAND_KT_GROSS.iter().find(|(l, _)| (l - lambda).abs() < 1e-12).map(|(_, k)| *k);
    Ok(ScfStudy { plate, levels: results, howland, heywood: heywood_kt_gross(lambda) })
}

/// Element kind of the standard SCF studies.
pub const STANDARD_KIND: CellKind = CellKind::Quad9;

/// Radial cell counts of the standard SCF studies (the finer pair is the one checked).
pub const STANDARD_LEVELS: [usize; 2] = [16, 32];

/// Length-to-width ratio `L/B` of the long strip of the Howland comparison.
pub const STRIP_LENGTH_RATIO: f64 = 4.0;

/// Howland's strip: `B = 1`, `L = 4B`, `a = λ B` for each tabulated `λ`.
///
/// # Errors
/// As [`scf_study`].
pub fn howland_studies(kind: CellKind, levels: &[usize]) -> Result<Vec<ScfStudy>, VerifyError> {
    HOWLAND_KT_GROSS
        .iter()
        .map(|&(lambda, _)| {
            scf_study(kind, PlateWithHole { half_length: STRIP_LENGTH_RATIO, half_width: 1.0, radius: lambda }, levels)
        })
        .collect()
}

/// Hole-to-plate ratios `a/W` of the Kirsch limit study on the square plate `L = B = W`.
pub const KIRSCH_RATIOS: [f64; 3] = [0.2, 0.1, 0.05];

/// The square plate `L = B = W = 1` with `a = ratio · W` for each of [`KIRSCH_RATIOS`].
///
/// # Errors
/// As [`scf_study`].
pub fn kirsch_studies(kind: CellKind, levels: &[usize]) -> Result<Vec<ScfStudy>, VerifyError> {
    KIRSCH_RATIOS
        .iter()
        .map(|&ratio| scf_study(kind, PlateWithHole { half_length: 1.0, half_width: 1.0, radius: ratio }, levels))
        .collect()
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn grading_ratio_inverts_its_equation() {
        for target in [0.04, 0.3, 0.9] {
            let g = grading_ratio(target);
            assert!((g.ln() / (g - 1.0) - target).abs() < 1e-10);
        }
        assert_eq!(grading_ratio(1.5), 1.0);
    }

    #[test]
    fn mesh_has_the_corner_on_a_grid_line_and_nodes_on_the_hole() {
        let plate = PlateWithHole { half_length: 4.0, half_width: 1.0, radius: 0.3 };
        for kind in [CellKind::Quad4, CellKind::Quad9, CellKind::Tri6] {
            let mesh = plate_with_hole_mesh(kind, &plate, 8).unwrap();
            assert!(mesh.points.iter().any(|p| p[0] == 4.0 && p[1] == 1.0), "{kind:?}: corner is a node");
            for n in mesh.group_nodes("hole").unwrap() {
                let p = mesh.points[n.0];
                assert!((p[0].hypot(p[1]) - 0.3).abs() < 1e-15);
            }
            for n in mesh.group_nodes("loaded").unwrap() {
                assert_eq!(mesh.points[n.0][0], 4.0);
            }
            for n in mesh.group_nodes("free").unwrap() {
                assert!((mesh.points[n.0][1] - 1.0).abs() < 1e-15);
            }
            for n in mesh.group_nodes("sym_x").unwrap() {
                assert_eq!(mesh.points[n.0][0], 0.0);
            }
            let mut model = Model::new(mesh);
            assert!(
                model
                    .add_body("plate", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 })
                    .is_ok()
            );
        }
        assert!(plate_with_hole_mesh(CellKind::Quad4, &plate, 6).is_err());
        let bad = PlateWithHole { radius: 1.5, ..plate };
        assert!(plate_with_hole_mesh(CellKind::Quad4, &bad, 8).is_err());
    }
}

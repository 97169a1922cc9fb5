//! Closed-form solutions and published reference values of plane elasticity.
//!
//! Voigt notation as in the element crate: `ε = [ε11, ε22, γ12]` with `γ12 = 2 ε12`,
//! `σ = [σ11, σ22, σ12]`; tension positive; polar components `(r, θ)` with `θ` from the x1 axis.
//!
//! ```text
//! Affine field (patch test):   u(x) = u0 + G x,   ε = [G11, G22, G12 + G21]  (constant)
//!
//! Lamé thick-walled cylinder, inner radius a, outer radius b, internal pressure p, outer
//! surface free (Timoshenko & Goodier 1970, §28; Barber 2010, §8.3.1):
//!   A = p a² / (b² - a²)
//!   σ_rr = A (1 - b²/r²),   σ_θθ = A (1 + b²/r²),   σ_rθ = 0       (both plane conditions)
//!   u_r  = C1 r + C2 / r,   ε_rr = C1 - C2/r²,      ε_θθ = C1 + C2/r²
//!   plane stress:  C1 = A (1 - ν) / E,         C2 = A (1 + ν) b² / E
//!   plane strain:  C1 = A (1 + ν)(1 - 2ν) / E, C2 = A (1 + ν) b² / E
//!
//! Kirsch (1898): infinite plate, circular hole of radius a, remote uniaxial tension σ along x1
//!   σ_rr = σ/2 (1 - a²/r²) + σ/2 (1 - 4a²/r² + 3a⁴/r⁴) cos 2θ
//!   σ_θθ = σ/2 (1 + a²/r²) - σ/2 (1 + 3a⁴/r⁴) cos 2θ
//!   σ_rθ = -σ/2 (1 + 2a²/r² - 3a⁴/r⁴) sin 2θ
//!   at the hole: σ_θθ(a, θ) = σ (1 - 2 cos 2θ),  so 3σ at θ = 90° and -σ at θ = 0
//!
//! Finite width (strip of width D = 2B, infinitely long, hole diameter d = 2a, λ = d/D):
//!   Kt_gross = σ_max / σ_gross,   Kt_net = σ_max / σ_net = Kt_gross (1 - λ)
//!   Howland (1930): series solution, tabulated for λ = 0.1 … 0.5
//!   Heywood (1952): Kt_net ≈ 2 + (1 - λ)³
//! ```
//!
//! # References
//! * G. Kirsch (1898), Die Theorie der Elastizität und die Bedürfnisse der Festigkeitslehre,
//!   Z. Vereines Deutscher Ingenieure 42, 797–807.
//! * R. C. J. Howland (1930), On the stresses in the neighbourhood of a circular hole in a strip
//!   under tension, Phil. Trans. R. Soc. Lond. A 229, 49–86, doi:10.1098/rsta.1930.0002.
//! * R. B. Heywood (1952), Designing by Photoelasticity, Chapman & Hall, London.
//! * W. D. Pilkey, D. F. Pilkey (2008), Peterson's Stress Concentration Factors, 3rd ed., Wiley,
//!   §4.3.1 and Chart 4.1 (Howland's values and the cubic fit of them).
//! * S. P. Timoshenko, J. N. Goodier (1970), Theory of Elasticity, 3rd ed., McGraw-Hill, §28
//!   (thick-walled cylinder) and §35 (Kirsch).

use contact2d_element::PlaneCondition;

use crate::VerifyError;

/// A displacement field known in closed form, with its strain.
pub trait ElasticField {
    /// Displacement `[u1, u2]` at `x`.
    fn displacement(&self, x: [f64; 2]) -> [f64; 2];
    /// Strain `[ε11, ε22, γ12]` at `x`.
    fn strain(&self, x: [f64; 2]) -> [f64; 3];
}

/// The affine field `u(x) = u0 + G x` that every complete element reproduces exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AffineField {
    /// Displacement at the origin.
    pub offset: [f64; 2],
    /// Displacement gradient `G_ij = ∂u_i/∂x_j`.
    pub gradient: [[f64; 2]; 2],
}

impl ElasticField for AffineField {
    fn displacement(&self, x: [f64; 2]) -> [f64; 2] {
        let g = &self.gradient;
        [self.offset[0] + g[0][0] * x[0] + g[0][1] * x[1], self.offset[1] + g[1][0] * x[0] + g[1][1] * x[1]]
    }

    fn strain(&self, _x: [f64; 2]) -> [f64; 3] {
        let g = &self.gradient;
        [g[0][0], g[1][1], g[0][1] + g[1][0]]
    }
}

/// The Lamé thick-walled cylinder under internal pressure (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LameCylinder {
    inner_radius: f64,
    outer_radius: f64,
    pressure: f64,
    c1: f64,
    c2: f64,
    a_coef: f64,
}

impl LameCylinder {
    /// The cylinder `a ≤ r ≤ b` with internal pressure `p` (positive pushes outward) in a
    /// material `(E, ν)` under `plane` conditions.
    ///
    /// # Errors
    /// [`VerifyError::InvalidParameter`] unless `0 < a < b`, `E > 0`, `-1 < ν < 0.5` and `p` is
    /// finite.
    ///
    /// # Examples
    /// ```
    /// use contact2d_verification::analytic::LameCylinder;
    /// use contact2d_element::PlaneCondition;
    /// let c = LameCylinder::new(1.0, 2.0, 3.0, 1000.0, 0.3, PlaneCondition::Strain)?;
    /// assert!((c.radial_stress(1.0) + 3.0).abs() < 1e-14); // σ_rr(a) = -p
    /// assert!(c.radial_stress(2.0).abs() < 1e-14); // free outer surface
    /// # Ok::<(), contact2d_verification::VerifyError>(())
    /// ```
    pub fn new(
        inner_radius: f64,
        outer_radius: f64,
        pressure: f64,
        youngs_modulus: f64,
        poissons_ratio: f64,
        plane: PlaneCondition,
    ) -> Result<LameCylinder, VerifyError> {
        let (a, b, e, nu) = (inner_radius, outer_radius, youngs_modulus, poissons_ratio);
        if !(a > 0.0 && b > a && b.is_finite() && e > 0.0 && e.is_finite() && nu > -1.0 && nu < 0.5)
            || !pressure.is_finite()
        {
            return Err(VerifyError::InvalidParameter(format!(
                "Lamé cylinder needs 0 < a < b, E > 0, -1 < ν < 0.5: got a = {a}, b = {b}, E = {e}, ν = {nu}, p = {pressure}"
            )));
        }
        let a_coef = pressure * a * a / (b * b - a * a);
        let c1 = match plane {
            PlaneCondition::Stress => a_coef * (1.0 - nu) / e,
            PlaneCondition::Strain => a_coef * (1.0 + nu) * (1.0 - 2.0 * nu) / e,
        };
        let c2 = a_coef * (1.0 + nu) * b * b / e;
        Ok(LameCylinder { inner_radius: a, outer_radius: b, pressure, c1, c2, a_coef })
    }

    /// Inner radius `a`.
    pub fn inner_radius(&self) -> f64 {
        self.inner_radius
    }

    /// Outer radius `b`.
    pub fn outer_radius(&self) -> f64 {
        self.outer_radius
    }

    /// Internal pressure `p`.
    pub fn pressure(&self) -> f64 {
        self.pressure
    }

    /// Radial displacement `u_r(r)`.
    pub fn radial_displacement(&self, r: f64) -> f64 {
        self.c1 * r + self.c2 / r
    }

    /// Radial stress `σ_rr(r)` (equals `-p` at `r = a` and `0` at `r = b`).
    pub fn radial_stress(&self, r: f64) -> f64 {
        let b = self.outer_radius;
        self.a_coef * (1.0 - b * b / (r * r))
    }

    /// Hoop stress `σ_θθ(r)`.
    pub fn hoop_stress(&self, r: f64) -> f64 {
        let b = self.outer_radius;
        self.a_coef * (1.0 + b * b / (r * r))
    }

    /// Cartesian stress `[σ11, σ22, σ12]` at `x`.
    pub fn stress(&self, x: [f64; 2]) -> [f64; 3] {
        let r = x[0].hypot(x[1]);
        let (c, s) = (x[0] / r, x[1] / r);
        polar_to_cartesian(self.radial_stress(r), self.hoop_stress(r), 0.0, c, s)
    }
}

impl ElasticField for LameCylinder {
    fn displacement(&self, x: [f64; 2]) -> [f64; 2] {
        let r = x[0].hypot(x[1]);
        let ur = self.radial_displacement(r);
        [ur * x[0] / r, ur * x[1] / r]
    }

    fn strain(&self, x: [f64; 2]) -> [f64; 3] {
        let r2 = x[0] * x[0] + x[1] * x[1];
        let (err, ett) = (self.c1 - self.c2 / r2, self.c1 + self.c2 / r2);
        let (c2, s2, cs) = (x[0] * x[0] / r2, x[1] * x[1] / r2, x[0] * x[1] / r2);
        [err * c2 + ett * s2, err * s2 + ett * c2, 2.0 * (err - ett) * cs]
    }
}

/// Cartesian `[σ11, σ22, σ12]` of polar components at a point with `cos θ = c`, `sin θ = s`.
pub fn polar_to_cartesian(s_rr: f64, s_tt: f64, s_rt: f64, c: f64, s: f64) -> [f64; 3] {
    [
        s_rr * c * c + s_tt * s * s - 2.0 * s_rt * c * s,
        s_rr * s * s + s_tt * c * c + 2.0 * s_rt * c * s,
        (s_rr - s_tt) * c * s + s_rt * (c * c - s * s),
    ]
}

/// The polar components `(σ_rr, σ_θθ, σ_rθ)` of a Cartesian stress at angle `θ` (`cos θ = c`).
pub fn cartesian_to_polar(stress: [f64; 3], c: f64, s: f64) -> (f64, f64, f64) {
    let [s11, s22, s12] = stress;
    (
        s11 * c * c + s22 * s * s + 2.0 * s12 * c * s,
        s11 * s * s + s22 * c * c - 2.0 * s12 * c * s,
        (s22 - s11) * c * s + s12 * (c * c - s * s),
    )
}

/// Kirsch's solution for the infinite plate with a hole of radius `radius` under remote uniaxial
/// tension `remote_stress` along x1 (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KirschPlate {
    /// Hole radius `a`.
    pub radius: f64,
    /// Remote tension `σ`.
    pub remote_stress: f64,
}

impl KirschPlate {
    /// The stress concentration factor of the infinite plate, `σ_θθ(a, 90°)/σ = 3`.
    pub const SCF: f64 = 3.0;

    /// Polar stresses `(σ_rr, σ_θθ, σ_rθ)` at radius `r ≥ a` and angle `theta`.
    pub fn polar_stress(&self, r: f64, theta: f64) -> (f64, f64, f64) {
        let (h, q) = (0.5 * self.remote_stress, (self.radius / r).powi(2));
        let (c2, s2) = ((2.0 * theta).cos(), (2.0 * theta).sin());
        (
            h * (1.0 - q) + h * (1.0 - 4.0 * q + 3.0 * q * q) * c2,
            h * (1.0 + q) - h * (1.0 + 3.0 * q * q) * c2,
            -h * (1.0 + 2.0 * q - 3.0 * q * q) * s2,
        )
    }

    /// Hoop stress on the hole, `σ_θθ(a, θ) = σ (1 - 2 cos 2θ)`.
    pub fn hoop_stress_at_hole(&self, theta: f64) -> f64 {
        self.remote_stress * (1.0 - 2.0 * (2.0 * theta).cos())
    }
}

/// Howland's (1930) stress concentration factors of a circular hole in an infinitely long strip
/// under tension, `(λ = d/D, Kt_gross = σ_max/σ_gross)`, as tabulated by Howland and reproduced
/// in Pilkey & Pilkey (2008, §4.3.1) — three significant figures.
#[allow(clippy::approx_constant)] // 3.14 is Howland's value at λ = 0.2, not π.
pub const HOWLAND_KT_GROSS: [(f64, f64); 5] = [(0.1, 3.03), (0.2, 3.14), (0.3, 3.36), (0.4, 3.74), (0.5, 4.32)];

/// Heywood's (1952) approximation of the gross stress concentration factor of a circular hole
/// in a strip, `Kt_gross = (2 + (1 - λ)³)/(1 - λ)` with `λ = d/D` (a cross-check of Howland).
pub fn heywood_kt_gross(diameter_ratio: f64) -> f64 {
    let net = 1.0 - diameter_ratio;
    (2.0 + net.powi(3)) / net
}

/// The gross stress concentration factor from the net one: `Kt_gross = Kt_net/(1 - λ)`.
pub fn gross_from_net(kt_net: f64, diameter_ratio: f64) -> f64 {
    kt_net / (1.0 - diameter_ratio)
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;

    #[test]
    fn lame_satisfies_its_boundary_conditions_and_compatibility() {
        for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
            let c = LameCylinder::new(1.0, 2.0, 3.0, 100.0, 0.3, plane).unwrap();
            assert!((c.radial_stress(1.0) + 3.0).abs() < 1e-14);
            assert!(c.radial_stress(2.0).abs() < 1e-14);
            // Hooke's law in polar form reproduces the closed-form stresses from the strains.
            let x = [0.9, 1.1];
            let e = c.strain(x);
            let d = plane.elasticity_matrix(&contact2d_element::Material::new(100.0, 0.3).unwrap());
            let s = d * nalgebra::Vector3::new(e[0], e[1], e[2]);
            let exact = c.stress(x);
            for k in 0..3 {
                assert!((s[k] - exact[k]).abs() < 1e-12, "{plane:?} component {k}");
            }
            // The strain is the symmetric gradient of the displacement (central differences).
            let h = 1e-6;
            let u = |p: [f64; 2]| c.displacement(p);
            let du1dx = (u([x[0] + h, x[1]])[0] - u([x[0] - h, x[1]])[0]) / (2.0 * h);
            let du2dy = (u([x[0], x[1] + h])[1] - u([x[0], x[1] - h])[1]) / (2.0 * h);
            let gamma = (u([x[0], x[1] + h])[0] - u([x[0], x[1] - h])[0]) / (2.0 * h)
                + (u([x[0] + h, x[1]])[1] - u([x[0] - h, x[1]])[1]) / (2.0 * h);
            assert!((du1dx - e[0]).abs() < 1e-8 && (du2dy - e[1]).abs() < 1e-8 && (gamma - e[2]).abs() < 1e-8);
        }
        assert!(LameCylinder::new(2.0, 1.0, 1.0, 1.0, 0.3, PlaneCondition::Stress).is_err());
        assert!(LameCylinder::new(1.0, 2.0, 1.0, 1.0, 0.5, PlaneCondition::Strain).is_err());
    }

    #[test]
    fn kirsch_hole_is_traction_free_and_far_field_is_uniaxial() {
        let k = KirschPlate { radius: 1.0, remote_stress: 2.0 };
        for theta in [0.0, 0.4, 1.2] {
            let (srr, stt, srt) = k.polar_stress(1.0, theta);
            assert!(srr.abs() < 1e-14 && srt.abs() < 1e-14);
            assert!((stt - k.hoop_stress_at_hole(theta)).abs() < 1e-14);
            let (srr, stt, srt) = k.polar_stress(1e6, theta);
            let far = polar_to_cartesian(srr, stt, srt, theta.cos(), theta.sin());
            assert!((far[0] - 2.0).abs() < 1e-10 && far[1].abs() < 1e-10 && far[2].abs() < 1e-10);
        }
        assert!((k.hoop_stress_at_hole(std::f64::consts::FRAC_PI_2) / 2.0 - KirschPlate::SCF).abs() < 1e-14);
    }

    #[test]
    fn polar_and_cartesian_transforms_are_inverse() {
        let (c, s) = (0.3f64.cos(), 0.3f64.sin());
        let cart = polar_to_cartesian(1.0, -2.0, 0.5, c, s);
        let (rr, tt, rt) = cartesian_to_polar(cart, c, s);
        assert!((rr - 1.0).abs() < 1e-14 && (tt + 2.0).abs() < 1e-14 && (rt - 0.5).abs() < 1e-14);
    }

    #[test]
    fn heywood_tends_to_kirsch_and_agrees_with_howland_at_small_holes() {
        assert!((heywood_kt_gross(0.0) - 3.0).abs() < 1e-15);
        assert!((heywood_kt_gross(0.1) - HOWLAND_KT_GROSS[0].1).abs() < 0.005);
        assert!((gross_from_net(2.16, 0.5) - 4.32).abs() < 1e-14);
    }
}

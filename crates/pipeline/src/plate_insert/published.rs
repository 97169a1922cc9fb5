//! The published values of Solodovnikov (1998) for the plate with insert (spec §7), typed, in one
//! place: the tables the examples, tests and docs compare with.
//!
//! ```text
//! no gap (ε = c = 0), E2 = E1, w = 1          μ = 0.3 and μ = 0
//! Table 2: c = 1, ε = 0.05, E2 = E1, w = 0.3838   U(1) variant 1 μ = 0.3, U(2) variant 2 μ = 0.3,
//!                                                 U(3) variant 2 μ = 0
//! ```
//! All values non-dimensional (spec §7). `b` is `None` where the paper has no stick zone to report
//! (frictionless cases, listed there as b = 0); `Φ_f` is `None` where the paper does not give it.
//! Caution (spec §7): Table 2's b of U(1), U(2) depends on the load steps; three equal steps
//! reproduce it.
//!
//! # References
//! V. N. Solodovnikov, *Solution of a contact problem for a plate with a deformable insert*, 1998
//! (the no-gap table and Table 2).

/// One published solution.
#[allow(non_snake_case)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PublishedCase {
    /// The bundled scene (file `scenes/<scene>.toml`) that sets this case up.
    pub scene: &'static str,
    /// The paper's label of the case.
    pub label: &'static str,
    /// Contact end l on η = 1 − φ/π.
    pub l: f64,
    /// Stick end b (`None`: frictionless).
    pub b: Option<f64>,
    /// Pulling force P.
    pub P: f64,
    /// Strain energy of the plate Φ_E1.
    pub Phi_E1: f64,
    /// Strain energy of the insert Φ_E2.
    pub Phi_E2: f64,
    /// Dissipated energy Φ_f (`None`: not published).
    pub Phi_f: Option<f64>,
    /// Largest hoop stress σ* on the hole edge.
    pub sigma_star: f64,
    /// Stress concentration factor K = H σ* / P.
    pub K: f64,
}

/// The published cases, each with the bundled scene that reproduces its set-up.
pub const PUBLISHED: [PublishedCase; 5] = [
    PublishedCase {
        scene: "plate_insert_nogap_mu0",
        label: "no gap, μ = 0",
        l: 0.4708,
        b: None,
        P: 0.184,
        Phi_E1: 0.07322,
        Phi_E2: 0.01874,
        Phi_f: Some(0.0),
        sigma_star: 0.3282,
        K: 4.460,
    },
    PublishedCase {
        scene: "plate_insert_nogap_mu03",
        label: "no gap, μ = 0.3",
        l: 0.4807,
        b: Some(0.1485),
        P: 0.195,
        Phi_E1: 0.07504,
        Phi_E2: 0.01996,
        Phi_f: Some(0.0025),
        sigma_star: 0.3873,
        K: 4.965,
    },
    PublishedCase {
        scene: "plate_insert_gap_v1_mu03",
        label: "Table 2, U(1): variant 1, μ = 0.3",
        l: 0.1455,
        b: Some(0.1309),
        P: 4.651e-2,
        Phi_E1: 6.411e-3,
        Phi_E2: 1.833e-3,
        Phi_f: None,
        sigma_star: 0.1017,
        K: 5.468,
    },
    PublishedCase {
        scene: "plate_insert_gap_v2_mu03",
        label: "Table 2, U(2): variant 2, μ = 0.3",
        l: 0.15,
        b: Some(0.1339),
        P: 4.694e-2,
        Phi_E1: 6.481e-3,
        Phi_E2: 1.836e-3,
        Phi_f: None,
        sigma_star: 0.1029,
        K: 5.483,
    },
    PublishedCase {
        scene: "plate_insert_gap_v2_mu0",
        label: "Table 2, U(3): variant 2, μ = 0",
        l: 0.1499,
        b: None,
        P: 4.679e-2,
        Phi_E1: 6.427e-3,
        Phi_E2: 1.874e-3,
        Phi_f: None,
        sigma_star: 0.0994,
        K: 5.313,
    },
];

/// The published case reproduced by the bundled scene `scene` (its name, e.g.
/// "plate_insert_nogap_mu03"), if any.
pub fn published_case(scene: &str) -> Option<&'static PublishedCase> {
    PUBLISHED.iter().find(|c| c.scene == scene)
}

impl PublishedCase {
    /// The compared quantities as (name, published value), in the paper's column order; `None`
    /// values are left out.
    pub fn quantities(&self) -> Vec<(&'static str, f64)> {
        let mut q = vec![("l", self.l)];
        if let Some(b) = self.b {
            q.push(("b", b));
        }
        q.extend([("P", self.P), ("Phi_E1", self.Phi_E1), ("Phi_E2", self.Phi_E2)]);
        if let Some(f) = self.Phi_f {
            q.push(("Phi_f", f));
        }
        q.extend([("sigma*", self.sigma_star), ("K", self.K)]);
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tables' own consistency checks: K = H σ* / P (H = 2.5) to the printed digits, and for
    /// proportional loading without gap P w / 2 = Φ_E1 + Φ_E2 + Φ_f (spec §7) to the 3 digits of P.
    #[test]
    fn the_tables_are_self_consistent() {
        for c in PUBLISHED {
            let k = 2.5 * c.sigma_star / c.P;
            assert!((k - c.K).abs() <= 0.01 * c.K, "{}: H σ*/P = {k} vs K = {}", c.scene, c.K);
        }
        for c in &PUBLISHED[..2] {
            let energy = c.Phi_E1 + c.Phi_E2 + c.Phi_f.unwrap_or(0.0);
            assert!((0.5 * c.P - energy).abs() <= 0.005 * energy, "{}", c.scene);
        }
    }

    /// Every published case names a bundled scene, and the scene's name matches.
    #[test]
    fn every_case_has_its_scene() {
        for c in PUBLISHED {
            let path = std::path::Path::new(crate::REPOSITORY_ROOT).join(format!("scenes/{}.toml", c.scene));
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            assert!(text.contains(&format!("name = \"{}\"", c.scene)), "{}", path.display());
            assert_eq!(published_case(c.scene), Some(&c));
        }
        assert!(published_case("nope").is_none());
    }
}

//! The generic pairing (closest point on the slave's quadratic edges) against the closed forms
//! of the paper's circles (spec §4): ρ_s, θ, γ1 and u_ρc for variant 1; r_s, φ̂, γ2 and u_rc for
//! variant 2. Mesh: ε = 0.05, N = 32 Quad9 elements along the half circle.
//!
//! Tolerances: the slave curve is the piecewise parabola through nodes on the exact circle; its
//! distance from the circle is at most R h⁴/512 ≈ 2e-7 for the arc h = π/32 per edge (the
//! interpolation error of a quadratic through three points of an arc), and its tangent is off by
//! at most β³/3 ≈ 4e-5 rad at the edge ends (β = h/2 the half edge angle). Normals are asserted
//! to 1e-4; paired points to 1e-5 (curve error plus gap × tangent error ≈ 0.1 × 4e-5); the
//! geometric gap to 1e-6 (second order in the point's tangential shift).
//! γ comes from central differences of paired arc lengths, O(h²) ≈ 1e-2 relative; asserted to
//! 2e-2 (1e-1 at the two end pairs, which use one-sided differences). The paper's gap
//! replacement differs from the geometric distance by O(ε²): |diff| ≤ 2 ε² (Taylor expansion).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::plate_insert::{GapModel, PairDiscretisation, PairingVariant, PlateInsert};

const EPS: f64 = 0.05;

fn build(variant: PairingVariant, gap_model: GapModel) -> contact2d::plate_insert::PlateInsertProblem {
    PlateInsert {
        variant,
        eps: EPS,
        clearance: EPS, // c = ε: ω = 1, gaps stay in length units
        gap_model,
        pairs: PairDiscretisation::NodeToSegment,
        ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0.05_N32.msh")
    }
    .build()
    .unwrap()
}

#[test]
fn variant1_pairs_match_rho_s_theta_gamma1_and_u_rho_c() {
    let geometric = build(PairingVariant::HoleMaster, GapModel::Geometric);
    let paper = build(PairingVariant::HoleMaster, GapModel::Paper);
    let p = &geometric.problem;
    let n = p.pairs.len();
    for (k, pair) in p.pairs.iter().enumerate() {
        let x = p.model.mesh.points[pair.master.0];
        let phi = x[1].atan2(x[0]);
        let rho_s = (1.0 + 2.0 * EPS * phi.cos() + EPS * EPS).sqrt();
        let (cos_t, sin_t) = ((phi.cos() + EPS) / rho_s, phi.sin() / rho_s);
        let r1 = 1.0 - EPS;
        let y = [r1 * cos_t - EPS, r1 * sin_t];
        assert!((pair.slave_point[0] - y[0]).hypot(pair.slave_point[1] - y[1]) < 1e-5, "pair {k}: point");
        assert!(
            (pair.normal[0] - cos_t).hypot(pair.normal[1] - sin_t) < 1e-4,
            "pair {k}: normal {:?} vs {:?} point {:?} vs {:?}",
            pair.normal,
            (cos_t, sin_t),
            pair.slave_point,
            y
        );
        assert!((pair.tangent[0] + sin_t).hypot(pair.tangent[1] - cos_t) < 1e-4, "pair {k}: tangent l_c");
        assert!((p.gap[k] - (rho_s - r1)).abs() < 1e-6, "pair {k}: gap {} vs rho_s R - R1 {}", p.gap[k], rho_s - r1);
        let gamma1 = rho_s * rho_s / ((1.0 - EPS) * (1.0 + EPS * phi.cos()));
        let tol = if k == 0 || k + 1 == n { 1e-1 } else { 2e-2 };
        assert!((pair.gamma - gamma1).abs() < tol * gamma1, "pair {k}: gamma {} vs {gamma1}", pair.gamma);
        let u_rho_c = -EPS * (1.0 + phi.cos()) / rho_s;
        assert!((paper.problem.gap[k] + u_rho_c).abs() < 1e-14);
        assert!((paper.problem.gap[k] - p.gap[k]).abs() <= 2.0 * EPS * EPS);
    }
}

#[test]
fn variant2_pairs_match_r_s_phi_hat_gamma2_and_u_rc() {
    let geometric = build(PairingVariant::InsertMaster, GapModel::Geometric);
    let paper = build(PairingVariant::InsertMaster, GapModel::Paper);
    let p = &geometric.problem;
    let n = p.pairs.len();
    for (k, pair) in p.pairs.iter().enumerate() {
        let x = p.model.mesh.points[pair.master.0];
        let theta = x[1].atan2(x[0] + EPS);
        let r_s = (1.0 - 2.0 * EPS * (1.0 - EPS) * (1.0 + theta.cos())).sqrt();
        let (cos_p, sin_p) = (((1.0 - EPS) * theta.cos() - EPS) / r_s, (1.0 - EPS) * theta.sin() / r_s);
        assert!(
            (pair.slave_point[0] - cos_p).hypot(pair.slave_point[1] - sin_p) < 1e-5,
            "pair {k}: point {:?} vs {:?} master {:?}",
            pair.slave_point,
            (cos_p, sin_p),
            x
        );
        // Out of the slave (plate) body: towards the hole centre, n = -n_p.
        assert!((pair.normal[0] + cos_p).hypot(pair.normal[1] + sin_p) < 1e-4, "pair {k}: normal");
        assert!((p.gap[k] - (1.0 - r_s)).abs() < 1e-6, "pair {k}: gap vs R (1 - r_s)");
        // The paper's γ is always ds_plate/ds_insert; ours is ds_master/ds_slave: γ2 = 1/γ.
        let gamma2 = (1.0 - EPS * (1.0 + theta.cos())) / (r_s * r_s);
        let tol = if k == 0 || k + 1 == n { 1e-1 } else { 2e-2 };
        assert!((1.0 / pair.gamma - gamma2).abs() < tol * gamma2, "pair {k}: 1/gamma {} vs {gamma2}", 1.0 / pair.gamma);
        let phi_hat = sin_p.atan2(cos_p);
        let u_rc = -EPS * (1.0 + phi_hat.cos());
        assert!((paper.problem.gap[k] + u_rc).abs() < 1e-6);
        assert!((paper.problem.gap[k] - p.gap[k]).abs() <= 2.0 * EPS * EPS);
    }
}

#[test]
fn neat_fit_pairs_are_node_to_node_with_zero_gap() {
    let case = PlateInsert {
        gap_model: GapModel::Geometric,
        pairs: PairDiscretisation::NodeToSegment,
        ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0_N16.msh")
    }
    .build()
    .unwrap();
    for pair in &case.problem.pairs {
        assert_eq!(pair.slave.len(), 1, "one slave node with weight 1");
        assert!((pair.slave[0].1 - 1.0).abs() < 1e-12);
        assert!((pair.gamma - 1.0).abs() < 1e-9);
    }
    assert!(case.problem.is_gapless());
}

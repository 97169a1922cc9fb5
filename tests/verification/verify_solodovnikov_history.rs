//! Solodovnikov (1998), the loading history with clearance and friction (spec §7): variant 1,
//! c = 1, ε = 0.05, μ = 0.3, E2 = E1, the paper's Boussinesq algorithm in 16 steps of the
//! contact length l = 0.05 ... 0.45 from zero slips.
//!
//! Goal: the behaviour the paper reports (its quantitative values are kept as independent
//! checks elsewhere): unlike the rigid pin, q and the slip keep their signs in the slip zone
//! throughout the loading and the plate edge slips clockwise over the insert; b grows to a
//! maximum and then decreases somewhat; the dissipated energy is negligible while l is small,
//! then grows quickly, but stays a small fraction of Φ_E.
//!
//! ```text
//!   plate with insert, Quad9, N = 32, node-to-node pairs, the paper's gap u_ρc
//!   steps: l* at the pair nearest to each of 16 equally spaced l in [0.05, 0.45]
//! ```
//! Thresholds, from the statements: "negligible" — Φ_f below 1e-3 Φ_E over the first quarter
//! of the steps; "small fraction" — below 5% at the end; "decreases somewhat" — the final b
//! at least one pair spacing below its maximum.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::{BoussinesqLoading, ContactStatus, Interface, PairState, solve_boussinesq_history};
use contact2d::plate_insert::PlateInsert;

#[test]
fn history_v1_behaves_as_the_paper_reports() {
    let case = PlateInsert {
        eps: 0.05,
        clearance: 1.0,
        friction: 0.3,
        ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0.05_N32.msh")
    }
    .build()
    .unwrap();
    let interface = Interface::new(&case.problem);
    let eta = case.eta_master();
    let mut order: Vec<usize> = (0..eta.len()).collect();
    order.sort_by(|a, b| eta[*a].total_cmp(&eta[*b]));
    let nearest = |l: f64| {
        (0..order.len()).min_by(|&a, &b| (eta[order[a]] - l).abs().total_cmp(&(eta[order[b]] - l).abs())).unwrap()
    };
    let mut positions: Vec<usize> = (0..16).map(|i| nearest(0.05 + 0.4 * i as f64 / 15.0)).collect();
    positions.dedup();
    let loadings: Vec<BoussinesqLoading> = positions.iter().map(|&p| BoussinesqLoading::ContactEnd(p)).collect();
    let history = solve_boussinesq_history(&case.problem, &interface, &order, &loadings, 200).unwrap();
    assert_eq!(history.len(), loadings.len());
    let mut b = vec![];
    let mut last_w = 0.0;
    for (i, step) in history.iter().enumerate() {
        let s = &step.solution;
        assert_eq!(s.status, ContactStatus::Converged, "step {i}");
        assert!(s.load_factor > last_w, "w grows with l");
        last_w = s.load_factor;
        // Slip only clockwise (Δs < 0 along the counter-clockwise tangent), at every step.
        assert!(!s.state.contains(&PairState::SlipPositive), "step {i}: a pair slips counter-clockwise");
        let q = case.results(s).unwrap();
        b.push(q.stick_end.unwrap_or(0.0));
        let energy = q.energy_plate + q.energy_insert;
        if i < history.len() / 4 {
            assert!(step.dissipated < 1e-3 * energy, "step {i}: Φ_f = {} is not negligible", step.dissipated);
        }
        if i + 1 == history.len() {
            assert!(step.dissipated < 0.05 * energy && step.dissipated > 1e-3 * energy, "final Φ_f/Φ_E");
        }
    }
    let (max_b, last_b) = (b.iter().cloned().fold(0.0, f64::max), b[b.len() - 1]);
    let spacing = 1.0 / (order.len() - 1) as f64;
    assert!(max_b > b[0] && max_b >= last_b + spacing, "b = {b:?}");
}

//! Zone ends finer than the mesh (spec §6, issue 4): nodes placed exactly at η = l* and η = b*
//! the way the paper adjusts its mesh, found by root finding on the Boussinesq condition
//! p(l*) = 0 and on the cone condition f(b*) = 0.
//!
//! Goal: the published l and b of the no-gap rows from one load step, without interpolating
//! between nodes: μ = 0, l = 0.4708; μ = 0.3, l = 0.4807, b = 0.1485 (spec §7).
//!
//! ```text
//!   plate with insert, Quad9, no gap, w = 1, variant 1 node-to-node pairs
//!   the hole-edge corner nodes nearest to l* and b* slide along the circle (mid nodes
//!   re-centred, interior relaxed); Illinois root finding in η to 1e-6
//! ```
//! Tolerances: l and b within 0.005 of the paper (issue 4). With nodes placed the remaining
//! difference is the mesh's discretisation error: μ = 0 gives l* = 0.4675, 0.4715, 0.4705 at
//! N = 16, 32, 64; μ = 0.3 gives l* = 0.4813, 0.4787 and b* = 0.1491, 0.1490 at N = 32, 64
//! (docs/verification.md);
//! the residuals at the placed nodes below 1e-4 of the largest contact pressure (the root
//! finder's tolerance of 1e-6 in η times the slope of p near l*, which is of order 1/√(l − η)
//! on one element); every inequality of (5.1) holds on the adjusted mesh.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::ContactStatus;
use contact2d::mesh::read_msh;
use contact2d::plate_insert::{ContourHistory, PlacedLoading, PlateInsert, ZoneEndSearch, place_zone_ends};

fn template(mu: f64, n: usize) -> PlateInsert {
    PlateInsert { friction: mu, ..PlateInsert::paper(format!("meshes/plate_insert/plate_insert_eps0_N{n}.msh")) }
}

#[test]
fn placed_zone_ends_reproduce_the_published_l_and_b() {
    for n in [16, 32] {
        for (mu, l_paper, b_paper) in [(0.0, 0.4708, None), (0.3, 0.4807, Some(0.1485))] {
            let t = template(mu, n);
            let mesh = read_msh(&t.mesh).unwrap();
            let found = place_zone_ends(
                &t,
                &mesh,
                PlacedLoading::Load(1.0),
                &ContourHistory::virgin(),
                ZoneEndSearch::default(),
            )
            .unwrap();
            assert_eq!(found.step.solution.status, ContactStatus::Converged, "{:?}", found.step.violations);
            assert!(
                (found.contact_end - l_paper).abs() <= 0.005,
                "μ = {mu}: l* = {:.5} vs {l_paper}",
                found.contact_end
            );
            if let Some(b_paper) = b_paper {
                assert!(found.stick_end_placed, "μ = {mu}: b* not placed");
                let b = found.stick_end;
                assert!((b - b_paper).abs() <= 0.005, "μ = {mu}: b* = {b:.5} vs {b_paper}");
            }
            assert!(found.residual_pressure <= 1e-4 && found.residual_cone <= 1e-4);
        }
    }
}

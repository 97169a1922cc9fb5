//! Zone ends finer than the mesh (spec §6, issue 4): the contact end l* found by placing a
//! master node exactly at η = l* and solving for the Boussinesq condition p(l*) = 0, the way the
//! paper adjusts its mesh.
//!
//! Goal: the published l of the no-gap rows, from one load step, without interpolating between
//! nodes: μ = 0, l = 0.4708; μ = 0.3, l = 0.4807 (spec §7).
//!
//! ```text
//!   plate with insert, Quad9, N = 32, no gap, w = 1, variant 1 node-to-node pairs
//!   the hole-edge corner node nearest to l* is moved onto the circle at l* (mid nodes re-centred,
//!   interior relaxed); bisection on l* in [0.45, 0.49] to 1e-5
//! ```
//! Tolerances: l within 0.002 of the paper (the issue asks 0.005; with nodes placed the
//! remaining difference is the mesh's, 0.0007 at N = 32 and 0.0003 at N = 64 for μ = 0); the
//! pressure left at l* below 1e-3 of the largest contact pressure (the bisection tolerance).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::contact::pair_tractions;
use contact2d::plate_insert::{PlateInsert, contact_end_by_placement};

fn template(mu: f64) -> PlateInsert {
    PlateInsert { friction: mu, ..PlateInsert::paper("meshes/plate_insert/plate_insert_eps0_N32.msh") }
}

#[test]
fn placed_contact_end_reproduces_the_published_l() {
    for (mu, published) in [(0.0, 0.4708), (0.3, 0.4807)] {
        let found = contact_end_by_placement(&template(mu), 1.0, [0.45, 0.49], 1e-5).unwrap();
        let l = found.contact_end;
        assert!((l - published).abs() <= 0.002, "μ = {mu}: l* = {l:.5} vs {published}");
        let (p, _) = pair_tractions(&found.case.problem, &found.solution);
        let p_max = p.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        assert!(found.residual_pressure.abs() <= 1e-3 * p_max, "μ = {mu}: p(l*) = {:.2e}", found.residual_pressure);
        // The adjusted mesh still gives the paper's P (forces converge fast, spec §8).
        let q = found.case.results(&found.solution).unwrap();
        let p_published = if mu == 0.0 { 0.184 } else { 0.195 };
        assert!((q.pull - p_published).abs() <= 0.01 * p_published);
    }
}

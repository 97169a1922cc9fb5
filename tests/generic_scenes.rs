//! The generic scene schema against the flagship preset: the same discrete problem written both
//! ways gives the same answer.
//!
//! Solodovnikov (1998), plate with a deformable insert, no gap, μ = 0.3, w = 1, N = 64
//! (scenes/plate_insert_nogap_mu03.toml and scenes/generic/plate_insert_nogap_mu03.toml): the
//! preset's P is the x reaction of the pulled edge `right` in the generic results, its Φ_E1 and
//! Φ_E2 the strain energies of `plate` and `insert`, its Φ_f the interface's dissipation, its
//! pressure and shear profiles the generic profile (paper's p = −pressure, q = −shear).
//!
//! Tolerance 1e-10 relative: the two paths build the same model, pairs and factorisation; only
//! the order of floating-point sums in the post-processing differs (round-off, ~1e-15), and the
//! generic run solves at w = 1 where the preset scales (exact).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{load_scene, solve_generic};
use contact2d::scene::Scene;

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= 1e-10 * b.abs().max(1e-12), "{what}: generic {a} against preset {b}");
}

#[test]
fn the_flagship_in_the_generic_schema_gives_the_presets_numbers() {
    let preset = Scene::load(Path::new("scenes/plate_insert_nogap_mu03.toml"), &[]).unwrap();
    let preset = contact2d::run::solve_scene(&preset).unwrap();
    let generic = load_scene(Path::new("scenes/generic/plate_insert_nogap_mu03.toml"), &[]).unwrap();
    let generic = solve_generic(&generic, &mut |_, _| {}).unwrap();
    let (r, g) = (&preset.report, &generic.report);
    assert_eq!(g.status, "converged");
    close(g.reactions["right"][0], r.P, "P");
    close(g.energies["plate"], r.Phi_E1, "Φ_E1");
    close(g.energies["insert"], r.Phi_E2, "Φ_E2");
    close(g.contacts["hole"].dissipation, r.Phi_f, "Φ_f");
    // Profiles: the same pairs (node-to-node on the same morphed mesh), pair by pair.
    let last = preset.steps.last().unwrap();
    let (p, q) = contact2d::contact::pair_tractions(&last.case.problem, &last.solution);
    let profile = g.contacts["hole"].profile.as_ref().unwrap();
    let mut preset_by_arc: Vec<(f64, f64, f64)> = last
        .case
        .problem
        .pairs
        .iter()
        .zip(p.iter().zip(&q))
        .map(|(pair, (p, q))| (pair.master_arc_length, *p, *q))
        .collect();
    preset_by_arc.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert_eq!(preset_by_arc.len(), profile.s.len());
    let scale = p.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    for (k, (s, p, q)) in preset_by_arc.iter().enumerate() {
        assert!((profile.s[k] - s).abs() < 1e-12);
        assert!((profile.pressure[k] + p).abs() <= 1e-10 * scale, "pressure at s = {s}");
        assert!((profile.shear[k] + q).abs() <= 1e-10 * scale, "shear at s = {s}");
    }
    // Equilibrium of the whole model (an independent check): the reactions of every constrained
    // DOF (each once; groups share corner nodes) balance, there being no other load.
    let step = generic.history.steps.last().unwrap();
    let problem = &generic.built.problem;
    let reactions = problem.reactions(&step.solution.displacement, &step.factors);
    let mut total = [0.0, 0.0];
    for (d, r) in problem.system.dofs.constrained_dofs().iter().zip(&reactions) {
        total[d.0 % 2] += r;
    }
    assert!(total[0].abs() < 1e-10 * r.P && total[1].abs() < 1e-10 * r.P, "reactions sum to {total:?}");
}

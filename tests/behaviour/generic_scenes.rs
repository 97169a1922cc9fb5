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
use contact2d::plate_insert::PlateInsertScene;

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= 1e-10 * b.abs().max(1e-12), "{what}: generic {a} against preset {b}");
}

#[test]
fn the_flagship_in_the_generic_schema_gives_the_presets_numbers() {
    let preset = PlateInsertScene::load(Path::new("scenes/plate_insert_nogap_mu03.toml"), &[]).unwrap();
    let preset = contact2d::run::solve_scene(&preset).unwrap();
    let generic = load_scene(Path::new("scenes/generic/plate_insert_nogap_mu03.toml"), &[]).unwrap();
    let generic = solve_generic(&generic, &mut |_, _| {}).unwrap();
    let (r, g) = (&preset.paper, &generic.report);
    assert_eq!(g.status, "converged");
    close(g.reactions["right"][0].unwrap(), r.P, "P");
    close(g.energies["plate"], r.Phi_E1, "Φ_E1");
    close(g.energies["insert"], r.Phi_E2, "Φ_E2");
    close(g.contacts["hole"].dissipation, r.Phi_f, "Φ_f");
    // The work of the prescribed pull, ½ f·u over every DOF (the reactions times the prescribed
    // displacements), is the preset's W = P w / 2.
    close(g.steps.last().unwrap().work, r.W, "W");
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
    let reactions = problem.reactions(&step.solution, &step.factors).unwrap();
    let mut total = [0.0, 0.0];
    for (d, r) in problem.system.dofs.constrained_dofs().iter().zip(&reactions) {
        total[d.0 % 2] += r;
    }
    assert!(total[0].abs() < 1e-10 * r.P && total[1].abs() < 1e-10 * r.P, "reactions sum to {total:?}");
}

fn solve(path: &str) -> contact2d::generic::GenericOutcome {
    let scene = load_scene(Path::new(path), &[]).unwrap();
    solve_generic(&scene, &mut |_, _| {}).unwrap()
}

#[test]
fn two_blocks_pressed_then_slid_reach_coulombs_limit() {
    // Force control in x2 (the upper block floats), then gross sliding: Σλ = P = 1000 exactly
    // (equilibrium of the floating block) and |Στ| = μ P = 300 (Coulomb's law on every slipping
    // pair). Tolerance 1e-8: the floating equilibrium is iterated to 1e-10 of the force scale.
    let out = solve("scenes/generic/two_blocks_press_slide.toml");
    let r = &out.report;
    assert_eq!(r.status, "converged");
    assert_eq!(r.steps.len(), 6);
    assert_eq!(r.floating_bodies.len(), 1);
    let joint = &r.contacts["joint"];
    assert!((joint.normal_force - 1000.0).abs() < 1e-8 * 1000.0, "{}", joint.normal_force);
    assert!((joint.tangential_force.abs() - 300.0).abs() < 1e-8 * 1000.0, "{}", joint.tangential_force);
    // Friction work only accumulates (each step's dissipation is ≥ 0) and grows once it slides.
    let work: Vec<f64> = r.steps.iter().map(|s| s.contacts["joint"].dissipation).collect();
    assert!(work.windows(2).all(|w| w[1] >= w[0]) && work[5] > work[2], "{work:?}");
    // The clamped bottom carries what the top receives.
    let (bottom, top) = (r.reactions["lower_bottom"], r.reactions["upper_top"]);
    let (b1, b2, t1) = (bottom[0].unwrap(), bottom[1].unwrap(), top[0].unwrap());
    assert!((b1 + t1).abs() < 1e-8 * 1000.0 && (b2 - 1000.0).abs() < 1e-8 * 1000.0);
    assert_eq!(top[1], None, "the top is driven in x only: its y is no reaction");
}

#[test]
fn a_floating_roller_on_a_block_is_held_by_its_contact() {
    // The roller (held only by the contact and the symmetry line) carries F/2 = 17 500 N/mm into
    // the block: Σλ equals it to the floating tolerance. The Hertz half-width a = 6.21 mm is met
    // within 1 % on the L2 mesh (the gallery's verification studies the convergence).
    let out = solve("scenes/generic/cylinder_on_block.toml");
    let r = &out.report;
    assert_eq!(r.status, "converged");
    assert_eq!(r.floating_bodies[0].body, "cylinder");
    assert_eq!(r.floating_bodies[0].free_modes, ["u2 translation"]);
    let hertz = &r.contacts["hertz"];
    assert!((hertz.normal_force - 17_500.0).abs() < 1e-8 * 17_500.0, "{}", hertz.normal_force);
    let e_star = 1.0 / ((1.0 - 0.09) / 210_000.0 + (1.0 - 0.09) / 70_000.0);
    let a = (4.0 * 35_000.0 * 50.0 / (std::f64::consts::PI * e_star)).sqrt();
    assert!((hertz.contact_length - a).abs() < 0.01 * a, "a = {} against {a}", hertz.contact_length);
    assert_eq!(hertz.stick_length, 0.0, "frictionless: no stick zone");
    let profile = hertz.profile.as_ref().unwrap();
    assert!(profile.state.iter().all(|s| *s == "contact" || *s == "free"), "frictionless pairs are 'contact'");
}

#[test]
fn a_floating_pin_pushed_through_its_clearance_bears_on_the_lug() {
    // The pin crosses the 0.1 mm clearance and bears on the hole; the lug's clamped end takes the
    // whole push (x equilibrium, to the floating tolerance).
    let out = solve("scenes/generic/pin_lug.toml");
    let r = &out.report;
    assert_eq!(r.status, "converged");
    assert_eq!(r.floating_bodies[0].body, "pin");
    let lug = r.reactions["lug_fixed"][0].unwrap();
    assert!((lug + 1000.0).abs() < 1e-7 * 1000.0, "{:?}", r.reactions["lug_fixed"]);
    let bore = &r.contacts["bore"];
    assert!(bore.contact_length > 0.0 && bore.stick_length <= bore.contact_length);
    assert!(r.kkt.max_penetration < 1e-9 && r.kkt.max_cone_violation < 1e-9);
}

#[test]
fn an_unheld_body_is_a_typed_error_naming_it() {
    // Pulling the roller away: the contact cannot hold it.
    let scene =
        load_scene(Path::new("scenes/generic/cylinder_on_block.toml"), &["load.0.force=[0.0, 1000.0]".into()]).unwrap();
    let err = solve_generic(&scene, &mut |_, _| {}).unwrap_err().to_string();
    assert!(err.contains("\"cylinder\"") && err.contains("u2 translation"), "{err}");
}

#[test]
fn a_scene_without_contact_is_plain_elasticity_and_optional_sections_take_overrides() {
    // The lower block alone under a pressure of 1 on its top (length 4): the clamped bottom
    // carries 4 (equilibrium, to round-off), with no pair to solve for.
    let text = "name = \"block\"\nmesh = \"../meshes/generic/two_blocks.msh\"\n[[body]]\nregion = \"lower\"\n\
                youngs_modulus = 1000.0\npoissons_ratio = 0.3\n[[fix]]\ngroup = \"lower_bottom\"\nu1 = 0.0\nu2 = 0.0\n\
                [[load]]\ngroup = \"lower_top\"\npressure = 1.0\n";
    let path = Path::new("scenes/block_without_contact.toml");
    for algorithm in ["active_set", "clarabel"] {
        let scene =
            contact2d::generic::GenericScene::from_toml_str(text, path, &[format!("solver.algorithm={algorithm}")])
                .unwrap();
        let out = solve_generic(&scene, &mut |_, _| {}).unwrap();
        assert_eq!(out.report.status, "converged");
        assert_eq!(out.report.pairs, 0);
        let [Some(r1), Some(r2)] = out.report.reactions["lower_bottom"] else { panic!("both components fixed") };
        assert!(r1.abs() < 1e-12 && (r2 - 4.0).abs() < 1e-12, "{r1}, {r2}");
    }
}

#[test]
fn penalties_are_read_for_the_penalty_method_only() {
    use contact2d::scene::SceneError;
    let scene = |sets: &[&str]| {
        let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
        load_scene(Path::new("scenes/generic/two_blocks_press_slide.toml"), &sets)
    };
    let p = scene(&["solver.algorithm=penalty", "solver.penalty=1e5"]).unwrap().settings().unwrap().penalty();
    // The tangential penalty defaults to the normal one.
    assert_eq!((p.normal, p.tangential), (1e5, 1e5));
    let p = scene(&["solver.algorithm=penalty", "solver.tangential_penalty=10"]).unwrap().settings().unwrap().penalty();
    assert_eq!((p.normal, p.tangential), (1e3, 10.0));
    let key = |sets: &[&str]| match scene(sets) {
        Err(SceneError::Value { key, .. }) => key,
        other => panic!("expected a value error, got {other:?}"),
    };
    assert_eq!(key(&["solver.penalty=1e3"]), "solver.penalty");
    assert_eq!(key(&["solver.algorithm=penalty", "solver.penalty=0"]), "solver.penalty");
    assert_eq!(key(&["solver.algorithm=penalty", "solver.tangential_penalty=1e20"]), "solver.tangential_penalty");
}

#[test]
fn a_schedule_set_on_the_command_line_replaces_the_files_steps() {
    // pin_lug has `steps = 4`; `--set loading.schedule=[…]` means that schedule (the two keys
    // exclude each other), and `--set loading.steps=2` on a scheduled scene means two equal steps.
    let path = Path::new("scenes/generic/pin_lug.toml");
    let set = |s: &str| contact2d::generic::load_scene(path, &[s.to_string()]).unwrap();
    let scheduled = solve_generic(&set("loading.schedule=[{main=0.5},{main=1.0}]"), &mut |_, _| {}).unwrap();
    let stepped = solve_generic(&set("loading.steps=2"), &mut |_, _| {}).unwrap();
    assert_eq!(scheduled.report.steps.len(), 2);
    let factors = |o: &contact2d::generic::GenericOutcome| -> Vec<f64> {
        o.report.steps.iter().map(|s| s.factors["main"]).collect()
    };
    assert_eq!(factors(&scheduled), vec![0.5, 1.0]);
    assert_eq!(factors(&scheduled), factors(&stepped), "two equal steps are that schedule");
}

#[test]
fn a_proportional_run_solved_once_counts_its_iterations_once() {
    // No gap and proportional loading: the schedule is solved once and scaled (exact), so five
    // steps did the work of one: their iterations sum to the one-step run's.
    let path = Path::new("scenes/generic/plate_insert_nogap_mu03.toml");
    let run = |steps: usize| {
        let scene = contact2d::generic::load_scene(path, &[format!("loading.steps={steps}")]).unwrap();
        solve_generic(&scene, &mut |_, _| {}).unwrap()
    };
    let (one, five) = (run(1), run(5));
    assert!(five.history.scaled, "no gap, proportional: solved once");
    let total = |o: &contact2d::generic::GenericOutcome| o.report.steps.iter().map(|s| s.iterations).sum::<usize>();
    assert_eq!(total(&five), total(&one));
    assert_eq!(five.report.iterations, one.report.iterations);
}

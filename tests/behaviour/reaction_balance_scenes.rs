//! Verification: every bundled generic scene is in global equilibrium at every step, as its JSON
//! reports it — the applied loads, the reactions of every constrained DOF and the rigid
//! obstacles' resultants sum to zero.
//!
//! Citation: the equilibrium of the discrete system, T. J. R. Hughes (2000), The Finite Element
//! Method, Dover, §1.14 (reactions from the assembled residual); the contact forces enter as the
//! multipliers' `B_Nᵀ λ + B_Tᵀ τ` (e.g. Wriggers (2006), Computational Contact Mechanics, §6.3).
//!
//! Also: cumulative dissipation never exceeds the cumulative work of the loads (issue 27's
//! property over every bundled scene).
//!
//! Goal: issue 27 item 3. `K` annihilates each body's translations, so summing
//! `K u = f + B_Nᵀ λ + B_Tᵀ τ + r` over every DOF of one direction gives
//! `Σ f + Σ r + Σ_rigid R = 0`: a deformable pair's forces are internal (its rows sum to zero),
//! a rigid obstacle's pairs exert `R` on the bodies. A reaction that leaves out the contact force
//! on a constrained DOF, or a node counted by two groups, breaks it by the size of a force.
//!
//! ```text
//!  every scenes/generic/*.toml (new scenes are covered), every step:
//!    F = Σ_p factor_p Σ_nodes f_p          (the loads, from the patterns' nodal forces)
//!    F + reactions_total + Σ contacts.<name>.rigid_resultant = 0
//!
//!  two_blocks_press_slide with the slave edge fixed instead of the bottom:
//!          P = 1000 ↓, u1 driven           upper block (held in y by the contact only)
//!    ┌──────────────────┐
//!    └──────────────────┘   joint, μ = 0.3
//!    ▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲▲   lower_top fixed (u1 = u2 = 0): the contact lands on the support
//!    lower block
//! ```
//!
//! Reference values: the sum is 0 (a conservation law, not a number of ours); with the slave
//! edge fixed the support takes the whole press, `R2 = P = 1000 N`, and at gross sliding
//! Coulomb's `|R1| = μ P = 300 N`, opposite the driven top's.
//!
//! Tolerance: 1e-6 of the force scale — the load's magnitude, or where no load is applied (a
//! driven displacement, an interference) the largest of the contact forces `Σ |λ| + |τ|` that
//! the reactions then carry. The balance is exact for the discrete system up to the solver's
//! residual: a backward-stable Cholesky solve (~1e-12 relative here) and, for bodies held only by
//! contact, the proximal iteration stopped at 1e-10 of the load; 1e-6 keeps a wide margin above
//! both while the defects it guards against (the 1,000 N and 300 N left out, the 14 N and 469 N
//! counted twice) are of order 1e-2 to 1 of the load. The two-blocks values to 1e-8 of P: the
//! floating block's equilibrium is iterated to 1e-10 of the force scale.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::common;
use common::bundled_scenes;

use std::path::Path;
use std::process::Command;

use contact2d::generic::{GenericOutcome, load_scene, solve_generic};

fn solve(path: &Path, overrides: &[String]) -> GenericOutcome {
    let scene = load_scene(path, overrides).unwrap();
    solve_generic(&scene, &mut |_, _| {}).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The step's loads, `Σ_p factor_p Σ f_p` per direction.
fn applied_load(out: &GenericOutcome, factors: &[f64]) -> [f64; 2] {
    let mut f = [0.0; 2];
    for (pattern, factor) in out.built.problem.patterns().iter().zip(factors) {
        for (d, v) in pattern.nodal.iter().enumerate() {
            f[d % 2] += factor * v;
        }
    }
    f
}

/// The step's rigid obstacles' resultants on the bodies, summed.
fn rigid_resultants(step: &contact2d::generic::StepResult) -> [f64; 2] {
    step.contacts.values().filter_map(|c| c.rigid_resultant).fold([0.0; 2], |a, r| [a[0] + r[0], a[1] + r[1]])
}

#[test]
fn every_bundled_scene_balances_its_loads_at_every_step() {
    let scenes = bundled_scenes();
    assert!(scenes.len() >= 10, "{scenes:?}");
    for path in &scenes {
        let out = solve(path, &[]);
        let name = path.display();
        assert_eq!(out.report.steps.len(), out.history.steps.len(), "{name}");
        let json = serde_json::to_value(&out.report).unwrap();
        for (i, (step, solved)) in out.report.steps.iter().zip(&out.history.steps).enumerate() {
            let load = applied_load(&out, &solved.factors);
            let rigid = rigid_resultants(&step);
            let s = &solved.solution;
            let contact: f64 = s.normal_force.iter().chain(&s.tangential_force).map(|f| f.abs()).sum();
            let scale = load[0].hypot(load[1]).max(contact);
            assert!(scale > 0.0, "{name} step {}: nothing loads the scene", i + 1);
            let total = step.reactions_total;
            // A body of revolution balances only its axial forces: radial forces act on rings and
            // cancel round each ring by symmetry, so their sum over a meridian is no resultant (a
            // tube under internal pressure has Σ F_r = p 2πaL and no reaction; a sphere pressed
            // on a block has the radial reactions of its nodes on the axis, u_r = 0).
            let components = if out.report.kinematics == "axisymmetric" { 1..2 } else { 0..2 };
            for c in components {
                let residual = load[c] + total[c] + rigid[c];
                assert!(
                    residual.abs() <= 1e-6 * scale,
                    "{name} step {}, x{}: loads {load:?} + reactions_total {total:?} + rigid {rigid:?} = {residual:e} \
                     (scale {scale:e})",
                    i + 1,
                    c + 1
                );
            }
            // The JSON carries the same total at every step.
            assert_eq!(json["steps"][i]["reactions_total"], serde_json::json!(total), "{name} step {}", i + 1);
        }
        assert_eq!(json["reactions_total"], serde_json::json!(out.report.steps.last().unwrap().reactions_total));
        // The second law of the history: the work of the loads is the strain energy (≥ 0) plus
        // the dissipation, so the friction never dissipates more than the loads have done
        // (Φ_f ≤ W). W is the trapezoid rule over the steps (exact when solved once and scaled);
        // the measured margins are 19 % of W or more on every bundled scene, far above the
        // trapezoid's error on these histories; 1e-9 of the largest |W| covers round-off.
        let largest = out.report.steps.iter().fold(0.0f64, |m, s| m.max(s.work.abs()));
        for (i, step) in out.report.steps.iter().enumerate() {
            assert!(
                step.dissipated <= step.work + 1e-9 * largest,
                "{name} step {}: Φ_f = {} exceeds the loads' work W = {}",
                i + 1,
                step.dissipated,
                step.work
            );
        }
        // A group reports exactly the components its own fixes prescribe in the last step; the
        // others are null (a fix released before it, `until_step`, exerts no force: null).
        let last = out.report.steps.len();
        for (group, r) in &out.report.reactions {
            let fixes: Vec<_> = out
                .scene
                .fix
                .iter()
                .filter(|f| f.group.as_ref() == Some(group) && f.until_step.is_none_or(|k| k >= last))
                .collect();
            let prescribed = [fixes.iter().any(|f| f.u1.is_some()), fixes.iter().any(|f| f.u2.is_some())];
            for c in 0..2 {
                assert_eq!(r[c].is_some(), prescribed[c], "{name}: reactions.{group}.{c}");
                assert_eq!(json["reactions"][group][c].is_null(), !prescribed[c], "{name}: JSON reactions.{group}.{c}");
            }
        }
    }
}

#[test]
fn rollers_report_only_the_direction_they_hold() {
    // The three rollers of the issue, each sharing nodes with a support in the other direction.
    for (scene, group, free) in [
        ("pin_lug.toml", "symmetry", 0),
        ("cylinder_on_block.toml", "axis", 1),
        ("interference_fit.toml", "sym_x", 1),
        ("interference_fit.toml", "sym_y", 0),
    ] {
        let out = solve(&Path::new("scenes/generic").join(scene), &[]);
        let r = out.report.reactions[group];
        assert_eq!(r[free], None, "{scene}: {group} does not hold x{}", free + 1);
        assert!(r[1 - free].is_some(), "{scene}: {group} holds x{}", 2 - free);
    }
}

#[test]
fn a_fixed_slave_edge_reports_the_contact_force_as_its_reaction() {
    let out =
        solve(Path::new("scenes/generic/two_blocks_press_slide.toml"), &["fix.lower_bottom.group=lower_top".into()]);
    let r = &out.report;
    assert_eq!(r.status, "converged");
    let p = 1000.0;
    for (i, step) in r.steps.iter().enumerate() {
        // Every step: the support under the contact takes the press (the upper block's x2
        // equilibrium) and the driven top's x1 force.
        let [Some(b1), Some(b2)] = step.reactions["lower_top"] else { panic!("lower_top holds both directions") };
        let top = step.reactions["upper_top"][0].unwrap();
        let press = step.factors["press"] * p;
        assert!((b2 - press).abs() <= 1e-8 * p, "step {}: R2 = {b2} against the press {press}", i + 1);
        assert!((b1 + top).abs() <= 1e-8 * p, "step {}: R1 = {b1} against the top's {top}", i + 1);
    }
    // Gross sliding at the last step: Coulomb's μ P through the support.
    let [Some(b1), _] = r.reactions["lower_top"] else { panic!("lower_top holds x1") };
    assert!((b1.abs() - 0.3 * p).abs() <= 1e-8 * p, "R1 = {b1} against μ P = {}", 0.3 * p);
}

#[test]
fn the_text_summary_prints_the_total_and_marks_an_unheld_component() {
    let out =
        Command::new(env!("CARGO_BIN_EXE_contact2d")).args(["run", "scenes/generic/pin_lug.toml"]).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("reactions total (every constrained DOF once): ["), "{text}");
    assert!(text.contains("reaction symmetry: [none, "), "{text}");
    let rigid = Command::new(env!("CARGO_BIN_EXE_contact2d"))
        .args(["run", "scenes/generic/pin_lug_rigid_pin.toml"])
        .output()
        .unwrap();
    let text = String::from_utf8(rigid.stdout).unwrap();
    assert!(text.contains("contact bore: rigid obstacle's resultant ["), "{text}");
}

/// Equilibrium on a curved interface with every pairing (issue 23): on the pins in the lug (a
/// circle against a circle, non-matching nodes; an elastic pin and a rigid one) the contact
/// forces on the two sides cancel, so the loads, the reactions and a rigid obstacle's resultant
/// balance to the solver's residual — a mortar (segment-to-segment) interface whose two sides'
/// integrals differ on the curve would leave the difference in the balance. Node-to-node pairing
/// needs nodes that face each other one to one; where a mesh lacks them it is refused with a
/// typed error, never solved to a wrong balance.
///
/// Tolerance: 1e-9 of the load. The balance is exact for the discrete system but for the pin's
/// proximal iteration (held only by contact), stopped at 1e-10 of the force scale, and the
/// backward-stable solves (~1e-12); measured 5e-11 (node-to-segment) and 6e-11
/// (segment-to-segment) on the elastic pin, 4e-13 with every pairing on the rigid one, against
/// an imbalance of the size of the pressure times the curve's length where the sides differ.
#[test]
fn a_curved_interface_balances_with_every_pairing() {
    for scene in ["pin_lug.toml", "pin_lug_rigid_pin.toml"] {
        let path = Path::new("scenes/generic").join(scene);
        for pairing in ["node_to_segment", "segment_to_segment", "node_to_node"] {
            let loaded = load_scene(&path, &[format!("contact.bore.pairing=\"{pairing}\"")]).unwrap();
            let out = match solve_generic(&loaded, &mut |_, _| {}) {
                Ok(out) => out,
                Err(e) if pairing == "node_to_node" => {
                    assert!(e.to_string().contains("node"), "{scene}: {e}");
                    continue;
                }
                Err(e) => panic!("{scene} {pairing}: {e}"),
            };
            for (i, (step, solved)) in out.report.steps.iter().zip(&out.history.steps).enumerate() {
                let load = applied_load(&out, &solved.factors);
                let rigid = rigid_resultants(&step);
                let scale = load[0].hypot(load[1]);
                for c in 0..2 {
                    let residual = load[c] + step.reactions_total[c] + rigid[c];
                    assert!(
                        residual.abs() <= 1e-9 * scale,
                        "{scene} {pairing} step {}, x{}: imbalance {residual:e} of load {scale:e}",
                        i + 1,
                        c + 1
                    );
                }
            }
        }
    }
}

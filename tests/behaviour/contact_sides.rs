//! Which curve of an interface is the master must not change the joint (issue 27, items 1–2).
//!
//! Goal: the bundled scenes run with master and slave swapped (the text of the scene changed as
//! a user would change it) give the same contact resultant as the original order; a pair whose
//! two curves bound one body is refused with the body's name unless `self_contact = true`, and
//! then a node behind a curve of its own body is open.
//!
//! ```text
//!   pin_lug: hole r = 10 (lug), pin r = 9.9; pin_contact = pin arc 0..120°, hole = 0..180°
//!
//!            hole (master, swapped)        nodes of the hole beyond 120° face no part of
//!        .-'''''''-.                       pin_contact: their closest point is its end, and
//!      .'  .-'''-.  `.  <- pin_contact     the gap there is the distance to it, not the
//!     /   /  pin  \   \    ends at 120°    offset along the end's normal (−1.24 at 150°)
//!   ==+==+=========+===+==  symmetry
//! ```
//!
//! Truth: the two orders are two discretisations of one joint (node-to-segment or mortar pairs
//! from either side), which converge to the same answer under refinement; 5 % is the issue's
//! bound for the difference at the bundled mesh sizes. The geometric gaps are checked against
//! the closed-form geometry of the meshes (concentric circles 0.1 apart; straight lines).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::contact::ContactError;
use contact2d::generic::{GenericError, GenericOutcome, GenericScene, solve_generic};

/// The scene's text with `master = "a"` and `slave = "b"` exchanged, plus `extra` appended.
fn scene_text(path: &str, swap: Option<(&str, &str)>, extra: &str) -> String {
    let mut text = std::fs::read_to_string(path).unwrap();
    if let Some((master, slave)) = swap {
        let (m, s) = (format!("master = \"{master}\""), format!("slave = \"{slave}\""));
        assert!(text.contains(&m) && text.contains(&s), "{path}: {m} / {s}");
        text = text.replace(&m, "master = \"@\"").replace(&s, &format!("slave = \"{master}\""));
        text = text.replace("master = \"@\"", &format!("master = \"{slave}\""));
    }
    text + extra
}

fn run(path: &str, text: &str) -> Result<GenericOutcome, GenericError> {
    let scene = GenericScene::from_toml_str(text, Path::new(path), &[]).unwrap();
    solve_generic(&scene, &mut |_, _| {})
}

/// Runs `path` in both orders and checks the interface's normal and tangential resultants.
fn both_orders_agree(path: &str, contact: &str, master: &str, slave: &str) -> (GenericOutcome, GenericOutcome) {
    let original = run(path, &scene_text(path, None, "")).unwrap();
    let swapped = run(path, &scene_text(path, Some((master, slave)), "")).unwrap();
    for out in [&original, &swapped] {
        assert_eq!(out.report.status, "converged", "{path}");
        assert!(!out.report.notes.iter().any(|n| n.contains("interference")), "{path}: {:?}", out.report.notes);
    }
    let (a, b) = (&original.report.contacts[contact], &swapped.report.contacts[contact]);
    // 5 % of the resultant (N, T): the issue's bound for two discretisations of one joint
    // (module docs). The tangential part alone is a small difference of two friction states
    // (|T| ≈ 3 % of N on the pin), so it is judged within the resultant, as the issue states.
    let resultant = a.normal_force.hypot(a.tangential_force).max(b.normal_force.hypot(b.tangential_force));
    let moved = (a.normal_force - b.normal_force).hypot(a.tangential_force - b.tangential_force);
    assert!(
        moved <= 0.05 * resultant,
        "{path}: resultant (N, T) ({}, {}) against ({}, {})",
        a.normal_force,
        a.tangential_force,
        b.normal_force,
        b.tangential_force
    );
    (original, swapped)
}

/// The initial gaps of the interface `name`.
fn gaps(out: &GenericOutcome, name: &str) -> Vec<f64> {
    let built = &out.built;
    let interface = built.interfaces.iter().find(|i| i.name == name).unwrap();
    built.problem.pairs[interface.pairs.clone()].iter().map(|p| p.gap).collect()
}

#[test]
fn pin_lug_with_the_hole_as_master_gives_the_same_joint() {
    let (_, swapped) = both_orders_agree("scenes/generic/pin_lug.toml", "bore", "pin_contact", "hole");
    // Concentric circles 0.1 apart: no initial gap of the swapped order is below the clearance
    // (the hole's nodes beyond 120° lie farther from pin_contact's end). Tolerance 1e-4 of it
    // (1e-5 mm): the hole's nodes lie on their circle, and the pin's Line3 edges (3° each) are
    // parabolas through three points of theirs, off the circle by ~R α⁴ / 8 < 1e-6 mm (α = 1.5°).
    let g = gaps(&swapped, "bore");
    let least = g.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(least > 0.1 * (1.0 - 1e-4), "least initial gap {least} (the clearance is 0.1)");
}

#[test]
fn cylinder_on_block_in_either_order_carries_the_same_load() {
    both_orders_agree("scenes/generic/cylinder_on_block.toml", "hertz", "cylinder_arc", "block_top");
}

#[test]
fn two_blocks_in_either_order_press_and_slide_alike() {
    let (_, swapped) =
        both_orders_agree("scenes/generic/two_blocks_press_slide.toml", "joint", "upper_bottom", "lower_top");
    // The lower block's top (x ∈ [0, 4], y = 1) against the upper block's bottom (x ∈ [1, 3],
    // y = 1): a point beyond the upper block lies at its distance |x − 1| or |x − 3| from the
    // curve, every other point touches it. A pair's gap is that distance averaged with the
    // node's multiplier weight, symmetric about the node over ±w (w its tributary length, for
    // Line2 and Line3 edges alike): where the distance is linear over [x − w, x + w] the average
    // is its value at the node. Those nodes (not the curve's ends, whose weight is one-sided)
    // are checked; round-off 1e-12.
    let out = &swapped;
    let interface = &out.built.interfaces[0];
    let distance = |x: f64| (1.0 - x).max(x - 3.0).max(0.0);
    let mut checked = 0;
    for pair in &out.built.problem.pairs[interface.pairs.clone()] {
        let x = out.built.problem.model.mesh.points[pair.master.0][0];
        let (a, b) = (x - pair.weight, x + pair.weight);
        let one_piece = |l: f64, r: f64| b <= r + 1e-12 && a >= l - 1e-12;
        if a > 1e-12 && b < 4.0 - 1e-12 && (one_piece(0.0, 1.0) || one_piece(1.0, 3.0) || one_piece(3.0, 4.0)) {
            let expected = distance(x);
            assert!((pair.gap - expected).abs() < 1e-12, "node at x = {x}: gap {} against {expected}", pair.gap);
            checked += 1;
        }
    }
    assert!(checked > 20, "only {checked} nodes checked");
}

const SELF_CONTACT: &str = "\n[[contact]]\nname = \"self\"\nmaster = \"upper_top\"\nslave = \"upper_bottom\"\n";

#[test]
fn two_curves_of_one_body_are_refused_with_the_body_named() {
    let path = "scenes/generic/two_blocks_press_slide.toml";
    let Err(error) = run(path, &scene_text(path, None, SELF_CONTACT)) else {
        panic!("a same-body pair must be refused")
    };
    match &error {
        GenericError::Contact { source, .. } => match source.as_ref() {
            ContactError::SameBody { contact, body, master, slave } => {
                assert_eq!((contact.as_str(), body.as_str()), ("self", "upper"));
                assert_eq!((master.as_str(), slave.as_str()), ("upper_top", "upper_bottom"));
            }
            other => panic!("not SameBody: {other}"),
        },
        other => panic!("not a contact error: {other}"),
    }
    let message = error.to_string();
    assert!(message.contains("\"upper\"") && message.contains("self_contact"), "{message}");
}

#[test]
fn declared_self_contact_across_a_block_is_open() {
    // The upper block's top (y = 2) faces its own bottom (y = 1) through the block: every pair
    // is open, its gap the height 1 (round-off 1e-12), and carries no force, so the joint keeps
    // its values: Σλ = P = 1000 (equilibrium of the floating block) and |Στ| = μ P = 300
    // (Coulomb), to the floating tolerance 1e-8 as in tests/behaviour/generic_scenes.rs.
    let path = "scenes/generic/two_blocks_press_slide.toml";
    for pairing in ["node_to_segment", "segment_to_segment"] {
        let extra = format!("{SELF_CONTACT}self_contact = true\npairing = \"{pairing}\"\n");
        let out = run(path, &scene_text(path, None, &extra)).unwrap();
        let r = &out.report;
        assert_eq!(r.status, "converged", "{pairing}");
        for g in gaps(&out, "self") {
            assert!((g - 1.0).abs() < 1e-12, "{pairing}: self-contact gap {g} (the block is 1 high)");
        }
        assert_eq!(r.contacts["self"].normal_force, 0.0, "{pairing}");
        assert_eq!(r.contacts["self"].contact_length, 0.0, "{pairing}");
        let joint = &r.contacts["joint"];
        assert!((joint.normal_force - 1000.0).abs() < 1e-8 * 1000.0, "{pairing}: {}", joint.normal_force);
        assert!((joint.tangential_force.abs() - 300.0).abs() < 1e-8 * 1000.0, "{pairing}: {}", joint.tangential_force);
    }
}

//! A slider pressed onto a long base and driven along it in a few long steps, with
//! `sliding = "finite"` (issue "Motion you can trust in any step", item 1): each step's pairs are
//! formed again on its answer until they hold, so a step of seven slider cells gives the answer
//! of many short ones.
//!
//! ```text
//!          F = 10 down (pattern "press"), u1 = d (pattern "drive") on the slider's top
//!        ┌──┐ ─────────────── 4 steps of 7 slider cells ──────────────→ ┌──┐
//!   ┌────┴──┴──────────────────────────────────────────────────────────┴──┴────┐ base [0, 6] × [−1, 0]
//!   └──────────────────────────────────────────────────────────────────────────┘ 24 cells, bottom clamped
//!   slider [0.5, 1.5] × [0, 0.5], 8 × 4 Quad9 cells of 0.125 (non-matching: the base's are 0.25)
//! ```
//!
//! Parameters: E = 1000 (base), 2000 (slider), ν = 0.3, plane strain, μ = 0.3, the press F = 10
//! per unit thickness (a force on the top), then the top driven by d = 3.5 (28 slider cells) in
//! four steps; the slider ends at [4, 5], still wholly on the base.
//!
//! Independent truths (closed forms, no stored output of ours):
//! * equilibrium of the slider (held in y by contact alone): the contact's resultant along y
//!   equals F at every step. Tolerance 1e-8 F: the floating body's iteration stops at a spring
//!   force of 1e-10 of the force scale (the bound `crates/contact/tests/integration/finite_sliding.rs` keeps).
//! * Coulomb in gross sliding: every pair in contact slips, Σ|τ| = μ Σλ, to 1e-6 F (the active
//!   set's cone is exact to round-off; the bound of the crate's sliding patch test).
//! * the contact length: the slider's whole bottom, 1 (the slider stays on the base; its trailing
//!   edge tips by O(μF/E) = 3e-3, far below a cell), within a quarter of a slider cell (the
//!   zone's ends are placed between nodes where the gap opens, `crate::generic::zones`).
//! * the converged path: the same drive in 28 steps of one slider cell gives the same friction
//!   force, normal force and contact length at the end to 1e-4 (Coulomb sliding on a flat base
//!   forgets its path once the whole interface slips: the long steps must find the short steps'
//!   state; what is left is the re-pairing's stopping rule, 1e-6 of a cell on the gap. The forces
//!   change by 3e-4 between whole and half base-cell positions, so a step that kept the wrong
//!   pairs would show; measured 4e-6.)
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::generic::{GenericOutcome, GenericScene, solve_generic_on_mesh};
use contact2d_mesh::generate::{append_prefixed, rectangle};
use contact2d_mesh::{CellKind, Mesh};

const F: f64 = 10.0;
const MU: f64 = 0.3;
const SLIDER_CELL: f64 = 0.125;

fn mesh() -> Mesh {
    let mut mesh = Mesh::default();
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.0, 6.0], [-1.0, 0.0], 24, 4), "base_");
    append_prefixed(&mut mesh, &rectangle(CellKind::Quad9, [0.5, 1.5], [0.0, 0.5], 8, 4), "slider_");
    mesh
}

/// The scene: press, then the drive of 28 slider cells in `steps` equal steps.
fn scene(steps: usize, pairing: &str) -> String {
    let drive = 28.0 * SLIDER_CELL;
    let mut schedule = String::from("  { press = 1.0 },\n");
    for j in 1..=steps {
        schedule.push_str(&format!("  {{ press = 1.0, drive = {:?} }},\n", j as f64 / steps as f64));
    }
    format!(
        r#"
name = "slider_long_steps"
mesh = "generated.msh"
plane = "strain"
[[body]]
region = "base_domain"
youngs_modulus = 1000.0
poissons_ratio = 0.3
[[body]]
region = "slider_domain"
youngs_modulus = 2000.0
poissons_ratio = 0.3
[[fix]]
group = "base_bottom"
u1 = 0.0
u2 = 0.0
[[fix]]
group = "slider_top"
u1 = {drive:?}
pattern = "drive"
[[load]]
group = "slider_top"
force = [0.0, -{F:?}]
pattern = "press"
[[contact]]
name = "joint"
master = "slider_bottom"
slave = "base_top"
friction = {MU:?}
pairing = "{pairing}"
sliding = "finite"
[loading]
schedule = [
{schedule}]
"#
    )
}

fn run(steps: usize, pairing: &str) -> GenericOutcome {
    let scene = GenericScene::from_toml_str(&scene(steps, pairing), Path::new("tests/generated.toml"), &[]).unwrap();
    solve_generic_on_mesh(&scene, mesh(), &mut |_, _| {}).unwrap()
}

/// (press, friction force Στ, normal force Σλ, contact length) of every step, checked against
/// equilibrium and Coulomb on the way.
fn checked(out: &GenericOutcome, label: &str) -> Vec<[f64; 4]> {
    assert_eq!(out.report.status, "converged", "{label}");
    let mut seen = vec![];
    for (i, step) in out.report.steps.iter().enumerate() {
        assert_eq!(step.status, "converged", "{label} step {}", i + 1);
        let c = &step.contacts["joint"];
        let press = c.resultant[1].abs();
        eprintln!(
            "{label} step {}: press {press:.10} Στ {:.8} Σλ {:.8} length {:.6} stick {:.4} re-pairings {:?}",
            i + 1,
            c.tangential_force,
            c.normal_force,
            c.contact_length,
            c.stick_length,
            step.repairings
        );
        assert!((press - F).abs() <= 1e-8 * F, "{label} step {}: press {press}, F = {F}", i + 1);
        if i > 0 {
            assert_eq!(c.stick_length, 0.0, "{label} step {}: a pair sticks while the slider is driven", i + 1);
            let coulomb = c.tangential_force.abs() - MU * c.normal_force;
            assert!(coulomb.abs() <= 1e-6 * F, "{label} step {}: Στ − μΣλ = {coulomb}", i + 1);
        }
        assert!(
            (c.contact_length - 1.0).abs() <= 0.25 * SLIDER_CELL,
            "{label} step {}: contact length {}",
            i + 1,
            c.contact_length
        );
        seen.push([press, c.tangential_force, c.normal_force, c.contact_length]);
    }
    seen
}

#[test]
fn a_slider_driven_in_four_long_steps_keeps_its_press_and_contact_length() {
    for pairing in ["node_to_segment", "segment_to_segment"] {
        let long = checked(&run(4, pairing), &format!("{pairing}, 4 steps"));
        let short = checked(&run(28, pairing), &format!("{pairing}, 28 steps"));
        let (a, b) = (long.last().unwrap(), short.last().unwrap());
        for (q, name) in [(1, "Στ"), (2, "Σλ"), (3, "contact length")] {
            assert!((a[q] - b[q]).abs() <= 1e-4 * b[q].abs(), "{pairing}: {name} {} in 4 steps, {} in 28", a[q], b[q]);
        }
    }
}

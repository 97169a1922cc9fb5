//! Hills–Nowell partial slip with a bulk stress in the flat, through the verification gallery's
//! case (`contact2d::verify::hills_nowell`, scene `scenes/generic/hills_nowell.toml`).
//!
//! ```text
//!                cylinder_top: u2 = −0.0142 (press), then u1 = 0.00293 · f (shear)
//!                    ___
//!                  /     \      roller R = 50, steel             a ≈ 0.5 ≪ R
//!   block_left ===== ‾‾‾‾‾ ===== block_right        block_top (slave)
//!   u1 = −0.045 f |  block σ  | u1 = +0.045 f      σ = E ε/(1 − ν²) ≈ 104 f MPa
//!                 =============  block_bottom: u2 = 0.0193 f (keeps the top at y = 0), u1 free
//! f = 1/3, 2/3, 1 after the press: Q and σ grow together.
//! ```
//!
//! Closed form (Nowell & Hills 1987, Int. J. Mech. Sci. 29; Hills & Nowell, *Mechanics of
//! Fretting Fatigue* (1994)): `c = a √(1 − Q/(μP))`, `e = sign(Q) a σ/(4 μ p0)` while
//! `|e| + c ≤ a`, evaluated at the measured P, Q and σ. Tolerances (justified in the case's
//! module docs): c/a and e/a within one pair spacing Δ/a on each mesh (0.060 on L1, 0.031 on
//! L2), because each end of the stick zone is placed inside the pair interval where the state
//! changes; σ of the end faces within 1e-4 of Hooke's law (the uniform state is exact on the
//! mesh); the shear profile's L2 error within 3 % of μ p0 on L2 (the Cattaneo–Mindlin bound, the
//! same two slip fronts). On the finest mesh the case also runs the last step with σ reversed
//! (the stick zone must move the other way by as much) and with σ = 0 (Cattaneo–Mindlin).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

use contact2d::verify::{Level, hills_nowell};

#[test]
fn the_stick_zone_shrinks_and_moves_by_a_sigma_over_4_mu_p0() {
    let report = hills_nowell::run(Path::new("."), Level::Fast).unwrap();
    println!("{}", contact2d::verify::report::text_table(std::slice::from_ref(&report)));
    assert!(report.notes.is_empty(), "{:?}", report.notes);
    // L1 and L2: 3 steps × (c, e, σ); L2 also 3 shear profiles; then σ reversed (c, e, σ,
    // shear) and σ = 0 (c, e, shear) on L2.
    assert_eq!(report.checks.len(), 2 * 9 + 3 + 4 + 3);
    for c in &report.checks {
        assert!(c.passed(), "{} on {}: {} against {}", c.quantity, c.mesh, c.measured, c.reference);
    }
    // The offset is σ's doing and follows its sign: the reversed run's e mirrors the scene's
    // last step about the common offset the roller itself causes (σ = 0), to within the pair
    // spacing (0.031 a on L2).
    let e = |prefix: &str| {
        report.checks.iter().filter(|c| c.mesh == "L2" && c.quantity.starts_with(prefix)).map(|c| c.measured).collect()
    };
    let offsets: Vec<f64> = e("e/a");
    let (last, reversed, zero) = (offsets[2], offsets[3], offsets[4]);
    assert!(last > 0.1 && reversed < -0.1, "{offsets:?}");
    assert!(((last - zero) + (reversed - zero)).abs() < 0.031, "{offsets:?}");
}

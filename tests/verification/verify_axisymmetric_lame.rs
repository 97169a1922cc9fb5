//! Verification: bodies of revolution (`kinematics = "axisymmetric"`) — the thick-walled tube
//! under internal pressure with closed and with open ends, and a solid cylinder's uniform
//! state with nodes on the axis.
//!
//! Citation: G. Lamé (1852), Leçons sur la théorie mathématique de l'élasticité des corps
//! solides; S. P. Timoshenko, J. N. Goodier (1970), Theory of Elasticity, 3rd ed., §28 (the
//! thick cylinder; with closed ends ε_zz = 0 the plane-strain displacement, with free ends
//! σ_zz = 0 the plane-stress displacement and a uniform axial strain); O. C. Zienkiewicz,
//! R. L. Taylor (2000), The Finite Element Method, vol. 1, ch. 5 (axisymmetric stress analysis:
//! the hoop row u_r / r, the weight 2πr). Rates: G. Strang, G. Fix (1973), An Analysis of the
//! Finite Element Method, ch. 3–4 (the weight r is smooth and positive on a tube a > 0).
//!
//! Set-up (`crates/verification/src/revolution.rs`): the meridian section a = 1 ≤ r ≤ b = 2,
//! 0 ≤ z ≤ 1 of a tube, p = 100 on r = a, E = 200 000, ν = 0.3, u_z = 0 at z = 0, and at z = 1
//! (closed) or free (open); n × n rectangle cells, n = 4, 8, 16 (T3, Q4) or 2, 4, 8 (T6, Q8, Q9).
//! Both closed forms are exact for the whole finite tube (no end effect).
//!
//! Goal and tolerances:
//! * the relative L2 error of u weighed by 2πr reaches the a priori rate h^(k+1) between the
//!   two finest meshes, to theory − 0.15 (the same bound as the plane Lamé study: the next
//!   term of the error expansion, which halves with each refinement, on the finest pair; a wrong
//!   hoop term or weight leaves an O(1) error and rate 0);
//! * the recovered σ_rr at the inner wall tends to −p and σ_θθ to Lamé's at rate ≥ k − 0.5
//!   between the two finest meshes. The recovery converges like the energy norm (h^k), but these
//!   meshes are pre-asymptotic for it: the plane Lamé study's first refinements measure k − 0.15
//!   (linear) to k − 0.42 (quadratic) (docs/verification.md), and here 0.73–0.92 (linear) and
//!   1.58–1.76 (quadratic); a wrong hoop term would not converge (rate ≈ 0);
//! * the solid cylinder's uniform state is reproduced to 1e-9 (round-off; its test is in
//!   `crates/verification/src/revolution.rs`).

use contact2d_mesh::CellKind;
use contact2d_verification::lame::{LameSetup, theoretical_rates};
use contact2d_verification::revolution::{TubeEnds, TubeLevel, solve_tube};

fn levels(kind: CellKind) -> [usize; 3] {
    match kind {
        CellKind::Tri3 | CellKind::Quad4 => [4, 8, 16],
        _ => [2, 4, 8],
    }
}

#[test]
fn the_tube_converges_to_lame_at_the_a_priori_rate_with_both_ends() {
    let setup = LameSetup::default();
    for kind in [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
        let (l2_rate, _) = theoretical_rates(kind);
        for ends in [TubeEnds::Closed, TubeEnds::Open] {
            let study: Vec<TubeLevel> =
                levels(kind).iter().map(|&n| solve_tube(kind, ends, n, &setup).unwrap().0).collect();
            let [_, coarse, fine] = [study[0], study[1], study[2]];
            let rate = (coarse.relative_l2 / fine.relative_l2).ln() / (coarse.h / fine.h).ln();
            assert!(rate >= l2_rate - 0.15, "{kind:?} {ends:?}: L2 rate {rate:.3} < {l2_rate} − 0.15 ({study:?})");
            let wall = |e: fn(&TubeLevel) -> f64| (e(&coarse) / e(&fine)).ln() / (coarse.h / fine.h).ln();
            let (radial, hoop) = (wall(|l| l.inner_radial_stress_error), wall(|l| l.inner_hoop_stress_error));
            eprintln!(
                "{kind:?} {ends:?}: L2 {:.3e} rate {rate:.2}; wall σrr {:.2e} rate {radial:.2}, σθθ {:.2e} rate {hoop:.2}",
                fine.relative_l2, fine.inner_radial_stress_error, fine.inner_hoop_stress_error
            );
            let k = l2_rate - 1.0;
            assert!(radial >= k - 0.5 && hoop >= k - 0.5, "{kind:?} {ends:?}: wall stress rates {radial}, {hoop}");
        }
    }
}

/// B-bar in a body of revolution (the hoop strain in the projected dilatation, every integral
/// weighed by 2πr), nearly incompressible: ν = 0.4999, closed ends. Lamé's displacement stays
/// finite as ν → ½ (u_r → p a² b² (1 + ν) / (E (b² − a²) r), isochoric), so a locking-free
/// element converges to it at its a priori rate, while the standard elements' error is set by
/// `λ div u_h` with λ = 5 000 E: the B-bar L2 error must reach rate k + 1 − 0.15 (the bound of
/// the compressible study above) and, on the finest mesh, be below a tenth of the standard
/// element's, and so must its inner-wall σθθ error (locking leaves the standard elements' wall
/// stress wrong by 12–57 times Lamé's, measured: docs/verification.md). Tri3 has no B-bar variant.
#[test]
fn bbar_tubes_of_revolution_do_not_lock() {
    use contact2d_element::Formulation;
    let nearly_incompressible = |formulation| LameSetup { poissons_ratio: 0.4999, formulation, ..LameSetup::default() };
    for kind in [CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
        let (l2_rate, _) = theoretical_rates(kind);
        let bbar = nearly_incompressible(Formulation::BBar);
        let study: Vec<TubeLevel> =
            levels(kind).iter().map(|&n| solve_tube(kind, TubeEnds::Closed, n, &bbar).unwrap().0).collect();
        let [_, coarse, fine] = [study[0], study[1], study[2]];
        let rate = (coarse.relative_l2 / fine.relative_l2).ln() / (coarse.h / fine.h).ln();
        let finest = levels(kind)[2];
        let standard =
            solve_tube(kind, TubeEnds::Closed, finest, &nearly_incompressible(Formulation::Standard)).unwrap().0;
        eprintln!(
            "{kind:?} ν = 0.4999: B-bar L2 {:.3e} (rate {rate:.2}), wall σθθ {:.2e}; standard L2 {:.3e}, wall σθθ {:.2e}",
            fine.relative_l2, fine.inner_hoop_stress_error, standard.relative_l2, standard.inner_hoop_stress_error
        );
        assert!(rate >= l2_rate - 0.15, "{kind:?}: B-bar L2 rate {rate:.3} < {l2_rate} − 0.15 ({study:?})");
        assert!(fine.relative_l2 < 0.1 * standard.relative_l2, "{kind:?}: B-bar {fine:?}, standard {standard:?}");
        assert!(
            fine.inner_hoop_stress_error < 0.1 * standard.inner_hoop_stress_error,
            "{kind:?}: wall σθθ, B-bar {fine:?}, standard {standard:?}"
        );
    }
}

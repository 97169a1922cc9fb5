//! Verification: the patch test on distorted meshes, for every element kind, in plane stress and
//! plane strain.
//!
//! Citation: B. M. Irons, A. Razzaque (1972), Experience with the patch test for convergence of
//! finite elements, in A. K. Aziz (ed.), The Mathematical Foundations of the Finite Element
//! Method, Academic Press, 557–587; R. L. Taylor, O. C. Zienkiewicz, J. C. Simo, A. H. C. Chan
//! (1986), The patch test — a condition for assessing FEM convergence, IJNME 22, 39–62.
//!
//! Goal: a constant-strain state must be reproduced exactly — displacements at every node and
//! the stress at every point of every cell — on a patch whose interior nodes are moved at random
//! (curved interior edges for the quadratic kinds). This is the consistency condition behind
//! every convergence result; it also exercises Dirichlet elimination with nonzero values, the
//! traction load vector and both nodal stress recoveries.
//!
//! ```text
//!  y = 1.5 +-----+----+-----+---+-----+   5 x 4 cells of T3 / T6 / Q4 / Q8 / Q9 on
//!          |     |     \    |    \    |   [1, 3] x [-0.5, 1.5], h = 0.4
//!          +-----+--+---+---+-----+---+   interior vertices: ±0.2 h per coordinate (seeded)
//!          |    /   |    \  |     |   |   interior mid-side / centre nodes: midpoint ± 0.05 h
//!          +---+----+-----+-+-----+---+   boundary nodes: not moved
//!          |   |      |     |     |   |
//!  y = -0.5+---+------+-----+-----+---+
//!         x = 1                     x = 3
//!
//!  (a) Dirichlet: u = u0 + G x on every boundary node,
//!      u0 = (0.01, -0.02), G = [[0.02, -0.015], [0.005, 0.03]]  (stretch, shear, rotation)
//!  (b) Traction:  u1 = 0 on x = 1, u2 = 0 on y = -0.5; traction (3, 0) on x = 3 and
//!      (0, -1.25) on y = 1.5, i.e. σ = (3, -1.25, 0); exact u1 = ε11 (x - 1), u2 = ε22 (y + 0.5)
//! ```
//!
//! Parameters: E = 200, ν = 0.3, thickness 1.
//!
//! Reference values: the affine field itself and its constant stress σ = D ε (exact).
//!
//! Tolerance: 1e-10, relative to the largest nodal displacement and the largest stress
//! component. The exact solution lies in the finite-element space and every stiffness rule
//! integrates `∫ ∇N_a · σ dΩ` exactly for constant σ, so only round-off remains: the stiffness of
//! this patch has a condition number of order 1e3–1e4, giving errors near 1e-13 at most;
//! 1e-10 leaves a wide margin while any consistency defect (a wrong shape-function derivative,
//! Jacobian, quadrature point or load) shows up at the 1e-3 level or above.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d::element::PlaneCondition;
use contact2d::mesh::CellKind;
use contact2d_verification::patch::{PatchSetup, PatchVariant, distorted_rectangle, run_patch_test};

const TOLERANCE: f64 = 1e-10;

fn check(kind: CellKind) {
    let setup = PatchSetup::default();
    for plane in [PlaneCondition::Stress, PlaneCondition::Strain] {
        for variant in [PatchVariant::Dirichlet, PatchVariant::Traction] {
            let r = run_patch_test(kind, plane, variant, &setup).unwrap();
            assert!(r.interior_nodes > 0, "{kind:?}: the patch has no interior node");
            assert!(
                r.displacement_error <= TOLERANCE,
                "{kind:?} {plane:?} {variant:?}: displacement error {:e}",
                r.displacement_error
            );
            assert!(r.stress_error <= TOLERANCE, "{kind:?} {plane:?} {variant:?}: stress error {:e}", r.stress_error);
        }
    }
}

#[test]
fn tri3_passes_the_patch_test() {
    check(CellKind::Tri3);
}

#[test]
fn tri6_passes_the_patch_test() {
    check(CellKind::Tri6);
}

#[test]
fn quad4_passes_the_patch_test() {
    check(CellKind::Quad4);
}

#[test]
fn quad8_passes_the_patch_test() {
    check(CellKind::Quad8);
}

#[test]
fn quad9_passes_the_patch_test() {
    check(CellKind::Quad9);
}

/// The patch is really distorted: vertices moved by a sizeable fraction of h, and the interior
/// mid-side nodes of quadratic cells off the chord of their edge (curved cells).
#[test]
fn patch_is_distorted_and_quadratic_edges_are_curved() {
    let setup = PatchSetup::default();
    for kind in [CellKind::Tri3, CellKind::Tri6, CellKind::Quad4, CellKind::Quad8, CellKind::Quad9] {
        let (mesh, max_move) = distorted_rectangle(kind, &setup).unwrap();
        assert!(max_move > 0.15, "{kind:?}: largest vertex move only {max_move} h");
        if matches!(kind, CellKind::Tri6 | CellKind::Quad8 | CellKind::Quad9) {
            let block = mesh.blocks.iter().find(|b| b.kind == kind).unwrap();
            let h = 0.4;
            let off_chord = block
                .cells()
                .flat_map(|c| {
                    let edges: &[[usize; 3]] = if kind == CellKind::Tri6 {
                        &[[0, 1, 3], [1, 2, 4], [2, 0, 5]]
                    } else {
                        &[[0, 1, 4], [1, 2, 5], [2, 3, 6], [3, 0, 7]]
                    };
                    edges
                        .iter()
                        .map(|&[s, e, m]| {
                            let (ps, pe, pm) = (mesh.points[c[s].0], mesh.points[c[e].0], mesh.points[c[m].0]);
                            let (dx, dy) = (pm[0] - 0.5 * (ps[0] + pe[0]), pm[1] - 0.5 * (ps[1] + pe[1]));
                            dx.hypot(dy) / h
                        })
                        .collect::<Vec<_>>()
                })
                .fold(0.0f64, f64::max);
            assert!(off_chord > 0.02, "{kind:?}: mid-side nodes at most {off_chord} h off the midpoint");
        }
    }
}

//! The condensed interface against an independent computation (`C = B K⁻¹ Bᵀ` by multi-RHS
//! solves with faer's AMD factorisation), and `ContactProblem::rebuild_moved` against building
//! the moved problem from scratch.
//!
//! ```text
//!   ┌──────────────┐  upper block "b_" (nodes moved by `lift` for the rebuild), master b_bottom
//!   └──────────────┘  ← gap
//!   ┌────────────────────┐  lower block "a_", slave a_top, bottom clamped
//!   └────────────────────┘
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use contact2d_contact::{ContactProblem, Interface, StepStart, pair_contours, solve_frictional_active_set};
use contact2d_element::{Kinematics, Material};
use contact2d_fem::{CholeskySolver, Component, Model};
use contact2d_mesh::generate::{MappedGrid, append_prefixed, mapped_grid, rectangle, side_name};
use contact2d_mesh::{CellKind, Contour};
use faer::Mat;

fn blocks(lift: f64, nb: usize) -> (Model, Vec<contact2d_contact::ContactPair>) {
    let kind = CellKind::Quad9;
    let mut mesh = rectangle(kind, [0.0, 3.0], [-1.0, 0.0], 9, 3);
    for g in &mut mesh.groups {
        g.name = format!("a_{}", g.name);
    }
    let upper = mapped_grid(
        &MappedGrid { kind, nx: nb, ny: 2, region: "domain" },
        |u, v| {
            let x = 0.5 + 2.0 * u;
            [x, 0.01 + lift * x + 0.8 * v]
        },
        |side, _| Some(side_name(side).to_string()),
    );
    append_prefixed(&mut mesh, &upper, "b_");
    let mut model = Model::new(mesh);
    model.add_body("a_domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.add_body("b_domain", Material::new(2.0, 0.25).unwrap(), Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
    model.fix("a_bottom", Component::X, 0.0).unwrap();
    model.fix("a_bottom", Component::Y, 0.0).unwrap();
    model.fix("b_top", Component::X, 0.01).unwrap();
    model.fix("b_top", Component::Y, -0.05).unwrap();
    let master = Contour::from_group(&model.mesh, "b_bottom").unwrap();
    let slave = Contour::from_group(&model.mesh, "a_top").unwrap();
    let pairs = pair_contours(&model, &master, &slave, "a_domain").unwrap();
    (model, pairs)
}

fn max_abs(m: &nalgebra::DMatrix<f64>) -> f64 {
    m.iter().fold(0.0f64, |a, v| a.max(v.abs()))
}

#[test]
fn compliances_equal_direct_solves() {
    let (model, pairs) = blocks(0.0, 5);
    let mut problem = ContactProblem::new(model, pairs).unwrap();
    problem.set_friction(0.3).unwrap();
    let interface = Interface::new(&problem);
    // Independent: AMD factor of the same K, K Z = Bᵀ, C = B Z.
    let amd = CholeskySolver::factor(&problem.system.stiffness).unwrap();
    let n = problem.system.dofs.num_free();
    let m = problem.num_pairs();
    let mut b = Mat::<f64>::zeros(n, 2 * m);
    for (k, row) in problem.normal_rows.iter().chain(&problem.tangent_rows).enumerate() {
        for &(i, v) in &row.free {
            b[(i, k)] += v;
        }
    }
    let c = b.transpose() * amd.solve_many(&b);
    let direct = nalgebra::DMatrix::from_fn(2 * m, 2 * m, |i, j| c[(i, j)]);
    let mut ours = nalgebra::DMatrix::zeros(2 * m, 2 * m);
    ours.view_mut((0, 0), (m, m)).copy_from(&interface.c_nn);
    ours.view_mut((0, m), (m, m)).copy_from(&interface.c_nt);
    ours.view_mut((m, 0), (m, m)).copy_from(&interface.c_tn);
    ours.view_mut((m, m), (m, m)).copy_from(&interface.c_tt);
    // Two backward-stable factorisations of a well-conditioned K: round-off agreement, 1e-10.
    assert!(max_abs(&(&ours - &direct)) < 1e-10 * max_abs(&direct));
    // The recovery: K u = w r + Bᵀ [λ; τ] for arbitrary forces.
    let forces: Vec<f64> = (0..2 * m).map(|k| (k as f64 * 0.7).sin()).collect();
    let u = interface.free_displacement(0.5, &forces[..m], &forces[m..]);
    let mut rhs: Vec<f64> = problem.pattern_rhs.iter().map(|r| 0.5 * r).collect();
    for (k, f) in forces.iter().enumerate() {
        for i in 0..n {
            rhs[i] += b[(i, k)] * f;
        }
    }
    let expected = amd.solve(&rhs);
    let scale = expected.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    assert!(u.iter().zip(&expected).all(|(a, e)| (a - e).abs() < 1e-10 * scale));
}

#[test]
fn rebuild_moved_equals_building_anew() {
    let (model, pairs) = blocks(0.0, 5);
    let mut problem = ContactProblem::new(model, pairs).unwrap();
    problem.set_friction(0.3).unwrap();
    let (moved, moved_pairs) = blocks(0.004, 5);
    let rebuilt = problem.rebuild_moved(moved.clone(), moved_pairs.clone()).unwrap();
    let mut fresh = ContactProblem::new(moved, moved_pairs).unwrap();
    fresh.set_friction(0.3).unwrap();
    assert_eq!(rebuilt.friction, fresh.friction);
    assert_eq!(rebuilt.gap, fresh.gap);
    let start = StepStart::initial(fresh.num_pairs());
    let a = solve_frictional_active_set(&rebuilt, &Interface::new(&rebuilt), 1.0, &start, None, 50);
    let b = solve_frictional_active_set(&fresh, &Interface::new(&fresh), 1.0, &start, None, 50);
    assert_eq!(a.state, b.state);
    // Same K and rows, different orderings: round-off agreement (1e-9 of the largest value).
    let scale = b.displacement.iter().fold(0.0f64, |x, v| x.max(v.abs()));
    assert!(a.displacement.iter().zip(&b.displacement).all(|(x, y)| (x - y).abs() < 1e-9 * scale));
    let fscale = b.normal_force.iter().fold(0.0f64, |x, v| x.max(v.abs()));
    assert!(a.normal_force.iter().zip(&b.normal_force).all(|(x, y)| (x - y).abs() < 1e-9 * fscale));
    // Another mesh (more cells in the upper block): a different pattern is refused.
    let (other, other_pairs) = blocks(0.0, 6);
    assert!(problem.rebuild_moved(other, other_pairs).is_err());
}

#[test]
fn load_terms_by_superposition_equal_one_solve() {
    let (model, pairs) = blocks(0.0, 5);
    let mut problem = ContactProblem::new(model, pairs).unwrap();
    problem.set_friction(0.3).unwrap();
    let main = problem.patterns()[0].clone();
    let n = main.rhs.len();
    let second = contact2d_contact::LoadPattern {
        name: "second".into(),
        rhs: (0..n).map(|i| (i as f64 * 0.37).sin()).collect(),
        prescribed: main.prescribed.iter().map(|v| -0.5 * v).collect(),
        nodal: vec![0.0; main.nodal.len()],
    };
    problem.set_patterns(vec![main, second]).unwrap();
    let mut interface = Interface::new(&problem);
    for factors in [[1.0, 0.0], [0.7, -1.3], [0.0, 2.0], [0.7, -1.3]] {
        problem.apply_load(&factors, None).unwrap();
        interface.update_load_factors(&problem, &factors);
        // Independent: one solve with the combined right-hand side.
        let direct = Interface::new(&problem);
        let close = |a: &[f64], b: &[f64]| {
            let scale = b.iter().fold(f64::MIN_POSITIVE, |m, v| m.max(v.abs()));
            // Superposing two backward-stable solves of a well-conditioned K differs from one
            // solve of the sum by round-off (cond(K) ε ≈ 1e-12 here): 1e-10.
            a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-10 * scale)
        };
        assert!(close(&interface.u0, &direct.u0), "u0 at {factors:?}");
        assert!(close(&interface.h_normal, &direct.h_normal), "h_N at {factors:?}");
        assert!(close(&interface.h_tangent, &direct.h_tangent), "h_T at {factors:?}");
    }
}

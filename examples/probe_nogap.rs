//! Probe: frictionless no-gap plate with insert, both algorithms.
#![allow(clippy::unwrap_used, clippy::expect_used)]
use contact2d::element::{Material, PlaneCondition};
use contact2d::fem::{BodyId, Component, Model, strain_energy};
use contact2d::mesh::{Contour, read_msh};
use contact2d_contact::*;
fn main() {
    let n: usize = std::env::args().nth(1).map(|s| s.parse().unwrap()).unwrap_or(16);
    let mesh = read_msh(format!("meshes/plate_insert/plate_insert_eps0_N{n}.msh")).unwrap();
    let mut model = Model::new(mesh);
    let m = Material::new(1.0, 0.3, PlaneCondition::Stress).unwrap();
    model.add_body("plate", m, 1.0).unwrap();
    model.add_body("insert", m, 1.0).unwrap();
    for g in ["top", "bottom_plate", "right"] {
        model.fix(g, Component::Y, 0.0).unwrap();
    }
    model.fix("right", Component::X, 1.0).unwrap();
    model.fix("insert_inner", Component::X, 0.0).unwrap();
    model.fix("insert_inner", Component::Y, 0.0).unwrap();
    model.fix("insert_symmetry", Component::Y, 0.0).unwrap();
    let hole = Contour::from_group(&model.mesh, "hole_edge").unwrap();
    let ins = Contour::from_group(&model.mesh, "insert_edge").unwrap();
    let t0 = std::time::Instant::now();
    let pairs = pair_contours(&model, &hole, &ins, "insert").unwrap();
    let problem = ContactProblem::new(model, pairs).unwrap();
    let t1 = t0.elapsed();
    let iface = Interface::new(&problem);
    let t2 = t0.elapsed();
    let sol = solve_frictionless_active_set(&problem, &iface, 1.0, 100);
    let qp = solve_frictionless_qp(&problem, 1.0);
    let report = |name: &str, s: &ContactSolution| {
        let fs = fem_solution(&problem, s);
        let p = fs.reaction_resultant(&problem.model, "right").unwrap()[0];
        let e1 = strain_energy(&problem.model, BodyId(0), &s.displacement).unwrap();
        let e2 = strain_energy(&problem.model, BodyId(1), &s.displacement).unwrap();
        let active = s.state.iter().filter(|st| **st != PairState::Free).count();
        println!(
            "{name}: {:?} it={} P={p:.5} E1={e1:.5} E2={e2:.5} P/2-E={:.2e} active={active}/{} kkt={:?} t={:?}",
            s.status,
            s.iterations,
            0.5 * p - e1 - e2,
            s.state.len(),
            s.kkt,
            s.time
        );
    };
    println!("setup {t1:?} interface {t2:?} dofs {}", problem.system.dofs.num_free());
    report("active-set", &sol);
    report("clarabel", &qp);
    let du = sol.displacement.iter().zip(&qp.displacement).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    let um = sol.displacement.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    println!("max |du|/max|u| = {:.2e}", du / um);
    // contact end: last pair with force, in eta = 1 - phi/pi
    for (k, p) in problem.pairs.iter().enumerate() {
        let x = problem.model.mesh.points[p.master.0];
        let eta = 1.0 - x[1].atan2(x[0]) / std::f64::consts::PI;
        if k % 4 == 0
            || sol.state[k] != PairState::Free
                && (k + 1 == problem.pairs.len()
                    || sol.state[k + 1] == PairState::Free
                    || sol.state[k.saturating_sub(1)] == PairState::Free)
        {
            println!(
                "  k={k} eta={eta:.4} lambda={:.5e} w={:.4e} p={:.5} gap={:.3e} gamma={:.4}",
                sol.normal_force[k],
                p.weight,
                -sol.normal_force[k] / p.weight,
                sol.gap[k],
                p.gamma
            );
        }
    }
}

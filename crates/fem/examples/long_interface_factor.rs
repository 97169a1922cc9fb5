//! The floor of the long-interface benchmark (docs/benchmarks.md, "Sparse contact solves"): the
//! two blocks of `meshes/generic/long_interface.geo` assembled without contact and `K_ff`
//! factored alone (faer's sparse Cholesky, AMD), timed.
//!
//! ```text
//! cargo run --release -p contact2d-fem --example long_interface_factor -- mesh.msh
//! → per factor kind (faer's automatic choice, forced supernodal): DOFs, entries of L,
//!   factorisation time (best of 3), one solve's time
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used)]

use contact2d_element::{Kinematics, Material};
use contact2d_fem::{CholeskySolver, Component, Model, assemble};

/// A factorisation of `K`.
type Factor = fn(&contact2d_fem::Csc) -> Result<CholeskySolver, contact2d_fem::FemError>;

fn main() {
    let path = std::env::args().nth(1).expect("usage: long_interface_factor <mesh.msh>");
    let mesh = contact2d_mesh::read_msh(&path).expect("a readable mesh");
    let mut model = Model::new(mesh);
    let steel = Material::new(2e5, 0.3).expect("valid material");
    model.add_body("lower", steel, Kinematics::PlaneStrain { thickness: 1.0 }).expect("region lower");
    model.add_body("upper", steel, Kinematics::PlaneStrain { thickness: 1.0 }).expect("region upper");
    model.fix("lower_bottom", Component::X, 0.0).expect("group lower_bottom");
    model.fix("lower_bottom", Component::Y, 0.0).expect("group lower_bottom");
    model.fix("upper_top", Component::X, 0.0).expect("group upper_top");
    model.fix("upper_top", Component::Y, -0.001).expect("group upper_top");
    let system = assemble(&model).expect("assembly");
    let rhs = system.rhs(system.dofs.prescribed_values());
    let factors: [(&str, Factor); 2] =
        [("automatic", CholeskySolver::factor), ("supernodal", CholeskySolver::factor_supernodal)];
    for (name, factor) in factors {
        let mut best = f64::INFINITY;
        let mut solver = None;
        for _ in 0..3 {
            let clock = std::time::Instant::now();
            solver = Some(factor(&system.stiffness).expect("K positive definite"));
            best = best.min(clock.elapsed().as_secs_f64());
        }
        let solver = solver.expect("factored");
        let clock = std::time::Instant::now();
        let _u = solver.solve(&rhs);
        let solve = clock.elapsed().as_secs_f64();
        println!(
            "{name}: dofs {} nnz(L) {} factor {best:.3} s solve {solve:.4} s",
            system.dofs.num_free(),
            solver.factor_nnz()
        );
    }
}

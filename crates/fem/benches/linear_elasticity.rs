//! Foundation benchmarks of linear plane elasticity on generated meshes: one element stiffness,
//! assembly, and Cholesky factorisation + solve of a structured Quad9 cantilever.
//!
//! ```text
//!        y = 1 ┌──────────────────────────────────────┐
//!  u1 = u2 = 0 │  4 ny × ny Quad9 cells               │ ← traction (0, -1) on "right"
//!     ("left") │  E = 1000, ν = 0.3, plane stress     │
//!        y = 0 └──────────────────────────────────────┘
//!            x = 0                                  x = 4
//!   DOFs = 2 (8 ny + 1)(2 ny + 1):  ny = 18 → 10 730,  ny = 56 → 101 474
//! ```
//!
//! Run with `cargo bench -p contact2d-fem --bench linear_elasticity` (about two minutes on two
//! cores). The 10⁶-DOF case, too slow for criterion's sampling, is timed phase by phase by
//! `examples/bench_linear.rs`; results and the machine are in docs/benchmarks.md.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use std::hint::black_box;
use std::time::Duration;

use contact2d_element::{ElementType, GaussRule, Kinematics, Material, PlaneCondition, element_stiffness};
use contact2d_fem::{CholeskySolver, Component, EdgeLoad, Model, assemble};
use contact2d_mesh::{CellKind, generate};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, SamplingMode, criterion_group, criterion_main};

/// The cantilever with `ny` cells across (and `4 ny` along), ready to assemble.
fn cantilever(ny: usize) -> Model {
    let mesh = generate::rectangle(CellKind::Quad9, [0.0, 4.0], [0.0, 1.0], 4 * ny, ny);
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(1000.0, 0.3).unwrap(), Kinematics::PlaneStress { thickness: 1.0 }).unwrap();
    model.fix("left", Component::X, 0.0).unwrap();
    model.fix("left", Component::Y, 0.0).unwrap();
    model.add_edge_load(EdgeLoad::Traction { group: "right".into(), traction: [0.0, -1.0] }).unwrap();
    model
}

/// Cells across the cantilever and a label with the resulting number of DOFs.
const SIZES: [(usize, &str); 2] = [(18, "10730_dofs"), (56, "101474_dofs")];

/// Ten samples of one run each (flat sampling): enough for runs of tens to hundreds of ms.
fn few_samples(group: &mut BenchmarkGroup<'_, WallTime>) {
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
}

fn element_stiffness_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("element_stiffness");
    let material = Material::new(1000.0, 0.3).unwrap();
    let kinematics = Kinematics::plane(PlaneCondition::Stress, 1.0).unwrap();
    for (name, element) in [("Q4", ElementType::Quad4), ("Q9", ElementType::Quad9), ("T6", ElementType::Tri6)] {
        // A sheared, stretched copy of the reference element (a general affine map).
        let coords: Vec<[f64; 2]> =
            element.reference_nodes().iter().map(|&[x, y]| [1.3 * x + 0.2 * y + 2.0, -0.1 * x + 0.9 * y]).collect();
        let rule = GaussRule::stiffness_rule(element);
        group.bench_function(name, |b| {
            b.iter(|| element_stiffness(element, black_box(&coords), &material, &kinematics, &rule).unwrap())
        });
    }
    group.finish();
}

fn assembly_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("assemble_q9");
    few_samples(&mut group);
    for (ny, label) in SIZES {
        let model = cantilever(ny);
        group.bench_with_input(BenchmarkId::from_parameter(label), &model, |b, model| {
            b.iter(|| assemble(model).unwrap())
        });
    }
    group.finish();
}

fn factor_solve_bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("cholesky_q9");
    few_samples(&mut group);
    for (ny, label) in SIZES {
        let system = assemble(&cantilever(ny)).unwrap();
        let rhs = system.rhs(system.dofs.prescribed_values());
        group.bench_with_input(BenchmarkId::new("factor_solve", label), &system, |b, system| {
            b.iter(|| CholeskySolver::factor(&system.stiffness).unwrap().solve(black_box(&rhs)))
        });
        // Numeric factorisation only, the symbolic analysis kept (as in contact iterations).
        let mut solver = CholeskySolver::factor(&system.stiffness).unwrap();
        group.bench_with_input(BenchmarkId::new("refactor", label), &system, |b, system| {
            b.iter(|| solver.refactor(&system.stiffness).unwrap())
        });
        let solver = CholeskySolver::factor(&system.stiffness).unwrap();
        group
            .bench_with_input(BenchmarkId::new("solve", label), &rhs, |b, rhs| b.iter(|| solver.solve(black_box(rhs))));
    }
    group.finish();
}

criterion_group!(benches, element_stiffness_bench, assembly_bench, factor_solve_bench);
criterion_main!(benches);

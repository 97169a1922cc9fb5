//! The penalty method's trade-off: its error against the relative penalty κ, and what a larger κ
//! costs in conditioning and iterations, on the generic two-block press-and-slide scene (μ = 0.3)
//! and the Hertz scene (NAFEMS roller on a block, frictionless).
//!
//! ```text
//! reference   the active set on the same mesh (the exact discrete solution: the penalty's error
//!             is the method's, not the mesh's)
//! errors      |x_κ − x_ref| / |x_ref| for the largest pressure, the contact length, the total
//!             strain energy and (two blocks) the tangential force, at the last step
//! cond        cond₂(K + ε_N Σ_active b bᵀ) on the converged contact set (K with a floating
//!             body's stabilising springs, as solved): λ_max by 300 power iterations, λ_min by
//!             300 inverse iterations (sparse Cholesky); "K alone" is the same without penalty
//! iterations  the penalty's state iterations summed over the steps (and over the floating
//!             roller's proximal iterations for Hertz)
//! ```
//!
//! Run: `cargo run --release --example penalty_tradeoff`; the tables are in docs/algorithms.md
//! ("Penalty").
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::Path;

use contact2d::contact::{ContactProblem, PairState, contact_stiffness};
use contact2d::generic::{GenericOutcome, load_scene, solve_generic};
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

fn run(scene: &str, overrides: &[String]) -> GenericOutcome {
    let scene = load_scene(Path::new(scene), overrides).unwrap();
    solve_generic(&scene, &mut |_, _| {}).unwrap()
}

/// `K_ff` (both triangles) plus `ε b bᵀ` for every pair in contact.
fn penalised(problem: &ContactProblem, state: &[PairState], epsilon: f64) -> SparseColMat<usize, f64> {
    let k = problem.system.stiffness.as_ref();
    let mut t = vec![];
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            t.push(Triplet::new(i, j, *v));
            if i != j {
                t.push(Triplet::new(j, i, *v));
            }
        }
    }
    for (row, s) in problem.normal_rows.iter().zip(state) {
        if *s == PairState::Free {
            continue;
        }
        for (i, a) in &row.free {
            for (j, b) in &row.free {
                t.push(Triplet::new(*i, *j, epsilon * a * b));
            }
        }
    }
    let n = k.ncols();
    SparseColMat::try_new_from_triplets(n, n, &t).unwrap()
}

/// `cond₂` of a symmetric positive definite matrix, by power and inverse iteration.
fn condition(a: &SparseColMat<usize, f64>) -> f64 {
    let n = a.ncols();
    let norm = |v: &Mat<f64>| (0..n).map(|i| v[(i, 0)] * v[(i, 0)]).sum::<f64>().sqrt();
    let start = Mat::<f64>::from_fn(n, 1, |i, _| 1.0 + ((i * 7919) % 13) as f64 / 13.0);
    let (mut v, mut largest) = (start.clone(), 0.0);
    for _ in 0..300 {
        let w = a * &v;
        largest = norm(&w) / norm(&v);
        v = &w * faer::Scale(1.0 / norm(&w));
    }
    let llt = a.sp_cholesky(Side::Lower).unwrap();
    let (mut v, mut smallest) = (start, 0.0);
    use faer::linalg::solvers::Solve;
    for _ in 0..300 {
        let w = llt.solve(&v);
        smallest = norm(&v) / norm(&w);
        v = &w * faer::Scale(1.0 / norm(&w));
    }
    largest / smallest
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

fn table(scene: &str, contact: &str, mesh: Option<&str>) {
    let base: Vec<String> = mesh.map(|m| format!("mesh=\"{m}\"")).into_iter().collect();
    let with = |extra: &[&str]| {
        let mut o = base.clone();
        o.extend(extra.iter().map(|s| s.to_string()));
        o
    };
    let reference = run(scene, &with(&["solver.algorithm=active_set"]));
    let r = &reference.report;
    let rc = &r.contacts[contact];
    let r_energy: f64 = r.energies.values().sum();
    let problem = &reference.built.problem;
    let k_c = contact_stiffness(problem);
    let state = &reference.history.steps.last().unwrap().solution.state;
    let cond_k = condition(&penalised(problem, state, 0.0));
    println!(
        "\n{scene} ({} DOFs, {} pairs; k_c = {k_c:.4e}; active set: {} iterations; cond(K alone) = {cond_k:.2e})",
        r.dofs, r.pairs, r.iterations
    );
    println!(
        "| κ | status | iterations | max pressure | contact length | energy | tangential force | max penetration / U | cond |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for kappa in [1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e8] {
        let out = run(scene, &with(&["solver.algorithm=penalty", &format!("solver.penalty={kappa:e}")]));
        let p = &out.report;
        let c = &p.contacts[contact];
        let energy: f64 = p.energies.values().sum();
        let last = &out.history.steps.last().unwrap().solution;
        let u = last.displacement.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let cond = condition(&penalised(&out.built.problem, &last.state, kappa * k_c));
        let tangential = if rc.tangential_force.abs() > 0.0 {
            format!("{:.2e}", relative(c.tangential_force, rc.tangential_force))
        } else {
            "—".into()
        };
        println!(
            "| {kappa:.0e} | {} | {} | {:.2e} | {:.2e} | {:.2e} | {tangential} | {:.2e} | {:.2e} |",
            p.status,
            p.iterations,
            relative(c.max_pressure, rc.max_pressure),
            relative(c.contact_length, rc.contact_length),
            relative(energy, r_energy),
            last.kkt.max_penetration / u,
            cond
        );
    }
}

fn main() {
    table("scenes/generic/two_blocks_press_slide.toml", "joint", None);
    table("scenes/generic/cylinder_on_block.toml", "hertz", Some("../../meshes/generic/cylinder_on_block_L1.msh"));
}

//! Where the full-system augmented Lagrangian overtakes the condensed active set: wall time
//! against interface size on two families of two-block problems (press and slide, μ = 0.3).
//!
//! ```text
//!            ↓ push 0.02, → slide 0.005 (prescribed on top)
//!   ┌────────────────┐  upper block, width 2W/3, E = 2, master (its bottom): nb + 1 pairs
//!   └────────────────┘  ← gap 0.002 + 0.002 (x/W − ½)
//!   ┌────────────────────────┐  lower block, width W, E = 1, slave (its top)
//!   └────────────────────────┘  bottom clamped
//! slab:    height 1, 4 cells through each block (DOFs grow like the interface)
//! square:  height W/3, cells square (DOFs grow like the interface squared)
//! ```
//!
//! Times (median of `--repeat`, default 3, wall clock, sequential faer): `condensed` is
//! `Interface::new` (u0 and C = Yᵀ Y on the factor's trailing block) plus the frictional active
//! set and the recovery of u; `full` is the augmented Lagrangian (one sparse LU of the
//! (n + 2m)-square system per Newton iteration). The Cholesky factor of K, built with every
//! problem, is shared set-up and excluded from both (the augmented Lagrangian uses it only for
//! its first state guess). Run:
//! `cargo run --release --example crossover_augmented_lagrangian -- 25 50 100 200 400`
//! (the arguments are the lower block's cells along the interface; `--slab-only` skips the
//! square family); results in
//! docs/benchmarks.md.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Instant;

use contact2d::contact::{
    ContactProblem, ContactStatus, Interface, StepStart, pair_contours, solve_augmented_lagrangian,
    solve_frictional_active_set,
};
use contact2d::element::{Kinematics, Material};
use contact2d::fem::{Component, Model};
use contact2d::mesh::generate::{MappedGrid, append_prefixed, mapped_grid, side_name};
use contact2d::mesh::{CellKind, Contour};

/// The two-block problem with `na` cells along the lower block and `rows` cells through each.
fn two_blocks(na: usize, rows: usize, height: f64) -> ContactProblem {
    let width = 3.0;
    let nb = (2 * na).div_ceil(3) + 1;
    let block = |nx: usize, x0: f64, x1: f64, y0: f64, bottom_gap: bool| {
        mapped_grid(
            &MappedGrid { kind: CellKind::Quad4, nx, ny: rows, region: "domain" },
            move |u, v| {
                let x = x0 + (x1 - x0) * u;
                let gap = if bottom_gap { 0.002 + 0.002 * (x / width - 0.5) } else { 0.0 };
                [x, y0 + gap + height * v]
            },
            |side, _| Some(side_name(side).to_string()),
        )
    };
    let mut mesh = block(na, 0.0, width, -height, false);
    for g in &mut mesh.groups {
        g.name = format!("a_{}", g.name);
    }
    append_prefixed(&mut mesh, &block(nb, 0.5, 2.5, 0.0, true), "b_");
    let mut model = Model::new(mesh);
    model.add_body("a_domain", Material::new(1.0, 0.3).unwrap(), Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
    model.add_body("b_domain", Material::new(2.0, 0.3).unwrap(), Kinematics::PlaneStrain { thickness: 1.0 }).unwrap();
    model.fix("a_bottom", Component::X, 0.0).unwrap();
    model.fix("a_bottom", Component::Y, 0.0).unwrap();
    model.fix("b_top", Component::X, 0.005).unwrap();
    model.fix("b_top", Component::Y, -0.02).unwrap();
    let master = Contour::from_group(&model.mesh, "b_bottom").unwrap();
    let slave = Contour::from_group(&model.mesh, "a_top").unwrap();
    let pairs = pair_contours(&model, &master, &slave, "a_domain").unwrap();
    let mut problem = ContactProblem::new(model, pairs).unwrap();
    problem.set_friction(0.3).unwrap();
    problem
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut repeat = 3;
    if let Some(i) = args.iter().position(|a| a == "--repeat") {
        repeat = args.get(i + 1).and_then(|r| r.parse().ok()).unwrap_or(3);
        args.drain(i..(i + 2).min(args.len()));
    }
    let slab_only = args.iter().any(|a| a == "--slab-only");
    let levels: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    println!(
        "| family | cells along | DOFs | pairs | condensed s | iterations | full s | iterations | max force difference |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for (family, slab) in [("slab", true), ("square", false)] {
        if slab_only && !slab {
            continue;
        }
        for &na in &levels {
            let (rows, height) = if slab { (4, 1.0) } else { (na.div_ceil(3).max(2), 1.0) };
            let problem = two_blocks(na, rows, height);
            let start = StepStart::initial(problem.num_pairs());
            let (mut condensed, mut full) = (vec![], vec![]);
            let (mut a, mut b) = (None, None);
            for _ in 0..repeat.max(1) {
                let clock = Instant::now();
                let interface = Interface::new(&problem);
                let s = solve_frictional_active_set(&problem, &interface, 1.0, &start, None, 200);
                condensed.push(clock.elapsed().as_secs_f64());
                a = Some(s);
                let clock = Instant::now();
                let s = solve_augmented_lagrangian(&problem, 1.0, &start, None, 200);
                full.push(clock.elapsed().as_secs_f64());
                b = Some(s);
            }
            let (a, b) = (a.unwrap(), b.unwrap());
            let scale = a.normal_force.iter().chain(&a.tangential_force).fold(0.0f64, |m, v| m.max(v.abs()));
            let diff = a
                .normal_force
                .iter()
                .zip(&b.normal_force)
                .chain(a.tangential_force.iter().zip(&b.tangential_force))
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
            let mark = |s: ContactStatus| if s == ContactStatus::Converged { "" } else { " (not converged)" };
            println!(
                "| {family} | {na} | {} | {} | {:.4} | {}{} | {:.4} | {}{} | {:.1e} |",
                problem.system.dofs.num_free(),
                problem.num_pairs(),
                median(condensed),
                a.iterations,
                mark(a.status),
                median(full),
                b.iterations,
                mark(b.status),
                diff / scale
            );
        }
    }
}

//! Contact-solve benchmark: the frictional no-gap plate with insert (μ = 0.3, w = 1, the scene
//! `scenes/plate_insert_nogap_mu03.toml`) at N = 16 … 128, each phase timed on its own, with
//! what each saving of docs/algorithms.md ("What a scene does not compute") is worth.
//!
//! ```text
//! set-up      mesh read + node-to-node morphing + pairing + ContactProblem::new (PlateInsert::build)
//!   of which  assemble | factor of K bordered by the pair rows (AMD on K, rows last, LDLᵀ)
//! condense    Interface::new: u0 = K⁻¹ r and C = W Wᵀ from the factor's last block
//! algorithm   frictional active set on the interface; recovery = one solve for u
//! before      the previous condensation: AMD factor, K Z = Bᵀ for 2 × pairs columns, C = B Z
//! linear      one linear solve of the same mesh (assemble + AMD factor + solve, no contact)
//! ```
//!
//! Every time is the mean over at least `--repeat` runs (default 3) and 0.25 s, in CPU time of the
//! whole process (all threads; `--wall` for wall-clock time). Run:
//! `RAYON_NUM_THREADS=1 cargo run --release --example bench_contact -- 16 32 64 128`; results in
//! docs/benchmarks.md.

use std::time::Instant;

use contact2d::contact::condensed_rows;
use contact2d::contact::{
    ContactProblem, Interface, RawSolution, StepStart, equal_steps, finish_from_forces, history::march,
    solve_frictional_active_set,
};
use contact2d::fem::{CholeskySolver, Component, Dof, DofKind, Ordering, assemble, fill_reducing_permutation};
use contact2d::plate_insert::PlateInsert;
use faer::Mat;

/// CPU time of all threads of this process so far (Linux `/proc/self/task/*/schedstat`, ns), if
/// readable.
fn cpu_seconds() -> Option<f64> {
    let mut total = 0u64;
    for task in std::fs::read_dir("/proc/self/task").ok()? {
        let stat = std::fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        total += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(total as f64 * 1e-9)
}

/// Whether times are CPU times (the default: robust on a shared machine; with
/// `RAYON_NUM_THREADS=1` they are what a quiet core would take) or wall times (`--wall`).
static WALL: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

fn now() -> f64 {
    static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
    let wall = START.get_or_init(Instant::now).elapsed().as_secs_f64();
    if WALL.load(std::sync::atomic::Ordering::Relaxed) { wall } else { cpu_seconds().unwrap_or(wall) }
}

/// Mean time of `f` over at least `repeat` runs and at least 0.25 s (so that the CPU clock, which
/// advances in scheduler ticks, resolves sub-millisecond phases), and the last result.
fn best<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let start = now();
    let mut calls = 0usize;
    loop {
        let r = f();
        calls += 1;
        let elapsed = now() - start;
        if calls >= repeat.max(1) && elapsed >= 0.25 {
            return (elapsed / calls as f64, r);
        }
    }
}

/// The free DOFs of every node a pair row touches (the DOFs "contact DOFs last" orders last).
fn contact_dofs(problem: &ContactProblem) -> Vec<usize> {
    let dofs = &problem.system.dofs;
    let mut seen = vec![false; dofs.num_free()];
    let mut out = vec![];
    for row in problem.normal_rows.iter().chain(&problem.tangent_rows) {
        for &(i, _) in &row.free {
            let node = dofs.free_dofs()[i].node();
            for c in [Component::X, Component::Y] {
                if let DofKind::Free(j) = dofs.kind(Dof::of(node, c))
                    && !std::mem::replace(&mut seen[j], true)
                {
                    out.push(j);
                }
            }
        }
    }
    out
}

fn ms(s: f64) -> String {
    format!("{:.1}", 1e3 * s)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut levels: Vec<usize> = vec![];
    let mut repeat = 3;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--wall" {
            WALL.store(true, std::sync::atomic::Ordering::Relaxed);
        } else if a == "--repeat" {
            repeat = args.next().ok_or("--repeat needs a value")?.parse()?;
        } else {
            levels.push(a.parse()?);
        }
    }
    if levels.is_empty() {
        levels = vec![16, 32, 64, 128];
    }
    println!(
        "| N | DOFs | pairs | contact DOFs | set-up | assemble | factor (bordered) | condense | algorithm (it) | recovery | contact total | linear solve | ratio | P | Φ_f |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut savings = vec![];
    let mut orderings = vec![];
    for n in levels {
        let mesh = format!("{}/meshes/plate_insert/plate_insert_eps0_N{n}.msh", env!("CARGO_MANIFEST_DIR"));
        let spec = PlateInsert { friction: 0.3, ..PlateInsert::paper(mesh) };
        let (t_setup, case) = best(repeat, || spec.build());
        let case = case?;
        let problem = &case.problem;
        let (model, pairs) = (problem.model.clone(), problem.pairs.clone());
        let (t_assemble, system) = best(repeat, || assemble(&model));
        let system = system?;
        let last = contact_dofs(problem);
        // The problem's own factorisation: K bordered by the pair rows (AMD on K, rows last).
        let (_, rows) = condensed_rows(&problem.normal_rows, &problem.tangent_rows);
        let (t_bordered, bordered) = best(repeat, || CholeskySolver::factor_with_constraints(&system.stiffness, &rows));
        let bordered = bordered?;
        // The previous one: AMD with the contact DOFs last (trailing block = Schur complement).
        let (t_order, forward) =
            best(repeat, || fill_reducing_permutation(&model, &system.dofs, &system.stiffness, Ordering::Amd, &last));
        let forward = forward?;
        let (t_factor, solver) = best(repeat, || CholeskySolver::factor_with_permutation(&system.stiffness, &forward));
        let solver = solver?;
        let (t_nd_last, nd_last) = best(repeat, || {
            let f =
                fill_reducing_permutation(&model, &system.dofs, &system.stiffness, Ordering::NestedDissection, &last)?;
            CholeskySolver::factor_with_permutation(&system.stiffness, &f)
        });
        let nd_last = nd_last?;
        let (t_condense, interface) = best(repeat, || Interface::new(problem));
        let start = StepStart::initial(problem.num_pairs());
        let (t_solve, solution) =
            best(repeat, || solve_frictional_active_set(problem, &interface, 1.0, &start, None, 100));
        // The recovery (one solve for u, then the evaluation) on its own; the algorithm is the rest.
        let raw = RawSolution {
            load_factor: 1.0,
            normal_force: solution.normal_force.clone(),
            tangential_force: solution.tangential_force.clone(),
            status: solution.status,
            iterations: solution.iterations,
            time: solution.time,
        };
        let (t_recovery, _) = best(repeat, || finish_from_forces(problem, &interface, raw.clone(), &start));
        let t_algorithm = (t_solve - t_recovery).max(0.0);
        let q = case.results(&solution)?;
        // One linear solve of the same mesh: assemble, factor (AMD), solve.
        let (t_linear, _) = best(repeat, || -> Result<Vec<f64>, Box<dyn std::error::Error>> {
            let s = assemble(&model)?;
            let k = CholeskySolver::factor(&s.stiffness)?;
            Ok(k.solve(&s.rhs(s.dofs.prescribed_values())))
        });
        let contact_total = t_setup + t_condense + t_solve;
        println!(
            "| {n} | {} | {} | {} | {} | {} | {} | {} | {} ({}) | {} | **{}** | {} | {:.2} | {:.5} | {:.6} |",
            system.dofs.num_free(),
            problem.num_pairs(),
            last.len(),
            ms(t_setup),
            ms(t_assemble),
            ms(t_bordered),
            ms(t_condense),
            ms(t_algorithm),
            solution.iterations,
            ms(t_recovery),
            ms(contact_total),
            ms(t_linear),
            (t_assemble + t_bordered + t_condense + t_solve) / t_linear,
            q.pull,
            q.dissipation,
        );

        // Before: AMD factor, then K Z = Bᵀ for the normal and tangential columns, C = B Z.
        let (t_amd, amd) = best(repeat, || CholeskySolver::factor(&system.stiffness));
        let amd = amd?;
        let nf = system.dofs.num_free();
        let (t_old_condense, _) = best(repeat, || {
            let mut b = Mat::<f64>::zeros(nf, 2 * problem.num_pairs());
            for (k, row) in problem.normal_rows.iter().chain(&problem.tangent_rows).enumerate() {
                for &(i, v) in &row.free {
                    b[(i, k)] += v;
                }
            }
            let u0 = amd.solve(&problem.pattern_rhs);
            let z = amd.solve_many(&b);
            (u0, b.transpose() * &z)
        });
        // Frictionless: no tangential unknowns against the same problem with them.
        let mut frictionless = problem.clone();
        frictionless.set_friction(0.0)?;
        let (t_condense_mu0, _) = best(repeat, || Interface::new(&frictionless));
        // Reusing the symbolic factorisation on a moved mesh against building anew.
        let (t_rebuild, rebuilt) = best(repeat, || problem.rebuild_moved(model.clone(), pairs.clone()));
        rebuilt?;
        let (t_new, _) = best(repeat, || ContactProblem::new(model.clone(), pairs.clone()));
        // No gap: one solve at w = 1 scaled, against a ten-step history.
        let (t_history, _) = best(repeat, || {
            march::<f64, std::convert::Infallible>(
                &equal_steps(1.0, 10),
                problem.num_pairs(),
                |&w, start, guess| Ok(solve_frictional_active_set(problem, &interface, w, start, guess, 100)),
                &mut |_| {},
            )
        });
        // Condensed once against re-solving the bodies in every active-set iteration.
        let (t_refactor_solve, _) = best(repeat, || {
            let mut s = solver.clone();
            s.refactor(&system.stiffness).map(|_| s.solve(&problem.pattern_rhs))
        });
        let (t_amd_plain, amd_plain) = best(repeat, || CholeskySolver::factor(&system.stiffness));
        let amd_plain = amd_plain?;
        orderings.push(format!(
            "| {n} | {nf} | {:.2} M, {} ms | {:.2} M, {} ms | {:.2} M, {} ms | {:.2} M, {} ms |",
            amd_plain.factor_nnz() as f64 * 1e-6,
            ms(t_amd_plain),
            bordered.factor_nnz() as f64 * 1e-6,
            ms(t_bordered),
            solver.factor_nnz() as f64 * 1e-6,
            ms(t_order + t_factor),
            nd_last.factor_nnz() as f64 * 1e-6,
            ms(t_nd_last)
        ));
        savings.push((
            n,
            nf,
            [
                (t_amd + t_old_condense, t_bordered + t_condense),
                (t_condense, t_condense_mu0),
                (t_new, t_rebuild),
                (t_history, t_solve),
                (solution.iterations as f64 * t_refactor_solve, t_condense + t_solve),
                (t_assemble, 0.0),
            ],
        ));
    }
    println!();
    println!(
        "| N | DOFs | AMD (faer's, free order, K alone): nnz(L), order + factor | bordered by the pair rows (the problem's) | AMD, contact DOFs last (before) | ND, contact DOFs last |"
    );
    println!("|---|---|---|---|---|---|");
    for row in orderings {
        println!("{row}");
    }
    println!();
    println!(
        "| N | DOFs | AMD factor + condensation: before (K Z = Bᵀ) / after (bordered factor, C from its last block) | μ = 0.3 / μ = 0 condensation | ContactProblem::new / rebuild_moved | 10-step history / one scaled solve | refactor + solve per iteration / condensed | second assembly avoided |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for (n, nf, s) in savings {
        let cells: Vec<String> = s[..5].iter().map(|(a, b)| format!("{} / {} ms", ms(*a), ms(*b))).collect();
        println!("| {n} | {nf} | {} | {} ms |", cells.join(" | "), ms(s[5].0));
    }
    Ok(())
}

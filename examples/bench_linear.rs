//! Foundation benchmark: one linear plane-elasticity solve on a structured Quad9 cantilever of a
//! requested size, each phase of the pipeline timed on its own.
//!
//! ```text
//!        y = 1 ┌──────────────────────────────────────┐
//!  u1 = u2 = 0 │  nx × ny Quad9 cells, nx = 4 ny      │ ← traction (0, -1) on "right"
//!     ("left") │  E = 1000, ν = 0.3, plane stress     │
//!        y = 0 └──────────────────────────────────────┘
//!            x = 0                                  x = 4
//!
//!   DOFs = 2 (2 nx + 1)(2 ny + 1) ≈ 32 ny²;   ny is chosen so that this is closest to the request.
//!   Timoshenko tip deflection (sanity check): δ = P L³ / (3 E I) + P L / (κ G A) ≈ 0.2685
//! ```
//!
//! Phases: mesh generation, model setup (`add_body`, which checks every Jacobian), assembly
//! (`assemble`: DOF map, rigid-mode check, `K_ff` in place in its node-graph pattern, the
//! constrained blocks from triplets, edge loads), the ordering (with `--ordering nd`),
//! symbolic analysis (ordering, elimination tree, supernodes), numeric factorisation
//! `K_ff = L Lᵀ`, solve. The factorisation goes through faer's low-level API with the defaults
//! that `CholeskySolver` uses (`SymbolicLlt::try_new` + `Llt::try_new_with_symbolic`: AMD, on
//! the twin-compressed pattern from `COMPRESS_FROM` DOFs, supernodal when worthwhile, the library's sequential `parallelism()`), so that the symbolic and numeric times and the
//! size of `L` can be reported separately.
//!
//! Variants, to measure what a change would gain:
//! * `--ordering nd`: the library's nested dissection (`contact2d_fem::fill_reducing_permutation`)
//!   instead of faer's AMD; `--ordering node-amd` AMD on the node graph; `--ordering dof-amd`
//!   faer's AMD on the uncompressed DOF pattern at every size.
//! * `--index u32`: the factorisation with 32-bit instead of 64-bit sparse indices.
//!
//! (The prototypes of the pattern assembly and the nested dissection that docs/benchmarks.md
//! measured first are now the library's own `assemble` and `fill_reducing_permutation`; their
//! copies here were removed.)
//!
//! The peak resident set size after each phase is read from `/proc/self/status` (Linux).
//!
//! Run: `cargo run --release --example bench_linear -- 1000000`; results in docs/benchmarks.md.

use std::time::Instant;

use anyhow::{Result, anyhow, bail};
use clap::{Parser, ValueEnum};
use contact2d_element::{Kinematics, Material};
use contact2d_fem::{
    COMPRESS_FROM, Component, Csc, Dof, DofKind, DofMap, EdgeLoad, Model, Ordering as FemOrdering, assemble,
    fill_reducing_permutation, twin_compressed_amd,
};
use contact2d_mesh::{CellKind, Mesh, generate};
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholeskyRaw, SymmetricOrdering, factorize_symbolic_cholesky};
use faer::sparse::{SparseColMat, SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, Mat, Side};

/// The integer type of the sparse indices handed to the factorisation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum IndexWidth {
    /// `usize`, as `contact2d_fem::Csc`.
    U64,
    /// `u32` (prototype: `K_ff` converted after assembly, the conversion timed on its own).
    U32,
}

/// The fill-reducing ordering of the Cholesky factorisation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Ordering {
    /// The library's default (`CholeskySolver::factor`): faer's approximate minimum degree, from
    /// `contact2d_fem::COMPRESS_FROM` DOFs on the pattern with twin columns merged
    /// (`contact2d_fem::twin_compressed_amd`).
    Amd,
    /// faer's approximate minimum degree on the DOF pattern at every size (the default before
    /// the twin compression).
    DofAmd,
    /// The library's nested dissection (`contact2d_fem::fill_reducing_permutation`).
    Nd,
    /// The library's AMD on the node graph (`contact2d_fem::Ordering::NodeAmd`).
    NodeAmd,
}

/// The cell type of the structured mesh.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Cell {
    /// Bilinear quadrilaterals (DOFs ≈ 8 ny²).
    Q4,
    /// Biquadratic quadrilaterals (DOFs ≈ 32 ny²).
    Q9,
}

#[derive(Debug, Parser)]
#[command(about = "Time each phase of a linear Quad4/Quad9 cantilever solve")]
struct Args {
    /// Requested number of DOFs (the mesh is chosen to be the closest).
    #[arg(default_value_t = 100_000)]
    dofs: usize,
    /// Length-to-height ratio of the rectangle (cells along x = aspect × cells along y).
    #[arg(long, default_value_t = 4)]
    aspect: usize,
    /// Cell type.
    #[arg(long, value_enum, default_value_t = Cell::Q9)]
    cell: Cell,
    /// Fill-reducing ordering.
    #[arg(long, value_enum, default_value_t = Ordering::Amd)]
    ordering: Ordering,
    /// Index width of the factorisation.
    #[arg(long, value_enum, default_value_t = IndexWidth::U64)]
    index: IndexWidth,
}

/// Wall-clock time, CPU time and peak RSS after each phase.
struct Phases {
    start: Instant,
    cpu: f64,
    rows: Vec<(&'static str, f64, f64, Option<f64>)>,
}

impl Phases {
    fn new() -> Phases {
        Phases { start: Instant::now(), cpu: cpu_seconds().unwrap_or(0.0), rows: vec![] }
    }

    /// Records the time since the previous call under `name`.
    fn lap(&mut self, name: &'static str) {
        let now = Instant::now();
        let cpu = cpu_seconds().unwrap_or(0.0);
        self.rows.push((name, (now - self.start).as_secs_f64(), cpu - self.cpu, peak_rss_mib()));
        self.start = now;
        self.cpu = cpu;
    }
}

/// CPU time of all threads of this process so far (Linux `/proc/self/task/*/schedstat`; it
/// advances in scheduler ticks, a few ms), if readable. On a shared machine it is what the
/// phases would take on otherwise idle cores (summed over the threads).
fn cpu_seconds() -> Option<f64> {
    let mut total = 0u64;
    for task in std::fs::read_dir("/proc/self/task").ok()? {
        let stat = std::fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        total += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(total as f64 * 1e-9)
}

/// `VmHWM` of this process in MiB, if `/proc/self/status` can be read.
fn peak_rss_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn main() -> Result<()> {
    let args = Args::parse();
    let (kind, per_cell) = match args.cell {
        Cell::Q4 => (CellKind::Quad4, 8.0),
        Cell::Q9 => (CellKind::Quad9, 32.0),
    };
    let aspect = args.aspect.max(1);
    let ny = ((args.dofs as f64 / (per_cell / 4.0 * aspect as f64)).sqrt().round() as usize).max(1);
    let mut phases = Phases::new();

    let mesh = generate::rectangle(kind, [0.0, aspect as f64], [0.0, 1.0], aspect * ny, ny);
    phases.lap("mesh generation");

    let model = setup_model(mesh)?;
    phases.lap("model setup (add_body)");
    let system = assemble(&model)?;
    let rhs = system.rhs(system.dofs.prescribed_values());
    let (k, dofs) = (system.stiffness, system.dofs);
    phases.lap("assembly");

    let forward = match args.ordering {
        Ordering::DofAmd => None,
        Ordering::Amd if k.nrows() < COMPRESS_FROM => None,
        Ordering::Amd => Some(twin_compressed_amd(&k)?),
        Ordering::Nd | Ordering::NodeAmd => {
            let library =
                if args.ordering == Ordering::Nd { FemOrdering::NestedDissection } else { FemOrdering::NodeAmd };
            Some(fill_reducing_permutation(&model, &dofs, &k, library, &[])?)
        }
    };
    let perm = forward.map(|forward| {
        let mut inverse = vec![0; forward.len()];
        for (new, &old) in forward.iter().enumerate() {
            inverse[old] = new;
        }
        (forward, inverse)
    });
    if perm.is_some() {
        phases.lap("ordering");
    }
    let (u, stats) = match args.index {
        IndexWidth::U64 => factor_and_solve(k.as_ref(), perm, &rhs, &mut phases)?,
        IndexWidth::U32 => {
            let k32 = to_u32(&k)?;
            let perm32 = perm.map(|(f, i)| (to_u32_vec(&f), to_u32_vec(&i)));
            phases.lap("convert indices to u32");
            factor_and_solve(k32.as_ref(), perm32, &rhs, &mut phases)?
        }
    };
    report(&args, &model, &k, &dofs, &stats, &u, &rhs, &phases);
    Ok(())
}

/// Size and cost of a Cholesky factor.
struct FactorStats {
    /// "supernodal, N supernodes" or "simplicial".
    kind: String,
    /// Structural nonzeros of `L` (lower triangle, diagonal included).
    nnz_l: u128,
    /// Values faer stores (dense diagonal blocks of supernodes included).
    stored: usize,
    /// `Σ_j c_j²` over the columns of `L` with `c_j` entries (supernodal only).
    flops: Option<f64>,
}

/// Symbolic analysis (AMD, or the given `(forward, inverse)` permutation), numeric
/// factorisation and solve, as `CholeskySolver` does them; one phase each.
fn factor_and_solve<I: faer::Index>(
    k: SparseColMatRef<'_, I, f64>,
    perm: Option<(Vec<I>, Vec<I>)>,
    rhs: &[f64],
    phases: &mut Phases,
) -> Result<(Vec<f64>, FactorStats)> {
    let ordering = match &perm {
        None => SymmetricOrdering::Amd,
        Some((fwd, inv)) => SymmetricOrdering::Custom(PermRef::new_checked(fwd, inv, fwd.len())),
    };
    let symbolic = factorize_symbolic_cholesky(k.symbolic(), Side::Lower, ordering, Default::default())
        .map_err(|e| anyhow!("symbolic analysis: {e:?}"))?;
    phases.lap("symbolic analysis");

    // The library's fixed parallelism (`CholeskySolver` runs faer sequentially, for bit-identical
    // answers whatever the thread count; on this 2-vCPU machine it is also the faster: numeric
    // factorisation 2.5 s against 3.2–4.1 s with faer's two-thread kernels at 10⁶ DOFs).
    let par = contact2d::fem::parallelism();
    let mut l_values = vec![0.0; symbolic.len_val()];
    let mut scratch = MemBuffer::try_new(symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()))
        .map_err(|e| anyhow!("factorisation workspace: {e:?}"))?;
    symbolic
        .factorize_numeric_llt(
            &mut l_values,
            k,
            Side::Lower,
            Default::default(),
            par,
            MemStack::new(&mut scratch),
            Default::default(),
        )
        .map_err(|e| anyhow!("numeric factorisation: {e:?}"))?;
    drop(scratch);
    phases.lap("numeric factorisation");

    let mut x = Mat::from_fn(rhs.len(), 1, |i, _| rhs[i]);
    let mut scratch = MemBuffer::try_new(symbolic.solve_in_place_scratch::<f64>(1, par))
        .map_err(|e| anyhow!("solve workspace: {e:?}"))?;
    LltRef::new(&symbolic, &l_values).solve_in_place_with_conj(Conj::No, x.as_mut(), par, MemStack::new(&mut scratch));
    phases.lap("solve");

    let stats = match symbolic.raw() {
        SymbolicCholeskyRaw::Supernodal(s) => {
            // Per supernode: a dense lower-trapezoidal block of `cols` columns and `cols + below` rows.
            let (mut nnz_l, mut flops) = (0u128, 0f64);
            for sn in 0..s.n_supernodes() {
                let cols = (s.supernode_end()[sn].zx() - s.supernode_begin()[sn].zx()) as u128;
                let below = s.nnz_per_super()[sn].zx() as u128;
                nnz_l += cols * (cols + 1) / 2 + cols * below;
                // A column with c entries costs about c² flops in L Lᵀ.
                flops += (1..=cols).map(|c| ((c + below) * (c + below)) as f64).sum::<f64>();
            }
            let kind = format!("supernodal, {} supernodes", s.n_supernodes());
            FactorStats { kind, nnz_l, stored: symbolic.len_val(), flops: Some(flops) }
        }
        SymbolicCholeskyRaw::Simplicial(s) => {
            FactorStats { kind: "simplicial".into(), nnz_l: s.len_val() as u128, stored: s.len_val(), flops: None }
        }
    };
    Ok(((0..x.nrows()).map(|i| x[(i, 0)]).collect(), stats))
}

/// `k` with 32-bit indices.
fn to_u32(k: &Csc) -> Result<SparseColMat<u32, f64>> {
    let (symbolic, values) = k.as_ref().parts();
    let pattern = SymbolicSparseColMat::new_checked(
        k.nrows(),
        k.ncols(),
        to_u32_vec(symbolic.col_ptr()),
        None,
        to_u32_vec(symbolic.row_idx()),
    );
    if k.compute_nnz() >= u32::MAX as usize / 2 {
        bail!("too many nonzeros for u32 indices");
    }
    Ok(SparseColMat::new(pattern, values.to_vec()))
}

fn to_u32_vec(v: &[usize]) -> Vec<u32> {
    v.iter().map(|&i| i as u32).collect()
}

/// Clamps the left side and pulls the right side down with a unit traction.
fn setup_model(mesh: Mesh) -> Result<Model> {
    let mut model = Model::new(mesh);
    model.add_body("domain", Material::new(1000.0, 0.3)?, Kinematics::PlaneStress { thickness: 1.0 })?;
    model.fix("left", Component::X, 0.0)?;
    model.fix("left", Component::Y, 0.0)?;
    model.add_edge_load(EdgeLoad::Traction { group: "right".into(), traction: [0.0, -1.0] })?;
    Ok(model)
}

#[allow(clippy::too_many_arguments)]
fn report(
    args: &Args,
    model: &Model,
    k: &Csc,
    dofs: &DofMap,
    stats: &FactorStats,
    u: &[f64],
    rhs: &[f64],
    phases: &Phases,
) {
    let nnz_lower = k.compute_nnz();
    println!("requested DOFs       {}", args.dofs);
    println!("order/index {:?}, {:?}", args.ordering, args.index);
    println!("rayon threads        {}", rayon::current_num_threads());
    println!("nodes                {}", model.mesh.num_nodes());
    println!("elements ({:?})       {}", args.cell, model.bodies.iter().map(|b| b.num_cells()).sum::<usize>());
    println!("DOFs (all / free)    {} / {}", dofs.num_global(), dofs.num_free());
    println!("nnz(K_ff) lower/full {nnz_lower} / {}", 2 * nnz_lower - k.ncols());
    println!("factor               {}", stats.kind);
    println!("nnz(L)               {} ({} values stored)", stats.nnz_l, stats.stored);
    if let Some(flops) = stats.flops {
        println!("factor flops         {flops:.3e}");
    }
    // Correctness: residual of the solve and the tip deflection at (4, 0.5).
    let ku = apply_lower(k, u);
    let res = ku.iter().zip(rhs).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
    let norm = rhs.iter().map(|b| b * b).sum::<f64>().sqrt();
    let mx = model.mesh.points.iter().take_while(|p| p[1] == 0.0).count();
    let tip_node = (model.mesh.num_nodes() / mx / 2) * mx + mx - 1;
    let tip = match dofs.kind(Dof::of(tip_node, Component::Y)) {
        DofKind::Free(i) => u[i],
        _ => f64::NAN,
    };
    println!("‖K u - f‖ / ‖f‖      {:.2e}", res / norm);
    println!("tip deflection       {tip:.6} at {:?} (Timoshenko ≈ -0.2685)", model.mesh.points[tip_node]);
    println!();
    let (mut total, mut total_cpu) = (0.0, 0.0);
    for (name, secs, cpu, rss) in &phases.rows {
        total += secs;
        total_cpu += cpu;
        let rss = rss.map_or_else(|| "?".to_string(), |r| format!("{r:.0}"));
        println!("{name:<28} {secs:>9.3} s  (CPU {cpu:>7.3} s)   peak RSS so far {rss:>6} MiB");
    }
    println!("{:<28} {total:>9.3} s  (CPU {total_cpu:>7.3} s)", "total");
}

/// `y = K x` from the stored lower triangle.
fn apply_lower(k: &Csc, x: &[f64]) -> Vec<f64> {
    let k = k.as_ref();
    let mut y = vec![0.0; x.len()];
    for j in 0..k.ncols() {
        for (i, v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
            y[i] += v * x[j];
            if i != j {
                y[j] += v * x[i];
            }
        }
    }
    y
}

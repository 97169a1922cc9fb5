//! The `contact2d` command-line tool.

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod text_summary;
use text_summary::print_summary;

/// 2D finite-element contact mechanics with Coulomb friction.
#[derive(Debug, Parser)]
#[command(name = "contact2d", version, about, long_about = None, after_help = TOP_EXAMPLES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

const TOP_EXAMPLES: &str = "\
Examples:
  contact2d run scenes/generic/pin_lug.toml
  contact2d run scenes/plate_insert_nogap_mu0.toml
  contact2d mesh meshes/plate_insert/plate_insert_eps0_N32.msh

Errors print one line naming the file and the key, line or byte at fault, and exit with status 1
(2 for a malformed command line). Guide: docs/user-guide.md; walk-through: docs/tutorial.md.";

const MESH_EXAMPLES: &str = "\
Examples:
  contact2d mesh meshes/plate_insert/plate_insert_eps0_N32.msh
  contact2d mesh meshes/plate_insert/plate_insert_eps0_N32.msh --json
  contact2d mesh meshes/fixtures/plate_hole_v22_bin.msh";

const RUN_EXAMPLES: &str = "\
Examples:
  contact2d run scenes/plate_insert_nogap_mu0.toml
  contact2d run scenes/plate_insert_nogap_mu03.toml --set plate_insert.friction=0.6
  contact2d run scenes/plate_insert_gap_v2_mu0.toml --set solver.algorithm=clarabel --json
  contact2d run scenes/plate_insert_nogap_mu0.toml --set plate_insert.stiffness_ratio=0.5 --out out/soft
  contact2d run scenes/plate_insert_nogap_mu03.toml --set plate_insert.rigid_insert=true
  contact2d run scenes/plate_insert_nogap_mu03.toml --set solver.algorithm=boussinesq -v
  contact2d run scenes/plate_insert_history_v1.toml --out out/history
  contact2d run scenes/generic/pin_lug.toml --about 0,-30 --json

--set takes a dotted key and a TOML value (a bare word is read as a string); it may set a key the
file leaves at its default. --unset KEY removes a key the file gives (applied before every --set),
e.g. `--unset loading.steps --set 'loading.schedule=[[1.0, 0.0], [1.0, 0.5]]'`, or a whole entry
(`--unset contact.1`). The scene keys are listed in docs/user-guide.md.";

#[derive(Debug, Subcommand)]
enum Command {
    /// Summarise a Gmsh .msh file: nodes, elements by type, physical groups, bounding box, quality.
    #[command(after_help = MESH_EXAMPLES)]
    Mesh {
        /// The .msh file (MSH 2.2 or 4.1, ASCII or binary).
        file: std::path::PathBuf,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Run a scene (TOML): any geometry, or the paper's plate with an insert (its preset adds l, b, P, ... under `paper`).
    #[command(after_help = RUN_EXAMPLES)]
    Run {
        /// The scene file.
        scene: std::path::PathBuf,
        /// Override a scene value by its dotted path, e.g. `plate_insert.load=0.5` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Remove a key the scene file gives, by its dotted path, e.g. `loading.steps` (so that
        /// `--set loading.schedule=...` gives the schedule instead) or a whole entry such as
        /// `contact.1` (repeatable; applied before every --set).
        #[arg(long = "unset", value_name = "KEY")]
        unset: Vec<String>,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
        /// Write the outputs into this directory: summary.json, figures (PNG, SVG), CSV profiles,
        /// VTU files per step with a .pvd collection, README.txt.
        #[arg(long, value_name = "DIR")]
        out: Option<std::path::PathBuf>,
        /// No progress bar (it is hidden anyway when stdout is not a terminal).
        #[arg(long, short)]
        quiet: bool,
        /// Log the algorithm's iterations of every step: state changes, pairs in contact and
        /// slipping, residuals.
        #[arg(long, short)]
        verbose: bool,
        /// Which steps carry the interfaces' profiles (pressure, shear, gap, slip, state along
        /// the master curve) in the JSON summary: `last` (default) or `all`; with `all`, `--out`
        /// also writes one CSV per interface and step (contact_<name>_step_<k>.csv).
        #[arg(long, value_name = "last|all", default_value = "last", value_parser = ["last", "all"])]
        profiles: String,
        /// The centre `x,y` the moments (reaction_moments, reaction_moment_total, each
        /// contact's moment) are taken about; the JSON's `moment_centre` (default the origin).
        #[arg(long, value_name = "X,Y", value_parser = parse_centre, allow_hyphen_values = true)]
        about: Option<[f64; 2]>,
    },
    /// Run a scene over the Cartesian product of varied values, in parallel; write sweep.csv,
    /// sweep.md and plots of the chosen outputs against the first varied key.
    ///
    /// A failed combination is a row with its error (exit status 1 when every row fails); rows
    /// are appended to sweep.csv.partial as they finish, so an interrupted sweep keeps them. The
    /// plots draw one line per combination of the other varied keys, with a log x axis when the
    /// values span more than two decades. At most 10 000 combinations.
    ///
    /// Examples:
    ///   contact2d sweep scenes/plate_insert_nogap_mu0.toml --vary plate_insert.friction=0,0.1,0.2,0.3
    ///   contact2d sweep scenes/plate_insert_nogap_mu03.toml --vary plate_insert.stiffness_ratio=0.01,0.1,1,10,100 --vary plate_insert.friction=0,0.3 --plot l,b,P,K --out out/stiffness
    ///   contact2d sweep scenes/generic/pin_lug.toml --vary contact.bore.friction=0,0.1,0.2,0.4 --plot contacts.bore.contact_length,contacts.bore.max_pressure
    ///   contact2d sweep scenes/plate_insert_gap_v1_mu03.toml --vary plate_insert.steps=1,2,3,5,10,20 --set plate_insert.mesh='"../meshes/plate_insert/plate_insert_eps0.05_N32.msh"' --quiet
    #[command(verbatim_doc_comment)]
    Sweep {
        /// The scene file.
        scene: std::path::PathBuf,
        /// A varied key and its values, e.g. `plate_insert.friction=0,0.1,0.3` (repeatable, each
        /// key once; the first one is the plots' x axis). Values are split at the commas outside
        /// brackets: `plate_insert.l_steps=[0.1,0.2],[0.3]` is two values.
        #[arg(long = "vary", value_name = "KEY=V1,V2,...", required = true)]
        vary: Vec<String>,
        /// Override a scene value for every run, as in `run` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Remove a key the scene file gives, for every run, as in `run` (repeatable; applied
        /// before every --set and --vary).
        #[arg(long = "unset", value_name = "KEY")]
        unset: Vec<String>,
        /// The outputs to plot, comma-separated: any number of the run's JSON summary by its
        /// dotted path (the flagship's scenes: l, b, P, Phi_E1, Phi_E2, Phi_f, W, sigma_star, K,
        /// insert_hoop_max; generic scenes e.g. contacts.hertz.max_pressure,
        /// reactions.block_bottom.1). Default: l, b, P for the flagship's scenes, each
        /// interface's normal force and contact length for generic ones.
        #[arg(long, value_name = "NAMES", default_value = DEFAULT_PLOT)]
        plot: String,
        /// The output directory (default: out/sweep_<scene file name>).
        #[arg(long, value_name = "DIR")]
        out: Option<std::path::PathBuf>,
        /// No progress bar and no table on stdout (the list of files written only).
        #[arg(long)]
        quiet: bool,
        /// Run only shard I (from 0) of --shards N: the I-th of N disjoint, contiguous slices of
        /// the combinations in their order, so that N jobs (a Slurm job array) share a sweep;
        /// the shards' sweep.csv rows in shard order are the unsharded rows (docs/python.md).
        #[arg(long, value_name = "I", default_value_t = 0, requires = "shards")]
        shard: usize,
        /// The number of shards (default 1: the whole sweep).
        #[arg(long, value_name = "N", default_value_t = 1)]
        shards: usize,
    },
    /// Wall time against discretisation error: flagship cases × mesh levels × algorithms.
    ///
    /// Examples:
    ///   contact2d bench --levels 16,32,64 --repeats 3 --out bench-out
    ///   contact2d bench --cases U3 --algorithms active_set,clarabel --max-seconds 10
    #[command(verbatim_doc_comment)]
    Bench(contact2d::bench::BenchArgs),
    /// Numerical stress tests: extreme stiffness ratios, friction, clearances, ν, distorted meshes.
    ///
    /// Examples:
    ///   contact2d stress --out stress-out
    ///   contact2d stress --ratios 1e-4,1e6 --frictions 0,1.5 --eps 0 --no-extra
    #[command(verbatim_doc_comment)]
    Stress(contact2d::stress::StressArgs),
    /// Every algorithm × pairing on one scene (generic, or the paper's case) over mesh levels:
    /// time, iterations, KKT residuals and the error of the key outputs; writes compare.csv,
    /// compare.md and work-precision figures.
    ///
    /// Examples:
    ///   contact2d compare scenes/plate_insert_nogap_mu03.toml --repeat 1
    ///   contact2d compare scenes/generic/cylinder_on_block.toml --mesh meshes/generic/cylinder_on_block_L1.msh --mesh meshes/generic/cylinder_on_block_L2.msh --reference contacts.hertz.max_pressure=3585 --reference contacts.hertz.contact_length=6.21
    ///   contact2d compare scenes/generic/two_blocks_press_slide.toml --repeat 1 --out compare-out
    ///   contact2d compare scenes/generic/pin_lug.toml --repeat 1 --time-limit 30
    ///
    /// Each combination prints a progress line on stderr. A combination still running after
    /// --time-limit seconds (default 120, all its repeats together; checked between load steps)
    /// stops and is listed with status timed_out.
    #[command(verbatim_doc_comment)]
    Compare(contact2d::compare::CompareArgs),
    /// The verification gallery: closed-form and published cases, measured against their
    /// references, PASS/FAIL per quantity (exit status 3 when a check fails).
    ///
    /// Examples:
    ///   contact2d verify
    ///   contact2d verify --level full --out verify-out
    ///   contact2d verify --cases hertz,incline --markdown
    #[command(verbatim_doc_comment)]
    Verify(contact2d::verify::VerifyArgs),
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Command::Mesh { file, json } => {
            // A device or FIFO would never end or block: refused before reading.
            contact2d::input_file::check_input_file(&file, contact2d::input_file::MAX_MESH_BYTES).map_err(
                |e| match e {
                    contact2d::input_file::InputFileError::Io { .. } => anyhow::anyhow!("cannot read {e}"),
                    other => anyhow::anyhow!(other),
                },
            )?;
            // An I/O error names the path already; a format error gets it prefixed.
            let mesh = contact2d::mesh::read_msh(&file).map_err(|e| match e {
                contact2d::mesh::MeshError::Io { .. } => anyhow::anyhow!(e),
                _ => anyhow::anyhow!("{}: {e}", file.display()),
            })?;
            let summary = contact2d::mesh_summary::summarize_mesh(&mesh);
            let mut stdout = std::io::stdout().lock();
            if json {
                writeln!(stdout, "{}", serde_json::to_string_pretty(&summary)?)?;
            } else {
                writeln!(stdout, "{}\n{summary}", file.display())?;
            }
        }
        Command::Run { scene, set, unset, json, out, quiet, verbose, profiles, about } => {
            let options = RunOptions { quiet, verbose, every_profile: profiles == "all", about };
            run_scene(&scene, &overrides(&unset, &set), json, out.as_deref(), options)?;
        }
        Command::Sweep { scene, vary, set, unset, plot, out, quiet, shard, shards } => {
            let shard = contact2d::sweep::Shard::new(shard, shards)?;
            sweep(&scene, &vary, &overrides(&unset, &set), &plot, (out, shard), quiet)?;
        }
        Command::Bench(args) => writeln!(std::io::stdout().lock(), "{}", contact2d::bench::run_command(&args)?)?,
        Command::Verify(args) => {
            let (table, passed) = contact2d::verify::run_command(&args)?;
            write!(std::io::stdout().lock(), "{table}")?;
            if !passed {
                return Err(VerificationFailed.into());
            }
        }
        Command::Stress(args) => writeln!(std::io::stdout().lock(), "{}", contact2d::stress::run_command(&args)?)?,
        Command::Compare(args) => {
            // One progress line per combination on stderr: a long table shows where it is.
            let mut progress = |done: usize, total: usize, row: &contact2d::compare::CompareRow| {
                let time = if row.time.is_finite() { format!(", {:.2} s", row.time) } else { String::new() };
                eprintln!(
                    "compare {done}/{total}: {} × {} on {}: {}{time}",
                    row.algorithm, row.pairing, row.mesh, row.status
                );
            };
            writeln!(std::io::stdout().lock(), "{}", contact2d::compare::run_command(&args, &mut progress)?)?;
        }
    }
    Ok(())
}

/// The override entries of `--unset` (first) and `--set`, in the order the scene applies them.
fn overrides(unset: &[String], set: &[String]) -> Vec<String> {
    unset.iter().map(|key| contact2d::scene::unset_override(key)).chain(set.iter().cloned()).collect()
}

/// `--about x,y`: two finite numbers separated by a comma.
fn parse_centre(text: &str) -> Result<[f64; 2], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let number = |p: &str| p.parse::<f64>().ok().filter(|v| v.is_finite());
    match parts.as_slice() {
        [x, y] => match (number(x), number(y)) {
            (Some(x), Some(y)) => Ok([x, y]),
            _ => Err(format!("expected two finite numbers X,Y, not {text:?}")),
        },
        _ => Err(format!("expected X,Y (two numbers separated by a comma), not {text:?}")),
    }
}

/// How `run` runs and reports, besides the scene and its outputs.
struct RunOptions {
    quiet: bool,
    verbose: bool,
    every_profile: bool,
    about: Option<[f64; 2]>,
}

/// `run`: solve any scene, print the summary (text or JSON), write the outputs.
fn run_scene(
    path: &std::path::Path,
    set: &[String],
    json: bool,
    out: Option<&std::path::Path>,
    RunOptions { quiet, verbose, every_profile, about }: RunOptions,
) -> anyhow::Result<()> {
    let mut scene = contact2d::scene::Scene::load(path, set)?;
    scene.set_every_profile(every_profile);
    if let Some(centre) = about {
        scene.set_moment_centre(centre);
    }
    scene.check_mesh_file()?;
    // The output folder is checked and locked before the work, so that a bad --out fails at
    // once and no other run writes there meanwhile.
    let mut folder =
        out.map(|dir| contact2d::output::OutputDir::prepare(dir, Some(contact2d::output::SUMMARY_FILE))).transpose()?;
    let mut bar = StepBar::new(quiet || json);
    // Each step of a generic scene goes to the outputs as it is solved (its VTU file, its line
    // with --verbose) and only the last step's solution is kept: memory stays flat in the number
    // of steps.
    let (mut lines, mut write_error) = (vec![], None);
    let outcome = scene.solve_streaming(&mut bar, &mut |built, i, step| {
        if let Some(folder) = folder.as_mut().filter(|_| write_error.is_none())
            && let Err(e) = contact2d::generic::outputs::write_step_vtu(folder, built, i, &step.solution)
        {
            write_error = Some(e);
        }
        if verbose {
            lines.push(iteration_log(&format!("step {}: factors {:?}", i + 1, step.factors), &step.solution));
        }
    })?;
    bar.finish();
    if let Some(e) = write_error {
        return Err(e.into());
    }
    if verbose && let contact2d::scene::Outcome::Preset(run) = &outcome {
        lines = run.iteration_logs().into_iter().map(|(step, s)| iteration_log(&step, s)).collect();
    }
    if !lines.is_empty() {
        print_stderr(lines.join("\n").trim_end());
    }
    let report = outcome.report();
    let mut stdout = std::io::stdout().lock();
    if json {
        // Written as it is serialised: no whole copy of the summary, which grows with the steps.
        serde_json::to_writer_pretty(&mut stdout, report).map_err(std::io::Error::from)?;
        writeln!(stdout)?;
    } else {
        print_summary(&mut stdout, report, &outcome.preset_lines())?;
    }
    if let Some(folder) = folder {
        let written = outcome.finish_streamed_outputs(folder)?;
        let lines: Vec<String> = written.iter().map(|p| format!("  {}", p.display())).collect();
        let text = format!("wrote {} files:\n{}", written.len(), lines.join("\n"));
        // With --json, stdout stays one JSON object; the file list goes to stderr.
        if json {
            print_stderr(&text);
        } else {
            writeln!(stdout, "{text}")?;
        }
    }
    Ok(())
}

fn sweep(
    scene: &std::path::Path,
    vary: &[String],
    set: &[String],
    plot: &str,
    (out, shard): (Option<std::path::PathBuf>, contact2d::sweep::Shard),
    quiet: bool,
) -> anyhow::Result<()> {
    use contact2d::sweep::{Variation, check_variations, csv_header, csv_row, markdown, run_sweep_shard, write_sweep};
    use std::io::IsTerminal;
    let variations = vary.iter().map(|v| Variation::parse(v)).collect::<Result<Vec<_>, _>>()?;
    // Unknown or repeated keys and oversized grids fail before any run, and so does a scene that
    // does not load at all (each combination is checked in its run).
    let runs = shard.range(check_variations(scene, &variations, set)?).len();
    let base = contact2d::scene::Scene::load(scene, set)?;
    let plots: Vec<String> = if plot == DEFAULT_PLOT {
        base.sweep_plots()
    } else {
        plot.split(',').map(|p| p.trim().to_string()).filter(|p| !p.is_empty()).collect()
    };
    let mut columns = base.sweep_columns();
    columns.extend(plots.iter().filter(|p| !columns.contains(p)).cloned().collect::<Vec<_>>());
    let stem = scene.file_stem().map_or("scene".into(), |s| s.to_string_lossy().into_owned());
    let suffix = if shard.count() > 1 { format!("_shard{}of{}", shard.index(), shard.count()) } else { String::new() };
    let dir = out.unwrap_or_else(|| std::path::PathBuf::from("out").join(format!("sweep_{stem}{suffix}")));
    let mut folder = contact2d::output::OutputDir::prepare(&dir, None)?;
    // Rows go to sweep.csv.partial as they finish (flushed), so an interrupted sweep keeps them.
    let mut partial = folder.stream("sweep.csv")?;
    partial.append(&csv_header(&variations, &columns))?;
    let partial = std::sync::Mutex::new(partial);
    let bar = if quiet || !std::io::stdout().is_terminal() {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(runs as u64)
    };
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} runs, {elapsed} elapsed, ETA {eta}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let append_error = std::sync::Mutex::new(None);
    let rows = run_sweep_shard(scene, &variations, set, shard, |row| {
        if let Ok(mut file) = partial.lock()
            && let Err(e) = file.append(&csv_row(row, &columns))
            && let Ok(mut slot) = append_error.lock()
        {
            slot.get_or_insert(e);
        }
        bar.inc(1);
    });
    bar.finish_and_clear();
    if let Some(e) = append_error.into_inner().ok().flatten() {
        return Err(e.into());
    }
    // The final sweep.csv lists the rows in combination order; writing it removes the partial.
    drop(partial);
    let written = write_sweep(folder, base.name(), &variations, &rows, &columns, &plots)?;
    let mut stdout = std::io::stdout().lock();
    if !quiet {
        write!(stdout, "{}", markdown(&variations, &rows, &columns))?;
    }
    let failed: Vec<&String> = rows.iter().filter_map(|r| r.result.as_ref().err()).collect();
    writeln!(stdout, "{} runs ({} failed); wrote {} files:", rows.len(), failed.len(), written.len())?;
    for p in &written {
        writeln!(stdout, "  {}", p.display())?;
    }
    if !rows.is_empty() && failed.len() == rows.len() {
        anyhow::bail!("every one of the {} runs failed; the first: {}", rows.len(), failed[0]);
    }
    Ok(())
}

/// The `--plot` default of `sweep`.
const DEFAULT_PLOT: &str = "l,b,P";

/// One step's iteration log: its status and, per iteration of the algorithm, the pairs that
/// changed state, in contact and slipping, and the residual.
fn iteration_log(step: &str, s: &contact2d::contact::ContactSolution) -> String {
    use std::fmt::Write as _;
    let mut text = format!("{step}, {:?} after {} iterations\n", s.status, s.iterations);
    text.push_str("  iter  changed  contact  slipping  residual");
    for r in &s.trace {
        let _ = write!(
            text,
            "\n  {:>4}  {:>7}  {:>7}  {:>8}  {:>9.2e}",
            r.iteration, r.changed, r.in_contact, r.slipping, r.residual
        );
    }
    text
}

/// One message on stderr; a closed or full stderr is ignored (there is nowhere left to say it,
/// and the exit status still tells).
fn print_stderr(text: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{text}");
}

/// The error and its causes on one line, each cause once: a cause whose text the message
/// already contains (as "{path}: {source}" contains its source) is not repeated.
fn error_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if !line.contains(&text) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&text);
        }
    }
    line.replace('\n', " ")
}

/// A progress bar over the load steps of a run, drawn only on a terminal.
struct StepBar(Option<indicatif::ProgressBar>);

impl StepBar {
    fn new(quiet: bool) -> StepBar {
        use std::io::IsTerminal;
        if quiet || !std::io::stdout().is_terminal() {
            return StepBar(None);
        }
        let bar = indicatif::ProgressBar::new(0);
        let style = indicatif::ProgressStyle::with_template("{bar:30} step {pos}/{len}  {msg}  eta {eta}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
        bar.set_style(style);
        StepBar(Some(bar))
    }

    fn finish(&self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}

impl contact2d::run::Progress for StepBar {
    fn step_done(&mut self, done: usize, total: usize, w: f64) {
        if let Some(bar) = &self.0 {
            bar.set_length(total as u64);
            bar.set_position(done as u64);
            bar.set_message(format!("w = {w:.4}"));
        }
    }
}

/// `contact2d verify` ran and a check failed (exit status 3).
#[derive(Debug)]
struct VerificationFailed;

impl std::fmt::Display for VerificationFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a verification check failed")
    }
}

impl std::error::Error for VerificationFailed {}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        // A closed pipe (`contact2d run ... | head`) ends the output quietly.
        Err(e) if e.downcast_ref::<std::io::Error>().is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe) => {
            ExitCode::SUCCESS
        }
        // The table is printed; the status says that a check failed.
        Err(e) if e.downcast_ref::<VerificationFailed>().is_some() => ExitCode::from(3),
        Err(e) => {
            print_stderr(&format!("error: {}", error_line(&e)));
            ExitCode::FAILURE
        }
    }
}

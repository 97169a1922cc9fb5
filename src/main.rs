//! The `contact2d` command-line tool.

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// 2D finite-element contact mechanics with Coulomb friction.
#[derive(Debug, Parser)]
#[command(name = "contact2d", version, about, long_about = None, after_help = TOP_EXAMPLES)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

const TOP_EXAMPLES: &str = "\
Examples:
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

--set takes a dotted key and a TOML value (a bare word is read as a string); it may set a key the
file leaves at its default. The scene keys are listed in docs/user-guide.md.";

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
    /// Run a scene (TOML) and report the paper's quantities.
    #[command(after_help = RUN_EXAMPLES)]
    Run {
        /// The scene file.
        scene: std::path::PathBuf,
        /// Override a scene value by its dotted path, e.g. `plate_insert.load=0.5` (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
        /// Write `summary.json` into this directory.
        #[arg(long, value_name = "DIR")]
        out: Option<std::path::PathBuf>,
    },
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Command::Mesh { file, json } => {
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
        Command::Run { scene, set, json, out } => {
            let scene = contact2d::scene::Scene::load(&scene, &set)?;
            // A mesh that cannot be read is reported by the run below, with the scene.
            if let Ok(mesh) = contact2d::mesh::read_msh(scene.mesh_path()) {
                scene.check_mesh_geometry(&mesh)?;
            }
            // Set-up failures past the scene checks concern the mesh: name both files.
            let report = contact2d::run::run_scene(&scene).map_err(|e| {
                anyhow::anyhow!("scene {}, mesh {}: {e}", scene.file.display(), scene.mesh_path().display())
            })?;
            let text = serde_json::to_string_pretty(&report)?;
            if let Some(dir) = out {
                std::fs::create_dir_all(&dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
                let path = dir.join("summary.json");
                std::fs::write(&path, &text).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
            }
            let mut stdout = std::io::stdout().lock();
            if json {
                writeln!(stdout, "{text}")?;
            } else {
                print_report(&mut stdout, &report)?;
            }
        }
    }
    Ok(())
}

fn print_report(out: &mut impl Write, r: &contact2d::run::RunReport) -> std::io::Result<()> {
    let opt = |v: Option<f64>| v.map_or("-".to_string(), |x| format!("{x:.4}"));
    writeln!(
        out,
        "scene {}  ({} DOFs, {} pairs, {:?}, {} after {} iterations in {} step(s))",
        r.scene,
        r.dofs,
        r.pairs,
        r.algorithm,
        r.status,
        r.iterations,
        r.steps.len()
    )?;
    writeln!(out, "  w      = {}   mu = {}", r.w, r.mu)?;
    writeln!(out, "  l      = {}   (bracket {:?}, master's own {})", opt(r.l), r.l_bracket, opt(r.l_master))?;
    writeln!(out, "  b      = {}   (bracket {:?})", opt(r.b), r.b_bracket)?;
    writeln!(out, "  P      = {:.5}   W = {:.6}", r.P, r.W)?;
    writeln!(out, "  Phi_E1 = {:.6}   Phi_E2 = {:.6}   Phi_f = {:.6}", r.Phi_E1, r.Phi_E2, r.Phi_f)?;
    writeln!(out, "  sigma* = {:.4}   K = {:.3}", r.sigma_star, r.K)?;
    writeln!(
        out,
        "  KKT: penetration {:.1e}, complementarity {:.1e}, cone {:.1e}, min dissipation {:.1e}",
        r.kkt.max_penetration, r.kkt.max_complementarity, r.kkt.max_cone_violation, r.kkt.min_dissipation
    )?;
    writeln!(out, "  time {:.3} s (contact solve {:.4} s)", r.time_s, r.solve_time_s)?;
    Ok(())
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        // A closed pipe (`contact2d run ... | head`) ends the output quietly.
        Err(e) if e.downcast_ref::<std::io::Error>().is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe) => {
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

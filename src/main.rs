//! The `contact2d` command-line tool.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// 2D finite-element contact mechanics with Coulomb friction.
#[derive(Debug, Parser)]
#[command(name = "contact2d", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Summarise a Gmsh .msh file: nodes, elements by type, physical groups, bounding box, quality.
    ///
    /// Examples:
    ///   contact2d mesh meshes/plate_insert/plate_insert_eps0_N32.msh
    ///   contact2d mesh meshes/plate_insert/plate_insert_eps0_N32.msh --json
    Mesh {
        /// The .msh file (MSH 2.2 or 4.1, ASCII or binary).
        file: std::path::PathBuf,
        /// Print one JSON object instead of text.
        #[arg(long)]
        json: bool,
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
            if json {
                println!("{}", serde_json::to_string_pretty(&summary)?);
            } else {
                println!("{}\n{summary}", file.display());
            }
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

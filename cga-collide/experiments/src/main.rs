//! `cga-experiment`: the papers' experiments from the command line (research, not the product's
//! `cga`): the double-sphere paper's Tables 2 and 3, and the sphere-tree paper's collision
//! method against the simultaneous descent. See `cga-experiment --help`.

mod double_spheres;
// The `cga` binary's output-file checks (`--csv`, `--plot` fail before the run, not after it),
// compiled from the same source; this binary uses only part of it.
#[allow(dead_code)]
#[path = "../../cli/src/output.rs"]
mod output;
mod spheretree_collide;
// Reading a file of two sphere trees, shared with `cga spheretree collide`.
#[path = "../../cli/src/tree_file.rs"]
mod tree_file;

use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand};

/// The papers' experiments on cga-collide.
#[derive(Parser, Debug)]
#[command(name = "cga-experiment", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The double outer/inner sphere hierarchy on the paper's polyhedra pairs (Tables 2, 3),
    /// every answer checked against the exact reference.
    DoubleSpheres(double_spheres::DoubleSpheresArgs),
    /// The sphere-tree paper's collision method (as published, and fixed) against the
    /// simultaneous descent, on the first two trees of a file in the paper's format.
    SpheretreeCollide(spheretree_collide::CollideArgs),
}

fn run(command: Command) -> Result<()> {
    match command {
        Command::DoubleSpheres(args) => double_spheres::run(args),
        Command::SpheretreeCollide(args) => spheretree_collide::run(args),
    }
}

fn main() -> ExitCode {
    match run(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

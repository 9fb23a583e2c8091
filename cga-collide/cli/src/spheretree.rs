//! `cga spheretree`: octree sphere trees (Fuentes Socorro's method) in the paper's text format.
//!
//! * `cga spheretree build MESH [MESH...] --depth D -o FILE`: one tree per mesh, written in
//!   the paper's format; `--rotate/--translate` move every mesh after the first (as `cga
//!   collide` moves B), so `cga spheretree build bunny armadillo --unit --translate 0.3,0.05,0
//!   --depth 5 -o pair.txt` makes a file `collide` can read.
//! * `cga spheretree collide FILE`: whether the first two trees of the file collide (the
//!   simultaneous descent of `SphereTree::collides`). The paper's own collision method, as
//!   published and fixed, is research: the experiments package compares it
//!   (`cga-experiment spheretree-collide`).
//!
//! A build deeper than [`estimate::PROBE_DEPTH`] is first estimated from a build to that depth,
//! and refused, with the estimate and the deepest depth that fits, when it would not fit in the
//! memory available.

mod estimate;

use std::fs;
use std::path::PathBuf;
use std::time::Instant;

use estimate::Probe;

use anyhow::{bail, Context, Result};
use cga_collide::collider::Collider;
use cga_collide::hierarchy::sphere_tree::format;
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
use clap::{Args, Subcommand};
use serde_json::json;

use crate::mesh::load_unit;
use crate::output;
use crate::placement::PoseArgs;
use crate::tree_file::{read_tree_pair, result_json};

/// Octree sphere trees: build them from meshes, test two for collision.
#[derive(Args, Debug)]
pub struct SphereTreeArgs {
    #[command(subcommand)]
    command: SphereTreeCommand,
}

#[derive(Subcommand, Debug)]
enum SphereTreeCommand {
    /// Build one octree sphere tree per mesh and write them in the paper's text format.
    Build(BuildArgs),
    /// Whether the first two trees of a file (the paper's format) collide.
    Collide(CollideArgs),
}

#[derive(Args, Debug)]
#[command(
    mut_arg("rotate", |a| a.help(
        "Rotate every mesh after the first by these degrees about x, then y, then z"
    )),
    mut_arg("translate", |a| a.help("Then translate every mesh after the first"))
)]
struct BuildArgs {
    /// Meshes: files (.obj, .off, .ply, .stl, optionally .gz) or built-in names (bunny,
    /// bunny00, armadillo). Each must be closed.
    #[arg(required = true)]
    meshes: Vec<String>,
    /// Octree depth (0: the root cell only; at most 16). Each level has about four times the
    /// spheres of the one above: a depth whose tree would not fit in the memory available is
    /// refused before it is built, with the estimate and the deepest depth that fits.
    #[arg(long, default_value_t = 5)]
    depth: u32,
    /// Output file.
    #[arg(short, long, value_name = "FILE")]
    output: PathBuf,
    /// Scale each mesh into the unit box centred at the origin first.
    #[arg(long)]
    unit: bool,
    #[command(flatten)]
    pose: PoseArgs,
    /// Split full cells too (all leaves at the full depth).
    #[arg(long)]
    subdivide_full: bool,
    /// Print a JSON summary.
    #[arg(long)]
    json: bool,
}

#[derive(Args, Debug)]
struct CollideArgs {
    /// A file in the paper's format with at least two trees.
    file: PathBuf,
    /// Accept a file that ends early (report what is missing on stderr, use what is there).
    #[arg(long)]
    lenient: bool,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Runs `cga spheretree`.
pub fn run(args: SphereTreeArgs) -> Result<()> {
    match args.command {
        SphereTreeCommand::Build(a) => build_cmd(a),
        SphereTreeCommand::Collide(a) => collide_cmd(a),
    }
}

fn build_cmd(args: BuildArgs) -> Result<()> {
    let options = BuildOptions {
        subdivide_full: args.subdivide_full,
        ..BuildOptions::depth(args.depth)
    };
    output::check("--output", &args.output, None)?;
    let iso = args.pose.isometry();
    // What the trees still to be built may take (each one built is held until all are written).
    let mut budget = Budget::of_this_machine();
    let mut trees = Vec::new();
    let mut summary = Vec::new();
    for (k, spec) in args.meshes.iter().enumerate() {
        let mut mesh = load_unit(spec, "", args.unit)?;
        if k > 0 {
            mesh = mesh.transformed(&iso).with_context(|| {
                format!("placing mesh `{spec}` with --rotate and --translate (give smaller values)")
            })?;
        }
        let start = Instant::now();
        let collider = Collider::new(mesh);
        let building = || format!("building the sphere tree of `{spec}`");
        if args.depth > estimate::PROBE_DEPTH {
            let probe_options = BuildOptions {
                depth: estimate::PROBE_DEPTH,
                ..options
            };
            let probe_start = Instant::now();
            let (tree, report) = build(&collider, &probe_options).with_context(building)?;
            let probe = Probe {
                tree: &tree,
                report: &report,
                took: probe_start.elapsed(),
                subdivide_full: args.subdivide_full,
            };
            budget = check_fits(&probe, args.depth, spec, budget)?;
        }
        let (tree, report) = build(&collider, &options).with_context(building)?;
        let millis = start.elapsed().as_secs_f64() * 1e3;
        summary.push(json!({
            "mesh": spec,
            "triangle_count": collider.mesh().num_triangles(),
            "nodes": tree.len(),
            "leaves": tree.leaf_count(),
            "bytes": tree.heap_bytes(),
            "root": {"centre": tree.root().centre, "radius": tree.root().radius},
            "cube_side": report.side,
            "partial": report.levels.iter().map(|l| l.partial).collect::<Vec<_>>(),
            "full": report.levels.iter().map(|l| l.full).collect::<Vec<_>>(),
            "millis": millis,
        }));
        trees.push(tree);
    }
    fs::write(&args.output, format::write(&trees))
        .with_context(|| format!("--output {}: cannot write the file", args.output.display()))?;
    if args.json {
        println!(
            "{}",
            json!({"file": args.output.display().to_string(), "depth": args.depth, "trees": summary})
        );
    } else {
        for s in &summary {
            println!(
                "{}: {} triangles -> {} spheres ({} leaves), depth {}, {:.1} ms",
                s["mesh"].as_str().unwrap_or("?"),
                s["triangle_count"],
                s["nodes"],
                s["leaves"],
                args.depth,
                s["millis"].as_f64().unwrap_or(0.0)
            );
        }
        println!("wrote {} trees to {}", trees.len(), args.output.display());
    }
    Ok(())
}

/// The memory the builds may still use.
#[derive(Debug, Clone, Copy)]
struct Budget {
    bytes: f64,
    /// Whether `bytes` was read from the machine (or assumed).
    measured: bool,
}

impl Budget {
    /// The memory available now, or 8 GB where that cannot be read.
    fn of_this_machine() -> Budget {
        match estimate::available_memory() {
            Some(bytes) => Budget {
                bytes,
                measured: true,
            },
            None => Budget {
                bytes: 8e9,
                measured: false,
            },
        }
    }
}

/// Refuses a build to `depth` that would not fit in `budget` (with the estimate and the deepest
/// depth that fits); otherwise the budget left for the next mesh.
fn check_fits(probe: &Probe<'_>, depth: u32, spec: &str, budget: Budget) -> Result<Budget> {
    let e = probe.at(depth);
    if e.memory <= budget.bytes {
        return Ok(Budget {
            bytes: budget.bytes - e.memory,
            ..budget
        });
    }
    let available = if budget.measured {
        format!("{} of memory is available", estimate::bytes(budget.bytes))
    } else {
        format!(
            "the available memory cannot be read here, so {} is assumed",
            estimate::bytes(budget.bytes)
        )
    };
    let instead = match probe.deepest_within(depth, budget.bytes) {
        Some(d) => format!(
            "choose --depth {d} or less (depth {d}: about {:.1e} spheres, {})",
            probe.at(d).spheres,
            estimate::bytes(probe.at(d).memory)
        ),
        None => "free memory, or build fewer meshes into one file".to_owned(),
    };
    bail!(
        "--depth {depth}: the sphere tree of `{spec}` would have about {:.1e} spheres and need \
         about {} of memory (a {} file; about {} to build), but {available}: {instead}",
        e.spheres,
        estimate::bytes(e.memory),
        estimate::bytes(e.file),
        estimate::duration(e.seconds),
    )
}

fn collide_cmd(args: CollideArgs) -> Result<()> {
    let trees = read_tree_pair(&args.file, args.lenient, "collide")?;
    let (x, y) = (&trees[0], &trees[1]);
    let start = Instant::now();
    let r = x.collides(y);
    let micros = start.elapsed().as_secs_f64() * 1e6;
    if args.json {
        let mut v = result_json(&r);
        v["method"] = json!("simultaneous");
        v["nodes"] = json!([x.len(), y.len()]);
        v["micros"] = json!(micros);
        println!("{v}");
    } else {
        println!(
            "{} (simultaneous: {} sphere tests, {micros:.1} µs)",
            if r.collides {
                "collide"
            } else {
                "no collision"
            },
            r.sphere_tests
        );
    }
    Ok(())
}

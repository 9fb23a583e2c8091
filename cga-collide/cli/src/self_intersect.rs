//! `cga self-intersect MESH`: every pair of triangles of one mesh that meet anywhere other than
//! in the vertices or edge they share (exact).

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;

use cga_collide::bounding::BuildStrategy;
use cga_collide::collider::Collider;
use clap::Args;
use serde_json::json;

use crate::mesh::load_mesh;
use crate::output;

/// Pairs of triangles of one mesh that meet other than in a shared vertex or edge (exact).
#[derive(Args, Debug)]
pub struct SelfIntersectArgs {
    /// The mesh: a file (.obj, .off, .ply, .stl) or a built-in name (bunny, bunny00, armadillo).
    mesh: String,
    /// Write the pairs, one `i j` per line (0-based triangle indices, `i < j`).
    #[arg(long, value_name = "FILE")]
    pairs: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Runs `cga self-intersect`.
pub fn run(args: SelfIntersectArgs) -> Result<()> {
    output::check_opt("--pairs", args.pairs.as_deref(), None)?;
    let mesh = load_mesh(&args.mesh, "")?;
    let start = Instant::now();
    // One question of a collider built for it: the Morton build costs a third of the SAH one,
    // and the self-intersection pairs do not depend on the tree.
    let collider = Collider::with_strategy(mesh, BuildStrategy::Morton);
    let build = start.elapsed();
    let start = Instant::now();
    let pairs = collider.self_intersections();
    let millis = start.elapsed().as_secs_f64() * 1e3;
    if let Some(path) = &args.pairs {
        output::write_lines(
            "--pairs",
            path,
            pairs.iter().map(|(i, j)| format!("{i} {j}")),
        )?;
    }
    if args.json {
        let value = json!({
            "pairs": pairs.len(),
            "self_intersects": !pairs.is_empty(),
            "triangle_count": collider.mesh().num_triangles(),
            "closed": collider.mesh().is_closed(),
            "build_millis": build.as_secs_f64() * 1e3,
            "millis": millis,
            "mesh": args.mesh,
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "{}: {} triangles, {} self-intersecting pairs (exact; {millis:.2} ms)",
            args.mesh,
            collider.mesh().num_triangles(),
            pairs.len()
        );
    }
    Ok(())
}

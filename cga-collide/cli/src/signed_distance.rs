//! `cga signed-distance MESH POINTS.txt`: the signed distance of query points to a mesh, with
//! certified error bounds and the exact inside/outside.
//!
//! POINTS holds one point a line, `x y z` (whitespace-separated numbers, each read as the
//! nearest `f64`, and the point is the one those `f64` values denote exactly); blank lines and
//! lines starting with `#` are skipped. A malformed line is an error naming the file and line.
//! The distance is negative inside, positive outside; a point on the surface is inside at
//! distance 0 (see `Collider::signed_distances` of the library for the definitions).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::collider::Collider;
use cga_collide::nalgebra::Point3;
use cga_collide::Error;
use clap::Args;
use serde_json::json;

use crate::mesh::load_unit;
use crate::number::short;

/// Signed distance of points to a mesh (negative inside), certified, with the exact sign.
#[derive(Args, Debug)]
pub struct SignedDistanceArgs {
    /// The mesh: a file (.obj, .off, .ply, .stl) or a built-in name (bunny, bunny00, armadillo).
    mesh: String,
    /// The points: one `x y z` a line.
    #[arg(value_name = "POINTS.txt")]
    points: PathBuf,
    /// Scale the mesh into the unit box centred at the origin (largest side 1) first.
    #[arg(long)]
    unit: bool,
    /// Print one JSON object: {"points", "signed_distance", "error_bound", "inside",
    /// "micros_per_point"}.
    #[arg(long)]
    json: bool,
}

/// The points of a file, in order, with the line each came from.
fn read_points(path: &Path) -> Result<(Vec<Point3<f64>>, Vec<usize>)> {
    let name = path.display();
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read {name} (check the path)"))?;
    let (mut points, mut lines) = (Vec::new(), Vec::new());
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let at = k + 1;
        let fields: Vec<&str> = line.split_whitespace().collect();
        if fields.len() != 3 {
            bail!(
                "{name}:{at}: expected three numbers `x y z`, found {} field(s)",
                fields.len()
            );
        }
        let mut xyz = [0.0; 3];
        for (v, f) in xyz.iter_mut().zip(&fields) {
            *v = f
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .with_context(|| format!("{name}:{at}: `{f}` is not a finite number"))?;
        }
        points.push(Point3::from(xyz));
        lines.push(at);
    }
    Ok((points, lines))
}

/// Runs `cga signed-distance`.
pub fn run(args: SignedDistanceArgs) -> Result<()> {
    let mesh = load_unit(&args.mesh, "", args.unit)?;
    let (points, lines) = read_points(&args.points)?;
    let collider = Collider::new(mesh);
    let start = Instant::now();
    let answers = collider.signed_distances(&points).map_err(|e| match e {
        Error::InShapePoint { index, source } => anyhow::anyhow!(
            "{}:{}: {source}",
            args.points.display(),
            lines.get(index).copied().unwrap_or(0)
        ),
        e => anyhow::Error::new(e).context(format!("mesh {}", args.mesh)),
    })?;
    let micros = start.elapsed().as_secs_f64() * 1e6 / points.len().max(1) as f64;
    if args.json {
        let value = json!({
            "points": points.len(),
            "signed_distance": answers.iter().map(|a| a.signed_distance).collect::<Vec<_>>(),
            "error_bound": answers.iter().map(|a| a.error_bound).collect::<Vec<_>>(),
            "inside": answers.iter().map(|a| a.inside).collect::<Vec<_>>(),
            "micros_per_point": micros,
        });
        println!("{value}");
    } else {
        let inside = answers.iter().filter(|a| a.inside).count();
        println!(
            "{}: {} points, {inside} inside ({micros:.3} µs per point)",
            args.points.display(),
            points.len()
        );
        for a in &answers {
            println!(
                "{} ± {} {}",
                short(a.signed_distance),
                short(a.error_bound),
                if a.inside { "inside" } else { "outside" }
            );
        }
    }
    Ok(())
}

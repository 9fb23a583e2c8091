//! `cga distance A B`: the minimum distance between two meshes' surfaces, with witness points,
//! the triangle pair attaining it and its certified error bound.

use std::time::Instant;

use anyhow::{Context, Result};
use cga_collide::query::{self, Collider};
use clap::Args;
use serde_json::json;

use crate::{load_mesh, parse_triple, placement};

#[derive(Args, Debug)]
pub(crate) struct DistanceArgs {
    /// Mesh A: a file (.obj, .off, .ply, .stl) or a built-in name (bunny, bunny00, armadillo).
    a: String,
    /// Mesh B (moved by --rotate and --translate).
    b: String,
    /// Scale each mesh uniformly into the unit box centred at the origin first.
    #[arg(long)]
    unit: bool,
    /// Rotate B by these degrees about x, then y, then z.
    #[arg(long, value_name = "AX,AY,AZ", value_parser = parse_triple, allow_hyphen_values = true)]
    rotate: Option<[f64; 3]>,
    /// Then translate B.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_triple, allow_hyphen_values = true)]
    translate: Option<[f64; 3]>,
    /// Also compute the squared distance exactly (rationals) and print it.
    #[arg(long)]
    exact: bool,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

pub(crate) fn run(args: DistanceArgs) -> Result<()> {
    let mut a = load_mesh(&args.a)?;
    let mut b = load_mesh(&args.b)?;
    if args.unit {
        a = a.unit();
        b = b.unit();
    }
    let b = b
        .transformed(&placement(args.rotate, args.translate))
        .context("placing mesh B")?;
    let (ca, cb) = (Collider::new(a), Collider::new(b));
    let start = Instant::now();
    let d = query::mesh_distance(&ca, &cb).context("a mesh has no triangles")?;
    let millis = start.elapsed().as_secs_f64() * 1e3;
    let exact = args
        .exact
        .then(|| query::exact_mesh_distance(&ca, &cb))
        .flatten();
    let (i, j) = d.triangles.unwrap_or((0, 0));
    let w = |p: &cga_collide::nalgebra::Point3<f64>| [p.x, p.y, p.z];
    if args.json {
        let mut value = json!({
            "distance": d.distance,
            "error_bound": d.error_bound,
            "witness_a": w(&d.witness_a),
            "witness_b": w(&d.witness_b),
            "triangles": [i, j],
            "millis": millis,
            "a": args.a,
            "b": args.b,
        });
        if let Some(e) = &exact {
            value["exact_distance2"] = json!(e.distance2.to_string());
        }
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "distance {} ± {:.3e} (certified) between triangle {i} of {} and {j} of {} ({millis:.3} ms)",
            d.distance, d.error_bound, args.a, args.b
        );
        println!(
            "witness A {:?}\nwitness B {:?}",
            w(&d.witness_a),
            w(&d.witness_b)
        );
        if let Some(e) = &exact {
            println!("exact squared distance {}", e.distance2);
        }
    }
    Ok(())
}

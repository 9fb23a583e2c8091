//! `cga distance A B`: the minimum distance between two meshes' surfaces, with witness points,
//! the triangle pair attaining it and its certified error bound.

use std::time::Instant;

use anyhow::{bail, Context, Result};

use cga_collide::collider::Collider;
use clap::Args;
use serde_json::json;

use crate::args::TwoMeshes;
use crate::number;
use crate::placement::PoseArgs;

/// Minimum distance between two meshes, with witnesses and a certified error bound.
#[derive(Args, Debug)]
#[command(mut_arg("a", |a| a.required(true)), mut_arg("b", |b| b.required(true)))]
pub struct DistanceArgs {
    #[command(flatten)]
    meshes: TwoMeshes,
    #[command(flatten)]
    pose: PoseArgs,
    /// Also compute the squared distance exactly (rationals) and print it.
    #[arg(long)]
    exact: bool,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Runs `cga distance`.
pub fn run(args: DistanceArgs) -> Result<()> {
    let (a_spec, b_spec) = args.meshes.both()?;
    let (a, b) = args.meshes.load()?;
    let b = b.transformed(&args.pose.isometry()).with_context(|| {
        format!("placing mesh B (`{b_spec}`) with --rotate and --translate (give smaller values)")
    })?;
    let (ca, cb) = (Collider::new(a), Collider::new(b));
    let start = Instant::now();
    let d = match ca.distance(&cb) {
        Ok(d) => d,
        Err(e @ cga_collide::Error::OutOfRange { .. }) => bail!(
            "the coordinates of {a_spec} and {b_spec} are out of the range where the distance \
             can be certified ({e}); scale the meshes down (e.g. with --unit) or move them \
             closer to the origin"
        ),
        Err(e) => return Err(e.into()),
    };
    let millis = start.elapsed().as_secs_f64() * 1e3;
    let w = |p: &cga_collide::nalgebra::Point3<f64>| [p.x, p.y, p.z];
    let (wa, wb) = (w(&d.witness_a), w(&d.witness_b));
    // Never print a non-finite number as certified.
    let finite = d.distance.is_finite()
        && d.error_bound.is_finite()
        && wa.iter().chain(&wb).all(|c| c.is_finite());
    if !finite {
        bail!(
            "the coordinates of {a_spec} and {b_spec} are out of the range where the distance \
             can be certified (the computation overflowed: distance {}, error bound {}); scale \
             the meshes down (e.g. with --unit) or move them closer to the origin",
            d.distance,
            d.error_bound
        );
    }
    let exact = args.exact.then(|| ca.exact_distance(&cb)).transpose()?;
    let (i, j) = d.triangles.unwrap_or((0, 0));
    if args.json {
        let mut value = json!({
            "distance": d.distance,
            "error_bound": d.error_bound,
            "witness_a": wa,
            "witness_b": wb,
            "witness_triangles": [i, j],
            "millis": millis,
            "a": a_spec,
            "b": b_spec,
        });
        if let Some(e) = &exact {
            value["exact_distance2"] = json!(e.distance2.to_string());
        }
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "distance {} ± {:.3e} (certified) between triangle {i} of {a_spec} and {j} of \
             {b_spec} ({millis:.3} ms)",
            number::short(d.distance),
            d.error_bound
        );
        println!(
            "witness A {}\nwitness B {}",
            number::point(wa),
            number::point(wb)
        );
        if let Some(e) = &exact {
            println!("exact squared distance {}", e.distance2);
        }
    }
    Ok(())
}

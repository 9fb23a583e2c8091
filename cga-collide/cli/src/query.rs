//! `cga query MESH --segment|--triangle|--sphere|--ball ...`: which triangles of a mesh a
//! primitive meets (exact), on the CPU or the GPU.

use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::collider::Collider;
use cga_collide::nalgebra::Point3;
use cga_collide::{Ball, Segment, Sphere, Triangle};
use clap::Args;
use serde_json::json;

use crate::args::{parse_numbers, ModeArg};
use crate::device::{self, DeviceArg, Primitive};
use crate::mesh::load_unit;

/// Which triangles of a mesh a segment, triangle, sphere or ball meets.
#[derive(Args, Debug)]
pub struct QueryArgs {
    /// The mesh: a file or a built-in name (bunny, bunny00, armadillo).
    mesh: String,
    /// Scale the mesh into the unit box centred at the origin first.
    #[arg(long)]
    unit: bool,
    /// A segment `x1,y1,z1,x2,y2,z2`.
    #[arg(long, value_parser = parse_numbers::<6>, allow_hyphen_values = true, group = "primitive")]
    segment: Option<[f64; 6]>,
    /// A triangle `x1,y1,z1,x2,y2,z2,x3,y3,z3`.
    #[arg(long, value_parser = parse_numbers::<9>, allow_hyphen_values = true, group = "primitive")]
    triangle: Option<[f64; 9]>,
    /// A sphere (surface) `cx,cy,cz,r`.
    #[arg(long, value_parser = parse_numbers::<4>, allow_hyphen_values = true, group = "primitive")]
    sphere: Option<[f64; 4]>,
    /// A ball (solid) `cx,cy,cz,r`.
    #[arg(long, value_parser = parse_numbers::<4>, allow_hyphen_values = true, group = "primitive")]
    ball: Option<[f64; 4]>,
    /// How triangles are found (default: bvh on the CPU; the GPU tests every triangle, brute).
    #[arg(long, value_enum)]
    mode: Option<ModeArg>,
    /// Where the exact tests run. `gpu` needs a wgpu adapter (a GPU driver, or Mesa's software
    /// Vulkan driver lavapipe: package mesa-vulkan-drivers); it tests every triangle, with
    /// answers equal to the CPU's, and reports how many it flagged for exact re-decision.
    #[arg(long, value_enum, default_value_t = DeviceArg::Cpu)]
    device: DeviceArg,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

fn point(c: &[f64]) -> Point3<f64> {
    Point3::new(c[0], c[1], c[2])
}

impl QueryArgs {
    /// The query primitive given.
    fn primitive(&self) -> Result<Primitive> {
        Ok(if let Some(s) = self.segment {
            Primitive::Segment(Segment::new(point(&s[0..3]), point(&s[3..6])).context("--segment")?)
        } else if let Some(t) = self.triangle {
            Primitive::Triangle(
                Triangle::new(point(&t[0..3]), point(&t[3..6]), point(&t[6..9]))
                    .context("--triangle")?,
            )
        } else if let Some(s) = self.sphere {
            Primitive::Sphere(Sphere::new(point(&s[0..3]), s[3]).context("--sphere")?)
        } else if let Some(s) = self.ball {
            Primitive::Ball(Ball::new(point(&s[0..3]), s[3]).context("--ball")?)
        } else {
            bail!("no query shape: give one of --segment, --triangle, --sphere or --ball (see `cga query --help`)");
        })
    }
}

/// Runs `cga query`.
pub fn run(args: QueryArgs) -> Result<()> {
    let mesh = load_unit(&args.mesh, "", args.unit)?;
    let shape = args.primitive()?;
    if args.device == DeviceArg::Gpu && args.mode == Some(ModeArg::Bvh) {
        device::reject_unsupported(&["--mode bvh"])?;
    }
    let gpu = device::open(args.device)?;
    let mode = args.mode.unwrap_or(if gpu.is_some() {
        ModeArg::Brute
    } else {
        ModeArg::Bvh
    });
    let what = shape.name();
    let (hits, millis, stats) = match &gpu {
        None => {
            let collider = Collider::new(mesh).with_mode(mode.into());
            let start = Instant::now();
            let hits = shape.cpu_hits(&collider);
            (hits, start.elapsed(), None)
        }
        Some(gpu) => {
            let start = Instant::now();
            let answers = gpu.hits(&shape, &mesh)?;
            (
                answers.hits,
                start.elapsed(),
                Some((answers.tested, answers.flagged)),
            )
        }
    };
    let millis = millis.as_secs_f64() * 1e3;
    let device_name = device::name(gpu.as_ref());
    let mode_name = mode.name();
    if args.json {
        let value = json!({
            "query": what,
            "hits": hits.len(),
            "triangles": hits,
            "mode": mode_name,
            "device": device_name,
            "tested": stats.map(|s| s.0),
            "flagged": stats.map(|s| s.1),
            "millis": millis,
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "{what} meets {} triangles of {} ({millis:.3} ms, mode {mode_name}, device {device_name})",
            hits.len(),
            args.mesh
        );
        if let Some((tested, flagged)) = stats {
            println!("{tested} triangles tested on the device, {flagged} flagged and re-decided exactly on the CPU");
        }
        let shown: Vec<String> = hits.iter().take(20).map(u32::to_string).collect();
        if !shown.is_empty() {
            let more = if hits.len() > 20 { " ..." } else { "" };
            println!("{}{more}", shown.join(" "));
        }
    }
    Ok(())
}

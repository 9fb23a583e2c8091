//! The thesis's GPU table, reproduced: a segment against a large bunny, and a ~1K-triangle mesh
//! against it, brute force, on the CPU (all cores, rayon) and on the GPU, same run, same
//! answers checked.
//!
//! ```text
//! cargo run --release -p cga-collide --features gpu --example gpu_batches -- [TRIANGLES] [SMALL]
//! ```
//!
//! `TRIANGLES` (default 3 700 000: the 3 674-triangle bunny subdivided to 3.76M triangles, the
//! thesis's ~4M-triangle bunny is not available) and `SMALL` (default 1 000: that many
//! triangles of a second, rotated bunny). On a software driver (lavapipe) the figures are
//! correctness runs, not speed.

use std::time::Instant;

use cga_collide::collider::{Collider, Mode};
use cga_collide::gpu::Device;
use cga_collide::mesh::TriMesh;
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::Segment;

fn seconds(t: Instant) -> f64 {
    t.elapsed().as_secs_f64()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let n: usize = args
        .next()
        .map(|a| a.parse())
        .transpose()?
        .unwrap_or(3_700_000);
    let small_n: usize = args.next().map(|a| a.parse()).transpose()?.unwrap_or(1_000);

    let device = Device::new()?;
    println!("device: {} ({:?})", device.name(), device.precision());
    println!(
        "cpu: {} threads (rayon)",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );

    let big = TriMesh::bunny_with_at_least(n).unit();
    let small = {
        let bunny = TriMesh::bunny().unit();
        let k = small_n.min(bunny.num_triangles());
        let tris = bunny.triangles()[..k].to_vec();
        let part = TriMesh::new(bunny.vertices().to_vec(), tris)?;
        part.transformed(&Isometry3::from_parts(
            Translation3::new(0.05, 0.02, 0.0),
            UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.4),
        ))?
    };
    println!(
        "meshes: {} triangles (bunny subdivided), {} triangles (part of a rotated bunny)",
        big.num_triangles(),
        small.num_triangles()
    );
    let t = Instant::now();
    let collider = Collider::new(big.clone());
    let small_collider = Collider::new(small.clone());
    println!(
        "(hierarchies built in {:.2} s, not part of the brute-force figures)",
        seconds(t)
    );

    let segment = Segment::new(Point3::new(-0.6, 0.05, -0.1), Point3::new(0.6, 0.1, 0.1))?;

    // Warm-up: shader compilation and first upload are not part of the figures.
    device.hits(&segment.into(), &small)?;

    println!("| test | pairs | CPU brute force (s) | GPU (s) | hits | flagged | same answers |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    let t = Instant::now();
    let cpu = collider
        .clone()
        .with_mode(Mode::Brute)
        .segment_hits(&segment);
    let cpu_s = seconds(t);
    let t = Instant::now();
    let gpu = device.hits(&segment.into(), &big)?;
    let gpu_s = seconds(t);
    println!(
        "| segment vs {} triangles | {} | {cpu_s:.3} | {gpu_s:.3} | {} | {} | {} |",
        big.num_triangles(),
        gpu.tested,
        gpu.hits.len(),
        gpu.flagged,
        gpu.hits == cpu
    );

    let t = Instant::now();
    let cpu = small_collider
        .clone()
        .with_mode(Mode::Brute)
        .intersecting_pairs(&collider);
    let cpu_s = seconds(t);
    let t = Instant::now();
    let gpu = device.intersecting_pairs(&small, &big)?;
    let gpu_s = seconds(t);
    println!(
        "| {} vs {} triangles | {} | {cpu_s:.3} | {gpu_s:.3} | {} | {} | {} |",
        small.num_triangles(),
        big.num_triangles(),
        gpu.tested,
        gpu.hits.len(),
        gpu.flagged,
        gpu.hits == cpu
    );
    let candidates = small_collider.box_pairs_bvh(&collider);
    let t = Instant::now();
    let tree = device.intersecting_candidates(&small, &big, &candidates)?;
    let tree_s = seconds(t);
    println!(
        "| same, candidate pairs of the trees | {} | - | {tree_s:.3} | {} | {} | {} |",
        tree.tested,
        tree.hits.len(),
        tree.flagged,
        tree.hits == cpu
    );
    if gpu.hits != cpu || tree.hits != cpu {
        return Err("GPU and CPU answers differ".into());
    }
    Ok(())
}

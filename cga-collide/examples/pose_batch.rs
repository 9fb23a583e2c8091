//! A batch of poses answered in one call, spread over the cores (feature `parallel`).
//!
//! Run: `cargo run --release -p cga-collide --example pose_batch`.

use cga_collide::collider::{Collider, PosePair};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::TriMesh;

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let bunny = Collider::new(TriMesh::bunny());
    let rod = Collider::new(TriMesh::cuboid(
        Point3::new(-0.005, -0.005, -0.2),
        Point3::new(0.005, 0.005, 0.2),
    )?);
    // A sweep of the rod across the bunny: 200 poses of the rod, the bunny fixed.
    let poses: Vec<PosePair> = (0..200)
        .map(|k| {
            let x = -0.15 + 0.3 * k as f64 / 199.0;
            let rod_pose = Isometry3::new(Vector3::new(x, 0.1, 0.0), Vector3::x() * 0.2);
            PosePair::new(Isometry3::identity(), rod_pose)
        })
        .collect();
    let hits = bunny.collides_batch(&rod, &poses)?;
    let pairs = bunny.intersecting_pairs_batch(&rod, &poses)?;
    // The two batch calls agree pose by pose.
    for (hit, p) in hits.iter().zip(&pairs) {
        assert_eq!(*hit, !p.is_empty());
    }
    let colliding = hits.iter().filter(|&&h| h).count();
    println!("{colliding} of {} poses collide", poses.len());
    Ok(())
}

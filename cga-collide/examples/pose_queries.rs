//! Mesh–mesh collision under poses: build each collider once in its own frame, then ask about
//! as many poses as you like, with no work proportional to the mesh size per pose.
//!
//! Run: `cargo run --release -p cga-collide --example pose_queries`.

use cga_collide::collider::Collider;
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::TriMesh;

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    // Built once: the BVH of each mesh, in the mesh's own coordinates.
    let bunny = Collider::new(TriMesh::bunny());
    let block = Collider::new(TriMesh::cuboid(
        Point3::new(-0.02, -0.02, -0.02),
        Point3::new(0.02, 0.02, 0.02),
    )?);

    let here = Isometry3::identity();
    for z in [0.0, 0.05, 0.5] {
        // The block at height z above the origin, turned a little about y.
        let pose = Isometry3::new(Vector3::new(0.0, 0.1, z), Vector3::y() * 0.3);
        let hit = bunny.collides_at(&here, &block, &pose)?;
        let pairs = bunny.intersecting_pairs_at(&here, &block, &pose)?;
        // Exactly the answer for the block placed with this pose (vertices `pose * v`).
        assert_eq!(hit, !pairs.is_empty());
        println!(
            "z = {z}: collides {hit}, {} intersecting triangle pairs",
            pairs.len()
        );
    }
    Ok(())
}

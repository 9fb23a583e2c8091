//! parry3d (the latest release) set up the way its users call it, shared by the benchmarks
//! that compare against it.

use cga_collide::shape::mesh::TriMesh;
use nalgebra::Isometry3;
use parry3d_latest::bounding_volume::BoundingVolume;
use parry3d_latest::math::{Pose, Vector};
use parry3d_latest::partitioning::BvhNode;
use parry3d_latest::query::intersection_test;
use parry3d_latest::shape::TriMesh as ParryMesh;

/// The same vertices and triangles as a parry3d mesh (its own tree, built by parry).
pub fn parry_mesh(m: &TriMesh) -> ParryMesh {
    let v = m
        .vertices()
        .iter()
        .map(|p| Vector::new(p.x, p.y, p.z))
        .collect();
    ParryMesh::new(v, m.triangles().to_vec()).unwrap()
}

/// A nalgebra pose as parry's.
pub fn parry_pose(iso: &Isometry3<f64>) -> Pose {
    let q = iso.rotation.quaternion();
    let t = iso.translation.vector;
    Pose::from_parts(
        Vector::new(t.x, t.y, t.z),
        parry3d_latest::glamx::DQuat::from_xyzw(q.i, q.j, q.k, q.w),
    )
}

/// parry's intersecting pairs at a pose: simultaneous traversal with B's boxes moved into A's
/// frame, then its triangle–triangle intersection test (`f64`, not exact).
pub fn parry_pairs(a: &ParryMesh, b: &ParryMesh, pos12: &Pose) -> usize {
    a.bvh()
        .leaf_pairs(b.bvh(), |n1: &BvhNode, n2: &BvhNode| {
            n1.aabb().intersects(&n2.aabb().transform_by(pos12))
        })
        .filter(|&(i, j)| {
            intersection_test(&Pose::IDENTITY, &a.triangle(i), pos12, &b.triangle(j))
                .map(|r| r.intersecting)
                .unwrap_or(false)
        })
        .count()
}

/// parry's first hit at a pose: its mesh–mesh `intersection_test`.
pub fn parry_collides(a: &ParryMesh, b: &ParryMesh, pos12: &Pose) -> bool {
    intersection_test(&Pose::IDENTITY, a, pos12, b)
        .map(|r| r.intersecting)
        .unwrap_or(false)
}

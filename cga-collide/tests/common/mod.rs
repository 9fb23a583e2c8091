//! Meshes and poses shared by the mesh-query tests (`bvh_query`, `posed`).
#![allow(dead_code)] // each test file uses a part

use cga_collide::shape::mesh::TriMesh;
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

/// A closed axis-aligned box mesh with integer corners (12 triangles): touching and coplanar
/// contacts happen exactly when such boxes share faces, edges or corners.
pub fn cube(lo: [i32; 3], hi: [i32; 3]) -> TriMesh {
    TriMesh::cuboid(lo.map(f64::from).into(), hi.map(f64::from).into()).unwrap()
}

/// A flat grid of `n × n` unit squares in the plane z = `z`, two triangles each.
pub fn grid(n: u32, z: f64) -> TriMesh {
    let mut v = Vec::new();
    for y in 0..=n {
        for x in 0..=n {
            v.push(Point3::new(x as f64, y as f64, z));
        }
    }
    let mut t = Vec::new();
    for y in 0..n {
        for x in 0..n {
            let i = y * (n + 1) + x;
            t.push([i, i + 1, i + n + 2]);
            t.push([i, i + n + 2, i + n + 1]);
        }
    }
    TriMesh::new(v, t).unwrap()
}

/// `n` random triangles with centres uniform in `[-spread, spread]³` and corners within 0.4
/// of the centre per axis; every 7th is degenerate (a repeated corner).
pub fn random_soup(seed: u64, n: usize, spread: f64) -> TriMesh {
    let mut rng = cga_collide::testing::adversarial::SplitMix64(seed);
    let mut v = Vec::new();
    let mut t = Vec::new();
    for k in 0..n {
        let c = Point3::new(
            rng.float(-spread, spread),
            rng.float(-spread, spread),
            rng.float(-spread, spread),
        );
        for _ in 0..3 {
            v.push(
                c + Vector3::new(
                    rng.float(-0.4, 0.4),
                    rng.float(-0.4, 0.4),
                    rng.float(-0.4, 0.4),
                ),
            );
        }
        let b = 3 * k as u32;
        t.push(if k % 7 == 0 {
            [b, b + 1, b + 1]
        } else {
            [b, b + 1, b + 2]
        });
    }
    TriMesh::new(v, t).unwrap()
}

/// Random rigid poses: translations in `[-1.5, 1.5]³`, Euler angles in `[-3.2, 3.2]³`.
pub fn iso() -> impl Strategy<Value = Isometry3<f64>> {
    (
        prop::array::uniform3(-1.5f64..1.5),
        prop::array::uniform3(-3.2f64..3.2),
    )
        .prop_map(|(t, r)| {
            Isometry3::from_parts(
                Translation3::new(t[0], t[1], t[2]),
                UnitQuaternion::from_euler_angles(r[0], r[1], r[2]),
            )
        })
}

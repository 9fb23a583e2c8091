use cga_collide::query::{self, Collider};
use cga_collide::shape::mesh::TriMesh;
use nalgebra::{Isometry3, Vector3};
use std::time::Instant;
const PLACEMENTS: [([f64; 3], [f64; 3]); 3] = [
    ([1.2, 0.05, 0.0], [0.0, 0.0, 0.0]),
    ([0.0, 1.1, 0.2], [0.3, 0.0, 0.5]),
    ([0.9, 0.6, -0.3], [0.0, 1.0, 0.0]),
];
fn main() {
    let a = Collider::new(TriMesh::bunny00().unit());
    let arm = TriMesh::armadillo().unit();
    println!(
        "tris a {} b {}",
        a.mesh().num_triangles(),
        arm.num_triangles()
    );
    let reps: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().unwrap())
        .unwrap_or(5);
    for (t, r) in PLACEMENTS.iter() {
        let iso = Isometry3::new(Vector3::from(*t), Vector3::from(*r));
        let b = Collider::new(arm.transformed(&iso).unwrap());
        let mut best = f64::INFINITY;
        let mut d = None;
        for _ in 0..reps {
            let t0 = Instant::now();
            d = query::mesh_distance(&a, &b);
            best = best.min(t0.elapsed().as_secs_f64());
        }
        println!("{:?} {:.3} ms", d, best * 1e3);
    }
}

//! Mesh distance (`query::mesh_distance`, certified bound included) against parry3d's
//! `query::distance` on the same placements, and exact self-intersection (tree) against the
//! brute-force all-pairs scan, in the same run.
//!
//! `cargo bench -p cga-collide --bench distance -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use cga_collide::query::{self, Collider};
use cga_collide::shape::mesh::TriMesh;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{Isometry3, Vector3};
use parry3d_f64::shape::TriMesh as ParryMesh;

/// Non-colliding placements of the unit-scaled armadillo beside bunny00 (B translated and
/// turned; the same transformed coordinates for both libraries).
const PLACEMENTS: [([f64; 3], [f64; 3]); 3] = [
    ([1.2, 0.05, 0.0], [0.0, 0.0, 0.0]),
    ([0.0, 1.1, 0.2], [0.3, 0.0, 0.5]),
    ([0.9, 0.6, -0.3], [0.0, 1.0, 0.0]),
];

fn distance(c: &mut Criterion) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let arm = TriMesh::armadillo().unit();
    let pa = ParryMesh::new(a.mesh().vertices().to_vec(), a.mesh().triangles().to_vec()).unwrap();
    let id = Isometry3::identity();
    let mut g = c.benchmark_group("mesh_distance_bunny00_x_armadillo");
    for (k, (t, r)) in PLACEMENTS.iter().enumerate() {
        let iso = Isometry3::new(Vector3::from(*t), Vector3::from(*r));
        let b = Collider::new(arm.transformed(&iso).unwrap());
        let pb =
            ParryMesh::new(b.mesh().vertices().to_vec(), b.mesh().triangles().to_vec()).unwrap();
        let ours = query::mesh_distance(&a, &b).unwrap();
        let parry = parry3d_f64::query::distance(&id, &pa, &id, &pb);
        eprintln!(
            "placement {k}: cga {} ± {:.1e} (triangles {:?}); parry3d {:?}",
            ours.distance, ours.error_bound, ours.triangles, parry
        );
        g.bench_with_input(BenchmarkId::new("cga_certified", k), &(), |bch, _| {
            bch.iter(|| query::mesh_distance(black_box(&a), black_box(&b)))
        });
        if parry.is_ok() {
            g.bench_with_input(BenchmarkId::new("parry3d", k), &(), |bch, _| {
                bch.iter(|| parry3d_f64::query::distance(&id, black_box(&pa), &id, black_box(&pb)))
            });
        }
    }
    g.finish();
}

fn self_intersection(c: &mut Criterion) {
    let mut g = c.benchmark_group("self_intersection");
    g.sample_size(10);
    for (name, mesh) in [("bunny00", TriMesh::bunny00()), ("bunny", TriMesh::bunny())] {
        let col = Collider::new(mesh);
        let n = col.mesh().num_triangles() as u32;
        g.bench_with_input(BenchmarkId::new("bvh_parallel", name), &(), |bch, _| {
            bch.iter(|| query::self_intersections(black_box(&col)))
        });
        if n <= 6000 {
            // Baseline: every pair, the same exact decision (what the tree must agree with).
            g.bench_with_input(BenchmarkId::new("brute_all_pairs", name), &(), |bch, _| {
                bch.iter(|| query::self_intersections_brute(black_box(&col)))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, distance, self_intersection);
criterion_main!(benches);

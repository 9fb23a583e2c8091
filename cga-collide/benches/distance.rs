//! Mesh distance (`query::mesh_distance`, certified bound included) against parry3d's
//! `query::distance` (0.20, and the latest release 0.31) on the same placements, and exact
//! self-intersection (tree) against the brute-force all-pairs scan, in the same run. coal's
//! figures for the same placements come from `benches/coal_distance.py` (Python), run right
//! after.
//!
//! Mesh distance under poses (`Collider::distance_at`) against placing both meshes and then
//! `query::mesh_distance` (what a user without pose queries does), on the same poses.
//!
//! `cargo bench -p cga-collide --bench distance -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use cga_collide::collider::{Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{Isometry3, Vector3};
use parry3d_f64::shape::TriMesh as ParryMesh;
use parry3d_latest::math::{Pose, Vector};
use parry3d_latest::shape::TriMesh as LatestMesh;

/// Non-colliding placements of the unit-scaled armadillo beside bunny00 (B translated and
/// turned; the same transformed coordinates for both libraries).
const PLACEMENTS: [([f64; 3], [f64; 3]); 3] = [
    ([1.2, 0.05, 0.0], [0.0, 0.0, 0.0]),
    ([0.0, 1.1, 0.2], [0.3, 0.0, 0.5]),
    ([0.9, 0.6, -0.3], [0.0, 1.0, 0.0]),
];

fn latest_mesh(m: &TriMesh) -> LatestMesh {
    let v = m
        .vertices()
        .iter()
        .map(|p| Vector::new(p.x, p.y, p.z))
        .collect();
    LatestMesh::new(v, m.triangles().to_vec()).unwrap()
}

fn distance(c: &mut Criterion) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let arm = TriMesh::armadillo().unit();
    let pa = ParryMesh::new(a.mesh().vertices().to_vec(), a.mesh().triangles().to_vec()).unwrap();
    let la = latest_mesh(a.mesh());
    let lid = Pose::IDENTITY;
    let id = Isometry3::identity();
    let mut g = c.benchmark_group("mesh_distance_bunny00_x_armadillo");
    // parry3d takes a tenth of a second per query: the minimum sample count keeps the run short.
    g.sample_size(10);
    for (k, (t, r)) in PLACEMENTS.iter().enumerate() {
        let iso = Isometry3::new(Vector3::from(*t), Vector3::from(*r));
        let b = Collider::new(arm.transformed(&iso).unwrap());
        let pb =
            ParryMesh::new(b.mesh().vertices().to_vec(), b.mesh().triangles().to_vec()).unwrap();
        let ours = a.distance(&b).unwrap();
        let lb = latest_mesh(b.mesh());
        let parry = parry3d_f64::query::distance(&id, &pa, &id, &pb);
        let latest = parry3d_latest::query::distance(&lid, &la, &lid, &lb);
        eprintln!(
            "placement {k}: cga {} ± {:.1e} (triangles {:?}); parry3d 0.20 {:?}; parry3d 0.31 {:?}",
            ours.distance, ours.error_bound, ours.triangles, parry, latest
        );
        g.bench_with_input(BenchmarkId::new("cga_certified", k), &(), |bch, _| {
            bch.iter(|| black_box(&a).distance(black_box(&b)))
        });
        if parry.is_ok() {
            g.bench_with_input(BenchmarkId::new("parry3d", k), &(), |bch, _| {
                bch.iter(|| parry3d_f64::query::distance(&id, black_box(&pa), &id, black_box(&pb)))
            });
        }
        if latest.is_ok() {
            g.bench_with_input(BenchmarkId::new("parry3d_0_31", k), &(), |bch, _| {
                bch.iter(|| {
                    parry3d_latest::query::distance(&lid, black_box(&la), &lid, black_box(&lb))
                })
            });
        }
    }
    g.finish();
}

/// Both meshes moved: A by a fixed pose, B by A's pose times each placement (so the relative
/// placements are those of [`distance`]).
fn distance_at_poses(c: &mut Criterion) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let b = Collider::new(TriMesh::armadillo().unit());
    let pa = Isometry3::new(Vector3::new(0.5, -0.2, 0.1), Vector3::new(0.2, 0.1, 0.3));
    let mut g = c.benchmark_group("distance_at_bunny00_x_armadillo");
    g.sample_size(10);
    for (k, (t, r)) in PLACEMENTS.iter().enumerate() {
        let pb = pa * Isometry3::new(Vector3::from(*t), Vector3::from(*r));
        let at = a.distance_at(&pa, &b, &pb).unwrap();
        let placed = a
            .placed(&pa)
            .unwrap()
            .distance(&b.placed(&pb).unwrap())
            .unwrap();
        eprintln!(
            "pose {k}: distance_at {:?}; identical to placing first: {}",
            (at.distance, at.error_bound, at.triangles),
            at == placed
        );
        g.bench_with_input(BenchmarkId::new("distance_at", k), &(), |bch, _| {
            bch.iter(|| black_box(&a).distance_at(&pa, black_box(&b), &pb))
        });
        g.bench_with_input(
            BenchmarkId::new("place_then_mesh_distance", k),
            &(),
            |bch, _| {
                bch.iter(|| {
                    let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
                    black_box(&wa).distance(black_box(&wb))
                })
            },
        );
        // Reference: the search alone, on copies placed once outside the timing.
        let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
        g.bench_with_input(
            BenchmarkId::new("mesh_distance_placed_once", k),
            &(),
            |bch, _| bch.iter(|| black_box(&wa).distance(black_box(&wb))),
        );
    }
    g.finish();
}

/// Clearance under the same poses: every pair within `CLEARANCE` (pose 1 has some, the others
/// none), against placing both meshes first.
fn clearance_at_poses(c: &mut Criterion) {
    const CLEARANCE: f64 = 0.1;
    let a = Collider::new(TriMesh::bunny00().unit());
    let b = Collider::new(TriMesh::armadillo().unit());
    let pa = Isometry3::new(Vector3::new(0.5, -0.2, 0.1), Vector3::new(0.2, 0.1, 0.3));
    let mut g = c.benchmark_group("pairs_within_distance_at_bunny00_x_armadillo");
    g.sample_size(10);
    for (k, (t, r)) in PLACEMENTS.iter().enumerate() {
        let pb = pa * Isometry3::new(Vector3::from(*t), Vector3::from(*r));
        let at = a.pairs_within_distance_at(&pa, &b, &pb, CLEARANCE).unwrap();
        let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
        let placed = wa.pairs_within_distance(&wb, CLEARANCE);
        eprintln!(
            "pose {k}: {} pairs within {CLEARANCE}; identical to placing first: {}",
            at.len(),
            at == placed
        );
        g.bench_with_input(
            BenchmarkId::new("pairs_within_distance_at", k),
            &(),
            |bch, _| {
                bch.iter(|| {
                    black_box(&a).pairs_within_distance_at(&pa, black_box(&b), &pb, CLEARANCE)
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("place_then_mesh_pairs_within_distance", k),
            &(),
            |bch, _| {
                bch.iter(|| {
                    let (wa, wb) = (a.placed(&pa).unwrap(), b.placed(&pb).unwrap());
                    black_box(&wa).pairs_within_distance(black_box(&wb), CLEARANCE)
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new("mesh_pairs_within_distance_placed_once", k),
            &(),
            |bch, _| bch.iter(|| black_box(&wa).pairs_within_distance(black_box(&wb), CLEARANCE)),
        );
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
            bch.iter(|| black_box(&col).self_intersections())
        });
        if n <= 6000 {
            // Baseline: every pair, the same exact decision (what the tree must agree with).
            let brute = col.clone().with_mode(Mode::Brute);
            g.bench_with_input(BenchmarkId::new("brute_all_pairs", name), &(), |bch, _| {
                bch.iter(|| black_box(&brute).self_intersections())
            });
        }
    }
    g.finish();
}

criterion_group!(
    benches,
    distance,
    distance_at_poses,
    clearance_at_poses,
    self_intersection
);
criterion_main!(benches);

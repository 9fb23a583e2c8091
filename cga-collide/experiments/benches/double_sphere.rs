//! The double-sphere tree's `collides_at` at level 3 on the paper's four pairs, against the
//! brute-force exact answer (every triangle pair plus containment) and the GJK reference of
//! [`cga_collide::collider::convex`], on the same random placements.
//!
//! `cargo bench -p cga-experiments --bench double_sphere -- --warm-up-time 1 --measurement-time 3`
//!
//! The second group times `DoubleSphereTree::build` at level 3 for the five solids.
//!
//! Each iteration runs a fixed batch of placements (`N` for the trees and GJK, `N_BRUTE` for the
//! brute force): divide the reported time by the batch size (the throughput line gives
//! queries per second). Placements: the experiment's (`experiment::placement`, seed 2009): both
//! centres uniform in an experiment sphere of radius 2, both orientations uniform (Arvo).

use std::hint::black_box;

use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
use cga_collide::nalgebra::{Isometry3, Point3};
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::testing::convex::ConvexMeshRef;
use cga_collide::{Intersects, Triangle};
use cga_experiments::experiment::placement;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

const N: usize = 1000;
const N_BRUTE: usize = 50;

fn placed(p: &ConvexPolyhedron, pose: &Isometry3<f64>) -> Vec<Point3<f64>> {
    p.vertices().iter().map(|v| pose * v).collect()
}

fn brute(
    a: &ConvexPolyhedron,
    pa: &[Point3<f64>],
    b: &ConvexPolyhedron,
    pb: &[Point3<f64>],
) -> bool {
    let tris = |p: &ConvexPolyhedron, v: &[Point3<f64>]| -> Vec<Triangle> {
        p.triangles()
            .iter()
            .map(|t| Triangle::new(v[t[0] as usize], v[t[1] as usize], v[t[2] as usize]).unwrap())
            .collect()
    };
    let (ta, tb) = (tris(a, pa), tris(b, pb));
    ta.iter().any(|x| tb.iter().any(|y| x.intersects(y)))
        || ConvexMeshRef::new(pa, a.triangles())
            .unwrap()
            .collides_solid(&ConvexMeshRef::new(pb, b.triangles()).unwrap())
            .intersect
}

fn bench(c: &mut Criterion) {
    let pairs = [
        ("truncated_octahedron", "diamond"),
        ("truncated_octahedron", "rh"),
        ("octahedron", "diamond"),
        ("cube", "cube"),
    ];
    let mut group = c.benchmark_group("double_sphere_level3");
    for (na, nb) in pairs {
        let (a, b) = (
            ConvexPolyhedron::by_name(na).unwrap(),
            ConvexPolyhedron::by_name(nb).unwrap(),
        );
        let poses: Vec<(Isometry3<f64>, Isometry3<f64>)> =
            (0..N as u64).map(|i| placement(2009, i, 2.0)).collect();
        let name = format!("{na}-{nb}");
        group.throughput(Throughput::Elements(N as u64));
        for kind in [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev] {
            let (ta, tb) = (
                DoubleSphereTree::build(&a, 3, kind).unwrap(),
                DoubleSphereTree::build(&b, 3, kind).unwrap(),
            );
            group.bench_function(BenchmarkId::new(format!("tree_{kind:?}"), &name), |bench| {
                bench.iter(|| {
                    poses
                        .iter()
                        .filter(|(pa, pb)| ta.collides_at(pa, &tb, pb).collides)
                        .count()
                })
            });
        }
        group.bench_function(BenchmarkId::new("gjk_reference", &name), |bench| {
            bench.iter(|| {
                poses
                    .iter()
                    .filter(|(pa, pb)| {
                        let (va, vb) = (placed(&a, pa), placed(&b, pb));
                        ConvexMeshRef::new(&va, a.triangles())
                            .unwrap()
                            .collides_solid(&ConvexMeshRef::new(&vb, b.triangles()).unwrap())
                            .intersect
                    })
                    .count()
            })
        });
        group.throughput(Throughput::Elements(N_BRUTE as u64));
        group.bench_function(BenchmarkId::new("brute_force", &name), |bench| {
            bench.iter(|| {
                poses[..N_BRUTE]
                    .iter()
                    .filter(|(pa, pb)| brute(&a, &placed(&a, pa), &b, &placed(&b, pb)))
                    .count()
            })
        });
        black_box(&poses);
    }
    group.finish();

    // Build time of the level-3 trees.
    let mut group = c.benchmark_group("double_sphere_build_level3");
    for name in ConvexPolyhedron::NAMES {
        let p = ConvexPolyhedron::by_name(name).unwrap();
        for kind in [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev] {
            group.bench_function(BenchmarkId::new(format!("{kind:?}"), name), |bench| {
                bench.iter(|| DoubleSphereTree::build(black_box(&p), 3, kind).unwrap())
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);

//! Hierarchy build time and size, and query times, each against its baseline in the same run:
//! SAH vs median build, refit vs rebuild, bvh vs brute queries.
//!
//! `cargo bench -p cga-collide --bench bvh -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use cga_collide::bounding::{BuildStrategy, Bvh};
use cga_collide::collider::{Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::{Segment, Sphere};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{Isometry3, Point3};

mod common;
use common::{parry_collides, parry_mesh, parry_pairs, parry_pose};

/// bunny00 × armadillo, both `--unit`, armadillo translated by (0.3, 0.05, 0).
fn placement() -> (Collider, Collider) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let b = Collider::new(TriMesh::armadillo().unit())
        .placed(&Isometry3::translation(0.3, 0.05, 0.0))
        .unwrap();
    (a, b)
}

fn build(c: &mut Criterion) {
    let mut g = c.benchmark_group("bvh_build");
    g.sample_size(10);
    for (name, mesh) in [
        ("bunny00", TriMesh::bunny00()),
        ("armadillo", TriMesh::armadillo()),
    ] {
        let (v, t) = (mesh.vertices(), mesh.triangles());
        for s in [BuildStrategy::Sah, BuildStrategy::Median] {
            let bvh = Bvh::build_with(v, t, s);
            eprintln!(
                "{name} {s:?}: {} nodes, {:.1} bytes/triangle",
                bvh.nodes().len(),
                bvh.heap_bytes() as f64 / t.len() as f64
            );
            g.bench_with_input(BenchmarkId::new(format!("{s:?}"), name), &(), |bch, _| {
                bch.iter(|| Bvh::build_with(black_box(v), black_box(t), s))
            });
        }
        let mut bvh = Bvh::build(v, t);
        g.bench_with_input(BenchmarkId::new("refit", name), &(), |bch, _| {
            bch.iter(|| bvh.refit(black_box(v), black_box(t)))
        });
    }
    g.finish();
}

fn mesh_mesh(c: &mut Criterion) {
    let (a, b) = placement();
    let median_a = Collider::with_strategy(a.mesh().clone(), BuildStrategy::Median);
    let median_b = Collider::with_strategy(b.mesh().clone(), BuildStrategy::Median);
    eprintln!(
        "bunny00 x armadillo: {} intersecting pairs, {} box-overlap candidates",
        a.intersecting_pairs(&b).len(),
        a.box_pairs_bvh(&b).len()
    );
    // parry3d (latest release) the way its users call it: both meshes in their own frame,
    // B's pose relative to A.
    let (pa, pb) = (
        parry_mesh(a.mesh()),
        parry_mesh(&TriMesh::armadillo().unit()),
    );
    let pos12 = parry_pose(&Isometry3::translation(0.3, 0.05, 0.0));
    eprintln!("parry3d pairs: {}", parry_pairs(&pa, &pb, &pos12));
    let mut g = c.benchmark_group("bunny00_x_armadillo");
    g.bench_function("parry3d_all_pairs", |bch| {
        bch.iter(|| parry_pairs(&pa, &pb, &pos12))
    });
    g.bench_function("parry3d_first_hit", |bch| {
        bch.iter(|| parry_collides(&pa, &pb, &pos12))
    });
    g.sample_size(10);
    g.bench_function("all_pairs_bvh_sah", |bch| {
        bch.iter(|| a.intersecting_pairs(&b))
    });
    g.bench_function("all_pairs_bvh_median", |bch| {
        bch.iter(|| median_a.intersecting_pairs(&median_b))
    });
    g.bench_function("box_pairs_only_sah", |bch| bch.iter(|| a.box_pairs_bvh(&b)));
    g.bench_function("first_hit_bvh", |bch| bch.iter(|| a.collides(&b)));
    g.bench_function("place_and_refit", |bch| {
        bch.iter(|| a.placed(black_box(&Isometry3::translation(0.3, 0.05, 0.0))))
    });
    g.finish();
}

fn primitives(c: &mut Criterion) {
    let big = Collider::new(TriMesh::bunny_with_at_least(3_000_000));
    eprintln!("big bunny: {} triangles", big.mesh().num_triangles());
    let (lo, hi) = big.mesh().bounds();
    let mid = nalgebra::center(&lo, &hi);
    let seg = Segment::new(
        Point3::new(lo.x, mid.y, mid.z),
        Point3::new(hi.x, mid.y, mid.z),
    )
    .unwrap();
    let spheres: Vec<Sphere> = (0..16)
        .map(|k| {
            let t = k as f64 / 15.0;
            Sphere::new(lo + (hi - lo) * t, 0.05 * (hi - lo).norm()).unwrap()
        })
        .collect();
    let mut g = c.benchmark_group("bunny_3.76M");
    g.sample_size(10);
    g.bench_function("segment_brute", |bch| {
        bch.iter(|| big.clone().with_mode(Mode::Brute).segment_hits(&seg))
    });
    g.bench_function("segment_bvh", |bch| bch.iter(|| big.segment_hits(&seg)));
    g.bench_function("16_spheres_brute", |bch| {
        bch.iter(|| big.clone().with_mode(Mode::Brute).spheres_hits(&spheres))
    });
    g.bench_function("16_spheres_bvh", |bch| {
        bch.iter(|| big.spheres_hits(&spheres))
    });
    g.finish();
}

criterion_group!(benches, build, mesh_mesh, primitives);
criterion_main!(benches);

//! Queries per new pose, against the peers on the same poses, and batches over the cores.
//!
//! `cargo bench -p cga-collide --bench poses -- --warm-up-time 1 --measurement-time 3`
//!
//! bunny00 × armadillo (both `--unit`), the 200 poses of `benches/poses_near_contact.txt`
//! (armadillo rotated and translated around (0.3, 0.05, 0), about half colliding). Every
//! iteration answers all poses from scratch: our colliders are built once in their own frames
//! and every per-pose cost (pose analysis, traversal, transforming candidate triangles, exact
//! tests) is inside the timed loop. Time per pose = reported time / number of poses
//! (criterion's throughput line gives poses per second).
//!
//! * `ours_*`: `Collider::collides_at` / `intersecting_pairs_at` (exact);
//! * `placed_*`: the old way, `Collider::placed` (transform every vertex, refit) then query,
//!   on the first 10 poses only;
//! * `parry_latest_*`: parry3d-f64 0.31 (its new BVH, glam): `intersection_test` of the two
//!   `TriMesh`es at their poses for the first hit; for all pairs its simultaneous traversal
//!   (`Bvh::leaf_pairs` with B's boxes moved by the relative pose, as parry's own mesh
//!   intersection does) and `intersection_test` per candidate triangle pair (`f64`, not exact);
//! * `batch_*`: 100,000 poses (the 200 repeated) in one `collides_batch` call on a pool of one
//!   or two threads; pairs per pose for 2,000 poses.
//!
//! coal runs on the same poses from Python: `python3 cga-collide/benches/coal_poses.py`.

use std::hint::black_box;

use cga_collide::collider::{Collider, PosePair};
use cga_collide::shape::mesh::TriMesh;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};

mod common;
use common::{parry_collides, parry_mesh, parry_pairs, parry_pose};

/// Rotation about x, then y, then z (degrees), then translation: the CLI's `--rotate`,
/// `--translate` and `--poses` formula.
fn placement(r: [f64; 3], t: [f64; 3]) -> Isometry3<f64> {
    let [ax, ay, az] = r.map(f64::to_radians);
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), az)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), ay)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), ax);
    Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rotation)
}

fn poses() -> Vec<Isometry3<f64>> {
    include_str!("poses_near_contact.txt")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|w| w.parse().unwrap()).collect();
            placement([v[0], v[1], v[2]], [v[3], v[4], v[5]])
        })
        .collect()
}

fn pool(n: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap()
}

fn per_pose(c: &mut Criterion) {
    let (ma, mb) = (TriMesh::bunny00().unit(), TriMesh::armadillo().unit());
    let (a, b) = (Collider::new(ma.clone()), Collider::new(mb.clone()));
    let (pa, pb) = (parry_mesh(&ma), parry_mesh(&mb));
    let poses = poses();
    let id = Isometry3::identity();
    let n = poses.len();
    // Agreement, and how many collide.
    let ours: Vec<usize> = poses
        .iter()
        .map(|p| a.intersecting_pairs_at(&id, &b, p).unwrap().len())
        .collect();
    let theirs: Vec<usize> = poses
        .iter()
        .map(|p| parry_pairs(&pa, &pb, &parry_pose(p)))
        .collect();
    eprintln!(
        "{n} poses: {} colliding, {} pairs in all (ours), {} poses where parry's count differs",
        ours.iter().filter(|&&k| k > 0).count(),
        ours.iter().sum::<usize>(),
        ours.iter().zip(&theirs).filter(|(x, y)| x != y).count()
    );
    let mut g = c.benchmark_group("per_pose");
    g.throughput(Throughput::Elements(n as u64));
    g.bench_function("ours_first_hit", |bch| {
        bch.iter(|| {
            poses
                .iter()
                .filter(|p| a.collides_at(&id, &b, black_box(p)).unwrap())
                .count()
        })
    });
    g.bench_function("parry_latest_first_hit", |bch| {
        bch.iter(|| {
            poses
                .iter()
                .filter(|p| parry_collides(&pa, &pb, &parry_pose(black_box(p))))
                .count()
        })
    });
    g.sample_size(10);
    let one = pool(1);
    g.bench_function("ours_all_pairs_1_thread", |bch| {
        bch.iter(|| {
            one.install(|| {
                poses
                    .iter()
                    .map(|p| {
                        a.intersecting_pairs_at(&id, &b, black_box(p))
                            .unwrap()
                            .len()
                    })
                    .sum::<usize>()
            })
        })
    });
    let two = pool(2);
    g.bench_function("ours_all_pairs_2_threads", |bch| {
        bch.iter(|| {
            two.install(|| {
                poses
                    .iter()
                    .map(|p| {
                        a.intersecting_pairs_at(&id, &b, black_box(p))
                            .unwrap()
                            .len()
                    })
                    .sum::<usize>()
            })
        })
    });
    g.bench_function("parry_latest_all_pairs", |bch| {
        bch.iter(|| {
            poses
                .iter()
                .map(|p| parry_pairs(&pa, &pb, &parry_pose(black_box(p))))
                .sum::<usize>()
        })
    });
    let few = &poses[..10];
    g.throughput(Throughput::Elements(few.len() as u64));
    g.bench_function("placed_then_first_hit", |bch| {
        bch.iter(|| {
            few.iter()
                .filter(|p| {
                    let placed = b.placed(black_box(p)).unwrap();
                    a.collides(&placed)
                })
                .count()
        })
    });
    let placed: Vec<Collider> = few.iter().map(|p| b.placed(p).unwrap()).collect();
    g.bench_function("preplaced_all_pairs_query_only", |bch| {
        bch.iter(|| {
            placed
                .iter()
                .map(|pb| a.intersecting_pairs(black_box(pb)).len())
                .sum::<usize>()
        })
    });
    g.bench_function("ours_all_pairs_1_thread_first_10", |bch| {
        bch.iter(|| {
            one.install(|| {
                few.iter()
                    .map(|p| {
                        a.intersecting_pairs_at(&id, &b, black_box(p))
                            .unwrap()
                            .len()
                    })
                    .sum::<usize>()
            })
        })
    });
    g.finish();
}

fn batches(c: &mut Criterion) {
    let a = Collider::new(TriMesh::bunny00().unit());
    let b = Collider::new(TriMesh::armadillo().unit());
    let base = poses();
    let all: Vec<PosePair> = (0..100_000)
        .map(|k| PosePair::new(Isometry3::identity(), base[k % base.len()]))
        .collect();
    let mut g = c.benchmark_group("batch");
    g.sample_size(10);
    for threads in [1, 2] {
        let p = pool(threads);
        g.throughput(Throughput::Elements(all.len() as u64));
        g.bench_function(format!("first_hit_100k_poses_{threads}_threads"), |bch| {
            bch.iter(|| p.install(|| a.collides_batch(&b, black_box(&all)).unwrap()))
        });
        let some = &all[..2000];
        g.throughput(Throughput::Elements(some.len() as u64));
        g.bench_function(format!("all_pairs_2000_poses_{threads}_threads"), |bch| {
            bch.iter(|| p.install(|| a.intersecting_pairs_batch(&b, black_box(some)).unwrap()))
        });
    }
    g.finish();
}

criterion_group!(benches, per_pose, batches);
criterion_main!(benches);

//! Exact tests against their `f64` baselines, in the same run.
//!
//! `cargo bench -p cga-collide --bench collide -- --warm-up-time 1 --measurement-time 3`
//!
//! Every benchmark runs one test over a fixed batch of `N` pairs per iteration, so the time per
//! test is the reported time divided by `N` (criterion's throughput line gives tests/second).

use std::hint::black_box;

use cga_collide::exact::predicates::{Orient3d, Orient3dCga};
use cga_collide::exact::{ExactKernel, Kernel};
use cga_collide::nalgebra::Isometry3;
use cga_collide::testing::adversarial::{triangle_pairs, SplitMix64};
use cga_collide::testing::baseline;
use cga_collide::{Ball, Intersects, Segment, Sphere, Triangle};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use parry3d_f64::query::intersection_test;
use parry3d_f64::shape::Triangle as ParryTriangle;

const N: usize = 1000;

fn random_triangle(rng: &mut SplitMix64, size: f64) -> Triangle {
    let c = rng.point();
    let mut v = || c + (rng.point().coords * size);
    Triangle::new(v(), v(), v()).expect("finite")
}

/// Random pairs (centres uniform in the cube, edges up to `size`) split by the exact answer.
fn random_pairs(want: bool) -> Vec<(Triangle, Triangle)> {
    let mut rng = SplitMix64(7);
    let mut out = Vec::new();
    while out.len() < N {
        let (a, b) = (
            random_triangle(&mut rng, 0.5),
            random_triangle(&mut rng, 0.5),
        );
        if a.intersects(&b) == want {
            out.push((a, b));
        }
    }
    out
}

/// Random pairs as they come (about 1 in 5 intersect).
fn random_mixed() -> Vec<(Triangle, Triangle)> {
    let mut rng = SplitMix64(11);
    (0..N)
        .map(|_| {
            (
                random_triangle(&mut rng, 0.5),
                random_triangle(&mut rng, 0.5),
            )
        })
        .collect()
}

/// Random pairs with every corner uniform in the cube `[-1, 1]³`, half of them intersecting
/// (about 28% of such pairs do; pairs are drawn until there are `N / 2` of each answer, then
/// shuffled): the mix the comparison with Möller's test is quoted on.
fn random_in_cube() -> Vec<(Triangle, Triangle)> {
    let mut rng = SplitMix64(13);
    let tri = |rng: &mut SplitMix64| {
        Triangle::new(rng.point(), rng.point(), rng.point()).expect("finite")
    };
    let (mut yes, mut no) = (Vec::new(), Vec::new());
    while yes.len() < N / 2 || no.len() < N / 2 {
        let pair = (tri(&mut rng), tri(&mut rng));
        let side = if pair.0.intersects(&pair.1) {
            &mut yes
        } else {
            &mut no
        };
        if side.len() < N / 2 {
            side.push(pair);
        }
    }
    let mut out: Vec<_> = yes.into_iter().chain(no).collect();
    // Fisher–Yates with the same generator: no pattern for the branch predictor to learn.
    for i in (1..out.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        out.swap(i, j);
    }
    out
}

fn parry(t: &Triangle) -> ParryTriangle {
    let [a, b, c] = *t.vertices();
    ParryTriangle::new(a, b, c)
}

fn tri_tri(c: &mut Criterion) {
    let id = Isometry3::identity();
    let sets = [
        ("random_in_cube", random_in_cube()),
        ("random_mixed", random_mixed()),
        ("random_disjoint", random_pairs(false)),
        ("random_intersecting", random_pairs(true)),
        ("near_degenerate", triangle_pairs(99, N)),
    ];
    let mut g = c.benchmark_group("tri_tri");
    g.throughput(Throughput::Elements(N as u64));
    for (name, pairs) in &sets {
        let pp: Vec<(ParryTriangle, ParryTriangle)> =
            pairs.iter().map(|(a, b)| (parry(a), parry(b))).collect();
        g.bench_with_input(BenchmarkId::new("exact", name), pairs, |bch, pairs| {
            bch.iter(|| {
                pairs
                    .iter()
                    .filter(|(a, b)| black_box(a).intersects(black_box(b)))
                    .count()
            })
        });
        g.bench_with_input(BenchmarkId::new("moller_f64", name), pairs, |bch, pairs| {
            bch.iter(|| {
                pairs
                    .iter()
                    .filter(|(a, b)| baseline::moller_tri_tri(black_box(a), black_box(b)))
                    .count()
            })
        });
        g.bench_with_input(BenchmarkId::new("parry3d", name), &pp, |bch, pp| {
            bch.iter(|| {
                pp.iter()
                    .filter(|(a, b)| {
                        intersection_test(&id, black_box(a), &id, black_box(b)).unwrap_or(false)
                    })
                    .count()
            })
        });
    }
    g.finish();
}

fn seg_tri(c: &mut Criterion) {
    let mut rng = SplitMix64(3);
    let pairs: Vec<(Segment, Triangle)> = (0..N)
        .map(|_| {
            let t = random_triangle(&mut rng, 0.8);
            let s = Segment::new(rng.point(), rng.point()).expect("finite");
            (s, t)
        })
        .collect();
    let mut g = c.benchmark_group("seg_tri");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("exact", |b| {
        b.iter(|| {
            pairs
                .iter()
                .filter(|(s, t)| black_box(s).intersects(black_box(t)))
                .count()
        })
    });
    g.bench_function("moller_trumbore_f64", |b| {
        b.iter(|| {
            pairs
                .iter()
                .filter(|(s, t)| {
                    baseline::moller_trumbore_segment_triangle(black_box(s), black_box(t))
                })
                .count()
        })
    });
    g.finish();
}

fn spheres(c: &mut Criterion) {
    let mut rng = SplitMix64(5);
    let tris: Vec<(Triangle, Ball)> = (0..N)
        .map(|_| {
            (
                random_triangle(&mut rng, 0.5),
                Ball::new(rng.point(), rng.float(0.0, 0.6)).expect("finite"),
            )
        })
        .collect();
    let segs: Vec<(Segment, Ball)> = (0..N)
        .map(|_| {
            let s = Segment::new(rng.point(), rng.point()).expect("finite");
            (
                s,
                Ball::new(rng.point(), rng.float(0.0, 0.6)).expect("finite"),
            )
        })
        .collect();
    let sph: Vec<(Sphere, Sphere)> = (0..N)
        .map(|_| {
            let a = Sphere::new(rng.point(), rng.float(0.0, 0.6)).expect("finite");
            (
                a,
                Sphere::new(rng.point(), rng.float(0.0, 0.6)).expect("finite"),
            )
        })
        .collect();
    let mut g = c.benchmark_group("spheres");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("tri_ball/exact", |b| {
        b.iter(|| {
            tris.iter()
                .filter(|(t, s)| black_box(t).intersects(black_box(s)))
                .count()
        })
    });
    g.bench_function("tri_ball/euclid_f64", |b| {
        b.iter(|| {
            tris.iter()
                .filter(|(t, s)| baseline::triangle_ball(black_box(t), black_box(s)))
                .count()
        })
    });
    g.bench_function("tri_sphere/exact", |b| {
        b.iter(|| {
            tris.iter()
                .filter(|(t, s)| black_box(t).intersects(&Sphere::from(*black_box(s))))
                .count()
        })
    });
    g.bench_function("tri_sphere/euclid_f64", |b| {
        b.iter(|| {
            tris.iter()
                .filter(|(t, s)| {
                    baseline::triangle_sphere(black_box(t), &Sphere::from(*black_box(s)))
                })
                .count()
        })
    });
    g.bench_function("seg_ball/exact", |b| {
        b.iter(|| {
            segs.iter()
                .filter(|(t, s)| black_box(t).intersects(black_box(s)))
                .count()
        })
    });
    g.bench_function("seg_ball/euclid_f64", |b| {
        b.iter(|| {
            segs.iter()
                .filter(|(t, s)| baseline::segment_ball(black_box(t), black_box(s)))
                .count()
        })
    });
    g.bench_function("sphere_sphere/exact", |b| {
        b.iter(|| {
            sph.iter()
                .filter(|(t, s)| black_box(t).intersects(black_box(s)))
                .count()
        })
    });
    g.bench_function("sphere_sphere/euclid_f64", |b| {
        b.iter(|| {
            sph.iter()
                .filter(|(t, s)| baseline::sphere_sphere(black_box(t), black_box(s)))
                .count()
        })
    });
    g.finish();
}

/// The literal conformal wedge (generated products) against the expanded determinant, both
/// through the certified-sign kernel.
fn orient(c: &mut Criterion) {
    let mut rng = SplitMix64(9);
    let xs: Vec<[f64; 12]> = (0..N)
        .map(|_| core::array::from_fn(|_| rng.float(-1.0, 1.0)))
        .collect();
    let mut g = c.benchmark_group("orient3d");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("expanded", |b| {
        b.iter(|| {
            xs.iter()
                .filter(|x| ExactKernel::sign::<Orient3d, 12>(black_box(x)).is_gt())
                .count()
        })
    });
    g.bench_function("generated_wedge", |b| {
        b.iter(|| {
            xs.iter()
                .filter(|x| ExactKernel::sign::<Orient3dCga, 12>(black_box(x)).is_gt())
                .count()
        })
    });
    g.finish();
}

criterion_group!(benches, tri_tri, seg_tri, spheres, orient);
criterion_main!(benches);

//! Contact manifolds, ours (`query::contact_manifold`, certified points) against parry's
//! (`parry3d-f64` 0.20, `DefaultQueryDispatcher::contact_manifolds`) on the pairs parry's own
//! benchmarks and demos use: box on box, ball on box, capsule on box, a stack of boxes and two
//! convex hulls, each overlapping a little (as resting contacts do in a physics step), in the
//! same run. Parry starts each call from an empty manifold list and workspace (no warm start),
//! as ours does. Both take the shapes in their own frames with a pose each (ours through
//! `contact_manifold_at`, which places the shapes first: that cost is counted).
//!
//! `cargo bench -p cga-collide --bench manifold_vs_parry -- --warm-up-time 1 --measurement-time 2`

use std::hint::black_box;

use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query;
use cga_collide::shape::{Ball, Capsule, ConvexHull, Cuboid, Shape};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use parry3d_f64::math::{Isometry as PIso, Point as PPoint, Vector as PVector};
use parry3d_f64::query::{
    ContactManifold as PManifold, DefaultQueryDispatcher, PersistentQueryDispatcher,
};
use parry3d_f64::shape as ps;

/// Parry's isometry from ours (same numbers).
fn piso(p: &Isometry3<f64>) -> PIso<f64> {
    let t = p.translation.vector;
    let r = p.rotation.scaled_axis();
    PIso::new(PVector::new(t.x, t.y, t.z), PVector::new(r.x, r.y, r.z))
}

/// Parry's two shapes with their poses.
type ParryPair = (Box<dyn ps::Shape>, PIso<f64>, Box<dyn ps::Shape>, PIso<f64>);

/// Our two shapes with their poses.
type OurPair = (Shape, Isometry3<f64>, Shape, Isometry3<f64>);

/// One pair in both libraries: each library's shapes in their own frames, with their poses.
struct Pair {
    name: &'static str,
    ours: OurPair,
    theirs: ParryPair,
}

fn ours(p: &Pair) -> Option<query::ContactManifold> {
    let (a, pa, b, pb) = &p.ours;
    query::contact_manifold_at(a, pa, b, pb, 0.0).unwrap()
}

fn pair(
    name: &'static str,
    (a, pa, ta): (Shape, Isometry3<f64>, Box<dyn ps::Shape>),
    (b, pb, tb): (Shape, Isometry3<f64>, Box<dyn ps::Shape>),
) -> Pair {
    Pair {
        name,
        ours: (a, pa, b, pb),
        theirs: (ta, piso(&pa), tb, piso(&pb)),
    }
}

fn cuboid(h: [f64; 3]) -> (Shape, Box<dyn ps::Shape>) {
    let ours = Cuboid::axis_aligned(Point3::origin(), Vector3::from(h)).unwrap();
    (
        ours.into(),
        Box::new(ps::Cuboid::new(PVector::new(h[0], h[1], h[2]))),
    )
}

fn hull_points(seed: u32) -> Vec<[f64; 3]> {
    // Twelve points on a unit sphere (a fixed spiral), turned by the seed.
    (0..12)
        .map(|k| {
            let t = f64::from(k) + 0.5;
            let z = 1.0 - 2.0 * t / 12.0;
            let phi = t * 2.399_963 + f64::from(seed);
            let r = (1.0 - z * z).sqrt();
            [r * phi.cos(), r * phi.sin(), z]
        })
        .collect()
}

fn hull(seed: u32) -> (Shape, Box<dyn ps::Shape>) {
    let pts = hull_points(seed);
    let ours = ConvexHull::new(pts.iter().map(|p| Point3::from(*p)).collect()).unwrap();
    let theirs: Vec<PPoint<f64>> = pts.iter().map(|p| PPoint::new(p[0], p[1], p[2])).collect();
    (
        ours.into(),
        Box::new(ps::ConvexPolyhedron::from_convex_hull(&theirs).unwrap()),
    )
}

fn at(x: f64, y: f64, z: f64, turn: Vector3<f64>) -> Isometry3<f64> {
    Isometry3::new(Vector3::new(x, y, z), turn)
}

fn pairs() -> Vec<Pair> {
    let id = Isometry3::identity();
    let (ground, pground) = cuboid([5.0, 5.0, 0.5]);
    let with = |s: (Shape, Box<dyn ps::Shape>), pose: Isometry3<f64>| (s.0, pose, s.1);
    let ball = (
        Shape::from(Ball::new(Point3::origin(), 0.5).unwrap()),
        Box::new(ps::Ball::new(0.5)) as Box<dyn ps::Shape>,
    );
    let capsule = (
        Shape::from(
            Capsule::new(
                Point3::new(-0.5, 0.0, 0.0),
                Point3::new(0.5, 0.0, 0.0),
                0.25,
            )
            .unwrap(),
        ),
        Box::new(ps::Capsule::new(
            PPoint::new(-0.5, 0.0, 0.0),
            PPoint::new(0.5, 0.0, 0.0),
            0.25,
        )) as Box<dyn ps::Shape>,
    );
    let mut out = vec![
        pair(
            "box-box",
            (ground.clone(), id, pground.clone_dyn()),
            with(cuboid([0.5; 3]), at(0.3, -0.2, 0.99, Vector3::z() * 0.3)),
        ),
        pair(
            "ball-box",
            (ground.clone(), id, pground.clone_dyn()),
            with(ball, at(0.3, -0.2, 0.99, Vector3::zeros())),
        ),
        pair(
            "capsule-box",
            (ground.clone(), id, pground.clone_dyn()),
            with(capsule, at(0.3, -0.2, 0.74, Vector3::z() * 0.4)),
        ),
        pair(
            "hull-hull",
            with(hull(0), id),
            with(hull(1), at(1.6, 0.1, 0.2, Vector3::new(0.1, 0.2, 0.3))),
        ),
    ];
    // A stack of four boxes, each sunk 0.01 into the one below and turned a little: the three
    // box-box contacts of the stack, timed together.
    for k in 1..4 {
        let z = |k: i32| f64::from(k) * 0.99;
        let turn = |k: i32| Vector3::z() * 0.1 * f64::from(k);
        out.push(pair(
            "stack",
            with(cuboid([0.5; 3]), at(0.0, 0.0, z(k - 1), turn(k - 1))),
            with(
                cuboid([0.5; 3]),
                at(0.0, 0.01 * f64::from(k), z(k), turn(k)),
            ),
        ));
    }
    out
}

fn bench(c: &mut Criterion) {
    let all = pairs();
    let margin = 0.0;
    let mut group = c.benchmark_group("manifold");
    let names = ["box-box", "ball-box", "capsule-box", "hull-hull", "stack"];
    for name in names {
        let chosen: Vec<&Pair> = all.iter().filter(|p| p.name == name).collect();
        // Both find contacts on every pair (a benchmark of empty answers would say nothing).
        for p in &chosen {
            let m = ours(p).expect("the pair touches");
            let mut pm: Vec<PManifold<(), ()>> = Vec::new();
            let (ta, pa, tb, pb) = &p.theirs;
            DefaultQueryDispatcher
                .contact_manifolds(
                    &pa.inv_mul(pb),
                    ta.as_ref(),
                    tb.as_ref(),
                    margin,
                    &mut pm,
                    &mut None,
                )
                .unwrap();
            let theirs: usize = pm.iter().map(|m| m.points.len()).sum();
            eprintln!(
                "{name}: ours {} points, parry {theirs} points",
                m.points.len()
            );
        }
        group.bench_function(BenchmarkId::new("cga_collide", name), |bch| {
            bch.iter(|| {
                for p in &chosen {
                    black_box(ours(p));
                }
            })
        });
        group.bench_function(BenchmarkId::new("parry3d-f64", name), |bch| {
            let mut manifolds: Vec<PManifold<(), ()>> = Vec::new();
            bch.iter(|| {
                for p in &chosen {
                    let (ta, pa, tb, pb) = &p.theirs;
                    manifolds.clear();
                    let mut workspace = None;
                    DefaultQueryDispatcher
                        .contact_manifolds(
                            &pa.inv_mul(pb),
                            ta.as_ref(),
                            tb.as_ref(),
                            margin,
                            &mut manifolds,
                            &mut workspace,
                        )
                        .unwrap();
                    black_box(&manifolds);
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

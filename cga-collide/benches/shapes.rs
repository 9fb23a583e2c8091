//! The generic primitive queries (`query::intersects` over `Shape`): time per pair test for
//! each pair type of the polytopal engine, on generic pairs (well apart or well overlapping,
//! decided by the floating-point certificates) and on near-contact pairs (exactly touching or
//! one ulp apart, decided by the exact stage).
//!
//! `cargo bench -p cga-collide --bench shapes -- --warm-up-time 1 --measurement-time 2`

use std::hint::black_box;

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::query;
use cga_collide::shape::{Ball, Capsule, ConvexHull, Cuboid, HalfSpace, Shape};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

/// A representative of each kind placed with its lowest point at height `z` (touching the
/// plane `z = 0` at `z = 0`), spanning about one unit.
fn at_height(kind: &str, z: f64) -> Shape {
    match kind {
        "ball" => Ball::new(p(0.1, 0.2, z + 0.5), 0.5).unwrap().into(),
        "capsule" => Capsule::new(p(-0.4, 0.1, z + 0.3), p(0.4, 0.3, z + 0.3), 0.3)
            .unwrap()
            .into(),
        "cuboid" => Cuboid::new(
            p(0.1, -0.1, z + 0.5),
            [
                Vector3::new(0.6, 0.0, 0.0),
                Vector3::new(0.0, 0.4, 0.0),
                Vector3::new(0.0, 0.0, 0.5),
            ],
        )
        .unwrap()
        .into(),
        _ => {
            let mut pts = vec![p(0.0, 0.0, z)];
            for k in 0..11 {
                let t = f64::from(k) * 0.57;
                pts.push(p(
                    0.5 * t.cos(),
                    0.5 * t.sin(),
                    z + 0.2 + 0.07 * f64::from(k),
                ));
            }
            ConvexHull::new(pts).unwrap().into()
        }
    }
}

/// The same kind mirrored below the plane `z = 0`, its highest point at `-z`.
fn below(kind: &str, z: f64) -> Shape {
    match at_height(kind, z) {
        Shape::Ball(b) => Ball::new(p(b.centre().x, b.centre().y, -b.centre().z), b.radius())
            .unwrap()
            .into(),
        Shape::Capsule(c) => Capsule::new(
            p(c.a().x, c.a().y, -c.a().z),
            p(c.b().x, c.b().y, -c.b().z),
            c.radius(),
        )
        .unwrap()
        .into(),
        Shape::Cuboid(c) => {
            Cuboid::new(p(c.centre().x, c.centre().y, -c.centre().z), *c.half_axes())
                .unwrap()
                .into()
        }
        Shape::ConvexHull(h) => {
            ConvexHull::new(h.points().iter().map(|q| p(q.x, q.y, -q.z)).collect())
                .unwrap()
                .into()
        }
        other => other,
    }
}

fn shapes(c: &mut Criterion) {
    let kinds = ["ball", "capsule", "cuboid", "convex", "halfspace"];
    let ground: Shape = HalfSpace::new(p(0.0, 0.0, 0.0), Vector3::z())
        .unwrap()
        .into();
    // Lowest point of the upper shape at `gap` above the plane z = 0, where the lower shape's
    // highest point is (`touching`: both at 0, in contact at a point or near one; one ulp:
    // the smallest subnormal above 0).
    let families = [
        ("generic_apart", 0.3),
        ("generic_overlap", -0.3),
        ("near_contact", 0.0),
        ("one_ulp", 0f64.next_up()),
    ];
    for (family, gap) in families {
        let mut g = c.benchmark_group(format!("intersects_{family}"));
        for (i, ka) in kinds.iter().enumerate() {
            for kb in &kinds[i..] {
                if *ka == "halfspace" {
                    continue;
                }
                let a = if *kb == "halfspace" {
                    at_height(ka, gap)
                } else {
                    below(ka, 0.0)
                };
                let b = if *kb == "halfspace" {
                    ground.clone()
                } else {
                    at_height(kb, gap)
                };
                let expected = query::intersects(&a, &b).unwrap();
                eprintln!("{family} {ka}-{kb}: {expected}");
                g.bench_with_input(
                    BenchmarkId::new(format!("{ka}-{kb}"), family),
                    &(a, b),
                    |bch, (a, b)| {
                        bch.iter(|| query::intersects(black_box(a), black_box(b)).unwrap())
                    },
                );
            }
        }
        g.finish();
    }
}

criterion_group!(benches, shapes);
criterion_main!(benches);

//! Generated products against hand-written straight-line code, in the same run.
//!
//! Each group times one product over a batch of 1024 random operands, both sides behind
//! `#[inline(never)]` functions with the same memory layout, so the only difference is who wrote
//! the arithmetic. The hand-written baselines are checked against the generated results first.
//!
//! Run: `cargo bench -p ga-core --bench products`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ga_core::cga::{Bivector, Multivector, Odd, Quadvector, Rotor, Trivector, Vector};
use ga_core::prelude::*;
use ga_core::reference::{DenseMultivector, Signature};
use std::hint::black_box;

const BATCH: usize = 1024;

/// A small deterministic generator (xorshift) so runs are repeatable.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    fn array<const N: usize>(&mut self) -> [f64; N] {
        core::array::from_fn(|_| self.next())
    }
}

// ---- hand-written straight-line baselines (Cl(4,1), canonical blade order) ----

#[inline(never)]
fn hand_vector_vector(a: &[f64; 5], b: &[f64; 5]) -> [f64; 11] {
    [
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] - a[4] * b[4],
        a[0] * b[1] - a[1] * b[0],
        a[0] * b[2] - a[2] * b[0],
        a[0] * b[3] - a[3] * b[0],
        a[0] * b[4] - a[4] * b[0],
        a[1] * b[2] - a[2] * b[1],
        a[1] * b[3] - a[3] * b[1],
        a[1] * b[4] - a[4] * b[1],
        a[2] * b[3] - a[3] * b[2],
        a[2] * b[4] - a[4] * b[2],
        a[3] * b[4] - a[4] * b[3],
    ]
}

#[inline(never)]
fn hand_bivector_vector(a: &[f64; 10], b: &[f64; 5]) -> [f64; 15] {
    [
        a[0] * b[1] + a[1] * b[2] + a[2] * b[3] - a[3] * b[4],
        -(a[0] * b[0]) + a[4] * b[2] + a[5] * b[3] - a[6] * b[4],
        -(a[1] * b[0]) - a[4] * b[1] + a[7] * b[3] - a[8] * b[4],
        -(a[2] * b[0]) - a[5] * b[1] - a[7] * b[2] - a[9] * b[4],
        -(a[3] * b[0]) - a[6] * b[1] - a[8] * b[2] - a[9] * b[3],
        a[0] * b[2] - a[1] * b[1] + a[4] * b[0],
        a[0] * b[3] - a[2] * b[1] + a[5] * b[0],
        a[0] * b[4] - a[3] * b[1] + a[6] * b[0],
        a[1] * b[3] - a[2] * b[2] + a[7] * b[0],
        a[1] * b[4] - a[3] * b[2] + a[8] * b[0],
        a[2] * b[4] - a[3] * b[3] + a[9] * b[0],
        a[4] * b[3] - a[5] * b[2] + a[7] * b[1],
        a[4] * b[4] - a[6] * b[2] + a[8] * b[1],
        a[5] * b[4] - a[6] * b[3] + a[9] * b[1],
        a[7] * b[4] - a[8] * b[3] + a[9] * b[2],
    ]
}

#[inline(never)]
fn hand_trivector_wedge_vector(a: &[f64; 10], b: &[f64; 5]) -> [f64; 5] {
    [
        a[0] * b[3] - a[1] * b[2] + a[3] * b[1] - a[6] * b[0],
        a[0] * b[4] - a[2] * b[2] + a[4] * b[1] - a[7] * b[0],
        a[1] * b[4] - a[2] * b[3] + a[5] * b[1] - a[8] * b[0],
        a[3] * b[4] - a[4] * b[3] + a[5] * b[2] - a[9] * b[0],
        a[6] * b[4] - a[7] * b[3] + a[8] * b[2] - a[9] * b[1],
    ]
}

#[inline(never)]
fn hand_rotor_sandwich(r: &[f64; 11], x: &[f64; 5]) -> [f64; 5] {
    let p0 = r[0] * x[0] + r[1] * x[1] + r[2] * x[2] + r[3] * x[3] - r[4] * x[4];
    let p1 = r[0] * x[1] - r[1] * x[0] + r[5] * x[2] + r[6] * x[3] - r[7] * x[4];
    let p2 = r[0] * x[2] - r[2] * x[0] - r[5] * x[1] + r[8] * x[3] - r[9] * x[4];
    let p3 = r[0] * x[3] - r[3] * x[0] - r[6] * x[1] - r[8] * x[2] - r[10] * x[4];
    let p4 = r[0] * x[4] - r[4] * x[0] - r[7] * x[1] - r[9] * x[2] - r[10] * x[3];
    let p5 = r[1] * x[2] - r[2] * x[1] + r[5] * x[0];
    let p6 = r[1] * x[3] - r[3] * x[1] + r[6] * x[0];
    let p7 = r[1] * x[4] - r[4] * x[1] + r[7] * x[0];
    let p8 = r[2] * x[3] - r[3] * x[2] + r[8] * x[0];
    let p9 = r[2] * x[4] - r[4] * x[2] + r[9] * x[0];
    let p10 = r[3] * x[4] - r[4] * x[3] + r[10] * x[0];
    let p11 = r[5] * x[3] - r[6] * x[2] + r[8] * x[1];
    let p12 = r[5] * x[4] - r[7] * x[2] + r[9] * x[1];
    let p13 = r[6] * x[4] - r[7] * x[3] + r[10] * x[1];
    let p14 = r[8] * x[4] - r[9] * x[3] + r[10] * x[2];
    [
        p0 * r[0] + p1 * r[1] + p2 * r[2] + p3 * r[3] - p4 * r[4] + p5 * r[5] + p6 * r[6]
            - p7 * r[7]
            + p8 * r[8]
            - p9 * r[9]
            - p10 * r[10],
        -(p0 * r[1]) + p1 * r[0] + p2 * r[5] + p3 * r[6] - p4 * r[7] - p5 * r[2] - p6 * r[3]
            + p7 * r[4]
            + p11 * r[8]
            - p12 * r[9]
            - p13 * r[10],
        -(p0 * r[2]) - p1 * r[5] + p2 * r[0] + p3 * r[8] - p4 * r[9] + p5 * r[1] - p8 * r[3]
            + p9 * r[4]
            - p11 * r[6]
            + p12 * r[7]
            - p14 * r[10],
        -(p0 * r[3]) - p1 * r[6] - p2 * r[8] + p3 * r[0] - p4 * r[10]
            + p6 * r[1]
            + p8 * r[2]
            + p10 * r[4]
            + p11 * r[5]
            + p13 * r[7]
            + p14 * r[9],
        -(p0 * r[4]) - p1 * r[7] - p2 * r[9] - p3 * r[10]
            + p4 * r[0]
            + p7 * r[1]
            + p9 * r[2]
            + p10 * r[3]
            + p12 * r[5]
            + p13 * r[6]
            + p14 * r[8],
    ]
}

// ---- the same products through the generated types ----

/// Cl(4,1) declared with a grades-1-and-3 type, so that bivector × vector lands in a type of
/// exactly the 15 blades it can reach (`ga_core::cga` maps it to `Odd`, which has a 16th,
/// grade-5 slot that the product leaves zero).
mod cga13 {
    ga_macros::algebra! {
        name: cga13,
        signature: [+1, +1, +1, +1, -1],
        types: { Vector: grade 1, Bivector: grade 2, Odd13: grades 1 3 },
    }
}

#[inline(never)]
fn gen_bivector_vector_13(a: &cga13::Bivector<f64>, b: &cga13::Vector<f64>) -> cga13::Odd13<f64> {
    a * b
}

#[inline(never)]
fn gen_vector_vector(a: &Vector<f64>, b: &Vector<f64>) -> Rotor<f64> {
    a * b
}
#[inline(never)]
fn gen_bivector_vector(a: &Bivector<f64>, b: &Vector<f64>) -> Odd<f64> {
    a * b
}
#[inline(never)]
fn gen_trivector_wedge_vector(a: &Trivector<f64>, b: &Vector<f64>) -> Quadvector<f64> {
    a ^ b
}
#[inline(never)]
fn gen_rotor_sandwich(r: &Rotor<f64>, x: &Vector<f64>) -> Vector<f64> {
    r.sandwich_unit(x)
}
#[inline(never)]
fn gen_dense_geometric(a: &Multivector<f64>, b: &Multivector<f64>) -> Multivector<f64> {
    a * b
}

fn vector(c: [f64; 5]) -> Vector<f64> {
    Vector::new(c[0], c[1], c[2], c[3], c[4])
}
fn bivector(c: [f64; 10]) -> Bivector<f64> {
    Bivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9])
}
fn trivector(c: [f64; 10]) -> Trivector<f64> {
    Trivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9])
}
fn rotor(c: [f64; 11]) -> Rotor<f64> {
    Rotor::new(
        c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10],
    )
}

/// Times `generated` and `hand` on the same batch, after checking they agree.
fn compare<GA, GB, GO, HO, const NA: usize, const NB: usize>(
    c: &mut Criterion,
    name: &str,
    make_a: impl Fn([f64; NA]) -> GA,
    make_b: impl Fn([f64; NB]) -> GB,
    generated: impl Fn(&GA, &GB) -> GO,
    hand: impl Fn(&[f64; NA], &[f64; NB]) -> HO,
    same: impl Fn(&GO, &HO) -> bool,
) {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let raw: Vec<([f64; NA], [f64; NB])> = (0..BATCH).map(|_| (rng.array(), rng.array())).collect();
    let typed: Vec<(GA, GB)> = raw.iter().map(|(a, b)| (make_a(*a), make_b(*b))).collect();
    for ((a, b), (ga, gb)) in raw.iter().zip(&typed) {
        assert!(
            same(&generated(ga, gb), &hand(a, b)),
            "{name}: baseline disagrees"
        );
    }
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function(BenchmarkId::new("generated", BATCH), |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&typed) {
                black_box(generated(a, b));
            }
        })
    });
    group.bench_function(BenchmarkId::new("hand-written", BATCH), |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&raw) {
                black_box(hand(a, b));
            }
        })
    });
    group.finish();
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + x.abs()))
}

fn products(c: &mut Criterion) {
    compare::<_, _, _, _, 5, 5>(
        c,
        "vector*vector",
        vector,
        vector,
        gen_vector_vector,
        hand_vector_vector,
        |g, h| {
            close(
                &Multivector::from(*g).coefficients()[..16]
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| *i == 0 || (6..16).contains(i))
                    .map(|(_, x)| *x)
                    .collect::<Vec<_>>(),
                h,
            )
        },
    );
    compare::<_, _, _, _, 10, 5>(
        c,
        "bivector*vector",
        bivector,
        vector,
        gen_bivector_vector,
        hand_bivector_vector,
        |g, h| {
            close(
                &Multivector::from(*g).coefficients()[1..26]
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| *i < 5 || *i >= 15)
                    .map(|(_, x)| *x)
                    .collect::<Vec<_>>(),
                h,
            )
        },
    );
    compare::<_, _, _, _, 10, 5>(
        c,
        "bivector*vector into grades 1 3",
        |c| cga13::Bivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]),
        |c| cga13::Vector::new(c[0], c[1], c[2], c[3], c[4]),
        gen_bivector_vector_13,
        hand_bivector_vector,
        |g, h| {
            close(
                &cga13::Multivector::from(*g).coefficients()[1..26]
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| *i < 5 || *i >= 15)
                    .map(|(_, x)| *x)
                    .collect::<Vec<_>>(),
                h,
            )
        },
    );
    compare::<_, _, _, _, 10, 5>(
        c,
        "trivector^vector",
        trivector,
        vector,
        gen_trivector_wedge_vector,
        hand_trivector_wedge_vector,
        |g, h| close(&Multivector::from(*g).coefficients()[26..31], h),
    );
    compare::<_, _, _, _, 11, 5>(
        c,
        "rotor sandwich of a point",
        rotor,
        vector,
        gen_rotor_sandwich,
        hand_rotor_sandwich,
        |g, h| close(&Multivector::from(*g).coefficients()[1..6], h),
    );
}

fn dense(c: &mut Criterion) {
    let mut rng = Rng(7);
    let pairs: Vec<(Vector<f64>, Vector<f64>)> = (0..BATCH)
        .map(|_| (vector(rng.array()), vector(rng.array())))
        .collect();
    let dense_pairs: Vec<(Multivector<f64>, Multivector<f64>)> = pairs
        .iter()
        .map(|(a, b)| ((*a).into(), (*b).into()))
        .collect();
    let signature = Signature::new(&[1, 1, 1, 1, -1]).expect("Cl(4,1)");
    let reference_pairs: Vec<(DenseMultivector<f64>, DenseMultivector<f64>)> = dense_pairs
        .iter()
        .map(|(a, b)| {
            let make = |m: &Multivector<f64>| {
                DenseMultivector::from_canonical(&signature, m.coefficients().to_vec())
                    .expect("32 coefficients")
            };
            (make(a), make(b))
        })
        .collect();
    let mut group = c.benchmark_group("vector*vector dense contrast");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("generated sparse", |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&pairs) {
                black_box(gen_vector_vector(a, b));
            }
        })
    });
    group.bench_function("generated dense 32x32", |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&dense_pairs) {
                black_box(gen_dense_geometric(a, b));
            }
        })
    });
    group.bench_function("dense reference (run-time bitmask)", |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&reference_pairs) {
                black_box(a.geometric(b));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, products, dense);
criterion_main!(benches);

//! Generated products against hand-written straight-line code, in the same run.
//!
//! Each group times one product over a batch of `BATCH` (1024) operand pairs: one call of an
//! `#[inline(never)]` batch function per iteration, with the product inlined into its loop and
//! each result written into an output slice (`benches/kernels/mod.rs`, shared with the
//! callgrind instruction counts of `examples/callgrind_products.rs`). Generated and hand-written
//! code read and write the same memory layout; the baselines are checked against the generated
//! results first.
//!
//! Run: `cargo bench -p ga-core --bench products -- --warm-up-time 1 --measurement-time 3`.

mod kernels;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ga_core::cga::{Multivector, Vector};
use ga_core::reference::{DenseMultivector, Signature};
use kernels::{
    call_gen_dense, call_gen_vv, kernels, run_all_and_check, Data, Out, Rng, Side, BATCH,
};
use std::hint::black_box;

fn products(c: &mut Criterion) {
    let data = Data::new();
    run_all_and_check(&data);
    let mut out = Out::new();
    let all = kernels();
    let mut products: Vec<&str> = all.iter().map(|k| k.product).collect();
    products.dedup();
    for product in products {
        let mut group = c.benchmark_group(product);
        group.throughput(Throughput::Elements(BATCH as u64));
        for side in [Side::Generated, Side::Hand] {
            let k = all
                .iter()
                .find(|k| k.product == product && k.side == side)
                .expect("both sides of every product");
            let label = match side {
                Side::Generated => "generated",
                Side::Hand => "hand-written",
            };
            group.bench_function(BenchmarkId::new(label, BATCH), |bench| {
                bench.iter(|| {
                    (k.run_batch)(black_box(&data), black_box(&mut out));
                })
            });
        }
        group.finish();
    }
    black_box(&out);
}

fn vector(c: [f64; 5]) -> Vector<f64> {
    Vector::new(c[0], c[1], c[2], c[3], c[4])
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
                black_box(call_gen_vv(a, b));
            }
        })
    });
    group.bench_function("generated dense 32x32", |bench| {
        bench.iter(|| {
            for (a, b) in black_box(&dense_pairs) {
                black_box(call_gen_dense(a, b));
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

//! Products per second on SIMD lanes against scalar code, in the same run.
//!
//! Every group runs one generated product over 1024 operand pairs: scalar `f64` (1024 calls),
//! `F64x4` (256 calls, 4 products each), scalar `f32` (1024 calls) and `F32x8` (128 calls, 8
//! products each). Criterion's throughput is in products (elements) per second. The same
//! generated code runs in all four; only the scalar type differs. Before timing, lane `i` of
//! every lane result is checked against the scalar result.
//!
//! Run: `cargo bench -p ga-core --bench lanes -- --warm-up-time 1 --measurement-time 3`
//! (add `RUSTFLAGS="-C target-cpu=native"` to let `wide` use AVX registers).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use ga_core::cga::{Even, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::lanes::{F32x8, F64x4};
use ga_core::scalar::Ring;
use std::hint::black_box;

const N: usize = 1024;

/// Packs `items[i]` into lane `i` of every coefficient.
macro_rules! pack {
    ($ty:ident, $lane:ty, $items:expr) => {{
        let items = $items;
        $ty::from_coefficients(core::array::from_fn(|k| {
            <$lane>::from_fn(|i| items[i].coefficients()[k])
        }))
    }};
}

/// A small deterministic generator (xorshift), values in [-1, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

struct Data<T> {
    a: Vec<Vector<T>>,
    b: Vec<Vector<T>>,
    r: Vec<Rotor<T>>,
    e: Vec<Even<T>>,
}

fn data64() -> Data<f64> {
    let mut rng = Rng(0x9e3779b97f4a7c15);
    let mut v = || Vector::from_coefficients(core::array::from_fn(|_| rng.next()));
    let a = (0..N).map(|_| v()).collect();
    let b = (0..N).map(|_| v()).collect();
    let mut rng = Rng(12345);
    let r = (0..N)
        .map(|_| Rotor::from_coefficients(core::array::from_fn(|_| rng.next())))
        .collect();
    let e = (0..N)
        .map(|_| Even::from_coefficients(core::array::from_fn(|_| rng.next())))
        .collect();
    Data { a, b, r, e }
}

fn to32(d: &Data<f64>) -> Data<f32> {
    let f32_of = |x: f64| x as f32;
    Data {
        a: d.a.iter().map(|x| x.map(f32_of)).collect(),
        b: d.b.iter().map(|x| x.map(f32_of)).collect(),
        r: d.r.iter().map(|x| x.map(f32_of)).collect(),
        e: d.e.iter().map(|x| x.map(f32_of)).collect(),
    }
}

/// Packs `LANES` consecutive elements per lane value.
macro_rules! packed {
    ($lane:ty, $width:literal, $d:expr) => {{
        let d = $d;
        Data::<$lane> {
            a: d.a
                .chunks($width)
                .map(|c| pack!(Vector, $lane, c))
                .collect(),
            b: d.b
                .chunks($width)
                .map(|c| pack!(Vector, $lane, c))
                .collect(),
            r: d.r.chunks($width).map(|c| pack!(Rotor, $lane, c)).collect(),
            e: d.e.chunks($width).map(|c| pack!(Even, $lane, c)).collect(),
        }
    }};
}

#[inline(never)]
fn vv<T: Ring + Copy>(d: &Data<T>, out: &mut [Rotor<T>]) {
    for ((o, a), b) in out.iter_mut().zip(&d.a).zip(&d.b) {
        *o = *a * *b;
    }
}

#[inline(never)]
fn sandwich<T: Ring + Copy>(d: &Data<T>, out: &mut [Vector<T>]) {
    for ((o, r), a) in out.iter_mut().zip(&d.r).zip(&d.a) {
        *o = r.sandwich_unit(a);
    }
}

#[inline(never)]
fn ee<T: Ring + Copy>(d: &Data<T>, out: &mut [Even<T>]) {
    for ((o, x), y) in out.iter_mut().zip(&d.e).zip(d.e.iter().rev()) {
        *o = *x * *y;
    }
}

/// Lane `i` of packed result `k` is scalar result `k * width + i`.
fn check(d64: &Data<f64>, l64: &Data<F64x4>, d32: &Data<f32>, l32: &Data<F32x8>) {
    let mut s = vec![Rotor::zero(); N];
    let mut l = vec![Rotor::zero(); N / 4];
    vv(d64, &mut s);
    vv(l64, &mut l);
    for (k, x) in s.iter().enumerate() {
        assert_eq!(x.e12, l[k / 4].e12.lanes()[k % 4]);
    }
    let mut s = vec![Vector::zero(); N];
    let mut l = vec![Vector::zero(); N / 4];
    sandwich(d64, &mut s);
    sandwich(l64, &mut l);
    for (k, x) in s.iter().enumerate() {
        assert_eq!(x.e4, l[k / 4].e4.lanes()[k % 4]);
    }
    let mut s = vec![Even::zero(); N];
    let mut l = vec![Even::zero(); N / 8];
    ee(d32, &mut s);
    // ee pairs x with the reversed sequence; the packed reversal is per chunk, so compare only
    // the squares-free products: multiply in the same order by packing the reversed data.
    let rev = Data {
        a: vec![],
        b: vec![],
        r: vec![],
        e: d32.e.iter().rev().copied().collect::<Vec<_>>(),
    };
    let lrev: Vec<Even<F32x8>> = rev.e.chunks(8).map(|c| pack!(Even, F32x8, c)).collect();
    for (k, (x, y)) in l32.e.iter().zip(&lrev).enumerate() {
        l[k] = *x * *y;
    }
    for (k, x) in s.iter().enumerate() {
        assert_eq!(x.e1234, l[k / 8].e1234.lanes()[k % 8]);
    }
}

fn bench_lanes(c: &mut Criterion) {
    let d64 = data64();
    let d32 = to32(&d64);
    let l64 = packed!(F64x4, 4, &d64);
    let l32 = packed!(F32x8, 8, &d32);
    check(&d64, &l64, &d32, &l32);

    macro_rules! group {
        ($name:literal, $kernel:ident, $zero:expr) => {{
            let mut g = c.benchmark_group($name);
            g.throughput(Throughput::Elements(N as u64));
            let mut o64 = vec![$zero; N];
            g.bench_function(BenchmarkId::new("f64", N), |b| {
                b.iter(|| $kernel(black_box(&d64), black_box(&mut o64)))
            });
            let mut ol64 = vec![$zero; N / 4];
            g.bench_function(BenchmarkId::new("F64x4", N), |b| {
                b.iter(|| $kernel(black_box(&l64), black_box(&mut ol64)))
            });
            let mut o32 = vec![$zero; N];
            g.bench_function(BenchmarkId::new("f32", N), |b| {
                b.iter(|| $kernel(black_box(&d32), black_box(&mut o32)))
            });
            let mut ol32 = vec![$zero; N / 8];
            g.bench_function(BenchmarkId::new("F32x8", N), |b| {
                b.iter(|| $kernel(black_box(&l32), black_box(&mut ol32)))
            });
            g.finish();
        }};
    }
    group!("vector * vector (25 mul)", vv, Rotor::zero());
    group!(
        "rotor sandwich of a vector (110 mul)",
        sandwich,
        Vector::zero()
    );
    group!("even * even (256 mul)", ee, Even::zero());
}

criterion_group!(benches, bench_lanes);
criterion_main!(benches);

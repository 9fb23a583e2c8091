//! The products compared by the benchmarks, shared by `benches/products.rs` (criterion, wall
//! time) and `examples/callgrind_products.rs` (callgrind, instruction counts).
//!
//! For each listed Cl(4,1) product there is a generated and a hand-written straight-line version,
//! each in two forms, all `#[inline(never)]`:
//! * `call_*`: one product per call (operands by reference, result by value), the function
//!   whose instructions callgrind counts per product;
//! * `batch_*`: the product inlined into a loop over a batch of operands, writing each result
//!   into an output slice (the form criterion times).
//!
//! Generated and hand-written versions read and write the same memory layout (a generated type
//! is a struct of its `f64` coefficients in canonical blade order; the hand-written code uses
//! arrays in the same order), so the only difference is who wrote the arithmetic.
#![allow(dead_code)] // each of the two users calls a different subset

use ga_core::cga::{Bivector, Multivector, Odd, Quadvector, Rotor, Trivector, Vector};
use ga_core::prelude::*;

/// Operands per batch.
pub const BATCH: usize = 1024;

/// Hand-written straight-line baselines (Cl(4,1), canonical blade order).
pub mod hand {
    #[inline(always)]
    pub fn vector_vector(a: &[f64; 5], b: &[f64; 5]) -> [f64; 11] {
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

    #[inline(always)]
    pub fn bivector_vector(a: &[f64; 10], b: &[f64; 5]) -> [f64; 15] {
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

    #[inline(always)]
    pub fn trivector_wedge_vector(a: &[f64; 10], b: &[f64; 5]) -> [f64; 5] {
        [
            a[0] * b[3] - a[1] * b[2] + a[3] * b[1] - a[6] * b[0],
            a[0] * b[4] - a[2] * b[2] + a[4] * b[1] - a[7] * b[0],
            a[1] * b[4] - a[2] * b[3] + a[5] * b[1] - a[8] * b[0],
            a[3] * b[4] - a[4] * b[3] + a[5] * b[2] - a[9] * b[0],
            a[6] * b[4] - a[7] * b[3] + a[8] * b[2] - a[9] * b[1],
        ]
    }

    #[inline(always)]
    pub fn rotor_sandwich(r: &[f64; 11], x: &[f64; 5]) -> [f64; 5] {
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
}

/// Cl(4,1) declared with a grades-1-and-3 type, so that bivector × vector lands in a type of
/// exactly the 15 blades it can reach (`ga_core::cga` maps it to `Odd`, which has a 16th,
/// grade-5 slot that the product leaves zero).
pub mod cga13 {
    ga_macros::algebra! {
        name: cga13,
        signature: [+1, +1, +1, +1, -1],
        types: { Vector: grade 1, Bivector: grade 2, Odd13: grades 1 3 },
    }
}

/// A small deterministic generator (xorshift) so runs are repeatable.
pub struct Rng(pub u64);

impl Rng {
    /// A value in `[-1, 1)`.
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    /// `N` values in `[-1, 1)`.
    pub fn array<const N: usize>(&mut self) -> [f64; N] {
        core::array::from_fn(|_| self.next())
    }
}

/// One batch of operands, as raw arrays (hand-written side) and as generated types.
pub struct Data {
    pub v1: Vec<[f64; 5]>,
    pub v2: Vec<[f64; 5]>,
    pub b: Vec<[f64; 10]>,
    pub t: Vec<[f64; 10]>,
    pub r: Vec<[f64; 11]>,
    pub gv1: Vec<Vector<f64>>,
    pub gv2: Vec<Vector<f64>>,
    pub gb: Vec<Bivector<f64>>,
    pub gt: Vec<Trivector<f64>>,
    pub gr: Vec<Rotor<f64>>,
    pub gb13: Vec<cga13::Bivector<f64>>,
    pub gv13: Vec<cga13::Vector<f64>>,
}

impl Data {
    /// `BATCH` random operands of each kind (fixed seed).
    pub fn new() -> Data {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let v1: Vec<[f64; 5]> = (0..BATCH).map(|_| rng.array()).collect();
        let v2: Vec<[f64; 5]> = (0..BATCH).map(|_| rng.array()).collect();
        let b: Vec<[f64; 10]> = (0..BATCH).map(|_| rng.array()).collect();
        let t: Vec<[f64; 10]> = (0..BATCH).map(|_| rng.array()).collect();
        let r: Vec<[f64; 11]> = (0..BATCH).map(|_| rng.array()).collect();
        let vector = |c: &[f64; 5]| Vector::new(c[0], c[1], c[2], c[3], c[4]);
        let gv1 = v1.iter().map(vector).collect();
        let gv2 = v2.iter().map(vector).collect();
        let gb = b
            .iter()
            .map(|c| Bivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]))
            .collect();
        let gt = t
            .iter()
            .map(|c| Trivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]))
            .collect();
        let gr = r
            .iter()
            .map(|c| {
                Rotor::new(
                    c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10],
                )
            })
            .collect();
        let gb13 = b
            .iter()
            .map(|c| {
                cga13::Bivector::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9])
            })
            .collect();
        let gv13 = v2
            .iter()
            .map(|c| cga13::Vector::new(c[0], c[1], c[2], c[3], c[4]))
            .collect();
        Data {
            v1,
            v2,
            b,
            t,
            r,
            gv1,
            gv2,
            gb,
            gt,
            gr,
            gb13,
            gv13,
        }
    }
}

/// Output slices for every product, generated and hand-written.
pub struct Out {
    pub rotor: Vec<Rotor<f64>>,
    pub odd: Vec<Odd<f64>>,
    pub odd13: Vec<cga13::Odd13<f64>>,
    pub quad: Vec<Quadvector<f64>>,
    pub vector: Vec<Vector<f64>>,
    pub h11: Vec<[f64; 11]>,
    pub h15: Vec<[f64; 15]>,
    pub h15b: Vec<[f64; 15]>,
    pub h5: Vec<[f64; 5]>,
    pub h5b: Vec<[f64; 5]>,
}

impl Out {
    /// Zeroed outputs for one batch.
    pub fn new() -> Out {
        Out {
            rotor: vec![Rotor::default(); BATCH],
            odd: vec![Odd::default(); BATCH],
            odd13: vec![cga13::Odd13::default(); BATCH],
            quad: vec![Quadvector::default(); BATCH],
            vector: vec![Vector::default(); BATCH],
            h11: vec![[0.0; 11]; BATCH],
            h15: vec![[0.0; 15]; BATCH],
            h15b: vec![[0.0; 15]; BATCH],
            h5: vec![[0.0; 5]; BATCH],
            h5b: vec![[0.0; 5]; BATCH],
        }
    }
}

// ---- one product per call ----

#[inline(never)]
pub fn call_gen_vv(a: &Vector<f64>, b: &Vector<f64>) -> Rotor<f64> {
    a * b
}
#[inline(never)]
pub fn call_hand_vv(a: &[f64; 5], b: &[f64; 5]) -> [f64; 11] {
    hand::vector_vector(a, b)
}
#[inline(never)]
pub fn call_gen_bv_odd(a: &Bivector<f64>, b: &Vector<f64>) -> Odd<f64> {
    a * b
}
#[inline(never)]
pub fn call_hand_bv_odd(a: &[f64; 10], b: &[f64; 5]) -> [f64; 15] {
    hand::bivector_vector(a, b)
}
// The hand-written side of "bivector * vector -> grades 1 3" is `*_hand_bv_odd` (a second copy
// of the same function would be merged into it by the compiler).
#[inline(never)]
pub fn call_gen_bv_13(a: &cga13::Bivector<f64>, b: &cga13::Vector<f64>) -> cga13::Odd13<f64> {
    a * b
}
#[inline(never)]
pub fn call_gen_tw(a: &Trivector<f64>, b: &Vector<f64>) -> Quadvector<f64> {
    a ^ b
}
#[inline(never)]
pub fn call_hand_tw(a: &[f64; 10], b: &[f64; 5]) -> [f64; 5] {
    hand::trivector_wedge_vector(a, b)
}
#[inline(never)]
pub fn call_gen_rs(r: &Rotor<f64>, x: &Vector<f64>) -> Vector<f64> {
    r.sandwich_unit(x)
}
#[inline(never)]
pub fn call_hand_rs(r: &[f64; 11], x: &[f64; 5]) -> [f64; 5] {
    hand::rotor_sandwich(r, x)
}
#[inline(never)]
pub fn call_gen_dense(a: &Multivector<f64>, b: &Multivector<f64>) -> Multivector<f64> {
    a * b
}

// ---- a batch per call, the product inlined into the loop ----

macro_rules! batch {
    ($name:ident, $a:ty, $b:ty, $o:ty, |$x:ident, $y:ident| $e:expr) => {
        #[inline(never)]
        pub fn $name(a: &[$a], b: &[$b], out: &mut [$o]) {
            for ((x, y), o) in a.iter().zip(b).zip(out.iter_mut()) {
                let ($x, $y) = (x, y);
                *o = $e;
            }
        }
    };
}

batch!(
    batch_gen_vv,
    Vector<f64>,
    Vector<f64>,
    Rotor<f64>,
    |a, b| a * b
);
batch!(batch_hand_vv, [f64; 5], [f64; 5], [f64; 11], |a, b| {
    hand::vector_vector(a, b)
});
batch!(
    batch_gen_bv_odd,
    Bivector<f64>,
    Vector<f64>,
    Odd<f64>,
    |a, b| a * b
);
batch!(batch_hand_bv_odd, [f64; 10], [f64; 5], [f64; 15], |a, b| {
    hand::bivector_vector(a, b)
});
batch!(
    batch_gen_bv_13,
    cga13::Bivector<f64>,
    cga13::Vector<f64>,
    cga13::Odd13<f64>,
    |a, b| a * b
);
batch!(
    batch_gen_tw,
    Trivector<f64>,
    Vector<f64>,
    Quadvector<f64>,
    |a, b| a ^ b
);
batch!(batch_hand_tw, [f64; 10], [f64; 5], [f64; 5], |a, b| {
    hand::trivector_wedge_vector(a, b)
});
batch!(
    batch_gen_rs,
    Rotor<f64>,
    Vector<f64>,
    Vector<f64>,
    |r, x| r.sandwich_unit(x)
);
batch!(batch_hand_rs, [f64; 11], [f64; 5], [f64; 5], |r, x| {
    hand::rotor_sandwich(r, x)
});

// ---- the comparisons ----

/// Which side of a comparison.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Side {
    /// The code generated by `ga_macros::algebra!`.
    Generated,
    /// The hand-written straight-line baseline.
    Hand,
}

/// One side of one product: its functions and how to run them over a batch.
pub struct Kernel {
    /// The product compared.
    pub product: &'static str,
    /// Generated or hand-written.
    pub side: Side,
    /// The name of the `call_*` function (for callgrind's `--toggle-collect`).
    pub call_fn: &'static str,
    /// The name of the `batch_*` function.
    pub batch_fn: &'static str,
    /// The address of the `call_*` function: the compiler merges functions whose code is
    /// identical, and then the generated and hand-written kernels share one address.
    pub call_addr: usize,
    /// The address of the `batch_*` function.
    pub batch_addr: usize,
    /// Calls `call_*` once per operand pair of the batch.
    pub run_calls: fn(&Data, &mut Out),
    /// Calls `batch_*` once on the batch.
    pub run_batch: fn(&Data, &mut Out),
}

macro_rules! kernel {
    ($product:expr, $side:ident, $call:ident, $batch:ident, $a:ident, $b:ident, $o:ident) => {
        Kernel {
            product: $product,
            side: Side::$side,
            call_fn: stringify!($call),
            batch_fn: stringify!($batch),
            call_addr: ($call as fn(_, _) -> _) as usize,
            batch_addr: ($batch as fn(_, _, _)) as usize,
            run_calls: |d, o| {
                for ((x, y), r) in d.$a.iter().zip(&d.$b).zip(o.$o.iter_mut()) {
                    *r = $call(x, y);
                }
            },
            run_batch: |d, o| $batch(&d.$a, &d.$b, &mut o.$o),
        }
    };
}

/// Every kernel, generated before hand-written for each product.
pub fn kernels() -> Vec<Kernel> {
    vec![
        kernel!(
            "vector * vector",
            Generated,
            call_gen_vv,
            batch_gen_vv,
            gv1,
            gv2,
            rotor
        ),
        kernel!(
            "vector * vector",
            Hand,
            call_hand_vv,
            batch_hand_vv,
            v1,
            v2,
            h11
        ),
        kernel!(
            "bivector * vector -> Odd",
            Generated,
            call_gen_bv_odd,
            batch_gen_bv_odd,
            gb,
            gv2,
            odd
        ),
        kernel!(
            "bivector * vector -> Odd",
            Hand,
            call_hand_bv_odd,
            batch_hand_bv_odd,
            b,
            v2,
            h15
        ),
        kernel!(
            "bivector * vector -> grades 1 3",
            Generated,
            call_gen_bv_13,
            batch_gen_bv_13,
            gb13,
            gv13,
            odd13
        ),
        kernel!(
            "bivector * vector -> grades 1 3",
            Hand,
            call_hand_bv_odd,
            batch_hand_bv_odd,
            b,
            v2,
            h15b
        ),
        kernel!(
            "trivector ^ vector",
            Generated,
            call_gen_tw,
            batch_gen_tw,
            gt,
            gv2,
            quad
        ),
        kernel!(
            "trivector ^ vector",
            Hand,
            call_hand_tw,
            batch_hand_tw,
            t,
            v2,
            h5
        ),
        kernel!(
            "rotor sandwich of a point",
            Generated,
            call_gen_rs,
            batch_gen_rs,
            gr,
            gv2,
            vector
        ),
        kernel!(
            "rotor sandwich of a point",
            Hand,
            call_hand_rs,
            batch_hand_rs,
            r,
            v2,
            h5b
        ),
    ]
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= 1e-12 * (1.0 + x.abs()))
}

/// Checks, after every kernel ran on the batch, that each hand-written result equals the
/// generated one (blade by blade, in canonical order). Panics with the product's name if not.
pub fn check(out: &Out) {
    let coeffs = |m: Multivector<f64>| m.coefficients().to_vec();
    for i in 0..BATCH {
        // Rotor: scalar and the ten bivectors (canonical indices 0 and 6..16).
        let g = coeffs(out.rotor[i].into());
        let g: Vec<f64> = core::iter::once(g[0])
            .chain(g[6..16].iter().copied())
            .collect();
        assert!(
            close(&g, &out.h11[i]),
            "vector * vector: baseline disagrees"
        );
        // Odd: vectors (1..6) and trivectors (16..26).
        let g = coeffs(out.odd[i].into());
        let g: Vec<f64> = g[1..6].iter().chain(&g[16..26]).copied().collect();
        assert!(
            close(&g, &out.h15[i]),
            "bivector * vector: baseline disagrees"
        );
        assert!(
            coeffs(out.odd[i].into())[31] == 0.0,
            "bivector * vector has no grade 5"
        );
        let g = cga13::Multivector::from(out.odd13[i])
            .coefficients()
            .to_vec();
        let g: Vec<f64> = g[1..6].iter().chain(&g[16..26]).copied().collect();
        assert!(
            close(&g, &out.h15b[i]),
            "bivector * vector (grades 1 3): baseline disagrees"
        );
        let g = coeffs(out.quad[i].into());
        assert!(
            close(&g[26..31], &out.h5[i]),
            "trivector ^ vector: baseline disagrees"
        );
        let g = coeffs(out.vector[i].into());
        assert!(
            close(&g[1..6], &out.h5b[i]),
            "rotor sandwich: baseline disagrees"
        );
    }
}

/// Runs every kernel once in both forms and checks the baselines (call at start-up).
pub fn run_all_and_check(data: &Data) {
    for form in [|k: &Kernel| k.run_calls, |k: &Kernel| k.run_batch] {
        let mut out = Out::new();
        for k in kernels() {
            form(&k)(data, &mut out);
        }
        check(&out);
    }
}

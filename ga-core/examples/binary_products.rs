//! ga-benchmark's conformal binary products, grade pair by grade pair, timed on the null-basis
//! types of [`ga_core::cga_null`] (`Vector`, `Bivector`, `Trivector`, `Quadvector`,
//! `Pseudoscalar`): the geometric, outer and scalar products and the left and right
//! contractions of a grade-`j` blade by a grade-`k` blade, `j, k` in `1..=5`.
//!
//! ```text
//! cargo run --release -p ga-core --example binary_products -- ROUNDS
//! {"op": "GeometricProduct", "lhs_grade": 2, "rhs_grade": 3, "median_ns": …}
//! ```
//!
//! The operands follow ga-benchmark's `MakeRandomBlade`: a grade-`k` blade is a scalar uniform
//! in `[-1, 1]` times the outer product of `k` vectors, the `i`-th of which has coordinate 1 on
//! the `i`-th basis vector, 0 on the other first `k`, and uniform in `[-1, 1]` on the last
//! `5 - k` (the basis `e1, e2, e3, eo, ei`, as in ga-benchmark's conformal model). Each line is
//! the median over ROUNDS batches of the time per product of a batch of 1,024 operand pairs,
//! each product inlined into the batch's loop and its result written to memory. A product that
//! is zero by grade returns the zero-sized `ga_core::Zero`, whose store writes nothing.
//!
//! `BINARY_PRODUCTS_ONLY="OuterProduct 2 1"` runs that one line only (to count its instructions
//! under `valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*run_batch*'`).

use std::hint::black_box;
use std::time::Instant;

use ga_core::cga_null::{Bivector, Pseudoscalar, Quadvector, Trivector, Vector};
use ga_core::ops::{Geometric, LeftContraction, RightContraction, ScalarProduct, Wedge};

/// Operand pairs per timed batch.
const BATCH: usize = 1024;

/// splitmix64: reproducible uniform numbers without a dependency.
struct Uniform(u64);

impl Uniform {
    /// Uniform in `[-1, 1)`.
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// ga-benchmark's random factors of a grade-`grade` blade: its scalar, then its vectors.
    fn factors(&mut self, grade: usize) -> (f64, Vec<Vector<f64>>) {
        let scalar = self.next();
        let vectors = (0..grade)
            .map(|i| {
                let mut c = [0.0; 5];
                c[i] = 1.0;
                for x in c.iter_mut().skip(grade) {
                    *x = self.next();
                }
                Vector::new(c[0], c[1], c[2], c[3], c[4])
            })
            .collect();
        (scalar, vectors)
    }
}

/// A grade-`k` blade type built from ga-benchmark's random factors.
trait Blade: Sized + Clone + Default {
    const GRADE: usize;
    fn random(u: &mut Uniform) -> Self;
}

impl Blade for Vector<f64> {
    const GRADE: usize = 1;
    fn random(u: &mut Uniform) -> Self {
        let (s, v) = u.factors(1);
        v[0].scale(&s)
    }
}

impl Blade for Bivector<f64> {
    const GRADE: usize = 2;
    fn random(u: &mut Uniform) -> Self {
        let (s, v) = u.factors(2);
        (v[0] ^ v[1]).scale(&s)
    }
}

impl Blade for Trivector<f64> {
    const GRADE: usize = 3;
    fn random(u: &mut Uniform) -> Self {
        let (s, v) = u.factors(3);
        (v[0] ^ v[1] ^ v[2]).scale(&s)
    }
}

impl Blade for Quadvector<f64> {
    const GRADE: usize = 4;
    fn random(u: &mut Uniform) -> Self {
        let (s, v) = u.factors(4);
        (v[0] ^ v[1] ^ v[2] ^ v[3]).scale(&s)
    }
}

impl Blade for Pseudoscalar<f64> {
    const GRADE: usize = 5;
    fn random(u: &mut Uniform) -> Self {
        let (s, v) = u.factors(5);
        (v[0] ^ v[1] ^ v[2] ^ v[3] ^ v[4]).scale(&s)
    }
}

/// Times `op` over `rounds` batches of random `(A, B)` pairs; prints one JSON line.
fn time<A: Blade, B: Blade, O: Default + Clone>(
    name: &str,
    rounds: usize,
    u: &mut Uniform,
    op: impl Fn(&A, &B) -> O,
) {
    if let Ok(only) = std::env::var("BINARY_PRODUCTS_ONLY") {
        if only != format!("{name} {} {}", A::GRADE, B::GRADE) {
            return;
        }
    }
    let lhs: Vec<A> = (0..BATCH).map(|_| A::random(u)).collect();
    let rhs: Vec<B> = (0..BATCH).map(|_| B::random(u)).collect();
    let mut out = vec![O::default(); BATCH];
    let mut per_op = Vec::with_capacity(rounds);
    for _ in 0..rounds {
        let start = Instant::now();
        run_batch(black_box(&lhs), black_box(&rhs), &mut out, &op);
        per_op.push(start.elapsed().as_nanos() as f64 / BATCH as f64);
        black_box(&out);
    }
    per_op.sort_by(f64::total_cmp);
    println!(
        "{{\"op\": \"{name}\", \"lhs_grade\": {}, \"rhs_grade\": {}, \"median_ns\": {:.2}}}",
        A::GRADE,
        B::GRADE,
        per_op[per_op.len() / 2]
    );
}

/// One batch: the product inlined into the loop, each result stored.
#[inline(never)]
fn run_batch<A, B, O>(lhs: &[A], rhs: &[B], out: &mut [O], op: &impl Fn(&A, &B) -> O) {
    for ((o, a), b) in out.iter_mut().zip(lhs).zip(rhs) {
        *o = op(a, b);
    }
}

/// Every product of ga-benchmark's list for the grade pair `(A, B)`.
macro_rules! pair {
    ($rounds:expr, $u:expr, $a:ty, $b:ty) => {{
        time::<$a, $b, _>("GeometricProduct", $rounds, $u, |a, b| a.geometric(b));
        time::<$a, $b, _>("OuterProduct", $rounds, $u, |a, b| a.wedge(b));
        time::<$a, $b, _>("LeftContraction", $rounds, $u, |a, b| a.left_contraction(b));
        time::<$a, $b, _>("RightContraction", $rounds, $u, |a, b| {
            a.right_contraction(b)
        });
        time::<$a, $b, _>("ScalarProduct", $rounds, $u, |a, b| a.scalar_product(b));
    }};
}

macro_rules! rows {
    ($rounds:expr, $u:expr, $a:ty) => {{
        pair!($rounds, $u, $a, Vector<f64>);
        pair!($rounds, $u, $a, Bivector<f64>);
        pair!($rounds, $u, $a, Trivector<f64>);
        pair!($rounds, $u, $a, Quadvector<f64>);
        pair!($rounds, $u, $a, Pseudoscalar<f64>);
    }};
}

fn main() {
    let rounds = match std::env::args().nth(1).map(|r| r.parse::<usize>()) {
        None => 200,
        Some(Ok(r)) if r > 0 => r,
        Some(_) => {
            eprintln!("usage: binary_products [ROUNDS > 0]");
            return;
        }
    };
    let mut u = Uniform(0x6A_B3);
    rows!(rounds, &mut u, Vector<f64>);
    rows!(rounds, &mut u, Bivector<f64>);
    rows!(rounds, &mut u, Trivector<f64>);
    rows!(rounds, &mut u, Quadvector<f64>);
    rows!(rounds, &mut u, Pseudoscalar<f64>);
}

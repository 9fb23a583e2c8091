//! The field's benchmark algorithm: ga-benchmark's conformal inverse-kinematics chain (a
//! 5-joint arm after Fernandes et al.), written the way a user of the crate writes it: the
//! whole chain declared once with `ga_core::cga_null_expressions!` over the null-basis types
//! (conformal points, dual lines, a 4th-order exponential series, motor applications), so that
//! it is generated as one straight-line function of the five angles, generic over the scalar,
//! with the arm's constants, the types' zeros and `ei² = 0` folded at compile time.
//!
//! ```text
//! cargo run --release -p ga-core --example ik_chain               # the sanity chain
//! cargo run --release -p ga-core --example ik_chain -- bench 200  # one JSON line
//! cargo run --release -p ga-core --example ik_chain -- bench-products 200
//! ```
//!
//! `bench-products` times the same chain written product by product with `ga_core::cga`
//! (`Even` rotors, one generated product per call): the baseline, and the reference's code.
//!
//! `bench ROUNDS` times ROUNDS batches of 1,024 chains with angles uniform in `[0, 2π)` (ga-benchmark's
//! `MakeRandomAngle`) and prints one JSON line:
//! `{"op": "g_ik_ga_benchmark", "median_ns": …, "max_rel_error_vs_exact": …,
//! "chains_beyond_f64": …, "worst_error_in_angle_ulps": …, "sanity_rel_error_vs_exact": …}`:
//! - `median_ns`: the median over the batches of the time per chain;
//! - `max_rel_error_vs_exact`: the largest relative error of the gripper point (the 5
//!   coefficients of `Jg_f` in `e1 … e5`; the max-norm of the error over the max-norm of the
//!   reference point, computed exactly) against the same chain evaluated in `Rational`
//!   arithmetic on the same angles (every `f64` is a dyadic rational, so the reference sees
//!   exactly the angles the `f64` chain sees; the arm's lengths are the exact decimals there),
//!   over the first 256 chains whose exact gripper lies within `f64`'s range. A result that is
//!   not finite while the exact one is counts as error 1;
//! - `chains_beyond_f64`: how many of those 256 chains have an exact gripper beyond `f64`'s range
//!   (the 4th-order series is not a unit rotor, so for angles near 2π each joint scales the
//!   next line and the values grow without bound): no `f64` result can be right there;
//! - `worst_error_in_angle_ulps`: the worst chain's error over how far its exact gripper moves
//!   when one of its angles moves by one unit in the last place (the largest over the five): the
//!   error in units of the chain's own conditioning, about 1 for an evaluation as good as
//!   rounding its inputs;
//! - `sanity_rel_error_vs_exact`: the same relative error for ga-benchmark's sanity angles.
//!
//! stderr gets the error distribution.
//!
//! Why the reference rounds: the chain is a polynomial of degree about 95,000 in the angles
//! (each 4th-order series multiplies the degree of its argument by 4, and each rotor feeds the
//! next line), so its exact value has millions of bits and one exact chain does not finish in
//! minutes. The reference therefore keeps `Rational` values but rounds every product, quotient
//! and sum to [`REFERENCE_BITS`] significant bits ([`Precise`]): a relative error near
//! `2^-300` per operation, about 280 bits below what is being measured.

use std::hint::black_box;
use std::time::Instant;

use ga_core::cga::{n_0, n_inf, up_generic, Bivector, Even, Vector};
use ga_core::cga_null;
use ga_core::prelude::*;
use ga_core::scalar::{rational_from_f64, Rational};
use num_bigint::BigInt;

/// Significant bits the reference keeps after each operation.
const REFERENCE_BITS: u64 = 320;

/// A `Rational` rounded (toward zero) to [`REFERENCE_BITS`] significant bits after every
/// operation: the high-precision reference scalar.
#[derive(Clone, PartialEq, PartialOrd)]
struct Precise(Rational);

impl Precise {
    fn new(x: Rational) -> Self {
        if x.is_zero() {
            return Precise(x);
        }
        // x = p/q; keep floor(|p| 2^k / q) with k chosen for REFERENCE_BITS bits.
        let bits = |v: &BigInt| v.bits() as i64;
        let k = REFERENCE_BITS as i64 - (bits(x.numer()) - bits(x.denom()));
        let (p, q) = (
            BigInt::from(x.numer().magnitude().clone()),
            x.denom().clone(),
        );
        let m = if k >= 0 {
            (p << k as usize) / q
        } else {
            p / (q << (-k) as usize)
        };
        let m = if x < Rational::zero() { -m } else { m };
        let scale = BigInt::from(1) << k.unsigned_abs() as usize;
        Precise(if k >= 0 {
            Rational::new(m, scale)
        } else {
            Rational::from_integer(m * scale)
        })
    }
}

macro_rules! precise_op {
    ($tr:ident, $m:ident, $op:tt) => {
        impl core::ops::$tr for Precise {
            type Output = Precise;
            fn $m(self, rhs: Precise) -> Precise {
                Precise::new(self.0 $op rhs.0)
            }
        }
    };
}
precise_op!(Add, add, +);
precise_op!(Sub, sub, -);
precise_op!(Mul, mul, *);
precise_op!(Div, div, /);

impl core::ops::Neg for Precise {
    type Output = Precise;
    fn neg(self) -> Precise {
        Precise(-self.0)
    }
}

impl Ring for Precise {
    fn zero() -> Self {
        Precise(Rational::zero())
    }
    fn one() -> Self {
        Precise(<Rational as Ring>::one())
    }
    fn from_i64(n: i64) -> Self {
        Precise(<Rational as Ring>::from_i64(n))
    }
    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }
}

impl Field for Precise {}

impl Real for Precise {
    fn sqrt(&self) -> Self {
        Precise::new(Real::sqrt(&self.0))
    }
    fn abs(&self) -> Self {
        Precise(Real::abs(&self.0))
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        Real::to_f64(&self.0)
    }
    fn from_f64(x: f64) -> Self {
        Precise(<Rational as Real>::from_f64(x))
    }
}

/// Chains per timed batch.
const BATCH: usize = 1024;
/// Chains of the first batch also evaluated by the reference.
const EXACT_SAMPLES: usize = 256;

/// `n/d` in any field (the arm's decimal lengths, the series' factorials).
fn ratio<T: Field>(n: i64, d: i64) -> T {
    T::from_i64(n) / T::from_i64(d)
}

/// ga-benchmark's `expp`: the exponential series to 4th order, `1 + x + x²/2 + x³/6 + x⁴/24`.
fn expp<T: Field>(x: &Bivector<T>) -> Even<T> {
    let x2: Even<T> = x * x;
    let x3: Even<T> = &x2 * x;
    let x4: Even<T> = &x3 * x;
    let mut one = Even::zero();
    one.s = T::one();
    one + x.clone() + x2.scale(&ratio(1, 2)) + x3.scale(&ratio(1, 6)) + x4.scale(&ratio(1, 24))
}

/// The arm: what does not depend on the angles, built once (joint points and the dual lines of
/// the joint axes before any rotation).
struct Arm<T> {
    j2: Vector<T>,
    jg: Vector<T>,
    lz: Bivector<T>,
    l2_init: Bivector<T>,
    l3_init: Bivector<T>,
    l4_init_unit: Bivector<T>,
    lg_init: Bivector<T>,
}

impl Arm<Rational> {
    /// The exact arm, its values then carried into the reference scalar.
    fn precise() -> Arm<Precise> {
        let a = Arm::<Rational>::new();
        Arm {
            j2: a.j2.map(Precise),
            jg: a.jg.map(Precise),
            lz: a.lz.map(Precise),
            l2_init: a.l2_init.map(Precise),
            l3_init: a.l3_init.map(Precise),
            l4_init_unit: a.l4_init_unit.map(Precise),
            lg_init: a.lg_init.map(Precise),
        }
    }
}

impl<T: Real> Arm<T> {
    /// ga-benchmark's arm: `d1..d5 = 200, 680, 150, 140, 114.2`, `l12 = 890`, `l23 = 880`.
    fn new() -> Self {
        let n = |k: i64| T::from_i64(k);
        let (d1, d2, d3, d4, d5) = (n(200), n(680), n(150), n(140), ratio::<T>(1142, 10));
        let (l12, l23) = (n(890), n(880));
        let p = |x: &T, y: &T, z: &T| up_generic(x.clone(), y.clone(), z.clone());
        let zero = T::zero();
        let one = T::one();
        let (j1x, j1z) = (d1.clone(), d2.clone());
        let (j2x, j2z) = (d1.clone(), d2.clone() + l12.clone());
        let (j3x, j3z) = (d1.clone() + l23.clone(), d2 + l12 + d3);
        let jgx = d1 + l23 + d4 + d5;
        let j1 = p(&j1x, &zero, &j1z);
        let j2 = p(&j2x, &zero, &j2z);
        let j3 = p(&j3x, &zero, &j3z);
        let jg = p(&jgx, &zero, &j3z);
        let ni = n_inf::<T>();
        // The dual line through two points, `(P ∧ Q ∧ n_inf)*`, with ga-benchmark's
        // pseudoscalar `e1 e2 e3 n_0 n_inf`, which is `-e12345` (so minus this crate's `!`).
        let line = |a: &Vector<T>, b: &Vector<T>| -> Bivector<T> { -!(a ^ b ^ ni.clone()) };
        let lz = line(&n_0(), &p(&zero, &zero, &one));
        let l2_init = line(&j1, &p(&j1x, &one, &j1z));
        let l3_init = line(&j2, &p(&j2x, &one, &j2z));
        let l4_init = line(&j3, &jg);
        // `L / |L|`, |L|² = |⟨L L̃⟩₀| (here the joints' distance squared, a perfect square).
        let l4_norm = l4_init.norm_squared().abs().sqrt();
        let l4_init_unit = l4_init.scale(&(T::one() / l4_norm));
        let lg_init = line(&j3, &p(&j3x, &one, &j3z));
        Arm {
            j2,
            jg,
            lz,
            l2_init,
            l3_init,
            l4_init_unit,
            lg_init,
        }
    }
}

/// What ga-benchmark's chain returns: the five joint versors, the translator and the gripper.
struct Pose<T> {
    r1: Even<T>,
    r2: Even<T>,
    r3: Even<T>,
    t2: Even<T>,
    r4: Even<T>,
    rg: Even<T>,
    jg_f: Vector<T>,
}

/// The chain for the joint angles `a` (radians), ga-benchmark's `AlgorithmInverseKinematics`,
/// product by product in `ga_core::cga` (`Even` rotors): the baseline and the reference's code.
fn chain_by_products<T: Real>(arm: &Arm<T>, a: &[T; 5]) -> Pose<T> {
    let half = ratio::<T>(1, 2);
    let r1 = expp(&arm.lz.scale(&(a[0].clone() * half.clone())));
    let l2 = r1.sandwich_unit(&arm.l2_init);
    let r2 = expp(&l2.scale(&(a[1].clone() * half.clone())));
    let r21 = &r2 * &r1;
    let j2_f = r21.sandwich_unit(&arm.j2);
    let l3 = r21.sandwich_unit(&arm.l3_init);
    let r3 = expp(&l3.scale(&(a[2].clone() * half.clone())));
    let j2_rot1 = r1.sandwich_unit(&arm.j2);
    // The Euclidean part of J2's displacement by the second joint (`sp(X, e_i)` = X's e_i).
    let t2 = Vector::new(
        j2_f.e1.clone() - j2_rot1.e1.clone(),
        j2_f.e2.clone() - j2_rot1.e2.clone(),
        j2_f.e3.clone() - j2_rot1.e3.clone(),
        T::zero(),
        T::zero(),
    );
    let t2 = expp(&(t2 ^ n_inf::<T>()).scale(&-half.clone()));
    let r3t2r1 = &(&r3 * &t2) * &r1;
    let l4 = r3t2r1.sandwich_unit(&arm.l4_init_unit);
    let r4 = expp(&l4.scale(&(a[3].clone() * half.clone())));
    let lg = (&r4 * &r3t2r1).sandwich_unit(&arm.lg_init);
    let rg = expp(&lg.scale(&(a[4].clone() * half)));
    // As in ga-benchmark, the gripper is moved by `Rg R3 T2 R1` (R4 is not in its product).
    let jg_f = (&rg * &r3t2r1).sandwich_unit(&arm.jg);
    Pose {
        r1,
        r2,
        r3,
        t2,
        r4,
        rg,
        jg_f,
    }
}

/// The chain on the null basis, generated whole (its helpers are inlined into it).
mod fused {
    ga_core::cga_null_expressions! {
        /// The conformal point `x + ½|x|² ei + eo`.
        fn point(x: T, y: T, z: T) -> Vector {
            x * e1() + y * e2() + z * e3() + eo() + (x * x + y * y + z * z) / 2 * ei()
        }

        /// The dual line through two points, `(P ∧ Q ∧ ei)*` (ga-benchmark's pseudoscalar
        /// `e1 e2 e3 n0 n∞` is this basis's `I`).
        fn line(p: Vector, q: Vector) -> Line {
            !(p ^ q ^ ei())
        }

        /// ga-benchmark's `expp`: the exponential series to 4th order. `x` is a line, a blade,
        /// so `x x` is the scalar `⟨x x⟩₀` and `x³ x = (x x)²`: declared `#[blade]`, the
        /// generator uses that rather than multiply out terms that are zero for a blade.
        fn expp(#[blade] x: Line) -> Motor {
            let x2 = x * x;
            let x3 = x2 * x;
            1 + x + x2 / 2 + x3 / 6 + x3 * x / 24
        }

        /// ga-benchmark's `AlgorithmInverseKinematics` for the joint angles (radians): the five
        /// joint motors, the translator and the gripper point.
        pub fn fused_chain(
            ang1: T,
            ang2: T,
            ang3: T,
            ang4: T,
            ang5: T,
        ) -> (Motor, Motor, Motor, Motor, Motor, Motor, Vector) {
            // The arm: d1..d5 = 200, 680, 150, 140, 114.2, l12 = 890, l23 = 880.
            let j1 = point(200, 0, 680);
            let j2 = point(200, 0, 680 + 890);
            let j3 = point(200 + 880, 0, 680 + 890 + 150);
            let jg = point(200 + 880 + 140 + 114.2, 0, 680 + 890 + 150);
            let lz = line(eo(), point(0, 0, 1));
            let l2_init = line(j1, point(200, 1, 680));
            let l3_init = line(j2, point(200, 1, 680 + 890));
            // Unit: the line through two points has the norm of their distance (140 + 114.2).
            let l4_init = line(j3, jg) / (140 + 114.2);
            let lg_init = line(j3, point(200 + 880, 1, 680 + 890 + 150));
            // The chain.
            let r1 = expp(lz * (ang1 / 2));
            let l2 = r1.sandwich_unit(&l2_init);
            let r2 = expp(l2 * (ang2 / 2));
            let r21 = r2 * r1;
            let j2_f = r21.sandwich_unit(&j2);
            let l3 = r21.sandwich_unit(&l3_init);
            let r3 = expp(l3 * (ang3 / 2));
            let j2_rot1 = r1.sandwich_unit(&j2);
            let t = (j2_f.e1 - j2_rot1.e1) * e1() + (j2_f.e2 - j2_rot1.e2) * e2()
                + (j2_f.e3 - j2_rot1.e3) * e3();
            let t2 = expp((t ^ ei()) * (-1 / 2));
            let r3t2r1 = r3 * t2 * r1;
            let l4 = r3t2r1.sandwich_unit(&l4_init);
            let r4 = expp(l4 * (ang4 / 2));
            let lg = (r4 * r3t2r1).sandwich_unit(&lg_init);
            let rg = expp(lg * (ang5 / 2));
            // As in ga-benchmark, the gripper is moved by `Rg R3 T2 R1` (R4 is not in it).
            let jg_f = (rg * r3t2r1).sandwich_unit(&jg);
            (r1, r2, r3, t2, r4, rg, jg_f)
        }
    }
}
use fused::fused_chain;

/// The fused chain's gripper point in `e1 … e5` (`x eo + y ei = (y - x/2) e4 + (y + x/2) e5`),
/// exactly: each coefficient as a `Rational`.
fn gripper_in_e12345(p: &cga_null::Vector<f64>) -> [Option<Rational>; 5] {
    let r = |x: f64| rational_from_f64(x);
    let half = Rational::new(1.into(), 2.into());
    let (o, i) = (r(p.eo), r(p.ei));
    let e4 = o.clone().zip(i.clone()).map(|(o, i)| i - o * half.clone());
    let e5 = o.zip(i).map(|(o, i)| i + o * half);
    [r(p.e1), r(p.e2), r(p.e3), e4, e5]
}

/// splitmix64: reproducible uniform angles without a dependency.
struct Angles(u64);

impl Angles {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        // 53 random bits: uniform in [0, 1), times 2π rounds into [0, 2π).
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        (u * std::f64::consts::TAU).min(std::f64::consts::TAU.next_down())
    }
    fn batch(&mut self) -> Vec<[f64; 5]> {
        (0..BATCH)
            .map(|_| core::array::from_fn(|_| self.next()))
            .collect()
    }
}

/// Max-norm relative error of `approx` (exact values of the computed coefficients, `None` where
/// not finite) against `exact`, computed exactly then rounded.
fn relative_error(approx: &[Option<Rational>; 5], exact: &Vector<Precise>) -> f64 {
    // A result that overflowed `f64` carries no information: 100% error (JSON has no inf).
    if approx.iter().any(Option::is_none) {
        return 1.0;
    }
    let mut err = Rational::zero();
    let mut size = Rational::zero();
    for (a, e) in approx.iter().flatten().zip(exact.coefficients()) {
        err = err.max((a - e.0.clone()).abs());
        size = size.max(e.0.abs());
    }
    if size.is_zero() {
        return if err.is_zero() { 0.0 } else { f64::INFINITY };
    }
    (err / size).to_f64()
}

fn exact_coefficients(v: &Vector<f64>) -> [Option<Rational>; 5] {
    v.coefficients().map(rational_from_f64)
}

/// Which implementation `bench` times.
#[derive(Clone, Copy, PartialEq)]
enum Implementation {
    /// The generated `fused_chain` (null basis, one straight-line function).
    Fused,
    /// `chain_by_products` (`cga`, `Even`, one generated product per call).
    Products,
}

fn gripper(which: Implementation, arm: &Arm<f64>, a: &[f64; 5]) -> [Option<Rational>; 5] {
    match which {
        Implementation::Fused => {
            let (.., jg_f) = fused_chain(a[0], a[1], a[2], a[3], a[4]);
            gripper_in_e12345(&jg_f)
        }
        Implementation::Products => exact_coefficients(&chain_by_products(arm, a).jg_f),
    }
}

/// The exact gripper of the chain for the `f64` angles `a` (each a dyadic rational).
fn exact_gripper(exact_arm: &Arm<Precise>, a: &[f64; 5]) -> Vector<Precise> {
    let exact_angles = a.map(|x| Precise(rational_from_f64(x).unwrap_or_else(Rational::zero)));
    chain_by_products(exact_arm, &exact_angles).jg_f
}

/// How far the exact gripper moves, relatively, when one angle moves by one unit in the last
/// place: the largest over the five angles. An `f64` evaluation rounds its intermediates by
/// that much, so an error of a few times this is the chain's conditioning, not the code's.
fn one_ulp_angle_effect(exact_arm: &Arm<Precise>, a: &[f64; 5], exact: &Vector<Precise>) -> f64 {
    (0..5)
        .map(|k| {
            let mut moved = *a;
            moved[k] = moved[k].next_up();
            let moved = exact_gripper(exact_arm, &moved).coefficients();
            relative_error(&moved.map(|c| Some(c.0)), exact)
        })
        .fold(0.0, f64::max)
}

/// The accuracy figures of `bench`: see the module documentation.
struct Accuracy {
    /// The largest relative error over the chains whose exact gripper fits `f64`.
    max_error: f64,
    /// Chains whose exact gripper lies beyond `f64`'s range (no `f64` result can be right).
    beyond_f64: usize,
    /// The worst chain's error over [`one_ulp_angle_effect`] of its angles.
    worst_in_angle_ulps: f64,
    /// The relative error of ga-benchmark's sanity chain.
    sanity_error: f64,
}

fn accuracy(which: Implementation, first: &[[f64; 5]]) -> Accuracy {
    let arm = Arm::<f64>::new();
    let exact_arm = Arm::precise();
    let largest = Rational::from_float(f64::MAX).unwrap_or_else(Rational::zero);
    let mut errors = Vec::with_capacity(EXACT_SAMPLES);
    let mut beyond_f64 = 0;
    let mut worst: Option<([f64; 5], Vector<Precise>)> = None;
    let mut max_error = 0.0f64;
    for a in first.iter().take(EXACT_SAMPLES) {
        let exact = exact_gripper(&exact_arm, a);
        if exact.coefficients().iter().any(|c| c.0.abs() > largest) {
            beyond_f64 += 1;
            continue;
        }
        let error = relative_error(&gripper(which, &arm, a), &exact);
        if error > max_error || worst.is_none() {
            max_error = error;
            worst = Some((*a, exact));
        }
        errors.push(error);
    }
    errors.sort_by(f64::total_cmp);
    let worst_in_angle_ulps = worst.map_or(0.0, |(a, exact)| {
        max_error / one_ulp_angle_effect(&exact_arm, &a, &exact)
    });
    let sanity_error = sanity_relative_error(which);
    if let (Some(median), Some(p90)) = (
        errors.get(errors.len() / 2),
        errors.get(errors.len() * 9 / 10),
    ) {
        eprintln!(
            "ik_chain: relative error of the gripper over the {} of {} chains whose exact result \
             fits f64: median {median:.2e}, 90% {p90:.2e}, max {max_error:.2e} \
             ({worst_in_angle_ulps:.2} times the effect of one ulp of an angle on the exact \
             result); {beyond_f64} chains exact beyond f64; sanity chain {sanity_error:.2e}",
            errors.len(),
            errors.len() + beyond_f64,
        );
    }
    Accuracy {
        max_error,
        beyond_f64,
        worst_in_angle_ulps,
        sanity_error,
    }
}

fn bench(rounds: usize, which: Implementation) {
    let arm = Arm::<f64>::new();
    let mut angles = Angles(0x1C_C4A1);
    let first = angles.batch();
    let acc = accuracy(which, &first);
    let mut per_chain = Vec::with_capacity(rounds);
    let mut batch = first;
    for round in 0..rounds.max(1) {
        if round > 0 {
            batch = angles.batch();
        }
        let start = Instant::now();
        match which {
            Implementation::Fused => {
                let mut out = vec![cga_null::Vector::<f64>::zero(); BATCH];
                for (o, a) in out.iter_mut().zip(black_box(&batch)) {
                    let (r1, r2, r3, t2, r4, rg, jg_f) = fused_chain(a[0], a[1], a[2], a[3], a[4]);
                    // Every output of the chain is kept, as ga-benchmark returns them all.
                    black_box((&r1, &r2, &r3, &t2, &r4, &rg));
                    *o = jg_f;
                }
                black_box(&out);
            }
            Implementation::Products => {
                let mut out = vec![Vector::<f64>::zero(); BATCH];
                for (o, a) in out.iter_mut().zip(black_box(&batch)) {
                    let pose = chain_by_products(&arm, a);
                    black_box((&pose.r1, &pose.r2, &pose.r3, &pose.t2, &pose.r4, &pose.rg));
                    *o = pose.jg_f;
                }
                black_box(&out);
            }
        }
        per_chain.push(start.elapsed().as_nanos() as f64 / BATCH as f64);
    }
    per_chain.sort_by(f64::total_cmp);
    let median = per_chain[per_chain.len() / 2];
    let op = match which {
        Implementation::Fused => "g_ik_ga_benchmark",
        Implementation::Products => "g_ik_ga_benchmark_products",
    };
    println!(
        "{{\"op\": \"{op}\", \"median_ns\": {median:.1}, \
         \"max_rel_error_vs_exact\": {:.3e}, \"chains_beyond_f64\": {}, \
         \"worst_error_in_angle_ulps\": {:.2}, \"sanity_rel_error_vs_exact\": {:.3e}}}",
        acc.max_error, acc.beyond_f64, acc.worst_in_angle_ulps, acc.sanity_error
    );
}

/// ga-benchmark's sanity angles (14°, -25°, 32.6°, 66.9°, -42°).
fn sanity_angles() -> [f64; 5] {
    [14.0, -25.0, 32.6, 66.9, -42.0f64].map(f64::to_radians)
}

/// The relative error of the gripper of ga-benchmark's sanity chain against the exact chain.
fn sanity_relative_error(which: Implementation) -> f64 {
    let sanity = sanity_angles();
    relative_error(
        &gripper(which, &Arm::new(), &sanity),
        &exact_gripper(&Arm::precise(), &sanity),
    )
}

/// The generated chain's gripper for ga-benchmark's sanity angles is within 1e-16 of the exact
/// chain's, relative to the point's size (Versor is quoted within 4e-17).
pub fn check_sanity_accuracy() {
    let error = sanity_relative_error(Implementation::Fused);
    assert!(error <= 1e-16, "sanity chain relative error {error:e}");
}

/// ga-benchmark's sanity chain, product by product.
fn sanity() -> Pose<f64> {
    chain_by_products(&Arm::new(), &sanity_angles())
}

/// Checks the sanity chain against the values ga-benchmark publishes for it (6 digits).
pub fn check_sanity() {
    let p = sanity();
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-5 * y.abs().max(1.0);
    assert!(
        close(p.r1.s, 0.992546) && close(p.r1.e12, 0.121869),
        "R1 = {}",
        p.r1
    );
    let jg = p.jg_f;
    // Jg_f = 1351.52 e1 - 498.052 e2 + 2132.49 e3 + 0.99996 n0 + 3.31122e6 n_inf, and
    // x n0 + y n_inf = (y - x/2) e4 + (y + x/2) e5.
    let (n0, ni) = (jg.e5 - jg.e4, (jg.e4 + jg.e5) / 2.0);
    assert!(close(jg.e1, 1351.52) && close(jg.e2, -498.052) && close(jg.e3, 2132.49));
    assert!(close(n0, 0.99996) && close(ni, 3.31122e6), "Jg_f = {jg}");
    // The fused chain, in the null basis: the same values.
    let a = sanity_angles();
    let (r1, .., jg) = fused_chain(a[0], a[1], a[2], a[3], a[4]);
    assert!(
        close(r1.s, 0.992546) && close(r1.e12, 0.121869),
        "R1 = {r1}"
    );
    assert!(close(jg.e1, 1351.52) && close(jg.e2, -498.052) && close(jg.e3, 2132.49));
    assert!(
        close(jg.eo, 0.99996) && close(jg.ei, 3.31122e6),
        "Jg_f = {jg}"
    );
}

pub fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [cmd, rounds] if cmd == "bench" || cmd == "bench-products" => {
            let which = if cmd == "bench" {
                Implementation::Fused
            } else {
                Implementation::Products
            };
            match rounds.parse::<usize>() {
                Ok(r) if r > 0 => bench(r, which),
                _ => eprintln!("ik_chain: ROUNDS must be a positive integer, got `{rounds}`"),
            }
        }
        [] => {
            let p = sanity();
            for (name, r) in [
                ("R1", &p.r1),
                ("R2", &p.r2),
                ("R3", &p.r3),
                ("T2", &p.t2),
                ("R4", &p.r4),
                ("Rg", &p.rg),
            ] {
                println!("{name} = {r}");
            }
            println!("Jg_f = {}", p.jg_f);
            let a = sanity_angles();
            let (.., jg) = fused_chain(a[0], a[1], a[2], a[3], a[4]);
            println!("Jg_f (fused, null basis) = {jg}");
        }
        _ => eprintln!("usage: ik_chain [bench ROUNDS | bench-products ROUNDS]"),
    }
}

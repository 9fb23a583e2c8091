//! Exact signs of polynomial predicates: the [`Predicate`] trait (a polynomial written once
//! for every [`Ring`]), exact evaluation on big integers, and the staged decision
//! ([`ErrF64`] filter, the same filter at unit scale, then exact).

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use ga_core::scalar::{Rational, Ring};
use num_traits::Signed;

use super::{counters, ErrF64, Expansion};

/// A polynomial predicate in `N` `f64` inputs, written once for every [`Ring`].
pub trait Predicate<const N: usize> {
    /// The polynomial's value at `x` (the same straight-line code for `f64`, [`ErrF64`] and
    /// [`Rational`]).
    fn eval<R: Ring>(x: &[R; N]) -> R;

    /// A hand-written exact sign for the inputs the predicate's common case covers, tried
    /// before the generic exact evaluation (`None`: not covered, the generic stages decide).
    /// Must agree with the sign of [`eval`](Self::eval) in exact arithmetic wherever it answers.
    #[inline(always)]
    fn exact_sign_direct(_x: &[f64; N]) -> Option<Ordering> {
        None
    }
}

/// The sign of an exact rational.
pub fn rational_sign(r: &Rational) -> Ordering {
    if Ring::is_zero(r) {
        Ordering::Equal
    } else if r.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// The exact sign of `P` at `x`, computed exactly (no rounding anywhere).
///
/// Every predicate in [`crate::exact::predicates`] is a homogeneous polynomial, so its sign does not
/// change when all inputs are multiplied by the same power of two: the inputs are first scaled
/// (exactly) to integers and the same generic code is evaluated on big integers
/// ([`BigInteger`]). This is exact rational arithmetic with the common denominator factored
/// out; it avoids the gcd normalisations of `BigRational`, which are quadratic in the size of
/// the numbers. (The tests check it against [`Rational`] evaluation from
/// `ga_core::scalar::rational_from_f64`.)
pub fn exact_sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering {
    P::eval(&integer_scaled(x))
        .0
        .sign()
        .cmp(&num_bigint::Sign::NoSign)
}

/// The exact sign of `P` at `x` by [`Rational`] evaluation of the unscaled inputs (slow;
/// reference for the tests).
#[cfg(feature = "testing")]
pub fn rational_exact_sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering {
    let q: [Rational; N] = core::array::from_fn(|i| {
        ga_core::scalar::rational_from_f64(x[i]).unwrap_or_else(<Rational as Ring>::zero)
    });
    rational_sign(&P::eval(&q))
}

/// An exact integer implementing [`Ring`] (a newtype over `num_bigint::BigInt`).
#[derive(Debug, Clone, PartialEq)]
pub struct BigInteger(pub num_bigint::BigInt);

impl Add for BigInteger {
    type Output = BigInteger;
    fn add(self, rhs: BigInteger) -> BigInteger {
        BigInteger(self.0 + rhs.0)
    }
}
impl Sub for BigInteger {
    type Output = BigInteger;
    fn sub(self, rhs: BigInteger) -> BigInteger {
        BigInteger(self.0 - rhs.0)
    }
}
impl Mul for BigInteger {
    type Output = BigInteger;
    fn mul(self, rhs: BigInteger) -> BigInteger {
        BigInteger(self.0 * rhs.0)
    }
}
impl Neg for BigInteger {
    type Output = BigInteger;
    fn neg(self) -> BigInteger {
        BigInteger(-self.0)
    }
}
impl Ring for BigInteger {
    fn zero() -> Self {
        BigInteger(num_bigint::BigInt::from(0))
    }
    fn one() -> Self {
        BigInteger(num_bigint::BigInt::from(1))
    }
    fn from_i64(n: i64) -> Self {
        BigInteger(num_bigint::BigInt::from(n))
    }
    fn is_zero(&self) -> bool {
        self.0.sign() == num_bigint::Sign::NoSign
    }
}

/// The inputs times a common power of two that makes them all integers.
pub fn integer_scaled<const N: usize>(x: &[f64; N]) -> [BigInteger; N] {
    use num_bigint::BigInt;
    let parts: [(u64, i16, i8); N] = core::array::from_fn(|i| decode(x[i]));
    let min_exp = parts
        .iter()
        .filter(|p| p.0 != 0)
        .map(|p| p.1)
        .min()
        .unwrap_or(0);
    core::array::from_fn(|i| {
        let (m, e, sign) = parts[i];
        if m == 0 || !x[i].is_finite() {
            return <BigInteger as Ring>::zero();
        }
        let v = BigInt::from(m) << ((e - min_exp) as usize);
        BigInteger(if sign < 0 { -v } else { v })
    })
}

/// `x · 2^k`, computed in steps that cannot overflow an intermediate factor.
fn ldexp(mut x: f64, mut k: i32) -> f64 {
    const UP: f64 = 1.0715086071862673e301; // 2^1000
    const DOWN: f64 = 9.332636185032189e-302; // 2^-1000
    while k > 1000 {
        x *= UP;
        k -= 1000;
    }
    while k < -1000 {
        x *= DOWN;
        k += 1000;
    }
    x * f64::from_bits(((k + 1023) as u64) << 52)
}

/// The inputs scaled by a common power of two so that the largest is about 1, if that is
/// exact (no input underflows); `None` otherwise.
fn rescaled<const N: usize>(x: &[f64; N]) -> Option<[f64; N]> {
    let max = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if max == 0.0 || !max.is_finite() {
        return None;
    }
    let k = -(decode(max).1 as i32 + 52);
    if k == 0 {
        return None;
    }
    let y: [f64; N] = core::array::from_fn(|i| ldexp(x[i], k));
    if (0..N).all(|i| ldexp(y[i], -k) == x[i]) {
        Some(y)
    } else {
        None
    }
}

/// Whether some nonzero input lies outside `[2^-60, 2^60]`, where products in the `f64` filter
/// may underflow into its absolute error allowance or overflow.
fn extreme_magnitudes(x: &[f64]) -> bool {
    const LO: f64 = 8.673617379884035e-19; // 2^-60
    const HI: f64 = 1.152921504606847e18; // 2^60
    x.iter()
        .any(|&v| v != 0.0 && !(v.abs() >= LO && v.abs() <= HI))
}

#[cold]
#[inline(never)]
pub(crate) fn slow_sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering {
    if let Some(s) = P::exact_sign_direct(x) {
        counters::count_expansion();
        return s;
    }
    // Homogeneous predicates: retry the filter at unit scale before going exact (only worth it
    // when the magnitudes are extreme: the filter's bound is relative otherwise).
    let unit = rescaled(x);
    if let Some(y) = unit.as_ref().filter(|_| extreme_magnitudes(x)) {
        let e: [ErrF64; N] = core::array::from_fn(|i| ErrF64::exact(y[i]));
        if let Some(s) = P::eval(&e).sign() {
            counters::count_rescaled();
            return s;
        }
    }
    // Exact without allocation, unless the value needs more components than the expansions
    // hold (or leaves their safe range).
    let y = unit.as_ref().unwrap_or(x);
    let e: [Expansion; N] = core::array::from_fn(|i| Expansion::from_f64(y[i]));
    if let Some(s) = P::eval(&e).sign() {
        counters::count_expansion();
        return s;
    }
    counters::count_big_integer();
    exact_sign::<P, N>(x)
}

/// `x = sign · mantissa · 2^exponent` with an integer mantissa (finite `x`).
pub(crate) fn decode(x: f64) -> (u64, i16, i8) {
    let bits = x.to_bits();
    let sign: i8 = if bits >> 63 == 0 { 1 } else { -1 };
    let exponent = ((bits >> 52) & 0x7ff) as i16;
    let mantissa = if exponent == 0 {
        (bits & 0xf_ffff_ffff_ffff) << 1
    } else {
        (bits & 0xf_ffff_ffff_ffff) | 0x10_0000_0000_0000
    };
    (mantissa, exponent - (1023 + 52), sign)
}

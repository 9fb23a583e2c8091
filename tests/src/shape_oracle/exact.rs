//! Exact rational vectors and the signs of sums with square roots.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// An exact rational number.
pub type Q = BigRational;
/// An exact point or vector.
pub type P3 = [Q; 3];

/// The exact rational value of a finite `f64`.
pub fn q(x: f64) -> Q {
    BigRational::from_float(x).expect("the oracle takes finite values only")
}

/// The exact point of three `f64` coordinates.
pub fn p3(x: &nalgebra::Point3<f64>) -> P3 {
    [q(x.x), q(x.y), q(x.z)]
}

/// The exact vector of three `f64` components.
pub fn v3(x: &nalgebra::Vector3<f64>) -> P3 {
    [q(x.x), q(x.y), q(x.z)]
}

pub fn int(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

pub fn add(a: &P3, b: &P3) -> P3 {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

pub fn sub(a: &P3, b: &P3) -> P3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

pub fn scale(a: &P3, s: &Q) -> P3 {
    [&a[0] * s, &a[1] * s, &a[2] * s]
}

pub fn dot(a: &P3, b: &P3) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

pub fn cross(a: &P3, b: &P3) -> P3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

pub fn is_zero(a: &P3) -> bool {
    a.iter().all(Zero::is_zero)
}

/// The sign of a rational as an ordering against zero.
pub fn sign(x: &Q) -> Ordering {
    if x.is_positive() {
        Ordering::Greater
    } else if x.is_negative() {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

fn neg(o: Ordering) -> Ordering {
    o.reverse()
}

/// The exact sign of `x + y·√a` (`a >= 0`).
pub fn sign_root(x: &Q, y: &Q, a: &Q) -> Ordering {
    let sx = sign(x);
    let sy = if a.is_zero() {
        Ordering::Equal
    } else {
        sign(y)
    };
    if sy == Ordering::Equal || sx == sy {
        return sx;
    }
    if sx == Ordering::Equal {
        return sy;
    }
    // Opposite signs: the larger magnitude wins.
    let t = sign(&(x * x - y * y * a));
    if sx == Ordering::Greater {
        t
    } else {
        neg(t)
    }
}

/// The exact sign of `k + α·√a + β·√b` (`a, b >= 0`).
pub fn sign_two_roots(k: &Q, alpha: &Q, a: &Q, beta: &Q, b: &Q) -> Ordering {
    let su = sign_root(k, alpha, a);
    let sb = if b.is_zero() {
        Ordering::Equal
    } else {
        sign(beta)
    };
    if sb == Ordering::Equal || su == sb {
        return su;
    }
    if su == Ordering::Equal {
        return sb;
    }
    // (k + α√a)² − β²b = (k² + α²a − β²b) + 2kα·√a
    let two = int(2);
    let t = sign_root(
        &(k * k + alpha * alpha * a - beta * beta * b),
        &(two * k * alpha),
        a,
    );
    if su == Ordering::Greater {
        t
    } else {
        neg(t)
    }
}

/// `1` as a rational.
pub fn one() -> Q {
    Q::one()
}

/// The absolute value.
pub fn abs(x: &Q) -> Q {
    x.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signs_with_roots() {
        // 3 − √9 = 0, 3 − √8 > 0, 3 − √10 < 0
        assert_eq!(sign_root(&int(3), &int(-1), &int(9)), Ordering::Equal);
        assert_eq!(sign_root(&int(3), &int(-1), &int(8)), Ordering::Greater);
        assert_eq!(sign_root(&int(3), &int(-1), &int(10)), Ordering::Less);
        // √2 + √3 − √(5 + 2√6): zero; check near it: 3.14 < √2 + √3 ≈ 3.1463 < 3.15
        let k = Q::new(314.into(), 100.into());
        assert_eq!(
            sign_two_roots(&-k, &int(1), &int(2), &int(1), &int(3)),
            Ordering::Greater
        );
        let k = Q::new(315.into(), 100.into());
        assert_eq!(
            sign_two_roots(&-k, &int(1), &int(2), &int(1), &int(3)),
            Ordering::Less
        );
        // 5 − √2·... : 2√2 + 3√2 − 5√2 = 0
        assert_eq!(
            sign_two_roots(&int(0), &int(2), &int(2), &int(-2), &int(2)),
            Ordering::Equal
        );
    }
}

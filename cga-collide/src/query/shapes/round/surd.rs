//! Exact signs in the field `Q(√x, √y)`: the numbers `p + q√x + s√y + w√(xy)` with rational
//! `p, q, s, w` and fixed rationals `x, y >= 0`.
//!
//! A cylinder's or cone's surface is a quadric, so the distances the round pairs compare carry
//! square roots: the distance of a point to the axis (`√x`) and the axis length (`√y`). Every
//! comparison they need is the sign of such a number, decided here by squaring with the signs
//! tracked (`a + b√x` has the sign of `a` times the sign of `a² − b²x` when `a` and `b` have
//! opposite signs), so no root is ever rounded.

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use ga_core::scalar::Rational;
use num_traits::{Signed, Zero};

/// The sign of a rational as an [`Ordering`] against zero.
pub(crate) fn sign(r: &Rational) -> Ordering {
    if r.is_positive() {
        Ordering::Greater
    } else if r.is_negative() {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

fn times(a: Ordering, b: Ordering) -> Ordering {
    match (a, b) {
        (Ordering::Equal, _) | (_, Ordering::Equal) => Ordering::Equal,
        (x, y) if x == y => Ordering::Greater,
        _ => Ordering::Less,
    }
}

/// The sign of `a + b√x` for a rational `x >= 0`.
pub(crate) fn sign_root(a: &Rational, b: &Rational, x: &Rational) -> Ordering {
    let sb = if x.is_zero() {
        Ordering::Equal
    } else {
        sign(b)
    };
    let sa = sign(a);
    if sb == Ordering::Equal {
        return sa;
    }
    if sa == Ordering::Equal || sa == sb {
        return sb;
    }
    // Opposite signs: the term of larger magnitude wins; |a| > |b|√x iff a² > b²x.
    times(sa, sign(&(a * a - b * b * x)))
}

/// The two radicands of the field.
#[derive(Debug, Clone)]
pub(crate) struct Radicands {
    pub x: Rational,
    pub y: Rational,
}

/// `p + q√x + s√y + w√(xy)` for the [`Radicands`] it is used with.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Surd {
    pub p: Rational,
    pub q: Rational,
    pub s: Rational,
    pub w: Rational,
}

impl Surd {
    /// The rational `p`.
    pub(crate) fn rational(p: Rational) -> Self {
        Surd {
            p,
            q: Rational::zero(),
            s: Rational::zero(),
            w: Rational::zero(),
        }
    }

    /// `q√x`.
    pub(crate) fn root_x(q: Rational) -> Self {
        Surd {
            q,
            ..Surd::rational(Rational::zero())
        }
    }

    /// `s√y`.
    pub(crate) fn root_y(s: Rational) -> Self {
        Surd {
            s,
            ..Surd::rational(Rational::zero())
        }
    }

    /// The product in the field of `k`.
    pub(crate) fn mul(&self, o: &Surd, k: &Radicands) -> Surd {
        let (x, y) = (&k.x, &k.y);
        let xy = x * y;
        Surd {
            p: &self.p * &o.p + &self.q * &o.q * x + &self.s * &o.s * y + &self.w * &o.w * &xy,
            q: &self.p * &o.q + &self.q * &o.p + (&self.s * &o.w + &self.w * &o.s) * y,
            s: &self.p * &o.s + &self.s * &o.p + (&self.q * &o.w + &self.w * &o.q) * x,
            w: &self.p * &o.w + &self.w * &o.p + &self.q * &o.s + &self.s * &o.q,
        }
    }

    /// The exact sign in the field of `k` (both radicands must be `>= 0`).
    pub(crate) fn sign(&self, k: &Radicands) -> Ordering {
        // self = A + B√y with A = p + q√x and B = s + w√x.
        let sa = sign_root(&self.p, &self.q, &k.x);
        let sb = if k.y.is_zero() {
            Ordering::Equal
        } else {
            sign_root(&self.s, &self.w, &k.x)
        };
        if sb == Ordering::Equal {
            return sa;
        }
        if sa == Ordering::Equal || sa == sb {
            return sb;
        }
        // A² − yB² = (p² + q²x − y(s² + w²x)) + 2(pq − ysw)√x.
        let (x, y) = (&k.x, &k.y);
        let two = Rational::from_integer(2.into());
        let a = &self.p * &self.p + &self.q * &self.q * x
            - y * (&self.s * &self.s + &self.w * &self.w * x);
        let b = two * (&self.p * &self.q - y * &self.s * &self.w);
        times(sa, sign_root(&a, &b, x))
    }
}

impl Add for &Surd {
    type Output = Surd;
    fn add(self, o: &Surd) -> Surd {
        Surd {
            p: &self.p + &o.p,
            q: &self.q + &o.q,
            s: &self.s + &o.s,
            w: &self.w + &o.w,
        }
    }
}

impl Sub for &Surd {
    type Output = Surd;
    fn sub(self, o: &Surd) -> Surd {
        Surd {
            p: &self.p - &o.p,
            q: &self.q - &o.q,
            s: &self.s - &o.s,
            w: &self.w - &o.w,
        }
    }
}

impl Neg for &Surd {
    type Output = Surd;
    fn neg(self) -> Surd {
        Surd {
            p: -&self.p,
            q: -&self.q,
            s: -&self.s,
            w: -&self.w,
        }
    }
}

impl Mul<&Rational> for &Surd {
    type Output = Surd;
    fn mul(self, k: &Rational) -> Surd {
        Surd {
            p: &self.p * k,
            q: &self.q * k,
            s: &self.s * k,
            w: &self.w * k,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64) -> Rational {
        Rational::from_integer(n.into())
    }

    #[test]
    fn signs_of_single_roots() {
        // 3 − √9 = 0, 3 − √10 < 0, 3 − √8 > 0, −3 + √10 > 0.
        assert_eq!(sign_root(&r(3), &r(-1), &r(9)), Ordering::Equal);
        assert_eq!(sign_root(&r(3), &r(-1), &r(10)), Ordering::Less);
        assert_eq!(sign_root(&r(3), &r(-1), &r(8)), Ordering::Greater);
        assert_eq!(sign_root(&r(-3), &r(1), &r(10)), Ordering::Greater);
        assert_eq!(sign_root(&r(0), &r(-1), &r(0)), Ordering::Equal);
    }

    #[test]
    fn signs_of_two_roots() {
        let k = Radicands { x: r(2), y: r(3) };
        // √2 + √3 − √6 − 1 ≈ −0.3032 < 0, and + 0.3033 ≈ 0.0001 > 0.
        let v = Surd {
            p: r(-1),
            q: r(1),
            s: r(1),
            w: r(-1),
        };
        assert_eq!(v.sign(&k), Ordering::Less);
        let lifted = &v + &Surd::rational(Rational::new(3033.into(), 10000.into()));
        assert_eq!(lifted.sign(&k), Ordering::Greater);
        // (√2 − √3)² = 5 − 2√6 exactly: the difference is zero.
        let d = &Surd::root_x(r(1)) - &Surd::root_y(r(1));
        let sq = d.mul(&d, &k);
        let expected = Surd {
            p: r(5),
            q: r(0),
            s: r(0),
            w: r(-2),
        };
        assert_eq!((&sq - &expected).sign(&k), Ordering::Equal);
        // √2·√3 − √6 = 0, and 5 − 2√6 > 0 (≈ 0.101).
        assert_eq!(sq.sign(&k), Ordering::Greater);
        // √3 − √2 − 0.318 ≈ −0.0002 < 0; − 0.317 > 0.
        let a = &Surd::root_y(r(1)) - &Surd::root_x(r(1));
        let c1 = &a - &Surd::rational(Rational::new(318.into(), 1000.into()));
        let c2 = &a - &Surd::rational(Rational::new(317.into(), 1000.into()));
        assert_eq!(c1.sign(&k), Ordering::Less);
        assert_eq!(c2.sign(&k), Ordering::Greater);
    }
}

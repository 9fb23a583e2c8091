//! The scalar traits every generated product is generic over.
//!
//! The hierarchy is deliberately small:
//! * [`Ring`]: what a product needs (`+ - *`, negation, zero, one, small integers).
//!   Implemented by `f64`, `f32`, exact rationals, intervals, symbolic polynomials.
//! * [`Field`]: adds division (inverses, normalised sandwiches).
//! * [`Real`]: adds ordering, square roots and finiteness (norms, geometry).

use core::ops::{Add, Div, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};

/// A commutative ring with unit: the coefficients of generated multivectors.
///
/// Generated code only ever clones coefficients, adds, subtracts, multiplies and negates them,
/// so any type with these operations works, including non-`Copy` ones such as big rationals or
/// symbolic polynomials.
///
/// ```
/// use ga_core::scalar::Ring;
/// assert_eq!(<f64 as Ring>::from_i64(3), 3.0);
/// assert!(<f64 as Ring>::zero().is_zero());
/// ```
pub trait Ring:
    Clone
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
{
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The image of a (small) integer; used for literals such as `2` in formulas.
    fn from_i64(n: i64) -> Self;
    /// Whether this value is exactly the additive identity.
    fn is_zero(&self) -> bool;
}

/// A [`Ring`] with division by nonzero elements.
pub trait Field: Ring + Div<Output = Self> {
    /// The multiplicative inverse, or `None` for zero.
    fn checked_recip(&self) -> Option<Self> {
        if self.is_zero() {
            None
        } else {
            Some(Self::one() / self.clone())
        }
    }
    /// How good a pivot this value is in Gaussian elimination: larger is better, `0.0` only for
    /// zero. The default treats every nonzero value alike (right for exact types).
    fn pivot_score(&self) -> f64 {
        if self.is_zero() {
            0.0
        } else {
            1.0
        }
    }
    /// The unit roundoff `u` of the arithmetic (a bound on the relative error of one operation):
    /// `0.0` for exact types (the default), half the machine epsilon for floats. Checks of
    /// computed results (such as `inverse()` of the generated types) allow rounding errors of
    /// this size; with `0.0` they demand exact equality.
    fn unit_roundoff() -> f64 {
        0.0
    }
}

/// An ordered [`Field`] approximating (or exactly representing part of) the real numbers.
pub trait Real: Field + PartialOrd {
    /// The square root (for exact types, of the nearest `f64`, see the implementation).
    fn sqrt(&self) -> Self;
    /// The absolute value.
    fn abs(&self) -> Self;
    /// Whether the value is finite (always true for exact types).
    fn is_finite(&self) -> bool;
    /// The nearest `f64`.
    fn to_f64(&self) -> f64;
    /// The value of an `f64` (exactly, for exact types; panics are never raised: non-finite
    /// input maps to zero for exact types, see [`Real::try_from_f64`] to detect it).
    fn from_f64(x: f64) -> Self;
    /// The value of a finite `f64`, or `None` if it is not finite and the type cannot hold it.
    fn try_from_f64(x: f64) -> Option<Self> {
        Some(Self::from_f64(x))
    }
}

macro_rules! impl_float {
    ($t:ty) => {
        impl Ring for $t {
            #[inline(always)]
            fn zero() -> Self {
                0.0
            }
            #[inline(always)]
            fn one() -> Self {
                1.0
            }
            #[inline(always)]
            fn from_i64(n: i64) -> Self {
                n as $t
            }
            #[inline(always)]
            fn is_zero(&self) -> bool {
                *self == 0.0
            }
        }
        impl Field for $t {
            #[inline]
            fn pivot_score(&self) -> f64 {
                <$t>::abs(*self) as f64
            }
            #[inline]
            fn unit_roundoff() -> f64 {
                (<$t>::EPSILON / 2.0) as f64
            }
        }
        impl Real for $t {
            #[inline(always)]
            fn sqrt(&self) -> Self {
                <$t>::sqrt(*self)
            }
            #[inline(always)]
            fn abs(&self) -> Self {
                <$t>::abs(*self)
            }
            #[inline(always)]
            fn is_finite(&self) -> bool {
                <$t>::is_finite(*self)
            }
            #[inline(always)]
            fn to_f64(&self) -> f64 {
                *self as f64
            }
            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
        }
    };
}
impl_float!(f64);
impl_float!(f32);

/// Exact rational numbers with big-integer numerator and denominator.
pub type Rational = BigRational;

impl Ring for BigRational {
    fn zero() -> Self {
        num_traits::Zero::zero()
    }
    fn one() -> Self {
        num_traits::One::one()
    }
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    fn is_zero(&self) -> bool {
        num_traits::Zero::is_zero(self)
    }
}
impl Field for BigRational {}
impl Real for BigRational {
    /// The exact square root when the value is the square of a rational; otherwise the
    /// rational nearest to the `f64` square root (not exact: exact code avoids `sqrt`).
    fn sqrt(&self) -> Self {
        let n = self.numer().sqrt();
        let d = self.denom().sqrt();
        if &n * &n == *self.numer() && &d * &d == *self.denom() {
            return BigRational::new(n, d);
        }
        Self::from_f64(Real::to_f64(self).sqrt())
    }
    fn abs(&self) -> Self {
        Signed::abs(self)
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }
    fn from_f64(x: f64) -> Self {
        BigRational::from_float(x).unwrap_or_else(<BigRational as Ring>::zero)
    }
    fn try_from_f64(x: f64) -> Option<Self> {
        BigRational::from_float(x)
    }
}

/// Converts an `f64` to an exact rational, `None` for NaN and infinities.
///
/// ```
/// use ga_core::scalar::rational_from_f64;
/// let r = rational_from_f64(0.1).unwrap();
/// assert_ne!(r, ga_core::scalar::Rational::new(1.into(), 10.into())); // 0.1 is not 1/10
/// ```
pub fn rational_from_f64(x: f64) -> Option<Rational> {
    BigRational::from_float(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_round_trip_is_exact() {
        for x in [0.1, -3.5e-300, 1.7976931348623157e308, 5e-324] {
            let r = rational_from_f64(x).unwrap();
            assert_eq!(Real::to_f64(&r), x);
        }
        assert!(rational_from_f64(f64::NAN).is_none());
    }

    #[test]
    fn exact_sqrt_of_squares() {
        let r = BigRational::new(9.into(), 4.into());
        assert_eq!(Real::sqrt(&r), BigRational::new(3.into(), 2.into()));
    }
}

//! Elementary functions on [`Real`] scalars: what closed-form exponentials and logarithms need.

use super::{Rational, Real, Ring};

/// A [`Real`] with the elementary functions that exponentials, logarithms and square roots of
/// versors need.
///
/// `f64` and `f32` forward to the standard library. [`Rational`] evaluates them through the
/// nearest `f64` (so they are *not* exact), except at the arguments where the value is an exact
/// rational (`sin 0 = 0`, `cos 0 = 1`, `exp 0 = 1`, `ln 1 = 0`, …). The exponentials and
/// logarithms of this crate only call these functions on the parts of a versor that are not
/// nilpotent: translators, transversions and pure translations use ring operations alone and
/// stay exact over rationals.
///
/// ```
/// use ga_core::scalar::{Elementary, Rational};
/// assert_eq!(Elementary::cos(&0.0_f64), 1.0);
/// assert_eq!(<Rational as Elementary>::exp(&Rational::from_integer(0.into())), Rational::from_integer(1.into()));
/// ```
pub trait Elementary: Real {
    /// The sine (radians).
    fn sin(&self) -> Self;
    /// The cosine (radians).
    fn cos(&self) -> Self;
    /// The hyperbolic sine.
    fn sinh(&self) -> Self;
    /// The hyperbolic cosine.
    fn cosh(&self) -> Self;
    /// The inverse hyperbolic sine.
    fn asinh(&self) -> Self;
    /// The angle of the point `(x, y) = (other, self)` in `[-π, π]`, as `f64::atan2`.
    fn atan2(&self, other: &Self) -> Self;
    /// `e^self`.
    fn exp(&self) -> Self;
    /// The natural logarithm (NaN or the nearest representable answer for non-positive input,
    /// as the float types; callers check the sign first).
    fn ln(&self) -> Self;
    /// The machine epsilon: the relative rounding unit of the type (`0` for exact types). Used
    /// to tell rounding noise from a genuine value when classifying versors.
    fn epsilon() -> Self;
}

macro_rules! impl_elementary_float {
    ($t:ty) => {
        impl Elementary for $t {
            #[inline]
            fn sin(&self) -> Self {
                <$t>::sin(*self)
            }
            #[inline]
            fn cos(&self) -> Self {
                <$t>::cos(*self)
            }
            #[inline]
            fn sinh(&self) -> Self {
                <$t>::sinh(*self)
            }
            #[inline]
            fn cosh(&self) -> Self {
                <$t>::cosh(*self)
            }
            #[inline]
            fn asinh(&self) -> Self {
                <$t>::asinh(*self)
            }
            #[inline]
            fn atan2(&self, other: &Self) -> Self {
                <$t>::atan2(*self, *other)
            }
            #[inline]
            fn exp(&self) -> Self {
                <$t>::exp(*self)
            }
            #[inline]
            fn ln(&self) -> Self {
                <$t>::ln(*self)
            }
            #[inline]
            fn epsilon() -> Self {
                <$t>::EPSILON
            }
        }
    };
}
impl_elementary_float!(f64);
impl_elementary_float!(f32);

/// Evaluates `f` at the nearest `f64`, returning `exact` instead when the argument is `at`.
fn through_f64(x: &Rational, at: i64, exact: i64, f: impl Fn(f64) -> f64) -> Rational {
    if *x == <Rational as Ring>::from_i64(at) {
        <Rational as Ring>::from_i64(exact)
    } else {
        <Rational as Real>::from_f64(f(Real::to_f64(x)))
    }
}

impl Elementary for Rational {
    fn sin(&self) -> Self {
        through_f64(self, 0, 0, f64::sin)
    }
    fn cos(&self) -> Self {
        through_f64(self, 0, 1, f64::cos)
    }
    fn sinh(&self) -> Self {
        through_f64(self, 0, 0, f64::sinh)
    }
    fn cosh(&self) -> Self {
        through_f64(self, 0, 1, f64::cosh)
    }
    fn asinh(&self) -> Self {
        through_f64(self, 0, 0, f64::asinh)
    }
    fn atan2(&self, other: &Self) -> Self {
        // atan2(0, x) = 0 exactly for x > 0.
        if self.is_zero() && *other > Self::zero() {
            return Self::zero();
        }
        Self::from_f64(Real::to_f64(self).atan2(Real::to_f64(other)))
    }
    fn exp(&self) -> Self {
        through_f64(self, 0, 1, f64::exp)
    }
    fn ln(&self) -> Self {
        through_f64(self, 1, 0, f64::ln)
    }
    fn epsilon() -> Self {
        Self::zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_is_exact_at_the_rational_points() {
        let r = |n: i64| Rational::from_integer(n.into());
        assert_eq!(Elementary::sin(&r(0)), r(0));
        assert_eq!(Elementary::cos(&r(0)), r(1));
        assert_eq!(Elementary::ln(&r(1)), r(0));
        assert_eq!(Elementary::atan2(&r(0), &r(5)), r(0));
        assert_eq!(<Rational as Elementary>::epsilon(), r(0));
        // Elsewhere: the nearest f64, converted exactly.
        assert_eq!(Real::to_f64(&Elementary::exp(&r(1))), std::f64::consts::E);
    }
}

//! [`Zero`]: the result of a product that is zero by grade.
//!
//! When no pair of blades of the two operand types contributes to a product (`A ⌋ B` with
//! `grade A > grade B`, `A ∧ B` with grades summing past the dimension, the scalar product of
//! different grades, …), the generated product returns `Zero<T>`. It holds nothing, so the
//! product costs nothing and storing its result writes nothing; its value is known from the
//! types alone.

use core::fmt;
use core::marker::PhantomData;
use core::ops::{Add, Neg, Sub};

use crate::scalar::Rational;
use crate::scalar::Ring;
use crate::symbolic::Poly;

/// The value zero of a multivector over scalars `T`, known from the operand types alone: the
/// output of a product that is zero by grade. Zero-sized and `Copy` for every `T`.
///
/// ```
/// use ga_core::cga::{Pseudoscalar, Vector};
/// use ga_core::prelude::*;
/// use ga_core::Zero;
///
/// let v = Vector::new(1.0, 2.0, 3.0, 4.0, 5.0);
/// let i = Pseudoscalar::new(2.0);
/// let z: Zero<f64> = v.wedge(&i); // grades 1 + 5 exceed the dimension: zero by grade
/// assert_eq!(z.value(), 0.0);
/// assert_eq!(f64::from(z), 0.0);
/// assert_eq!(v + z, v);
/// assert_eq!(z.to_string(), "0");
/// assert_eq!(std::mem::size_of::<Zero<f64>>(), 0);
/// ```
// `fn() -> T` rather than `T`: a zero holds no `T`, so it is `Send`, `Sync` and `Copy` whatever
// `T` is (`Rational` and `Poly` are not `Copy`).
pub struct Zero<T>(PhantomData<fn() -> T>);

impl<T> Zero<T> {
    /// The zero of scalars `T`.
    pub const fn new() -> Self {
        Zero(PhantomData)
    }

    /// The zero as a scalar, `T::zero()`.
    pub fn value(&self) -> T
    where
        T: Ring,
    {
        T::zero()
    }

    /// The zero as a value of type `X` (a scalar or a generated multivector type).
    pub fn to<X: From<Self>>(self) -> X {
        X::from(self)
    }
}

impl<T> Clone for Zero<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for Zero<T> {}

impl<T> Default for Zero<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T> PartialEq for Zero<T> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<T> Eq for Zero<T> {}

impl<T> core::hash::Hash for Zero<T> {
    fn hash<H: core::hash::Hasher>(&self, _: &mut H) {}
}

impl<T> fmt::Debug for Zero<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Zero")
    }
}

/// Prints `0`, as the generated types print a multivector with no nonzero blade.
impl<T> fmt::Display for Zero<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("0")
    }
}

impl<T> Add for Zero<T> {
    type Output = Self;
    fn add(self, _: Self) -> Self {
        self
    }
}

impl<T> Sub for Zero<T> {
    type Output = Self;
    fn sub(self, _: Self) -> Self {
        self
    }
}

impl<T> Neg for Zero<T> {
    type Output = Self;
    fn neg(self) -> Self {
        self
    }
}

/// Zero as a scalar of each of `ga_core`'s scalar types (generated types convert with `From`
/// too; `value()` works for any [`Ring`]).
macro_rules! scalar_from_zero {
    ($($t:ty),*) => {$(
        impl From<Zero<$t>> for $t {
            fn from(_: Zero<$t>) -> $t {
                <$t as Ring>::zero()
            }
        }
    )*};
}

scalar_from_zero!(f64, f32, Rational, Poly);

impl<T: approx::AbsDiffEq> approx::AbsDiffEq for Zero<T> {
    type Epsilon = T::Epsilon;
    fn default_epsilon() -> T::Epsilon {
        T::default_epsilon()
    }
    fn abs_diff_eq(&self, _: &Self, _: T::Epsilon) -> bool {
        true
    }
}

impl<T: approx::RelativeEq> approx::RelativeEq for Zero<T> {
    fn default_max_relative() -> T::Epsilon {
        T::default_max_relative()
    }
    fn relative_eq(&self, _: &Self, _: T::Epsilon, _: T::Epsilon) -> bool {
        true
    }
}

impl<T: approx::UlpsEq> approx::UlpsEq for Zero<T> {
    fn default_max_ulps() -> u32 {
        T::default_max_ulps()
    }
    fn ulps_eq(&self, _: &Self, _: T::Epsilon, _: u32) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_is_zero_sized_and_its_value_is_the_scalar_zero() {
        assert_eq!(core::mem::size_of::<Zero<Rational>>(), 0);
        let z = Zero::<Rational>::new();
        assert_eq!(z.value(), <Rational as Ring>::zero());
        assert_eq!(Rational::from(z), <Rational as Ring>::zero());
        assert_eq!(Poly::from(Zero::<Poly>::new()), <Poly as Ring>::zero());
        assert_eq!(f32::from(Zero::<f32>::new()), 0.0);
    }

    #[test]
    fn zero_is_closed_under_sum_difference_and_negation() {
        let z = Zero::<f64>::new();
        assert_eq!(z + z, z);
        assert_eq!(z - z, z);
        assert_eq!(-z, z);
        assert_eq!(format!("{z} {z:?}"), "0 Zero");
    }
}

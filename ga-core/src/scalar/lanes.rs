//! SIMD lanes as scalars: the generated products evaluated on 4 (`f64`) or 8 (`f32`)
//! multivectors at once.
//!
//! [`F64x4`] and [`F32x8`] wrap the portable SIMD vectors of the `wide` crate. They are
//! [`Ring`]s and [`Field`]s lane by lane, so every generated type is usable with them:
//! `cga::Vector<F64x4>` holds four vectors (one per lane) and `a * b` computes four geometric
//! products with the same straight-line code, each operation a SIMD instruction (or two, when
//! the target has no 256-bit registers: compile with `-C target-cpu=native` for AVX).
//!
//! They are not [`Real`](super::Real): lanes have no total order. The comparisons a `Real`
//! would need are per lane and return masks in `wide`; use [`F64x4::lanes`] to leave the
//! SIMD world.
//!
//! ```
//! use ga_core::cga::Vector;
//! use ga_core::scalar::lanes::F64x4;
//! use ga_core::prelude::*;
//!
//! let a = Vector::new(F64x4::from([1.0, 2.0, 3.0, 4.0]), F64x4::splat(0.0), F64x4::splat(0.0),
//!                     F64x4::splat(1.0), F64x4::splat(0.0));
//! let b = Vector::new(F64x4::splat(2.0), F64x4::splat(1.0), F64x4::splat(0.0),
//!                     F64x4::splat(0.0), F64x4::splat(1.0));
//! let dots = a.scalar_product(&b);
//! assert_eq!(dots.lanes(), [2.0, 4.0, 6.0, 8.0]);
//! ```
//!
//! # Semantics
//! * `==` is true when every lane is equal; [`Ring::is_zero`] when every lane is zero.
//! * [`Field::checked_recip`] is `None` only when every lane is zero; a lane that is zero while
//!   others are not divides to `±inf`/NaN in that lane, as `f64` division does. Check the
//!   lanes you divide by ([`F64x4::any_zero`]) when that matters.
//! * [`Field::pivot_score`] is the largest absolute value over the lanes (`+inf` for a NaN
//!   lane), so a residual passes the checks of `inverse()` only when it passes in every lane.
//!   Gaussian elimination (`general_inverse`, and `inverse()` of non-versors) pivots on that
//!   score: a pivot zero in some lanes only divides to `inf`/NaN there (see above), and then the
//!   checked `inverse()` returns `None` for the whole batch. Per-lane pivoting is not possible
//!   with one instruction stream; the straight-line `versor_inverse()` is exact lane by lane.

use core::ops::{Add, Div, Mul, Neg, Sub};

use super::{Field, Ring};

macro_rules! lane_type {
    ($name:ident, $wide:ty, $elem:ty, $n:literal, $doc:literal) => {
        #[doc = $doc]
        #[derive(Clone, Copy, Default)]
        pub struct $name(pub $wide);

        impl $name {
            /// The number of lanes.
            pub const LANES: usize = $n;

            /// Every lane equal to `x`.
            #[inline(always)]
            pub fn splat(x: $elem) -> Self {
                Self(<$wide>::splat(x))
            }

            /// Lane `i` is `f(i)`.
            #[inline]
            pub fn from_fn(f: impl FnMut(usize) -> $elem) -> Self {
                Self(<$wide>::new(core::array::from_fn(f)))
            }

            /// The lanes as an array.
            #[inline(always)]
            pub fn lanes(&self) -> [$elem; $n] {
                self.0.to_array()
            }

            /// Lane `i`, `None` when `i >= LANES`.
            #[inline]
            pub fn lane(&self, i: usize) -> Option<$elem> {
                self.lanes().get(i).copied()
            }

            /// The square root of every lane.
            #[inline(always)]
            pub fn sqrt(&self) -> Self {
                Self(self.0.sqrt())
            }

            /// The absolute value of every lane.
            #[inline(always)]
            pub fn abs(&self) -> Self {
                Self(self.0.abs())
            }

            /// Whether every lane is finite.
            #[inline]
            pub fn all_finite(&self) -> bool {
                self.lanes().iter().all(|x| x.is_finite())
            }

            /// Whether some lane is zero.
            #[inline]
            pub fn any_zero(&self) -> bool {
                self.lanes().iter().any(|x| *x == 0.0)
            }
        }

        impl From<[$elem; $n]> for $name {
            #[inline(always)]
            fn from(a: [$elem; $n]) -> Self {
                Self(<$wide>::new(a))
            }
        }

        impl From<$name> for [$elem; $n] {
            #[inline(always)]
            fn from(v: $name) -> Self {
                v.lanes()
            }
        }

        impl PartialEq for $name {
            /// Every lane equal (so `NaN` lanes compare unequal, as for the element type).
            #[inline]
            fn eq(&self, other: &Self) -> bool {
                self.lanes() == other.lanes()
            }
        }

        impl core::fmt::Debug for $name {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                write!(f, "{:?}", self.lanes())
            }
        }

        impl core::fmt::Display for $name {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                write!(f, "{:?}", self.lanes())
            }
        }

        impl Add for $name {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                Self(self.0 + o.0)
            }
        }
        impl Sub for $name {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self {
                Self(self.0 - o.0)
            }
        }
        impl Mul for $name {
            type Output = Self;
            #[inline(always)]
            fn mul(self, o: Self) -> Self {
                Self(self.0 * o.0)
            }
        }
        impl Div for $name {
            type Output = Self;
            #[inline(always)]
            fn div(self, o: Self) -> Self {
                Self(self.0 / o.0)
            }
        }
        impl Neg for $name {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                Self(-self.0)
            }
        }

        impl Ring for $name {
            #[inline(always)]
            fn zero() -> Self {
                Self::splat(0.0)
            }
            #[inline(always)]
            fn one() -> Self {
                Self::splat(1.0)
            }
            #[inline(always)]
            fn from_i64(n: i64) -> Self {
                Self::splat(n as $elem)
            }
            #[inline]
            fn is_zero(&self) -> bool {
                self.lanes().iter().all(|x| *x == 0.0)
            }
        }

        impl Field for $name {
            /// The largest absolute value over the lanes, `+inf` if a lane is NaN: a residual
            /// is small only when it is small in every lane (the checked `inverse()` relies on
            /// this); see the [module documentation](self) for pivoting.
            #[inline]
            fn pivot_score(&self) -> f64 {
                self.lanes().iter().fold(0.0f64, |m, x| {
                    if x.is_nan() {
                        f64::INFINITY
                    } else {
                        m.max(x.abs() as f64)
                    }
                })
            }
            /// The unit roundoff of the element type.
            #[inline]
            fn unit_roundoff() -> f64 {
                (<$elem>::EPSILON / 2.0) as f64
            }
        }
    };
}

lane_type!(
    F64x4,
    wide::f64x4,
    f64,
    4,
    "Four `f64` lanes (`wide::f64x4`): a [`Ring`] and [`Field`] lane by lane."
);
lane_type!(
    F32x8,
    wide::f32x8,
    f32,
    8,
    "Eight `f32` lanes (`wide::f32x8`): a [`Ring`] and [`Field`] lane by lane."
);

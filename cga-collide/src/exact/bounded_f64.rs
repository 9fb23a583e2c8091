//! [`ErrF64`]: an `f64` value that carries a rigorous bound on its rounding error (running
//! error analysis). Evaluating a predicate's polynomial on it gives a value whose sign is
//! certain when the bound excludes zero: the cheap first stage of every exact decision.

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use ga_core::scalar::Ring;

/// Unit roundoff doubled (`2^-52`): per-operation relative error charged by [`ErrF64`]; the
/// factor two also pays for the rounding of the error bound itself.
const U: f64 = f64::EPSILON;
/// Absolute error charged to every multiplication for a possible underflow. The true bound is
/// `2^-1075`; the normal number `2^-900` is charged instead so that the error bookkeeping itself
/// never computes with subnormal numbers (very slow on common hardware). Predicates whose
/// values are that small go to the exact path, which is where they belong anyway.
const ETA: f64 = 1.1834109918413096e-271;

/// An `f64` value with a rigorous bound on the distance to the exact value of the expression
/// that produced it (running error analysis).
///
/// Each `+`/`-` adds `2^-52·|result|` to the bound, each `*` adds
/// `|a|·eb + |b|·ea + ea·eb + 2^-52·|result| + 2^-900` (the last term covers underflow).
/// Overflow produces infinities or NaN, which [`ErrF64::sign`] reports as uncertain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrF64 {
    /// The computed value.
    pub value: f64,
    /// A bound on `|value - exact|`.
    pub error: f64,
}

impl ErrF64 {
    /// An exactly known value (error bound zero).
    #[inline(always)]
    pub fn exact(value: f64) -> Self {
        ErrF64 { value, error: 0.0 }
    }

    /// The certain sign of the exact value, or `None` if the error bound does not exclude
    /// zero or the computation overflowed.
    #[inline(always)]
    pub fn sign(&self) -> Option<Ordering> {
        if self.error == 0.0 {
            // No rounding happened anywhere: the value is exact.
            return self.value.partial_cmp(&0.0);
        }
        // The margin covers the rounding of the bound's own computation.
        if self.value.abs() > self.error * (1.0 + 1e-9) {
            if self.value > 0.0 {
                Some(Ordering::Greater)
            } else {
                Some(Ordering::Less)
            }
        } else {
            None
        }
    }
}

impl Add for ErrF64 {
    type Output = ErrF64;
    #[inline(always)]
    fn add(self, rhs: ErrF64) -> ErrF64 {
        let value = self.value + rhs.value;
        ErrF64 {
            value,
            error: self.error + rhs.error + U * value.abs(),
        }
    }
}

impl Sub for ErrF64 {
    type Output = ErrF64;
    #[inline(always)]
    fn sub(self, rhs: ErrF64) -> ErrF64 {
        let value = self.value - rhs.value;
        ErrF64 {
            value,
            error: self.error + rhs.error + U * value.abs(),
        }
    }
}

impl Mul for ErrF64 {
    type Output = ErrF64;
    #[inline(always)]
    fn mul(self, rhs: ErrF64) -> ErrF64 {
        let value = self.value * rhs.value;
        // |a|·eb + |b|·ea + ea·eb, arranged so that no product of two error terms occurs.
        let error = self.value.abs() * rhs.error
            + (rhs.value.abs() + rhs.error) * self.error
            + U * value.abs()
            + ETA;
        ErrF64 { value, error }
    }
}

impl Neg for ErrF64 {
    type Output = ErrF64;
    #[inline(always)]
    fn neg(self) -> ErrF64 {
        ErrF64 {
            value: -self.value,
            error: self.error,
        }
    }
}

impl Ring for ErrF64 {
    fn zero() -> Self {
        ErrF64::exact(0.0)
    }
    fn one() -> Self {
        ErrF64::exact(1.0)
    }
    fn from_i64(n: i64) -> Self {
        let value = n as f64;
        // Exact for |n| <= 2^53; otherwise charge the conversion's rounding.
        let error = if (value as i64) == n && value.abs() <= 9_007_199_254_740_992.0 {
            0.0
        } else {
            U * value.abs()
        };
        ErrF64 { value, error }
    }
    fn is_zero(&self) -> bool {
        self.value == 0.0 && self.error == 0.0
    }
}

//! Scalars a computation can be re-run in, from least to most exact, and the one rule every
//! certified decision of the crate follows: run the computation on error-bounded [`ErrF64`]
//! first, and only when a sign there is uncertain, run the *same generic code* exactly.
//!
//! Polynomial predicates ([`super::Predicate`]) use this through [`super::ExactKernel`]; the
//! conformal primitives and meets ([`crate::conformal`]) rebuild their blades in a
//! [`CertifiedScalar`] and call [`decide`].

use core::cmp::Ordering;

use ga_core::scalar::{Rational, Ring};

use super::{rational_sign, ErrF64};

/// A ring a computation on `f64` inputs can be re-run in: plain `f64` (no certificate),
/// error-bounded [`ErrF64`] (certain signs when the bound excludes zero) and exact [`Rational`].
pub trait CertifiedScalar: Ring {
    /// The value of a finite `f64` input (exact for `ErrF64` and `Rational`).
    fn lift(x: f64) -> Self;
    /// The sign when it is certain (always for `Rational`; `None` for NaN in `f64`).
    fn certain_sign(&self) -> Option<Ordering>;
}

impl CertifiedScalar for f64 {
    fn lift(x: f64) -> Self {
        x
    }
    fn certain_sign(&self) -> Option<Ordering> {
        self.partial_cmp(&0.0)
    }
}

impl CertifiedScalar for ErrF64 {
    fn lift(x: f64) -> Self {
        ErrF64::exact(x)
    }
    fn certain_sign(&self) -> Option<Ordering> {
        self.sign()
    }
}

impl CertifiedScalar for Rational {
    fn lift(x: f64) -> Self {
        ga_core::scalar::rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
    }
    fn certain_sign(&self) -> Option<Ordering> {
        Some(rational_sign(self))
    }
}

/// Whether every coefficient is zero: `Some(true/false)` when certain, `None` otherwise.
pub fn all_zero<T: CertifiedScalar>(coefficients: &[T]) -> Option<bool> {
    let mut unknown = false;
    for c in coefficients {
        match c.certain_sign() {
            Some(Ordering::Equal) => {}
            Some(_) => return Some(false),
            None => unknown = true,
        }
    }
    if unknown {
        None
    } else {
        Some(true)
    }
}

/// Runs a certified computation: `filtered` (on [`ErrF64`]) first, then, if it could not
/// decide, `exact` (on [`Rational`]); `fallback` only if neither decided (not reached for
/// finite inputs, since exact arithmetic always decides).
pub fn decide<R>(
    filtered: impl FnOnce() -> Option<R>,
    exact: impl FnOnce() -> Option<R>,
    fallback: R,
) -> R {
    filtered().or_else(exact).unwrap_or(fallback)
}

//! Three-vectors as `[R; 3]` over any [`Ring`]: the few operations the predicates, the exact
//! geometry and the `f64` searches share, written once. Generic so that the same expression runs
//! on `f64`, on error-bounded `f64` and on exact rationals.

use ga_core::scalar::Ring;

/// A three-vector over a ring.
pub(crate) type V3<R> = [R; 3];

/// `a - b`.
#[inline(always)]
pub(crate) fn sub<R: Ring>(a: &V3<R>, b: &V3<R>) -> V3<R> {
    [
        a[0].clone() - b[0].clone(),
        a[1].clone() - b[1].clone(),
        a[2].clone() - b[2].clone(),
    ]
}

/// `a + s u`.
#[inline(always)]
pub(crate) fn add_scaled<R: Ring>(a: &V3<R>, u: &V3<R>, s: &R) -> V3<R> {
    [
        a[0].clone() + u[0].clone() * s.clone(),
        a[1].clone() + u[1].clone() * s.clone(),
        a[2].clone() + u[2].clone() * s.clone(),
    ]
}

/// `-a`.
#[inline(always)]
#[cfg(feature = "testing")] // only the test-support GJK reference negates exact vectors
pub(crate) fn neg<R: Ring>(a: &V3<R>) -> V3<R> {
    [-a[0].clone(), -a[1].clone(), -a[2].clone()]
}

/// `a · b`.
#[inline(always)]
pub(crate) fn dot<R: Ring>(a: &V3<R>, b: &V3<R>) -> R {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

/// `u × v`.
#[inline(always)]
pub(crate) fn cross<R: Ring>(u: &V3<R>, v: &V3<R>) -> V3<R> {
    [
        u[1].clone() * v[2].clone() - u[2].clone() * v[1].clone(),
        u[2].clone() * v[0].clone() - u[0].clone() * v[2].clone(),
        u[0].clone() * v[1].clone() - u[1].clone() * v[0].clone(),
    ]
}

/// `|a - b|²`.
#[inline(always)]
pub(crate) fn dist2<R: Ring>(a: &V3<R>, b: &V3<R>) -> R {
    let d = sub(a, b);
    dot(&d, &d)
}

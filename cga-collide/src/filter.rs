//! Certified signs of polynomials: an `f64` evaluation with a rigorous error bound, and the
//! exact rational evaluation of the *same* generic code when the bound cannot decide.
//!
//! A predicate is a polynomial written once, as straight-line code generic over
//! [`ga_core::scalar::Ring`] (a [`Poly`]). [`ExactKernel`] evaluates it first on [`ErrF64`]
//! (an `f64` value carrying a running bound on its rounding error, underflow and overflow
//! included) and, only if the sign is not certain, on [`Rational`] (exact `BigRational` made
//! from the `f64` inputs without rounding). [`FloatKernel`] evaluates it on plain `f64` and
//! believes the result: it is the "no exact fall-back" variant used to measure what rounding
//! costs.

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use num_traits::Signed;

/// Unit roundoff doubled (`2^-52`): per-operation relative error charged by [`ErrF64`]; the
/// factor two also pays for the rounding of the error bound itself.
const U: f64 = f64::EPSILON;
/// Largest absolute error of a multiplication whose result is subnormal (`2^-1074`).
const ETA: f64 = 5e-324;

/// An `f64` value with a rigorous bound on the distance to the exact value of the expression
/// that produced it (running error analysis).
///
/// Each `+`/`-` adds `2^-52·|result|` to the bound, each `*` adds
/// `|a|·eb + |b|·ea + ea·eb + 2^-52·|result| + 2^-1074` (the last term covers underflow).
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
        let error = self.value.abs() * rhs.error
            + rhs.value.abs() * self.error
            + self.error * rhs.error
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

/// A polynomial predicate in `N` `f64` inputs, written once for every [`Ring`].
pub trait Poly<const N: usize> {
    /// The polynomial's value at `x` (the same straight-line code for `f64`, [`ErrF64`] and
    /// [`Rational`]).
    fn eval<R: Ring>(x: &[R; N]) -> R;
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

/// The exact sign of `P` at `x`, computed with exact rationals only.
pub fn exact_sign<P: Poly<N>, const N: usize>(x: &[f64; N]) -> Ordering {
    let q: [Rational; N] =
        core::array::from_fn(|i| rational_from_f64(x[i]).unwrap_or_else(<Rational as Ring>::zero));
    rational_sign(&P::eval(&q))
}

/// The side of a point with respect to the (oriented) plane of a triangle, with the plane's
/// data computed once and reused for many points (as Möller computes a plane once).
pub trait PlaneSide {
    /// The sign of `orient3d(p0, p1, p2, q)` for the triangle `p0 p1 p2` this plane was made of.
    fn side(&self, q: &[f64; 3]) -> Ordering;
    /// Whether the three vertices are collinear (the plane is undefined).
    fn is_degenerate(&self) -> bool;
}

/// How predicate signs are decided. The algorithms in [`crate::intersect`] are generic over it.
pub trait Kernel {
    /// The cached plane of a triangle.
    type Plane: PlaneSide;
    /// The sign of the polynomial `P` at `x`.
    fn sign<P: Poly<N>, const N: usize>(x: &[f64; N]) -> Ordering;
    /// The plane of the triangle `p`.
    fn plane(p: &[[f64; 3]; 3]) -> Self::Plane;
}

/// Exact signs: certified `f64` first (a static filter for plane sides, [`ErrF64`] for the
/// other predicates), exact rationals when uncertain.
#[derive(Debug, Clone, Copy, Default)]
pub struct ExactKernel;

/// Plain `f64` signs without error bound or fall-back (wrong near zero; for comparison only).
#[derive(Debug, Clone, Copy, Default)]
pub struct FloatKernel;

impl Kernel for ExactKernel {
    type Plane = ExactPlane;
    #[inline]
    fn sign<P: Poly<N>, const N: usize>(x: &[f64; N]) -> Ordering {
        let e: [ErrF64; N] = core::array::from_fn(|i| ErrF64::exact(x[i]));
        match P::eval(&e).sign() {
            Some(s) => s,
            None => exact_sign::<P, N>(x),
        }
    }
    #[inline]
    fn plane(p: &[[f64; 3]; 3]) -> ExactPlane {
        ExactPlane::new(p)
    }
}

impl Kernel for FloatKernel {
    type Plane = FloatPlane;
    #[inline]
    fn sign<P: Poly<N>, const N: usize>(x: &[f64; N]) -> Ordering {
        P::eval(x).partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }
    #[inline]
    fn plane(p: &[[f64; 3]; 3]) -> FloatPlane {
        let u = sub(&p[1], &p[0]);
        let v = sub(&p[2], &p[0]);
        FloatPlane {
            a: p[0],
            n: cross(&u, &v),
        }
    }
}

#[inline(always)]
fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
fn cross(u: &[f64; 3], v: &[f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// A triangle's plane in plain `f64` ([`FloatKernel`]).
#[derive(Debug, Clone, Copy)]
pub struct FloatPlane {
    a: [f64; 3],
    n: [f64; 3],
}

impl PlaneSide for FloatPlane {
    #[inline]
    fn side(&self, q: &[f64; 3]) -> Ordering {
        let w = sub(q, &self.a);
        let d = w[0] * self.n[0] + w[1] * self.n[1] + w[2] * self.n[2];
        d.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }
    fn is_degenerate(&self) -> bool {
        self.n == [0.0; 3]
    }
}

/// Inputs of the static filter must be zero or have a magnitude in `[2^-300, 2^300]`: then no
/// product of three of them (nor any intermediate) overflows or underflows, and the classical
/// relative error analysis holds.
const RANGE_LO: f64 = 4.909093465297727e-91; // 2^-300
const RANGE_HI: f64 = 2.037035976334486e90; // 2^300
/// Error bound factor of `w·(u×v)` from rounded differences: `(1+ε)^8 - 1 < 8.0000001ε`,
/// rounded up together with the rounding of the permanent (ε = 2^-53).
const ORIENT_BOUND: f64 = 1.0e-15;
/// Error bound factor of a 2x2 minor `u_y v_z - u_z v_y` of rounded differences (`≈ 4ε`).
const MINOR_BOUND: f64 = 5.0e-16;

#[inline(always)]
fn in_range(x: f64) -> bool {
    let a = x.abs();
    a <= RANGE_HI && (a >= RANGE_LO || a == 0.0)
}

/// A triangle's plane for [`ExactKernel`]: the normal `n = (p1 - p0) × (p2 - p0)` and its
/// permanents, computed once. [`PlaneSide::side`] is a semi-static filter on `n·(q - p0)`
/// (Shewchuk-style bound `1e-15 · Σ|w_i|(|u_j v_k| + |u_k v_j|)`), with range checks that rule
/// out overflow and underflow, and the exact rational `orient3d` when it cannot decide.
///
/// In conformal terms this is the plane `P = up(p0) ∧ up(p1) ∧ up(p2) ∧ n_inf` taken in the
/// frame translated to `p0`, where `P` reduces to `n` (times `e123 ∧ n_0 ∧ n_inf` duals) and
/// `P ∧ up(q)` to `n·(q - p0)` times the pseudoscalar.
#[derive(Debug, Clone, Copy)]
pub struct ExactPlane {
    p: [[f64; 3]; 3],
    n: [f64; 3],
    m: [f64; 3],
    ok: bool,
}

impl ExactPlane {
    /// The plane of the triangle `p` with its filter data.
    #[inline]
    pub fn new(p: &[[f64; 3]; 3]) -> Self {
        let u = sub(&p[1], &p[0]);
        let v = sub(&p[2], &p[0]);
        let n = cross(&u, &v);
        let m = [
            (u[1] * v[2]).abs() + (u[2] * v[1]).abs(),
            (u[2] * v[0]).abs() + (u[0] * v[2]).abs(),
            (u[0] * v[1]).abs() + (u[1] * v[0]).abs(),
        ];
        let ok = in_range(u[0])
            & in_range(u[1])
            & in_range(u[2])
            & in_range(v[0])
            & in_range(v[1])
            & in_range(v[2]);
        ExactPlane { p: *p, n, m, ok }
    }
}

impl PlaneSide for ExactPlane {
    #[inline]
    fn side(&self, q: &[f64; 3]) -> Ordering {
        let w = sub(q, &self.p[0]);
        if self.ok & in_range(w[0]) & in_range(w[1]) & in_range(w[2]) {
            let det = w[0] * self.n[0] + w[1] * self.n[1] + w[2] * self.n[2];
            let perm = w[0].abs() * self.m[0] + w[1].abs() * self.m[1] + w[2].abs() * self.m[2];
            let bound = ORIENT_BOUND * perm;
            if det > bound {
                return Ordering::Greater;
            }
            if det < -bound {
                return Ordering::Less;
            }
            if perm == 0.0 {
                // Every term is exactly zero (no underflow is possible in range).
                return Ordering::Equal;
            }
        }
        let [a, b, c] = self.p;
        exact_sign::<crate::predicates::Orient3d, 12>(&[
            a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], q[0], q[1], q[2],
        ])
    }

    fn is_degenerate(&self) -> bool {
        if self.ok {
            let mut all_zero = true;
            for i in 0..3 {
                if self.n[i].abs() > MINOR_BOUND * self.m[i] {
                    return false;
                }
                all_zero &= self.m[i] == 0.0;
            }
            if all_zero {
                return true;
            }
        }
        let [a, b, c] = self.p;
        let x = [a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]];
        exact_sign::<crate::predicates::NormalX, 9>(&x) == Ordering::Equal
            && exact_sign::<crate::predicates::NormalY, 9>(&x) == Ordering::Equal
            && exact_sign::<crate::predicates::NormalZ, 9>(&x) == Ordering::Equal
    }
}

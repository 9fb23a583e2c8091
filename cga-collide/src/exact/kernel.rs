//! Certified signs of polynomials: an `f64` evaluation with a rigorous error bound, and the
//! exact evaluation of the *same* generic code when the bound cannot decide.
//!
//! A predicate is a polynomial written once, as straight-line code generic over
//! [`ga_core::scalar::Ring`] (a [`Predicate`]). [`ExactKernel`] evaluates it
//! 1. on [`ErrF64`] (an `f64` value carrying a running bound on its rounding error, underflow
//!    and overflow included); for the plane sides of the triangle tests a cheaper semi-static
//!    filter ([`ExactPlane`]) is used instead;
//! 2. if uncertain, on [`ErrF64`] again after scaling all inputs by a common power of two to
//!    unit size (exact; the predicates are homogeneous), which rescues coordinates around
//!    `1e±150` whose products would underflow or overflow;
//! 3. if still uncertain, exactly: the inputs are scaled to integers and the same code runs on
//!    [`BigInteger`] (exact rational arithmetic with the common denominator factored out; the
//!    tests cross-check it against `ga_core::scalar::Rational` evaluation).

use crate::exact::vector::{cross, sub};
use core::cmp::Ordering;

use super::predicates::Orient2d;
use super::sign::slow_sign;
use super::{ErrF64, Predicate};

/// The side of a point with respect to the (oriented) plane of a triangle, with the plane's
/// data computed once and reused for many points (as Möller computes a plane once).
pub trait PlaneSide {
    /// The sign of `orient3d(p0, p1, p2, q)` for the triangle `p0 p1 p2` this plane was made of.
    fn side(&self, q: &[f64; 3]) -> Ordering;
    /// The sides of the three vertices of `other`'s triangle.
    fn sides(&self, other: &Self) -> [Ordering; 3];
    /// The sides of three points.
    fn sides_of(&self, q: &[[f64; 3]; 3]) -> [Ordering; 3];
    /// Whether the three vertices are collinear (the plane is undefined).
    fn is_degenerate(&self) -> bool;
    /// An axis `k` whose normal component is certainly nonzero, when one is known cheaply:
    /// dropping coordinate `k` then maps the plane one-to-one onto a coordinate plane, so
    /// coplanar sets meet exactly when their projections do.
    fn projection_axis(&self) -> Option<usize>;
}

/// How predicate signs are decided. The algorithms in [`crate::query`] are generic over it.
pub trait Kernel {
    /// The cached plane of a triangle.
    type Plane: PlaneSide;
    /// The sign of the polynomial `P` at `x`.
    fn sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering;
    /// The plane of the triangle `p`.
    fn plane(p: &[[f64; 3]; 3]) -> Self::Plane;
    /// `orient3d(a, b, c, d)`, the sign of `(b - a) × (c - a) · (d - a)`.
    #[inline]
    fn orient3d(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3], d: &[f64; 3]) -> Ordering {
        Self::plane(&[*a, *b, *c]).side(d)
    }
    /// `orient2d(a, b, c)`, the sign of `(b - a) × (c - a)` in the plane.
    #[inline]
    fn orient2d(a: &[f64; 2], b: &[f64; 2], c: &[f64; 2]) -> Ordering {
        Self::sign::<Orient2d, 6>(&[a[0], a[1], b[0], b[1], c[0], c[1]])
    }
}

/// Exact signs: certified `f64` first (a semi-static filter for plane sides and `orient3d`,
/// [`ErrF64`] for the other predicates), exact rationals when uncertain.
#[derive(Debug, Clone, Copy, Default)]
pub struct ExactKernel;

impl Kernel for ExactKernel {
    type Plane = ExactPlane;
    #[inline]
    fn sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering {
        let e: [ErrF64; N] = core::array::from_fn(|i| ErrF64::exact(x[i]));
        match P::eval(&e).sign() {
            Some(s) => s,
            None => slow_sign::<P, N>(x),
        }
    }
    #[inline(always)]
    fn plane(p: &[[f64; 3]; 3]) -> ExactPlane {
        ExactPlane::new(p)
    }
    /// A semi-static filter (Shewchuk's bound for rounded differences and products, plus the
    /// underflow allowance), then the exact stages. The coplanar tests of engineering meshes
    /// call it for every edge pair, so it avoids [`ErrF64`]'s per-operation bookkeeping.
    #[inline]
    fn orient2d(a: &[f64; 2], b: &[f64; 2], c: &[f64; 2]) -> Ordering {
        let left = (b[0] - a[0]) * (c[1] - a[1]);
        let right = (b[1] - a[1]) * (c[0] - a[0]);
        let det = left - right;
        // Infinite or NaN terms fail both comparisons: no certificate.
        let bound = ORIENT2D_BOUND * (left.abs() + right.abs()) + UNDERFLOW;
        if det > bound {
            Ordering::Greater
        } else if -det > bound {
            Ordering::Less
        } else {
            slow_sign::<Orient2d, 6>(&[a[0], a[1], b[0], b[1], c[0], c[1]])
        }
    }
}

/// The index of the component of largest magnitude.
#[inline]
pub(crate) fn largest_component(n: &[f64; 3]) -> usize {
    let a = [n[0].abs(), n[1].abs(), n[2].abs()];
    if a[0] >= a[1] && a[0] >= a[2] {
        0
    } else if a[1] >= a[2] {
        1
    } else {
        2
    }
}

/// Error bound factor of `w·(u×v)` from rounded differences: `(1+ε)^8 - 1 < 8.0000001ε`,
/// rounded up together with the rounding of the permanent (ε = 2^-53).
const ORIENT_BOUND: f64 = 1.0e-15;
/// Error bound factor of `orient2d` from rounded differences and products, relative to
/// `|left| + |right|`: Shewchuk's `(3 + 16ε)ε` (ε = 2^-53), rounded up.
const ORIENT2D_BOUND: f64 = 3.4e-16;
/// Error bound factor of a 2x2 minor `u_y v_z - u_z v_y` of rounded differences (`≈ 4ε`).
const MINOR_BOUND: f64 = 5.0e-16;
/// Absolute error allowance for underflow: every product that underflows errs by at most
/// `2^-1075`; through the filter's formula the total is below `2^-1072 (1 + Σ|w_i|)`. The
/// normal number `2^-1000` is used as the factor (an over-estimate that keeps subnormals out).
const UNDERFLOW: f64 = 9.332636185032189e-302; // 2^-1000
/// Permanents above this (or NaN) mean an overflow may have happened: no certificate.
const PERM_MAX: f64 = 8.98846567431158e307; // 2^1023

/// A triangle's plane for [`ExactKernel`]: the normal `n = (p1 - p0) × (p2 - p0)` and its
/// permanents, computed once. [`PlaneSide::side`] is a semi-static filter on `n·(q - p0)`:
/// the sign is certain when `|det| > 1e-15 · Σ|w_i| · max_i m_i + 2^-1000 (1 + Σ|w_i|)`, with
/// `m_i = |u_j v_k| + |u_k v_j|` (a Shewchuk-style relative bound, the permanent
/// `Σ|w_i| m_i` bounded by one product so each point costs one multiplication, plus an
/// absolute allowance for underflow) and that bound is finite (no overflow); otherwise the
/// exact `orient3d` decides: an exact zero from zero differences (axis-aligned planes) first,
/// then floating-point expansions, then big integers.
///
/// In conformal terms this is the plane `P = up(p0) ∧ up(p1) ∧ up(p2) ∧ n_inf` taken in the
/// frame translated to `p0`, where `P ∧ up(q)` is `n·(q - p0)` times the pseudoscalar (see
/// [`crate::exact::predicates::Orient3d`]).
#[derive(Debug, Clone, Copy)]
pub struct ExactPlane {
    p: [[f64; 3]; 3],
    n: [f64; 3],
    m: [f64; 3],
    /// `1e-15 · max m + 2^-1000`: the per-point error bound is `k · Σ|w_i| + 2^-1000`.
    k: f64,
}

/// The components of the normal `(p1 - p0) × (p2 - p0)` that are exactly zero because each of
/// their two products has an exactly zero factor (a zero coordinate difference: equal
/// coordinates). Comparisons only; a cheap certificate of exact zeros on the axis-aligned
/// faces and edges of engineering meshes.
#[inline]
fn normal_zero(p: &[[f64; 3]; 3]) -> [bool; 3] {
    let (u, v) = (sub(&p[1], &p[0]), sub(&p[2], &p[0]));
    let zero = |x: f64, y: f64| x == 0.0 || y == 0.0;
    [
        zero(u[1], v[2]) && zero(u[2], v[1]),
        zero(u[2], v[0]) && zero(u[0], v[2]),
        zero(u[0], v[1]) && zero(u[1], v[0]),
    ]
}

/// Bounds at or above this mean the permanent may have overflowed: no certificate.
const BOUND_MAX: f64 = ORIENT_BOUND * PERM_MAX;

impl ExactPlane {
    /// The plane of the triangle `p` with its filter data.
    #[inline(always)]
    pub fn new(p: &[[f64; 3]; 3]) -> Self {
        let u = sub(&p[1], &p[0]);
        let v = sub(&p[2], &p[0]);
        let n = cross(&u, &v);
        let m = [
            (u[1] * v[2]).abs() + (u[2] * v[1]).abs(),
            (u[2] * v[0]).abs() + (u[0] * v[2]).abs(),
            (u[0] * v[1]).abs() + (u[1] * v[0]).abs(),
        ];
        let k = ORIENT_BOUND * m[0].max(m[1]).max(m[2]) + UNDERFLOW;
        ExactPlane { p: *p, n, m, k }
    }

    /// The triangle this plane was made of.
    #[inline(always)]
    pub fn corners(&self) -> &[[f64; 3]; 3] {
        &self.p
    }

    /// The side of `q` when the `f64` filter alone certifies it (`None` when only the exact
    /// evaluation could tell): for callers that only need certain answers and have a cheaper
    /// plan B than exact arithmetic.
    ///
    /// The bound is the permanent's `Σ|w_i| m_i ≤ Σ|w_i| · max m` (one multiplication per point
    /// instead of three), plus the underflow allowance.
    #[inline(always)]
    pub fn filtered_side(&self, q: &[f64; 3]) -> Option<Ordering> {
        let w = sub(q, &self.p[0]);
        let det = w[0] * self.n[0] + w[1] * self.n[1] + w[2] * self.n[2];
        let sum = w[0].abs() + w[1].abs() + w[2].abs();
        let bound = sum * self.k + UNDERFLOW;
        if bound < BOUND_MAX {
            if det > bound {
                return Some(Ordering::Greater);
            }
            if det < -bound {
                return Some(Ordering::Less);
            }
        }
        None
    }

    #[inline(always)]
    fn side_with(&self, q: &[f64; 3]) -> Ordering {
        match self.filtered_side(q) {
            Some(side) => side,
            None => self.exact_side(q),
        }
    }

    #[cold]
    #[inline(never)]
    fn exact_side(&self, q: &[f64; 3]) -> Ordering {
        // An exact zero without arithmetic: every term `w_k n_k` of `n·(q - p0)` has an exactly
        // zero factor (`q_k = p0_k`, or a normal component made of zero differences). The
        // common case on axis-aligned faces of engineering meshes.
        let [a, b, c] = self.p;
        let normal_zero = normal_zero(&self.p);
        if (0..3).all(|k| normal_zero[k] || q[k] == a[k]) {
            return Ordering::Equal;
        }
        // The plane's own filter already failed: straight to the exact stages.
        slow_sign::<crate::exact::predicates::Orient3d, 12>(&[
            a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], q[0], q[1], q[2],
        ])
    }
}

impl PlaneSide for ExactPlane {
    #[inline]
    fn side(&self, q: &[f64; 3]) -> Ordering {
        self.side_with(q)
    }

    #[inline(always)]
    fn sides(&self, other: &Self) -> [Ordering; 3] {
        self.sides_of(&other.p)
    }

    #[inline(always)]
    fn sides_of(&self, q: &[[f64; 3]; 3]) -> [Ordering; 3] {
        [
            self.side_with(&q[0]),
            self.side_with(&q[1]),
            self.side_with(&q[2]),
        ]
    }

    #[inline]
    fn is_degenerate(&self) -> bool {
        // A component of the normal is certainly nonzero (`m` finite: no overflow).
        if (self.n[0].abs() > MINOR_BOUND * self.m[0] + UNDERFLOW)
            | (self.n[1].abs() > MINOR_BOUND * self.m[1] + UNDERFLOW)
            | (self.n[2].abs() > MINOR_BOUND * self.m[2] + UNDERFLOW)
        {
            return false;
        }
        self.exact_degenerate()
    }

    #[inline]
    fn projection_axis(&self) -> Option<usize> {
        let k = largest_component(&self.n);
        (self.n[k].abs() > MINOR_BOUND * self.m[k] + UNDERFLOW && self.m[k] <= PERM_MAX)
            .then_some(k)
    }
}

impl ExactPlane {
    #[cold]
    #[inline(never)]
    fn exact_degenerate(&self) -> bool {
        let [a, b, c] = self.p;
        if normal_zero(&self.p) == [true; 3] {
            // Every normal component is made of zero differences: repeated corners, or corners
            // on an axis-parallel line.
            return true;
        }
        let x = [a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]];
        ExactKernel::sign::<crate::exact::predicates::NormalX, 9>(&x) == Ordering::Equal
            && ExactKernel::sign::<crate::exact::predicates::NormalY, 9>(&x) == Ordering::Equal
            && ExactKernel::sign::<crate::exact::predicates::NormalZ, 9>(&x) == Ordering::Equal
    }
}

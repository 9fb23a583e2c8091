//! Signed distances with a half-space: exact, by the support function.
//!
//! A convex shape `S = core ⊕ ball(s)` and the half-space `{x : (x − p)·m ≤ 0}` are apart by
//! `min over the core of (x − p)·m / |m| − s` when that is positive, and otherwise the
//! shortest translation that takes `S` out of the half-space is minus that value (along `m`):
//! the same expression is the signed distance in both cases. It is computed exactly (the
//! minimum over the core's points in rationals) and rounded once. Two half-spaces with
//! opposite normals form a slab or a gap, with signed distance `(p_b − p_a)·m_a / |m_a|`; any
//! other two overlap however far one is moved, and have no finite depth. A cylinder or a cone
//! has the same expression with its support function, which holds a square root: its sign is
//! decided exactly and its value bounded with outward rounding ([`to_round`]).

use ga_core::scalar::{Rational, Ring};
use nalgebra::{Point3, Vector3};
use num_traits::Signed;

use super::body::{q, Body};
use super::polytope::Core;
use super::rounding::{midpoint, signed_root_minus};
use super::SignedDistance;
use crate::exact::vector::{cross, dot, sub};
use crate::query::shapes::round::interval::{dot3, lift as lift3, norm2};
use crate::shape::HalfSpace;

fn lift(p: &Vector3<f64>) -> [Rational; 3] {
    [q(p.x), q(p.y), q(p.z)]
}

/// `N / √D − s` from the exact `N` and `D > 0`.
fn value(n: &Rational, d: &Rational, s: f64) -> (f64, f64, super::SignedDistanceKind) {
    signed_root_minus(n.is_positive(), &(n * n / d), [s, 0.0])
}

/// The signed distance from the half-space `h` to the polytopal shape with core `core`, with
/// the normal from the half-space to the shape (`flip` swaps the roles: the shape first).
pub(super) fn to_core(h: &HalfSpace, core: &Core, flip: bool) -> SignedDistance {
    let m = lift(h.normal());
    let p = lift(&h.point().coords);
    let mut best: Option<(Rational, usize)> = None;
    for (i, x) in core.points.iter().enumerate() {
        let g = dot(&sub(&x.lift(&q), &p), &m);
        if best.as_ref().is_none_or(|b| g < b.0) {
            best = Some((g, i));
        }
    }
    let (n, i) = best.unwrap_or_else(|| (<Rational as Ring>::zero(), 0));
    let (v, e, kind) = value(&n, &dot(&m, &m), core.radius);
    let up = super::unit(h.normal());
    let x = Point3::from(core.points[i].approx()) - up * core.radius;
    from_deepest(h, x, (v, e, kind), flip)
}

/// The signed distance `value` (with its bound and kind) from the half-space `h` to a shape
/// whose point deepest along the half-space's outward normal is `x`; the witnesses are `x` and
/// its shadow on the boundary plane moved by the value (`flip`: the shape first).
fn from_deepest(
    h: &HalfSpace,
    x: Point3<f64>,
    (value, error_bound, kind): (f64, f64, super::SignedDistanceKind),
    flip: bool,
) -> SignedDistance {
    let up = super::unit(h.normal());
    let on_plane = x - up * value;
    let (normal, witness_a, witness_b) = if flip {
        (-up, x, on_plane)
    } else {
        (up, on_plane, x)
    };
    SignedDistance {
        value,
        error_bound,
        normal,
        witness_a,
        witness_b,
        kind,
    }
}

/// The signed distance of two half-spaces when their normals are opposite, else `None` (no
/// translation separates them).
pub(super) fn between(a: &HalfSpace, b: &HalfSpace) -> Option<SignedDistance> {
    let (ma, mb) = (lift(a.normal()), lift(b.normal()));
    let c = cross(&ma, &mb);
    if !c.iter().all(|x| x.is_zero()) || !dot(&ma, &mb).is_negative() {
        return None;
    }
    let n = dot(
        &sub(&lift(&b.point().coords), &lift(&a.point().coords)),
        &ma,
    );
    let (v, e, kind) = value(&n, &dot(&ma, &ma), 0.0);
    let normal = super::unit(a.normal());
    Some(SignedDistance {
        value: v,
        error_bound: e,
        normal,
        witness_a: *a.point(),
        witness_b: a.point() + normal * v,
        kind,
    })
}

/// Exactly: the sign of `Q − √s` (`s ≥ 0`).
fn sign_minus_root(big_q: &Rational, s: &Rational) -> core::cmp::Ordering {
    use core::cmp::Ordering::{Equal, Less};
    if !big_q.is_positive() {
        return if big_q.is_zero() && s.is_zero() {
            Equal
        } else {
            Less
        };
    }
    (big_q * big_q).cmp(s)
}

/// The signed distance from the half-space `h` to a cylinder or cone `body` (`flip`: the
/// round shape first). The value `min over x of (x − p)·m / |m|` is
/// `(−h_S(−m) − p·m) / |m|`: bounded with outward rounding, its sign decided exactly branch by
/// branch (each `Q − √s` with exact `Q`, `s`), so touching is exactly 0.
pub(super) fn to_round(h: &HalfSpace, body: &Body, flip: bool) -> SignedDistance {
    use core::cmp::Ordering::{Equal, Less};
    let m = [h.normal().x, h.normal().y, h.normal().z];
    let minus = m.map(|x| -x);
    let p = [h.point().x, h.point().y, h.point().z];
    let (mq, pq) = (m.map(q), p.map(q));
    let pm = dot(&pq, &mq);
    let sign = body
        .branches(&minus)
        .iter()
        .map(|b| sign_minus_root(&(-b.q.clone() - &pm), &b.s))
        .min()
        .unwrap_or(Equal);
    let mi = lift3(&m);
    let g = body
        .support(&minus)
        .neg()
        .sub(dot3(&lift3(&p), &mi))
        .div_positive(norm2(&mi).sqrt());
    let (mut lo, mut hi) = (g.lo, g.hi);
    let kind = match sign {
        Less => {
            hi = hi.min(0.0);
            super::SignedDistanceKind::Penetrating
        }
        core::cmp::Ordering::Greater => {
            lo = lo.max(0.0);
            super::SignedDistanceKind::Separated
        }
        Equal => {
            (lo, hi) = (0.0, 0.0);
            super::SignedDistanceKind::Touching
        }
    };
    let (v, e) = midpoint(lo, hi);
    let x = body.support_point(&-super::unit(h.normal()));
    from_deepest(h, x, (v, e, kind), flip)
}

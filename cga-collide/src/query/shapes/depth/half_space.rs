//! Signed distances with a half-space: exact, by the support function.
//!
//! A convex shape `S = core ⊕ ball(s)` and the half-space `{x : (x − p)·m ≤ 0}` are apart by
//! `min over the core of (x − p)·m / |m| − s` when that is positive, and otherwise the
//! shortest translation that takes `S` out of the half-space is minus that value (along `m`):
//! the same expression is the signed distance in both cases. It is computed exactly (the
//! minimum over the core's points in rationals) and rounded once. Two half-spaces with
//! opposite normals form a slab or a gap, with signed distance `(p_b − p_a)·m_a / |m_a|`; any
//! other two overlap however far one is moved, and have no finite depth.

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::{Point3, Vector3};
use num_traits::Signed;

use super::polytope::Core;
use super::rounding::signed_root_minus;
use super::SignedDistance;
use crate::exact::vector::{cross, dot, sub};
use crate::shape::HalfSpace;

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

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
    let on_plane = x - up * v;
    let (normal, wa, wb) = if flip {
        (-up, x, on_plane)
    } else {
        (up, on_plane, x)
    };
    SignedDistance {
        value: v,
        error_bound: e,
        normal,
        witness_a: wa,
        witness_b: wb,
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

//! A cylinder or cone against a half-space.
//!
//! The lowest point of the solid along the outward normal `n` is on a cap disc (or at a cone's
//! apex): the disc of centre `c`, axis `d` and radius `r` reaches down to
//! `n·c − r·|n × d| / |d|`. The solid is within `e` of `{x : (x − p)·n <= 0}` iff some cap
//! disc (or the apex) reaches `(x − p)·n <= e|n|`; with `α = (c − p)·n` that is
//! `α√L − r√C − e√(|n|²L) <= 0` (`L = |d|²`, `C = |n × d|²`), decided exactly by squaring.

use core::cmp::Ordering;

use ga_core::scalar::Rational;

use super::exact3::{cross, dot, norm2, point, sub, Profile, Round, V3};
use super::surd::sign_root;
use crate::shape::HalfSpace;

/// The half-space as exact data.
struct Plane {
    point: V3,
    normal: V3,
    normal2: Rational,
}

/// Is the point within `e` of the half-space?
fn point_within(v: &V3, h: &Plane, e: &Rational) -> bool {
    let alpha = dot(&sub(v, &h.point), &h.normal);
    sign_root(&alpha, &-e, &h.normal2) != Ordering::Greater
}

/// Is the disc of centre `c` (axis and radius of `round`) within `e` of the half-space?
fn disc_within(c: &V3, round: &Round, h: &Plane, e: &Rational) -> bool {
    let alpha = dot(&sub(c, &h.point), &h.normal);
    // A = √L(α − e|n|), B = r√C >= 0: A − B <= 0 iff A <= 0 or A² <= B².
    if sign_root(&alpha, &-e, &h.normal2) != Ordering::Greater {
        return true;
    }
    let l = &round.length2;
    let c2 = norm2(&cross(&h.normal, &round.axis));
    let r = &round.radius;
    let rational = l * (&alpha * &alpha + e * e * &h.normal2) - r * r * &c2;
    let two = Rational::from_integer(2.into());
    let root = -(two * l * &alpha * e);
    sign_root(&rational, &root, &h.normal2) != Ordering::Greater
}

/// Exact: is the cylinder or cone within `e >= 0` of the half-space (`e = 0`: do they meet)?
pub(crate) fn within(round: &Round, h: &HalfSpace, e: &Rational) -> bool {
    let normal = point(&nalgebra::Point3::from(*h.normal()));
    within_plane(round, &point(h.point()), &normal, e)
}

/// [`within`] for the half-space `{x : (x − on)·normal <= 0}` given exactly (`normal != 0`).
pub(crate) fn within_plane(round: &Round, on: &V3, normal: &V3, e: &Rational) -> bool {
    let plane = Plane {
        point: on.clone(),
        normal: normal.clone(),
        normal2: norm2(normal),
    };
    match round.profile {
        Profile::Cylinder => {
            disc_within(&round.origin, round, &plane, e)
                || disc_within(&round.end, round, &plane, e)
        }
        Profile::Cone => {
            point_within(&round.origin, &plane, e) || disc_within(&round.end, round, &plane, e)
        }
    }
}

/// Exact: is the point `v` within `e >= 0` of `{x : (x − on)·normal <= 0}`?
pub(crate) fn point_within_plane(v: &V3, on: &V3, normal: &V3, e: &Rational) -> bool {
    let plane = Plane {
        point: on.clone(),
        normal: normal.clone(),
        normal2: norm2(normal),
    };
    point_within(v, &plane, e)
}

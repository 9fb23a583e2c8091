//! Rational points and vectors, and the cylinder or cone as exact rational data.

use ga_core::scalar::{rational_from_f64, Rational};
use nalgebra::Point3;
use num_traits::Zero;

use crate::shape::{Cone, Cylinder};

/// An exact point or vector.
pub(crate) type V3 = [Rational; 3];

/// The exact value of a finite `f64` (the shapes' constructors refuse every other value).
pub(crate) fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(Rational::zero)
}

pub(crate) fn point(p: &Point3<f64>) -> V3 {
    [q(p.x), q(p.y), q(p.z)]
}

pub(crate) fn sub(a: &V3, b: &V3) -> V3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

pub(crate) fn add(a: &V3, b: &V3) -> V3 {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

pub(crate) fn scale(a: &V3, k: &Rational) -> V3 {
    [&a[0] * k, &a[1] * k, &a[2] * k]
}

pub(crate) fn dot(a: &V3, b: &V3) -> Rational {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

pub(crate) fn cross(a: &V3, b: &V3) -> V3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

pub(crate) fn norm2(a: &V3) -> Rational {
    dot(a, a)
}

/// Which solid of revolution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Profile {
    /// Flat caps at both ends of the axis.
    Cylinder,
    /// Apex at the axis origin, base disc at its end.
    Cone,
}

/// A cylinder or a cone as exact data: the axis from `origin` (a cylinder's `a`, a cone's
/// apex) to `end` (a cylinder's `b`, a cone's base centre), `axis = end − origin` (never zero:
/// the constructors refuse it), `length2 = |axis|²`, and the radius.
#[derive(Debug, Clone)]
pub(crate) struct Round {
    pub profile: Profile,
    pub origin: V3,
    pub end: V3,
    pub axis: V3,
    pub length2: Rational,
    pub radius: Rational,
}

impl Round {
    fn new(profile: Profile, origin: &Point3<f64>, end: &Point3<f64>, radius: f64) -> Self {
        let origin = point(origin);
        let end = point(end);
        let axis = sub(&end, &origin);
        let length2 = norm2(&axis);
        Round {
            profile,
            origin,
            end,
            axis,
            length2,
            radius: q(radius),
        }
    }

    pub(crate) fn cylinder(c: &Cylinder) -> Self {
        Round::new(Profile::Cylinder, c.a(), c.b(), c.radius())
    }

    pub(crate) fn cone(c: &Cone) -> Self {
        Round::new(Profile::Cone, c.apex(), c.base(), c.radius())
    }
}

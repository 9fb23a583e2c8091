//! Curved against curved: a cylinder or cone against a cylinder or cone (a capsule is decided
//! exactly before it gets here, as its axis segment grown by its radius; the certificates below
//! still accept one).
//!
//! * Parallel cylinders are exact: in a frame along the common axis both are an interval times
//!   a disc, so they are within `e` iff the axial gap `g` and the gap between the discs `δ`
//!   satisfy `g² + δ² <= e²`.
//! * Every other pair is decided by exact certificates, each a rational or `a + b√c` sign:
//!   apart if the lines of the axes are farther apart than the radii and `e` (every one of these
//!   solids lies in the infinite cylinder around its axis), or if one solid misses the slab
//!   between the other's end planes (grown by `e`); meeting if the closest points of the two
//!   axis lines lie on both axis segments within the sum of the local radii and `e` (the
//!   segment between them crosses both solids), or if an end point of one lies in the other.
//! * Then a filter: approximate nearest points `x ∈ a`, `y ∈ b` (alternating projections in
//!   `f64`) suggest a plane between them, proved separating by the exact half-space tests, or
//!   points near them, proved to lie in `a` and within `e` of `b` by the exact point tests.
//!   Either proof settles the pair; a pair that touches or nearly does gets neither.
//!
//!   When no certificate applies the pair is left undecided (`None`), never guessed.

use core::cmp::Ordering;

use ga_core::scalar::Rational;
use num_traits::{One, Signed, Zero};

use super::distance::Solid;
use super::exact3::{add, cross, dot, norm2, point, q, scale, sub, Round, V3};
use super::half_space::{point_within_plane, within_plane};
use super::meridian;
use super::surd::sign_root;
use crate::shape::Shape;

/// What kind of tube around its axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Cylinder,
    /// Apex at the axis origin, the full radius at its end.
    Cone,
    Capsule,
}

/// A solid in the infinite cylinder of radius `radius` around the line of `origin + t·axis`.
struct Tube {
    kind: Kind,
    origin: V3,
    axis: V3,
    radius: Rational,
    round: Option<Round>,
}

impl Tube {
    fn of(s: &Shape) -> Option<Tube> {
        let (kind, round) = match s {
            Shape::Cylinder(c) => (Kind::Cylinder, Round::cylinder(c)),
            Shape::Cone(c) => (Kind::Cone, Round::cone(c)),
            Shape::Capsule(c) => {
                let (a, b) = (point(c.a()), point(c.b()));
                return Some(Tube {
                    kind: Kind::Capsule,
                    axis: sub(&b, &a),
                    origin: a,
                    radius: q(c.radius()),
                    round: None,
                });
            }
            _ => return None,
        };
        Some(Tube {
            kind,
            origin: round.origin.clone(),
            axis: round.axis.clone(),
            radius: round.radius.clone(),
            round: Some(round),
        })
    }

    fn end(&self) -> V3 {
        add(&self.origin, &self.axis)
    }

    /// The radius of the solid's cross-section at axis parameter `t ∈ [0, 1]`.
    fn local_radius(&self, t: &Rational) -> Rational {
        match self.kind {
            Kind::Cone => &self.radius * t,
            Kind::Cylinder | Kind::Capsule => self.radius.clone(),
        }
    }

    /// Is this solid within `e` of `{x : (x − on)·normal <= 0}`?
    fn within_plane(&self, on: &V3, normal: &V3, e: &Rational) -> bool {
        match &self.round {
            Some(r) => within_plane(r, on, normal, e),
            None => {
                let reach = e + &self.radius;
                point_within_plane(&self.origin, on, normal, &reach)
                    || point_within_plane(&self.end(), on, normal, &reach)
            }
        }
    }

    /// The two half-spaces whose intersection holds this solid: `(on, outward normal, grown)`,
    /// the half-space being `{x : (x − on)·normal <= 0}` grown by `grown`.
    fn slab(&self) -> [(V3, V3, Rational); 2] {
        let grown = match self.kind {
            Kind::Capsule => self.radius.clone(),
            Kind::Cylinder | Kind::Cone => Rational::zero(),
        };
        let back = scale(&self.axis, &-Rational::one());
        [
            (self.origin.clone(), back, grown.clone()),
            (self.end(), self.axis.clone(), grown),
        ]
    }

    /// Points of the solid with the radius of a ball around each that the solid holds.
    fn inner_balls(&self) -> Vec<(V3, Rational)> {
        match self.kind {
            Kind::Capsule => vec![
                (self.origin.clone(), self.radius.clone()),
                (self.end(), self.radius.clone()),
            ],
            Kind::Cylinder | Kind::Cone => {
                vec![
                    (self.origin.clone(), Rational::zero()),
                    (self.end(), Rational::zero()),
                ]
            }
        }
    }
}

/// Parallel cylinders, exactly.
fn parallel_cylinders(a: &Tube, b: &Tube, e: &Rational) -> bool {
    let d = &a.axis;
    let l = norm2(d);
    // Axial intervals, in units of d·x.
    let span = |t: &Tube| {
        let (u, v) = (dot(&t.origin, d), dot(&t.end(), d));
        if u <= v {
            (u, v)
        } else {
            (v, u)
        }
    };
    let ((a0, a1), (b0, b1)) = (span(a), span(b));
    let gap = if b0 > a1 {
        &b0 - &a1
    } else if a0 > b1 {
        &a0 - &b1
    } else {
        Rational::zero()
    };
    // Squared distance of the lines: X = |w × d|² / L.
    let x = norm2(&cross(&sub(&b.origin, &a.origin), d)) / &l;
    let reach = &a.radius + &b.radius;
    let g2 = &gap * &gap / &l;
    if x <= &reach * &reach {
        return g2 <= e * e;
    }
    // g² + (√X − R)² <= e², with √X > R.
    let two = Rational::from_integer(2.into());
    let rational = &g2 + &x + &reach * &reach - e * e;
    sign_root(&rational, &-(two * &reach), &x) != Ordering::Greater
}

/// The certificates of the module documentation; `None` when none applies.
fn certify(a: &Tube, b: &Tube, e: &Rational) -> Option<bool> {
    let n = cross(&a.axis, &b.axis);
    let w = sub(&b.origin, &a.origin);
    let reach = &a.radius + &b.radius + e;
    let n2 = norm2(&n);
    if n2.is_positive() {
        let wn = dot(&w, &n);
        if &wn * &wn > &reach * &reach * &n2 {
            return Some(false);
        }
    }
    for (x, y) in [(a, b), (b, a)] {
        for (on, normal, grown) in x.slab() {
            if !y.within_plane(&on, &normal, &(e + grown)) {
                return Some(false);
            }
        }
    }
    if n2.is_positive() {
        let (aa, bb, cc) = (norm2(&a.axis), dot(&a.axis, &b.axis), norm2(&b.axis));
        let (dd, ff) = (dot(&a.axis, &w), dot(&b.axis, &w));
        let ta = (&cc * &dd - &bb * &ff) / &n2;
        let tb = (&bb * &dd - &aa * &ff) / &n2;
        let unit = |t: &Rational| !t.is_negative() && *t <= Rational::one();
        if unit(&ta) && unit(&tb) {
            let gap = sub(&add(&w, &scale(&b.axis, &tb)), &scale(&a.axis, &ta));
            let local = a.local_radius(&ta) + b.local_radius(&tb) + e;
            if norm2(&gap) <= &local * &local {
                return Some(true);
            }
        }
    }
    for (x, y) in [(a, b), (b, a)] {
        if let Some(r) = &x.round {
            for (centre, radius) in y.inner_balls() {
                if meridian::point_within(r, &centre, &(radius + e)) {
                    return Some(true);
                }
            }
        }
    }
    None
}

/// Alternating projections between the two solids: for disjoint convex sets they converge to
/// a nearest pair, for overlapping ones to a common point.
const PROJECTIONS: usize = 64;

/// How far candidate common points are moved from the approximate contact into each solid.
const INWARD: [f64; 5] = [0.0, 1e-9, 1e-6, 1e-3, 0.05];

fn exact(v: &nalgebra::Vector3<f64>) -> V3 {
    [q(v.x), q(v.y), q(v.z)]
}

/// The `f64` filter of the module documentation, on two cylinders or cones.
fn filtered(sa: &Solid, ra: &Round, sb: &Solid, rb: &Round, e: &Rational) -> Option<bool> {
    let mut y = sb.centre();
    let mut x = sa.nearest(&y);
    for _ in 0..PROJECTIONS {
        y = sb.nearest(&x);
        x = sa.nearest(&y);
    }
    if !(x.iter().chain(y.iter()).all(|c| c.is_finite())) {
        return None;
    }
    let u = y - x;
    let gap = u.norm();
    let ef = num_traits::ToPrimitive::to_f64(e).unwrap_or(f64::INFINITY);
    if gap.is_finite() && gap > ef {
        // The plane through the middle of what is left of the gap once `e` is taken off.
        let on = exact(&(x + u * (0.5 * (1.0 - ef / gap))));
        let normal = exact(&u);
        let back = scale(&normal, &-Rational::one());
        if !within_plane(ra, &on, &back, &Rational::zero()) && !within_plane(rb, &on, &normal, e) {
            return Some(false);
        }
    }
    let zero = Rational::zero();
    for (p, centre) in [(x, sa.centre()), (y, sb.centre())] {
        for s in INWARD {
            let c = exact(&(p + (centre - p) * s));
            if meridian::point_within(ra, &c, &zero) && meridian::point_within(rb, &c, e) {
                return Some(true);
            }
        }
    }
    None
}

/// Exact: is `a` within `e` of `b` (each a cylinder, cone or capsule, at least one not a
/// capsule)? `None` when no exact method applies yet.
pub(crate) fn within(a: &Shape, b: &Shape, e: &Rational) -> Option<bool> {
    let (ta, tb) = (Tube::of(a)?, Tube::of(b)?);
    if ta.kind == Kind::Cylinder
        && tb.kind == Kind::Cylinder
        && norm2(&cross(&ta.axis, &tb.axis)).is_zero()
    {
        return Some(parallel_cylinders(&ta, &tb, e));
    }
    certify(&ta, &tb, e).or_else(|| {
        let (sa, sb) = (super::solid(a)?, super::solid(b)?);
        filtered(&sa, ta.round.as_ref()?, &sb, tb.round.as_ref()?, e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Cylinder;
    use nalgebra::Point3;

    fn cyl(a: [f64; 3], b: [f64; 3], r: f64) -> Shape {
        Cylinder::new(Point3::from(a), Point3::from(b), r)
            .expect("valid")
            .into()
    }

    /// Pairs the certificates leave (the closest points of the axis lines are off the first
    /// axis segment, no end point is inside the other) are settled by the proved filter.
    #[test]
    fn the_filter_settles_what_the_certificates_leave() {
        let post = cyl([0.0, 0.0, 0.0], [0.0, 0.0, 4.0], 1.0);
        let zero = Rational::zero();
        // Across the top, overlapping the cap: (0, 0.8, 4) is in both.
        let over = cyl([-3.0, 0.8, 4.5], [3.0, 0.8, 4.5], 0.9);
        // Across the top near the rim, 0.0296… above it.
        let above = cyl([1.5, -3.0, 4.9], [1.5, 3.0, 4.9], 1.0);
        for (other, expected) in [(&over, true), (&above, false)] {
            let (ta, tb) = (
                Tube::of(&post).expect("tube"),
                Tube::of(other).expect("tube"),
            );
            assert_eq!(certify(&ta, &tb, &zero), None, "a certificate applies");
            assert_eq!(within(&post, other, &zero), Some(expected));
            assert_eq!(within(other, &post, &zero), Some(expected));
        }
        // Within 0.03 of each other, not within 0.029.
        let near = Rational::new(3.into(), 100.into());
        let less = Rational::new(29.into(), 1000.into());
        assert_eq!(within(&post, &above, &near), Some(true));
        assert_eq!(within(&post, &above, &less), Some(false));
    }
}

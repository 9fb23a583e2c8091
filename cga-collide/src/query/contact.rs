//! The exact intersection of two closed triangles: a point, a segment or a coplanar convex
//! polygon, in rationals ([`triangle_intersection`]). The contact class of two closed meshes is
//! built on it and on the pieces below (clipping, exact points).

use core::cmp::Ordering;

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::Point3;
use num_traits::Signed;

use crate::exact::vector::{cross, dot, sub};
use crate::query::Intersects;
use crate::shape::Triangle;

/// An exact point.
pub type ExactPoint = [Rational; 3];

/// The intersection of two closed triangles, exactly.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactGeometry {
    /// They meet in one point.
    Point(ExactPoint),
    /// They meet in a segment of positive length (its two end points).
    Segment(ExactPoint, ExactPoint),
    /// They are coplanar and overlap in a convex polygon of positive area (its corners in
    /// order around it).
    Polygon(Vec<ExactPoint>),
}

impl ContactGeometry {
    /// The corners as `f64` (nearest values), for drawing and for files.
    pub fn points_f64(&self) -> Vec<[f64; 3]> {
        let f = |p: &ExactPoint| p.clone().map(|x| ga_core::scalar::Real::to_f64(&x));
        match self {
            ContactGeometry::Point(p) => vec![f(p)],
            ContactGeometry::Segment(p, q) => vec![f(p), f(q)],
            ContactGeometry::Polygon(ps) => ps.iter().map(f).collect(),
        }
    }
}

pub(crate) type Q3 = ExactPoint;

pub(crate) fn q3(p: &Point3<f64>) -> Q3 {
    [p.x, p.y, p.z].map(|x| rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero))
}
pub(crate) fn lerp(a: &Q3, b: &Q3, t: &Rational) -> Q3 {
    let d = sub(b, a);
    [&a[0] + &d[0] * t, &a[1] + &d[1] * t, &a[2] + &d[2] * t]
}
pub(crate) fn is_zero(v: &Q3) -> bool {
    v.iter().all(Ring::is_zero)
}
pub(crate) fn zero() -> Rational {
    <Rational as Ring>::zero()
}
pub(crate) fn one() -> Rational {
    <Rational as Ring>::one()
}
pub(crate) fn half() -> Rational {
    Rational::new(1.into(), 2.into())
}

/// The parameter interval `[t0, t1] ⊂ [0, 1]` of segment `ab` inside the closed segment `cd`.
fn clip_segment(a: &Q3, b: &Q3, c: &Q3, d: &Q3) -> Option<(Rational, Rational)> {
    let (u, v, w) = (sub(b, a), sub(d, c), sub(c, a));
    if is_zero(&u) {
        // `ab` is a point: on `cd`?
        let x = sub(a, c);
        let on = is_zero(&cross(&v, &x)) && {
            let t = dot(&x, &v);
            !t.is_negative() && t <= dot(&v, &v)
        };
        return on.then(|| (zero(), zero()));
    }
    let n = cross(&u, &v);
    if !is_zero(&n) {
        if !dot(&n, &w).is_zero() {
            return None; // skew lines
        }
        let nn = dot(&n, &n);
        let s = dot(&cross(&w, &v), &n) / &nn;
        let t = dot(&cross(&w, &u), &n) / &nn;
        let inside = |x: &Rational| !x.is_negative() && x <= &one();
        return (inside(&s) && inside(&t)).then(|| (s.clone(), s));
    }
    if !is_zero(&cross(&u, &w)) {
        return None; // parallel, not collinear
    }
    let uu = dot(&u, &u);
    let tc = dot(&w, &u) / &uu;
    let td = dot(&sub(d, a), &u) / &uu;
    let (lo, hi) = if tc <= td { (tc, td) } else { (td, tc) };
    let (lo, hi) = (lo.max(zero()), hi.min(one()));
    (lo <= hi).then_some((lo, hi))
}

/// The parameter interval of segment `ab` inside the closed triangle `t` (any triangle).
pub(crate) fn clip(a: &Q3, b: &Q3, t: &[Q3; 3]) -> Option<(Rational, Rational)> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    if is_zero(&n) {
        // A degenerate triangle is the union of its edges (one of them covers it).
        let mut out: Option<(Rational, Rational)> = None;
        for i in 0..3 {
            if let Some((lo, hi)) = clip_segment(a, b, &t[i], &t[(i + 1) % 3]) {
                out = Some(match out {
                    None => (lo, hi),
                    Some((l, h)) => (l.min(lo), h.max(hi)),
                });
            }
        }
        return out;
    }
    let edge = |x: &Q3, i: usize| dot(&cross(&sub(&t[(i + 1) % 3], &t[i]), &sub(x, &t[i])), &n);
    let (da, db) = (dot(&n, &sub(a, &t[0])), dot(&n, &sub(b, &t[0])));
    if da.is_zero() && db.is_zero() {
        let (mut lo, mut hi) = (zero(), one());
        for i in 0..3 {
            let (f0, f1) = (edge(a, i), edge(b, i));
            let slope = &f1 - &f0;
            if slope.is_zero() {
                if f0.is_negative() {
                    return None;
                }
            } else {
                let root = -&f0 / &slope;
                if slope.is_positive() {
                    lo = lo.max(root);
                } else {
                    hi = hi.min(root);
                }
            }
        }
        return (lo <= hi).then_some((lo, hi));
    }
    if (da.is_positive() && db.is_positive()) || (da.is_negative() && db.is_negative()) {
        return None;
    }
    let s = &da / (&da - &db);
    let x = lerp(a, b, &s);
    (0..3)
        .all(|i| !edge(&x, i).is_negative())
        .then(|| (s.clone(), s))
}

/// The intersection of two closed triangles, exactly; `None` when they do not meet.
///
/// The intersection is convex, and each of its corners is an end point of the part of some
/// edge of one triangle inside the other; those end points are computed in rationals and
/// sorted into a point, a segment or a polygon.
///
/// ```
/// use cga_collide::{nalgebra::Point3, query::{self, ContactGeometry}, Triangle};
/// let p = |x, y, z| Point3::new(x, y, z);
/// let a = Triangle::new(p(0., 0., 0.), p(2., 0., 0.), p(0., 2., 0.))?;
/// let b = Triangle::new(p(0.5, 0.5, -1.), p(0.5, 0.5, 1.), p(3., 3., 0.))?;
/// assert!(matches!(query::triangle_intersection(&a, &b), Some(ContactGeometry::Segment(..))));
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn triangle_intersection(a: &Triangle, b: &Triangle) -> Option<ContactGeometry> {
    if !a.intersects(b) {
        return None;
    }
    let (p, r) = (a.vertices().map(|v| q3(&v)), b.vertices().map(|v| q3(&v)));
    let mut pts: Vec<Q3> = Vec::new();
    for (s, t) in [(&p, &r), (&r, &p)] {
        for i in 0..3 {
            let (x, y) = (&s[i], &s[(i + 1) % 3]);
            if let Some((t0, t1)) = clip(x, y, t) {
                for e in [lerp(x, y, &t0), lerp(x, y, &t1)] {
                    if !pts.contains(&e) {
                        pts.push(e);
                    }
                }
            }
        }
    }
    Some(shape_of(pts))
}

fn shape_of(mut pts: Vec<Q3>) -> ContactGeometry {
    if pts.len() == 1 {
        return ContactGeometry::Point(pts.remove(0));
    }
    let o = pts[0].clone();
    // A point off the line through the first two: then it is a polygon.
    let normal = pts[2..]
        .iter()
        .map(|x| cross(&sub(&pts[1], &o), &sub(x, &o)))
        .find(|n| !is_zero(n));
    let Some(n) = normal else {
        // Collinear: the two extremes along the line.
        let dir = sub(&pts[1], &o);
        let key = |x: &Q3| dot(&sub(x, &o), &dir);
        let lo = pts.iter().min_by(|x, y| key(x).cmp(&key(y))).cloned();
        let hi = pts.iter().max_by(|x, y| key(x).cmp(&key(y))).cloned();
        return match (lo, hi) {
            (Some(lo), Some(hi)) => ContactGeometry::Segment(lo, hi),
            _ => ContactGeometry::Point(o),
        };
    };
    // Keep only the corners (drop points strictly inside a segment between two others).
    let between = |x: &Q3, y: &Q3, z: &Q3| {
        x != y
            && x != z
            && is_zero(&cross(&sub(y, x), &sub(z, x)))
            && dot(&sub(y, x), &sub(z, x)).is_negative()
    };
    let corners: Vec<Q3> = pts
        .iter()
        .filter(|x| !pts.iter().any(|y| pts.iter().any(|z| between(x, y, z))))
        .cloned()
        .collect();
    let mut pts = corners;
    // Convex position: sort around the first point by orientation about `n`, after moving the
    // lowest point (along a fixed order) first so that the angles span less than π.
    let first = (0..pts.len())
        .min_by(|&i, &j| pts[i].partial_cmp(&pts[j]).unwrap_or(Ordering::Equal))
        .unwrap_or(0);
    let pivot = pts.swap_remove(first);
    pts.sort_by(|x, y| {
        let s = dot(&cross(&sub(x, &pivot), &sub(y, &pivot)), &n);
        if s.is_positive() {
            Ordering::Less
        } else if s.is_negative() {
            Ordering::Greater
        } else {
            // Collinear with the pivot: nearer first.
            dot(&sub(x, &pivot), &sub(x, &pivot)).cmp(&dot(&sub(y, &pivot), &sub(y, &pivot)))
        }
    });
    let mut poly = vec![pivot];
    poly.extend(pts);
    ContactGeometry::Polygon(poly)
}

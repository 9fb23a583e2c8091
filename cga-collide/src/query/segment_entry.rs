//! Where a segment first meets a triangle: the exact parameter along the segment.
//!
//! The segment `[p, q]` is the set of points `p + t (q − p)`, `t ∈ [0, 1]`. Its *entry* into a
//! closed triangle is the least `t` at which it meets the triangle, an exact rational: where it
//! crosses the triangle's plane, or, when the segment lies in that plane, where it enters the
//! triangle (0 when `p` is in it). Computed in rationals from the `f64` coordinates, so it is
//! the true value for the real numbers those coordinates denote.

use ga_core::scalar::{rational_from_f64, Rational};
use num_traits::{One, Signed, Zero};

use crate::exact::vector::{add_scaled, cross, dot, sub};
use crate::{Intersects, Segment, Triangle};

type V = [Rational; 3];

fn q(x: f64) -> Rational {
    // Shapes hold finite coordinates only.
    rational_from_f64(x).unwrap_or_else(Rational::zero)
}

fn qv(p: &nalgebra::Point3<f64>) -> V {
    [q(p.x), q(p.y), q(p.z)]
}

fn is_zero(v: &V) -> bool {
    v.iter().all(Zero::is_zero)
}

/// The least parameter `t ∈ [0, 1]` at which the closed segment `s` (the points
/// `s.a() + t (s.b() − s.a())`) meets the closed triangle `t`: where it crosses the triangle's
/// plane, or, for a segment in that plane, where it enters the triangle (0 when `s.a()` is on
/// it). An exact rational, the true value for the real numbers the `f64` coordinates denote;
/// `None` when they do not meet. `Some` exactly when
/// [`intersects_segment_triangle`](crate::query::intersects_segment_triangle) is true.
/// A segment whose ends coincide is a point: `Some(0)` when the point is on the triangle.
/// Degenerate triangles (collinear corners) are the segments between their corners.
///
/// ```
/// use cga_collide::{nalgebra::Point3, query::segment_triangle_entry, Segment, Triangle};
/// let t = Triangle::new(Point3::origin(), Point3::new(4.0, 0.0, 0.0), Point3::new(0.0, 4.0, 0.0))?;
/// // Down through the plane z = 0: a quarter of the way along.
/// let s = Segment::new(Point3::new(1.0, 1.0, 1.0), Point3::new(1.0, 1.0, -3.0))?;
/// assert_eq!(segment_triangle_entry(&s, &t).unwrap().to_string(), "1/4");
/// // In the plane, from outside: it enters at the edge x + y = 4.
/// let s = Segment::new(Point3::new(4.0, 4.0, 0.0), Point3::new(0.0, 0.0, 0.0))?;
/// assert_eq!(segment_triangle_entry(&s, &t).unwrap().to_string(), "1/2");
/// let miss = Segment::new(Point3::new(5.0, 5.0, 1.0), Point3::new(5.0, 5.0, -1.0))?;
/// assert!(segment_triangle_entry(&miss, &t).is_none());
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn segment_triangle_entry(s: &Segment, t: &Triangle) -> Option<Rational> {
    let (p, qq) = (qv(s.a()), qv(s.b()));
    let d = sub(&qq, &p);
    if is_zero(&d) {
        return s.intersects(t).then(Rational::zero);
    }
    let [a, b, c] = t.vertices().map(|v| qv(&v));
    let n = cross(&sub(&b, &a), &sub(&c, &a));
    if is_zero(&n) {
        // Collinear corners: the union of the three edges.
        return [(&a, &b), (&b, &c), (&c, &a)]
            .into_iter()
            .filter_map(|(u, v)| segment_entry(&p, &d, u, v))
            .min();
    }
    let dp = dot(&n, &sub(&p, &a));
    let dq = dot(&n, &sub(&qq, &a));
    let corners = [&a, &b, &c];
    // `edge(i, x) ≥ 0` for every edge exactly when the point `x` of the plane is in the
    // triangle (the edges' inward sides, oriented by `n`).
    let edge = |i: usize, alpha: &V| -> (Rational, Rational) {
        let (u, v) = (corners[i], corners[(i + 1) % 3]);
        let e = sub(v, u);
        (dot(&cross(&e, &sub(alpha, u)), &n), dot(&cross(&e, &d), &n))
    };
    if !(dp.is_zero() && dq.is_zero()) {
        // Crossing the plane (at one point) or parallel to it.
        if (dp.is_positive() && dq.is_positive()) || (dp.is_negative() && dq.is_negative()) {
            return None;
        }
        let tt = &dp / &(&dp - &dq);
        let x = add_scaled(&p, &d, &tt);
        return (0..3).all(|i| !edge(i, &x).0.is_negative()).then_some(tt);
    }
    // In the plane: clip [0, 1] by the three inward half-planes, each `α + β t ≥ 0`.
    let (mut lo, mut hi) = (Rational::zero(), Rational::one());
    for i in 0..3 {
        let (alpha, beta) = edge(i, &p);
        if beta.is_zero() {
            if alpha.is_negative() {
                return None;
            }
        } else {
            let at = -&alpha / &beta;
            if beta.is_positive() {
                lo = lo.max(at);
            } else {
                hi = hi.min(at);
            }
        }
    }
    (lo <= hi).then_some(lo)
}

/// The least `t ∈ [0, 1]` with `p + t d` on the closed segment `[u, v]` (`d ≠ 0`), exactly.
pub(crate) fn segment_entry(p: &V, d: &V, u: &V, v: &V) -> Option<Rational> {
    let e = sub(v, u);
    let w = sub(u, p);
    let m = cross(d, &e);
    let unit = |x: &Rational| !x.is_negative() && *x <= Rational::one();
    if !is_zero(&m) {
        // Lines not parallel: one common point at most, if they are coplanar.
        if !dot(&w, &m).is_zero() {
            return None;
        }
        let mm = dot(&m, &m);
        let tt = dot(&cross(&w, &e), &m) / &mm;
        let ss = dot(&cross(&w, d), &m) / &mm;
        return (unit(&tt) && unit(&ss)).then_some(tt);
    }
    // Parallel (or `[u, v]` a point): they meet only on a common line.
    if !is_zero(&cross(&w, d)) {
        return None;
    }
    let dd = dot(d, d);
    let tu = dot(&w, d) / &dd;
    let tv = dot(&sub(v, p), d) / &dd;
    let (first, last) = if tu <= tv { (tu, tv) } else { (tv, tu) };
    let lo = first.max(Rational::zero());
    let hi = last.min(Rational::one());
    (lo <= hi).then_some(lo)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;
    use proptest::prelude::*;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            4 => (-3i32..=3).prop_map(f64::from),
            2 => -3.0f64..3.0,
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e-9),
        ]
    }

    fn point() -> impl Strategy<Value = Point3<f64>> {
        [coord(), coord(), coord()].prop_map(Point3::from)
    }

    /// Segments and triangles in general position, in a common plane (`z = 0` often), and
    /// degenerate ones (collinear corners, segments that are points).
    fn case() -> impl Strategy<Value = (Segment, Triangle)> {
        let flat = |p: Point3<f64>| Point3::new(p.x, p.y, 0.0);
        (point(), point(), point(), point(), point(), 0..4u8).prop_map(move |(p, q, a, b, c, k)| {
            let (p, q, a, b, c) = match k {
                0 => (p, q, a, b, c),
                1 => (flat(p), flat(q), flat(a), flat(b), flat(c)),
                2 => (flat(p), flat(q), flat(a), flat(b), flat(a + (b - a) * 2.0)),
                _ => (p, p, a, b, c),
            };
            (Segment::new(p, q).unwrap(), Triangle::new(a, b, c).unwrap())
        })
    }

    /// Whether the exact point `x` of the triangle's plane lies in the closed triangle, by
    /// the entry routine of the edges (an independent formulation): on an edge, or inside, as
    /// seen along a segment from `x` through a corner.
    fn entry_by_edges(s: &Segment, t: &Triangle) -> Option<Rational> {
        // In the plane: 0 when p is in the triangle, else the least entry through an edge.
        let (p, qq) = (qv(s.a()), qv(s.b()));
        let d = sub(&qq, &p);
        let [a, b, c] = t.vertices().map(|v| qv(&v));
        let start = Segment::new(*s.a(), *s.a()).unwrap();
        if start.intersects(t) {
            return Some(Rational::zero());
        }
        [(&a, &b), (&b, &c), (&c, &a)]
            .into_iter()
            .filter_map(|(u, v)| segment_entry(&p, &d, u, v))
            .min()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        /// `Some` exactly when the exact test says they meet; in a common plane, the entry
        /// equals the least entry through an edge (0 when the start is on the triangle).
        #[test]
        fn entry_agrees_with_the_exact_test((s, t) in case()) {
            let entry = segment_triangle_entry(&s, &t);
            prop_assert_eq!(entry.is_some(), s.intersects(&t), "{:?} {:?} {:?}", s, t, entry);
            if let Some(e) = &entry {
                prop_assert!(!e.is_negative() && *e <= Rational::one());
            }
            let coplanar = {
                let (p, qq) = (qv(s.a()), qv(s.b()));
                let [a, b, c] = t.vertices().map(|v| qv(&v));
                let n = cross(&sub(&b, &a), &sub(&c, &a));
                dot(&n, &sub(&p, &a)).is_zero() && dot(&n, &sub(&qq, &a)).is_zero()
            };
            if coplanar && s.a() != s.b() {
                prop_assert_eq!(entry, entry_by_edges(&s, &t));
            }
        }
    }

    #[test]
    fn touching_ends_and_edges() {
        let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
        let t = Triangle::new(p(0., 0., 0.), p(2., 0., 0.), p(0., 2., 0.)).unwrap();
        let at =
            |a, b| segment_triangle_entry(&Segment::new(a, b).unwrap(), &t).map(|r| r.to_string());
        // Ending on the triangle; starting on it; along an edge from outside; grazing a corner.
        assert_eq!(at(p(1., 1., 1.), p(0.5, 0.5, 0.)), Some("1".into()));
        assert_eq!(at(p(0.5, 0.5, 0.), p(1., 1., 1.)), Some("0".into()));
        assert_eq!(at(p(-2., 0., 0.), p(4., 0., 0.)), Some("1/3".into()));
        assert_eq!(at(p(-1., 2., 0.), p(1., 2., 0.)), Some("1/2".into()));
        assert_eq!(at(p(-1., 3., 0.), p(1., 3., 0.)), None);
    }
}

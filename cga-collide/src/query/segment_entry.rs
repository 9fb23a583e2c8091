//! Where a segment first meets a triangle: the exact parameter along the segment.
//!
//! The segment `[p, q]` is the set of points `p + t (q − p)`, `t ∈ [0, 1]`. Its *entry* into a
//! closed triangle is the least `t` at which it meets the triangle, an exact rational: where it
//! crosses the triangle's plane, or, when the segment lies in that plane, where it enters the
//! triangle (0 when `p` is in it). Computed exactly from the `f64` coordinates (in integers,
//! the coordinates scaled by one power of two, and one fraction at the end), so it is the true
//! value for the real numbers those coordinates denote.

use ga_core::scalar::Rational;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::{Intersects, Segment, Triangle};

/// A three-vector of integers: the coordinates of the segment and triangle, all scaled by one
/// power of two (`2^-e`, `e` the least exponent among them), so every `f64` is an exact
/// integer and the arithmetic needs no fractions until the one division at the end.
pub(crate) type W = [BigInt; 3];

/// `x = m 2^e` exactly, `m` an integer with at most 53 bits.
fn decompose(x: f64) -> (i64, i32) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 {
        (fraction, -1074) // zero and subnormals
    } else {
        (fraction | (1i64 << 52), biased - 1075)
    };
    (if x.is_sign_negative() { -m } else { m }, e)
}

/// The points as integer vectors under a common scale (see [`W`]); finite coordinates only.
fn scaled<const N: usize>(points: [&nalgebra::Point3<f64>; N]) -> [W; N] {
    let parts = points.map(|p| [p.x, p.y, p.z].map(decompose));
    let least = parts
        .iter()
        .flatten()
        .filter(|(m, _)| *m != 0)
        .map(|&(_, e)| e)
        .min()
        .unwrap_or(0);
    parts.map(|p| p.map(|(m, e)| BigInt::from(m) << ((e - least) as usize)))
}

fn sub(a: &W, b: &W) -> W {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn dot(a: &W, b: &W) -> BigInt {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn cross(u: &W, v: &W) -> W {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}

fn scale(a: &W, s: &BigInt) -> W {
    [&a[0] * s, &a[1] * s, &a[2] * s]
}

fn is_zero(v: &W) -> bool {
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
    let [a, b, c] = t.vertices();
    let [p, q, a, b, c] = scaled([s.a(), s.b(), a, b, c]);
    let d = sub(&q, &p);
    if is_zero(&d) {
        return s.intersects(t).then(Rational::zero);
    }
    let n = cross(&sub(&b, &a), &sub(&c, &a));
    if is_zero(&n) {
        // Collinear corners: the union of the three edges.
        return [(&a, &b), (&b, &c), (&c, &a)]
            .into_iter()
            .filter_map(|(u, v)| segment_entry(&p, &d, u, v))
            .min();
    }
    let dp = dot(&n, &sub(&p, &a));
    let dq = dot(&n, &sub(&q, &a));
    let corners = [&a, &b, &c];
    // `(e_i × (x − u_i)) · n ≥ 0` for the three edges `e_i = v_i − u_i` exactly when the point
    // `x` of the plane is in the triangle (each edge's inner side, oriented by `n`). Along the
    // segment, `x = p + t d` makes it `α_i + β_i t`.
    let edge = |i: usize, x: &W| -> W {
        let (u, v) = (corners[i], corners[(i + 1) % 3]);
        let e = sub(v, u);
        cross(&e, &sub(x, u))
    };
    if !(dp.is_zero() && dq.is_zero()) {
        // Crossing the plane (at one point, t = dp / (dp − dq)) or parallel to it.
        if (dp.is_positive() && dq.is_positive()) || (dp.is_negative() && dq.is_negative()) {
            return None;
        }
        let den = &dp - &dq;
        // The crossing point times `den`: `den p + dp d`; its inner-side tests, times `den`.
        let x = {
            let (pp, dd) = (scale(&p, &den), scale(&d, &dp));
            [&pp[0] + &dd[0], &pp[1] + &dd[1], &pp[2] + &dd[2]]
        };
        let inside = (0..3).all(|i| {
            let u = corners[i];
            let e = sub(corners[(i + 1) % 3], u);
            let side = dot(&cross(&e, &sub(&x, &scale(u, &den))), &n);
            side.is_zero() || side.is_positive() == den.is_positive()
        });
        return inside.then(|| Rational::new(dp, den));
    }
    // In the plane: clip [0, 1] by the three inner half-planes `α + β t ≥ 0`.
    let (mut lo, mut hi) = (Rational::zero(), Rational::one());
    for i in 0..3 {
        let u = corners[i];
        let e = sub(corners[(i + 1) % 3], u);
        let alpha = dot(&edge(i, &p), &n);
        let beta = dot(&cross(&e, &d), &n);
        if beta.is_zero() {
            if alpha.is_negative() {
                return None;
            }
        } else {
            let at = Rational::new(-alpha, beta.clone());
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
pub(crate) fn segment_entry(p: &W, d: &W, u: &W, v: &W) -> Option<Rational> {
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
        let tt = Rational::new(dot(&cross(&w, &e), &m), mm.clone());
        let ss = Rational::new(dot(&cross(&w, d), &m), mm);
        return (unit(&tt) && unit(&ss)).then_some(tt);
    }
    // Parallel (or `[u, v]` a point): they meet only on a common line.
    if !is_zero(&cross(&w, d)) {
        return None;
    }
    let dd = dot(d, d);
    let tu = Rational::new(dot(&w, d), dd.clone());
    let tv = Rational::new(dot(&sub(v, p), d), dd);
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
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e150),
            1 => (-3.0f64..3.0).prop_map(|x| x * 1e-310),
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
        let [a, b, c] = t.vertices();
        let [p, qq, a, b, c] = scaled([s.a(), s.b(), a, b, c]);
        let d = sub(&qq, &p);
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
                let [a, b, c] = t.vertices();
                let [p, qq, a, b, c] = scaled([s.a(), s.b(), a, b, c]);
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

//! The nearest points of two segments, a segment and a triangle, or two triangles: one generic
//! routine, written once over [`Real`] and run on `f64` (fast) and on exact rationals. The
//! minimum is taken over the closest-feature candidates (vertex–triangle, edge–edge, and an edge
//! crossing the other triangle, which gives 0 for intersecting triangles).

use ga_core::scalar::Real;

use crate::exact::vector::{add_scaled, cross, dist2, dot, sub};

pub(crate) type V<F> = [F; 3];

/// A candidate nearest pair: squared distance and the two points.
pub(crate) type Near<F> = (F, V<F>, V<F>);

#[inline(always)]
pub(crate) fn keep<F: Real>(best: &mut Option<Near<F>>, c: Near<F>) {
    if best.as_ref().is_none_or(|b| c.0 < b.0) {
        *best = Some(c);
    }
}

/// The point of segment `ab` nearest to `p`.
pub(crate) fn point_segment<F: Real>(a: &V<F>, b: &V<F>, p: &V<F>) -> V<F> {
    let u = sub(b, a);
    let t = dot(&sub(p, a), &u);
    if t <= F::zero() {
        return a.clone();
    }
    let den = dot(&u, &u);
    if t >= den {
        return b.clone();
    }
    add_scaled(a, &u, &(t / den))
}

/// The point of triangle `t` nearest to `p`.
pub(crate) fn point_triangle<F: Real>(t: &[V<F>; 3], p: &V<F>) -> V<F> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let nn = dot(&n, &n);
    let inside = !nn.is_zero()
        && (0..3).all(|i| {
            let e = sub(&t[(i + 1) % 3], &t[i]);
            dot(&cross(&e, &sub(p, &t[i])), &n) >= F::zero()
        });
    if inside {
        let h = dot(&n, &sub(p, &t[0])) / nn;
        return add_scaled(p, &n, &-h);
    }
    let mut best: Option<Near<F>> = None;
    for i in 0..3 {
        let q = point_segment(&t[i], &t[(i + 1) % 3], p);
        keep(&mut best, (dist2(&q, p), q, p.clone()));
    }
    best.map(|b| b.1).unwrap_or_else(|| t[0].clone())
}

/// The nearest points of segments `ab` and `cd`.
pub(crate) fn segment_segment<F: Real>(a: &V<F>, b: &V<F>, c: &V<F>, d: &V<F>) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for (p, s0, s1, first) in [
        (a, c, d, true),
        (b, c, d, true),
        (c, a, b, false),
        (d, a, b, false),
    ] {
        let q = point_segment(s0, s1, p);
        let d2 = dist2(p, &q);
        keep(
            &mut best,
            if first {
                (d2, p.clone(), q)
            } else {
                (d2, q, p.clone())
            },
        );
    }
    if let Some(near) = common_perpendicular(a, b, c, d) {
        keep(&mut best, near);
    }
    best.unwrap_or_else(|| unreachable!("four candidates"))
}

/// The points where the common perpendicular of lines `ab` and `cd` meets them, if it meets
/// both segments (the interior candidate of the nearest points of two segments).
pub(crate) fn common_perpendicular<F: Real>(
    a: &V<F>,
    b: &V<F>,
    c: &V<F>,
    d: &V<F>,
) -> Option<Near<F>> {
    let (u, v, w) = (sub(b, a), sub(d, c), sub(c, a));
    let n = cross(&u, &v);
    let nn = dot(&n, &n);
    if !nn.is_zero() {
        let s = dot(&cross(&w, &v), &n);
        let t = dot(&cross(&w, &u), &n);
        let zero = F::zero();
        if s >= zero && s <= nn && t >= zero && t <= nn {
            let p = add_scaled(a, &u, &(s / nn.clone()));
            let q = add_scaled(c, &v, &(t / nn));
            return Some((dist2(&p, &q), p, q));
        }
    }
    None
}

/// Where segment `ab` crosses the plane of the triangle `t` strictly (its end points strictly
/// on opposite sides), if it does.
pub(crate) fn plane_crossing<F: Real>(a: &V<F>, b: &V<F>, t: &[V<F>; 3]) -> Option<V<F>> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let da = dot(&n, &sub(a, &t[0]));
    let db = dot(&n, &sub(b, &t[0]));
    let zero = F::zero();
    let crosses = (da > zero && db < zero) || (da < zero && db > zero);
    crosses.then(|| add_scaled(a, &sub(b, a), &(da.clone() / (da - db))))
}

/// The nearest points of segment `ab` and triangle `t`.
pub(crate) fn segment_triangle<F: Real>(a: &V<F>, b: &V<F>, t: &[V<F>; 3]) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for p in [a, b] {
        let q = point_triangle(t, p);
        keep(&mut best, (dist2(p, &q), p.clone(), q));
    }
    for i in 0..3 {
        keep(&mut best, segment_segment(a, b, &t[i], &t[(i + 1) % 3]));
    }
    if let Some(x) = plane_crossing(a, b, t) {
        let q = point_triangle(t, &x);
        keep(&mut best, (dist2(&x, &q), x, q));
    }
    best.unwrap_or_else(|| unreachable!("candidates"))
}

/// The nearest points of triangles `p` and `q`.
pub(crate) fn triangle_triangle<F: Real>(p: &[V<F>; 3], q: &[V<F>; 3]) -> Near<F> {
    let mut best: Option<Near<F>> = None;
    for v in p {
        let y = point_triangle(q, v);
        keep(&mut best, (dist2(v, &y), v.clone(), y));
    }
    for v in q {
        let x = point_triangle(p, v);
        keep(&mut best, (dist2(&x, v), x, v.clone()));
    }
    // Edge pairs: only their interiors, since a vertex's distance to an edge is never below
    // its distance to that edge's triangle (a candidate above).
    for i in 0..3 {
        for j in 0..3 {
            if let Some(near) = common_perpendicular(&p[i], &p[(i + 1) % 3], &q[j], &q[(j + 1) % 3])
            {
                keep(&mut best, near);
            }
        }
    }
    // Intersecting triangles: an edge of one crosses the other.
    for i in 0..3 {
        if let Some(x) = plane_crossing(&p[i], &p[(i + 1) % 3], q) {
            let y = point_triangle(q, &x);
            keep(&mut best, (dist2(&x, &y), x, y));
        }
        if let Some(y) = plane_crossing(&q[i], &q[(i + 1) % 3], p) {
            let x = point_triangle(p, &y);
            keep(&mut best, (dist2(&x, &y), x, y));
        }
    }
    best.unwrap_or_else(|| unreachable!("candidates"))
}

//! A disc against a convex set in the disc's own plane, exactly.
//!
//! The set is `conv(points) + cone(rays)`, all in the disc's plane (rays appear when a cone's
//! section is unbounded). The disc meets it iff the disc's centre is in the set, or some
//! boundary piece is within the radius: the boundary of a plane set of this form is covered by
//! the segments between its points and the rays from its points, so every candidate is an
//! exact rational test. Orientation is decided in the projection that drops the coordinate
//! where the plane's normal is largest: an affine bijection of the plane, so it keeps
//! incidences, convex combinations and the coefficients of linear systems.

use core::cmp::Ordering;

use ga_core::scalar::Rational;
use num_traits::{Signed, Zero};

use super::exact3::{dot, norm2, sub, V3};
use super::surd::sign;

/// The projection of the plane onto two coordinates.
#[derive(Clone, Copy)]
struct Chart {
    i: usize,
    j: usize,
}

impl Chart {
    fn new(normal: &V3) -> Self {
        let k = (0..3)
            .max_by(|&a, &b| normal[a].abs().cmp(&normal[b].abs()))
            .unwrap_or(2);
        Chart {
            i: (k + 1) % 3,
            j: (k + 2) % 3,
        }
    }

    /// The 2D cross product of two vectors of the plane, in this chart.
    fn cross(&self, u: &V3, v: &V3) -> Rational {
        &u[self.i] * &v[self.j] - &u[self.j] * &v[self.i]
    }
}

/// Is `v` within squared distance `r2` of the segment `[u, w]`?
fn segment_within(v: &V3, u: &V3, w: &V3, r2: &Rational) -> bool {
    let d = sub(w, u);
    let rel = sub(v, u);
    let s = dot(&rel, &d);
    let l = norm2(&d);
    if !s.is_positive() || l.is_zero() {
        return norm2(&rel) <= *r2;
    }
    if s >= l {
        return norm2(&sub(v, w)) <= *r2;
    }
    norm2(&rel) * &l - &s * &s <= r2 * &l
}

/// Is `v` within squared distance `r2` of the ray `u + t·w`, `t >= 0`?
fn ray_within(v: &V3, u: &V3, w: &V3, r2: &Rational) -> bool {
    let rel = sub(v, u);
    let s = dot(&rel, w);
    if !s.is_positive() {
        return norm2(&rel) <= *r2;
    }
    let l = norm2(w);
    norm2(&rel) * &l - &s * &s <= r2 * &l
}

/// The convex hull of the points in the chart, counter-clockwise, without repeated or
/// collinear points (Andrew's monotone chain with exact orientations).
fn hull(points: &[V3], chart: Chart) -> Vec<V3> {
    let mut sorted: Vec<&V3> = points.iter().collect();
    sorted.sort_by(|a, b| (&a[chart.i], &a[chart.j]).cmp(&(&b[chart.i], &b[chart.j])));
    sorted.dedup_by(|a, b| a[chart.i] == b[chart.i] && a[chart.j] == b[chart.j]);
    if sorted.len() < 3 {
        return sorted.into_iter().cloned().collect();
    }
    let turn = |o: &V3, a: &V3, b: &V3| sign(&chart.cross(&sub(a, o), &sub(b, o)));
    let mut chain: Vec<&V3> = Vec::with_capacity(2 * sorted.len());
    for pass in 0..2 {
        let start = chain.len();
        let ordered: Vec<&V3> = if pass == 0 {
            sorted.clone()
        } else {
            sorted.iter().rev().cloned().collect()
        };
        for p in ordered {
            while chain.len() >= start + 2
                && turn(chain[chain.len() - 2], chain[chain.len() - 1], p) != Ordering::Greater
            {
                chain.pop();
            }
            chain.push(p);
        }
        chain.pop();
    }
    chain.into_iter().cloned().collect()
}

/// Is `v` in the cone of `a` and `b` (plane vectors)?
fn in_cone(v: &V3, a: &V3, b: &V3, chart: Chart) -> bool {
    let det = chart.cross(a, b);
    if det.is_zero() {
        // Parallel generators: the union of the two rays, or the whole line when opposite.
        let on_ray = |w: &V3| chart.cross(v, w).is_zero() && !dot(v, w).is_negative();
        if dot(a, b).is_negative() {
            return chart.cross(v, a).is_zero();
        }
        return on_ray(a) || on_ray(b);
    }
    // v = α a + β b with α = (v × b)/(a × b), β = (a × v)/(a × b).
    let alpha = chart.cross(v, b);
    let beta = chart.cross(a, v);
    let s = sign(&det);
    sign(&alpha) != s.reverse() && sign(&beta) != s.reverse()
}

/// Is `v` in `[u, w] + t·ray`, `t >= 0`, when `w − u` and `ray` are independent?
fn in_swept_segment(v: &V3, u: &V3, w: &V3, ray: &V3, chart: Chart) -> bool {
    let e = sub(w, u);
    let det = chart.cross(&e, ray);
    if det.is_zero() {
        return false; // covered by the rays from u and w and by the segment itself
    }
    let rel = sub(v, u);
    let s = chart.cross(&rel, ray); // s/det in [0, 1]
    let t = chart.cross(&e, &rel); // t/det >= 0
    let (s, t) = if det.is_negative() { (-s, -t) } else { (s, t) };
    let det = det.abs();
    !s.is_negative() && s <= det && !t.is_negative()
}

/// Exact: does the disc of centre `centre`, plane normal `normal` and squared radius `r2` meet
/// `conv(points) + cone(rays)`? Every point and ray must lie in the disc's plane; `points`
/// must not be empty (an empty set meets nothing).
pub(crate) fn disc_meets(
    centre: &V3,
    normal: &V3,
    r2: &Rational,
    points: &[V3],
    rays: &[V3],
) -> bool {
    if points.is_empty() {
        return false;
    }
    let chart = Chart::new(normal);
    let polygon = hull(points, chart);
    let edges = || {
        polygon
            .iter()
            .zip(polygon.iter().cycle().skip(1))
            .take(polygon.len())
    };
    // The centre inside the bounded part.
    if polygon.len() >= 3
        && edges().all(|(u, w)| {
            chart.cross(&sub(w, u), &sub(centre, u)).is_positive()
                || chart.cross(&sub(w, u), &sub(centre, u)).is_zero()
        })
    {
        return true;
    }
    if rays.is_empty() {
        return match polygon.len() {
            1 => norm2(&sub(centre, &polygon[0])) <= *r2,
            2 => segment_within(centre, &polygon[0], &polygon[1], r2),
            _ => edges().any(|(u, w)| segment_within(centre, u, w, r2)),
        };
    }
    // With rays: Carathéodory in the plane; the centre is in the set iff it is in the convex
    // hull of at most three generators, at least one a point.
    for (n, u) in polygon.iter().enumerate() {
        let rel = sub(centre, u);
        for (m, a) in rays.iter().enumerate() {
            if rays[m..].iter().any(|b| in_cone(&rel, a, b, chart)) {
                return true;
            }
        }
        for w in &polygon[n + 1..] {
            if rays
                .iter()
                .any(|ray| in_swept_segment(centre, u, w, ray, chart))
            {
                return true;
            }
        }
    }
    let near_segment = polygon.iter().enumerate().any(|(n, u)| {
        polygon[n..]
            .iter()
            .any(|w| segment_within(centre, u, w, r2))
    });
    near_segment
        || polygon
            .iter()
            .any(|u| rays.iter().any(|w| ray_within(centre, u, w, r2)))
}

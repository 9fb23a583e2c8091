//! Certified distances where the exact `within_distance` always decides: a cylinder or cone
//! against a ball (or a point), a half-space, a segment or a capsule.
//!
//! The distance and witnesses are computed in `f64` (the nearest point in the meridian
//! half-plane, the lowest point along the half-space's normal, or the nearest point along a
//! segment, where the distance to the convex solid is a convex function); the bound is then
//! proved by the exact `within_distance` tests on either side of the value, widened until they
//! agree (the crate's usual certification).

use nalgebra::{Point3, Vector3};

use crate::query::distance::certify;
use crate::query::CertifiedDistance;
use crate::shape::{Ball, Cone, Cylinder, HalfSpace};

/// Golden-section steps along a segment: enough to shrink `[0, 1]` below `f64` resolution.
const SECTION_STEPS: usize = 90;

/// A cylinder or cone in `f64`: axis origin (a cylinder's `a`, a cone's apex), axis end, radius.
#[derive(Clone, Copy)]
pub(crate) struct Solid {
    cone: bool,
    origin: Vector3<f64>,
    end: Vector3<f64>,
    radius: f64,
}

impl Solid {
    pub(crate) fn cylinder(c: &Cylinder) -> Self {
        Solid {
            cone: false,
            origin: c.a().coords,
            end: c.b().coords,
            radius: c.radius(),
        }
    }

    pub(crate) fn cone(c: &Cone) -> Self {
        Solid {
            cone: true,
            origin: c.apex().coords,
            end: c.base().coords,
            radius: c.radius(),
        }
    }

    /// The middle of the axis, a point of the solid (inside it when the radius is positive).
    pub(crate) fn centre(&self) -> Vector3<f64> {
        (self.origin + self.end) * 0.5
    }

    fn scale(&self) -> f64 {
        self.origin.amax().max(self.end.amax()).max(self.radius)
    }

    /// The point of the solid nearest to `v` (in `f64`).
    pub(crate) fn nearest(&self, v: &Vector3<f64>) -> Vector3<f64> {
        let d = self.end - self.origin;
        let h = d.norm();
        let axis = d / h;
        let rel = v - self.origin;
        let t = rel.dot(&axis);
        let radial = rel - axis * t;
        let rho = radial.norm();
        let out = if rho > 0.0 {
            radial / rho
        } else {
            axis.cross(&Vector3::x())
                .try_normalize(0.0)
                .unwrap_or_else(|| {
                    axis.cross(&Vector3::y())
                        .try_normalize(0.0)
                        .unwrap_or_else(Vector3::z)
                })
        };
        let r = self.radius;
        let profile: Vec<[f64; 2]> = if self.cone {
            vec![[0.0, 0.0], [h, 0.0], [h, r]]
        } else {
            vec![[0.0, 0.0], [h, 0.0], [h, r], [0.0, r]]
        };
        let (tt, rr) = nearest_in_polygon(&profile, [t, rho]);
        self.origin + axis * tt + out * rr
    }

    /// The point of the solid lowest along `n` (in `f64`).
    fn lowest(&self, n: &Vector3<f64>) -> Vector3<f64> {
        let d = self.end - self.origin;
        let axis = d / d.norm();
        let across = n - axis * n.dot(&axis);
        let drop = across.try_normalize(0.0).unwrap_or_else(Vector3::zeros) * self.radius;
        let end = self.end - drop;
        if self.cone {
            if n.dot(&self.origin) <= n.dot(&end) {
                self.origin
            } else {
                end
            }
        } else {
            let start = self.origin - drop;
            if n.dot(&start) <= n.dot(&end) {
                start
            } else {
                end
            }
        }
    }
}

/// The nearest point to `p` of the convex polygon (counter-clockwise) in the plane.
fn nearest_in_polygon(poly: &[[f64; 2]], p: [f64; 2]) -> (f64, f64) {
    let edges = || {
        poly.iter()
            .zip(poly.iter().cycle().skip(1))
            .take(poly.len())
    };
    let inside =
        edges().all(|(u, w)| (w[0] - u[0]) * (p[1] - u[1]) - (w[1] - u[1]) * (p[0] - u[0]) >= 0.0);
    if inside {
        return (p[0], p[1]);
    }
    let mut best = (f64::INFINITY, poly[0][0], poly[0][1]);
    for (u, w) in edges() {
        let e = [w[0] - u[0], w[1] - u[1]];
        let l = e[0] * e[0] + e[1] * e[1];
        let s = if l > 0.0 {
            (((p[0] - u[0]) * e[0] + (p[1] - u[1]) * e[1]) / l).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let x = [u[0] + s * e[0], u[1] + s * e[1]];
        let d2 = (x[0] - p[0]).powi(2) + (x[1] - p[1]).powi(2);
        if d2 < best.0 {
            best = (d2, x[0], x[1]);
        }
    }
    (best.1, best.2)
}

fn result(distance: f64, error_bound: f64, a: Vector3<f64>, b: Vector3<f64>) -> CertifiedDistance {
    CertifiedDistance {
        distance,
        error_bound,
        witness_a: Point3::from(a),
        witness_b: Point3::from(b),
        triangles: None,
    }
}

/// The solid against a ball; `within(c)` is the exact test.
pub(crate) fn to_ball(s: &Solid, ball: &Ball, within: impl Fn(f64) -> bool) -> CertifiedDistance {
    let centre = ball.centre().coords;
    let x = s.nearest(&centre);
    let gap = (centre - x).norm();
    let (distance, y) = if gap > ball.radius() {
        (
            gap - ball.radius(),
            centre + (x - centre) * (ball.radius() / gap),
        )
    } else {
        (0.0, x)
    };
    let scale = s.scale().max(centre.amax()).max(ball.radius());
    let bound = certify(distance, scale, || within(0.0), &within, &within);
    result(distance, bound, x, y)
}

/// The solid against a half-space; `within(c)` is the exact test.
pub(crate) fn to_half_space(
    s: &Solid,
    h: &HalfSpace,
    within: impl Fn(f64) -> bool,
) -> CertifiedDistance {
    let n = *h.normal();
    let x = s.lowest(&n);
    let height = (x - h.point().coords).dot(&n) / n.norm();
    let (distance, y) = if height > 0.0 {
        (height, x - n * (height / n.norm()))
    } else {
        (0.0, x)
    };
    let scale = s.scale().max(h.point().coords.amax());
    let bound = certify(distance, scale, || within(0.0), &within, &within);
    result(distance, bound, x, y)
}

/// The solid against the segment `[p, q]` grown by `radius` (a capsule; `0` for a segment);
/// `within(c)` is the exact test.
pub(crate) fn to_segment(
    s: &Solid,
    p: &Point3<f64>,
    q: &Point3<f64>,
    radius: f64,
    within: impl Fn(f64) -> bool,
) -> CertifiedDistance {
    let (p, q) = (p.coords, q.coords);
    let at = |t: f64| p + (q - p) * t;
    let gap = |t: f64| {
        let v = at(t);
        (v - s.nearest(&v)).norm()
    };
    // The distance to a convex set is convex along a line: golden-section search.
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..SECTION_STEPS {
        let (m1, m2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
        if gap(m1) <= gap(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    let t = [0.0, 1.0, 0.5 * (lo + hi)]
        .into_iter()
        .fold(
            0.5 * (lo + hi),
            |best, t| if gap(t) < gap(best) { t } else { best },
        );
    let v = at(t);
    let x = s.nearest(&v);
    let d = (v - x).norm();
    let (distance, y) = if d > radius {
        (d - radius, v + (x - v) * (radius / d))
    } else {
        (0.0, x)
    };
    let scale = s.scale().max(p.amax()).max(q.amax()).max(radius);
    let bound = certify(distance, scale, || within(0.0), &within, &within);
    result(distance, bound, x, y)
}

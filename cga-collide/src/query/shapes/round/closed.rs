//! Closed-form certified answers, tried before the search of [`super::filter`], for the pairs
//! whose distance has a formula in the meridian half-plane of the round solid: a ball, a
//! segment or a capsule, and a half-space, against a cylinder or a cone.
//!
//! A point `x` has axial coordinate `t = (x − o)·u/|u|` and radial distance
//! `ρ = |(x − o) × u|/|u|` (`o` the cylinder's `a` or the cone's apex, `u` the axis); its
//! distance to the solid is its distance to the profile in the `(t, ρ)` plane: the rectangle
//! `[0, |u|] × [0, r]` or the triangle `(0, 0), (|u|, 0), (|u|, r)`. That distance is
//! evaluated in outward-rounded interval arithmetic ([`super::interval`]), so its bounds hold
//! the exact value at every scale (an overflow or a degenerate axis only widens them to the
//! whole line); a comparison with the clearance that the bounds do not settle returns `None`,
//! and the caller goes on to the filter and the exact method. Nothing here changes an answer,
//! only how soon it comes.
//!
//! * ball: the centre's distance against `radius + c`;
//! * segment or capsule: a point of the segment (nearest the solid, found in `f64` by a few
//!   alternating projections) whose distance is proved at most `radius + c` proves meeting;
//!   the direction from the solid's nearest point to it, with the solid's support function
//!   bounded and the segment's ends, proves them apart;
//! * half-space: the solid's lowest point along the normal, `min(n·a, n·b) − r·|n × û|` for a
//!   cylinder, `min(n·apex, n·base − r·|n × û|)` for a cone.

use super::interval::{cross_norm2, dot3, lift, norm2, sub3, Iv, IvP3};
use crate::shape::{HalfSpace, Shape};

type P3 = [f64; 3];

/// Alternating projections between the segment and the solid before the proofs.
const PROJECTIONS: usize = 4;

/// A cylinder or cone: `f64` values for the search, intervals for the proofs.
struct Solid {
    cone: bool,
    origin: P3,
    axis: P3,
    radius: f64,
    origin_iv: IvP3,
    axis_iv: IvP3,
    /// `|u|²` and `|u|`.
    axis2: Iv,
    length: Iv,
    radius_iv: Iv,
}

fn zero() -> Iv {
    Iv::point(0.0)
}

fn min(a: Iv, b: Iv) -> Iv {
    a.neg().max(b.neg()).neg()
}

fn solid(s: &Shape) -> Option<Solid> {
    let (cone, o, e, r) = match s {
        Shape::Cylinder(c) => (false, c.a(), c.b(), c.radius()),
        Shape::Cone(c) => (true, c.apex(), c.base(), c.radius()),
        _ => return None,
    };
    let origin = [o.x, o.y, o.z];
    let end = [e.x, e.y, e.z];
    let origin_iv = lift(&origin);
    let axis_iv = sub3(&lift(&end), &origin_iv);
    let axis2 = norm2(&axis_iv);
    Some(Solid {
        cone,
        origin,
        axis: [end[0] - o.x, end[1] - o.y, end[2] - o.z],
        radius: r,
        origin_iv,
        axis_iv,
        axis2,
        length: axis2.sqrt(),
        radius_iv: Iv::point(r),
    })
}

impl Solid {
    /// Bounds on the distance from the exact point(s) of the box `x` to the solid.
    fn distance(&self, x: &IvP3) -> Iv {
        let rel = sub3(x, &self.origin_iv);
        let t = dot3(&rel, &self.axis_iv).div_positive(self.length);
        let rho = cross_norm2(&rel, &self.axis_iv)
            .div_positive(self.axis2)
            .sqrt();
        let (h, r) = (self.length, self.radius_iv);
        let beyond_rim = zero().max(rho.sub(r));
        if !self.cone {
            let axial = zero().max(t.neg()).max(t.sub(h));
            return axial.sqr().add(beyond_rim.sqr()).sqrt();
        }
        let slant_in = rho.mul(h);
        let slant_at = r.mul(t);
        if t.lo >= 0.0 && t.hi <= h.lo && slant_in.hi <= slant_at.lo {
            return zero();
        }
        let outside = t.hi < 0.0 || t.lo > h.hi || slant_in.lo > slant_at.hi;
        // Outside, the nearest point of the triangle is on the base or the slant edge.
        let base = t.sub(h).sqr().add(beyond_rim.sqr());
        let along = t
            .mul(h)
            .add(rho.mul(r))
            .div_positive(self.axis2.add(r.sqr()));
        let along = min(zero().max(along), Iv::point(1.0));
        let slant = t.sub(along.mul(h)).sqr().add(rho.sub(along.mul(r)).sqr());
        let edges = min(base, slant).sqrt();
        if outside {
            edges
        } else {
            Iv {
                lo: 0.0,
                hi: edges.hi,
            }
        }
    }

    /// Bounds on `max over the solid of d·y`.
    fn support(&self, d: &IvP3) -> Iv {
        let reach = self.radius_iv.mul(
            cross_norm2(d, &self.axis_iv)
                .div_positive(self.axis2)
                .sqrt(),
        );
        let at_origin = dot3(d, &self.origin_iv);
        let at_end = at_origin.add(dot3(d, &self.axis_iv));
        if self.cone {
            at_origin.max(at_end.add(reach))
        } else {
            at_origin.max(at_end).add(reach)
        }
    }

    /// The point of the solid nearest `x`, in plain `f64` (a guide, never a proof).
    fn nearest(&self, x: &P3) -> P3 {
        let h = dot(&self.axis, &self.axis).sqrt();
        let unit = self.axis.map(|v| v / h);
        let rel = sub(x, &self.origin);
        let t = dot(&rel, &unit);
        let radial = [
            rel[0] - t * unit[0],
            rel[1] - t * unit[1],
            rel[2] - t * unit[2],
        ];
        let rho = dot(&radial, &radial).sqrt();
        let out = if rho > 0.0 {
            radial.map(|v| v / rho)
        } else {
            [0.0; 3]
        };
        let r = self.radius;
        let (tt, rr) = if !self.cone {
            (t.clamp(0.0, h), rho.min(r))
        } else if (0.0..=h).contains(&t) && rho * h <= r * t {
            (t, rho)
        } else {
            let base = (h, rho.min(r));
            let s = ((t * h + rho * r) / (h * h + r * r)).clamp(0.0, 1.0);
            let slant = (s * h, s * r);
            let d2 = |(a, b): (f64, f64)| (a - t) * (a - t) + (b - rho) * (b - rho);
            if d2(base) <= d2(slant) {
                base
            } else {
                slant
            }
        };
        core::array::from_fn(|k| self.origin[k] + tt * unit[k] + rr * out[k])
    }
}

fn dot(a: &P3, b: &P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: &P3, b: &P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `d ≤ e`, decided by the bounds or `None`.
fn compare(d: Iv, e: Iv) -> Option<bool> {
    if d.hi <= e.lo {
        Some(true)
    } else if d.lo > e.hi {
        Some(false)
    } else {
        None
    }
}

/// The parameter in `[0, 1]` of the point of `pq` nearest `y` (`f64`).
fn project(p: &P3, q: &P3, y: &P3) -> f64 {
    let pq = sub(q, p);
    let s = dot(&sub(y, p), &pq) / dot(&pq, &pq);
    if s.is_nan() {
        0.0
    } else {
        s.clamp(0.0, 1.0)
    }
}

/// The parameter on `pq` of the point nearest the segment `ab` (`f64`, clamped).
fn nearest_between(p: &P3, q: &P3, a: &P3, b: &P3) -> f64 {
    let (d1, d2, r) = (sub(q, p), sub(b, a), sub(p, a));
    let (aa, ee, f) = (dot(&d1, &d1), dot(&d2, &d2), dot(&d2, &r));
    let (c, bb) = (dot(&d1, &r), dot(&d1, &d2));
    let denom = aa * ee - bb * bb;
    let s = if denom > 0.0 {
        ((bb * f - c * ee) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let t = (bb * s + f) / ee;
    // `t` NaN (a zero-length `ab`) takes the first branch too.
    let s = if t.is_nan() || t <= 0.0 {
        -c / aa
    } else if t > 1.0 {
        (bb - c) / aa
    } else {
        s
    };
    if s.is_nan() {
        0.0
    } else {
        s.clamp(0.0, 1.0)
    }
}

fn ball(solid: &Solid, centre: &P3, e: Iv) -> Option<bool> {
    compare(solid.distance(&lift(centre)), e)
}

fn segment(solid: &Solid, p: &P3, q: &P3, e: Iv) -> Option<bool> {
    let end = [
        solid.origin[0] + solid.axis[0],
        solid.origin[1] + solid.axis[1],
        solid.origin[2] + solid.axis[2],
    ];
    let mut s = nearest_between(p, q, &solid.origin, &end);
    let at = |s: f64| -> P3 { core::array::from_fn(|k| p[k] + s * (q[k] - p[k])) };
    let mut y = solid.nearest(&at(s));
    for _ in 0..PROJECTIONS {
        let next = project(p, q, &y);
        if next == s {
            break;
        }
        s = next;
        y = solid.nearest(&at(s));
    }
    // The exact point `p + s·(q − p)` of the segment lies in this box.
    let (pi, qi) = (lift(p), lift(q));
    let x: IvP3 = core::array::from_fn(|k| pi[k].add(Iv::point(s).mul(qi[k].sub(pi[k]))));
    let d = solid.distance(&x);
    if d.hi <= e.lo {
        return Some(true);
    }
    let n = sub(&at(s), &y);
    let ni = lift(&n);
    if dot(&n, &n) > 0.0 {
        let low = dot3(&ni, &pi).neg().max(dot3(&ni, &qi).neg()).neg();
        let gap = low.sub(solid.support(&ni));
        if gap.lo > e.mul(norm2(&ni).sqrt()).hi {
            return Some(false);
        }
    }
    // `d.lo > e` says only that this one point is far, not the whole segment.
    None
}

fn half_space(solid: &Solid, h: &HalfSpace, c: f64) -> Option<bool> {
    let n = lift(&[h.normal().x, h.normal().y, h.normal().z]);
    let p = lift(&[h.point().x, h.point().y, h.point().z]);
    let lowest = solid.support(&n.map(Iv::neg)).neg();
    let height = lowest.sub(dot3(&n, &p));
    compare(height, Iv::point(c).mul(norm2(&n).sqrt()))
}

/// The proved answer of "is the distance between `a` and `b` at most `c`?" by a closed form,
/// or `None` (no closed form for the pair, or the bounds do not settle it).
pub(super) fn within(a: &Shape, b: &Shape, c: f64) -> Option<bool> {
    let (round, other) = match (solid(a), solid(b)) {
        (Some(r), _) => (r, b),
        (None, Some(r)) => (r, a),
        (None, None) => return None,
    };
    let point = |p: &nalgebra::Point3<f64>| [p.x, p.y, p.z];
    let e = |radius: f64| Iv::point(radius).add(Iv::point(c));
    match other {
        Shape::Ball(b) => ball(&round, &point(b.centre()), e(b.radius())),
        Shape::Capsule(k) => segment(&round, &point(k.a()), &point(k.b()), e(k.radius())),
        Shape::Segment(g) => segment(&round, &point(g.a()), &point(g.b()), e(0.0)),
        Shape::HalfSpace(h) => half_space(&round, h, c),
        _ => None,
    }
}

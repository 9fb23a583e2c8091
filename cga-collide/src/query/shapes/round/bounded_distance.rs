//! A certified distance for the pairs with a cylinder or a cone that have no exact distance
//! method (against a triangle, cuboid, hull, cylinder or cone), proved in interval arithmetic
//! around the `f64` search of the [filter](super::filter).
//!
//! * **Lower bound.** The search converged on the nearest point `v` of the difference
//!   `A − B`; along `v`, the support functions bounded outward give
//!   `min_A v·x − max_B v·y ≥ g`, so every point of `A` is at least `g / |v|` from every point
//!   of `B` (when `g > 0`; otherwise the lower bound is `0`). Along the true nearest direction
//!   this is the distance itself, so a converged search makes it tight.
//! * **Upper bound.** The same search on both bodies shrunk by a tiny depth gives witness
//!   points as convex combinations of support points; each is proved inside its (unshrunk)
//!   body: a polytope's as the exact combination of its vertices held in an interval box, a
//!   cylinder's, cone's, ball's or capsule's by the slab and radial bounds. The distance is at
//!   most the largest distance between the two boxes.
//! * **Meeting.** When the search reaches the origin, a common point proved inside both (the
//!   filter's shrunk searches) gives the distance `0` exactly.
//!
//! The answer is the middle of `[lower, upper]` with half its width as the error bound, so
//! the true distance lies within `distance ± error_bound`; the witnesses are the proved
//! points. Nothing proved (magnitudes out of the range the scaling keeps exact, degenerate
//! bodies whose shrinking fails) is `None`, and the caller refuses the pair.

use nalgebra::Point3;

use super::body::{dot, magnitude, sub, Body, P3};
use super::filter::{meets, search, search_steps, unit_scale, Found};
use super::interval::{lift, norm2, sub3, IvP3};
use crate::query::CertifiedDistance;
use crate::shape::Shape;

/// Depths (fractions of each body's largest shrink) tried for the witness search: the first
/// whose witnesses are proved inside decides; smaller is tighter.
const SHRINK_FRACTIONS: [f64; 3] = [1.0 / (1u64 << 44) as f64, 1.0 / (1u64 << 34) as f64, 1e-6];

/// Search steps for a distance: two curved bodies converge linearly, and the bounds are as
/// tight as the search is converged.
const STEPS: usize = 1024;

/// The certified distance between two bounded shapes, one of them a cylinder or cone (any
/// pair the filter's bodies hold: not a half-space).
pub(super) fn distance(a: &Shape, b: &Shape) -> Option<CertifiedDistance> {
    let scale = unit_scale(magnitude(a).max(magnitude(b)));
    let (ba, bb) = (body(a, scale)?, body(b, scale)?);
    if let Some((lower, upper, xa, xb)) = lateral(&ba, &bb) {
        return certified(lower, upper, &xa, &xb, scale);
    }
    let found = search_steps(&ba, 0.0, &bb, 0.0, f64::INFINITY, STEPS);
    if !found.norm2.is_finite() {
        return None;
    }
    if found.norm2 == 0.0 || found.norm2.sqrt() <= 1e-3 * ba.max_shrink().max(bb.max_shrink()) {
        if let Some(x) = common_point(&ba, &bb) {
            let p = unscaled(&x, scale)?;
            return Some(CertifiedDistance {
                distance: 0.0,
                error_bound: 0.0,
                witness_a: p,
                witness_b: p,
                triangles: None,
            });
        }
    }
    let (upper, xa, xb) = upper_bound(&ba, &bb)?;
    // Along the search's direction, and along the witnesses' (often the better one: a
    // search whose support points repeat, as a cone's apex and rim do, stops on a direction
    // a little off, and the gap along it is short by the square of that angle).
    let between: P3 = core::array::from_fn(|k| xa[k] - xb[k]);
    let lower = [found.v, between]
        .iter()
        .filter(|d| d.iter().any(|x| *x != 0.0))
        .map(|d| lower_bound(&ba, &bb, d))
        .fold(0.0, f64::max);
    if lower.is_nan() || upper.is_nan() || lower > upper {
        return None;
    }
    certified(lower, upper, &xa, &xb, scale)
}

/// The answer for the scaled bounds `lower ≤ distance ≤ upper` and witnesses.
fn certified(lower: f64, upper: f64, xa: &P3, xb: &P3, scale: f64) -> Option<CertifiedDistance> {
    // Back to the input's units: `scale` is a power of two, so only results below the
    // normal range round, and they are moved outwards.
    let (lower, upper) = (
        (lower / scale).next_down().max(0.0),
        (upper / scale).next_up(),
    );
    let distance = 0.5 * lower + 0.5 * upper;
    let error_bound = (upper - distance).max(distance - lower).next_up();
    if !(distance.is_finite() && error_bound.is_finite()) {
        return None;
    }
    Some(CertifiedDistance {
        distance,
        error_bound,
        witness_a: unscaled(xa, scale)?,
        witness_b: unscaled(xb, scale)?,
        triangles: None,
    })
}

/// How much wider than this (in the scaled units, where the bodies' numbers are in
/// `[1, 2)`) the lateral bracket may not be: wider means the feet were not where the
/// distance is, and the search takes over.
const LATERAL_WIDTH: f64 = 1e-12;

/// Two cylinders whose nearest points lie on both curved sides: the common perpendicular of
/// the axis lines meets both axis segments strictly inside, longer than the two radii
/// together. Then the distance is that perpendicular less the radii (no two points of the
/// infinite solid cylinders are nearer), with witnesses at the radii along it. The `f64`
/// feet only guide: the witnesses, pulled in by `2^-40` of the radii, are proved inside
/// their bodies (the upper bound) and the gap along their direction is proved with the
/// support functions (the lower bound), as for the search's answers. Closed form where the
/// search converges slowest (two curved sides); `None` elsewhere, and the search decides.
pub(super) fn lateral(a: &Body, b: &Body) -> Option<(f64, f64, P3, P3)> {
    let (Body::Cylinder(a0, a1, ra), Body::Cylinder(b0, b1, rb)) = (a, b) else {
        return None;
    };
    let (u, v, w) = (sub(a1, a0), sub(b1, b0), sub(a0, b0));
    let (uu, uv, vv) = (dot(&u, &u), dot(&u, &v), dot(&v, &v));
    let (uw, vw) = (dot(&u, &w), dot(&v, &w));
    let den = uu * vv - uv * uv;
    // Parallel or nearly: no single foot on each axis.
    if den.is_nan() || den <= 1e-12 * uu * vv {
        return None;
    }
    let s = (uv * vw - vv * uw) / den;
    let t = (uu * vw - uv * uw) / den;
    if !(s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) {
        return None;
    }
    let at = |o: &P3, d: &P3, x: f64| -> P3 { core::array::from_fn(|k| o[k] + x * d[k]) };
    let (p, q) = (at(a0, &u, s), at(b0, &v, t));
    // From `b`'s foot to `a`'s.
    let n = sub(&p, &q);
    let length = dot(&n, &n).sqrt();
    if !(length > ra + rb && length.is_finite()) {
        return None;
    }
    let inward = 1.0 - 1.0 / (1u64 << 40) as f64;
    let xa = lift(&at(&p, &n, -ra * inward / length));
    let xb = lift(&at(&q, &n, rb * inward / length));
    if !(a.holds(&xa) && b.holds(&xb)) {
        return None;
    }
    let upper = norm2(&sub3(&xa, &xb)).sqrt().hi;
    let lower = lower_bound(a, b, &n);
    (lower > 0.0 && lower <= upper && upper - lower <= LATERAL_WIDTH)
        .then(|| (lower, upper, middle(&xa), middle(&xb)))
}

/// Search steps for [`lower`]: a bound to set a pair aside with, not a distance.
const LOWER_STEPS: usize = 32;

/// A proved lower bound on the distance from a short search (no witness searches): a few microseconds where [`distance`] can take tens. `None` when
/// nothing is proved.
pub(super) fn lower(a: &Shape, b: &Shape) -> Option<f64> {
    let scale = unit_scale(magnitude(a).max(magnitude(b)));
    let (ba, bb) = (body(a, scale)?, body(b, scale)?);
    let found = search_steps(&ba, 0.0, &bb, 0.0, f64::INFINITY, LOWER_STEPS);
    if !(found.norm2 > 0.0 && found.norm2.is_finite()) {
        return None;
    }
    let lower = (lower_bound(&ba, &bb, &found.v) / scale)
        .next_down()
        .max(0.0);
    lower.is_finite().then_some(lower)
}

/// The filter's body of a shape; a cylinder or cone of radius `0` is its axis segment.
pub(super) fn body(s: &Shape, scale: f64) -> Option<Body> {
    let axis = |p: &Point3<f64>, q: &Point3<f64>| {
        crate::shape::Segment::new(*p, *q)
            .ok()
            .and_then(|g| Body::new(&Shape::Segment(g), scale))
    };
    match s {
        Shape::Cylinder(c) if c.radius() == 0.0 => axis(c.a(), c.b()),
        Shape::Cone(c) if c.radius() == 0.0 => axis(c.apex(), c.base()),
        _ => Body::new(s, scale),
    }
}

fn unscaled(x: &P3, scale: f64) -> Option<Point3<f64>> {
    let p = Point3::new(x[0] / scale, x[1] / scale, x[2] / scale);
    p.iter().all(|v| v.is_finite()).then_some(p)
}

/// `(min_A v·x − max_B v·y) / |v|` rounded down, or `0` when not positive.
fn lower_bound(a: &Body, b: &Body, v: &P3) -> f64 {
    let low_a = a.support_value(&v.map(|x| -x)).neg();
    let gap = low_a.sub(b.support_value(v));
    if gap.lo.is_nan() || gap.lo <= 0.0 {
        return 0.0;
    }
    let length = norm2(&lift(v)).sqrt();
    let lower = gap.div_positive(length).lo;
    if lower.is_finite() {
        lower.max(0.0)
    } else {
        0.0
    }
}

/// A proved upper bound on the distance and the two witness points (box middles), from a
/// search on the slightly shrunk bodies.
fn upper_bound(a: &Body, b: &Body) -> Option<(f64, P3, P3)> {
    let (ka, kb) = (a.max_shrink(), b.max_shrink());
    for f in SHRINK_FRACTIONS {
        let found = search_steps(a, f * ka, b, f * kb, f64::INFINITY, STEPS);
        let (Some(xa), Some(xb)) = (witness(a, &found, true), witness(b, &found, false)) else {
            continue;
        };
        let reach = norm2(&sub3(&xa, &xb)).sqrt().hi;
        if reach.is_finite() {
            return Some((reach, middle(&xa), middle(&xb)));
        }
    }
    None
}

fn middle(x: &IvP3) -> P3 {
    x.map(|c| 0.5 * c.lo + 0.5 * c.hi)
}

/// The search's point of `A` (`of_a`) or of `B` as an interval box proved inside the body.
fn witness(body: &Body, found: &Found, of_a: bool) -> Option<IvP3> {
    if let Body::Points(..) = body {
        return found.exact_point(body, of_a);
    }
    let x = lift(&found.point(of_a)?);
    body.holds(&x).then_some(x)
}

/// A point common to both bodies, proved to exist (the filter's shrunk searches); the point
/// reported is the `f64` middle of the deepest search's two witnesses.
fn common_point(a: &Body, b: &Body) -> Option<P3> {
    if !meets(a, b) {
        return None;
    }
    let (ka, kb) = (a.max_shrink(), b.max_shrink());
    let found = search(a, 0.25 * ka, b, 0.25 * kb, 0.0);
    let (xa, xb) = (found.point(true)?, found.point(false)?);
    let x: P3 = core::array::from_fn(|k| 0.5 * xa[k] + 0.5 * xb[k]);
    x.iter().all(|c| c.is_finite()).then_some(x)
}

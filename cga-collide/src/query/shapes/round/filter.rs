//! The certified floating-point filter in front of the exact round tests.
//!
//! A Gilbert–Johnson–Keerthi search in plain `f64` over the support functions of the two
//! bodies (a cylinder's support in direction `d` is the farther cap centre plus
//! `r·(d − (d·â)â)/|d − (d·â)â|`) proposes one of two certificates, each then checked in
//! outward-rounded interval arithmetic ([`super::interval`]):
//! * **apart**: a direction `d` with `min_A d·x − max_B d·y > c·|d|` (the support functions
//!   bounded outward, square roots included);
//! * **meeting**: a common point, found by running the same search on both bodies *shrunk*
//!   (every point of a shrunk body lies at that depth in the body) so the point found is deep
//!   in both, then proved inside each: for a polytope, the point is the exact convex
//!   combination of its vertices with the search's weights, held in an interval box; for a
//!   cylinder, cone, ball or capsule, slab and squared radial distance bounds.
//!
//! A half-space is decided by the body's lowest point along the normal, bounded both ways.
//! Nothing proved means `None`: the exact method decides (touching pairs, pairs closer than
//! the bounds, degenerate bodies, scales the `f64` range cannot hold).

use super::body::{dot, magnitude, scaled, scaled_point, sub, Body, P3};
use super::interval::{lift, norm2, Iv, IvP3};
use crate::query::shapes::polytopal::float_simplex::nearest_to_origin;
use crate::shape::{HalfSpace, Shape};

const MAX_STEPS: usize = 64;
/// Shrunk searches tried for a common point before giving up.
const MAX_SHRINKS: usize = 6;

/// A power of two `s` with `s · magnitude` in `[1, 2)` (clamped to the normal range).
pub(super) fn unit_scale(magnitude: f64) -> f64 {
    if magnitude == 0.0 || !magnitude.is_finite() {
        return 1.0;
    }
    let e = magnitude.log2().floor() as i32;
    2f64.powi((-e).clamp(-1022, 1022))
}

/// The proved answer of "is the distance between `a` and `b` at most `c`?", or `None`.
pub(super) fn within(a: &Shape, b: &Shape, c: f64) -> Option<bool> {
    if !(c >= 0.0 && c.is_finite()) {
        return None;
    }
    match (a, b) {
        (Shape::HalfSpace(h), o) | (o, Shape::HalfSpace(h)) => return half_space(o, h, c),
        _ => {}
    }
    let scale = unit_scale(magnitude(a).max(magnitude(b)).max(c));
    let (a, b, c) = (
        Body::new(a, scale)?,
        Body::new(b, scale)?,
        scaled(c, scale)?,
    );
    let found = search(&a, 0.0, &b, 0.0, c);
    if found.norm2 > 0.0 {
        if found.lower > 0.0 && apart(&a, &b, &found.v, c) {
            return Some(false);
        }
        // Not proved apart: worth a common point only if the search saw them (nearly) meet.
        let reach = a.max_shrink().max(b.max_shrink());
        if found.norm2.sqrt() > 1e-3 * reach {
            return None;
        }
    }
    meets(&a, &b).then_some(true)
}

/// `min_A d·x − max_B d·y > c·|d|`, proved.
fn apart(a: &Body, b: &Body, d: &P3, c: f64) -> bool {
    let low_a = a.support_value(&d.map(|x| -x)).neg();
    let gap = low_a.sub(b.support_value(d));
    gap.lo > Iv::point(c).mul(norm2(&lift(d)).sqrt()).hi
}

/// A common point, found by shrunk searches and proved.
pub(super) fn meets(a: &Body, b: &Body) -> bool {
    let (ka, kb) = (a.max_shrink(), b.max_shrink());
    let shrinkable = ka + kb > 0.0;
    if !shrinkable {
        return false;
    }
    let mut f = 0.5;
    for _ in 0..MAX_SHRINKS {
        let (sa, sb) = (f * ka, f * kb);
        let found = search(a, sa, b, sb, 0.0);
        let depth = [sa, sb]
            .into_iter()
            .filter(|s| *s > 0.0)
            .fold(f64::INFINITY, f64::min);
        let gap = found.norm2.sqrt();
        if gap <= 0.5 * depth {
            if common_point(a, b, &found) {
                return true;
            }
            f /= 16.0;
            continue;
        }
        // The shrunk bodies are `gap` apart, and the gap shrinks by at most `ka + kb` per unit
        // of `f`: the deepest common point is at about `f − gap / (ka + kb)`.
        let estimate = f - gap / (ka + kb);
        f = if estimate > 0.0 {
            0.5 * estimate
        } else {
            f / 16.0
        };
    }
    false
}

/// The search's witness points proved inside both bodies.
fn common_point(a: &Body, b: &Body, found: &Found) -> bool {
    if let Some(x) = found.exact_point(a, true) {
        return b.holds(&x);
    }
    if let Some(x) = found.exact_point(b, false) {
        return a.holds(&x);
    }
    let (Some(xa), Some(xb)) = (found.point(true), found.point(false)) else {
        return false;
    };
    let mid = lift(&core::array::from_fn(|k| 0.5 * xa[k] + 0.5 * xb[k]));
    a.holds(&mid) && b.holds(&mid)
}

/// One point of the difference `A − B` and the support points it came from.
#[derive(Clone, Copy, Debug, Default)]
struct Vertex {
    w: P3,
    a: P3,
    index_a: usize,
    b: P3,
    index_b: usize,
}

/// The search's end: the nearest point `v` of the difference of the last simplex, its squared
/// norm (`0`: the simplex holds the origin), the simplex with its weights, and `lower`, the
/// last `v·w` (with exact supports, every point `x` of the difference has `v·x ≥ lower`).
pub(super) struct Found {
    pub(super) v: P3,
    pub(super) norm2: f64,
    lower: f64,
    vertices: [Vertex; 4],
    weights: [f64; 4],
    len: usize,
}

impl Found {
    /// The simplex's weights clamped at `0`, and their sum (`None` unless positive and finite).
    fn clamped_weights(&self) -> Option<([f64; 4], f64)> {
        let weights = self.weights.map(|w| w.max(0.0));
        let total: f64 = weights[..self.len].iter().sum();
        (total > 0.0 && total.is_finite()).then_some((weights, total))
    }

    /// The search's point of `A` (`of_a`) or of `B` in plain `f64`: the weighted support
    /// points. A guide, never a proof.
    pub(super) fn point(&self, of_a: bool) -> Option<P3> {
        let (weights, total) = self.clamped_weights()?;
        let mut x = [0.0; 3];
        for (v, &w) in self.vertices[..self.len].iter().zip(&weights) {
            let p = if of_a { v.a } else { v.b };
            for (xk, pk) in x.iter_mut().zip(p) {
                *xk += w / total * pk;
            }
        }
        Some(x)
    }

    /// For a points body (`A` when `of_a`, else `B`), the search's point as the exact convex
    /// combination of its vertices divided by the exact sum, held in an interval box: proved
    /// in the hull. `None` for the other bodies.
    pub(super) fn exact_point(&self, body: &Body, of_a: bool) -> Option<IvP3> {
        let Body::Points(_, boxes) = body else {
            return None;
        };
        let (weights, _) = self.clamped_weights()?;
        let mut sum = [Iv::point(0.0); 3];
        let mut weight = Iv::point(0.0);
        for (v, &w) in self.vertices[..self.len].iter().zip(&weights) {
            let p = &boxes[if of_a { v.index_a } else { v.index_b }];
            sum = core::array::from_fn(|k| sum[k].add(Iv::point(w).mul(p[k])));
            weight = weight.add(Iv::point(w));
        }
        Some(sum.map(|s| s.div_positive(weight)))
    }
}

fn vertex(a: &Body, sa: f64, b: &Body, sb: f64, d: &P3) -> Vertex {
    let (pa, index_a) = a.support(&d.map(|x| -x), sa);
    let (pb, index_b) = b.support(d, sb);
    Vertex {
        w: sub(&pa, &pb),
        a: pa,
        index_a,
        b: pb,
        index_b,
    }
}

/// The `f64` search for the point of `A_sa − B_sb` nearest the origin. It stops early once
/// `v` separates with some margin (`v·w ≥ v·v / 2` and `v·w > c·|v|`): the proof needs
/// no more.
pub(super) fn search(a: &Body, sa: f64, b: &Body, sb: f64, c: f64) -> Found {
    search_steps(a, sa, b, sb, c, MAX_STEPS)
}

/// [`search`] with at most `steps` steps (curved bodies converge linearly: a distance wants
/// more than a yes/no proof does).
pub(super) fn search_steps(a: &Body, sa: f64, b: &Body, sb: f64, c: f64, steps: usize) -> Found {
    let (p0, _) = a.support(&[1.0, 0.0, 0.0], sa);
    let (q0, _) = b.support(&[-1.0, 0.0, 0.0], sb);
    let start = vertex(a, sa, b, sb, &sub(&p0, &q0));
    let mut found = Found {
        v: start.w,
        norm2: dot(&start.w, &start.w),
        lower: f64::NEG_INFINITY,
        vertices: [start; 4],
        weights: [1.0, 0.0, 0.0, 0.0],
        len: 1,
    };
    for _ in 0..steps {
        let points: [P3; 4] = core::array::from_fn(|i| found.vertices[i].w);
        let nearest = nearest_to_origin(&points[..found.len]);
        let mut kept = 0;
        for i in 0..found.len {
            if nearest.used & (1 << i) != 0 {
                found.vertices[kept] = found.vertices[i];
                found.weights[kept] = nearest.weights[i];
                kept += 1;
            }
        }
        found.len = kept.max(1);
        found.v = nearest.point;
        found.norm2 = nearest.norm2;
        let off_origin = found.norm2 > 0.0;
        if !off_origin || !found.norm2.is_finite() {
            if !found.norm2.is_finite() {
                found.norm2 = f64::INFINITY;
            }
            return found;
        }
        let next = vertex(a, sa, b, sb, &found.v);
        let vw = dot(&found.v, &next.w);
        found.lower = found.lower.max(vw);
        if vw >= 0.5 * found.norm2 && vw > c * found.norm2.sqrt() {
            return found;
        }
        let converged = found.norm2 - vw <= 1e-13 * found.norm2;
        let repeated = found.vertices[..found.len].iter().any(|u| u.w == next.w);
        if converged || repeated || found.len == 4 {
            return found;
        }
        found.vertices[found.len] = next;
        found.weights[found.len] = 0.0;
        found.len += 1;
    }
    found
}

/// A body against the half-space `(x − p)·n ≤ 0`: its lowest point along `n` bounded.
fn half_space(o: &Shape, h: &HalfSpace, c: f64) -> Option<bool> {
    let n = h.normal();
    let normal_scale = unit_scale(n.iter().fold(0.0f64, |m, x| m.max(x.abs())));
    let n = [
        scaled(n.x, normal_scale)?,
        scaled(n.y, normal_scale)?,
        scaled(n.z, normal_scale)?,
    ];
    let scale = unit_scale(
        magnitude(o)
            .max(c)
            .max(h.point().iter().fold(0.0f64, |m, x| m.max(x.abs()))),
    );
    let body = Body::new(o, scale)?;
    let (p, c) = (scaled_point(h.point(), scale)?, scaled(c, scale)?);
    let lowest = body.support_value(&n.map(|x| -x)).neg();
    let height = lowest.sub(super::interval::dot3(&lift(&n), &lift(&p)));
    let reach = Iv::point(c).mul(norm2(&lift(&n)).sqrt());
    if height.hi <= reach.lo {
        Some(true)
    } else if height.lo > reach.hi {
        Some(false)
    } else {
        None
    }
}

//! An exact reference for the signed distance of two shapes (distance when apart, minus the
//! penetration depth when overlapping), written apart from the product's method.
//!
//! * Two grown polytopes `hull(P) ⊕ ball(r)`, `hull(Q) ⊕ ball(s)` whose hulls are apart:
//!   `√D − r − s` with `D` the oracle's exact squared hull distance ([`super::hull`]).
//! * Whose hulls meet: `−(depth + r + s)`, where `depth` is the distance from the origin to
//!   the boundary of `M = hull(P) − hull(Q)`: 0 when `M` is flat (the rank of the point
//!   differences, exactly), else the least distance from the origin to a supporting plane of
//!   `M` over a brute-force set of normals holding every facet normal of `M` — each facet of a
//!   Minkowski sum is a facet of one summand plus a face of the other, or an edge of each, so
//!   its normal is a facet normal of `P` or `Q` (found by enumerating the planes through three
//!   points with all points on one side) or the cross product of an edge of `P` and one of `Q`
//!   (every difference of two points is tried). Hulls of more than [`MAX_POINTS`] distinct
//!   points are not judged.
//! * A half-space `{(x − p)·m ≤ 0}` against a grown polytope: `min (x − p)·m / |m| − s` over
//!   the hull's points.
//!
//! The truth is `sign · √X − R` with `X` and `R` exact rationals; [`Truth::contains`] checks
//! an interval exactly (squares compared, signs first).

use std::cmp::Ordering;

use cga_collide::shape::Shape;
use num_traits::{Signed, Zero};

use super::exact::{cross, dot, sub, P3, Q};
use super::hull::{distance2, distinct};
use super::{body, Body};

/// The largest number of distinct points of either hull for which the depth is judged.
pub const MAX_POINTS: usize = 12;

/// An exact signed distance: `(if outward { √X } else { −√X }) − R`.
#[derive(Debug, Clone)]
pub struct Truth {
    pub outward: bool,
    pub x: Q,
    pub r: Q,
}

fn q(x: f64) -> Q {
    super::exact::q(x)
}

/// `√x >= a`, exactly.
fn root_at_least(x: &Q, a: &Q) -> bool {
    !a.is_positive() || x >= &(a * a)
}

/// `√x <= b`, exactly.
fn root_at_most(x: &Q, b: &Q) -> bool {
    !b.is_negative() && x <= &(b * b)
}

impl Truth {
    /// Whether the true value lies in `[value − bound, value + bound]` (exactly).
    pub fn contains(&self, value: f64, bound: f64) -> bool {
        if !value.is_finite() || !bound.is_finite() || bound < 0.0 {
            return false;
        }
        let (lo, hi) = (q(value) - q(bound), q(value) + q(bound));
        let (lo, hi) = (lo + &self.r, hi + &self.r);
        if self.outward {
            root_at_least(&self.x, &lo) && root_at_most(&self.x, &hi)
        } else {
            root_at_most(&self.x, &-lo) && root_at_least(&self.x, &-hi)
        }
    }

    /// The sign of the true value.
    pub fn sign(&self) -> Ordering {
        if self.outward {
            let r2 = &self.r * &self.r;
            self.x.cmp(&r2)
        } else if self.x.is_zero() && self.r.is_zero() {
            Ordering::Equal
        } else {
            Ordering::Less
        }
    }

    /// The value rounded (for messages).
    pub fn approx(&self) -> f64 {
        use num_traits::ToPrimitive;
        let root = self.x.to_f64().unwrap_or(f64::NAN).sqrt();
        let r = self.r.to_f64().unwrap_or(f64::NAN);
        if self.outward {
            root - r
        } else {
            -root - r
        }
    }
}

/// The normals of the planes through three of `p` with all of `p` on one side (for a flat
/// `p`, its plane's normal).
fn facet_normals(p: &[P3]) -> Vec<P3> {
    let mut out = Vec::new();
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            for k in j + 1..p.len() {
                let n = cross(&sub(&p[j], &p[i]), &sub(&p[k], &p[i]));
                if dot(&n, &n).is_zero() {
                    continue;
                }
                let base = dot(&n, &p[i]);
                let sides: Vec<Ordering> = p.iter().map(|x| dot(&n, x).cmp(&base)).collect();
                if sides.iter().all(|s| *s != Ordering::Greater)
                    || sides.iter().all(|s| *s != Ordering::Less)
                {
                    out.push(n);
                }
            }
        }
    }
    out
}

/// The dimension of the span of `vectors` (exact elimination).
fn rank(vectors: &[P3]) -> usize {
    let mut rows: Vec<P3> = Vec::new();
    for v in vectors {
        let mut v = v.clone();
        for r in &rows {
            let k = (0..3).find(|&k| !r[k].is_zero()).unwrap_or(0);
            if !v[k].is_zero() {
                let f = &v[k] / &r[k];
                v = core::array::from_fn(|c| &v[c] - &f * &r[c]);
            }
        }
        if v.iter().any(|x| !x.is_zero()) {
            rows.push(v);
        }
    }
    rows.len()
}

fn differences(p: &[P3]) -> Vec<P3> {
    let mut out = Vec::new();
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            out.push(sub(&p[j], &p[i]));
        }
    }
    out
}

/// The squared depth of the origin in `M = hull(P) − hull(Q)` (which holds it): 0 when `M`
/// is flat, else the least `h_M(n)² / n·n` over every candidate facet normal of `M` (the
/// facet normals of `P` and of `Q`, and the cross products of a difference of two points of
/// `P` with one of `Q`, each taken both ways).
fn depth2(p: &[P3], q: &[P3]) -> Q {
    let (dp, dq) = (differences(p), differences(q));
    let all: Vec<P3> = dp.iter().chain(&dq).cloned().collect();
    if rank(&all) < 3 {
        return Q::zero();
    }
    let mut candidates = facet_normals(p);
    candidates.extend(facet_normals(q));
    for u in &dp {
        for v in &dq {
            candidates.push(cross(u, v));
        }
    }
    // Each candidate either way: the facet of `M` on that line may face either way, and
    // `h_M(n)` differs from `h_M(−n)` unless the origin is the centre of `M`.
    let opposite: Vec<P3> = candidates
        .iter()
        .map(|n| core::array::from_fn(|k| -n[k].clone()))
        .collect();
    candidates.extend(opposite);
    let mut best: Option<Q> = None;
    for n in candidates {
        let nn = dot(&n, &n);
        if nn.is_zero() {
            continue;
        }
        let hp = p.iter().map(|x| dot(&n, x)).max().unwrap_or_else(Q::zero);
        let hq = q.iter().map(|x| dot(&n, x)).min().unwrap_or_else(Q::zero);
        let h = hp - hq;
        let d = &h * &h / nn;
        if best.as_ref().is_none_or(|b| d < *b) {
            best = Some(d);
        }
    }
    best.unwrap_or_else(Q::zero)
}

fn half_grown(point: &P3, normal: &P3, points: &[P3], radius: &Q) -> Truth {
    let n = points
        .iter()
        .map(|x| dot(&sub(x, point), normal))
        .min()
        .unwrap_or_else(Q::zero);
    Truth {
        outward: !n.is_negative(),
        x: &n * &n / dot(normal, normal),
        r: radius.clone(),
    }
}

/// The exact signed distance of the pair, or `None` where this reference has no method
/// (cylinders, cones, two half-spaces, too many difference points).
pub fn signed_distance(a: &Shape, b: &Shape) -> Option<Truth> {
    match (body(a), body(b)) {
        (
            Body::Grown {
                points: p,
                radius: r,
            },
            Body::Grown {
                points: qs,
                radius: s,
            },
        ) => {
            let radii = &r + &s;
            let d = distance2(&p, &qs);
            if !d.is_zero() {
                return Some(Truth {
                    outward: true,
                    x: d,
                    r: radii,
                });
            }
            let (p, qs) = (distinct(&p), distinct(&qs));
            if p.len().max(qs.len()) > MAX_POINTS {
                return None;
            }
            Some(Truth {
                outward: false,
                x: depth2(&p, &qs),
                r: radii,
            })
        }
        (Body::Half { point, normal }, Body::Grown { points, radius })
        | (Body::Grown { points, radius }, Body::Half { point, normal }) => {
            Some(half_grown(&point, &normal, &points, &radius))
        }
        _ => None,
    }
}

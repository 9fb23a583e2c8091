//! The contact points of two facing features: both projected on the plane across the
//! normal, the lower-dimensional one clipped against the other, each clipped point lifted back
//! onto both features; then at most four kept.

use nalgebra::{Point3, Vector3};

use super::feature::{plane_basis, Feature};

/// A point of `a`'s feature and the point of `b`'s feature over it along the normal.
#[derive(Debug, Clone, Copy)]
pub(super) struct Pair {
    pub(super) a: Point3<f64>,
    pub(super) b: Point3<f64>,
}

type P2 = [f64; 2];

/// The plane across the normal, with an origin near the contact (for precision).
struct Frame {
    origin: Point3<f64>,
    n: Vector3<f64>,
    u: Vector3<f64>,
    v: Vector3<f64>,
}

impl Frame {
    fn to2(&self, p: &Point3<f64>) -> P2 {
        let r = p - self.origin;
        [r.dot(&self.u), r.dot(&self.v)]
    }

    fn to3(&self, q: &P2) -> Point3<f64> {
        self.origin + self.u * q[0] + self.v * q[1]
    }

    /// The point of `feature` over `q` (along the normal).
    fn lift(&self, feature: &Feature, q: &P2) -> Point3<f64> {
        match feature {
            Feature::Point(p) => *p,
            Feature::Segment(s, t) => {
                let (s2, t2) = (self.to2(s), self.to2(t));
                let e = [t2[0] - s2[0], t2[1] - s2[1]];
                let len2 = e[0] * e[0] + e[1] * e[1];
                let k = if len2 > 0.0 {
                    (((q[0] - s2[0]) * e[0] + (q[1] - s2[1]) * e[1]) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                s + (t - s) * k
            }
            Feature::Plane(p, m) => {
                let x = self.to3(q);
                let along = self.n.dot(m);
                if along == 0.0 {
                    x
                } else {
                    x + self.n * ((p - x).dot(m) / along)
                }
            }
            Feature::Polygon(ps) => self.lift_polygon(ps, q),
        }
    }

    /// Over `q` on the fan of triangles from the polygon's first corner: the fan triangle
    /// holding `q` (or the nearest to holding it), interpolated, so the point is a convex
    /// combination of the polygon's corners.
    fn lift_polygon(&self, ps: &[Point3<f64>], q: &P2) -> Point3<f64> {
        let p2: Vec<P2> = ps.iter().map(|p| self.to2(p)).collect();
        let mut best: Option<(f64, Point3<f64>)> = None;
        for i in 1..ps.len() - 1 {
            let Some(w) = barycentric(&p2[0], &p2[i], &p2[i + 1], q) else {
                continue;
            };
            let worst = w[0].min(w[1]).min(w[2]);
            if best.is_none_or(|(b, _)| worst > b) {
                let w = w.map(|x| x.max(0.0));
                let s = w[0] + w[1] + w[2];
                let p = Point3::from(
                    (ps[0].coords * w[0] + ps[i].coords * w[1] + ps[i + 1].coords * w[2]) / s,
                );
                best = Some((worst, p));
            }
        }
        best.map_or(ps[0], |(_, p)| p)
    }
}

fn barycentric(a: &P2, b: &P2, c: &P2, q: &P2) -> Option<[f64; 3]> {
    let area = cross(a, b, c);
    if area == 0.0 {
        return None;
    }
    let wa = cross(q, b, c) / area;
    let wb = cross(a, q, c) / area;
    Some([wa, wb, 1.0 - wa - wb])
}

fn cross(o: &P2, a: &P2, b: &P2) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

fn rank(f: &Feature) -> u8 {
    match f {
        Feature::Point(_) => 0,
        Feature::Segment(..) => 1,
        Feature::Polygon(_) => 2,
        Feature::Plane(..) => 3,
    }
}

/// The feature's corners projected, a polygon counter-clockwise.
fn projected(frame: &Frame, f: &Feature) -> Vec<P2> {
    let mut out: Vec<P2> = match f {
        Feature::Point(p) => vec![frame.to2(p)],
        Feature::Segment(s, t) => vec![frame.to2(s), frame.to2(t)],
        Feature::Polygon(ps) => ps.iter().map(|p| frame.to2(p)).collect(),
        Feature::Plane(..) => Vec::new(),
    };
    if out.len() >= 3 {
        let twice_area: f64 = (0..out.len())
            .map(|i| cross(&[0.0, 0.0], &out[i], &out[(i + 1) % out.len()]))
            .sum();
        if twice_area < 0.0 {
            out.reverse();
        }
    }
    out
}

/// Sutherland–Hodgman: the part of the convex polygon or segment `subject` inside the
/// counter-clockwise convex polygon `clip`.
fn clip_polygon(subject: &[P2], clip: &[P2]) -> Vec<P2> {
    let closed = subject.len() >= 3;
    let mut out = subject.to_vec();
    for i in 0..clip.len() {
        let (c0, c1) = (clip[i], clip[(i + 1) % clip.len()]);
        let side = |p: &P2| cross(&c0, &c1, p);
        let input = core::mem::take(&mut out);
        let m = input.len();
        let edges = if closed { m } else { m.saturating_sub(1) };
        if m == 1 {
            if side(&input[0]) >= 0.0 {
                out.push(input[0]);
            }
            continue;
        }
        for k in 0..edges {
            let (p, q) = (input[k], input[(k + 1) % m]);
            let (sp, sq) = (side(&p), side(&q));
            if sp >= 0.0 && (closed || k == 0) {
                out.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let t = sp / (sp - sq);
                out.push([p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t]);
            }
            if !closed && sq >= 0.0 {
                out.push(q);
            }
        }
        if out.is_empty() {
            break;
        }
    }
    out
}

/// The overlap of two segments that are parallel in the projection (else `None`).
fn parallel_overlap(s: &[P2], t: &[P2]) -> Option<Vec<P2>> {
    let e = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let f = [t[1][0] - t[0][0], t[1][1] - t[0][1]];
    let (le, lf) = (e[0].hypot(e[1]), f[0].hypot(f[1]));
    if le == 0.0 || lf == 0.0 || (e[0] * f[1] - e[1] * f[0]).abs() > 0.045 * le * lf {
        return None;
    }
    let along = |p: &P2| ((p[0] - s[0][0]) * e[0] + (p[1] - s[0][1]) * e[1]) / (le * le);
    let (t0, t1) = (along(&t[0]), along(&t[1]));
    let lo = t0.min(t1).max(0.0);
    let hi = t0.max(t1).min(1.0);
    (lo <= hi).then(|| {
        [lo, hi]
            .iter()
            .map(|k| [s[0][0] + e[0] * k, s[0][1] + e[1] * k])
            .collect()
    })
}

/// The contact points of `fa` (of `a`) and `fb` (of `b`) along the unit normal `n`, around
/// `origin`; empty when the features give no clipped region (the caller then uses the
/// signed distance's witnesses).
pub(super) fn contact_pairs(
    fa: &Feature,
    fb: &Feature,
    n: &Vector3<f64>,
    origin: Point3<f64>,
) -> Vec<Pair> {
    let (u, v) = plane_basis(n);
    let frame = Frame {
        origin,
        n: *n,
        u,
        v,
    };
    let (ra, rb) = (rank(fa), rank(fb));
    let (pa, pb) = (projected(&frame, fa), projected(&frame, fb));
    let region: Vec<P2> = match (ra, rb) {
        (3, 3) | (0, _) | (_, 0) => return Vec::new(),
        (3, _) => pb,
        (_, 3) => pa,
        (1, 1) => match parallel_overlap(&pa, &pb) {
            Some(r) => r,
            None => return Vec::new(),
        },
        _ if ra >= rb => clip_polygon(&pb, &pa),
        _ => clip_polygon(&pa, &pb),
    };
    region
        .iter()
        .map(|q| Pair {
            a: frame.lift(fa, q),
            b: frame.lift(fb, q),
        })
        .collect()
}

/// At most four of the points (deterministic): see [`keep_four`].
pub(super) fn reduce(points: Vec<(Pair, f64)>, n: &Vector3<f64>) -> Vec<(Pair, f64)> {
    let mids: Vec<Point3<f64>> = points
        .iter()
        .map(|(p, _)| Point3::from(p.a.coords + (p.b - p.a) * 0.5))
        .collect();
    let distances: Vec<f64> = points.iter().map(|(_, d)| *d).collect();
    keep_four(&mids, &distances, n)
        .into_iter()
        .map(|i| points[i])
        .collect()
}

/// The indices (ascending) of at most four of the points, deterministic: the deepest (least
/// distance, the first on ties), the one farthest from it across the normal `n`, the one
/// making the largest triangle with those two, and the one farthest outside that triangle's
/// edges (when one is outside).
pub(crate) fn keep_four(points: &[Point3<f64>], distance: &[f64], n: &Vector3<f64>) -> Vec<usize> {
    if points.len() <= super::MAX_POINTS_PER_REGION {
        return (0..points.len()).collect();
    }
    let (u, v) = plane_basis(n);
    let q: Vec<P2> = points
        .iter()
        .map(|m| [m.coords.dot(&u), m.coords.dot(&v)])
        .collect();
    let argmax = |score: &dyn Fn(usize) -> f64, taken: &[usize]| {
        let mut best: Option<(usize, f64)> = None;
        for i in (0..q.len()).filter(|i| !taken.contains(i)) {
            let s = score(i);
            if best.is_none_or(|(_, b)| s > b) {
                best = Some((i, s));
            }
        }
        best.map(|(i, _)| i)
    };
    let mut keep = Vec::with_capacity(4);
    let deepest = argmax(&|i| -distance[i], &keep).unwrap_or(0);
    keep.push(deepest);
    let d2 = |i: usize, j: usize| (q[i][0] - q[j][0]).powi(2) + (q[i][1] - q[j][1]).powi(2);
    if let Some(far) = argmax(&|i| d2(i, deepest), &keep) {
        keep.push(far);
    }
    let (k0, k1) = (keep[0], keep[1]);
    if let Some(third) = argmax(&|i| cross(&q[k0], &q[k1], &q[i]).abs(), &keep) {
        keep.push(third);
        let mut tri = [k0, k1, third];
        if cross(&q[k0], &q[k1], &q[third]) < 0.0 {
            tri.swap(0, 1);
        }
        let outside = |i: usize| {
            (0..3)
                .map(|e| -cross(&q[tri[e]], &q[tri[(e + 1) % 3]], &q[i]))
                .fold(f64::NEG_INFINITY, f64::max)
        };
        if let Some(fourth) = argmax(&outside, &keep) {
            if outside(fourth) > 0.0 {
                keep.push(fourth);
            }
        }
    }
    keep.sort_unstable();
    keep
}

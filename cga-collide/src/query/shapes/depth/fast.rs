//! The signed distance of two polytopal shapes in plain `f64` with a proved error bound: the
//! fast path in front of the exact one ([`super::polytope`]), taken whenever its bound is
//! small against the answer.
//!
//! **Overlapping cores.** The depth of the origin in `M = P − Q` is `min over unit n of
//! h_M(n)` and, when `M` is solid, the minimum over its facet normals, each the cross product
//! of two edge directions (a facet pair of `P` or of `Q`, or an edge of `P` with an edge of `Q`;
//! see [`super::polytope`]; between two solid hulls only the edge pairs whose Gauss-map arcs
//! may cross, [`arcs`]). Each candidate `f` is formed in `f64` as `ñ` with a proved
//! componentwise bound `|f − ñ| ≤ ε`; since `|h_M(f) − h_M(ñ)| ≤ Σ_k ε_k X_k` with `X_k` the
//! largest `|x_k|` over `M`, every candidate gets a proved interval of `h_M(f)/|f|`. When every
//! candidate's lower end is `> 0` the origin is inside every facet: the cores overlap, and the
//! depth lies between the least lower end and the least upper end (any direction's
//! `h_M(ñ)/|ñ|` bounds the depth from above). It is used only when at least one core is solid
//! (so `M` is) and every nonzero input lies within `2^±250` (so no product under- or
//! overflows and each rounding is relative).
//!
//! **Cores apart, radii overlapping** (a ball or capsule sunk into something): the cores'
//! certified distance `d` gives `d − r − s`; for point, segment and cuboid cores `d` is
//! bracketed in closed form ([`apart`]), otherwise it comes from the `f64` search.
//!
//! Either answer is returned only when its proved bound is at most `2^-30 · |value|`; otherwise
//! (touching, a few ulps of overlap, huge or tiny coordinates, near-degenerate directions) the
//! exact path decides, so every answer keeps its kind exactly.

mod apart;
mod arcs;

use nalgebra::{Point3, Vector3};

use super::{unit, SignedDistance, SignedDistanceKind};
use crate::query::shapes::polytopal;
use crate::query::shapes::rounded_f64::{cross, dot, tame, P3, U};
use crate::shape::{Ball, Segment, Shape};

/// The fast answer is kept when its bound is at most this fraction of `|value|`.
const RELATIVE: f64 = 1.0 / (1u64 << 30) as f64;
/// The most candidate-times-point evaluations the fast path spends before leaving the pair to
/// the exact path (hull pairs with many edges).
const BUDGET: usize = 400_000;

/// A core in `f64`: a cuboid in closed form, or exact points.
enum Core {
    Cuboid { centre: P3, axes: [P3; 3] },
    Points(Vec<P3>),
}

/// A core with its edge directions (and the relative error of each), the pairs of directions
/// whose crosses contain its facet normals, its radius, the largest `|x_k|` over it, and
/// whether it is solid.
struct Prepared {
    core: Core,
    directions: Vec<(P3, f64)>,
    facet_pairs: Vec<(usize, usize)>,
    radius: f64,
    extent: P3,
    solid: bool,
    /// Solid hulls: each direction's (edge's) Gauss-map arc, for pruning edge pairs.
    arcs: Option<Vec<arcs::Arc>>,
}

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

fn all_pairs(n: usize) -> Vec<(usize, usize)> {
    (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .collect()
}

fn points_core(points: Vec<P3>, radius: f64) -> Prepared {
    let mut directions = Vec::new();
    for (i, a) in points.iter().enumerate() {
        for b in &points[i + 1..] {
            // One rounding: within `u` of the exact difference, relatively.
            directions.push(([b[0] - a[0], b[1] - a[1], b[2] - a[2]], U * 1.01));
        }
    }
    let facet_pairs = all_pairs(directions.len());
    let extent = extent_of(&points);
    Prepared {
        core: Core::Points(points),
        directions,
        facet_pairs,
        radius,
        extent,
        solid: false,
        arcs: None,
    }
}

/// A solid hull: its edges (diagonals of facets included) as directions, two edges of each
/// boundary triangle as a facet pair.
fn solid_hull(corners: Vec<P3>, triangles: &[[u32; 3]]) -> Prepared {
    let mut edges: Vec<(u32, u32)> = Vec::new();
    let mut faces_of_edge: Vec<Vec<usize>> = Vec::new();
    let mut facet_pairs = Vec::new();
    let mut index = |u: u32, v: u32, face: usize| {
        let key = (u.min(v), u.max(v));
        let at = edges.iter().position(|e| *e == key).unwrap_or_else(|| {
            edges.push(key);
            faces_of_edge.push(Vec::new());
            edges.len() - 1
        });
        faces_of_edge[at].push(face);
        at
    };
    for (face, t) in triangles.iter().enumerate() {
        let i = index(t[0], t[1], face);
        let j = index(t[0], t[2], face);
        index(t[1], t[2], face);
        facet_pairs.push((i, j));
    }
    let directions = edges
        .iter()
        .map(|&(u, v)| {
            let (a, b) = (corners[u as usize], corners[v as usize]);
            ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], U * 1.01)
        })
        .collect();
    let extent = extent_of(&corners);
    let arcs = arcs::of_hull(&corners, triangles, &faces_of_edge);
    Prepared {
        core: Core::Points(corners),
        directions,
        facet_pairs,
        radius: 0.0,
        extent,
        solid: true,
        arcs,
    }
}

fn extent_of(points: &[P3]) -> P3 {
    core::array::from_fn(|k| points.iter().fold(0.0f64, |m, p| m.max(p[k].abs())))
}

impl Prepared {
    fn of(shape: &Shape) -> Option<Prepared> {
        let prepared = match shape {
            Shape::Ball(b) => points_core(vec![p3(b.centre())], b.radius()),
            Shape::Capsule(c) => points_core(vec![p3(c.a()), p3(c.b())], c.radius()),
            Shape::Segment(s) => points_core(vec![p3(s.a()), p3(s.b())], 0.0),
            Shape::Triangle(t) => points_core(t.vertices().iter().map(p3).collect(), 0.0),
            Shape::Cuboid(c) => {
                let centre = p3(c.centre());
                let axes = c.half_axes().map(|a| [a.x, a.y, a.z]);
                let extent = core::array::from_fn(|k| {
                    centre[k].abs() + axes.iter().map(|a| a[k].abs()).sum::<f64>()
                });
                // Solid when the triple product is provably nonzero.
                let triple = dot(&axes[0], &cross(&axes[1], &axes[2]));
                let size: f64 = axes
                    .iter()
                    .map(|a| a.iter().map(|x| x.abs()).sum::<f64>())
                    .product();
                Prepared {
                    core: Core::Cuboid { centre, axes },
                    directions: axes.iter().map(|a| (*a, 0.0)).collect(),
                    facet_pairs: all_pairs(3),
                    radius: 0.0,
                    extent: extent.map(|x: f64| x * (1.0 + 4.0 * U)),
                    solid: triple.abs() > 8.0 * U * size,
                    arcs: None,
                }
            }
            Shape::ConvexHull(h) => {
                let corners: Vec<P3> = h.corners().iter().map(p3).collect();
                if h.dimension() == 3 {
                    solid_hull(corners, h.triangles())
                } else if corners.len() <= 16 {
                    // A flat hull's directions are all its corner differences: kept small.
                    points_core(corners, 0.0)
                } else {
                    return None;
                }
            }
            Shape::HalfSpace(_) | Shape::Cylinder(_) | Shape::Cone(_) => return None,
        };
        let mut values: Vec<f64> = prepared.extent.to_vec();
        values.push(prepared.radius);
        match &prepared.core {
            Core::Cuboid { centre, axes } => {
                values.extend(centre);
                values.extend(axes.iter().flatten());
            }
            Core::Points(points) => values.extend(points.iter().flatten()),
        }
        tame(&values).then_some(prepared)
    }

    fn point_count(&self) -> usize {
        match &self.core {
            Core::Cuboid { .. } => 4,
            Core::Points(p) => p.len(),
        }
    }

    /// The largest `n · x` over the core, rounded (within `8u Σ|n_k| extent_k` of the exact
    /// maximum over the exact core), and a point attaining it, rounded.
    fn support(&self, n: &P3) -> (f64, P3) {
        match &self.core {
            Core::Cuboid { centre, axes } => {
                let mut value = dot(n, centre);
                let mut point = *centre;
                for a in axes {
                    let s = dot(n, a);
                    let sign = if s >= 0.0 { 1.0 } else { -1.0 };
                    value += s.abs();
                    for k in 0..3 {
                        point[k] += sign * a[k];
                    }
                }
                (value, point)
            }
            Core::Points(points) => {
                let mut best = (dot(n, &points[0]), points[0]);
                for p in &points[1..] {
                    let d = dot(n, p);
                    if d > best.0 {
                        best = (d, *p);
                    }
                }
                best
            }
        }
    }
}

/// A proved interval of the penetration depth of the overlapping cores, with the direction of
/// the least upper end and the two support points along it; `None` when the cores are not
/// proved to overlap.
fn core_depth(a: &Prepared, b: &Prepared) -> Option<(f64, f64, P3, P3, P3)> {
    if !(a.solid || b.solid) {
        return None;
    }
    let na = a.directions.len();
    let mut lines: Vec<(usize, usize)> = a.facet_pairs.clone();
    lines.extend(b.facet_pairs.iter().map(|&(i, j)| (na + i, na + j)));
    for i in 0..na {
        match (&a.arcs, &b.arcs) {
            // Two solid hulls: only the edge pairs whose Gauss-map arcs may cross.
            (Some(pa), Some(pb)) => lines.extend(
                (0..b.directions.len())
                    .filter(|&j| arcs::may_face(&pa[i], &pb[j]))
                    .map(|j| (i, na + j)),
            ),
            _ => lines.extend((0..b.directions.len()).map(|j| (i, na + j))),
        }
    }
    if lines.len() * 2 * (a.point_count() + b.point_count()) > BUDGET {
        return None;
    }
    let direction = |i: usize| {
        if i < na {
            a.directions[i]
        } else {
            b.directions[i - na]
        }
    };
    let extent: P3 = core::array::from_fn(|k| a.extent[k] + b.extent[k]);
    let (mut low, mut high) = (f64::INFINITY, f64::INFINITY);
    let mut best: Option<(P3, P3, P3)> = None;
    for (i, j) in lines {
        let ((d, ed), (e, ee)) = (direction(i), direction(j));
        let n = cross(&d, &e);
        // |f_k − ñ_k| ≤ (|d_i e_j| + |d_j e_i|)(ε_d + ε_e + 3u), per component.
        let rel = ed + ee + 3.0 * U;
        let err: P3 = [
            (d[1] * e[2]).abs() + (d[2] * e[1]).abs(),
            (d[2] * e[0]).abs() + (d[0] * e[2]).abs(),
            (d[0] * e[1]).abs() + (d[1] * e[0]).abs(),
        ]
        .map(|x| x * rel * (1.0 + 4.0 * U));
        let err_sum = err[0] + err[1] + err[2];
        let length = dot(&n, &n).sqrt();
        if length == 0.0 && err_sum == 0.0 {
            continue; // exactly parallel directions: no facet normal here
        }
        for n in [n, n.map(|x| -x)] {
            let (hp, sp) = a.support(&n);
            let minus = n.map(|x| -x);
            let (hq, sq) = b.support(&minus);
            let h = hp + hq;
            let rounding = 8.0
                * U
                * (n[0].abs() * extent[0] + n[1].abs() * extent[1] + n[2].abs() * extent[2])
                + 4.0 * U * h.abs();
            let shift = err[0] * extent[0] + err[1] * extent[1] + err[2] * extent[2];
            let lo = (h - rounding - shift) * (1.0 - 8.0 * U);
            let lo = if lo > 0.0 {
                lo / (length * (1.0 + 8.0 * U) + err_sum) * (1.0 - 8.0 * U)
            } else {
                return None; // this candidate does not prove the origin inside
            };
            low = low.min(lo);
            if length > 0.0 {
                let hi =
                    (h + rounding) * (1.0 + 8.0 * U) / (length * (1.0 - 8.0 * U)) * (1.0 + 8.0 * U);
                if hi < high {
                    high = hi;
                    best = Some((n, sp, sq));
                }
            }
        }
    }
    let (n, sp, sq) = best?;
    (low.is_finite() && high.is_finite()).then_some((low, high, n, sp, sq))
}

/// The core of a ball or capsule (its centre or axis), and the shape itself otherwise.
fn core_shape(s: &Shape) -> Option<Shape> {
    match s {
        Shape::Ball(b) => Ball::new(*b.centre(), 0.0).ok().map(Shape::Ball),
        Shape::Capsule(c) => Segment::new(*c.a(), *c.b()).ok().map(Shape::Segment),
        _ => None,
    }
}

/// The fast signed distance of two polytopal shapes (neither a half-space, cylinder or cone),
/// or `None` when the exact path must decide.
pub(super) fn signed_distance(a: &Shape, b: &Shape) -> Option<SignedDistance> {
    let (pa, pb) = (Prepared::of(a)?, Prepared::of(b)?);
    let radii = pa.radius + pb.radius;
    if let Some((low, high, n, sp, sq)) = core_depth(&pa, &pb) {
        let lo = (low + radii) * (1.0 - 2.0 * U);
        let hi = (high + radii) * (1.0 + 2.0 * U);
        let value = -(lo + hi) * 0.5;
        let bound = (((hi - lo) * 0.5 + 2.0 * U * hi) * (1.0 + 4.0 * U)).next_up();
        if bound > RELATIVE * value.abs() {
            return None;
        }
        let normal = unit(&Vector3::from(n));
        return Some(SignedDistance {
            value,
            error_bound: bound,
            normal,
            witness_a: Point3::from(sp) + normal * pa.radius,
            witness_b: Point3::from(sq) - normal * pb.radius,
            kind: SignedDistanceKind::Penetrating,
        });
    }
    if radii == 0.0 {
        return None;
    }
    // Cores apart and radii reaching across: the cores' distance minus the radii, in closed
    // form for point, segment and cuboid cores, else from the certified core distance.
    let (distance, error, wa, wb) = match apart::bracket(&pa, &pb) {
        Some(br) => {
            let mid = (br.low + br.high) * 0.5;
            let half = ((br.high - br.low) * 0.5 + 2.0 * U * br.high) * (1.0 + 4.0 * U);
            (mid, half, Point3::from(br.x), Point3::from(br.y))
        }
        None => {
            let (ca, cb) = (
                core_shape(a).unwrap_or_else(|| a.clone()),
                core_shape(b).unwrap_or_else(|| b.clone()),
            );
            let d = polytopal::distance(&ca, &cb);
            if d.distance - d.error_bound <= 0.0
                || d.distance.is_nan()
                || !d.error_bound.is_finite()
            {
                return None;
            }
            (d.distance, d.error_bound, d.witness_a, d.witness_b)
        }
    };
    let value = distance - radii;
    let bound = ((error + 2.0 * U * (distance + radii)) * (1.0 + 4.0 * U)).next_up();
    if bound > RELATIVE * value.abs() {
        return None;
    }
    let kind = if value > 0.0 {
        SignedDistanceKind::Separated
    } else {
        SignedDistanceKind::Penetrating
    };
    let normal = unit(&(wb - wa));
    Some(SignedDistance {
        value,
        error_bound: bound,
        normal,
        witness_a: wa + normal * pa.radius,
        witness_b: wb - normal * pb.radius,
        kind,
    })
}

//! The penetration depth of two overlapping convex polytopes, exactly.
//!
//! For cores `P` and `Q` that meet, the origin lies in `M = P − Q`, and the shortest
//! translation of `Q` that leaves the two with disjoint interiors is the distance from the
//! origin to the boundary of `M`: `depth = min over unit n of h_M(n)` with the support
//! function `h_M(n) = h_P(n) + h_Q(−n)`. The minimum is attained at a facet normal of `M`
//! (or, when `M` is flat, at a normal of its plane, where it is 0), and every facet of the
//! Minkowski sum is a face of `P` plus a face of `−Q`, so its normal is the cross product of
//! two edge directions of `P` and `Q`: a facet normal of `P`, one of `Q`, or an edge of `P`
//! crossed with an edge of `Q`. This module takes a finite superset of those normals — every
//! direction of `P` crossed with every direction of `Q`, the facet normals of each core (for
//! the small cores every cross product of two of its directions; for an exact hull two edges
//! of each boundary triangle), each direction crossed with the coordinate axes, and the axes —
//! and minimises `(h_P(n) + h_Q(−n)) / |n|` over it. Any candidate only gives an upper
//! bound of the depth (`h_M(n) ≥ depth·|n|` for every `n`), so extra candidates are harmless.
//!
//! The minimum is found in two passes: every candidate is evaluated on [`ErrF64`] (a proved
//! interval of its value), and only the candidates whose interval reaches below the smallest
//! upper end are evaluated exactly in rationals, compared by their squares
//! `(h_P(n) + h_Q(−n))² / n·n`. The exact minimum is rounded once ([`super::rounding`]).

use ga_core::scalar::{rational_from_f64, Rational, Real, Ring};
use nalgebra::{Point3, Vector3};

use crate::exact::vector::{cross, dot};
use crate::exact::ErrF64;
use crate::shape::{ConvexHull, Shape};

type P3 = [f64; 3];

/// The largest number of corners of a hull whose penetration depth is computed (the candidate
/// set grows as the product of the two shapes' edge counts, and each candidate is evaluated at
/// every corner).
pub const MAX_HULL_POINTS: usize = 128;

/// An exact point or vector: the exact sum of up to four `f64` vectors (a cuboid's corner
/// `c ± U ± V ± W`, the difference of two points); negation is exact, so signs live in the
/// terms.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sum {
    terms: [P3; 4],
    len: usize,
}

impl Sum {
    fn of(terms: &[P3]) -> Sum {
        let mut s = Sum {
            terms: [[0.0; 3]; 4],
            len: terms.len(),
        };
        s.terms[..terms.len()].copy_from_slice(terms);
        s
    }

    fn difference(a: &P3, b: &P3) -> Sum {
        Sum::of(&[*a, b.map(|x| -x)])
    }

    /// The coordinates in the ring `R`, each the sum of its lifted terms.
    pub(super) fn lift<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 3] {
        core::array::from_fn(|k| {
            let mut s = lift(self.terms[0][k]);
            for t in &self.terms[1..self.len] {
                s = s + lift(t[k]);
            }
            s
        })
    }

    /// The `f64` vectors whose exact sum this is.
    pub(super) fn parts(&self) -> &[P3] {
        &self.terms[..self.len]
    }

    /// The coordinates rounded to `f64`.
    pub(super) fn approx(&self) -> P3 {
        core::array::from_fn(|k| self.terms[..self.len].iter().map(|t| t[k]).sum())
    }
}

/// A shape as core ⊕ ball(radius), with the core's points, a set of directions that contains
/// every edge direction of the core, and the pairs of those directions whose cross products
/// contain every facet normal of the core (`None`: every pair).
pub(super) struct Core {
    pub(super) points: Vec<Sum>,
    pub(super) directions: Vec<Sum>,
    pub(super) facet_pairs: Option<Vec<(usize, usize)>>,
    pub(super) radius: f64,
}

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

fn v3(v: &Vector3<f64>) -> P3 {
    [v.x, v.y, v.z]
}

impl Core {
    /// The core of a polytopal shape; `None` for half-spaces, cylinders and cones, and for
    /// hulls of more than [`MAX_HULL_POINTS`] points.
    pub(super) fn of(shape: &Shape) -> Option<Core> {
        let polygon = |pts: &[P3], radius: f64| {
            let mut directions = Vec::new();
            for (i, a) in pts.iter().enumerate() {
                for b in &pts[i + 1..] {
                    directions.push(Sum::difference(b, a));
                }
            }
            Core {
                points: pts.iter().map(|p| Sum::of(&[*p])).collect(),
                directions,
                facet_pairs: None,
                radius,
            }
        };
        Some(match shape {
            Shape::Ball(b) => polygon(&[p3(b.centre())], b.radius()),
            Shape::Capsule(c) => polygon(&[p3(c.a()), p3(c.b())], c.radius()),
            Shape::Segment(s) => polygon(&[p3(s.a()), p3(s.b())], 0.0),
            Shape::Triangle(t) => polygon(&t.vertices().map(|p| p3(&p)), 0.0),
            Shape::ConvexHull(h) => {
                if h.corners().len() > MAX_HULL_POINTS {
                    return None;
                }
                hull_core(h)
            }
            Shape::Cuboid(c) => {
                let axes = c.half_axes().map(|a| v3(&a));
                let centre = p3(c.centre());
                let points = (0..8)
                    .map(|i: usize| {
                        let mut terms = [centre; 4];
                        for (k, axis) in axes.iter().enumerate() {
                            terms[k + 1] = if i >> k & 1 == 1 {
                                *axis
                            } else {
                                axis.map(|x| -x)
                            };
                        }
                        Sum::of(&terms)
                    })
                    .collect();
                Core {
                    points,
                    directions: axes.iter().map(|a| Sum::of(&[*a])).collect(),
                    facet_pairs: None,
                    radius: 0.0,
                }
            }
            Shape::HalfSpace(_) | Shape::Cylinder(_) | Shape::Cone(_) => return None,
        })
    }
}

/// The core of an exact hull: its corners; as directions its edges (a flat polygon's
/// boundary edges, a solid's triangulation edges, diagonals of facets included), which contain
/// every edge direction; as facet pairs two edges of each triangle (a solid) or of the polygon.
fn hull_core(h: &ConvexHull) -> Core {
    let corners: Vec<P3> = h.corners().iter().map(p3).collect();
    let mut edges: Vec<(u32, u32)> = Vec::new();
    let mut facet_pairs = Vec::new();
    let edge_index = |u: u32, v: u32, edges: &mut Vec<(u32, u32)>| {
        let key = (u.min(v), u.max(v));
        match edges.iter().position(|e| *e == key) {
            Some(i) => i,
            None => {
                edges.push(key);
                edges.len() - 1
            }
        }
    };
    match h.dimension() {
        3 => {
            for t in h.triangles() {
                let i = edge_index(t[0], t[1], &mut edges);
                let j = edge_index(t[0], t[2], &mut edges);
                edge_index(t[1], t[2], &mut edges);
                facet_pairs.push((i, j));
            }
        }
        _ => {
            let n = corners.len() as u32;
            for k in 0..n {
                // A segment's two corners give one edge (twice, deduplicated).
                if n > 1 {
                    edge_index(k, (k + 1) % n, &mut edges);
                }
            }
            if edges.len() >= 2 {
                facet_pairs.push((0, 1));
            }
        }
    }
    Core {
        points: corners.iter().map(|p| Sum::of(&[*p])).collect(),
        directions: edges
            .iter()
            .map(|&(u, v)| Sum::difference(&corners[v as usize], &corners[u as usize]))
            .collect(),
        facet_pairs: Some(facet_pairs),
        radius: 0.0,
    }
}

/// One candidate line: a coordinate axis, a direction crossed with an axis, or the cross
/// product of two directions (indices into the directions of `P` followed by those of `Q`).
#[derive(Debug, Clone, Copy)]
enum Line {
    Axis(usize),
    WithAxis(usize, usize),
    Pair(usize, usize),
}

/// One candidate normal: a [`Line`] taken either way. Both ways are needed: `h_M(n)` and
/// `h_M(−n)` differ whenever the origin is not the centre of `M`, and the facet normal that
/// attains the depth may point either way along the cross product that spans it.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    line: Line,
    negated: bool,
}

fn axis<R: Ring>(k: usize) -> [R; 3] {
    core::array::from_fn(|i| if i == k { R::one() } else { R::zero() })
}

impl Candidate {
    fn vector<R: Ring>(&self, directions: &[[R; 3]]) -> [R; 3] {
        let v: [R; 3] = match self.line {
            Line::Axis(k) => axis(k),
            Line::WithAxis(i, k) => cross(&directions[i], &axis(k)),
            Line::Pair(i, j) => cross(&directions[i], &directions[j]),
        };
        if self.negated {
            v.map(|x| -x)
        } else {
            v
        }
    }
}

/// The candidate normals of `P − Q`: the axes, every direction crossed with an axis, the
/// facet pairs of each core, and every direction of `P` crossed with every direction of `Q`.
fn candidates(a: &Core, b: &Core) -> Vec<Candidate> {
    let (na, nb) = (a.directions.len(), b.directions.len());
    let mut lines: Vec<Line> = (0..3).map(Line::Axis).collect();
    for i in 0..na + nb {
        lines.extend((0..3).map(|k| Line::WithAxis(i, k)));
    }
    for (core, offset) in [(a, 0), (b, na)] {
        let n = core.directions.len();
        match &core.facet_pairs {
            Some(pairs) => lines.extend(
                pairs
                    .iter()
                    .map(|&(i, j)| Line::Pair(offset + i, offset + j)),
            ),
            None => {
                for i in 0..n {
                    lines.extend((i + 1..n).map(|j| Line::Pair(offset + i, offset + j)));
                }
            }
        }
    }
    for i in 0..na {
        lines.extend((0..nb).map(|j| Line::Pair(i, na + j)));
    }
    lines
        .into_iter()
        .flat_map(|line| [false, true].map(|negated| Candidate { line, negated }))
        .collect()
}

/// The exact penetration depth of two meeting cores, squared, with its normal.
pub(super) struct Depth {
    /// `depth²`, exactly.
    pub(super) depth2: Rational,
    /// The unit normal (rounded): translating `Q` by `depth · normal` separates the cores.
    pub(super) normal: Vector3<f64>,
    /// A point of `P` extreme along the normal, rounded.
    pub(super) support_a: P3,
    /// A point of `Q` extreme along minus the normal, rounded.
    pub(super) support_b: P3,
}

type E3 = [ErrF64; 3];

/// Proved bounds `(low, high)` of the largest (`largest`) or smallest `n · x` over `points`.
fn extreme(points: &[E3], n: &E3, largest: bool) -> (f64, f64) {
    let mut bounds = if largest {
        (f64::NEG_INFINITY, f64::NEG_INFINITY)
    } else {
        (f64::INFINITY, f64::INFINITY)
    };
    for p in points {
        let d = dot(p, n);
        let slack = d.error * (1.0 + 1e-9);
        let (lo, hi) = ((d.value - slack).next_down(), (d.value + slack).next_up());
        bounds = if largest {
            (bounds.0.max(lo), bounds.1.max(hi))
        } else {
            (bounds.0.min(lo), bounds.1.min(hi))
        };
    }
    bounds
}

/// A proved interval of `(h_P(n) + h_Q(−n)) / |n|` for the `f64`-lifted candidate `n`, or
/// `None` when `n` is exactly zero.
fn interval(p: &[E3], q: &[E3], n: &E3) -> Option<(f64, f64)> {
    let unknown = Some((0.0, f64::INFINITY));
    let nn = dot(n, n);
    if nn.value == 0.0 && nn.error == 0.0 {
        return None;
    }
    let (pl, ph) = extreme(p, n, true);
    let (ql, qh) = extreme(q, n, false);
    let (hl, hh) = ((pl - qh).next_down().max(0.0), (ph - ql).next_up());
    let slack = nn.error * (1.0 + 1e-9);
    let (nl, nh) = ((nn.value - slack).next_down(), (nn.value + slack).next_up());
    if ![hl, hh, nl, nh].iter().all(|x| x.is_finite()) {
        return unknown;
    }
    let low = (hl / nh.sqrt().next_up()).next_down().max(0.0);
    let high = if nl > 0.0 {
        (hh / nl.sqrt().next_down()).next_up()
    } else {
        f64::INFINITY
    };
    Some((low, high))
}

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

/// The index of the point maximising `n · x` (the first on ties) and the maximum, exactly.
fn exact_max(points: &[[Rational; 3]], n: &[Rational; 3]) -> (usize, Rational) {
    let mut best = (0, dot(&points[0], n));
    for (i, p) in points.iter().enumerate().skip(1) {
        let d = dot(p, n);
        if d > best.1 {
            best = (i, d);
        }
    }
    best
}

/// The exact penetration depth of the meeting cores `a` and `b` (the caller has proved that
/// they meet), its normal and support points.
pub(super) fn depth(a: &Core, b: &Core) -> Depth {
    let directions: Vec<Sum> = a.directions.iter().chain(&b.directions).copied().collect();
    let all = candidates(a, b);
    let lift_e = |s: &Sum| s.lift(&ErrF64::exact);
    let (pe, qe): (Vec<E3>, Vec<E3>) = (
        a.points.iter().map(lift_e).collect(),
        b.points.iter().map(lift_e).collect(),
    );
    let de: Vec<E3> = directions.iter().map(lift_e).collect();
    let bounds: Vec<Option<(f64, f64)>> = all
        .iter()
        .map(|c| interval(&pe, &qe, &c.vector(&de)))
        .collect();
    let best_high = bounds
        .iter()
        .flatten()
        .map(|b| b.1)
        .fold(f64::INFINITY, f64::min);
    // The exact pass over the candidates the intervals cannot rule out.
    let lift_q = |s: &Sum| s.lift(&q);
    let pq: Vec<[Rational; 3]> = a.points.iter().map(lift_q).collect();
    let qq: Vec<[Rational; 3]> = b.points.iter().map(lift_q).collect();
    let dq: Vec<[Rational; 3]> = directions.iter().map(lift_q).collect();
    let mut best: Option<(Rational, [Rational; 3], usize, usize)> = None;
    for (c, bound) in all.iter().zip(&bounds) {
        match bound {
            Some((low, _)) if *low <= best_high => {}
            _ => continue,
        }
        let n = c.vector(&dq);
        let nn = dot(&n, &n);
        if nn.is_zero() {
            continue;
        }
        let (ia, ha) = exact_max(&pq, &n);
        let minus: [Rational; 3] = core::array::from_fn(|k| -n[k].clone());
        let (ib, hb) = exact_max(&qq, &minus);
        let mut h = ha + hb;
        if h < <Rational as Ring>::zero() {
            // Impossible when the cores meet (the origin is in M); kept total.
            h = <Rational as Ring>::zero();
        }
        let ratio = &h * &h / nn;
        if best.as_ref().is_none_or(|b| ratio < b.0) {
            best = Some((ratio, n, ia, ib));
        }
    }
    // The axes are never zero, so some candidate always survives.
    let (depth2, n, ia, ib) = best.unwrap_or_else(|| {
        let n = axis::<Rational>(0);
        (<Rational as Ring>::zero(), n, 0, 0)
    });
    let nf = Vector3::new(
        Real::to_f64(&n[0]),
        Real::to_f64(&n[1]),
        Real::to_f64(&n[2]),
    );
    // Scaled by its largest component first, so that neither squares of 1e200 overflow nor
    // squares of 1e-200 underflow in the norm.
    let largest = nf.amax();
    let normal = if largest > 0.0 && largest.is_finite() {
        (nf / largest).try_normalize(0.0)
    } else {
        None
    }
    .unwrap_or_else(Vector3::x);
    Depth {
        depth2,
        normal,
        support_a: a.points[ia].approx(),
        support_b: b.points[ib].approx(),
    }
}

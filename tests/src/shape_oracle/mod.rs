//! An exact oracle for the solid primitives of `cga_collide::shape`, written apart from the
//! product's engines: it reads the shapes' public data only and decides with exact rationals.
//!
//! * Shapes that are a convex polytope grown by a ball (balls, capsules, segments, triangles,
//!   cuboids, hulls, and cylinders or cones of radius 0) are `hull(points) ⊕ ball(radius)`;
//!   between two of them the distance is `max(0, √D − rA − rB)` with `D` the exact squared
//!   distance of the hulls ([`hull::distance2`]).
//! * Half-spaces against anything the oracle knows: the minimum of a linear function over the
//!   other shape, exactly, with square roots compared by sign rules ([`exact::sign_root`]).
//! * A ball (or any one-point core) against a cylinder: the point's axial and radial
//!   coordinates, exactly.
//! * Other pairs with a cylinder or a cone have no general oracle here: the constructed pairs
//!   ([`construct`]) give them truth by construction.

pub mod construct;
pub mod depth;
pub mod exact;
pub mod generate;
pub mod hull;
pub mod json;

use std::cmp::Ordering;

use cga_collide::query::CertifiedDistance;
use cga_collide::shape::Shape;
use num_traits::{Signed, Zero};

use exact::{dot, p3, q, sign, sign_root, sign_two_roots, sub, v3, P3, Q};

/// A shape in the oracle's terms.
#[derive(Debug, Clone)]
pub enum Body {
    /// `hull(points) ⊕ ball(radius)`.
    Grown { points: Vec<P3>, radius: Q },
    /// `{x : (x − point)·normal <= 0}`.
    Half { point: P3, normal: P3 },
    /// The solid cylinder of axis `[a, b]`, radius > 0.
    Cylinder { a: P3, b: P3, radius: Q },
    /// The solid cone, radius > 0.
    Cone { apex: P3, base: P3, radius: Q },
}

fn cuboid_corners(c: &cga_collide::shape::Cuboid) -> Vec<P3> {
    let centre = p3(c.centre());
    let [u, v, w] = c.half_axes().map(|h| v3(&h));
    let mut out = Vec::with_capacity(8);
    for m in 0..8 {
        let mut p = centre.clone();
        for (bit, axis) in [&u, &v, &w].into_iter().enumerate() {
            for d in 0..3 {
                if m >> bit & 1 == 1 {
                    p[d] += &axis[d];
                } else {
                    p[d] -= &axis[d];
                }
            }
        }
        out.push(p);
    }
    out
}

/// The oracle's reading of a shape.
pub fn body(shape: &Shape) -> Body {
    let grown = |points: Vec<P3>, radius: f64| Body::Grown {
        points,
        radius: q(radius),
    };
    match shape {
        Shape::Ball(b) => grown(vec![p3(b.centre())], b.radius()),
        Shape::Capsule(c) => grown(vec![p3(c.a()), p3(c.b())], c.radius()),
        Shape::Segment(s) => grown(vec![p3(s.a()), p3(s.b())], 0.0),
        Shape::Triangle(t) => grown(t.vertices().iter().map(p3).collect(), 0.0),
        Shape::Cuboid(c) => grown(cuboid_corners(c), 0.0),
        Shape::ConvexHull(h) => grown(h.points().iter().map(p3).collect(), 0.0),
        Shape::HalfSpace(h) => Body::Half {
            point: p3(h.point()),
            normal: v3(h.normal()),
        },
        Shape::Cylinder(c) if c.radius() == 0.0 => grown(vec![p3(c.a()), p3(c.b())], 0.0),
        Shape::Cone(c) if c.radius() == 0.0 => grown(vec![p3(c.apex()), p3(c.base())], 0.0),
        Shape::Cylinder(c) => Body::Cylinder {
            a: p3(c.a()),
            b: p3(c.b()),
            radius: q(c.radius()),
        },
        Shape::Cone(c) => Body::Cone {
            apex: p3(c.apex()),
            base: p3(c.base()),
            radius: q(c.radius()),
        },
    }
}

/// The oracle's answer for one pair: `distance = max(0, core − radius)` where `core` is a
/// distance it compares exactly with any rational (`core_cmp(s)` is the sign of `core − s`).
pub struct Decided {
    radius: Q,
    core_cmp: Box<dyn Fn(&Q) -> Ordering>,
}

impl Decided {
    /// The exact sign of `distance − c` for `c >= 0`.
    pub fn compare(&self, c: &Q) -> Ordering {
        if c.is_zero() {
            if (self.core_cmp)(&self.radius) == Ordering::Greater {
                Ordering::Greater
            } else {
                Ordering::Equal
            }
        } else {
            (self.core_cmp)(&(&self.radius + c))
        }
    }

    /// Do the shapes meet?
    pub fn intersects(&self) -> bool {
        self.compare(&Q::zero()) != Ordering::Greater
    }

    /// Is the distance at most `c` (`c >= 0`)?
    pub fn within(&self, c: f64) -> bool {
        self.compare(&q(c)) != Ordering::Greater
    }

    /// The smallest `f64` clearance `c >= 0` with `distance <= c` (`None` beyond
    /// [`cga_collide::shape::MAX_MAGNITUDE`]): the product's `within_distance` must say yes at
    /// it and no just below it.
    pub fn threshold(&self) -> Option<f64> {
        let limit = cga_collide::shape::MAX_MAGNITUDE;
        if !self.within(limit) {
            return None;
        }
        // Non-negative floats are ordered as their bit patterns.
        let (mut lo, mut hi) = (0u64, limit.to_bits());
        if self.within(0.0) {
            return Some(0.0);
        }
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if self.within(f64::from_bits(mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(f64::from_bits(hi))
    }

    /// Does `[distance − error_bound, distance + error_bound]` (exact reals) hold the true
    /// distance?
    pub fn bound_holds(&self, d: &CertifiedDistance) -> bool {
        if !d.distance.is_finite() || !d.error_bound.is_finite() || d.error_bound < 0.0 {
            return false;
        }
        let hi = q(d.distance) + q(d.error_bound);
        let lo = q(d.distance) - q(d.error_bound);
        !hi.is_negative()
            && self.compare(&hi) != Ordering::Greater
            && (!lo.is_positive() || self.compare(&lo) != Ordering::Less)
    }
}

/// The oracle for a pair, `None` where it has no method.
pub fn oracle(a: &Shape, b: &Shape) -> Option<Decided> {
    decide(&body(a), &body(b))
}

fn min_linear(points: &[P3], point: &P3, normal: &P3) -> Q {
    points
        .iter()
        .map(|x| dot(&sub(x, point), normal))
        .min()
        .expect("non-empty")
}

/// The sign of `max(0, m/√b) − s` for `s >= 0` (a half-space's gap `m/|n|`).
fn gap_cmp(m: &Q, b: &Q, s: &Q) -> Ordering {
    if !m.is_positive() {
        return Q::zero().cmp(s);
    }
    sign(&(m * m - s * s * b))
}

/// The minimum of `(x − p)·n` over a cylinder or cone as candidates `k − ρ·√A`.
fn round_extremes(body: &Body, point: &P3, normal: &P3) -> (Vec<(Q, Q)>, Q) {
    let (ends, u, r): (Vec<(P3, bool)>, P3, Q) = match body {
        Body::Cylinder { a, b, radius } => (
            vec![(a.clone(), true), (b.clone(), true)],
            sub(b, a),
            radius.clone(),
        ),
        Body::Cone { apex, base, radius } => (
            vec![(apex.clone(), false), (base.clone(), true)],
            sub(base, apex),
            radius.clone(),
        ),
        _ => unreachable!(),
    };
    let nu = dot(normal, &u);
    let a_perp = dot(normal, normal) - &nu * &nu / dot(&u, &u);
    let candidates = ends
        .into_iter()
        .map(|(c, disc)| {
            let k = dot(&sub(&c, point), normal);
            (k, if disc { r.clone() } else { Q::zero() })
        })
        .collect();
    (candidates, a_perp)
}

fn half_vs(half: (&P3, &P3), other: &Body) -> Option<Decided> {
    let (point, normal) = half;
    let b = dot(normal, normal);
    match other {
        Body::Grown { points, radius } => {
            let m = min_linear(points, point, normal);
            Some(Decided {
                radius: radius.clone(),
                core_cmp: Box::new(move |s| gap_cmp(&m, &b, s)),
            })
        }
        Body::Half {
            point: p2,
            normal: n2,
        } => {
            let cross = exact::cross(normal, n2);
            let d = dot(normal, n2);
            // Disjoint only when the normals are opposite and the boundary planes apart:
            // on n2 = −k·n (k > 0), the second is n·x >= −(n2·p2)/k.
            let m = if exact::is_zero(&cross) && d.is_negative() {
                let k = -&d / &b;
                let c1 = dot(normal, point);
                let c2 = dot(n2, p2);
                -c2 / k - c1
            } else {
                Q::zero()
            };
            Some(Decided {
                radius: Q::zero(),
                core_cmp: Box::new(move |s| gap_cmp(&m, &b, s)),
            })
        }
        round @ (Body::Cylinder { .. } | Body::Cone { .. }) => {
            let (candidates, a_perp) = round_extremes(round, point, normal);
            Some(Decided {
                radius: Q::zero(),
                core_cmp: Box::new(move |s| {
                    // min over candidates of sign(k − ρ√A − s√B); with s = 0 the gap is 0
                    // exactly when some candidate is <= 0.
                    candidates
                        .iter()
                        .map(|(k, rho)| {
                            let g = sign_root(k, &-rho, &a_perp);
                            if s.is_zero() {
                                if g == Ordering::Greater {
                                    Ordering::Greater
                                } else {
                                    Ordering::Equal
                                }
                            } else {
                                sign_two_roots(k, &-rho, &a_perp, &-s, &b)
                            }
                        })
                        .min()
                        .expect("two candidates")
                }),
            })
        }
    }
}

/// The sign of `dist(x, cylinder) − s`.
fn point_cylinder_cmp(x: &P3, a: &P3, b: &P3, r: &Q, s: &Q) -> Ordering {
    let u = sub(b, a);
    let l2 = dot(&u, &u);
    let d = sub(x, a);
    let tau = dot(&d, &u);
    let rho2 = dot(&d, &d) - &tau * &tau / &l2;
    let inside_radius = rho2 <= r * r;
    if !tau.is_negative() && tau <= l2 {
        if inside_radius {
            return Q::zero().cmp(s);
        }
        let rs = r + s;
        return sign(&(&rho2 - &rs * &rs));
    }
    let over = if tau.is_negative() {
        tau.clone()
    } else {
        &tau - &l2
    };
    let h2 = &over * &over / &l2;
    if inside_radius {
        return sign(&(h2 - s * s));
    }
    let two = exact::int(2);
    sign_root(&(h2 + &rho2 + r * r - s * s), &(-(two * r)), &rho2)
}

fn decide(a: &Body, b: &Body) -> Option<Decided> {
    match (a, b) {
        (
            Body::Grown {
                points: pa,
                radius: ra,
            },
            Body::Grown {
                points: pb,
                radius: rb,
            },
        ) => {
            let d2 = hull::distance2(pa, pb);
            Some(Decided {
                radius: ra + rb,
                core_cmp: Box::new(move |s| d2.cmp(&(s * s))),
            })
        }
        (Body::Half { point, normal }, other) | (other, Body::Half { point, normal }) => {
            half_vs((point, normal), other)
        }
        (Body::Grown { points, radius }, Body::Cylinder { a, b, radius: r })
        | (Body::Cylinder { a, b, radius: r }, Body::Grown { points, radius }) => {
            let core = hull::distinct(points);
            if core.len() != 1 {
                return None;
            }
            let (x, a, b, r) = (core[0].clone(), a.clone(), b.clone(), r.clone());
            Some(Decided {
                radius: radius.clone(),
                core_cmp: Box::new(move |s| point_cylinder_cmp(&x, &a, &b, &r, s)),
            })
        }
        _ => None,
    }
}

/// The exact sign of `distance(a, b) − c` for `c >= 0`; `None` where the oracle has no method
/// for the pair (pairs of cylinders and cones with anything but half-spaces, and cones or
/// cylinders against more than a point).
pub fn compare_distance(a: &Shape, b: &Shape, c: &Q) -> Option<Ordering> {
    oracle(a, b).map(|d| d.compare(c))
}

/// Exact: do two oracle bodies meet? `None` where the oracle has no method.
pub fn intersects_bodies(a: &Body, b: &Body) -> Option<bool> {
    decide(a, b).map(|d| d.intersects())
}

/// Exact: do the closed shapes meet?
pub fn intersects(a: &Shape, b: &Shape) -> Option<bool> {
    oracle(a, b).map(|d| d.intersects())
}

/// The exact squared distance for two grown shapes (`max(0, √D − R)` squared is not rational,
/// so this returns `(D, R)`); `None` for other pairs.
pub fn grown_core(a: &Shape, b: &Shape) -> Option<(Q, Q)> {
    match (body(a), body(b)) {
        (
            Body::Grown {
                points: pa,
                radius: ra,
            },
            Body::Grown {
                points: pb,
                radius: rb,
            },
        ) => Some((hull::distance2(&pa, &pb), ra + rb)),
        _ => None,
    }
}

//! The polytopal view of a shape: a *core*, the convex hull of finitely many exact points,
//! grown by a ball of radius `r` (a ball is a point grown, a capsule a segment grown, a cuboid,
//! hull, triangle or segment is its own core with `r = 0`).

use nalgebra::Point3;

use crate::shape::{ConvexHull, Shape};
use ga_core::scalar::Ring;

/// A point or vector in `f64`.
pub(super) type P3 = [f64; 3];

/// One exact point: the exact sum of up to four `f64` vectors. A cuboid's corner
/// `c ± U ± V ± W` is such a sum (negating a vector is exact, so the signs live in the terms);
/// every other core point is a single term.
#[derive(Debug, Clone, Copy)]
pub(super) struct ExactPoint {
    terms: [P3; 4],
    len: usize,
}

impl ExactPoint {
    fn single(p: P3) -> Self {
        ExactPoint {
            terms: [p, [0.0; 3], [0.0; 3], [0.0; 3]],
            len: 1,
        }
    }

    /// The point's coordinates in the ring `R`, each the sum of its lifted terms (exact for
    /// exact rings, error-bounded for [`crate::exact::ErrF64`]).
    #[inline]
    pub(super) fn lift<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; 3] {
        core::array::from_fn(|k| {
            let mut s = lift(self.terms[0][k]);
            for t in &self.terms[1..self.len] {
                s = s + lift(t[k]);
            }
            s
        })
    }
}

// The corners stay inline: a `Core` lives on the stack for one query, and boxing them would
// allocate on every call.
#[allow(clippy::large_enum_variant)]
enum Points<'a> {
    /// Up to three points given inline (ball centre, capsule axis, triangle, segment).
    Few { points: [P3; 3], len: usize },
    /// A hull's extreme points.
    Hull(&'a ConvexHull),
    /// A parallelepiped's eight corners: corner `i` takes `+axis k` when bit `k` of `i` is set
    /// (`corners`: each rounded once to `f64`, for the search).
    Box {
        centre: P3,
        axes: [P3; 3],
        corners: [P3; 8],
    },
}

/// A shape as core ⊕ ball(radius).
pub(super) struct Core<'a> {
    points: Points<'a>,
    /// The radius of the ball the core is grown by.
    pub(super) radius: f64,
    /// The largest magnitude of a coordinate, term or the radius (computed once).
    magnitude: f64,
}

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

impl<'a> Core<'a> {
    /// The core of `shape`; `None` for the kinds that are not a grown polytope (half-spaces,
    /// cylinders, cones).
    pub(super) fn of(shape: &'a Shape) -> Option<Core<'a>> {
        let few = |pts: &[&Point3<f64>], radius: f64| {
            let mut points = [[0.0; 3]; 3];
            for (slot, p) in points.iter_mut().zip(pts) {
                *slot = p3(p);
            }
            Core {
                points: Points::Few {
                    points,
                    len: pts.len(),
                },
                radius,
                magnitude: 0.0,
            }
        };
        let mut core = match shape {
            Shape::Ball(b) => few(&[b.centre()], b.radius()),
            Shape::Capsule(c) => few(&[c.a(), c.b()], c.radius()),
            Shape::Segment(s) => few(&[s.a(), s.b()], 0.0),
            Shape::Triangle(t) => {
                let [a, b, c] = t.vertices();
                few(&[a, b, c], 0.0)
            }
            Shape::Cuboid(c) => {
                let centre = p3(c.centre());
                let axes = c.half_axes().map(|h| [h.x, h.y, h.z]);
                let corners = core::array::from_fn(|i| {
                    core::array::from_fn(|k| {
                        let term = |j: usize| {
                            if i >> j & 1 == 1 {
                                axes[j][k]
                            } else {
                                -axes[j][k]
                            }
                        };
                        centre[k] + term(0) + term(1) + term(2)
                    })
                });
                Core {
                    points: Points::Box {
                        centre,
                        axes,
                        corners,
                    },
                    radius: 0.0,
                    magnitude: 0.0,
                }
            }
            Shape::ConvexHull(h) => Core {
                points: Points::Hull(h),
                radius: 0.0,
                magnitude: 0.0,
            },
            Shape::HalfSpace(_) | Shape::Cylinder(_) | Shape::Cone(_) => return None,
        };
        core.magnitude = core.compute_magnitude();
        Some(core)
    }

    /// The centre and half axes when the core is a parallelepiped.
    pub(super) fn parallelepiped(&self) -> Option<(&P3, &[P3; 3])> {
        match &self.points {
            Points::Box { centre, axes, .. } => Some((centre, axes)),
            _ => None,
        }
    }

    /// How many points span the core.
    pub(super) fn len(&self) -> usize {
        match &self.points {
            Points::Few { len, .. } => *len,
            Points::Hull(h) => h.extreme_points().len(),
            Points::Box { .. } => 8,
        }
    }

    /// Point `i` exactly.
    pub(super) fn point(&self, i: usize) -> ExactPoint {
        match &self.points {
            Points::Few { points, .. } => ExactPoint::single(points[i]),
            Points::Hull(h) => ExactPoint::single(p3(&h.extreme_points()[i])),
            Points::Box { centre, axes, .. } => {
                let mut terms = [*centre; 4];
                for (k, axis) in axes.iter().enumerate() {
                    terms[k + 1] = if i >> k & 1 == 1 {
                        *axis
                    } else {
                        axis.map(|x| -x)
                    };
                }
                ExactPoint { terms, len: 4 }
            }
        }
    }

    /// Point `i` rounded to `f64` (for the floating-point search only).
    pub(super) fn approx(&self, i: usize) -> P3 {
        match &self.points {
            Points::Few { points, .. } => points[i],
            Points::Hull(h) => p3(&h.extreme_points()[i]),
            Points::Box { corners, .. } => corners[i],
        }
    }

    /// The index of a point maximising `d · x` (in `f64`: a search step, not a decision).
    pub(super) fn support(&self, d: &P3) -> usize {
        let dot = |p: &P3| d[0] * p[0] + d[1] * p[1] + d[2] * p[2];
        match &self.points {
            Points::Few { points, len } => argmax(points[..*len].iter().map(dot)),
            Points::Hull(h) => argmax(h.extreme_points().iter().map(|p| dot(&p3(p)))),
            Points::Box { axes, .. } => axes
                .iter()
                .enumerate()
                .map(|(k, a)| usize::from(dot(a) > 0.0) << k)
                .sum(),
        }
    }

    /// The largest magnitude of a coordinate, a term of one or the radius (a scale for error
    /// bounds).
    pub(super) fn magnitude(&self) -> f64 {
        self.magnitude
    }

    fn compute_magnitude(&self) -> f64 {
        let largest = |m: f64, p: &P3| p.iter().fold(m, |m, x| m.max(x.abs()));
        match &self.points {
            Points::Few { points, len } => points[..*len].iter().fold(self.radius, largest),
            Points::Hull(h) => h
                .extreme_points()
                .iter()
                .fold(self.radius, |m, p| largest(m, &p3(p))),
            Points::Box { centre, axes, .. } => {
                axes.iter().fold(largest(self.radius, centre), largest)
            }
        }
    }
}

fn argmax(values: impl Iterator<Item = f64>) -> usize {
    let mut best = (0, f64::NEG_INFINITY);
    for (i, v) in values.enumerate() {
        if v > best.1 {
            best = (i, v);
        }
    }
    best.0
}

//! Where a solid primitive may reach, for pruning box trees and broad phases: a box holding
//! the exact shape (outward-rounded), or for a half-space the half-space itself, and a lower
//! bound on the distance from a box to it. Every bound is conservative: a box is set aside
//! only when no point of the exact shape can be within the distance asked.

use crate::bounding::{box_distance2, Aabb};
use crate::shape::{HalfSpace, Shape};

/// What a shape may reach: its certified box, or (a half-space has none) the half-space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Reach {
    /// A box holding the exact shape.
    Box(Aabb),
    /// The closed half-space itself.
    HalfSpace(HalfSpace),
}

/// The largest `f64` not above the exact result of one rounded-to-nearest operation.
fn down(x: f64) -> f64 {
    x.next_down()
}

/// The smallest `f64` not below the exact result of one rounded-to-nearest operation.
fn up(x: f64) -> f64 {
    x.next_up()
}

/// The box of the points, grown by `r` on every side, outward-rounded.
fn points_grown(points: &[nalgebra::Point3<f64>], r: f64) -> Aabb {
    let b = Aabb::of_points(points);
    if r == 0.0 {
        return b;
    }
    Aabb {
        min: b.min.map(|x| down(x - r)),
        max: b.max.map(|x| up(x + r)),
    }
}

/// A box holding the exact shape: exact for points, segments, triangles and hulls; rounded
/// outwards for the others. A cylinder or cone gets the box of the capsule of its axis (which
/// holds it). A half-space gets the whole space, except that a normal along a coordinate axis
/// bounds it exactly on that side (the ground `z <= 0` has the box `z <= 0`).
pub(crate) fn shape_box(shape: &Shape) -> Aabb {
    match shape {
        Shape::Ball(b) => points_grown(&[*b.centre()], b.radius()),
        Shape::Cuboid(c) => {
            let [u, v, w] = c.half_axes();
            let centre = c.centre();
            let mut b = Aabb::EMPTY;
            for k in 0..3 {
                // Each rounding of the sum is followed by a step up: an upper bound.
                let e = up(up(u[k].abs() + v[k].abs()) + w[k].abs());
                b.min[k] = down(centre[k] - e);
                b.max[k] = up(centre[k] + e);
            }
            b
        }
        Shape::Capsule(c) => points_grown(&[*c.a(), *c.b()], c.radius()),
        Shape::Cylinder(c) => points_grown(&[*c.a(), *c.b()], c.radius()),
        Shape::Cone(c) => points_grown(&[*c.apex(), *c.base()], c.radius()),
        Shape::HalfSpace(h) => half_space_box(h),
        Shape::ConvexHull(h) => Aabb::of_points(h.points()),
        Shape::Triangle(t) => Aabb::of_points(t.vertices()),
        Shape::Segment(s) => Aabb::of_points(&[*s.a(), *s.b()]),
    }
}

fn half_space_box(h: &HalfSpace) -> Aabb {
    let mut b = Aabb {
        min: [f64::NEG_INFINITY; 3],
        max: [f64::INFINITY; 3],
    };
    let n = h.normal();
    let axes: Vec<usize> = (0..3).filter(|&k| n[k] != 0.0).collect();
    if let [k] = axes[..] {
        // {x : (x_k - p_k) n_k <= 0}: exactly x_k <= p_k (n_k > 0) or x_k >= p_k.
        if n[k] > 0.0 {
            b.max[k] = h.point()[k];
        } else {
            b.min[k] = h.point()[k];
        }
    }
    b
}

impl Reach {
    /// What `shape` may reach.
    pub(crate) fn of(shape: &Shape) -> Reach {
        match shape {
            Shape::HalfSpace(h) => Reach::HalfSpace(*h),
            other => Reach::Box(shape_box(other)),
        }
    }

    /// A lower bound on the distance from the closed box `b` to the shape (`0` when they may
    /// meet), never above the true distance. `b` must be finite with coordinates of
    /// magnitude at most `2^500` (as the shapes'), so no square overflows.
    pub(crate) fn gap(&self, b: &Aabb) -> f64 {
        match self {
            Reach::Box(s) => {
                let d2 = box_distance2(s, b);
                // The gaps, squares and sum round to nearest (a few ulps relative); an
                // underflow only makes the bound smaller.
                (d2 * (1.0 - 1e-12)).sqrt() * (1.0 - 1e-12)
            }
            Reach::HalfSpace(h) => half_space_gap(h, b),
        }
    }

    /// Conservative: `false` only if the box is certainly farther than `c` from the shape.
    pub(crate) fn within(&self, b: &Aabb, c: f64) -> bool {
        self.gap(b) <= c
    }
}

/// A lower bound on the distance from the box to the half-space `{x : (x − p)·n ≤ 0}`: the
/// value of `(x − p)·n/|n|` at the box's corner that minimises it, rounded down.
fn half_space_gap(h: &HalfSpace, b: &Aabb) -> f64 {
    let (p, n) = (h.point(), h.normal());
    // Scaled so that the largest component is 1 (no underflow of |n|); each quotient is
    // rounded, which the relative margin below pays for.
    let m = n.iter().fold(0.0f64, |acc, x| acc.max(x.abs()));
    let mut value = 0.0;
    let mut magnitude = 0.0;
    let mut norm2 = 0.0;
    for k in 0..3 {
        if n[k] == 0.0 {
            continue;
        }
        let nk = n[k] / m;
        let corner = if nk > 0.0 { b.min[k] } else { b.max[k] };
        let term = (corner - p[k]) * nk;
        value += term;
        magnitude += term.abs();
        norm2 += nk * nk;
    }
    // Every rounding above is within a few ulps of `magnitude`; an underflowed product within
    // 2^-1074 each.
    let certain = value - (magnitude * 1e-12 + 1e-300);
    if !(certain > 0.0) || !certain.is_finite() {
        return 0.0;
    }
    // |n/m| lies in [1, sqrt(3)]: divided by an upper bound of it and rounded down.
    certain / (norm2.sqrt() * (1.0 + 1e-12)) * (1.0 - 1e-12)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{Capsule, Cone, Cuboid, Cylinder};
    use crate::Ball;
    use nalgebra::{Point3, Vector3};

    fn contains(b: &Aabb, p: &Point3<f64>) -> bool {
        (0..3).all(|k| b.min[k] <= p[k] && p[k] <= b.max[k])
    }

    #[test]
    fn boxes_hold_the_extreme_points() {
        let c = Point3::new(0.1, -0.3, 1e-300);
        let ball = shape_box(&Ball::new(c, 0.7).unwrap().into());
        assert!(contains(&ball, &Point3::new(0.1 + 0.7, -0.3, 0.0)));
        assert!(ball.min[0] <= 0.1 - 0.7 && ball.max[2] >= 0.7);
        let [u, v, w] = [
            Vector3::new(0.1, 0.2, 0.3),
            Vector3::new(-0.3, 0.1, 0.0),
            Vector3::new(0.0, 0.0, 1e-3),
        ];
        let cuboid = shape_box(&Cuboid::new(c, [u, v, w]).unwrap().into());
        for s in [
            [1.0, 1.0, 1.0],
            [-1.0, 1.0, -1.0],
            [1.0, -1.0, 1.0],
            [-1.0, -1.0, -1.0],
        ] {
            assert!(contains(&cuboid, &(c + u * s[0] + v * s[1] + w * s[2])));
        }
        let (a, b) = (Point3::new(1.0, 2.0, 3.0), Point3::new(-1.0, 0.0, 3.0));
        for shape in [
            Shape::from(Capsule::new(a, b, 0.5).unwrap()),
            Cylinder::new(a, b, 0.5).unwrap().into(),
            Cone::new(a, b, 0.5).unwrap().into(),
        ] {
            let bx = shape_box(&shape);
            assert!(contains(&bx, &Point3::new(1.5, 2.5, 3.5)), "{shape:?}");
            assert!(contains(&bx, &Point3::new(-1.5, -0.5, 2.5)), "{shape:?}");
        }
    }

    #[test]
    fn a_ground_plane_is_bounded_on_one_side_only() {
        let ground = HalfSpace::new(Point3::new(0.0, 0.0, 0.25), Vector3::z()).unwrap();
        let b = shape_box(&ground.into());
        assert_eq!(b.max[2], 0.25);
        assert_eq!(b.min[2], f64::NEG_INFINITY);
        assert_eq!(b.max[0], f64::INFINITY);
        let tilted = HalfSpace::new(Point3::origin(), Vector3::new(1.0, 1.0, 0.0)).unwrap();
        assert_eq!(shape_box(&tilted.into()).max, [f64::INFINITY; 3]);
    }

    #[test]
    fn the_half_space_gap_is_a_lower_bound_and_zero_on_contact() {
        let h = HalfSpace::new(Point3::origin(), Vector3::new(0.0, 3.0, 4.0)).unwrap();
        let reach = Reach::HalfSpace(h);
        let unit = |y: f64, z: f64| Aabb {
            min: [0.0, y, z],
            max: [1.0, y + 1.0, z + 1.0],
        };
        // The corner (0, 3, 4) is at distance (9 + 16) / 5 = 5.
        let g = reach.gap(&unit(3.0, 4.0));
        assert!(g <= 5.0 && g > 5.0 * (1.0 - 1e-9), "{g}");
        // Touching at the corner (0, 0, 0): distance 0.
        assert_eq!(reach.gap(&unit(0.0, 0.0)), 0.0);
        assert_eq!(reach.gap(&unit(-1.0, -1.0)), 0.0);
        // Tiny normals and coordinates: still a bound, never a false gap.
        let tiny = HalfSpace::new(Point3::origin(), Vector3::new(0.0, 1e-310, 0.0)).unwrap();
        let b = Aabb {
            min: [0.0, 5e-324, 0.0],
            max: [1.0, 1e-323, 1.0],
        };
        assert!(Reach::HalfSpace(tiny).gap(&b) <= 5e-324);
    }
}

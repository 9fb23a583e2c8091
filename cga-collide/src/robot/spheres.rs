//! Bounding spheres, the cheapest conservative test: each part's sphere in its link's frame
//! and each link's sphere around its parts' are computed once when the robot is loaded; at a
//! configuration, only the centres move (one transform per link), and a pair whose spheres
//! are proved farther apart than the reach is set aside before any of its parts is placed.

use nalgebra::{Isometry3, Point3};

use super::geometry::Geometry;
use crate::bounding::shape_box::shape_box;
use crate::bounding::Aabb;

/// A ball holding every point of a part or a link (in some frame); an unbounded part has an
/// infinite radius and is never set aside.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sphere {
    pub centre: Point3<f64>,
    pub radius: f64,
}

/// Grows a radius computed in `f64` past its rounding (the tests below add their own margin
/// for the placement's rounding).
fn outwards(r: f64) -> f64 {
    r * (1.0 + 1e-12) + 1e-300
}

impl Sphere {
    const UNBOUNDED: Sphere = Sphere {
        centre: Point3::new(0.0, 0.0, 0.0),
        radius: f64::INFINITY,
    };

    /// The sphere of a part: centred at the middle of its local box, through its farthest
    /// vertex (meshes) or its box's corners (primitives), carried into the link's frame by
    /// `local` (the part's pose in its link).
    pub fn of_part(geometry: &Geometry, local: &Isometry3<f64>) -> Sphere {
        let (centre, radius) = match geometry {
            Geometry::Mesh(c) => {
                let centre = middle(&c.bvh().bounds());
                let far = c
                    .mesh()
                    .vertices()
                    .iter()
                    .fold(0.0f64, |r, v| r.max((v - centre).norm()));
                (centre, far)
            }
            Geometry::Shape(s) => {
                let b = shape_box(s);
                let half = (Point3::from(b.max) - Point3::from(b.min)) / 2.0;
                (middle(&b), half.norm())
            }
        };
        if !(radius.is_finite() && centre.iter().all(|x| x.is_finite())) {
            return Sphere::UNBOUNDED;
        }
        Sphere {
            centre: local * centre,
            radius: outwards(radius),
        }
    }

    /// A world box's sphere (an environment object's).
    pub fn of_box(b: &Aabb) -> Sphere {
        let half = (Point3::from(b.max) - Point3::from(b.min)) / 2.0;
        let (centre, radius) = (middle(b), half.norm());
        if !(radius.is_finite() && centre.iter().all(|x| x.is_finite())) {
            return Sphere::UNBOUNDED;
        }
        Sphere {
            centre,
            radius: outwards(radius),
        }
    }

    /// A sphere holding all of `spheres` (`None` when there are none).
    pub fn around(spheres: &[Sphere]) -> Option<Sphere> {
        let mut b = Aabb::EMPTY;
        for s in spheres {
            b.grow(&s.centre);
        }
        let centre = middle(&b);
        let radius = spheres
            .iter()
            .map(|s| (s.centre - centre).norm() + s.radius)
            .reduce(f64::max)?;
        if !(radius.is_finite() && centre.iter().all(|x| x.is_finite())) {
            return Some(Sphere::UNBOUNDED);
        }
        Some(Sphere {
            centre,
            radius: outwards(radius),
        })
    }

    /// The sphere carried by a pose (the link's world pose).
    pub fn placed(&self, pose: &Isometry3<f64>) -> Sphere {
        Sphere {
            centre: pose * self.centre,
            radius: self.radius,
        }
    }

    /// A lower bound on the distance between anything in the two spheres, with a margin far
    /// above every rounding of the centres, of the radii and of the placement rule's placed
    /// points (relative errors of a few units in the last place of the coordinates); 0 when
    /// they may meet or are unbounded.
    pub fn gap_lower(&self, o: &Sphere) -> f64 {
        let d = (self.centre - o.centre).norm();
        let reach = self.radius + o.radius;
        let scale =
            1.0 + self.centre.coords.amax() + o.centre.coords.amax() + self.radius + o.radius;
        let gap = d - reach - 1e-9 * scale;
        if gap.is_finite() && gap > 0.0 {
            gap
        } else {
            0.0
        }
    }

    /// Whether the two are proved farther apart than `c` (conservative).
    pub fn apart(&self, o: &Sphere, c: f64) -> bool {
        self.gap_lower(o) > c * (1.0 + 1e-9)
    }
}

fn middle(b: &Aabb) -> Point3<f64> {
    Point3::from((Point3::from(b.min).coords + Point3::from(b.max).coords) / 2.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion, Vector3};

    fn ball(x: f64, r: f64) -> Sphere {
        Sphere {
            centre: Point3::new(x, 0.0, 0.0),
            radius: r,
        }
    }

    #[test]
    fn touching_spheres_are_never_apart_and_far_ones_are() {
        assert!(!ball(0.0, 1.0).apart(&ball(2.0, 1.0), 0.0));
        assert!(!ball(0.0, 1.0).apart(&ball(2.5, 1.0), 0.5));
        assert!(ball(0.0, 1.0).apart(&ball(2.001, 1.0), 0.0));
        assert!(ball(0.0, 1.0).apart(&ball(2.6, 1.0), 0.5));
        let gap = ball(0.0, 1.0).gap_lower(&ball(5.0, 1.0));
        assert!(gap <= 3.0 && gap > 3.0 - 1e-8);
    }

    #[test]
    fn unbounded_spheres_are_never_apart() {
        let inf = Sphere::UNBOUNDED;
        assert!(!inf.apart(&ball(1e6, 1.0), 0.0));
        assert_eq!(inf.gap_lower(&ball(1e6, 1.0)), 0.0);
        assert!(Sphere::of_box(&Aabb::EMPTY).radius.is_infinite());
    }

    #[test]
    fn the_sphere_around_others_holds_them() {
        let spheres = [ball(0.0, 1.0), ball(3.0, 0.5), ball(-1.0, 2.0)];
        let all = Sphere::around(&spheres).unwrap();
        for s in &spheres {
            assert!((s.centre - all.centre).norm() + s.radius <= all.radius);
        }
        assert!(Sphere::around(&[]).is_none());
    }

    #[test]
    fn a_placed_sphere_moves_its_centre_only() {
        let pose = Isometry3::from_parts(
            Translation3::new(1.0, 2.0, 3.0),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5),
        );
        let s = ball(1.0, 0.25).placed(&pose);
        assert!((s.centre - pose * Point3::new(1.0, 0.0, 0.0)).norm() < 1e-15);
        assert_eq!(s.radius, 0.25);
    }
}

//! The generic queries over [`Shape`]: one entry point for every pair of solid primitives.
//!
//! [`intersects`], [`within_distance`] and [`distance`] take any two [`Shape`]s; the `_at`
//! forms place them first by the crate's placement rule ([`Shape::placed`]). Every answer is
//! exact for the shapes the `f64` values denote (closed sets: touching counts). The pairs are
//! decided by two engines:
//! * [`polytopal`]: shapes that are a convex polytope grown by a ball (points, segments,
//!   triangles, cuboids, hulls, balls, capsules) and half-spaces;
//! * [`round`]: every pair with a cylinder or a cone.
//!
//! Many poses in one call: [`intersects_batch`], [`within_distance_batch`] and
//! [`distance_batch`] answer the `_at` query for every [`PosePair`], spread over the cores;
//! each answer equals the `_at` answer, and the first refused pose is reported as
//! [`Error::InBatch`]. The pair functions of the crate's naming rule
//! (`intersects_cuboid_capsule` and the rest) are in [`named`].

use nalgebra::Isometry3;

use crate::error::Error;
use crate::parallel::over_batch;
use crate::query::CertifiedDistance;
use crate::shape::{PosePair, Shape};

pub(crate) mod depth;
pub(crate) mod manifold;
pub(crate) mod named;
pub(crate) mod polytopal;
pub(crate) mod round;
mod rounded_f64;

fn is_round(s: &Shape) -> bool {
    matches!(s, Shape::Cylinder(_) | Shape::Cone(_))
}

pub(crate) fn check_clearance(c: f64) -> Result<(), Error> {
    if (0.0..=crate::shape::MAX_MAGNITUDE).contains(&c) {
        Ok(())
    } else {
        Err(Error::InvalidClearance { value: c })
    }
}

/// Exact: do the two closed shapes share a point?
///
/// ```
/// use cga_collide::{nalgebra::{Point3, Vector3}, query, shape::{Cuboid, HalfSpace}, Ball};
/// let ground = HalfSpace::new(Point3::origin(), Vector3::z())?;
/// let resting = Ball::new(Point3::new(0.0, 0.0, 1.0), 1.0)?; // touches the plane at the origin
/// assert!(query::intersects(&ground.into(), &resting.into())?);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn intersects(a: &Shape, b: &Shape) -> Result<bool, Error> {
    a.check_range()?;
    b.check_range()?;
    if is_round(a) || is_round(b) {
        round::intersects(a, b)
    } else {
        Ok(polytopal::intersects(a, b))
    }
}

/// Exact: is the distance between the two closed shapes at most `c`? `c` must be finite and
/// `>= 0` ([`Error::InvalidClearance`] otherwise).
pub fn within_distance(a: &Shape, b: &Shape, c: f64) -> Result<bool, Error> {
    a.check_range()?;
    b.check_range()?;
    check_clearance(c)?;
    if is_round(a) || is_round(b) {
        round::within_distance(a, b, c)
    } else {
        Ok(polytopal::within_distance(a, b, c))
    }
}

/// [`within_distance`] where it is proved without the exact methods of the curved pairs
/// (`None`: not proved; every pair without a cylinder or cone is always answered). For a
/// caller that has a cheaper way on (a certified distance) than an exact clearance between
/// two cylinders.
pub(crate) fn within_distance_filtered(
    a: &Shape,
    b: &Shape,
    c: f64,
) -> Result<Option<bool>, Error> {
    a.check_range()?;
    b.check_range()?;
    check_clearance(c)?;
    Ok(if is_round(a) || is_round(b) {
        round::within_distance_filtered(a, b, c)
    } else {
        Some(polytopal::within_distance(a, b, c))
    })
}

/// A proved lower bound on [`distance`] from a short search, for the pairs whose certified
/// distance is a long one (a cylinder or cone against a triangle, cuboid, hull, cylinder or
/// cone); `None` for every other pair (their distance is quick) and where nothing is proved.
pub(crate) fn distance_lower_bound(a: &Shape, b: &Shape) -> Option<f64> {
    if a.check_range().is_err() || b.check_range().is_err() {
        return None;
    }
    if is_round(a) || is_round(b) {
        round::distance_lower_bound(a, b)
    } else {
        None
    }
}

/// The minimum distance between the two shapes (`0` when they meet) with witnesses and a
/// proved error bound.
pub fn distance(a: &Shape, b: &Shape) -> Result<CertifiedDistance, Error> {
    a.check_range()?;
    b.check_range()?;
    if is_round(a) || is_round(b) {
        round::distance(a, b)
    } else {
        Ok(polytopal::distance(a, b))
    }
}

/// [`intersects`] of the two shapes placed by their poses ([`Shape::placed`]).
pub fn intersects_at(
    a: &Shape,
    pose_a: &Isometry3<f64>,
    b: &Shape,
    pose_b: &Isometry3<f64>,
) -> Result<bool, Error> {
    intersects(&a.placed(pose_a)?, &b.placed(pose_b)?)
}

/// [`within_distance`] of the two shapes placed by their poses ([`Shape::placed`]).
pub fn within_distance_at(
    a: &Shape,
    pose_a: &Isometry3<f64>,
    b: &Shape,
    pose_b: &Isometry3<f64>,
    c: f64,
) -> Result<bool, Error> {
    within_distance(&a.placed(pose_a)?, &b.placed(pose_b)?, c)
}

/// [`distance`] of the two shapes placed by their poses ([`Shape::placed`]).
pub fn distance_at(
    a: &Shape,
    pose_a: &Isometry3<f64>,
    b: &Shape,
    pose_b: &Isometry3<f64>,
) -> Result<CertifiedDistance, Error> {
    distance(&a.placed(pose_a)?, &b.placed(pose_b)?)
}

/// For each pose pair, [`intersects_at`] of `a` at `pose.a` and `b` at `pose.b`, spread over
/// the cores; the first refused pose is [`Error::InBatch`] with its index.
///
/// ```
/// use cga_collide::{nalgebra::{Isometry3, Point3}, query, shape::PosePair, Ball};
/// let ball = Ball::new(Point3::origin(), 1.0)?.into();
/// let poses: Vec<PosePair> = [1.5, 2.0, 2.5]
///     .map(|x| PosePair::new(Isometry3::identity(), Isometry3::translation(x, 0.0, 0.0)))
///     .into();
/// assert_eq!(query::intersects_batch(&ball, &ball, &poses)?, vec![true, true, false]);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn intersects_batch(a: &Shape, b: &Shape, poses: &[PosePair]) -> Result<Vec<bool>, Error> {
    over_batch(poses, |p| intersects_at(a, &p.a, b, &p.b))
}

/// For each pose pair, [`within_distance_at`] with clearance `c`, spread over the cores; the
/// first refused pose is [`Error::InBatch`] with its index.
pub fn within_distance_batch(
    a: &Shape,
    b: &Shape,
    poses: &[PosePair],
    c: f64,
) -> Result<Vec<bool>, Error> {
    over_batch(poses, |p| within_distance_at(a, &p.a, b, &p.b, c))
}

/// For each pose pair, [`distance_at`], spread over the cores; the first refused pose is
/// [`Error::InBatch`] with its index.
pub fn distance_batch(
    a: &Shape,
    b: &Shape,
    poses: &[PosePair],
) -> Result<Vec<CertifiedDistance>, Error> {
    over_batch(poses, |p| distance_at(a, &p.a, b, &p.b))
}

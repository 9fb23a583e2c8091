//! Contact manifolds of two shapes: a few contact points, each with the pair's normal, its
//! signed distance along that normal and a proved error bound, as a physics solver takes them.
//!
//! # Definition
//! [`contact_manifold`] answers `None` when the shapes are farther apart than the margin, and
//! otherwise a [`ContactManifold`]:
//! * `signed_distance`: the pair's [`signed_distance`] (always `Some` for shapes);
//! * `normal`: the unit normal from `a` to `b` of [`signed_distance`] (the direction of the
//!   shortest separating translation when they overlap, the direction between the nearest
//!   points when apart), rounded to `f64`;
//! * `points`: one convex contact region, at most [`MAX_POINTS_PER_REGION`] points. Each
//!   [`ManifoldPoint`] has `point_a` on `a`'s boundary, `point_b` on `b`'s boundary over it
//!   along the normal, `point` halfway between them, and `distance = (point_b − point_a) ·
//!   normal` (negative where they overlap: minus the local depth; never below the pair's
//!   signed distance, up to rounding).
//!
//! # How the points are found
//! Each shape's *support feature* facing the other along the normal (a point, a segment, a
//! flat face, a half-space's plane; a face counts when its normal is within about 2.6° of the
//! contact normal, a cylinder's cap or a cone's base is taken as 8 points of its rim) is
//! projected on the plane across the normal; the lower-dimensional feature is clipped against
//! the other (Sutherland–Hodgman, or the overlap of two parallel segments), and each clipped
//! point is lifted back onto both features along the normal. Points farther apart than the
//! margin are dropped. When this gives nothing (a point feature, crossing edges), the one point
//! is the signed distance's witness pair.
//!
//! **Reduction to at most four**: the deepest point (least distance, the first on ties), the
//! point farthest from it across the normal, the point making the largest triangle with those
//! two, and the point farthest outside that triangle. Every step is deterministic: the same
//! inputs give the same manifold, bit for bit.
//!
//! # What is certified
//! `error_bound` of each point is a proved upper bound of that point's distance to each shape:
//! in plain `f64` with proved rounding for balls, capsules, segments, cuboids and half-spaces
//! (the distance to a point of the shape built from clamped exact parameters, `0` when the
//! point is proved inside), for solid hulls (`0` when proved strictly inside every boundary
//! plane) and triangles (the distance to the point under it, when that falls inside the
//! triangle), and from the crate's exact point–shape distance for the rest:
//! * when the shapes meet (touching or overlapping): `point` lies within `error_bound` of `a`
//!   and within `error_bound` of `b`; `error_bound == 0` means `point` lies exactly in the
//!   intersection `a ∩ b`;
//! * when they are apart (within the margin): `point_a` lies within `error_bound` of `a` and
//!   `point_b` within `error_bound` of `b` (the closest features).
//!
//! The signed distance (`signed_distance`, with its own bound) and the kind are certified as
//! in [`signed_distance`]; the normal and the points are rounded `f64` values, the normal unit
//! to within a few ulps.
//!
//! # Refused
//! The pairs [`signed_distance`] refuses ([`Error::UnsupportedPair`]): a cylinder or cone pair
//! whose contact it cannot decide (see there), two half-spaces whose normals are not opposite, overlapping hulls of more than
//! [`MAX_HULL_POINTS`](crate::query::MAX_HULL_POINTS) points; and a margin that is not a finite
//! number `>= 0` ([`Error::InvalidClearance`]).

mod clip;
mod feature;
pub(super) mod point_bound;

use nalgebra::{Isometry3, Point3, Vector3};

use super::depth::{signed_distance, SignedDistance, SignedDistanceKind};
use super::{check_clearance, distance};
use crate::error::Error;
use crate::parallel::over_batch;
use crate::shape::{Ball, PosePair, Shape};

/// The most points a manifold keeps per contact region.
pub const MAX_POINTS_PER_REGION: usize = 4;

pub(crate) use clip::keep_four;

/// One contact point of a [`ContactManifold`] (defined on [`contact_manifold`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ManifoldPoint {
    /// Halfway between `point_a` and `point_b`: when the shapes meet, within `error_bound` of
    /// both shapes (in their intersection when the bound is `0`).
    pub point: Point3<f64>,
    /// On `a`'s boundary (rounded); when apart, within `error_bound` of `a`.
    pub point_a: Point3<f64>,
    /// On `b`'s boundary over `point_a` along the normal (rounded); when apart, within
    /// `error_bound` of `b`.
    pub point_b: Point3<f64>,
    /// `(point_b − point_a) · normal`: negative where the shapes overlap.
    pub distance: f64,
    /// The proved bound described on [`contact_manifold`].
    pub error_bound: f64,
}

/// One contact region of two shapes or two meshes: one normal and up to
/// [`MAX_POINTS_PER_REGION`] points.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactManifold {
    /// Unit (rounded), from `a` towards `b`.
    pub normal: Vector3<f64>,
    /// The contact points (at least one), in a deterministic order.
    pub points: Vec<ManifoldPoint>,
    /// Shape pairs: the pair's certified signed distance, with its bound and kind. `None` for
    /// a region of two meshes
    /// ([`Collider::contact_manifolds`](crate::collider::Collider::contact_manifolds)).
    pub signed_distance: Option<SignedDistance>,
    /// Mesh regions: the intersecting triangle pairs `(i, j)` of the region, sorted; empty for
    /// shape pairs.
    pub triangle_pairs: Vec<(u32, u32)>,
}

/// The contact manifold of two shapes, or `None` when they are farther apart than `margin`
/// (the definitions, what is certified and what is refused: [`ContactManifold`] and the section
/// "Contact manifolds" of `docs/contacts.md`).
///
/// ```
/// use cga_collide::{nalgebra::{Point3, Vector3}, query, shape::Cuboid};
/// let table = Cuboid::axis_aligned(Point3::origin(), Vector3::new(2.0, 2.0, 0.5))?.into();
/// // A unit box sunk 0.125 into the table's top face: four corners, each 0.125 deep.
/// let block = Cuboid::axis_aligned(Point3::new(0.0, 0.0, 0.875), Vector3::new(0.5, 0.5, 0.5))?;
/// let m = query::contact_manifold(&table, &block.into(), 0.0)?.expect("they overlap");
/// assert_eq!(m.normal, Vector3::z());
/// assert_eq!(m.points.len(), 4);
/// for p in &m.points {
///     assert_eq!(p.distance, -0.125);
///     assert_eq!(p.error_bound, 0.0); // exactly inside both boxes
/// }
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn contact_manifold(
    a: &Shape,
    b: &Shape,
    margin: f64,
) -> Result<Option<ContactManifold>, Error> {
    check_clearance(margin)?;
    let sd = signed_distance(a, b)?;
    if sd.kind == SignedDistanceKind::Separated && sd.value - sd.error_bound > margin {
        return Ok(None);
    }
    let n = sd.normal;
    // A ball's feature is one point, which clips to nothing: its one contact point is the
    // witness pair, without building the other shape's feature.
    let ball = matches!(a, Shape::Ball(_)) || matches!(b, Shape::Ball(_));
    let mut pairs: Vec<(clip::Pair, f64)> = if ball {
        Vec::with_capacity(1)
    } else {
        let fa = feature::support_feature(a, &n);
        let fb = feature::support_feature(b, &-n);
        let origin = Point3::from((sd.witness_a.coords + sd.witness_b.coords) * 0.5);
        clip::contact_pairs(&fa, &fb, &n, origin)
            .into_iter()
            .map(|p| (p, (p.b - p.a).dot(&n)))
            .filter(|(_, d)| *d <= margin)
            .collect()
    };
    if pairs.is_empty() {
        let witness = clip::Pair {
            a: sd.witness_a,
            b: sd.witness_b,
        };
        pairs.push((witness, (witness.b - witness.a).dot(&n)));
    }
    let meeting = sd.kind != SignedDistanceKind::Separated;
    let points = clip::reduce(pairs, &n)
        .into_iter()
        .map(|(p, d)| certified(a, b, p, d, meeting))
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(Some(ContactManifold {
        normal: n,
        points,
        signed_distance: Some(sd),
        triangle_pairs: Vec::new(),
    }))
}

/// The proved upper end of the distance from `p` to `shape`: the `f64` bound where it applies,
/// else the exact point–shape distance.
fn distance_up_to(p: &Point3<f64>, shape: &Shape) -> Result<f64, Error> {
    if let Some(bound) = point_bound::upper_distance(p, shape) {
        return Ok(bound);
    }
    let d = distance(&Shape::Ball(Ball::new(*p, 0.0)?), shape)?;
    // Rounded up: the sum of two non-negative `f64`s, nudged past its rounding.
    let sum = d.distance + d.error_bound;
    Ok(if sum == 0.0 { 0.0 } else { sum.next_up() })
}

fn certified(
    a: &Shape,
    b: &Shape,
    p: clip::Pair,
    distance: f64,
    meeting: bool,
) -> Result<ManifoldPoint, Error> {
    let point = Point3::from((p.a.coords + p.b.coords) * 0.5);
    let error_bound = if meeting {
        distance_up_to(&point, a)?.max(distance_up_to(&point, b)?)
    } else {
        distance_up_to(&p.a, a)?.max(distance_up_to(&p.b, b)?)
    };
    Ok(ManifoldPoint {
        point,
        point_a: p.a,
        point_b: p.b,
        distance,
        error_bound,
    })
}

/// [`contact_manifold`] of the two shapes placed by their poses ([`Shape::placed`]).
pub fn contact_manifold_at(
    a: &Shape,
    pose_a: &Isometry3<f64>,
    b: &Shape,
    pose_b: &Isometry3<f64>,
    margin: f64,
) -> Result<Option<ContactManifold>, Error> {
    contact_manifold(&a.placed(pose_a)?, &b.placed(pose_b)?, margin)
}

/// For each pose pair, [`contact_manifold_at`], spread over the cores; the first refused pose
/// is [`Error::InBatch`] with its index.
pub fn contact_manifold_batch(
    a: &Shape,
    b: &Shape,
    poses: &[PosePair],
    margin: f64,
) -> Result<Vec<Option<ContactManifold>>, Error> {
    over_batch(poses, |p| contact_manifold_at(a, &p.a, b, &p.b, margin))
}

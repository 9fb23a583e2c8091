//! Signed distance between two shapes: the distance when they are apart, minus the
//! penetration depth when they overlap, each exact up to one final rounding with a proved
//! bound.
//!
//! # Definition
//! For two closed convex shapes `A` and `B`, [`signed_distance`] is
//! * their distance when they are apart ([`SignedDistanceKind::Separated`], `value > 0`);
//! * `0` when they touch: they meet, but no translation of `B` is needed to make their
//!   interiors disjoint ([`SignedDistanceKind::Touching`]);
//! * minus the **penetration depth** when they overlap
//!   ([`SignedDistanceKind::Penetrating`], `value < 0`): the length of the shortest
//!   translation of `B` after which the two only touch.
//!
//! In every case, translating `B` by `−value · normal` brings the two into touching contact,
//! and [`SignedDistance::witness_a`], [`SignedDistance::witness_b`] are points of `A` and `B`
//! with `(witness_b − witness_a) · normal = value` (up to rounding).
//!
//! # How it is computed
//! Every kind but the half-space, the cylinder and the cone is a convex polytope (its *core*)
//! grown by a ball of radius `r` (a ball is a point grown by its radius, a capsule a segment,
//! the other kinds are their own core with `r = 0`). The Minkowski difference of
//! `A = P ⊕ ball(r)` and `B = Q ⊕ ball(s)` is `(P − Q) ⊕ ball(r + s)`, so
//! * when the cores are apart by `d`: `value = d − (r + s)` (exact squared core distance from
//!   the exact GJK search, the difference formed exactly before the one rounding);
//! * when the cores meet: `value = −(depth(P − Q) + r + s)`, the depth of the origin in the
//!   polytope `P − Q`, found exactly over a finite set of candidate facet normals
//!   ([`polytope`]).
//!
//! Half-spaces use their support function exactly ([`half_space`]), a cylinder's or cone's
//! too (its sign decided exactly, its value bounded with outward rounding). Any other pair
//! with a cylinder or a cone gets its certified distance when that proves it apart, and
//! otherwise a certified bracket ([`curved`]): inner polytopes proved inside the round
//! shapes give a lower bound of the depth, the true support functions in the inner
//! optimum's direction an upper bound; the kind comes from the exact `intersects` and an
//! exact touching test, and a meeting pair whose sign neither decides is
//! [`Error::UnsupportedPair`] (as are the pairs `intersects` refuses). Two half-spaces whose
//! normals are not opposite have no finite depth and are also [`Error::UnsupportedPair`], as
//! are overlapping hulls of more than [`MAX_HULL_POINTS`] corners.
//!
//! # Error bound
//! The true signed distance of the shapes the `f64` inputs denote lies in
//! `value ± error_bound`. Apart: the bound of the certified distance, or, near contact, a few
//! ulps of the value itself. Touching: `value = 0` with bound `0`. Overlapping polytopal
//! shapes are first answered in plain `f64` with proved rounding bounds ([`fast`]: every
//! candidate normal's support gap as an interval), kept when the bound is at most
//! `2^-30 · |value|` (about `1e-14` relative in practice, and microseconds instead of the exact
//! path's milliseconds); otherwise (touching, tiny overlaps, extreme magnitudes) the exact
//! squared depth is rounded once (a few ulps of `|value|`), so a one-ulp overlap of two boxes
//! gets its exact tiny depth. Pairs with a cylinder or a cone (other than half-spaces): the
//! half width of the bracket, which the refinement brings below `32 · 2^-52` of the pair's
//! scale where it converges within its round cap. The normal and the witnesses are rounded `f64` values, not
//! certified; the normal of overlapping cores is the exact minimising facet direction,
//! rounded.
//!
//! ```
//! use cga_collide::{nalgebra::{Point3, Vector3}, query, shape::Cuboid, Ball};
//! let table = Cuboid::axis_aligned(Point3::origin(), Vector3::new(1.0, 1.0, 0.5))?.into();
//! // A ball sunk 0.25 into the table's top face.
//! let ball = Ball::new(Point3::new(0.0, 0.0, 1.0), 0.75)?.into();
//! let sd = query::signed_distance(&table, &ball)?;
//! assert_eq!(sd.kind, query::SignedDistanceKind::Penetrating);
//! assert!((sd.value + 0.25).abs() <= sd.error_bound);
//! assert_eq!(sd.normal, Vector3::z()); // move the ball up by 0.25 to separate them
//! // Lifted by 1: apart by 0.75.
//! let lifted = Ball::new(Point3::new(0.0, 0.0, 2.0), 0.75)?.into();
//! let sd = query::signed_distance(&table, &lifted)?;
//! assert!((sd.value - 0.75).abs() <= sd.error_bound);
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod body;
mod curved;
mod fast;
mod half_space;
mod inner;
mod polytope;
mod rounding;
#[cfg(test)]
mod tests;

use nalgebra::{Isometry3, Point3, Vector3};

use super::{is_round, polytopal, round};
use crate::error::Error;
use crate::parallel::over_batch;
use crate::shape::{PosePair, Shape};

pub use polytope::MAX_HULL_POINTS;

/// Which side of contact two shapes are on (decided exactly).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SignedDistanceKind {
    /// The shapes do not meet: the value is their distance, `> 0`.
    Separated,
    /// The shapes meet and no translation is needed to make their interiors disjoint: the
    /// value is exactly `0`.
    Touching,
    /// The interiors overlap: the value is minus the penetration depth, `< 0`.
    Penetrating,
}

/// A signed distance with a proved error bound, its direction and witness points (defined on
/// [`signed_distance`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SignedDistance {
    /// The signed distance in `f64`: the distance when apart, minus the penetration depth
    /// when overlapping.
    pub value: f64,
    /// The true signed distance lies in `[value − error_bound, value + error_bound]`.
    pub error_bound: f64,
    /// A unit vector (rounded) from `a` towards `b`: translating `b` by `−value · normal`
    /// makes the two touch.
    pub normal: Vector3<f64>,
    /// A point of `a`: its nearest point when apart, its point deepest along `normal` when
    /// overlapping.
    pub witness_a: Point3<f64>,
    /// A point of `b`, with `(witness_b − witness_a) · normal = value` up to rounding.
    pub witness_b: Point3<f64>,
    /// Separated, touching or penetrating, decided exactly.
    pub kind: SignedDistanceKind,
}

/// `v` scaled to unit length (the `x` axis for a zero vector), safe at every magnitude.
fn unit(v: &Vector3<f64>) -> Vector3<f64> {
    let m = v.amax();
    if m == 0.0 || !m.is_finite() {
        return Vector3::x();
    }
    (v / m).normalize()
}

fn unsupported(a: &Shape, b: &Shape) -> Error {
    Error::UnsupportedPair {
        query: "signed_distance",
        a: a.kind(),
        b: b.kind(),
    }
}

/// The signed distance of two shapes: their distance when apart, minus the penetration depth
/// when they overlap, with a proved error bound, the normal from `a` to `b` and witness
/// points. Apart, it is their distance; touching, `0`; overlapping, minus the penetration depth
/// (the length of the shortest translation of `b` after which the two only touch); translating
/// `b` by `−value · normal` brings them into touching contact. Refused with
/// [`Error::UnsupportedPair`]: a cylinder or cone pair that `intersects` refuses or whose
/// contact is within the bound of touching without an exact proof either way, two
/// half-spaces whose normals are not opposite (no finite depth), overlapping hulls of more
/// than [`MAX_HULL_POINTS`] corners.
///
/// ```
/// use cga_collide::{nalgebra::{Point3, Vector3}, query, shape::Cuboid};
/// let c = |x: f64| Cuboid::axis_aligned(Point3::new(x, 0.0, 0.0), Vector3::new(0.5, 0.5, 0.5));
/// // Faces flush at x = 0.5: touching, exactly 0.
/// let sd = query::signed_distance(&c(0.0)?.into(), &c(1.0)?.into())?;
/// assert_eq!((sd.value, sd.error_bound), (0.0, 0.0));
/// assert_eq!(sd.kind, query::SignedDistanceKind::Touching);
/// // One ulp of overlap: the depth is that ulp.
/// let ulp = 1.0 - 1f64.next_down();
/// let sd = query::signed_distance(&c(0.0)?.into(), &c(1f64.next_down())?.into())?;
/// assert!((sd.value + ulp).abs() <= sd.error_bound && sd.error_bound < 1e-30);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn signed_distance(a: &Shape, b: &Shape) -> Result<SignedDistance, Error> {
    a.check_range()?;
    b.check_range()?;
    if is_round(a) || is_round(b) {
        return round_pair(a, b);
    }
    match (a, b) {
        (Shape::HalfSpace(ha), Shape::HalfSpace(hb)) => {
            half_space::between(ha, hb).ok_or_else(|| unsupported(a, b))
        }
        (Shape::HalfSpace(h), other) => polytope::Core::of(other)
            .map(|core| half_space::to_core(h, &core, false))
            .ok_or_else(|| unsupported(a, b)),
        (other, Shape::HalfSpace(h)) => polytope::Core::of(other)
            .map(|core| half_space::to_core(h, &core, true))
            .ok_or_else(|| unsupported(a, b)),
        _ => cores(a, b),
    }
}

/// A pair with a cylinder or a cone: against a half-space exactly ([`half_space::to_round`]);
/// otherwise the certified distance when it proves the two apart, else the bracket of
/// [`curved`], its kind from the exact `intersects` (whose refusals are kept).
fn round_pair(a: &Shape, b: &Shape) -> Result<SignedDistance, Error> {
    match (a, b) {
        (Shape::HalfSpace(h), other) => {
            return body::Body::of(other)
                .map(|body| half_space::to_round(h, &body, false))
                .ok_or_else(|| unsupported(a, b));
        }
        (other, Shape::HalfSpace(h)) => {
            return body::Body::of(other)
                .map(|body| half_space::to_round(h, &body, true))
                .ok_or_else(|| unsupported(a, b));
        }
        _ => {}
    }
    if let Ok(d) = round::distance(a, b) {
        if d.distance - d.error_bound > 0.0 {
            return Ok(apart(d.distance, d.error_bound, d.witness_a, d.witness_b));
        }
    }
    let meets = round::intersects(a, b)?;
    curved::signed_distance(a, b, meets)
}

/// A separated answer from a certified distance and its witnesses.
fn apart(distance: f64, bound: f64, wa: Point3<f64>, wb: Point3<f64>) -> SignedDistance {
    SignedDistance {
        value: distance,
        error_bound: bound,
        normal: unit(&(wb - wa)),
        witness_a: wa,
        witness_b: wb,
        kind: SignedDistanceKind::Separated,
    }
}

/// The radius a polytopal shape's core is grown by.
fn radius(s: &Shape) -> f64 {
    match s {
        Shape::Ball(b) => b.radius(),
        Shape::Capsule(c) => c.radius(),
        _ => 0.0,
    }
}

/// Two polytopal shapes (neither a half-space).
fn cores(a: &Shape, b: &Shape) -> Result<SignedDistance, Error> {
    match fast::signed_distance(a, b) {
        Some(answer) => Ok(answer),
        None => exact_cores(a, b),
    }
}

/// Two polytopal shapes (neither a half-space), by the exact path alone.
fn exact_cores(a: &Shape, b: &Shape) -> Result<SignedDistance, Error> {
    let d = polytopal::distance(a, b);
    if d.distance - d.error_bound > 0.0 {
        return Ok(apart(d.distance, d.error_bound, d.witness_a, d.witness_b));
    }
    let radii = [radius(a), radius(b)];
    let Some((d2, x, y)) = polytopal::exact_core_distance2(a, b) else {
        return Err(unsupported(a, b));
    };
    if !ga_core::scalar::Ring::is_zero(&d2) {
        // The cores are apart: only the radii overlap (or nearly touch).
        let (value, error_bound, kind) = rounding::signed_root_minus(true, &d2, radii);
        let (x, y) = (Point3::from(x), Point3::from(y));
        let normal = unit(&(y - x));
        return Ok(SignedDistance {
            value,
            error_bound,
            normal,
            witness_a: x + normal * radii[0],
            witness_b: y - normal * radii[1],
            kind,
        });
    }
    let (Some(ca), Some(cb)) = (polytope::Core::of(a), polytope::Core::of(b)) else {
        return Err(unsupported(a, b));
    };
    let deep = polytope::depth(&ca, &cb);
    let (value, error_bound, kind) = rounding::signed_root_minus(false, &deep.depth2, radii);
    let n = deep.normal;
    Ok(SignedDistance {
        value,
        error_bound,
        normal: n,
        witness_a: Point3::from(deep.support_a) + n * radii[0],
        witness_b: Point3::from(deep.support_b) - n * radii[1],
        kind,
    })
}

/// [`signed_distance`] of the two shapes placed by their poses ([`Shape::placed`]).
pub fn signed_distance_at(
    a: &Shape,
    pose_a: &Isometry3<f64>,
    b: &Shape,
    pose_b: &Isometry3<f64>,
) -> Result<SignedDistance, Error> {
    signed_distance(&a.placed(pose_a)?, &b.placed(pose_b)?)
}

/// For each pose pair, [`signed_distance_at`], spread over the cores; the first refused pose
/// is [`Error::InBatch`] with its index.
pub fn signed_distance_batch(
    a: &Shape,
    b: &Shape,
    poses: &[PosePair],
) -> Result<Vec<SignedDistance>, Error> {
    over_batch(poses, |p| signed_distance_at(a, &p.a, b, &p.b))
}

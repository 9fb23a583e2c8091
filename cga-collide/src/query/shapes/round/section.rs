//! A cylinder or cone against a convex polytope (segment, triangle, cuboid, hull): does it meet?
//!
//! * Cylinder: it is its first cap disc `D` swept along the axis `d`, so it meets a polytope
//!   `P` iff `D` meets `P ⊕ [−d, 0]` (the hull of the vertices and the vertices moved by `−d`),
//!   iff the disc's centre is within the radius of that polytope's section by the disc's
//!   plane. The section of the hull of points by a plane is the hull of the points on the plane
//!   and of the crossings of the segments between points on either side: all rational.
//! * Cone: clip `P` to the slab between the apex plane and the base plane. The cone meets the
//!   clipped `P` iff the apex is in it or some segment from the apex to a point of `P` reaches
//!   the base disc, i.e. the disc meets the central projection of `P` from the apex onto the
//!   base plane: points with a positive height project to rational points, points on the apex
//!   plane become rays (the projection of a set touching that plane is unbounded).

use ga_core::scalar::Rational;
use num_traits::{Signed, Zero};

use super::exact3::{add, dot, scale, sub, Profile, Round, V3};
use super::planar::disc_meets;

/// The points and crossings that span the section of `conv(points)` by the plane
/// `{x : (x − on)·normal = 0}`.
fn section(points: &[V3], on: &V3, normal: &V3) -> Vec<V3> {
    let height: Vec<Rational> = points.iter().map(|p| dot(&sub(p, on), normal)).collect();
    let mut out = Vec::new();
    for (i, p) in points.iter().enumerate() {
        if height[i].is_zero() {
            out.push(p.clone());
        }
        for (j, other) in points.iter().enumerate().skip(i + 1) {
            if height[i].is_positive() && height[j].is_negative()
                || height[i].is_negative() && height[j].is_positive()
            {
                let t = &height[i] / (&height[i] - &height[j]);
                out.push(add(p, &scale(&sub(other, p), &t)));
            }
        }
    }
    dedup(out)
}

/// The points spanning `conv(points) ∩ {x : (x − on)·normal <= 0}`.
fn clip(points: &[V3], on: &V3, normal: &V3) -> Vec<V3> {
    let mut out: Vec<V3> = points
        .iter()
        .filter(|p| !dot(&sub(p, on), normal).is_positive())
        .cloned()
        .collect();
    out.extend(section(points, on, normal));
    dedup(out)
}

fn dedup(mut points: Vec<V3>) -> Vec<V3> {
    points.sort();
    points.dedup();
    points
}

/// Exact: does the cylinder or cone meet the convex hull of `vertices` (not empty)?
pub(crate) fn meets_polytope(round: &Round, vertices: &[V3]) -> bool {
    let r2 = &round.radius * &round.radius;
    match round.profile {
        Profile::Cylinder => {
            let mut swept: Vec<V3> = vertices.to_vec();
            swept.extend(vertices.iter().map(|v| sub(v, &round.axis)));
            let cut = section(&dedup(swept), &round.origin, &round.axis);
            disc_meets(&round.origin, &round.axis, &r2, &cut, &[])
        }
        Profile::Cone => {
            let down = scale(&round.axis, &-Rational::from_integer(1.into()));
            let above_apex = clip(vertices, &round.origin, &down);
            let slab = clip(&above_apex, &round.end, &round.axis);
            if slab.is_empty() {
                return false;
            }
            let heights: Vec<Rational> = slab
                .iter()
                .map(|p| dot(&sub(p, &round.origin), &round.axis))
                .collect();
            let on_apex_plane: Vec<V3> = slab
                .iter()
                .zip(&heights)
                .filter(|(_, h)| h.is_zero())
                .map(|(p, _)| p.clone())
                .collect();
            let zero = Rational::zero();
            if !on_apex_plane.is_empty()
                && disc_meets(&round.origin, &round.axis, &zero, &on_apex_plane, &[])
            {
                return true;
            }
            let projected: Vec<V3> = slab
                .iter()
                .zip(&heights)
                .filter(|(_, h)| h.is_positive())
                .map(|(p, h)| {
                    add(
                        &round.origin,
                        &scale(&sub(p, &round.origin), &(&round.length2 / h)),
                    )
                })
                .collect();
            let rays: Vec<V3> = on_apex_plane
                .iter()
                .map(|p| sub(p, &round.origin))
                .collect();
            disc_meets(&round.end, &round.axis, &r2, &projected, &rays)
        }
    }
}

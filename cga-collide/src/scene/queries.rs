//! The questions a [`Scene`] answers: the broad phase proposes pairs (or objects), and each is
//! decided exactly by the colliders' pose queries or the shapes' pair queries, over the cores.

use ga_core::scalar::{rational_from_f64, Rational, Real};
use nalgebra::{Isometry3, Point3};

use super::broad_phase::box_gap;
use super::pair::Placed;
use super::{placed_shape, ObjectId, Scene};
use crate::collider::Collider;
use crate::error::Error;
use crate::parallel::*;
use crate::query::{self, segment_triangle_entry, CertifiedDistance};
use crate::shape::Shape;
use crate::Segment;

/// A pair of objects with their certified distance.
pub type NearestPair = (ObjectId, ObjectId, CertifiedDistance);

/// Where a segment `[a, b]` first meets an object ([`Scene::segment_hits_along`],
/// [`Scene::first_segment_hit`]): the least `t ∈ [0, 1]` with `a + t (b − a)` on the object's
/// placed surface, exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentHit {
    /// The object.
    pub object: ObjectId,
    /// The triangle of the object's mesh met first (the smallest index if several are met
    /// first at the same point); `0` for a shape object.
    pub triangle: u32,
    /// The exact parameter `t` of the first hit: the true value for the `f64` coordinates of
    /// the segment and of the placed mesh (see [`segment_triangle_entry`](crate::query::segment_triangle_entry)).
    pub parameter: Rational,
    /// The point `a + t (b − a)` of the first hit, each coordinate the exact value rounded to
    /// the nearest `f64`.
    pub point: Point3<f64>,
}

impl SegmentHit {
    fn new(object: ObjectId, triangle: u32, parameter: Rational, segment: &Segment) -> SegmentHit {
        let at = |a: f64, b: f64| {
            let (a, b) = (exact(a), exact(b));
            Real::to_f64(&(&a + &(&(&b - &a) * &parameter)))
        };
        let (a, b) = (segment.a(), segment.b());
        let point = Point3::new(at(a.x, b.x), at(a.y, b.y), at(a.z, b.z));
        SegmentHit {
            object,
            triangle,
            parameter,
            point,
        }
    }

    /// The parameter rounded to the nearest `f64` (in `[0, 1]`).
    pub fn parameter_f64(&self) -> f64 {
        Real::to_f64(&self.parameter)
    }
}

fn exact(x: f64) -> Rational {
    // Segments hold finite coordinates only.
    rational_from_f64(x).unwrap_or_default()
}

impl Scene {
    /// Every pair of objects `(a, b)` that touch (surfaces meet; solids share a point with
    /// [`set_solid`](Self::set_solid)), exactly, sorted, `a` before `b`; excluded pairs and
    /// pairs kept apart by their groups are left out. The candidate pairs of the broad phase
    /// are decided in parallel.
    pub fn colliding_pairs(&self) -> Result<Vec<(ObjectId, ObjectId)>, Error> {
        let candidates = self.candidates(0.0);
        let hits = candidates
            .par_iter()
            .map(|&(a, b)| self.touch(a, b))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.ids_of(candidates.into_iter().zip(hits)))
    }

    /// Every object that touches `id` (see [`colliding_pairs`](Self::colliding_pairs)), sorted.
    pub fn colliding_with(&self, id: ObjectId) -> Result<Vec<ObjectId>, Error> {
        let world = *self.broad.bounds(self.object(id).map(|_| id.index)?);
        let others: Vec<u32> = self
            .broad
            .near_box(&world, 0.0)
            .into_iter()
            .filter(|&o| o != id.index && self.tested(id.index, o))
            .collect();
        let hits = others
            .par_iter()
            .map(|&o| self.touch(id.index, o))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(others, hits))
    }

    /// Every object that an outside collider placed at `pose` would touch (a new object: does
    /// it fit?), sorted. Groups and exclusions do not apply to it.
    pub fn colliding_at(
        &self,
        collider: &Collider,
        pose: &Isometry3<f64>,
    ) -> Result<Vec<ObjectId>, Error> {
        let world = collider.world_box(pose)?;
        self.colliding_with_outside(&world, Placed::Mesh(collider, pose))
    }

    /// Every object that an outside shape placed at `pose` ([`Shape::placed`]) would touch,
    /// sorted (as [`colliding_at`](Self::colliding_at) for a collider).
    pub fn colliding_at_shape(
        &self,
        shape: &Shape,
        pose: &Isometry3<f64>,
    ) -> Result<Vec<ObjectId>, Error> {
        let (placed, world) = placed_shape(shape, pose)?;
        self.colliding_with_outside(&world, Placed::Shape(&placed))
    }

    fn colliding_with_outside(
        &self,
        world: &crate::bounding::Aabb,
        outside: Placed,
    ) -> Result<Vec<ObjectId>, Error> {
        let near = self.broad.near_box(world, 0.0);
        let hits = near
            .par_iter()
            .map(|&o| outside.touches(self.slot(o).placed(), self.solid))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(near, hits))
    }

    /// Every pair of objects whose surfaces (a shape's solid) come within distance `c`,
    /// exactly (closed: a distance of exactly `c` counts), sorted. NaN and negative `c` give
    /// no pair; a pair with a shape refuses a `c` that is not a finite distance
    /// ([`Error::InvalidClearance`]).
    pub fn pairs_within_distance(&self, c: f64) -> Result<Vec<(ObjectId, ObjectId)>, Error> {
        if c.is_nan() || c < 0.0 {
            return Ok(Vec::new());
        }
        let candidates = self.candidates(c);
        let hits = candidates
            .par_iter()
            .map(|&(a, b)| self.slot(a).placed().within(self.slot(b).placed(), c))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.ids_of(candidates.into_iter().zip(hits)))
    }

    /// The nearest pair of objects (surfaces) and its certified distance: among the pairs the
    /// search cannot prove farther, the one with the least `f64` distance, ties to the smaller
    /// pair. `None` with fewer than two objects that may be paired.
    ///
    /// Objects whose surfaces meet are at distance 0 (whatever [`set_solid`](Self::set_solid)
    /// says: the distance is between surfaces): when some do, the first such pair the broad
    /// phase's sweep meets is reported and the search stops there (as FCL's minimum-distance
    /// callback does). Its distance and error bound are exactly 0, proved by the intersecting
    /// triangle pair the collision test stops at (`triangles`); the witnesses are the `f64`
    /// nearest points of those two placed triangles (each on its triangle up to rounding).
    pub fn nearest_pair(&self) -> Result<Option<NearestPair>, Error> {
        // Touching pairs first: their distance is 0, so the first pair the sweep meets whose
        // surfaces meet is a nearest pair, and the search stops there. The intersecting
        // triangle pair the collision test stops at proves the 0 exactly (no distance search).
        let mut touching = None;
        let found = self.broad.first_pair(|a, b| {
            if !self.tested(a, b) {
                return Ok::<bool, Error>(false);
            }
            touching = self
                .slot(a)
                .placed()
                .touching_distance(self.slot(b).placed())?;
            Ok(touching.is_some())
        })?;
        if let (Some((a, b)), Some(d)) = (found, touching) {
            return Ok(Some((self.id_of(a), self.id_of(b), d)));
        }
        // A first bound from the pair of neighbours in sweep order with the smallest box gap.
        let order = self.broad.sweep_order();
        let seed = order
            .windows(2)
            .filter(|w| self.tested(w[0], w[1]))
            .map(|w| {
                (
                    box_gap(self.broad.bounds(w[0]), self.broad.bounds(w[1])),
                    w[0],
                    w[1],
                )
            })
            .min_by(|x, y| x.0.total_cmp(&y.0));
        let Some((_, a, b)) = seed.or_else(|| self.any_tested_pair()) else {
            return Ok(None);
        };
        let mut best = (a.min(b), a.max(b), self.distance(a, b)?);
        // Then every pair whose boxes come within the bound, nearest boxes first.
        let reach = best.2.distance + best.2.error_bound;
        let mut candidates: Vec<(f64, u32, u32)> = self
            .candidates(reach)
            .into_iter()
            .map(|(a, b)| (box_gap(self.broad.bounds(a), self.broad.bounds(b)), a, b))
            .collect();
        candidates.sort_by(|x, y| x.0.total_cmp(&y.0));
        for (gap, a, b) in candidates {
            if gap > best.2.distance + best.2.error_bound {
                break;
            }
            if (a, b) == (best.0, best.1) {
                continue;
            }
            let d = self.distance(a, b)?;
            if (d.distance, a, b) < (best.2.distance, best.0, best.1) {
                best = (a, b, d);
            }
        }
        Ok(Some((self.id_of(best.0), self.id_of(best.1), best.2)))
    }

    /// The object nearest to `id` (surfaces) and the certified distance, as
    /// [`nearest_pair`](Self::nearest_pair) restricted to pairs with `id`: when some objects'
    /// surfaces meet its surface, the one with the smallest handle, at distance exactly 0.
    /// `None` when no other object may be paired with it.
    pub fn nearest_to(&self, id: ObjectId) -> Result<Option<(ObjectId, CertifiedDistance)>, Error> {
        self.object(id)?;
        let me = id.index;
        let world = *self.broad.bounds(me);
        let mut others: Vec<(f64, u32)> = self
            .ids()
            .into_iter()
            .map(|o| o.index)
            .filter(|&o| o != me && self.tested(me, o))
            .map(|o| (box_gap(&world, self.broad.bounds(o)), o))
            .collect();
        others.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        // Surfaces that meet this one first (boxes at gap 0, in slot order): distance 0,
        // proved by an intersecting triangle pair, and the search stops there.
        let me_object = self.slot(me).placed();
        for &(_, o) in others.iter().take_while(|(gap, _)| *gap == 0.0) {
            if let Some(d) = me_object.touching_distance(self.slot(o).placed())? {
                return Ok(Some((self.id_of(o), d)));
            }
        }
        let mut best: Option<(u32, CertifiedDistance)> = None;
        for (gap, o) in others {
            if best.is_some_and(|(_, d)| gap > d.distance + d.error_bound) {
                break;
            }
            let d = self.distance(me, o)?;
            if best.is_none_or(|(b, bd)| (d.distance, o) < (bd.distance, b)) {
                best = Some((o, d));
            }
        }
        Ok(best.map(|(o, d)| (self.id_of(o), d)))
    }

    /// Every object whose surface (a shape's solid) the closed segment meets, sorted.
    pub fn segment_hits(&self, segment: &Segment) -> Result<Vec<ObjectId>, Error> {
        let near = self.near_segment(segment);
        let hits = near
            .par_iter()
            .map(|&o| match self.slot(o).placed() {
                Placed::Mesh(collider, pose) => collider
                    .segment_hits_at(pose, segment)
                    .map(|t| !t.is_empty()),
                Placed::Shape(shape) => query::intersects(&(*segment).into(), shape),
            })
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(near, hits))
    }

    /// Every object whose surface the closed segment meets, each with its first hit, in order
    /// along the segment: by the exact parameter of the first hit, ties (objects first met at
    /// the same point) by handle. See [`SegmentHit`]; the objects are those of
    /// [`segment_hits`](Self::segment_hits).
    ///
    /// A shape object's first hit is the least `t` with the point in the solid shape; it is
    /// given exactly for triangles and half-spaces. The first point on the other shapes'
    /// surfaces is not rational in general (a ball's is a root of a quadratic): a segment that
    /// meets one of them is refused with [`Error::UnsupportedPair`].
    ///
    /// ```
    /// use std::sync::Arc;
    /// use cga_collide::collider::Collider;
    /// use cga_collide::nalgebra::{Isometry3, Point3};
    /// use cga_collide::scene::Scene;
    /// use cga_collide::{Segment, TriMesh};
    /// let cube = Arc::new(Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?));
    /// let mut scene = Scene::new();
    /// let far = scene.add(cube.clone(), Isometry3::translation(6.0, 0.0, 0.0))?; // x in [6, 7]
    /// let near = scene.add(cube.clone(), Isometry3::translation(2.0, 0.0, 0.0))?; // x in [2, 3]
    /// let s = Segment::new(Point3::new(0.0, 0.5, 0.5), Point3::new(8.0, 0.5, 0.5))?;
    /// let hits = scene.segment_hits_along(&s)?;
    /// assert_eq!(hits.iter().map(|h| h.object).collect::<Vec<_>>(), vec![near, far]);
    /// assert_eq!(hits[0].parameter.to_string(), "1/4"); // x = 2
    /// assert_eq!((hits[1].parameter_f64(), hits[1].point), (0.75, Point3::new(6.0, 0.5, 0.5)));
    /// assert_eq!(scene.first_segment_hit(&s)?, Some(hits[0].clone()));
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn segment_hits_along(&self, segment: &Segment) -> Result<Vec<SegmentHit>, Error> {
        let near = self.near_segment(segment);
        let firsts = near
            .par_iter()
            .map(|&o| match self.slot(o).placed() {
                Placed::Mesh(collider, pose) => collider.first_segment_hit_at(pose, segment),
                Placed::Shape(shape) => first_entry(segment, shape),
            })
            .collect::<Result<Vec<_>, Error>>()?;
        let mut out: Vec<SegmentHit> = near
            .into_iter()
            .zip(firsts)
            .filter_map(|(o, first)| {
                first.map(|(triangle, parameter)| {
                    SegmentHit::new(self.id_of(o), triangle, parameter, segment)
                })
            })
            .collect();
        out.sort_by(|x, y| x.parameter.cmp(&y.parameter).then(x.object.cmp(&y.object)));
        Ok(out)
    }

    /// The first object the closed segment meets, going from `segment.a()` to `segment.b()`:
    /// the first of [`segment_hits_along`](Self::segment_hits_along) (least exact parameter,
    /// ties by handle). `None` when the segment meets no object.
    pub fn first_segment_hit(&self, segment: &Segment) -> Result<Option<SegmentHit>, Error> {
        Ok(self.segment_hits_along(segment)?.into_iter().next())
    }

    /// The live slots whose world boxes the segment may meet.
    fn near_segment(&self, segment: &Segment) -> Vec<u32> {
        let (p, q) = (*segment.a(), *segment.b());
        self.ids()
            .into_iter()
            .map(|o| o.index)
            .filter(|&o| self.broad.bounds(o).may_meet_segment(&p, &q))
            .collect()
    }

    /// The tested pairs of slots whose boxes come within `reach`, `a < b`.
    pub(super) fn candidates(&self, reach: f64) -> Vec<(u32, u32)> {
        let mut pairs = self.broad.pairs(reach);
        pairs.retain(|&(a, b)| self.tested(a, b));
        pairs
    }

    fn any_tested_pair(&self) -> Option<(f64, u32, u32)> {
        let ids: Vec<u32> = self.ids().into_iter().map(|o| o.index).collect();
        ids.iter().enumerate().find_map(|(k, &a)| {
            ids[k + 1..]
                .iter()
                .find(|&&b| self.tested(a, b))
                .map(|&b| (0.0, a, b))
        })
    }

    /// The pairs whose answer is `true`, as handles, sorted.
    fn ids_of(
        &self,
        answers: impl Iterator<Item = ((u32, u32), bool)>,
    ) -> Vec<(ObjectId, ObjectId)> {
        let mut out: Vec<(ObjectId, ObjectId)> = answers
            .filter(|&(_, hit)| hit)
            .map(|((a, b), _)| (self.id_of(a), self.id_of(b)))
            .collect();
        out.sort_unstable();
        out
    }

    /// The objects whose answer is `true`, as handles, sorted.
    fn objects_hit(&self, slots: Vec<u32>, hits: Vec<bool>) -> Vec<ObjectId> {
        let mut out: Vec<ObjectId> = slots
            .into_iter()
            .zip(hits)
            .filter(|&(_, hit)| hit)
            .map(|(o, _)| self.id_of(o))
            .collect();
        out.sort_unstable();
        out
    }
}

/// Where the segment first enters the placed solid shape: `(0, t)` with the least exact `t`,
/// `None` when it misses (see [`Scene::segment_hits_along`]).
fn first_entry(segment: &Segment, shape: &Shape) -> Result<Option<(u32, Rational)>, Error> {
    if !query::intersects(&(*segment).into(), shape)? {
        return Ok(None);
    }
    let t = match shape {
        Shape::Triangle(t) => segment_triangle_entry(segment, t),
        Shape::HalfSpace(h) => Some(half_space_entry(segment, h.point(), h.normal())),
        other => {
            return Err(Error::UnsupportedPair {
                query: "segment_hits_along",
                a: "segment",
                b: other.kind(),
            })
        }
    };
    Ok(t.map(|t| (0, t)))
}

/// The least `t ∈ [0, 1]` with `(a + t (b − a) − p)·n <= 0`, for a segment known to meet the
/// half-space: `0` when `a` is in it, else where the segment crosses the plane.
fn half_space_entry(
    segment: &Segment,
    p: &nalgebra::Point3<f64>,
    n: &nalgebra::Vector3<f64>,
) -> Rational {
    let dot = |x: &nalgebra::Point3<f64>| -> Rational {
        (0..3).fold(Rational::default(), |acc, k| {
            &acc + &(&(&exact(x[k]) - &exact(p[k])) * &exact(n[k]))
        })
    };
    let (at_a, at_b) = (dot(segment.a()), dot(segment.b()));
    if at_a <= Rational::default() {
        return Rational::default();
    }
    // at_a > 0 >= at_b: the crossing at_a / (at_a - at_b) lies in (0, 1].
    &at_a / &(&at_a - &at_b)
}

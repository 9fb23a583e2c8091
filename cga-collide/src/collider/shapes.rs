//! A solid primitive ([`Shape`]) against a mesh: which triangles it meets, whether it meets
//! any, whether it comes within a clearance, and the certified distance, through the mesh's
//! box tree (not triangle by triangle); in the mesh's frame, or under poses (`_at`: the mesh
//! at `pose`, the shape placed by `shape_pose` by [`Shape::placed`]).
//!
//! Every answer is the answer of the generic pair query
//! ([`query::intersects`](crate::query::intersects) and the rest) between the shape and each
//! triangle, gathered over the mesh: the tree only sets aside nodes whose boxes are proved to
//! be out of reach of the shape (a box holding the exact shape, rounded outwards; for a
//! half-space, which has no box, a conservatively rounded box-against-half-space test). So
//! a triangle the shape may meet is never skipped, and the answers are those of the brute
//! force over every triangle. The mesh is its surface here, as in every collider query; a
//! shape inside a closed mesh meets no triangle
//! ([`intersects_shape_solid`](Collider::intersects_shape_solid) counts it).
//!
//! Refused: a shape or mesh (placed by its pose) with a coordinate beyond
//! [`MAX_MAGNITUDE`] ([`Error::CoordinateOutOfRange`], [`Error::OutOfRange`]), a clearance
//! that is not a distance ([`Error::InvalidClearance`]), a pose that is not a rigid motion, and
//! a pair the engines do not decide ([`Error::UnsupportedPair`]). A refused triangle does not
//! decide the mesh's answer by itself, so the answer does not depend on the order the
//! triangles are visited in: `intersects_shape` and `shape_within_distance` are `true` when
//! any triangle is proved to meet (to come within reach), `false` when every candidate
//! triangle is proved not to, and refused otherwise; `distance_to_shape` sets a refused
//! triangle aside only when its box is proved farther than the distance found; `shape_hits`
//! is refused when any candidate triangle is (the list would not be known).
//!
//! ```
//! use cga_collide::{nalgebra::{Isometry3, Point3}, shape::Shape, Ball, Collider, TriMesh};
//! let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
//! let ball: Shape = Ball::new(Point3::new(2.0, 0.5, 0.5), 1.0)?.into(); // touches x = 1
//! assert!(cube.intersects_shape(&ball)?);
//! assert!(!cube.shape_hits(&ball)?.is_empty());
//! let moved = Isometry3::translation(0.5, 0.0, 0.0);
//! assert!(!cube.intersects_shape_at(&Isometry3::identity(), &ball, &moved)?);
//! assert!(cube.shape_within_distance_at(&Isometry3::identity(), &ball, &moved, 0.5)?);
//! let d = cube.distance_to_shape_at(&Isometry3::identity(), &ball, &moved)?;
//! assert!((d.distance - 0.5).abs() <= d.error_bound);
//! # Ok::<(), cga_collide::Error>(())
//! ```

use std::cell::Cell;
use std::ops::ControlFlow;

use nalgebra::{Isometry3, Point3};

use crate::bounding::shape_box::Reach;
use crate::bounding::Aabb;
use crate::collider::Bounded;
use crate::collider::{Collider, Mode};
use crate::error::Error;
use crate::query::shapes::check_clearance;
use crate::query::{self, CertifiedDistance};
use crate::shape::{Shape, MAX_MAGNITUDE};
use crate::{Segment, Triangle};

/// The frame the mesh is asked in.
#[derive(Clone, Copy)]
enum Frame<'a> {
    /// Its own coordinates.
    Own,
    /// Placed by a pose.
    Posed(&'a Isometry3<f64>),
}

/// A point of the shape (a shape that does not meet a closed surface lies wholly inside or
/// wholly outside it, as this point does).
fn point_of(shape: &Shape) -> Point3<f64> {
    match shape {
        Shape::Ball(b) => *b.centre(),
        Shape::Cuboid(c) => *c.centre(),
        Shape::Capsule(c) => *c.a(),
        Shape::Cylinder(c) => *c.a(),
        Shape::Cone(c) => *c.apex(),
        Shape::HalfSpace(h) => *h.point(),
        // Hulls hold at least one point.
        Shape::ConvexHull(h) => h.points().first().copied().unwrap_or_else(Point3::origin),
        Shape::Triangle(t) => t.vertices()[0],
        Shape::Segment(s) => *s.a(),
    }
}

/// The error a traversal stopped on, if any.
fn stopped<T>(flow: ControlFlow<Result<T, Error>>) -> Result<Option<T>, Error> {
    match flow {
        ControlFlow::Break(Ok(found)) => Ok(Some(found)),
        ControlFlow::Break(Err(e)) => Err(e),
        ControlFlow::Continue(()) => Ok(None),
    }
}

/// Triangle `t` as the generic queries take it.
fn as_shape(t: &Triangle) -> Shape {
    Shape::Triangle(*t)
}

impl Collider {
    /// Every triangle the closed shape meets, sorted (the shape in the mesh's frame).
    pub fn shape_hits(&self, shape: &Shape) -> Result<Vec<u32>, Error> {
        self.shape_hits_in(Frame::Own, shape)
    }

    /// [`shape_hits`](Self::shape_hits) of this mesh at `pose` and the shape placed by
    /// `shape_pose`: equal to `self.placed(pose)?.shape_hits(&shape.placed(shape_pose)?)`.
    pub fn shape_hits_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        shape_pose: &Isometry3<f64>,
    ) -> Result<Vec<u32>, Error> {
        self.shape_hits_in(Frame::Posed(pose), &shape.placed(shape_pose)?)
    }

    /// Whether the closed shape meets a triangle of the mesh (stops at the first one met).
    pub fn intersects_shape(&self, shape: &Shape) -> Result<bool, Error> {
        self.intersects_shape_in(Frame::Own, shape)
    }

    /// [`intersects_shape`](Self::intersects_shape) under poses (see
    /// [`shape_hits_at`](Self::shape_hits_at)).
    pub fn intersects_shape_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        shape_pose: &Isometry3<f64>,
    ) -> Result<bool, Error> {
        self.intersects_shape_in(Frame::Posed(pose), &shape.placed(shape_pose)?)
    }

    /// Whether the closed shape and the closed solid this mesh bounds share a point: the shape
    /// meets the surface, or lies inside the solid, or the solid lies inside the shape.
    /// Meant for closed meshes (see [`contains_point`](Self::contains_point)).
    pub fn intersects_shape_solid(&self, shape: &Shape) -> Result<bool, Error> {
        self.intersects_shape_solid_in(Frame::Own, shape)
    }

    /// [`intersects_shape_solid`](Self::intersects_shape_solid) under poses (see
    /// [`shape_hits_at`](Self::shape_hits_at)).
    pub fn intersects_shape_solid_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        shape_pose: &Isometry3<f64>,
    ) -> Result<bool, Error> {
        self.intersects_shape_solid_in(Frame::Posed(pose), &shape.placed(shape_pose)?)
    }

    /// Exact: is the shape within distance `c` of the mesh's surface (closed: exactly `c`
    /// counts)? `c` must be a finite number `>= 0` ([`Error::InvalidClearance`]).
    pub fn shape_within_distance(&self, shape: &Shape, c: f64) -> Result<bool, Error> {
        self.shape_within_distance_in(Frame::Own, shape, c)
    }

    /// [`shape_within_distance`](Self::shape_within_distance) under poses (see
    /// [`shape_hits_at`](Self::shape_hits_at)).
    pub fn shape_within_distance_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        shape_pose: &Isometry3<f64>,
        c: f64,
    ) -> Result<bool, Error> {
        self.shape_within_distance_in(Frame::Posed(pose), &shape.placed(shape_pose)?, c)
    }

    /// The minimum distance between the mesh's surface and the shape, certified: the true
    /// distance lies in `[distance - error_bound, distance + error_bound]` over **every**
    /// triangle. `witness_a` is on the mesh, `witness_b` on the shape, and `triangles` is
    /// `Some((i, 0))` with `i` the triangle holding `witness_a` (a shape has no triangles: the
    /// second index is always 0).
    ///
    /// The triangle reported has the least `f64` distance of
    /// [`query::distance`] among the triangles the search examines
    /// (ties to the smaller index), which skips only triangles proved farther than the best so
    /// far; `distance` and the witnesses are that pair's. The error bound covers the pair's own
    /// bound and every other triangle examined (near-ties). A triangle whose pair distance is
    /// refused is skipped only when its box is proved farther than the distance found;
    /// otherwise the answer is that refusal. An empty mesh is [`Error::Empty`].
    pub fn distance_to_shape(&self, shape: &Shape) -> Result<CertifiedDistance, Error> {
        self.distance_to_shape_in(Frame::Own, shape)
    }

    /// [`distance_to_shape`](Self::distance_to_shape) under poses (see
    /// [`shape_hits_at`](Self::shape_hits_at)).
    pub fn distance_to_shape_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        shape_pose: &Isometry3<f64>,
    ) -> Result<CertifiedDistance, Error> {
        self.distance_to_shape_in(Frame::Posed(pose), &shape.placed(shape_pose)?)
    }

    fn shape_hits_in(&self, frame: Frame, shape: &Shape) -> Result<Vec<u32>, Error> {
        let reach = self.check_shape_pair(frame, shape)?;
        let mut out = Vec::new();
        let flow = self.shape_candidates(
            frame,
            |b| reach.within(b, 0.0),
            |i, t| match query::intersects(&as_shape(t), shape) {
                Ok(hit) => {
                    if hit {
                        out.push(i);
                    }
                    ControlFlow::Continue(())
                }
                Err(e) => ControlFlow::Break(Err(e)),
            },
        )?;
        stopped::<()>(flow)?;
        out.sort_unstable();
        Ok(out)
    }

    fn intersects_shape_in(&self, frame: Frame, shape: &Shape) -> Result<bool, Error> {
        let reach = self.check_shape_pair(frame, shape)?;
        self.any_triangle(
            frame,
            |b| reach.within(b, 0.0),
            |t| query::intersects(&as_shape(t), shape),
        )
    }

    /// Whether `pair` holds for a candidate triangle (a triangle whose box passes `keep`):
    /// `true` at the first triangle it is proved for; `false` when it is proved false for
    /// every candidate; otherwise the first refusal ([`Error::UnsupportedPair`]) met, which
    /// does not stop the search, so the answer does not depend on the visiting order. Any
    /// other error stops it.
    fn any_triangle(
        &self,
        frame: Frame,
        keep: impl Fn(&Aabb) -> bool,
        pair: impl Fn(&Triangle) -> Result<bool, Error>,
    ) -> Result<bool, Error> {
        let mut refused = None;
        let flow = self.shape_candidates(frame, keep, |_, t| match pair(t) {
            Ok(false) => ControlFlow::Continue(()),
            Ok(true) => ControlFlow::Break(Ok(())),
            Err(e @ Error::UnsupportedPair { .. }) => {
                refused.get_or_insert(e);
                ControlFlow::Continue(())
            }
            Err(e) => ControlFlow::Break(Err(e)),
        })?;
        match (stopped(flow)?, refused) {
            (Some(()), _) => Ok(true),
            (None, Some(e)) => Err(e),
            (None, None) => Ok(false),
        }
    }

    fn intersects_shape_solid_in(&self, frame: Frame, shape: &Shape) -> Result<bool, Error> {
        if self.intersects_shape_in(frame, shape)? {
            return Ok(true);
        }
        let p = point_of(shape);
        let inside = match frame {
            Frame::Own => self.contains_point(&p),
            Frame::Posed(pose) => self.contains_point_at(pose, &p)?,
        };
        if inside {
            return Ok(true);
        }
        // The first vertex, placed by the expression `placed()` uses.
        let Some(v) = self.mesh().vertices().first() else {
            return Ok(false);
        };
        let v = match frame {
            Frame::Own => *v,
            Frame::Posed(pose) => pose * v,
        };
        query::intersects(&Segment::new(v, v)?.into(), shape)
    }

    fn shape_within_distance_in(&self, frame: Frame, shape: &Shape, c: f64) -> Result<bool, Error> {
        check_clearance(c)?;
        let reach = self.check_shape_pair(frame, shape)?;
        self.any_triangle(
            frame,
            |b| reach.within(b, c),
            |t| query::within_distance(&as_shape(t), shape, c),
        )
    }

    fn distance_to_shape_in(
        &self,
        frame: Frame,
        shape: &Shape,
    ) -> Result<CertifiedDistance, Error> {
        match self.distance_to_shape_below_in(frame, shape, f64::INFINITY)? {
            Bounded::Below(d) => Ok(d),
            // With no cutoff, only a mesh without triangles has none examined.
            Bounded::AtLeast(_) => Err(Error::Empty {
                file: "Collider".to_owned(),
            }),
        }
    }

    /// [`distance_to_shape_at`](Self::distance_to_shape_at) when the mesh at `pose` and the
    /// shape are nearer than `cutoff` (in `f64`), found by a search that sets aside every node
    /// proved farther than `cutoff` from the start; otherwise [`Bounded::AtLeast`] with a proved
    /// lower bound on their distance (at most `cutoff`). `cutoff = +∞` is
    /// `distance_to_shape_at` (an empty mesh: `AtLeast(+∞)`).
    pub(crate) fn distance_to_shape_below_at(
        &self,
        pose: &Isometry3<f64>,
        shape: &Shape,
        cutoff: f64,
    ) -> Result<Bounded, Error> {
        self.distance_to_shape_below_in(Frame::Posed(pose), shape, cutoff)
    }

    fn distance_to_shape_below_in(
        &self,
        frame: Frame,
        shape: &Shape,
        cutoff: f64,
    ) -> Result<Bounded, Error> {
        let reach = self.check_shape_pair(frame, shape)?;
        self.nearest_triangle(frame, &reach, cutoff, |t| {
            query::distance(&as_shape(t), shape)
        })
    }

    /// The search of [`distance_to_shape_below_at`](Self::distance_to_shape_below_at) with
    /// `pair` the certified distance of a triangle to the shape, which reaches `reach`. A
    /// triangle `pair` refuses ([`Error::UnsupportedPair`]) is set aside when its box is
    /// proved farther than the least upper bound found in the end (so it cannot be the
    /// nearest); otherwise the first refusal is the answer. Any other error stops the search.
    fn nearest_triangle(
        &self,
        frame: Frame,
        reach: &Reach,
        cutoff: f64,
        pair: impl Fn(&Triangle) -> Result<CertifiedDistance, Error>,
    ) -> Result<Bounded, Error> {
        let cutoff = cutoff.max(0.0);
        // The least proved upper bound on the distance so far (or the cutoff): nodes farther
        // are set aside.
        let bound = Cell::new(cutoff);
        // The least proved lower bound over the triangles examined.
        let mut lower = f64::INFINITY;
        let mut best: Option<(u32, CertifiedDistance)> = None;
        // The first refusal, and the boxes of the triangles refused.
        let mut refused: Option<(Error, Vec<Aabb>)> = None;
        // Nearest first: the bound falls early, so few triangles are measured.
        let flow = self.shape_candidates_nearest_first(
            frame,
            |b| reach.gap(b),
            || bound.get(),
            |i, t| match pair(t) {
                Ok(d) => {
                    lower = lower.min((d.distance - d.error_bound).next_down().max(0.0));
                    bound.set(bound.get().min((d.distance + d.error_bound).next_up()));
                    if best
                        .as_ref()
                        .is_none_or(|(j, b)| (d.distance, i) < (b.distance, *j))
                    {
                        best = Some((i, d));
                    }
                    ControlFlow::Continue(())
                }
                Err(e @ Error::UnsupportedPair { .. }) => {
                    let b = Aabb::of_points(t.vertices());
                    refused.get_or_insert_with(|| (e, Vec::new())).1.push(b);
                    ControlFlow::Continue(())
                }
                Err(e) => ControlFlow::Break(Err(e)),
            },
        )?;
        stopped::<()>(flow)?;
        // A refused triangle whose box is proved farther than the final bound is farther
        // than a triangle examined (or than the cutoff), as a node set aside is.
        if let Some((e, boxes)) = refused {
            if boxes.iter().any(|b| reach.within(b, bound.get())) {
                return Err(e);
            }
        }
        // A node set aside is farther than the bound at the time: at least the cutoff or the
        // upper end of an examined triangle, itself at least `lower`.
        let (i, d) = match best {
            // (A NaN distance goes on, to be refused below.)
            Some((i, d)) if cutoff.is_infinite() || d.distance < cutoff || d.distance.is_nan() => {
                (i, d)
            }
            _ => return Ok(Bounded::AtLeast(lower.min(cutoff))),
        };
        let error_bound = d.error_bound.max((d.distance - lower).next_up());
        if !(d.distance.is_finite() && error_bound.is_finite()) {
            return Err(Error::OutOfRange {
                magnitude: self.extent(),
                limit: MAX_MAGNITUDE,
            });
        }
        Ok(Bounded::Below(CertifiedDistance {
            error_bound,
            triangles: Some((i, 0)),
            ..d
        }))
    }

    /// Checks the shape's and the mesh's range (in the frame asked) and says where the shape
    /// may reach.
    fn check_shape_pair(&self, frame: Frame, shape: &Shape) -> Result<Reach, Error> {
        shape.check_range()?;
        let magnitude = match frame {
            Frame::Own => self.extent(),
            Frame::Posed(pose) => {
                let b = self.world_box(pose)?;
                b.min
                    .iter()
                    .chain(&b.max)
                    .fold(0.0f64, |m, x| m.max(x.abs()))
            }
        };
        if magnitude > MAX_MAGNITUDE {
            return Err(Error::OutOfRange {
                magnitude,
                limit: MAX_MAGNITUDE,
            });
        }
        Ok(Reach::of(shape))
    }

    /// [`shape_candidates`](Self::shape_candidates) for a nearest-triangle search: nodes and
    /// triangles in increasing order of `gap` (a lower bound on their distance to the shape),
    /// none whose gap exceeds `bound()`, read again before each (the search lowers it).
    fn shape_candidates_nearest_first<B>(
        &self,
        frame: Frame,
        gap: impl Fn(&Aabb) -> f64,
        bound: impl Fn() -> f64,
        mut visit: impl FnMut(u32, &Triangle) -> ControlFlow<B>,
    ) -> Result<ControlFlow<B>, Error> {
        match (frame, self.mode()) {
            (Frame::Own, Mode::Bvh) => Ok(self
                .bvh()
                .for_each_nearest_first(gap, bound, |i| visit(i, &self.triangle(i)))),
            (Frame::Posed(pose), Mode::Bvh) => {
                let world = self.world_boxes(pose)?;
                Ok(self.posed_nearest_first(&world, pose, gap, bound, |p| visit(p.index, &p.tri)))
            }
            // No tree: every triangle, as the depth-first walk takes them.
            (_, Mode::Brute) => self.shape_candidates(frame, |b| gap(b) <= bound(), visit),
        }
    }

    /// Calls `visit` with every triangle (its index and itself, in the frame) whose box passes
    /// `keep`, reached through nodes whose boxes pass `keep`; stops when `visit` breaks.
    fn shape_candidates<B>(
        &self,
        frame: Frame,
        keep: impl Fn(&Aabb) -> bool,
        mut visit: impl FnMut(u32, &Triangle) -> ControlFlow<B>,
    ) -> Result<ControlFlow<B>, Error> {
        match (frame, self.mode()) {
            (Frame::Own, Mode::Bvh) => Ok(self
                .bvh()
                .for_each_candidate(&keep, |i| visit(i, &self.triangle(i)))),
            (Frame::Own, Mode::Brute) => {
                for i in 0..self.mesh().num_triangles() {
                    if keep(&self.tri_box(i)) {
                        let i = i as u32;
                        if let ControlFlow::Break(b) = visit(i, &self.triangle(i)) {
                            return Ok(ControlFlow::Break(b));
                        }
                    }
                }
                Ok(ControlFlow::Continue(()))
            }
            (Frame::Posed(pose), Mode::Bvh) => {
                let world = self.world_boxes(pose)?;
                Ok(self.posed_candidates(&world, pose, keep, |p| visit(p.index, &p.tri)))
            }
            (Frame::Posed(pose), Mode::Brute) => {
                // The pose is checked as the tree path checks it, so both modes refuse alike.
                self.world_boxes(pose)?;
                self.placed(pose)?.shape_candidates(Frame::Own, keep, visit)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Ball, TriMesh};

    /// Two upright triangles in the planes `x = 1` and `x = 10`, in either order.
    fn two_walls(near_first: bool) -> Collider {
        let wall = |x: f64| {
            [
                Point3::new(x, -1.0, -1.0),
                Point3::new(x, 1.0, -1.0),
                Point3::new(x, 0.0, 1.0),
            ]
        };
        let (first, second) = if near_first {
            (wall(1.0), wall(10.0))
        } else {
            (wall(10.0), wall(1.0))
        };
        let vertices = first.into_iter().chain(second).collect();
        Collider::new(TriMesh::new(vertices, vec![[0, 1, 2], [3, 4, 5]]).expect("valid"))
    }

    fn refusal() -> Error {
        Error::UnsupportedPair {
            query: "test",
            a: "triangle",
            b: "ball",
        }
    }

    fn is_near(t: &Triangle) -> bool {
        t.vertices()[0].x < 5.0
    }

    #[test]
    fn a_refused_triangle_does_not_decide_alone_in_either_order() {
        let everything = |_: &Aabb| true;
        for near_first in [true, false] {
            for mode in [Mode::Bvh, Mode::Brute] {
                let mesh = two_walls(near_first).with_mode(mode);
                // One proved, one refused: proved, whichever comes first.
                let near_holds = |t: &Triangle| if is_near(t) { Ok(true) } else { Err(refusal()) };
                assert!(mesh
                    .any_triangle(Frame::Own, everything, near_holds)
                    .unwrap());
                let far_holds = |t: &Triangle| if is_near(t) { Err(refusal()) } else { Ok(true) };
                assert!(mesh
                    .any_triangle(Frame::Own, everything, far_holds)
                    .unwrap());
                // One proved false, one refused: refused.
                let unknown = |t: &Triangle| {
                    if is_near(t) {
                        Ok(false)
                    } else {
                        Err(refusal())
                    }
                };
                assert!(matches!(
                    mesh.any_triangle(Frame::Own, everything, unknown),
                    Err(Error::UnsupportedPair { .. })
                ));
                assert!(!mesh
                    .any_triangle(Frame::Own, everything, |_| Ok(false))
                    .unwrap());
                // Other errors stop the search.
                let broken = |t: &Triangle| {
                    if is_near(t) {
                        Ok(true)
                    } else {
                        Err(Error::InvalidClearance { value: -1.0 })
                    }
                };
                let got = mesh.any_triangle(Frame::Own, everything, broken);
                assert!(matches!(
                    got,
                    Ok(true) | Err(Error::InvalidClearance { .. })
                ));
                if matches!(mode, Mode::Brute) {
                    // Brute force visits the triangles in order.
                    assert_eq!(got.is_ok(), near_first);
                }
            }
        }
    }

    #[test]
    fn a_refused_triangle_proved_farther_than_the_nearest_is_set_aside() {
        let ball: Shape = Ball::new(Point3::origin(), 0.5).expect("valid").into();
        let reach = Reach::of(&ball);
        let exact = |t: &Triangle| query::distance(&as_shape(t), &ball);
        for near_first in [true, false] {
            for mode in [Mode::Bvh, Mode::Brute] {
                let mesh = two_walls(near_first).with_mode(mode);
                let near_index = u32::from(!near_first);
                // The far wall refused: its box is 9.5 away, the near wall 0.5.
                let far_refused = |t: &Triangle| if is_near(t) { exact(t) } else { Err(refusal()) };
                let Bounded::Below(d) = mesh
                    .nearest_triangle(Frame::Own, &reach, f64::INFINITY, far_refused)
                    .unwrap()
                else {
                    panic!("no distance");
                };
                assert_eq!(d.triangles, Some((near_index, 0)));
                assert!((d.distance - 0.5).abs() <= d.error_bound);
                // The near wall refused: the far one cannot stand for it.
                let near_refused =
                    |t: &Triangle| if is_near(t) { Err(refusal()) } else { exact(t) };
                assert!(matches!(
                    mesh.nearest_triangle(Frame::Own, &reach, f64::INFINITY, near_refused),
                    Err(Error::UnsupportedPair { .. })
                ));
                // Both refused but beyond a cutoff: a lower bound, as before.
                let all_refused = |_: &Triangle| Err(refusal());
                assert!(matches!(
                    mesh.nearest_triangle(Frame::Own, &reach, 0.25, all_refused),
                    Ok(Bounded::AtLeast(b)) if b <= 0.5
                ));
            }
        }
    }
}

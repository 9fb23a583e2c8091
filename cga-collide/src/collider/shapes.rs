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
//! a pair the engines do not decide ([`Error::UnsupportedPair`]).
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
    /// bound and every other triangle examined (near-ties). An empty mesh is
    /// [`Error::Empty`].
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
        let flow = self.shape_candidates(
            frame,
            |b| reach.within(b, 0.0),
            |_, t| match query::intersects(&as_shape(t), shape) {
                Ok(false) => ControlFlow::Continue(()),
                Ok(true) => ControlFlow::Break(Ok(())),
                Err(e) => ControlFlow::Break(Err(e)),
            },
        )?;
        Ok(stopped(flow)?.is_some())
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
        let flow = self.shape_candidates(
            frame,
            |b| reach.within(b, c),
            |_, t| match query::within_distance(&as_shape(t), shape, c) {
                Ok(false) => ControlFlow::Continue(()),
                Ok(true) => ControlFlow::Break(Ok(())),
                Err(e) => ControlFlow::Break(Err(e)),
            },
        )?;
        Ok(stopped(flow)?.is_some())
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
        let cutoff = cutoff.max(0.0);
        // The least proved upper bound on the distance so far (or the cutoff): nodes farther
        // are set aside.
        let bound = Cell::new(cutoff);
        // The least proved lower bound over the triangles examined.
        let mut lower = f64::INFINITY;
        let mut best: Option<(u32, CertifiedDistance)> = None;
        // Nearest first: the bound falls early, so few triangles are measured.
        let flow = self.shape_candidates_nearest_first(
            frame,
            |b| reach.gap(b),
            || bound.get(),
            |i, t| match query::distance(&as_shape(t), shape) {
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
                Err(e) => ControlFlow::Break(Err(e)),
            },
        )?;
        stopped::<()>(flow)?;
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

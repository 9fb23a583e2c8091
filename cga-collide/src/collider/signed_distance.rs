//! Points against a mesh: the signed distance of many query points, with a certified error
//! bound, the exact inside/outside, and the nearest point and triangle.
//!
//! # Definitions
//! * **Inside** is [`Collider::contains_point`]'s answer, exact: a point on a triangle is
//!   inside; otherwise the parity of the crossings of a ray (the even–odd rule). For a closed
//!   mesh ([`TriMesh::is_closed`](crate::TriMesh::is_closed)) that is the solid the surface
//!   bounds; for an open or self-intersecting mesh it is the even–odd rule of that one ray
//!   (documented, deterministic, but not a winding number).
//! * **Distance** is the distance from the point to the nearest point of the surface (the union
//!   of the triangles), in `f64` with an `error_bound` proved with exact predicates: the true
//!   distance (of the real numbers the `f64` inputs denote) lies in
//!   `[distance − error_bound, distance + error_bound]`.
//! * **Signed distance** is `−distance` inside and `+distance` outside; a point on the surface
//!   is inside at distance exactly `0` (error bound `0`).
//!
//! # How
//! Per point, a best-first search of the box tree for the nearest triangle (boxes ordered by
//! their distance to the point, `f64` point–triangle distances, every triangle not examined
//! proved farther, with a margin above the rounding); the distance is then certified as the
//! mesh distance is (an exact clearance test of the winner for the upper end, exact tests of
//! the few triangles not proved farther for the lower end).
//!
//! The sign comes from the faces that may hold the nearest point when that is certain: the
//! mesh is closed, consistently oriented and free of self-intersections (checked once, exactly,
//! on the first query, [`SolidSides`]), the distance is certified tightly enough that every
//! triangle outside a small candidate set is proved farther than the nearest point, and the
//! point lies strictly on the outer side of every candidate's plane (then it is outside) or
//! strictly on the inner side of every one (then inside), each an exact `orient3d` sign. Why
//! that is exact: a nearest point `q` lies in a candidate, and so does every triangle through
//! `q` (each is as near); the open segment from `p` to `q` crosses nothing, so `p` is inside
//! exactly when the directions from `q` into the solid hold `p − q`; near `q` the solid is the
//! polyhedral cone of the triangles through `q` (one face, the wedge of an edge, the fan of a
//! vertex), and a direction strictly outside every face plane of such a cone is outside it
//! (walking round from it in any plane through it, the first face met would have to be left
//! against its outward normal), strictly inside every one inside it. This covers points nearest
//! to a face, and to an edge or a vertex whose faces all see them on one side (a convex edge or
//! vertex seen from outside, a reflex one from inside, all but the sharpest). Every other point
//! (mixed sides, a point on a candidate's plane, meshes that fail the check) takes the exact ray
//! test. Both routes give the same answer, exact either way; the first is only faster.
//!
//! Each work item of a batch reuses one set of search buffers for its points (no allocation
//! per point).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use nalgebra::{Isometry3, Point3};

use crate::bounding::{box_distance2, Aabb};
use crate::collider::distance::check_distance_range;
use crate::collider::nearest::{enqueue, queued, unqueued};
use crate::collider::solid_sides::SolidSides;
use crate::collider::Collider;
use crate::error::Error;
use crate::exact::{ExactKernel, Kernel};
use crate::parallel::*;
use crate::query::closest_points::point_triangle;
use crate::query::distance::{certify, scale_of};
use crate::query::separation::{separated_beyond, separation, separation_bound};
use crate::query::within_distance::triangle_point;
use crate::shape::limits::check_point;

/// `2⁻⁵³`, the unit roundoff.
const U: f64 = f64::EPSILON / 2.0;

/// Points per work item of the batches.
const CHUNK: usize = 256;

/// The signed distance of one point to a mesh (defined on [`Collider::signed_distance`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointDistance {
    /// `−distance` inside, `+distance` outside; `0` on the surface (which is inside).
    pub signed_distance: f64,
    /// The true distance lies within this of `|signed_distance|` (proved).
    pub error_bound: f64,
    /// Whether the point lies in the closed solid (exact; [`Collider::contains_point`]).
    pub inside: bool,
    /// The nearest point of the surface (computed in `f64`: on the triangle up to rounding; the
    /// point itself when it lies on the surface).
    pub nearest: Point3<f64>,
    /// The triangle holding `nearest` (among equally near ones found in `f64`, the smallest
    /// index).
    pub triangle: u32,
}

/// The nearest triangle of a point, its certified distance and whether it is the only nearest
/// one.
pub(crate) struct Nearest {
    pub(crate) triangle: u32,
    /// `f64` distance to `triangle`.
    pub(crate) distance: f64,
    pub(crate) error_bound: f64,
    /// The `f64` nearest point of `triangle`.
    pub(crate) witness: [f64; 3],
    /// A triangle the point lies on (exact), if any.
    pub(crate) on_surface: Option<u32>,
    /// Every other triangle is proved farther than `triangle`.
    pub(crate) unique: bool,
}

/// An examined triangle: `(proved lower bound on its distance, triangle, separation)`.
type Examined = (f64, u32, Option<(f64, f64)>);

/// The buffers of one nearest-triangle search, kept between the points of a batch.
#[derive(Default)]
pub(crate) struct Scratch {
    examined: Vec<Examined>,
    open: Vec<(f64, u32)>,
    heap: BinaryHeap<u128>,
    /// After a search: the triangles that may hold the nearest point (every other one is
    /// proved farther), or empty when the search could not prove that.
    candidates: Vec<u32>,
}

impl Collider {
    /// The signed distance of `p` to this mesh: negative inside, `0` on the surface, with its
    /// certified error bound, the exact inside/outside, and the nearest point and triangle.
    /// Inside is [`Collider::contains_point`]'s exact answer (for a closed mesh the solid it
    /// bounds; for an open or self-intersecting one the even–odd rule of one ray); the
    /// distance is to the nearest point of the surface, and the true value lies within
    /// `error_bound` of the one returned.
    ///
    /// Errors: [`Error::NonFiniteCoordinate`] or [`Error::CoordinateOutOfRange`] for a point
    /// that is not finite or beyond `2^500`, [`Error::Empty`] for a mesh without triangles,
    /// [`Error::OutOfRange`] for a mesh too large to certify.
    ///
    /// ```
    /// use cga_collide::{nalgebra::Point3, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let d = cube.signed_distance(&Point3::new(0.5, 0.5, 0.25))?;
    /// assert!(d.inside && (d.signed_distance + 0.25).abs() <= d.error_bound);
    /// let on = cube.signed_distance(&Point3::new(1.0, 0.5, 0.5))?;
    /// assert!(on.inside && on.signed_distance == 0.0 && on.error_bound == 0.0);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn signed_distance(&self, p: &Point3<f64>) -> Result<PointDistance, Error> {
        self.check_points(std::slice::from_ref(p))?;
        Ok(self.point_distance(p, &mut Scratch::default()))
    }

    /// [`signed_distance`](Self::signed_distance) of every point, spread over the cores (in the
    /// order of `points`). A bad point fails the whole batch with
    /// [`Error::InShapePoint`] naming its index.
    pub fn signed_distances(&self, points: &[Point3<f64>]) -> Result<Vec<PointDistance>, Error> {
        self.check_points(points)?;
        let _ = self.sides();
        let _ = self.pose_tree();
        Ok(points
            .par_chunks(CHUNK)
            .flat_map_iter(|chunk| {
                let mut scratch = Scratch::default();
                chunk
                    .iter()
                    .map(move |p| self.point_distance(p, &mut scratch))
            })
            .collect())
    }

    /// [`signed_distances`](Self::signed_distances) of world points against this mesh placed at
    /// `pose`: the mesh is placed first ([`placed`](Self::placed), work proportional to its
    /// size once per call, not per point), so the answers are exactly those of the placed mesh;
    /// nearest points are in world coordinates.
    pub fn signed_distances_at(
        &self,
        pose: &Isometry3<f64>,
        points: &[Point3<f64>],
    ) -> Result<Vec<PointDistance>, Error> {
        self.world_boxes(pose)?; // checks the pose: finite, a rotation, within range
        self.placed(pose)?.signed_distances(points)
    }

    /// Rejects non-finite or too large points (naming the first bad one) and meshes that
    /// cannot be certified.
    fn check_points(&self, points: &[Point3<f64>]) -> Result<(), Error> {
        if self.mesh().num_triangles() == 0 {
            return Err(Error::Empty {
                file: "Collider".to_owned(),
            });
        }
        check_distance_range(self.extent())?;
        for (index, p) in points.iter().enumerate() {
            check_point("point", "points", p).map_err(|source| Error::InShapePoint {
                index,
                source: Box::new(source),
            })?;
        }
        Ok(())
    }

    /// Which side of each triangle is outside (found on the first call).
    pub(crate) fn sides(&self) -> &SolidSides {
        self.sides.get_or_init(|| SolidSides::find(self))
    }

    /// The answer for one checked point.
    fn point_distance(&self, point: &Point3<f64>, scratch: &mut Scratch) -> PointDistance {
        let p = [point.x, point.y, point.z];
        // A checked point and a non-empty mesh always give an answer; the fallback is for
        // completeness only (the exact ray test and no distance).
        let Some(near) = self.nearest_certified(&p, scratch) else {
            return PointDistance {
                signed_distance: f64::NAN,
                error_bound: f64::INFINITY,
                inside: self.contains_point(point),
                nearest: *point,
                triangle: 0,
            };
        };
        if let Some(triangle) = near.on_surface {
            return PointDistance {
                signed_distance: 0.0,
                error_bound: 0.0,
                inside: true,
                nearest: *point,
                triangle,
            };
        }
        let inside = self
            .side_from_candidates(&scratch.candidates, &p)
            .unwrap_or_else(|| self.contains_point(point));
        PointDistance {
            signed_distance: if inside {
                -near.distance
            } else {
                near.distance
            },
            error_bound: near.error_bound,
            inside,
            nearest: Point3::from(near.witness),
            triangle: near.triangle,
        }
    }

    /// Inside (`true`) or outside from the faces that may hold the nearest point, when they all
    /// agree (see the module docs); `None` when they do not, when one's side is unknown or the
    /// point is on one's plane, or when there are none.
    fn side_from_candidates(&self, candidates: &[u32], p: &[f64; 3]) -> Option<bool> {
        let sides = self.sides();
        let mut answer = None;
        for &t in candidates {
            let outward = sides.of(t);
            if outward == 0 {
                return None;
            }
            let [a, b, c] = self.corners(t);
            let inside = match ExactKernel::orient3d(&a, &b, &c, p) {
                Ordering::Greater => outward < 0,
                Ordering::Less => outward > 0,
                Ordering::Equal => return None,
            };
            if answer.is_some_and(|x| x != inside) {
                return None;
            }
            answer = Some(inside);
        }
        answer
    }

    /// The nearest triangle of `p` (finite, within range), certified; `None` for an empty mesh.
    /// `scratch` holds the search's buffers and, after it, the candidate triangles.
    pub(crate) fn nearest_certified(&self, p: &[f64; 3], scratch: &mut Scratch) -> Option<Nearest> {
        scratch.candidates.clear();
        if self.mesh().num_triangles() == 0 {
            return None;
        }
        let scale = p.iter().fold(self.extent(), |m, x| m.max(x.abs()));
        // Every triangle not examined is proved farther than the best distance plus this
        // margin, four times the first error bound tried (see below).
        let margin = |d: f64| 16384.0 * U * (scale + d);
        let limit_of = |d2: f64| {
            let r = d2.sqrt() + margin(d2.sqrt());
            r * r * (1.0 + 1e-9)
        };
        let nodes = self.bvh().nodes();
        let tree = self.pose_tree();
        let at = Aabb { min: *p, max: *p };
        let Scratch {
            examined,
            open,
            heap,
            candidates,
        } = scratch;
        examined.clear();
        open.clear();
        heap.clear();
        let mut best = (f64::INFINITY, u32::MAX, [0.0; 3]);
        let mut limit = f64::INFINITY;
        let mut next = Some(queued(box_distance2(&at, &nodes[0].bounds), 0, 0));
        while let Some((lower, i, _)) = next.take().map(unqueued) {
            if lower > limit {
                break; // best first: everything left is farther
            }
            let node = &nodes[i as usize];
            let s = node.start as usize;
            if node.is_leaf() {
                for k in s..s + node.count as usize {
                    let q = tree.vertices(k).map(|v| [v.x, v.y, v.z]);
                    if box_distance2(&at, &corners_box(&q)) > limit {
                        continue;
                    }
                    let t = tree.index(k);
                    let w = point_triangle(&q, p);
                    let d2 = dist2(&w, p);
                    let sep = separation(&[w[0] - p[0], w[1] - p[1], w[2] - p[2]], &[*p; 3], &q);
                    examined.push((sep.map_or(0.0, separation_bound), t, sep));
                    if d2 < best.0 || (d2 == best.0 && t < best.1) {
                        best = (d2, t, w);
                        limit = limit_of(d2);
                    }
                }
                next = heap.pop();
                continue;
            }
            for child in [node.start, node.start + 1] {
                let d = box_distance2(&at, &nodes[child as usize].bounds);
                if d <= limit {
                    enqueue(&mut next, heap, queued(d, child, 0));
                }
            }
            if next.is_none() {
                next = heap.pop();
            }
        }
        let (best2, triangle, witness) = best;
        let distance = best2.sqrt();
        // Certification first with every examined triangle not proved farther than the best
        // `f64` distance (every other triangle is).
        open.extend(
            examined
                .iter()
                .filter(|&&(_, _, sep)| !sep.is_some_and(|s| separated_beyond(s, best2)))
                .map(|&(lb, x, _)| (lb, x)),
        );
        let t = self.corners(triangle);
        let within = |x: u32, c: f64| triangle_point(&self.corners(x), p, &[c, 0.0, 0.0]);
        // The first bound tried is `4096u` times the scale (about `1e-12` relative), not the
        // `32u` of mesh distances: the exact tests then decide in `f64` (their filters) instead
        // of in exact arithmetic, which per point would cost far more than the search.
        let error_bound = certify(
            distance,
            128.0 * scale_of(&[p, &t[0], &t[1], &t[2]]),
            || triangle_point(&t, p, &[0.0; 3]),
            |c| triangle_point(&t, p, &[c, 0.0, 0.0]),
            |c| open.iter().any(|&(lb, x)| lb <= c && within(x, c)),
        );
        let on_surface = if error_bound >= distance {
            open.iter()
                .find(|&&(lb, x)| lb <= 0.0 && within(x, 0.0))
                .map(|&(_, x)| x)
        } else {
            None
        };
        // The triangles not examined are farther than `distance + margin`, above the certified
        // upper end when the bound is small enough; of the examined ones, those not proved
        // beyond that end are the candidates. Unique: the winner is the only one.
        let upper = (distance + error_bound) * (1.0 + 4.0 * U);
        if on_surface.is_none() && error_bound <= 0.5 * margin(distance) {
            candidates.extend(
                examined
                    .iter()
                    .filter(|&&(lb, x, _)| x == triangle || lb <= upper)
                    .map(|&(_, x, _)| x),
            );
        }
        let unique = candidates.len() == 1;
        Some(Nearest {
            triangle,
            distance,
            error_bound,
            witness,
            on_surface,
            unique,
        })
    }
}

/// The box of a triangle's corners (exact `min`/`max`).
#[inline]
fn corners_box(t: &[[f64; 3]; 3]) -> Aabb {
    Aabb {
        min: std::array::from_fn(|k| t[0][k].min(t[1][k]).min(t[2][k])),
        max: std::array::from_fn(|k| t[0][k].max(t[1][k]).max(t[2][k])),
    }
}

#[inline]
fn dist2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TriMesh;

    fn unit_cube() -> Collider {
        Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap())
    }

    /// The faces that may hold the nearest point of `p`, and the sign they give.
    fn sign(c: &Collider, p: [f64; 3]) -> (usize, Option<bool>) {
        let mut scratch = Scratch::default();
        c.nearest_certified(&p, &mut scratch).unwrap();
        let n = scratch.candidates.len();
        (n, c.side_from_candidates(&scratch.candidates, &p))
    }

    #[test]
    fn points_nearest_to_edges_and_vertices_take_their_sign_from_the_faces() {
        let c = unit_cube();
        // Outside, nearest to an edge (two faces) and to a vertex (its fan): all see it outside.
        let (n, s) = sign(&c, [1.5, 1.5, 0.5]);
        assert!(n >= 2 && s == Some(false), "{n} {s:?}");
        let (n, s) = sign(&c, [1.5, -0.25, 1.75]);
        assert!(n >= 2 && s == Some(false), "{n} {s:?}");
        let (n, s) = sign(&c, [-0.5, -0.5, -0.5]);
        assert!(n >= 3 && s == Some(false), "{n} {s:?}");
        // Inside, as near to two faces as to each other: both see it inside.
        let (n, s) = sign(&c, [0.75, 0.75, 0.5]);
        assert!(n >= 2 && s == Some(true), "{n} {s:?}");
        // Nearest to one face.
        assert_eq!(sign(&c, [0.5, 0.25, 1.125]), (1, Some(false)));
        for p in [[1.5, 1.5, 0.5], [-0.5, -0.5, -0.5], [0.75, 0.75, 0.5]] {
            let r = c.signed_distance(&Point3::from(p)).unwrap();
            assert_eq!(r.inside, c.contains_point(&Point3::from(p)));
        }
    }

    #[test]
    fn a_point_on_a_candidate_plane_or_on_an_open_mesh_has_no_fast_sign() {
        let c = unit_cube();
        // On the plane of the face x = 1, beyond the edge: the exact ray test decides.
        assert_eq!(sign(&c, [1.0, 1.5, 0.5]).1, None);
        let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap();
        let mut tris = cube.triangles().to_vec();
        tris.pop();
        let open = Collider::new(TriMesh::new(cube.vertices().to_vec(), tris).unwrap());
        assert_eq!(sign(&open, [0.5, 0.5, 1.5]).1, None);
    }
}

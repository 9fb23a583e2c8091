//! Solids: whether a point lies in the closed solid a mesh bounds, and whether two solids share a
//! point (one may lie wholly inside the other).

use std::ops::ControlFlow;

use nalgebra::Point3;

use crate::bounding::Aabb;
use crate::collider::{widen, Collider, Mode};
use crate::parallel::*;
use crate::query::ray_crosses_triangle;
use crate::{Intersects, Segment};

impl Collider {
    /// Whether `p` lies in the closed solid bounded by this mesh: on a triangle, or inside by
    /// the parity of the crossings of a ray from `p` along `+x`. Exact: the ray is perturbed
    /// symbolically (simulation of simplicity in the `(y, z)` projection), so rays through
    /// edges and vertices are counted consistently, and every sign is an exact predicate.
    ///
    /// The answer is the solid's for a closed mesh (every edge used by an even number of
    /// triangles, see [`TriMesh::is_closed`](crate::TriMesh::is_closed)); for other meshes it is the even–odd rule of
    /// that one ray. A point with a non-finite coordinate lies in no solid: `false`.
    pub fn contains_point(&self, p: &Point3<f64>) -> bool {
        let Ok(point) = Segment::new(*p, *p) else {
            return false;
        };
        let on_ray = |b: &Aabb| b.meets_x_ray(p);
        // (on the surface, crossings)
        let visit = |i: u32| -> (bool, bool) {
            let tri = self.mesh.corners(i);
            let t = self.triangle(i);
            if t.intersects(&point) {
                (true, false)
            } else {
                (false, ray_crosses_triangle(&tri, p))
            }
        };
        match self.mode {
            Mode::Brute => {
                let boxes32 = self.boxes32();
                let (on, crossings) = (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .filter(|&i| on_ray(&widen(&boxes32[i])))
                    .map(|i| {
                        let (on, c) = visit(i as u32);
                        (on, usize::from(c))
                    })
                    .collect::<Vec<_>>()
                    .into_iter()
                    .fold((false, 0), |x, y| (x.0 || y.0, x.1 + y.1));
                on || crossings % 2 == 1
            }
            Mode::Bvh => {
                let mut crossings = 0usize;
                let on = self
                    .bvh()
                    .for_each_candidate(on_ray, |i| {
                        let (on, c) = visit(i);
                        if on {
                            return ControlFlow::Break(());
                        }
                        crossings += usize::from(c);
                        ControlFlow::Continue(())
                    })
                    .is_break();
                on || crossings % 2 == 1
            }
        }
    }

    /// Whether the closed solids bounded by the two closed meshes share a point: their surfaces
    /// intersect, or one lies wholly inside the other (which [`collides`](Self::collides),
    /// a surface test, does not report). Exact.
    pub fn collides_solid(&self, other: &Collider) -> bool {
        self.collides(other)
            || self
                .mesh
                .vertices()
                .first()
                .is_some_and(|v| other.contains_point(v))
            || other
                .mesh
                .vertices()
                .first()
                .is_some_and(|v| self.contains_point(v))
    }
}

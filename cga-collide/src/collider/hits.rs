//! Which triangles of a mesh a segment, triangle, sphere surface, ball or set of spheres meets,
//! in the mesh's own frame (the same questions under a pose are in `poses`).

use std::ops::ControlFlow;

use crate::bounding::Aabb;
use crate::collider::{ball_box, overlap32, query_box32, widen, Collider, Mode, CHUNK};
use crate::parallel::*;
use crate::{Ball, Intersects, Segment, Sphere, Triangle};

impl Collider {
    /// Sorted indices of the triangles for which `hit` holds, among those whose box passes
    /// `test` (brute: all triangles, in parallel; bvh: candidates of the hierarchy).
    /// `query` is a box holding the query shape up to `f64` rounding (used, widened to `f32`,
    /// as the first filter of the brute-force scan).
    fn hits(
        &self,
        query: &Aabb,
        test: impl Fn(&Aabb) -> bool + Sync,
        hit: impl Fn(&Triangle) -> bool + Sync,
    ) -> Vec<u32> {
        match self.mode {
            Mode::Brute => {
                let q = query_box32(query);
                let chunks: Vec<Vec<u32>> = self
                    .boxes32()
                    .par_chunks(CHUNK)
                    .enumerate()
                    .map(|(c, boxes)| {
                        let mut out = Vec::new();
                        for (k, b) in boxes.iter().enumerate() {
                            if overlap32(b, &q) {
                                let i = (c * CHUNK + k) as u32;
                                if test(&widen(b)) && hit(&self.triangle(i)) {
                                    out.push(i);
                                }
                            }
                        }
                        out
                    })
                    .collect();
                chunks.concat()
            }
            Mode::Bvh => {
                let mut out = Vec::new();
                let _ = self.bvh().for_each_candidate::<()>(&test, |t| {
                    if hit(&self.triangle(t)) {
                        out.push(t);
                    }
                    ControlFlow::Continue(())
                });
                out.sort_unstable();
                out
            }
        }
    }

    /// Sorted indices of the triangles the closed segment meets.
    pub fn segment_hits(&self, s: &Segment) -> Vec<u32> {
        let (p, q) = (*s.a(), *s.b());
        let query = Aabb::of_points(&[p, q]);
        self.hits(&query, |b| b.may_meet_segment(&p, &q), |t| t.intersects(s))
    }

    /// Sorted indices of the triangles the closed triangle meets.
    pub fn triangle_hits(&self, t: &Triangle) -> Vec<u32> {
        let tb = Aabb::of_points(t.vertices());
        self.hits(&tb, |b| b.overlaps(&tb), |u| u.intersects(t))
    }

    /// Sorted indices of the triangles the sphere *surface* meets.
    pub fn sphere_hits(&self, s: &Sphere) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(
            &ball_box(&c, r),
            |b| b.may_meet_sphere(&c, r),
            |t| t.intersects(s),
        )
    }

    /// Sorted indices of the triangles the solid ball meets.
    pub fn ball_hits(&self, s: &Ball) -> Vec<u32> {
        let (c, r) = (*s.centre(), s.radius());
        self.hits(
            &ball_box(&c, r),
            |b| b.may_meet_ball(&c, r),
            |t| t.intersects(s),
        )
    }

    /// Sorted indices of the triangles met by at least one of the sphere surfaces.
    pub fn spheres_hits(&self, spheres: &[Sphere]) -> Vec<u32> {
        let mut out: Vec<u32> = match self.mode {
            Mode::Brute => {
                let qs: Vec<[f32; 6]> = spheres
                    .iter()
                    .map(|s| query_box32(&ball_box(s.centre(), s.radius())))
                    .collect();
                let boxes32 = self.boxes32();
                (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .filter(|&i| {
                        let b32 = &boxes32[i];
                        spheres.iter().zip(&qs).any(|(s, q)| {
                            overlap32(b32, q)
                                && widen(b32).may_meet_sphere(s.centre(), s.radius())
                                && self.triangle(i as u32).intersects(s)
                        })
                    })
                    .map(|i| i as u32)
                    .collect()
            }
            Mode::Bvh => spheres
                .par_iter()
                .flat_map_iter(|s| self.sphere_hits(s))
                .collect(),
        };
        out.sort_unstable();
        out.dedup();
        out
    }
}

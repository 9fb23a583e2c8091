//! Mesh against mesh in one frame: every intersecting triangle pair, and whether any exists.

use std::ops::ControlFlow;

use crate::collider::{Collider, Mode};
use crate::parallel::*;
use crate::Intersects;

impl Collider {
    /// Every pair `(i, j)` of a triangle `i` of `self` and `j` of `other` that intersect
    /// (closed triangles, exact), sorted.
    pub fn intersecting_pairs(&self, other: &Collider) -> Vec<(u32, u32)> {
        let mut out = match self.mode {
            Mode::Brute => {
                let other_boxes = other.triangle_boxes();
                (0..self.mesh.num_triangles())
                    .into_par_iter()
                    .flat_map_iter(|i| {
                        let bi = self.tri_box(i);
                        let ti = self.triangle(i as u32);
                        let other_boxes = &other_boxes;
                        (0..other.mesh.num_triangles()).filter_map(move |j| {
                            (bi.overlaps(&other_boxes[j])
                                && ti.intersects(&other.triangle(j as u32)))
                            .then_some((i as u32, j as u32))
                        })
                    })
                    .collect()
            }
            Mode::Bvh => {
                let mut out = Vec::new();
                let _ = self.bvh().for_each_pair::<()>(other.bvh(), |i, j| {
                    if self.triangle(i).intersects(&other.triangle(j)) {
                        out.push((i, j));
                    }
                    ControlFlow::Continue(())
                });
                out
            }
        };
        out.sort_unstable();
        out
    }

    /// Whether any triangle of `self` meets any triangle of `other` (stops at the first hit).
    pub fn collides(&self, other: &Collider) -> bool {
        match self.mode {
            Mode::Brute => {
                let other_boxes = other.triangle_boxes();
                (0..self.mesh.num_triangles()).into_par_iter().any(|i| {
                    let bi = self.tri_box(i);
                    let ti = self.triangle(i as u32);
                    (0..other.mesh.num_triangles()).any(|j| {
                        bi.overlaps(&other_boxes[j]) && ti.intersects(&other.triangle(j as u32))
                    })
                })
            }
            Mode::Bvh => self
                .bvh()
                .for_each_pair(other.bvh(), |i, j| {
                    if self.triangle(i).intersects(&other.triangle(j)) {
                        ControlFlow::Break(())
                    } else {
                        ControlFlow::Continue(())
                    }
                })
                .is_break(),
        }
    }

    /// Pairs of triangles whose boxes overlap, by brute force (the ground truth the hierarchy's
    /// enumeration is tested against), sorted.
    #[cfg(any(test, feature = "testing"))]
    pub fn box_pairs_brute(&self, other: &Collider) -> Vec<(u32, u32)> {
        let other_boxes = other.triangle_boxes();
        (0..self.mesh.num_triangles())
            .into_par_iter()
            .flat_map_iter(|i| {
                let bi = self.tri_box(i);
                let other_boxes = &other_boxes;
                (0..other_boxes.len())
                    .filter(move |&j| bi.overlaps(&other_boxes[j]))
                    .map(move |j| (i as u32, j as u32))
            })
            .collect()
    }

    /// Pairs of triangles whose boxes overlap, enumerated by the hierarchies, sorted.
    #[cfg(any(test, feature = "testing"))]
    pub fn box_pairs_bvh(&self, other: &Collider) -> Vec<(u32, u32)> {
        let mut out = Vec::new();
        let _ = self.bvh().for_each_pair::<()>(other.bvh(), |i, j| {
            out.push((i, j));
            ControlFlow::Continue(())
        });
        out.sort_unstable();
        out
    }
}

//! The hierarchy of a [`Collider`](crate::collider::Collider) laid out for queries under poses:
//! each node as a centre and half-extent (what a box test under a rotation reads) with its
//! size, one 64-byte cache line per node, and the triangles' vertices copied in leaf order, so
//! that placing the triangles of a leaf reads one contiguous block instead of an index and
//! three scattered vertices per triangle.
//!
//! Each node also has an oriented box fitted to its vertices ([`OrientedBoxes`]), fitted on the
//! first distance search and read only by the distance searches.
//!
//! Built once per collider, on its first pose or distance query (about 30 bytes a triangle for
//! the nodes, 72 for the vertices, and 64 for the oriented boxes once fitted), so colliders that
//! never ask such questions never pay for it; the pose queries (`collider/poses.rs`,
//! crate-private; its docs are in the source) read nothing else of the mesh.
//!
//! # Conservativeness
//! A node's real box `[c - e, c + e]` (per coordinate) contains the exact box `[min, max]` of
//! the [`Bvh`] node it stands for: `c` is `fl((min + max) / 2)`, which lies in `[min, max]`
//! (rounding is monotone and `2 min`, `2 max` are floats), and `e` is
//! `fl(fl(max(fl(max - c), fl(c - min))) (1 + 8u)) + 2⁻¹⁰⁰⁰` with `u = 2⁻⁵³`, which exceeds the
//! real `max - c` and `c - min` (each subtraction errs by at most a factor `1 + u`, the product
//! by `1 - u`, and an underflow by less than `2⁻¹⁰⁰⁰`). So `|c| ≤ ρ` and `e ≤ 2ρ(1 + 10u) +
//! 2⁻¹⁰⁰⁰` when every vertex coordinate is at most `ρ` in magnitude.
//!

use std::sync::OnceLock;

use nalgebra::Point3;

use crate::bounding::oriented_boxes::{centre_half, fit, OrientedBoxes};
use crate::bounding::{Aabb, Bvh};

/// A node of the hierarchy for queries under poses.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct PoseNode {
    /// Centre of a box containing the node's box.
    pub c: [f64; 3],
    /// Half-extents of that box (`[c - e, c + e]` contains the node's box, see the module docs).
    pub e: [f64; 3],
    /// Half the surface area of the node's box (which node of a pair to descend).
    pub size: f64,
    /// Leaf: first position in the leaf order; inner: index of the left child (the right one
    /// follows it).
    pub start: u32,
    /// Leaf: number of triangles; inner: 0.
    pub count: u32,
}

impl PoseNode {
    /// Whether the node is a leaf.
    #[inline(always)]
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// Centre and half-extents of a box holding `b` (module docs).
fn centre_extent(b: &Aabb) -> ([f64; 3], [f64; 3]) {
    let mut c = [0.0; 3];
    let mut e = [0.0; 3];
    for k in 0..3 {
        (c[k], e[k]) = centre_half(b.min[k], b.max[k]);
    }
    (c, e)
}

/// The layout of one collider's hierarchy for pose queries.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PoseTree {
    nodes: Vec<PoseNode>,
    /// Triangle indices in leaf order (as [`Bvh::order`]).
    order: Vec<u32>,
    /// The vertices of the triangles, in leaf order.
    vertices: Vec<[Point3<f64>; 3]>,
    /// Bound on every vertex coordinate.
    rho: f64,
    /// The nodes' oriented boxes, fitted on the first distance search.
    oriented: OnceLock<OrientedBoxes>,
}

impl PoseTree {
    /// The layout of `bvh`, built over the triangles `triangle(i)`, whose coordinates are at
    /// most `rho` in magnitude.
    pub fn new(bvh: &Bvh, triangle: impl Fn(usize) -> [Point3<f64>; 3], rho: f64) -> PoseTree {
        let nodes: Vec<PoseNode> = bvh
            .nodes()
            .iter()
            .map(|n| {
                let (c, e) = centre_extent(&n.bounds);
                PoseNode {
                    c,
                    e,
                    size: n.bounds.half_area(),
                    start: n.start,
                    count: n.count,
                }
            })
            .collect();
        let order = bvh.order().to_vec();
        let vertices = order.iter().map(|&t| triangle(t as usize)).collect();
        PoseTree {
            nodes,
            order,
            vertices,
            rho,
            oriented: OnceLock::new(),
        }
    }

    /// The nodes' oriented boxes (indexed like [`nodes`](Self::nodes)), fitted on first use
    /// (about half the time of building the hierarchy; only the distance searches need them).
    pub fn oriented(&self) -> &OrientedBoxes {
        self.oriented.get_or_init(|| {
            let shape: Vec<(u32, u32)> = self.nodes.iter().map(|n| (n.start, n.count)).collect();
            fit(
                &shape,
                |i| (self.nodes[i].c, self.nodes[i].e),
                &self.vertices,
                self.rho,
            )
        })
    }

    /// The nodes (root first).
    #[inline(always)]
    pub fn nodes(&self) -> &[PoseNode] {
        &self.nodes
    }

    /// The mesh index of the triangle at leaf position `k`.
    #[inline(always)]
    pub fn index(&self, k: usize) -> u32 {
        self.order[k]
    }

    /// The vertices of the triangle at leaf position `k`.
    #[inline(always)]
    pub fn vertices(&self, k: usize) -> &[Point3<f64>; 3] {
        &self.vertices[k]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use proptest::prelude::*;

    fn exact(x: f64) -> BigRational {
        BigRational::from_float(x).expect("finite")
    }

    proptest! {
        /// `[c - e, c + e]` holds `[min, max]` in exact arithmetic, at every scale.
        #[test]
        fn centre_extent_holds_the_box(
            a in -1.0f64..1.0, b in -1.0f64..1.0, ea in -330i32..300, eb in -330i32..300,
        ) {
            let (x, y) = (a * 10f64.powi(ea), b * 10f64.powi(eb));
            let bx = Aabb { min: [x.min(y); 3], max: [x.max(y); 3] };
            let (c, e) = centre_extent(&bx);
            for k in 0..3 {
                prop_assert!(exact(c[k]) - exact(e[k]) <= exact(bx.min[k]));
                prop_assert!(exact(c[k]) + exact(e[k]) >= exact(bx.max[k]));
                prop_assert!(c[k].abs() <= x.abs().max(y.abs()));
            }
        }
    }

    #[test]
    fn node_is_one_cache_line() {
        assert_eq!(std::mem::size_of::<PoseNode>(), 64);
    }
}

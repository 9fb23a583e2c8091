//! A node of the flat node array of a [`Bvh`](crate::bounding::Bvh), and the leaf size every
//! build keeps to.

use crate::bounding::aabb::Aabb;

/// Largest number of triangles in a leaf.
pub const MAX_LEAF: usize = 4;

/// A node: its box, and either a leaf range of [`Bvh::order`](crate::bounding::Bvh::order) (`count > 0`) or the index of
/// its left child (the right one follows it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BvhNode {
    /// Box of everything below.
    pub bounds: Aabb,
    /// Leaf: first position in the triangle order; inner: index of the left child.
    pub start: u32,
    /// Leaf: number of triangles; inner: 0.
    pub count: u32,
}

impl BvhNode {
    /// Whether the node is a leaf.
    #[inline]
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// A node before its range and box are known.
pub(super) const BLANK: BvhNode = BvhNode {
    bounds: Aabb::EMPTY,
    start: 0,
    count: 0,
};

//! Exact overlap of a triangle and a closed axis-aligned box (the octree cell test).
//!
//! Separating-axis theorem for two convex polytopes: the closed triangle and the closed box are
//! disjoint exactly when one of 13 directions separates them strictly: the 3 box axes, the
//! triangle's normal and the 9 cross products `e_i × edge`. (For a degenerate triangle, a
//! segment or a point, the zero directions drop out and the others still suffice: the faces of
//! the Minkowski difference of a box and a segment have normals among the box axes and the
//! `e_i × edge`.) Every comparison is an exact sign:
//! * box axes: comparisons of `f64` coordinates;
//! * the normal: the corners' [`orient3d`](crate::exact::predicates::Orient3d) signs (the crate's
//!   exact plane filter);
//! * `e_i × (b - a)`: the sign of the 2×2 determinant `(b - a)_j (p - q)_k - (b - a)_k (p - q)_j`
//!   for a vertex `p` and a box corner `q` (the [`EdgeAxis`] polynomial through the crate's
//!   certified filter with exact fall-back).
//!
//! Touching counts as overlap (a triangle in a face of the cell meets the cell).
//!
//! ```
//! use cga_collide::testing::sphere_tree::triangle_meets_box;
//! let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
//! assert!(triangle_meets_box(&t, &[0.5, 0.5, -1.0], &[1.0, 1.0, 1.0]));
//! assert!(triangle_meets_box(&t, &[1.0, 1.0, 0.0], &[2.0, 2.0, 1.0])); // touches at (1, 1, 0)
//! assert!(!triangle_meets_box(&t, &[1.0, 1.0 + 1e-15, 0.0], &[2.0, 2.0, 1.0]));
//! ```

use std::cmp::Ordering;

use crate::exact::predicates::EdgeAxis;
use crate::exact::{ExactKernel, Kernel, PlaneSide};

/// Whether the closed triangle `t` meets the closed box `[lo, hi]`, exactly.
pub fn triangle_meets_box(t: &[[f64; 3]; 3], lo: &[f64; 3], hi: &[f64; 3]) -> bool {
    // 1. Box axes.
    for i in 0..3 {
        let min = t[0][i].min(t[1][i]).min(t[2][i]);
        let max = t[0][i].max(t[1][i]).max(t[2][i]);
        if max < lo[i] || min > hi[i] {
            return false;
        }
    }
    // 2. The triangle's plane: all eight corners strictly on one side.
    let plane = ExactKernel::plane(t);
    if !plane.is_degenerate() {
        let mut first = Ordering::Equal;
        let mut separated = true;
        for c in 0..8 {
            let q = [
                if c & 1 == 0 { lo[0] } else { hi[0] },
                if c & 2 == 0 { lo[1] } else { hi[1] },
                if c & 4 == 0 { lo[2] } else { hi[2] },
            ];
            let s = plane.side(&q);
            if s == Ordering::Equal || (c > 0 && s != first) {
                separated = false;
                break;
            }
            first = s;
        }
        if separated {
            return false;
        }
    }
    // 3. Edge × box axis.
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let corners = [
            [lo[j], lo[k]],
            [hi[j], lo[k]],
            [lo[j], hi[k]],
            [hi[j], hi[k]],
        ];
        for m in 0..3 {
            let (a, b, other) = (&t[m], &t[(m + 1) % 3], &t[(m + 2) % 3]);
            if a[j] == b[j] && a[k] == b[k] {
                continue; // the axis is zero
            }
            // The projections of `a` and `b` on the axis coincide, so `a` and `other` stand
            // for the triangle.
            let sign = |p: &[f64; 3], q: &[f64; 2]| {
                ExactKernel::sign::<EdgeAxis, 8>(&[a[j], a[k], b[j], b[k], p[j], p[k], q[0], q[1]])
            };
            let first = sign(a, &corners[0]);
            if first == Ordering::Equal {
                continue;
            }
            let separated = [a, other]
                .into_iter()
                .all(|p| corners.iter().all(|q| sign(p, q) == first));
            if separated {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounding::Aabb;
    use crate::{Intersects, Segment, TriMesh, Triangle};
    use nalgebra::Point3;
    use proptest::prelude::*;

    /// Reference: the triangle meets the box iff it meets one of the box's 12 triangles (its
    /// surface) or a vertex of the triangle lies in the box (containment), using the crate's
    /// exact triangle–triangle and segment tests.
    fn reference(t: &[[f64; 3]; 3], lo: &[f64; 3], hi: &[f64; 3]) -> bool {
        let inside = |p: &[f64; 3]| (0..3).all(|i| lo[i] <= p[i] && p[i] <= hi[i]);
        if t.iter().any(inside) {
            return true;
        }
        let p = |v: &[f64; 3]| Point3::new(v[0], v[1], v[2]);
        let surface = TriMesh::cuboid(p(lo), p(hi)).expect("a box with lo <= hi");
        let tri = Triangle::new(p(&t[0]), p(&t[1]), p(&t[2])).expect("finite vertices");
        // Degenerate triangles: also test the edges as segments (covered by the triangle
        // tests already; kept for clarity).
        let edges: Vec<Segment> = (0..3)
            .map(|m| Segment::new(p(&t[m]), p(&t[(m + 1) % 3])).expect("finite vertices"))
            .collect();
        (0..surface.num_triangles()).any(|i| {
            let face = surface.triangle(i as u32);
            tri.intersects(&face) || edges.iter().any(|e| face.intersects(e))
        })
    }

    /// Coordinates on a coarse grid, so that touching and coplanar cases are common.
    fn coord() -> impl Strategy<Value = f64> {
        (-4i32..=4).prop_map(|v| f64::from(v) * 0.5)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        #[test]
        fn agrees_with_the_exact_triangle_tests(
            t in prop::array::uniform3(prop::array::uniform3(coord())),
            a in prop::array::uniform3(coord()),
            b in prop::array::uniform3(coord()),
        ) {
            let lo = [a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])];
            let hi = [a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])];
            prop_assert_eq!(triangle_meets_box(&t, &lo, &hi), reference(&t, &lo, &hi));
        }

        #[test]
        fn agrees_on_random_floats(
            t in prop::array::uniform3(prop::array::uniform3(-1.0f64..1.0)),
            c in prop::array::uniform3(-1.0f64..1.0),
            h in prop::array::uniform3(0.0f64..0.5),
        ) {
            let lo = [c[0] - h[0], c[1] - h[1], c[2] - h[2]];
            let hi = [c[0] + h[0], c[1] + h[1], c[2] + h[2]];
            prop_assert_eq!(triangle_meets_box(&t, &lo, &hi), reference(&t, &lo, &hi));
            // The box test is necessary.
            let tb = Aabb { min: lo, max: hi };
            let pts: Vec<Point3<f64>> = t.iter().map(|v| Point3::new(v[0], v[1], v[2])).collect();
            if triangle_meets_box(&t, &lo, &hi) {
                prop_assert!(Aabb::of_points(&pts).overlaps(&tb));
            }
        }
    }
}

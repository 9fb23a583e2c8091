//! Tests of the bounding layer that need whole colliders: the oriented boxes hold every vertex
//! and bound every triangle pair's distance, and placed leaves are the placed mesh's triangles.

mod oriented_boxes {
    use crate::bounding::oriented_boxes::*;
    use crate::collider::poses::tests::soup;
    use crate::collider::Collider;
    use crate::query::exact_distance_triangle_triangle;
    use crate::TriMesh;
    use ga_core::scalar::{rational_from_f64, Rational};
    use nalgebra::{Isometry3, Point3, Vector3};
    use proptest::prelude::*;

    fn q(x: f64) -> Rational {
        rational_from_f64(x).expect("finite")
    }

    /// The triangles (mesh indices) under every node of `c`'s tree, root first.
    fn under(c: &Collider) -> Vec<Vec<u32>> {
        let tree = c.pose_tree();
        let nodes = tree.nodes();
        let mut out = vec![Vec::new(); nodes.len()];
        for i in (0..nodes.len()).rev() {
            let n = &nodes[i];
            out[i] = if n.is_leaf() {
                (n.start..n.start + n.count)
                    .map(|k| tree.index(k as usize))
                    .collect()
            } else {
                let (l, r) = (n.start as usize, n.start as usize + 1);
                [out[l].clone(), out[r].clone()].concat()
            };
        }
        out
    }

    fn scaled(m: &TriMesh, scale: f64, shift: [f64; 3]) -> TriMesh {
        let v = m
            .vertices()
            .iter()
            .map(|p| Point3::from(p.coords * scale + Vector3::from(shift)))
            .collect();
        TriMesh::new(v, m.triangles().to_vec()).unwrap()
    }

    fn scale() -> impl Strategy<Value = f64> {
        prop_oneof![Just(1.0), Just(1e-9), Just(1e9), Just(1e-200), Just(1e200)]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Every vertex under a node projects into its box on every axis, in exact arithmetic,
        /// and the axes are orthonormal up to the tree's `η_F`, at every scale.
        #[test]
        fn boxes_hold_every_vertex_exactly(
            seed in any::<u64>(), n in 1usize..40, s in scale(),
            shift in prop::array::uniform3(-3.0f64..3.0),
        ) {
            let m = scaled(&soup(seed, n, 1.0, 0.4, seed % 3 == 0), s, shift.map(|x| x * s));
            let c = Collider::new(m);
            let boxes = c.pose_tree().oriented();
            let one = Rational::from_integer(1.into());
            for (b, tris) in boxes.boxes.iter().zip(under(&c)) {
                for (i, a) in b.axes.iter().enumerate() {
                    let (lo, hi) = (q(b.c[i]) - q(b.e[i]), q(b.c[i]) + q(b.e[i]));
                    for &t in &tris {
                        for v in c.mesh().corners(t) {
                            let p = q(a[0]) * q(v.x) + q(a[1]) * q(v.y) + q(a[2]) * q(v.z);
                            prop_assert!(lo <= p && p <= hi, "vertex outside the box");
                        }
                    }
                    for (j, x) in b.axes.iter().enumerate() {
                        let dot = q(a[0]) * q(x[0]) + q(a[1]) * q(x[1]) + q(a[2]) * q(x[2]);
                        let dev = if i == j { dot - &one } else { dot };
                        prop_assert!(-q(boxes.eta) <= dev && dev <= q(boxes.eta));
                    }
                }
            }
        }

    }

    proptest! {
        // Exact rational distances are slow: few cases.
        #![proptest_config(ProptestConfig::with_cases(10))]

        /// Meshes in one frame: for every pair of nodes, the bound is at most the exact squared
        /// distance of every pair of triangles under them.
        #[test]
        fn same_frame_bound_never_exceeds_the_distance(
            seed in any::<u64>(), s in scale(),
            shift in prop::array::uniform3(-2.0f64..2.0),
        ) {
            let a = Collider::new(scaled(&soup(seed, 8, 1.0, 0.3, false), s, [0.0; 3]));
            let b = Collider::new(scaled(&soup(seed ^ 9, 6, 1.0, 0.3, false), s, shift.map(|x| x * s)));
            let gaps = OrientedGaps::same_frame(
                (a.extent(), b.extent()),
                a.pose_tree().oriented().eta.max(b.pose_tree().oriented().eta),
            );
            let exact: Vec<Vec<Rational>> = (0..8)
                .map(|i| (0..6).map(|j| {
                    exact_distance_triangle_triangle(&a.triangle(i), &b.triangle(j))
                        .distance2
                }).collect())
                .collect();
            let (ua, ub) = (under(&a), under(&b));
            let (fa, fb) = (&a.pose_tree().oriented().boxes, &b.pose_tree().oriented().boxes);
            for (x, ta) in fa.iter().zip(&ua) {
                for (y, tb) in fb.iter().zip(&ub) {
                    let least = ta.iter()
                        .flat_map(|&i| tb.iter().map(move |&j| (i, j)))
                        .map(|(i, j)| &exact[i as usize][j as usize])
                        .min()
                        .unwrap();
                    let lb = gaps.gap2(x, y);
                    if lb == f64::INFINITY {
                        // Squares beyond the f64 range: only for distances beyond it too.
                        prop_assert!(*least > q(f64::MAX));
                    } else {
                        prop_assert!(q(lb) <= *least);
                    }
                }
            }
        }
    }

    /// A turned slab gets a box along it (its principal axes), far smaller than its
    /// axis-aligned box; a cube keeps the coordinate axes (its corners have no principal
    /// direction).
    #[test]
    fn boxes_follow_the_geometry() {
        let slab = TriMesh::cuboid(Point3::origin(), Point3::new(4.0, 1.0, 0.1)).unwrap();
        let turn = Isometry3::rotation(Vector3::new(0.3, 0.5, 0.7));
        let c = Collider::new(slab.transformed(&turn).unwrap());
        let root = &c.pose_tree().oriented().boxes[0];
        let volume = root.e.iter().product::<f64>();
        assert!(volume < 0.5 * 1.01, "{volume}"); // the slab's half-extents: 2 × 0.5 × 0.05
        let node = &c.pose_tree().nodes()[0];
        assert!(volume < 0.2 * node.e.iter().product::<f64>());
        let cube =
            Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.)).unwrap());
        assert_eq!(cube.pose_tree().oriented().boxes[0].axes, IDENTITY);
    }
}

mod placed_leaves {
    use crate::bounding::placed_leaves::*;
    use crate::collider::Collider;
    use crate::TriMesh;
    use nalgebra::Isometry3;

    /// Leaves placed in an earlier traversal (or of another tree) are placed again, and the
    /// triangles are those of the placed mesh.
    #[test]
    fn epochs_separate_traversals() {
        let c = Collider::new(TriMesh::bunny().unit());
        let tree = c.pose_tree();
        let leaf = tree
            .nodes()
            .iter()
            .position(|n| n.is_leaf())
            .expect("a leaf");
        let n = tree.nodes()[leaf];
        for k in 0..3 {
            let iso = Isometry3::translation(0.1 * k as f64, 0.0, 0.0);
            let placed = c.placed(&iso).unwrap();
            with_scratch(tree.nodes().len(), tree.nodes().len(), |s| {
                let r = s.leaf(0, leaf as u32, &n, tree, &iso);
                assert_eq!(s.leaf(0, leaf as u32, &n, tree, &iso), r);
                for p in s.placed(r) {
                    assert_eq!(p.tri, placed.triangle(p.index));
                }
            });
        }
    }
}

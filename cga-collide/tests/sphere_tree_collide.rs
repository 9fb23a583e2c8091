//! Collision of sphere trees: the paper's method, the simultaneous descent and every leaf pair
//! agree on nested trees (random sphere sets and octree trees of meshes in random placements);
//! octree trees have no false negatives against the exact solids; the paper's C++ as written
//! misses a collision.
#![allow(clippy::needless_range_loop)]

use std::sync::OnceLock;

use cga_collide::collider::{Collider, Mode};
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
use cga_collide::hierarchy::sphere_tree::{CellState, NestedNode, SphereTree};
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::query::intersects_ball_ball;
use cga_collide::shape::mesh::TriMesh;
use cga_collide::testing::sphere_tree::{
    self as methods, ball_contains_box, cell_of, triangle_meets_box,
};
use cga_collide::Ball;
use proptest::prelude::*;

fn arb_node(depth: u32) -> BoxedStrategy<NestedNode> {
    let leaf = (prop::array::uniform3(-10.0f64..10.0), 0.0f64..3.0)
        .prop_map(|(c, r)| NestedNode::leaf(c, r, CellState::Partial));
    if depth == 0 {
        return leaf.boxed();
    }
    (leaf, prop::collection::vec(arb_node(depth - 1), 0..=8))
        .prop_map(|(mut n, children)| {
            n.children = children;
            n
        })
        .boxed()
}

fn agree(x: &SphereTree, y: &SphereTree) -> Result<bool, TestCaseError> {
    let reference = methods::brute_force(x, y).collides;
    let s = methods::paper_method(x, y);
    let m = x.collides(y);
    prop_assert_eq!(s.collides, reference);
    prop_assert_eq!(m.collides, reference);
    // The witnesses really are meeting leaves.
    for r in [s, m] {
        if let Some((i, j)) = r.witness {
            let (a, b) = (x.node(i), y.node(j));
            prop_assert!(a.is_leaf() && b.is_leaf());
            let ball = |c: [f64; 3], r| Ball::new(Point3::from(c), r).unwrap();
            prop_assert!(intersects_ball_ball(
                &ball(a.centre, a.radius),
                &ball(b.centre, b.radius)
            ));
        }
    }
    // The paper's method as published never claims a collision that is not there.
    prop_assert!(!methods::paper_method_as_published(x, y).collides || reference);
    Ok(reference)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_nested_sphere_trees_agree(a in arb_node(3), b in arb_node(3)) {
        let x = SphereTree::from_nested(&a).unwrap().nested_enclosing();
        let y = SphereTree::from_nested(&b).unwrap().nested_enclosing();
        prop_assert!(x.nesting_violations().is_empty());
        agree(&x, &y)?;
        agree(&y, &x)?;
    }
}

#[test]
fn paper_method_as_published_misses_a_collision() {
    // Y: a root with two children; the first child's ball meets X's leaf but its own leaf does
    // not; the second child's leaf does. The C++ follows only the first meeting child.
    let leaf = |x: f64, r: f64| NestedNode::leaf([x, 0.0, 0.0], r, CellState::Partial);
    let y = SphereTree::from_nested(&NestedNode {
        centre: [0.0; 3],
        radius: 10.0,
        state: CellState::Partial,
        children: vec![
            NestedNode {
                centre: [-1.0, 0.0, 0.0],
                radius: 5.0,
                state: CellState::Partial,
                children: vec![leaf(-5.0, 1.0)],
            },
            NestedNode {
                centre: [2.0, 0.0, 0.0],
                radius: 5.0,
                state: CellState::Partial,
                children: vec![leaf(3.0, 1.0)],
            },
        ],
    })
    .unwrap();
    assert!(y.nesting_violations().is_empty());
    let x = SphereTree::single([1.5, 0.0, 0.0], 1.0, CellState::Full).unwrap();
    assert!(methods::brute_force(&x, &y).collides);
    assert!(methods::paper_method(&x, &y).collides);
    assert!(x.collides(&y).collides);
    assert!(!methods::paper_method_as_published(&x, &y).collides);
}

/// A closed, outward-oriented cube mesh.
fn cube(lo: [f64; 3], hi: [f64; 3]) -> TriMesh {
    TriMesh::cuboid(lo.into(), hi.into()).unwrap()
}

/// Every node's state re-derived by brute force over all triangles (no hierarchy), every
/// dropped octant checked empty, every ball containing its cell.
fn check_classification(c: &Collider, tree: &SphereTree, side: f64) {
    let mesh = c.mesh();
    let tris: Vec<[[f64; 3]; 3]> = (0..mesh.num_triangles())
        .map(|i| mesh.corners(i as u32).map(|p| [p.x, p.y, p.z]))
        .collect();
    let partial = |b: &cga_collide::bounding::Aabb| {
        tris.iter().any(|t| triangle_meets_box(t, &b.min, &b.max))
    };
    let mut level = vec![0u32; tree.len()];
    for i in 0..tree.len() {
        for ch in tree.children(i) {
            level[ch] = level[i] + 1;
        }
    }
    for i in 0..tree.len() {
        let n = tree.node(i);
        let b = cell_of(&n.centre, side, level[i]);
        assert!(ball_contains_box(&n.centre, n.radius, &b), "node {i}");
        let expected = if partial(&b) {
            CellState::Partial
        } else {
            assert!(
                c.clone()
                    .with_mode(Mode::Brute)
                    .contains_point(&n.centre.into()),
                "node {i} is empty"
            );
            CellState::Full
        };
        assert_eq!(n.state, expected, "node {i}");
        if !n.is_leaf() {
            // The octants not kept are empty.
            let h = side / 2f64.powi(level[i] as i32 + 2);
            let kept: Vec<[f64; 3]> = tree.children(i).map(|k| tree.node(k).centre).collect();
            for m in 0..8 {
                let cc = [
                    n.centre[0] + if m & 1 == 0 { -h } else { h },
                    n.centre[1] + if m & 2 == 0 { -h } else { h },
                    n.centre[2] + if m & 4 == 0 { -h } else { h },
                ];
                if !kept.contains(&cc) {
                    let cb = cell_of(&cc, side, level[i] + 1);
                    assert!(!partial(&cb));
                    assert!(!c.clone().with_mode(Mode::Brute).contains_point(&cc.into()));
                }
            }
        }
    }
}

#[test]
fn cube_and_bunny_cells_are_classified_exactly() {
    let c = Collider::new(cube([0.1, 0.2, 0.3], [0.9, 0.7, 1.0]));
    for d in 0..=4 {
        let (t, report) = build(&c, &BuildOptions::depth(d)).unwrap();
        assert!(t.nesting_violations().is_empty());
        assert_eq!(t.height(), d as usize);
        check_classification(&c, &t, report.side);
        assert!(report.levels.iter().skip(2).all(|l| l.full > 0));
    }
    let bunny = Collider::new(TriMesh::bunny().unit());
    let (t, report) = build(&bunny, &BuildOptions::depth(3)).unwrap();
    check_classification(&bunny, &t, report.side);
    let full = BuildOptions {
        subdivide_full: true,
        ..BuildOptions::depth(3)
    };
    let (t2, _) = build(&bunny, &full).unwrap();
    assert!(t2.len() > t.len());
    assert!((0..t2.len()).all(|i| !t2.node(i).is_leaf() || level_of(&t2, i) == 3));
}

fn level_of(t: &SphereTree, i: usize) -> usize {
    let mut level = vec![0usize; t.len()];
    for p in 0..t.len() {
        for ch in t.children(p) {
            level[ch] = level[p] + 1;
        }
    }
    level[i]
}

#[test]
fn open_meshes_and_silly_depths_are_typed_errors() {
    let m = TriMesh::new(
        vec![
            cga_collide::nalgebra::Point3::new(0.0, 0.0, 0.0),
            cga_collide::nalgebra::Point3::new(1.0, 0.0, 0.0),
            cga_collide::nalgebra::Point3::new(0.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2]],
    )
    .unwrap();
    let c = Collider::new(m);
    assert!(build(&c, &BuildOptions::depth(2)).is_err());
    let c = Collider::new(cube([0.0; 3], [1.0; 3]));
    assert!(build(&c, &BuildOptions::depth(99)).is_err());
}

struct Fixture {
    a: Collider,
    b: Collider,
    ta: SphereTree,
    tb: SphereTree,
}

fn fixture() -> &'static Fixture {
    static F: OnceLock<Fixture> = OnceLock::new();
    F.get_or_init(|| {
        let a = Collider::new(TriMesh::bunny().unit());
        let b = Collider::new(cube([-0.2, -0.1, -0.3], [0.25, 0.1, 0.2]));
        let ta = build(&a, &BuildOptions::depth(4)).unwrap().0;
        let tb = build(&b, &BuildOptions::depth(3)).unwrap().0;
        Fixture { a, b, ta, tb }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mesh_trees_in_random_placements_agree_and_never_miss(
        t in prop::array::uniform3(-1.0f64..1.0),
        axis in prop::array::uniform3(-1.0f64..1.0),
        angle in 0.0f64..6.3,
    ) {
        let f = fixture();
        let rot = UnitQuaternion::from_axis_angle(
            &cga_collide::nalgebra::Unit::new_normalize(Vector3::new(axis[0], axis[1], axis[2] + 2.0)),
            angle,
        );
        let iso = Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rot);
        let moved = f.tb.transformed(&iso);
        let trees = agree(&f.ta, &moved)?;
        agree(&moved, &f.ta)?;
        // The posed entry point moves both trees the same way.
        let posed = f.ta.collides_at(&Isometry3::identity(), &f.tb, &iso);
        let id = Isometry3::identity();
        prop_assert_eq!(posed, f.ta.transformed(&id).collides(&moved));
        let exact = f.a.collides_solid(&f.b.placed(&iso).unwrap());
        // No false negatives: the leaf balls cover the solids.
        prop_assert!(trees || !exact);
    }
}

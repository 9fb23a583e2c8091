//! A solid primitive against a mesh `Collider`: the answers through the box tree equal the
//! generic pair query against each triangle, in both modes, in one frame and under poses.

use cga_collide::collider::{Collider, Mode};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query;
use cga_collide::shape::{Cuboid, HalfSpace, Shape};
use cga_collide::{Ball, Error, Segment, TriMesh, Triangle};
use proptest::prelude::*;

fn point(scale: f64) -> impl Strategy<Value = Point3<f64>> {
    (-scale..scale, -scale..scale, -scale..scale).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// Balls, segments and triangles (the pairs every branch answers).
fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (point(3.0), 0.0f64..1.5).prop_map(|(c, r)| Ball::new(c, r).unwrap().into()),
        (point(3.0), point(3.0)).prop_map(|(a, b)| Segment::new(a, b).unwrap().into()),
        (point(3.0), point(3.0), point(3.0))
            .prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap().into()),
    ]
}

/// A soup of small triangles (up to 48, so both the lazily and the eagerly built trees are
/// met), some sharing vertices, or a box.
fn mesh() -> impl Strategy<Value = TriMesh> {
    prop_oneof![
        (
            prop::collection::vec(point(2.5), 3..40),
            prop::collection::vec((0usize..1000, 0usize..1000, 0usize..1000), 1..48),
        )
            .prop_map(|(vertices, faces)| {
                let n = vertices.len();
                let triangles = faces
                    .into_iter()
                    .map(|(a, b, c)| [(a % n) as u32, (b % n) as u32, (c % n) as u32])
                    .collect();
                TriMesh::new(vertices, triangles).unwrap()
            }),
        (point(1.0), 0.1f64..2.0).prop_map(|(lo, side)| {
            TriMesh::cuboid(lo, lo + Vector3::new(side, side * 0.5, side * 2.0)).unwrap()
        }),
    ]
}

fn pose() -> impl Strategy<Value = Isometry3<f64>> {
    (point(1.0), point(3.0)).prop_map(|(t, r)| Isometry3::new(t.coords, r.coords))
}

/// Every answer of the generic pair query against each triangle of `mesh`.
struct Brute {
    hits: Vec<u32>,
    within: bool,
    distance: f64,
}

fn brute(mesh: &TriMesh, shape: &Shape, c: f64) -> Brute {
    let triangles: Vec<Shape> = (0..mesh.num_triangles() as u32)
        .map(|i| mesh.triangle(i).into())
        .collect();
    Brute {
        hits: (0..triangles.len() as u32)
            .filter(|&i| query::intersects(&triangles[i as usize], shape).unwrap())
            .collect(),
        within: triangles
            .iter()
            .any(|t| query::within_distance(t, shape, c).unwrap()),
        distance: triangles
            .iter()
            .map(|t| query::distance(t, shape).unwrap().distance)
            .fold(f64::INFINITY, f64::min),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn tree_answers_equal_the_answers_per_triangle(
        mesh in mesh(),
        shape in shape(),
        c in 0.0f64..1.0,
        brute_mode in any::<bool>(),
    ) {
        let expected = brute(&mesh, &shape, c);
        let mode = if brute_mode { Mode::Brute } else { Mode::Bvh };
        let collider = Collider::new(mesh).with_mode(mode);
        prop_assert_eq!(&collider.shape_hits(&shape).unwrap(), &expected.hits);
        prop_assert_eq!(collider.intersects_shape(&shape).unwrap(), !expected.hits.is_empty());
        prop_assert_eq!(collider.shape_within_distance(&shape, c).unwrap(), expected.within);
        let d = collider.distance_to_shape(&shape).unwrap();
        prop_assert_eq!(d.distance, expected.distance);
        let (i, zero) = d.triangles.unwrap();
        prop_assert_eq!(zero, 0);
        let own = query::distance(&collider.triangle(i).into(), &shape).unwrap();
        prop_assert_eq!((own.distance, own.witness_a, own.witness_b), (d.distance, d.witness_a, d.witness_b));
        prop_assert!(d.error_bound >= own.error_bound);
    }

    #[test]
    fn pose_answers_equal_the_placed_answers(
        mesh in mesh(),
        shape in shape(),
        pose in pose(),
        shape_pose in pose(),
        c in 0.0f64..1.0,
        brute_mode in any::<bool>(),
    ) {
        let mode = if brute_mode { Mode::Brute } else { Mode::Bvh };
        let collider = Collider::new(mesh).with_mode(mode);
        let placed = collider.placed(&pose).unwrap();
        let placed_shape = shape.placed(&shape_pose).unwrap();
        let expected = brute(placed.mesh(), &placed_shape, c);
        prop_assert_eq!(&collider.shape_hits_at(&pose, &shape, &shape_pose).unwrap(), &expected.hits);
        prop_assert_eq!(
            collider.intersects_shape_at(&pose, &shape, &shape_pose).unwrap(),
            !expected.hits.is_empty()
        );
        prop_assert_eq!(
            collider.shape_within_distance_at(&pose, &shape, &shape_pose, c).unwrap(),
            expected.within
        );
        let d = collider.distance_to_shape_at(&pose, &shape, &shape_pose).unwrap();
        prop_assert_eq!(d.distance, expected.distance);
        prop_assert_eq!(
            collider.intersects_shape_solid_at(&pose, &shape, &shape_pose).unwrap(),
            placed.intersects_shape_solid(&placed_shape).unwrap()
        );
    }
}

fn unit_cube() -> Collider {
    Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap())
}

#[test]
fn a_shape_inside_a_closed_mesh_meets_no_triangle_but_the_solid() {
    let cube = unit_cube();
    let inside: Shape = Ball::new(Point3::new(0.5, 0.5, 0.5), 0.25).unwrap().into();
    assert!(!cube.intersects_shape(&inside).unwrap());
    assert!(cube.intersects_shape_solid(&inside).unwrap());
    // The cube inside a large ball: the solid again.
    let around: Shape = Ball::new(Point3::new(0.5, 0.5, 0.5), 10.0).unwrap().into();
    assert!(!cube.intersects_shape(&around).unwrap());
    assert!(cube.intersects_shape_solid(&around).unwrap());
    let apart: Shape = Ball::new(Point3::new(3.0, 0.5, 0.5), 1.0).unwrap().into();
    assert!(!cube.intersects_shape_solid(&apart).unwrap());
    let d = cube.distance_to_shape(&inside).unwrap();
    assert!((d.distance - 0.25).abs() <= d.error_bound + 1e-15, "{d:?}");
}

/// Far shapes of kinds whose exact pair tests with triangles may not exist here: the tree sets
/// every node aside, so no triangle test is asked (a test asked here would be refused).
#[test]
fn far_shapes_prune_the_whole_tree() {
    let cube = unit_cube();
    let above = HalfSpace::new(Point3::new(0.0, 0.0, 2.0), -Vector3::z()).unwrap();
    let tilted =
        HalfSpace::new(Point3::new(-1.0, -1.0, -1.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
    let far_box =
        Cuboid::axis_aligned(Point3::new(5.0, 0.0, 0.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
    for shape in [Shape::from(above), tilted.into(), far_box.into()] {
        for mode in [Mode::Bvh, Mode::Brute] {
            let c = unit_cube().with_mode(mode);
            assert_eq!(
                c.shape_hits(&shape).unwrap(),
                Vec::<u32>::new(),
                "{shape:?}"
            );
            assert!(!c.intersects_shape(&shape).unwrap());
            assert!(!c.shape_within_distance(&shape, 0.5).unwrap());
            let id = Isometry3::identity();
            assert!(!c.intersects_shape_at(&id, &shape, &id).unwrap());
        }
    }
    let _ = cube;
}

#[test]
fn refusals_are_typed() {
    let cube = unit_cube();
    let ball: Shape = Ball::new(Point3::origin(), 1.0).unwrap().into();
    assert!(matches!(
        cube.shape_within_distance(&ball, f64::NAN),
        Err(Error::InvalidClearance { .. })
    ));
    let huge: Shape = Ball::new(Point3::new(1e200, 0.0, 0.0), 1.0).unwrap().into();
    assert!(matches!(
        cube.intersects_shape(&huge),
        Err(Error::CoordinateOutOfRange { .. })
    ));
    let far = Isometry3::translation(1e200, 0.0, 0.0);
    assert!(matches!(
        cube.intersects_shape_at(&far, &ball, &Isometry3::identity()),
        Err(Error::OutOfRange { .. })
    ));
    let big =
        Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1e300, 1.0, 1.0)).unwrap());
    assert!(matches!(
        big.shape_hits(&ball),
        Err(Error::OutOfRange { .. })
    ));
}

//! The generic shape queries over many poses (`query::*_batch`) answer as the `_at` queries do,
//! pose by pose, and report the first refused pose with its index; the named pair functions
//! answer as the generic entry points.

use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query;
use cga_collide::shape::{Capsule, Cuboid, HalfSpace, PosePair, Shape};
use cga_collide::{Ball, Error, Segment, Triangle};
use proptest::prelude::*;

fn point() -> impl Strategy<Value = Point3<f64>> {
    (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// Balls, segments and triangles: the pairs answered on every branch.
fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (point(), 0.0f64..2.0).prop_map(|(c, r)| Ball::new(c, r).unwrap().into()),
        (point(), point()).prop_map(|(a, b)| Segment::new(a, b).unwrap().into()),
        (point(), point(), point()).prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap().into()),
    ]
}

fn pose() -> impl Strategy<Value = Isometry3<f64>> {
    (point(), -3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0)
        .prop_map(|(t, ax, ay, az)| Isometry3::new(t.coords, Vector3::new(ax, ay, az)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn batches_answer_as_the_pose_queries(
        a in shape(),
        b in shape(),
        poses in prop::collection::vec((pose(), pose()), 0..6),
        c in 0.0f64..2.0,
    ) {
        let poses: Vec<PosePair> = poses.into_iter().map(|(x, y)| PosePair::new(x, y)).collect();
        let hits = query::intersects_batch(&a, &b, &poses).unwrap();
        let near = query::within_distance_batch(&a, &b, &poses, c).unwrap();
        let far = query::distance_batch(&a, &b, &poses).unwrap();
        prop_assert_eq!((hits.len(), near.len(), far.len()), (poses.len(), poses.len(), poses.len()));
        for (k, p) in poses.iter().enumerate() {
            prop_assert_eq!(hits[k], query::intersects_at(&a, &p.a, &b, &p.b).unwrap());
            prop_assert_eq!(near[k], query::within_distance_at(&a, &p.a, &b, &p.b, c).unwrap());
            prop_assert_eq!(&far[k], &query::distance_at(&a, &p.a, &b, &p.b).unwrap());
            // And the `_at` answer is the answer for the placed shapes.
            let (pa, pb) = (a.placed(&p.a).unwrap(), b.placed(&p.b).unwrap());
            prop_assert_eq!(hits[k], query::intersects(&pa, &pb).unwrap());
        }
    }
}

#[test]
fn the_first_refused_pose_is_named_with_its_index() {
    let ball: Shape = Ball::new(Point3::origin(), 1.0).unwrap().into();
    let fine = PosePair::new(Isometry3::identity(), Isometry3::identity());
    // A translation beyond the primitives' range: the placed ball is refused.
    let far = PosePair::new(
        Isometry3::identity(),
        Isometry3::translation(1e200, 0.0, 0.0),
    );
    let e = query::intersects_batch(&ball, &ball, &[fine, far, far]).unwrap_err();
    assert!(
        matches!(e, Error::InBatch { index: 1, ref source } if matches!(**source, Error::CoordinateOutOfRange { .. })),
        "{e:?}"
    );
    assert!(e.to_string().starts_with("pose 1 of the batch"), "{e}");
    let e = query::within_distance_batch(&ball, &ball, &[fine], -1.0).unwrap_err();
    assert!(matches!(e, Error::InBatch { index: 0, .. }), "{e:?}");
    assert_eq!(query::distance_batch(&ball, &ball, &[]).unwrap(), vec![]);
}

/// Every named pair function answers as the generic query on the same pair.
#[test]
fn named_pair_functions_answer_as_the_generic_queries() {
    let cube = Cuboid::axis_aligned(Point3::origin(), Vector3::new(1.0, 1.0, 1.0)).unwrap();
    let capsule =
        Capsule::new(Point3::new(2.0, -1.0, 0.0), Point3::new(2.0, 1.0, 0.0), 1.0).unwrap();
    let ground = HalfSpace::new(Point3::new(0.0, 0.0, -1.0), Vector3::z()).unwrap();
    let ball = Ball::new(Point3::new(0.0, 0.0, 3.0), 1.0).unwrap();
    let (s_cube, s_capsule): (Shape, Shape) = (cube.into(), capsule.into());
    assert_eq!(
        query::intersects_cuboid_capsule(&cube, &capsule),
        query::intersects(&s_cube, &s_capsule).unwrap()
    );
    assert_eq!(
        query::distance_cuboid_capsule(&cube, &capsule),
        query::distance(&s_cube, &s_capsule).unwrap()
    );
    assert_eq!(
        query::within_distance_cuboid_half_space(&cube, &ground, 0.0).unwrap(),
        query::within_distance(&s_cube, &ground.into(), 0.0).unwrap()
    );
    assert_eq!(
        query::intersects_ball_cuboid(&ball, &cube).unwrap(),
        query::intersects(&ball.into(), &s_cube).unwrap()
    );
}

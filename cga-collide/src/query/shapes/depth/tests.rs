//! Unit tests of the signed distance: exact contacts, one-ulp overlaps, the closed forms of
//! boxes and balls, and deep overlaps.

use nalgebra::{Isometry3, Point3, Vector3};

use super::*;
use crate::shape::{Capsule, ConvexHull, Cuboid, Cylinder, HalfSpace};
use crate::Ball;

fn cube(centre: [f64; 3], half: f64) -> Shape {
    Cuboid::axis_aligned(Point3::from(centre), Vector3::repeat(half))
        .unwrap()
        .into()
}

fn boxed(centre: [f64; 3], half: [f64; 3]) -> Shape {
    Cuboid::axis_aligned(Point3::from(centre), Vector3::from(half))
        .unwrap()
        .into()
}

fn ball(centre: [f64; 3], r: f64) -> Shape {
    Ball::new(Point3::from(centre), r).unwrap().into()
}

fn sd(a: &Shape, b: &Shape) -> SignedDistance {
    signed_distance(a, b).unwrap()
}

/// `expected` is inside the answer's bound, and the bound is at most `1e-13` of the value (the
/// `f64` path's proved bounds are about `1e-14` relative; the exact path's a few ulps) or `abs`.
fn assert_value(got: &SignedDistance, expected: f64, abs: f64) {
    assert!(
        (got.value - expected).abs() <= got.error_bound,
        "value {} expected {expected} bound {}",
        got.value,
        got.error_bound
    );
    assert!(
        got.error_bound <= abs.max(1e-13 * expected.abs()),
        "bound {} too wide for {expected}",
        got.error_bound
    );
}

#[test]
fn touching_boxes_are_exactly_zero() {
    for (x, y, z) in [
        (1.0, 0.0, 0.0),
        (1.0, 1.0, 0.0),
        (1.0, 1.0, 1.0),
        (0.0, 0.0, -1.0),
    ] {
        let got = sd(&cube([0.0; 3], 0.5), &cube([x, y, z], 0.5));
        assert_eq!((got.value, got.error_bound), (0.0, 0.0), "{x} {y} {z}");
        assert_eq!(got.kind, SignedDistanceKind::Touching);
    }
}

#[test]
fn a_one_ulp_overlap_has_its_exact_tiny_depth() {
    let x = 1f64.next_down();
    let got = sd(&cube([0.0; 3], 0.5), &cube([x, 0.3, -0.2], 0.5));
    assert_eq!(got.kind, SignedDistanceKind::Penetrating);
    assert_value(&got, -(1.0 - x), 1e-30);
    assert_eq!(got.normal, Vector3::x());
    // And in the other order, the normal flips.
    let got = sd(&cube([x, 0.3, -0.2], 0.5), &cube([0.0; 3], 0.5));
    assert_value(&got, -(1.0 - x), 1e-30);
    assert_eq!(got.normal, -Vector3::x());
}

#[test]
fn box_on_box_takes_the_shallowest_axis() {
    let got = sd(
        &boxed([0.0; 3], [2.0, 1.0, 0.5]),
        &cube([0.5, 0.25, 0.8], 0.5),
    );
    // Overlaps along x: 2.0 + 0.5 - 0.5 = 2, y: 1.25, z: 0.5 + 0.5 - 0.8 = 0.2.
    assert_value(&got, -0.2, 1e-15);
    assert_eq!(got.normal, Vector3::z());
    assert!(((got.witness_b - got.witness_a).dot(&got.normal) - got.value).abs() < 1e-12);
}

#[test]
fn separated_boxes_get_their_distance() {
    let got = sd(&cube([0.0; 3], 0.5), &cube([3.0, 4.0, 0.0], 0.5));
    assert_eq!(got.kind, SignedDistanceKind::Separated);
    // Apart: the certified distance's bound (a few dozen ulps of the scale).
    assert_value(&got, (2.0f64 * 2.0 + 3.0 * 3.0).sqrt(), 1e-13);
}

#[test]
fn capsule_on_box() {
    let table = boxed([0.0; 3], [1.0, 1.0, 0.5]);
    // Lying on the top face, sunk by 0.125 (the core is outside the box).
    let capsule: Shape = Capsule::new(
        Point3::new(-0.5, 0.0, 0.75),
        Point3::new(0.5, 0.0, 0.75),
        0.375,
    )
    .unwrap()
    .into();
    let got = sd(&table, &capsule);
    assert_value(&got, -0.125, 1e-15);
    assert!((got.normal - Vector3::z()).norm() < 1e-15);
    // Standing through the top face: the core reaches 0.25 into the box, plus the radius.
    let standing: Shape = Capsule::new(
        Point3::new(0.0, 0.0, 0.25),
        Point3::new(0.0, 0.0, 3.0),
        0.125,
    )
    .unwrap()
    .into();
    let got = sd(&table, &standing);
    assert_value(&got, -0.375, 1e-15);
    assert_eq!(got.normal, Vector3::z());
}

#[test]
fn ball_in_hull() {
    // The tetrahedron x, y, z >= 0, x + y + z <= 3 and a ball at (0.5, 0.5, 0.5) of radius 0.25:
    // the nearest faces are the three coordinate planes at 0.5.
    let p = |x, y, z| Point3::new(x, y, z);
    let hull: Shape = ConvexHull::new(vec![
        p(0.0, 0.0, 0.0),
        p(3.0, 0.0, 0.0),
        p(0.0, 3.0, 0.0),
        p(0.0, 0.0, 3.0),
    ])
    .unwrap()
    .into();
    let got = sd(&hull, &ball([0.5, 0.5, 0.5], 0.25));
    assert_value(&got, -0.75, 1e-15);
    assert_eq!(got.normal.iter().filter(|c| **c == -1.0).count(), 1);
    // Near the slanted face: depth to x + y + z = 3 is (3 - 2.7)/√3.
    let got = sd(&hull, &ball([0.9, 0.9, 0.9], 0.0));
    assert_value(&got, -(3.0 - 2.7f64) / 3f64.sqrt(), 1e-15);
}

#[test]
fn deep_overlaps() {
    // Concentric cubes: the depth is the sum of the half sizes.
    let got = sd(&cube([0.0; 3], 1.0), &cube([0.0; 3], 0.25));
    assert_value(&got, -1.25, 1e-15);
    // Concentric balls: the sum of the radii.
    let got = sd(&ball([1.0, 2.0, 3.0], 1.0), &ball([1.0, 2.0, 3.0], 2.0));
    assert_value(&got, -3.0, 1e-15);
    assert_eq!(got.kind, SignedDistanceKind::Penetrating);
    // A rotated box around the origin in a big box.
    let r = Isometry3::rotation(Vector3::new(0.3, -0.2, 0.7));
    let small = cube([0.0; 3], 0.5).placed(&r).unwrap();
    let got = sd(&cube([0.0; 3], 10.0), &small);
    assert!(got.value < -10.0 && got.value > -11.0);
}

#[test]
fn balls_apart_touching_and_overlapping() {
    let got = sd(&ball([0.0; 3], 1.0), &ball([3.0, 0.0, 0.0], 1.0));
    assert_value(&got, 1.0, 1e-13);
    let got = sd(&ball([0.0; 3], 1.0), &ball([2.0, 0.0, 0.0], 1.0));
    assert_eq!(
        (got.value, got.error_bound, got.kind),
        (0.0, 0.0, SignedDistanceKind::Touching)
    );
    let got = sd(&ball([0.0; 3], 1.0), &ball([1.5, 0.0, 0.0], 1.0));
    assert_value(&got, -0.5, 1e-15);
    assert_eq!(got.normal, Vector3::x());
}

#[test]
fn half_spaces() {
    let ground: Shape = HalfSpace::new(Point3::origin(), Vector3::new(0.0, 0.0, 2.0))
        .unwrap()
        .into();
    let got = sd(&ground, &ball([5.0, 1.0, 0.75], 1.0));
    assert_value(&got, -0.25, 1e-15);
    assert_eq!(got.normal, Vector3::z());
    let got = sd(&cube([0.0, 0.0, 3.0], 1.0), &ground);
    assert_value(&got, 2.0, 1e-15);
    assert_eq!(got.normal, -Vector3::z());
    let got = sd(&ground, &cube([0.0, 0.0, 1.0], 1.0));
    assert_eq!((got.value, got.kind), (0.0, SignedDistanceKind::Touching));
    let roof: Shape = HalfSpace::new(Point3::new(0.0, 0.0, 1.0), -Vector3::z())
        .unwrap()
        .into();
    assert_value(&sd(&ground, &roof), 1.0, 1e-15);
    let wall: Shape = HalfSpace::new(Point3::origin(), Vector3::x())
        .unwrap()
        .into();
    assert!(matches!(
        signed_distance(&ground, &wall),
        Err(Error::UnsupportedPair { .. })
    ));
}

#[test]
fn cylinders_are_answered_when_apart_and_when_meeting() {
    let cyl: Shape = Cylinder::new(Point3::origin(), Point3::new(0.0, 0.0, 1.0), 0.5)
        .unwrap()
        .into();
    let got = sd(&cyl, &ball([3.0, 0.0, 0.5], 0.5));
    assert_value(&got, 2.0, 1e-12);
    // A ball centred on the lower cap: out through the cap, by its radius.
    let got = sd(&cyl, &ball([0.0; 3], 0.5));
    assert_eq!(got.kind, SignedDistanceKind::Penetrating);
    assert_value(&got, -0.5, 1e-14);
    assert!(
        (got.normal + Vector3::z()).norm() < 1e-12,
        "{:?}",
        got.normal
    );
}

#[test]
fn batch_equals_the_single_answers() {
    let a = cube([0.0; 3], 0.5);
    let b = ball([0.0; 3], 0.5);
    let poses: Vec<PosePair> = [0.25, 1.0, 2.0]
        .map(|x| PosePair::new(Isometry3::identity(), Isometry3::translation(x, 0.0, 0.0)))
        .into();
    let got = signed_distance_batch(&a, &b, &poses).unwrap();
    for (g, p) in got.iter().zip(&poses) {
        assert_eq!(*g, signed_distance_at(&a, &p.a, &b, &p.b).unwrap());
    }
    assert_value(&got[0], -0.75, 1e-15);
    assert_eq!(got[1].kind, SignedDistanceKind::Touching);
    assert_value(&got[2], 1.0, 1e-13);
}

/// A facet of `M` whose normal is the cross product of two directions taken the other way
/// round: with one orientation per candidate line the depth came out 1.7871 instead of the
/// true 1.7467 (found by the workspace reference's proptest).
#[test]
fn hull_against_parallelepiped_regression() {
    let p = |x, y, z| Point3::new(x, y, z);
    let hull: Shape = ConvexHull::new(vec![
        p(0.375, -0.625, 1.75),
        p(0.25, 1.5, -0.5),
        p(-0.875, -2.0, 1.125),
        p(0.75, -1.875, -0.5),
        p(0.0, -1.625, 1.5),
        p(0.5, -1.0, -0.375),
        p(-0.5, -1.75, 1.0),
        p(-1.875, -0.5, -0.5),
    ])
    .unwrap()
    .into();
    let c: Shape = Cuboid::new(
        p(1.3228396862032046, -0.25, -1.0),
        [
            Vector3::new(2.0, 2.0, 1.0),
            Vector3::new(3.0, 2.0, -1.0),
            Vector3::new(-3.0, -1.0, -2.0),
        ],
    )
    .unwrap()
    .into();
    let got = sd(&hull, &c);
    assert!((got.value + 1.7467046199073775).abs() < 1e-9, "{got:?}");
}

/// The `f64` path against the exact path on random overlapping pairs: whenever the fast path
/// answers, the exact value lies within the two bounds and the kinds agree.
#[test]
fn the_fast_path_agrees_with_the_exact_path() {
    let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut answered = 0;
    for _ in 0..300 {
        let ka = (next() * 4.0) as u32;
        let kb = (next() * 4.0) as u32;
        let mut pick = |kind: u32| -> Shape {
            let centre = Point3::new(next() - 0.5, next() - 0.5, next() - 0.5);
            let turn = Vector3::new(next() * 3.0, next() * 3.0, next() * 3.0);
            let pose = Isometry3::new(centre.coords, turn);
            let local: Shape = match kind {
                0 => Cuboid::axis_aligned(
                    Point3::origin(),
                    Vector3::new(0.2 + next(), 0.2 + next(), 0.2 + next()),
                )
                .unwrap()
                .into(),
                1 => Capsule::new(
                    Point3::new(-0.5, 0.0, 0.0),
                    Point3::new(0.5, 0.0, 0.0),
                    0.1 + next() * 0.5,
                )
                .unwrap()
                .into(),
                2 => Ball::new(Point3::origin(), 0.1 + next()).unwrap().into(),
                _ => ConvexHull::new(
                    (0..10)
                        .map(|_| Point3::new(next() - 0.5, next() - 0.5, next() - 0.5))
                        .collect(),
                )
                .unwrap()
                .into(),
            };
            local.placed(&pose).unwrap()
        };
        let (a, b) = (pick(ka), pick(kb));
        let Some(fast) = fast::signed_distance(&a, &b) else {
            continue;
        };
        answered += 1;
        let exact = exact_cores(&a, &b).unwrap();
        assert_eq!(fast.kind, exact.kind, "{a:?} {b:?}");
        assert!(
            (fast.value - exact.value).abs() <= fast.error_bound + exact.error_bound,
            "fast {fast:?} exact {exact:?}"
        );
        assert!(fast.error_bound <= fast.value.abs() / f64::from(1u32 << 30));
    }
    assert!(
        answered > 150,
        "the fast path answered only {answered} of 300"
    );
}

#[test]
fn round_shapes_in_half_spaces_are_exact_at_contact() {
    use crate::shape::Cone;
    let ground: Shape = HalfSpace::new(Point3::origin(), Vector3::z())
        .unwrap()
        .into();
    // Resting on its side, and a cone on its rim (axis tilted so that one rim point is
    // lowest): touching, exactly 0.
    let lying: Shape = Cylinder::new(Point3::new(-1.0, 0.0, 0.5), Point3::new(1.0, 0.5, 0.5), 0.5)
        .unwrap()
        .into();
    let got = sd(&ground, &lying);
    assert_eq!((got.value, got.error_bound), (0.0, 0.0));
    assert_eq!(got.kind, SignedDistanceKind::Touching);
    // Axis along (0.75, 0, 1): the lowest rim point is 0.625 · 0.6 = 0.375 below the base
    // centre.
    let cone: Shape = Cone::new(
        Point3::new(0.75, 0.0, 1.375),
        Point3::new(0.0, 0.0, 0.375),
        0.625,
    )
    .unwrap()
    .into();
    let got = sd(&cone, &ground);
    assert_eq!(got.kind, SignedDistanceKind::Touching, "{got:?}");
    // Sunk by 2^-40 and lifted by it.
    for (dz, kind) in [
        (-(2f64.powi(-40)), SignedDistanceKind::Penetrating),
        (2f64.powi(-40), SignedDistanceKind::Separated),
    ] {
        let moved = lying.placed(&Isometry3::translation(0.0, 0.0, dz)).unwrap();
        let got = sd(&ground, &moved);
        assert_eq!(got.kind, kind);
        // Bounded by interval arithmetic: a few ulps of the scale.
        assert_value(&got, dz, 1e-14);
    }
}

#[test]
fn a_cylinder_sunk_one_ulp_into_a_box_has_that_depth() {
    let table = boxed([0.0; 3], [2.0, 2.0, 0.5]);
    let z = 1f64.next_down();
    let cyl: Shape = Cylinder::new(Point3::new(-1.0, 0.0, z), Point3::new(1.0, 0.0, z), 0.5)
        .unwrap()
        .into();
    let got = sd(&table, &cyl);
    assert_eq!(got.kind, SignedDistanceKind::Penetrating);
    assert!((got.value + (1.0 - z)).abs() <= got.error_bound, "{got:?}");
    assert!(got.error_bound < 1e-15);
    assert_eq!(got.normal, Vector3::z());
}

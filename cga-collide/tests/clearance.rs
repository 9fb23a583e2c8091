//! Exact clearance (`dist(a, b) <= c`) against the exact rational brute-force oracle, including
//! pairs at exactly distance `c` and the `f64` just below it.

use cga_collide::collider::Collider;
use cga_collide::ga_core::scalar::{rational_from_f64, Rational, Real};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query::WithinDistance;
use cga_collide::testing::oracle::{self, Shape};
use cga_collide::{Ball, Segment, Sphere, TriMesh, Triangle};
use proptest::prelude::*;

/// Small integers (many exact touches, parallel and coplanar configurations) or halves.
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => (-3i32..=3).prop_map(f64::from),
        1 => (-6i32..=6).prop_map(|v| f64::from(v) * 0.5),
        1 => -3.0f64..3.0,
    ]
}

fn point() -> impl Strategy<Value = Point3<f64>> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

fn segment() -> impl Strategy<Value = Segment> {
    (point(), point()).prop_map(|(a, b)| Segment::new(a, b).unwrap())
}

fn triangle() -> impl Strategy<Value = Triangle> {
    (point(), point(), point()).prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap())
}

fn radius() -> impl Strategy<Value = f64> {
    prop_oneof![(0i32..=4).prop_map(f64::from), 0.0f64..3.0]
}

fn ball() -> impl Strategy<Value = Ball> {
    (point(), radius()).prop_map(|(c, r)| Ball::new(c, r).unwrap())
}

fn sphere() -> impl Strategy<Value = Sphere> {
    (point(), radius()).prop_map(|(c, r)| Sphere::new(c, r).unwrap())
}

fn clearance() -> impl Strategy<Value = f64> {
    prop_oneof![
        2 => (0i32..=4).prop_map(f64::from),
        1 => (0i32..=8).prop_map(|v| f64::from(v) * 0.5),
        2 => 0.0f64..4.0,
    ]
}

/// The exact distance as an `f64`, when the exact distance is one (`d²` a square of an `f64`).
fn exact_f64_distance(d2: &Rational) -> Option<f64> {
    let d = Real::sqrt(d2);
    if &(&d * &d) != d2 {
        return None;
    }
    let f = Real::to_f64(&d);
    (rational_from_f64(f)? == d).then_some(f)
}

fn prev(x: f64) -> f64 {
    if x > 0.0 {
        f64::from_bits(x.to_bits() - 1)
    } else {
        -f64::MIN_POSITIVE
    }
}

/// Agreement with the oracle at `c`, and at an exactly representable distance `d`: true at `d`,
/// false at the `f64` just below.
fn check<A, B>(a: &A, b: &B, c: f64) -> Result<(), TestCaseError>
where
    A: WithinDistance<B>,
    B: WithinDistance<A>,
    for<'x> Shape: From<&'x A> + From<&'x B>,
{
    let (sa, sb) = (Shape::from(a), Shape::from(b));
    let expected = oracle::within_distance(&sa, &sb, c);
    prop_assert_eq!(a.within_distance(b, c), expected, "c = {}", c);
    prop_assert_eq!(b.within_distance(a, c), expected, "swapped, c = {}", c);
    if let (Shape::Hull(p), Shape::Hull(r)) = (&sa, &sb) {
        if let Some(d) = exact_f64_distance(&oracle::hulls_distance2(p, r)) {
            prop_assert!(a.within_distance(b, d), "at exactly d = {}", d);
            if d > 0.0 {
                prop_assert!(!a.within_distance(b, prev(d)), "just below d = {}", d);
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn segment_segment(a in segment(), b in segment(), c in clearance()) {
        check(&a, &b, c)?;
    }

    #[test]
    fn segment_triangle(a in segment(), b in triangle(), c in clearance()) {
        check(&a, &b, c)?;
    }

    #[test]
    fn triangle_triangle(a in triangle(), b in triangle(), c in clearance()) {
        check(&a, &b, c)?;
    }

    #[test]
    fn with_balls(s in segment(), t in triangle(), a in ball(), b in ball(), c in clearance()) {
        check(&s, &a, c)?;
        check(&t, &a, c)?;
        check(&a, &b, c)?;
    }

    #[test]
    fn with_spheres(s in segment(), t in triangle(), a in sphere(), b in sphere(), ball in ball(),
                    c in clearance()) {
        check(&s, &a, c)?;
        check(&t, &a, c)?;
        check(&a, &b, c)?;
        check(&ball, &a, c)?;
    }
}

#[test]
fn clearance_outside_zero_to_infinity() {
    let p = |x, y, z| Point3::new(x, y, z);
    let t = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
    let u = Triangle::new(p(0., 0., 5.), p(1., 0., 5.), p(0., 1., 5.)).unwrap();
    assert!(!t.within_distance(&t, -1.0));
    assert!(!t.within_distance(&u, f64::NAN));
    assert!(t.within_distance(&u, f64::INFINITY));
    assert!(t.within_distance(&u, 5.0) && !t.within_distance(&u, prev(5.0)));
    // Huge clearances and coordinates go through the exact path without overflow trouble.
    let far = Triangle::new(p(1e300, 0., 0.), p(1e300, 1., 0.), p(1e300, 0., 1.)).unwrap();
    assert!(t.within_distance(&far, 1e300) && !t.within_distance(&far, prev(1e300 - 1.0)));
}

/// Sphere surfaces: inside a sphere, the clearance is to the surface, not to the ball.
#[test]
fn inside_a_sphere_the_clearance_is_to_the_surface() {
    let s = Sphere::new(Point3::origin(), 3.0).unwrap();
    let t = Triangle::new(
        Point3::new(0., 0., 0.),
        Point3::new(1., 0., 0.),
        Point3::new(0., 1., 0.),
    )
    .unwrap();
    assert!(t.within_distance(&s, 2.0) && !t.within_distance(&s, prev(2.0)));
    assert!(t.within_distance(&Ball::from(s), 0.0));
}

fn oracle_mesh_pairs(a: &Collider, b: &Collider, c: f64) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for i in 0..a.mesh().num_triangles() {
        for j in 0..b.mesh().num_triangles() {
            let (p, r) = (a.mesh().corners(i as u32), b.mesh().corners(j as u32));
            if oracle::hulls_distance2(&p, &r) <= rational_from_f64(c).unwrap().pow(2) {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    /// Mesh clearance: the tree's pairs are exactly the oracle's (cubes, so the gaps are often
    /// exact: faces and edges at exactly `c`).
    #[test]
    fn mesh_pairs_match_the_oracle(
        t in (-3i32..=3, -3i32..=3, -3i32..=3),
        angle in prop_oneof![Just(0.0), 0.0f64..1.6],
        c in prop_oneof![(0i32..=3).prop_map(f64::from), 0.0f64..2.0],
    ) {
        let cube = Collider::new(
            TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.)).unwrap());
        let iso = Isometry3::new(
            Vector3::new(f64::from(t.0), f64::from(t.1), f64::from(t.2)) * 0.75,
            Vector3::z() * angle,
        );
        let moved = cube.placed(&iso).unwrap();
        let pairs = cube.pairs_within_distance(&moved, c);
        prop_assert_eq!(&pairs, &oracle_mesh_pairs(&cube, &moved, c));
        prop_assert_eq!(cube.within_distance(&moved, c), !pairs.is_empty());
    }
}

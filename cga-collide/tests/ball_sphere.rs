//! `query::intersects_ball_sphere`: the solid ball against the spherical surface, exactly, as
//! closed sets. A ball strictly inside the surface does not meet it; touching from outside or
//! from inside counts; a surface inside the ball is met. Checked on named cases (tangencies to
//! the last bit, at extreme scales) and against the independent exact oracle.

use cga_collide::nalgebra::Point3;
use cga_collide::query::{intersects_ball_sphere, within_distance_ball_sphere};
use cga_collide::testing::oracle::{self, Shape};
use cga_collide::{Ball, Intersects, Sphere};
use proptest::prelude::*;

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

fn ball(c: Point3<f64>, r: f64) -> Ball {
    Ball::new(c, r).unwrap()
}

fn sphere(c: Point3<f64>, r: f64) -> Sphere {
    Sphere::new(c, r).unwrap()
}

/// The answer in both argument orders, which must agree.
fn meets(b: &Ball, s: &Sphere) -> bool {
    let answer = intersects_ball_sphere(b, s);
    assert_eq!(b.intersects(s), answer, "{b:?} {s:?}");
    assert_eq!(s.intersects(b), answer, "swapped {b:?} {s:?}");
    answer
}

fn below(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

fn above(x: f64) -> f64 {
    f64::from_bits(x.to_bits() + 1)
}

#[test]
fn apart_and_external_tangency() {
    // 3-4-5: the centres are 5 apart.
    let s = sphere(p(3., 4., 0.), 3.);
    assert!(meets(&ball(p(0., 0., 0.), 2.), &s), "touching from outside");
    assert!(!meets(&ball(p(0., 0., 0.), below(2.)), &s), "one ulp apart");
    assert!(
        meets(&ball(p(0., 0., 0.), above(2.)), &s),
        "one ulp overlapping"
    );
    assert!(!meets(&ball(p(0., 0., 0.), 1.), &s), "apart");
}

#[test]
fn a_ball_strictly_inside_the_surface_does_not_meet_it() {
    let s = sphere(p(0., 0., 0.), 5.);
    // Centre 3-4-0 away (distance 5) would be on the surface; these are well inside.
    assert!(!meets(&ball(p(0., 0., 0.), 1.), &s), "concentric, smaller");
    assert!(!meets(&ball(p(1., 1., 1.), 2.), &s));
    // Touching the surface from inside: |c1 - c2| + r1 = r2 exactly (5 + 2 = 7).
    let s7 = sphere(p(0., 0., 0.), 7.);
    assert!(meets(&ball(p(3., 4., 0.), 2.), &s7), "internally tangent");
    assert!(
        !meets(&ball(p(3., 4., 0.), below(2.)), &s7),
        "one ulp inside"
    );
    assert!(
        meets(&ball(p(3., 4., 0.), above(2.)), &s7),
        "one ulp across"
    );
    // A point (radius 0) inside, on and outside the surface.
    assert!(!meets(&ball(p(3., 0., 0.), 0.), &s));
    assert!(meets(&ball(p(3., 4., 0.), 0.), &s));
    assert!(!meets(&ball(p(3., 4., above(0.)), 0.), &s));
}

#[test]
fn a_surface_inside_the_ball_or_equal_to_its_boundary_is_met() {
    // The solid ball contains the whole surface: the surface is part of the ball.
    assert!(meets(&ball(p(0., 0., 0.), 10.), &sphere(p(1., 2., 3.), 1.)));
    // The ball's own boundary.
    assert!(meets(&ball(p(1., 2., 3.), 4.), &sphere(p(1., 2., 3.), 4.)));
    // A point sphere inside the ball, on its boundary, outside it.
    assert!(meets(&ball(p(0., 0., 0.), 5.), &sphere(p(1., 1., 1.), 0.)));
    assert!(meets(&ball(p(0., 0., 0.), 5.), &sphere(p(3., 4., 0.), 0.)));
    assert!(!meets(
        &ball(p(0., 0., 0.), 5.),
        &sphere(p(3., 4., 1e-300), 0.)
    ));
}

#[test]
fn tangencies_hold_at_extreme_scales() {
    // Powers of two, so that the scaled tangencies stay exact.
    for scale in [
        2f64.powi(-500),
        2f64.powi(-300),
        1.0,
        2f64.powi(300),
        2f64.powi(500),
    ] {
        let q = |x: f64, y: f64, z: f64| p(x * scale, y * scale, z * scale);
        let outer = sphere(q(0., 0., 0.), 7. * scale);
        assert!(
            meets(&ball(q(3., 4., 0.), 2. * scale), &outer),
            "inner tangency at {scale}"
        );
        assert!(
            !meets(&ball(q(3., 4., 0.), below(2. * scale)), &outer),
            "inside at {scale}"
        );
        let s = sphere(q(3., 4., 0.), 3. * scale);
        assert!(
            meets(&ball(q(0., 0., 0.), 2. * scale), &s),
            "outer tangency at {scale}"
        );
        assert!(
            !meets(&ball(q(0., 0., 0.), below(2. * scale)), &s),
            "apart at {scale}"
        );
    }
}

fn small_int() -> impl Strategy<Value = f64> {
    (-4i32..=4).prop_map(f64::from)
}

fn int_point() -> impl Strategy<Value = Point3<f64>> {
    (small_int(), small_int(), small_int()).prop_map(|(x, y, z)| p(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Small integers make exact tangencies (from outside and inside) and concentric pairs
    /// common; random radii the general case; the oracle is exact rational arithmetic.
    #[test]
    fn agrees_with_the_oracle(
        c1 in int_point(),
        c2 in int_point(),
        r1 in (0i32..=6).prop_map(f64::from),
        r2 in (0i32..=6).prop_map(f64::from),
        jitter in 0.0f64..3.0,
        scale in prop::sample::select(vec![1e-150, 1.0, 0.1, 1e150]),
    ) {
        let sc = |q: Point3<f64>| p(q.x * scale, q.y * scale, q.z * scale);
        for (r1, r2) in [(r1, r2), (r1 + jitter, r2), (r1, r2 + jitter)] {
            let (b, s) = (ball(sc(c1), r1 * scale), sphere(sc(c2), r2 * scale));
            let truth = oracle::intersects(&Shape::from(&b), &Shape::from(&s));
            prop_assert_eq!(meets(&b, &s), truth, "{:?} {:?}", b, s);
            // Clearance zero is the same question.
            prop_assert_eq!(within_distance_ball_sphere(&b, &s, 0.0), truth);
        }
    }
}

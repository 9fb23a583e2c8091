//! Constructors: bad input is rejected with a typed error naming the argument.

use cga_collide::nalgebra::Point3;
use cga_collide::{testing::baseline, Ball, Error, Segment, Sphere, Triangle};

#[test]
fn rejects_non_finite_coordinates_naming_the_argument() {
    let o = Point3::origin();
    let bad = Point3::new(0.0, 0.0, f64::NEG_INFINITY);
    let e = Segment::new(o, bad).unwrap_err();
    assert_eq!(
        e,
        Error::NonFiniteCoordinate {
            shape: "Segment",
            argument: "b",
            axis: "z",
            value: f64::NEG_INFINITY
        }
    );
    assert!(e.to_string().contains("argument `b`"), "{e}");
    let e = Triangle::new(Point3::new(f64::NAN, 0.0, 0.0), o, o).unwrap_err();
    assert!(matches!(
        e,
        Error::NonFiniteCoordinate {
            argument: "a",
            axis: "x",
            ..
        }
    ));
    assert!(matches!(
        Sphere::new(bad, 1.0),
        Err(Error::NonFiniteCoordinate {
            shape: "Sphere",
            argument: "centre",
            ..
        })
    ));
    assert!(matches!(
        Ball::new(bad, 1.0),
        Err(Error::NonFiniteCoordinate { shape: "Ball", .. })
    ));
}

#[test]
fn rejects_bad_radii() {
    let o = Point3::origin();
    assert_eq!(
        Sphere::new(o, -0.5).unwrap_err(),
        Error::NegativeRadius {
            shape: "Sphere",
            value: -0.5
        }
    );
    assert!(matches!(
        Ball::new(o, f64::INFINITY),
        Err(Error::NonFiniteRadius { shape: "Ball", .. })
    ));
    assert!(Ball::new(o, f64::NAN)
        .unwrap_err()
        .to_string()
        .contains("not finite"));
    // Zero radius is a point, and degenerate segments/triangles are valid.
    assert!(Sphere::new(o, 0.0).is_ok());
    assert!(Segment::new(o, o).is_ok());
    assert!(Triangle::new(o, o, o).is_ok());
}

#[test]
fn references_on_simple_cases() {
    let p = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
    let t1 = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
    let far = Triangle::new(p(0., 0., 5.), p(1., 0., 5.), p(0., 1., 5.)).unwrap();
    let cross = Triangle::new(p(0.2, 0.2, -1.), p(0.2, 0.2, 1.), p(3., 3., 0.)).unwrap();
    let cop = Triangle::new(p(0.1, 0.1, 0.), p(3., 0.1, 0.), p(0.1, 3., 0.)).unwrap();
    let cop_far = Triangle::new(p(2., 2., 0.), p(3., 2., 0.), p(2., 3., 0.)).unwrap();
    assert!(!baseline::moller_tri_tri(&t1, &far));
    assert!(baseline::moller_tri_tri(&t1, &cross));
    assert!(baseline::moller_tri_tri(&t1, &cop));
    assert!(!baseline::moller_tri_tri(&t1, &cop_far));
    let s = Segment::new(p(0.25, 0.25, 1.), p(0.25, 0.25, -1.)).unwrap();
    assert!(baseline::moller_trumbore_segment_triangle(&s, &t1));
    assert!(!baseline::moller_trumbore_segment_triangle(&s, &far));
    let b = Ball::new(p(0.25, 0.25, 0.5), 0.5).unwrap();
    assert!(baseline::triangle_ball(&t1, &b));
    assert!(!baseline::triangle_sphere(
        &t1,
        &Sphere::new(p(0.2, 0.2, 0.), 10.0).unwrap()
    ));
    assert!(baseline::segment_sphere(&s, &Sphere::from(b)));
    assert!(baseline::sphere_sphere(
        &Sphere::new(p(0., 0., 0.), 1.).unwrap(),
        &Sphere::new(p(2., 0., 0.), 1.).unwrap()
    ));
    assert!(!baseline::ball_ball(
        &Ball::new(p(0., 0., 0.), 1.).unwrap(),
        &Ball::new(p(2.5, 0., 0.), 1.).unwrap()
    ));
}

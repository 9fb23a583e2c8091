//! Cylinders and cones against every other shape: constructed contacts whose truth is known by
//! construction (dyadic values, so the tangency is exact), the same moved by one ulp both
//! ways, containment, zero radii, and scales `2^±300`.

use cga_collide::ga_core::scalar::rational_from_f64;
use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::query::{intersects, within_distance};
use cga_collide::shape::{Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Shape};
use cga_collide::{Ball, Error, Segment, Triangle};

fn p(s: f64, x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(s * x, s * y, s * z)
}

fn cyl(a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    Cylinder::new(a, b, r).unwrap().into()
}

fn cone(apex: Point3<f64>, base: Point3<f64>, r: f64) -> Shape {
    Cone::new(apex, base, r).unwrap().into()
}

fn ball(c: Point3<f64>, r: f64) -> Shape {
    Ball::new(c, r).unwrap().into()
}

fn ground(s: f64, z: f64) -> Shape {
    HalfSpace::new(p(s, 0.0, 0.0, z), Vector3::z())
        .unwrap()
        .into()
}

fn boxed(c: Point3<f64>, h: [f64; 3]) -> Shape {
    Cuboid::axis_aligned(c, Vector3::new(h[0], h[1], h[2]))
        .unwrap()
        .into()
}

/// Both argument orders give `expected`, for `intersects` and for `within_distance(0)`.
fn check(name: &str, a: &Shape, b: &Shape, expected: bool) {
    for (x, y) in [(a, b), (b, a)] {
        let got = intersects(x, y).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(got, expected, "{name}: intersects({x:?}, {y:?})");
        let got = within_distance(x, y, 0.0).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(got, expected, "{name}: within_distance 0");
    }
}

/// A family touching at `t = t0`: `build(scale, t)` with `t0` (touching), the next `f64`
/// above and below; `apart` says which side of `t0` separates the shapes.
struct Family {
    name: &'static str,
    t0: f64,
    apart_above: bool,
    build: fn(f64, f64) -> (Shape, Shape),
}

fn run(f: &Family) {
    for k in [0, 300, -300] {
        let s = 2f64.powi(k);
        let t0 = f.t0 * s;
        let (a, b) = (f.build)(s, t0);
        check(&format!("{} touching at 2^{k}", f.name), &a, &b, true);
        let (up, down) = (t0.next_up(), t0.next_down());
        let (a, b) = (f.build)(s, up);
        check(&format!("{} up at 2^{k}", f.name), &a, &b, !f.apart_above);
        let (a, b) = (f.build)(s, down);
        check(&format!("{} down at 2^{k}", f.name), &a, &b, f.apart_above);
    }
}

#[test]
fn cylinders_and_cones_on_half_spaces() {
    let families = [
        Family {
            name: "cylinder lying on a plane",
            t0: 1.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(
                        p(s, 0.0, 0.0, 0.0) + Vector3::new(0.0, 0.0, z),
                        p(s, 4.0, 0.0, 0.0) + Vector3::new(0.0, 0.0, z),
                        s,
                    ),
                    ground(s, 0.0),
                )
            },
        },
        Family {
            name: "oblique cylinder on its rim",
            t0: 1.5,
            apart_above: true,
            // axis (3, 0, 4)/5, radius 2.5: the rim reaches 1.5 below the cap centre.
            build: |s, z| {
                (
                    cyl(
                        Point3::new(0.0, 0.0, z),
                        Point3::new(3.0 * s, 0.0, z + 4.0 * s),
                        2.5 * s,
                    ),
                    ground(s, 0.0),
                )
            },
        },
        Family {
            name: "cone standing on its base",
            t0: 0.0,
            apart_above: true,
            build: |s, z| {
                (
                    cone(
                        p(s, 0.0, 0.0, 2.0) + Vector3::new(0.0, 0.0, z),
                        Point3::new(0.0, 0.0, z),
                        s,
                    ),
                    ground(s, 0.0),
                )
            },
        },
        Family {
            name: "cone standing on its apex",
            t0: 0.0,
            apart_above: true,
            build: |s, z| {
                (
                    cone(
                        Point3::new(0.0, 0.0, z),
                        p(s, 1.0, 0.0, 2.0) + Vector3::new(0.0, 0.0, z),
                        s,
                    ),
                    ground(s, 0.0),
                )
            },
        },
        Family {
            name: "cone lying on its slant",
            t0: 2.0,
            apart_above: true,
            // axis (4, 0, -3)/5 from the apex on the plane, tan(half angle) = 3/4 = r/5: the
            // slant line from the apex runs along the plane z = 2.
            build: |s, z| {
                (
                    cone(p(s, 0.0, 0.0, 2.0), p(s, 4.0, 0.0, -1.0), 3.75 * s),
                    HalfSpace::new(Point3::new(0.0, 0.0, z), -Vector3::z())
                        .unwrap()
                        .into(),
                )
            },
        },
    ];
    for f in &families {
        run(f);
    }
}

#[test]
fn an_irrational_tangency_is_decided_exactly() {
    // Axis (1, 1, 1) from height h, radius 1: the lowest rim point is at h − √(2/3).
    let h0 = (2.0f64 / 3.0).sqrt();
    for h in [h0.next_down(), h0, h0.next_up()] {
        let a = cyl(
            Point3::new(0.0, 0.0, h),
            Point3::new(1.0, 1.0, h + 1.0),
            1.0,
        );
        let hr = rational_from_f64(h).unwrap();
        let truth = &hr * &hr * cga_collide::ga_core::scalar::Rational::from_integer(3.into())
            <= cga_collide::ga_core::scalar::Rational::from_integer(2.into());
        check("irrational rim", &a, &ground(1.0, 0.0), truth);
    }
}

#[test]
fn balls_on_cylinders_and_cones() {
    let families = [
        Family {
            name: "ball on a cylinder's side",
            t0: 1.0,
            apart_above: false,
            build: |s, r| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    ball(p(s, 2.0, 0.0, 2.0), r),
                )
            },
        },
        Family {
            name: "ball on a cylinder's cap",
            t0: 1.0,
            apart_above: false,
            build: |s, r| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    ball(p(s, 0.5, 0.25, 5.0), r),
                )
            },
        },
        Family {
            name: "ball on a cylinder's rim",
            t0: 0.625,
            apart_above: false,
            build: |s, r| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    ball(p(s, 1.375, 0.0, 4.5), r),
                )
            },
        },
        Family {
            name: "ball on a cone's apex",
            t0: 3.0,
            apart_above: true,
            build: |s, z| {
                (
                    cone(p(s, 0.0, 0.0, 2.0), p(s, 0.0, 0.0, 0.0), s),
                    ball(Point3::new(0.0, 0.0, z), s),
                )
            },
        },
        Family {
            name: "ball on a cone's rim",
            t0: 0.625,
            apart_above: false,
            // direction (3, 0, -4)/5 from the rim point (1, 0, 0) is in the rim's normal cone.
            build: |s, r| {
                (
                    cone(p(s, 0.0, 0.0, 2.0), p(s, 0.0, 0.0, 0.0), s),
                    ball(p(s, 1.375, 0.0, -0.5), r),
                )
            },
        },
        Family {
            name: "ball on a cone's slant",
            t0: 1.25,
            apart_above: false,
            // slant from (3, 0, 0) to the apex (0, 0, 4), outward normal (4, 0, 3)/5.
            build: |s, r| {
                (
                    cone(p(s, 0.0, 0.0, 4.0), p(s, 0.0, 0.0, 0.0), 3.0 * s),
                    ball(p(s, 2.5, 0.0, 2.75), r),
                )
            },
        },
    ];
    for f in &families {
        run(f);
    }
}

#[test]
fn cylinders_and_cones_on_boxes_and_polygons() {
    let families = [
        Family {
            name: "cylinder lying on a box face",
            t0: 1.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(
                        p(s, -1.0, 0.0, 0.0) + Vector3::new(0.0, 0.0, z),
                        p(s, 1.0, 0.0, 0.0) + Vector3::new(0.0, 0.0, z),
                        s,
                    ),
                    boxed(p(s, 0.0, 0.0, -1.0), [3.0 * s, 3.0 * s, s]),
                )
            },
        },
        Family {
            name: "cylinder standing on a box corner region",
            t0: 0.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(
                        Point3::new(2.5 * s, 2.5 * s, z),
                        Point3::new(2.5 * s, 2.5 * s, z + 2.0 * s),
                        s,
                    ),
                    boxed(p(s, 0.0, 0.0, -1.0), [3.0 * s, 3.0 * s, s]),
                )
            },
        },
        Family {
            name: "box edge along a cylinder",
            t0: 2.0,
            apart_above: true,
            // a box turned 45 degrees about x, its lowest edge the line y = 0, z = centre − 1.
            build: |s, z| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 4.0, 0.0, 0.0), s),
                    Cuboid::new(
                        Point3::new(2.0 * s, 0.0, z),
                        [
                            Vector3::new(2.0 * s, 0.0, 0.0),
                            Vector3::new(0.0, 0.5 * s, 0.5 * s),
                            Vector3::new(0.0, -0.5 * s, 0.5 * s),
                        ],
                    )
                    .unwrap()
                    .into(),
                )
            },
        },
        Family {
            name: "box corner on a cylinder's rim",
            t0: 2.0,
            apart_above: true,
            // the rim point (1, 0, 4); the box's face x = centre − 1 and its bottom z = 4.
            build: |s, x| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    boxed(Point3::new(x, 0.0, 5.0 * s), [s, s, s]),
                )
            },
        },
        Family {
            name: "triangle on a cylinder's side",
            t0: 1.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 4.0, 0.0, 0.0), s),
                    Triangle::new(
                        Point3::new(s, -s, z),
                        Point3::new(3.0 * s, -s, z),
                        Point3::new(2.0 * s, s, z),
                    )
                    .unwrap()
                    .into(),
                )
            },
        },
        Family {
            name: "segment crossing over a cylinder",
            t0: 1.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 4.0, 0.0, 0.0), s),
                    Segment::new(
                        Point3::new(s, -5.0 * s, z),
                        Point3::new(3.0 * s, 5.0 * s, z),
                    )
                    .unwrap()
                    .into(),
                )
            },
        },
        Family {
            name: "cone standing on its apex on a box",
            t0: 0.0,
            apart_above: true,
            build: |s, z| {
                (
                    cone(
                        Point3::new(0.5 * s, 0.0, z),
                        p(s, 0.5, 0.0, 2.0) + Vector3::new(0.0, 0.0, z),
                        s,
                    ),
                    boxed(p(s, 0.0, 0.0, -1.0), [3.0 * s, 3.0 * s, s]),
                )
            },
        },
        Family {
            name: "cone standing on its base on a box",
            t0: 0.0,
            apart_above: true,
            build: |s, z| {
                (
                    cone(
                        p(s, 0.0, 0.0, 2.0) + Vector3::new(0.0, 0.0, z),
                        Point3::new(0.0, 0.0, z),
                        s,
                    ),
                    boxed(p(s, 0.0, 0.0, -1.0), [3.0 * s, 3.0 * s, s]),
                )
            },
        },
        Family {
            name: "cone lying on its slant on a box",
            t0: 7.0,
            apart_above: true,
            // the box's bottom face is z = centre − 5, the cone's top slant line z = 2.
            build: |s, z| {
                (
                    cone(p(s, 1.0, 0.0, 2.0), p(s, 5.0, 0.0, -1.0), 3.75 * s),
                    boxed(Point3::new(2.0 * s, 0.0, z), [5.0 * s, 5.0 * s, 5.0 * s]),
                )
            },
        },
        Family {
            name: "cone apex against a hull's face",
            t0: 0.0,
            apart_above: false,
            build: |s, x| {
                (
                    cone(Point3::new(x, 0.0, 0.0), p(s, -2.0, 0.0, 0.0), s),
                    ConvexHull::new(vec![
                        p(s, 0.0, -1.0, -1.0),
                        p(s, 0.0, 1.0, -1.0),
                        p(s, 0.0, 0.0, 1.0),
                        p(s, 2.0, 0.0, 0.0),
                    ])
                    .unwrap()
                    .into(),
                )
            },
        },
        Family {
            name: "segment grazing a cone's rim",
            t0: 1.0,
            apart_above: true,
            build: |s, x| {
                (
                    cone(p(s, 0.0, 0.0, 2.0), p(s, 0.0, 0.0, 0.0), s),
                    Segment::new(Point3::new(x, -s, 0.0), Point3::new(x, s, 0.0))
                        .unwrap()
                        .into(),
                )
            },
        },
        Family {
            name: "hull along a cone's slant, touching the apex plane",
            t0: 0.0,
            apart_above: false,
            // the hull lies in x >= z/2 and holds the slant segment from (0.5, 0, 1) to
            // (1, 0, 2); its vertex (1, 0, 0) is on the apex plane z = 0 (the rays' case).
            // The cone moves along x.
            build: |s, x| {
                (
                    cone(Point3::new(x, 0.0, 0.0), Point3::new(x, 0.0, 2.0 * s), s),
                    ConvexHull::new(vec![
                        p(s, 0.5, 0.0, 1.0),
                        p(s, 1.0, 0.0, 2.0),
                        p(s, 1.0, 0.0, 0.0),
                        p(s, 2.0, 1.0, 1.0),
                        p(s, 2.0, -1.0, 1.0),
                    ])
                    .unwrap()
                    .into(),
                )
            },
        },
    ];
    for f in &families {
        run(f);
    }
}

#[test]
fn containment_and_zero_radii() {
    let c = cyl(Point3::origin(), Point3::new(0.0, 0.0, 4.0), 2.0);
    check(
        "small box inside",
        &c,
        &boxed(Point3::new(0.0, 0.0, 2.0), [0.5; 3]),
        true,
    );
    check(
        "cylinder inside a big box",
        &c,
        &boxed(Point3::origin(), [10.0; 3]),
        true,
    );
    check(
        "ball inside",
        &c,
        &ball(Point3::new(0.5, 0.0, 1.0), 0.25),
        true,
    );
    check(
        "cylinder inside a ball",
        &c,
        &ball(Point3::origin(), 100.0),
        true,
    );
    let k = cone(Point3::new(0.0, 0.0, 4.0), Point3::origin(), 2.0);
    check(
        "triangle inside a cone",
        &k,
        &Triangle::new(
            Point3::new(0.1, 0.0, 1.0),
            Point3::new(-0.1, 0.1, 1.0),
            Point3::new(0.0, -0.1, 1.5),
        )
        .unwrap()
        .into(),
        true,
    );
    check(
        "cone inside a hull",
        &k,
        &ConvexHull::new(vec![
            Point3::new(-9.0, -9.0, -1.0),
            Point3::new(9.0, -9.0, -1.0),
            Point3::new(0.0, 9.0, -1.0),
            Point3::new(0.0, 0.0, 20.0),
        ])
        .unwrap()
        .into(),
        true,
    );
    // Radius 0: the axis segment.
    let thin = cyl(Point3::origin(), Point3::new(0.0, 0.0, 4.0), 0.0);
    check(
        "thin cylinder against a ball at its end",
        &thin,
        &ball(Point3::new(0.0, 0.0, 5.0), 1.0),
        true,
    );
    check(
        "thin cylinder beside a ball",
        &thin,
        &ball(Point3::new(1.0, 0.0, 2.0), 1.0f64.next_down()),
        false,
    );
    check("thin cylinder on a plane", &thin, &ground(1.0, 0.0), true);
    let needle = cone(Point3::origin(), Point3::new(4.0, 0.0, 0.0), 0.0);
    check(
        "needle through a box",
        &needle,
        &boxed(Point3::new(2.0, 0.0, 0.0), [0.5; 3]),
        true,
    );
    check(
        "thin cylinder against a cylinder",
        &thin,
        &cyl(Point3::new(-1.0, 1.0, 2.0), Point3::new(1.0, 1.0, 2.0), 1.0),
        true,
    );
    check(
        "thin cylinder apart from a cylinder",
        &thin,
        &cyl(
            Point3::new(-1.0, 1.0, 2.0),
            Point3::new(1.0, 1.0, 2.0),
            1.0f64.next_down(),
        ),
        false,
    );
}

#[test]
fn within_distance_is_exact_for_balls_and_planes() {
    let c = cyl(Point3::new(0.0, 0.0, 1.0), Point3::new(4.0, 0.0, 1.0), 1.0);
    let gap = 2f64.powi(-40);
    let floor = ground(1.0, -gap);
    assert!(!intersects(&c, &floor).unwrap());
    assert!(within_distance(&c, &floor, gap).unwrap());
    assert!(!within_distance(&c, &floor, gap.next_down()).unwrap());
    // An oblique normal: the plane x + z <= -√2·gap·... use a normal (3, 0, 4): distance is
    // (n·x − n·p)/5 exactly.
    let tilted: Shape = HalfSpace::new(Point3::new(-5.0, 0.0, 0.0), Vector3::new(3.0, 0.0, 4.0))
        .unwrap()
        .into();
    // lowest point of the cylinder along (3,0,4)/5: cap a at (0,0,1): 4/5·1 − 1·|n×d|/|d|/5
    // = 0.8 − 0.8 = 0; the plane is at n·x = −15, i.e. distance 3.
    assert!(within_distance(&c, &tilted, 3.0).unwrap());
    assert!(!within_distance(&c, &tilted, 3.0f64.next_down()).unwrap());
    let b = ball(Point3::new(0.0, 3.0, 1.0), 1.0);
    assert!(within_distance(&c, &b, 1.0).unwrap());
    assert!(!within_distance(&c, &b, 1.0f64.next_down()).unwrap());
    let k = cone(Point3::new(0.0, 0.0, 2.0), Point3::origin(), 1.0);
    let b = ball(Point3::new(1.375, 0.0, -0.5), 0.5);
    assert!(within_distance(&k, &b, 0.125).unwrap());
    assert!(!within_distance(&k, &b, 0.125f64.next_down()).unwrap());
}

#[test]
fn unsupported_pairs_say_so() {
    let a = cyl(Point3::origin(), Point3::new(0.0, 0.0, 4.0), 1.0);
    let b = cyl(Point3::new(5.0, 0.0, 0.0), Point3::new(5.0, 3.0, 4.0), 1.0);
    match intersects(&a, &b) {
        Ok(_) => {}
        Err(Error::UnsupportedPair { a, b, .. }) => assert_eq!((a, b), ("cylinder", "cylinder")),
        Err(e) => panic!("{e}"),
    }
    // Half a unit apart: within 1, but no exact method for a box and `c > 0` yet (a box 3
    // apart is proved beyond 1 by the filter, and answered).
    let boxy = boxed(Point3::new(2.5, 0.0, 0.0), [1.0; 3]);
    assert!(!within_distance(&a, &boxed(Point3::new(5.0, 0.0, 0.0), [1.0; 3]), 1.0).unwrap());
    assert!(matches!(
        within_distance(&a, &boxy, 1.0),
        Err(Error::UnsupportedPair { .. })
    ));
}

#[test]
fn parallel_and_crossed_cylinders() {
    let families = [
        Family {
            name: "parallel cylinders r1 + r2 apart",
            t0: 1.5,
            apart_above: true,
            build: |s, x| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    cyl(
                        Point3::new(x, 0.0, s),
                        Point3::new(x, 0.0, 5.0 * s),
                        0.5 * s,
                    ),
                )
            },
        },
        Family {
            name: "opposite parallel cylinders end to end",
            t0: 4.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    cyl(
                        Point3::new(0.25 * s, 0.0, z + 3.0 * s),
                        Point3::new(0.25 * s, 0.0, z),
                        0.5 * s,
                    ),
                )
            },
        },
        Family {
            name: "crossed cylinders touching",
            t0: 2.0,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(p(s, -2.0, 0.0, 0.0), p(s, 2.0, 0.0, 0.0), s),
                    cyl(
                        Point3::new(0.0, -2.0 * s, z),
                        Point3::new(0.0, 2.0 * s, z),
                        s,
                    ),
                )
            },
        },
        Family {
            name: "crossed cylinder and capsule touching",
            t0: 1.5,
            apart_above: true,
            build: |s, z| {
                (
                    cyl(p(s, -2.0, 0.0, 0.0), p(s, 2.0, 0.0, 0.0), s),
                    cga_collide::shape::Capsule::new(
                        Point3::new(0.0, -2.0 * s, z),
                        Point3::new(0.0, 2.0 * s, z),
                        0.5 * s,
                    )
                    .unwrap()
                    .into(),
                )
            },
        },
    ];
    for f in &families {
        run(f);
    }
    let a = cyl(Point3::origin(), Point3::new(0.0, 0.0, 4.0), 1.0);
    let b = cyl(Point3::new(2.0, 0.0, 5.0), Point3::new(2.0, 0.0, 9.0), 0.5);
    // axial gap 1, radial gap 0.5: distance √1.25.
    let d = 1.25f64.sqrt();
    let inside = within_distance(&a, &b, d.next_up()).unwrap()
        && !within_distance(&a, &b, d.next_down()).unwrap();
    assert!(inside);
}

#[test]
fn certified_distances_to_balls_and_planes() {
    let gap = 2f64.powi(-40);
    let c = cyl(Point3::new(0.0, 0.0, 1.0), Point3::new(4.0, 0.0, 1.0), 1.0);
    let floor = ground(1.0, -gap);
    let d = cga_collide::query::distance(&c, &floor).unwrap();
    assert!(
        d.distance - d.error_bound <= gap && gap <= d.distance + d.error_bound,
        "{d:?}"
    );
    assert!(d.error_bound <= 1e-13, "{d:?}");
    let d = cga_collide::query::distance(&floor, &c).unwrap();
    assert!(
        (d.witness_a.z + gap).abs() < 1e-15 && (d.witness_b.z - 0.0).abs() < 1e-15,
        "{d:?}"
    );
    let k = cone(Point3::new(0.0, 0.0, 2.0), Point3::origin(), 1.0);
    let b = ball(Point3::new(1.375, 0.0, -0.5), 0.5);
    let d = cga_collide::query::distance(&k, &b).unwrap();
    assert!(
        d.distance - d.error_bound <= 0.125 && 0.125 <= d.distance + d.error_bound,
        "{d:?}"
    );
    assert!(d.error_bound < 1e-12, "{d:?}");
    let touching = ball(Point3::new(1.375, 0.0, -0.5), 0.625);
    let d = cga_collide::query::distance(&touching, &k).unwrap();
    assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
    let inside = ball(Point3::new(0.0, 0.0, 0.5), 0.125);
    assert_eq!(
        cga_collide::query::distance(&k, &inside).unwrap().distance,
        0.0
    );
}

fn capsule(a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    cga_collide::shape::Capsule::new(a, b, r).unwrap().into()
}

#[test]
fn capsules_on_cylinders_and_cones() {
    let families = [
        // Along the side: the capsule's axis at x = t, radius 1/2, against radius 1.
        Family {
            name: "capsule along a cylinder's side",
            t0: 1.5,
            apart_above: true,
            build: |s, x| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    capsule(
                        Point3::new(x, 0.0, s),
                        Point3::new(x, 0.0, 3.0 * s),
                        0.5 * s,
                    ),
                )
            },
        },
        // Across past the rim, the nearest axis point (3/2, 0, 4 + 3/4)·s is 5/4·s from the
        // rim circle of radius 1 at height 4: touching at radius 5/4.
        Family {
            name: "capsule across a cylinder's rim",
            t0: 1.25,
            apart_above: false,
            build: |s, r| {
                (
                    cyl(p(s, 0.0, 0.0, 0.0), p(s, 0.0, 0.0, 4.0), s),
                    capsule(p(s, 2.0, -4.0, 4.75), p(s, 2.0, 5.0, 4.75), r),
                )
            },
        },
        // Along a generator of the cone (apex 0, base height 4, radius 3: the generator through
        // (3/4, 0, 1) and (9/4, 0, 3) has the outward normal (4, 0, −3)/5): the capsule's axis
        // is that segment moved by (1, 0, −3/4), 5/4 out.
        Family {
            name: "capsule along a cone's generator",
            t0: 1.25,
            apart_above: false,
            build: |s, r| {
                (
                    cone(Point3::origin(), p(s, 0.0, 0.0, 4.0), 3.0 * s),
                    capsule(p(s, 1.75, 0.0, 0.25), p(s, 3.25, 0.0, 2.25), r),
                )
            },
        },
    ];
    for f in &families {
        run(f);
    }
    // within_distance at the exact threshold, and a certified distance around it.
    let c = cyl(Point3::origin(), Point3::new(0.0, 0.0, 4.0), 1.0);
    let k = capsule(
        Point3::new(2.0, -4.0, 4.75),
        Point3::new(2.0, 5.0, 4.75),
        0.25,
    );
    assert!(within_distance(&c, &k, 1.0).unwrap());
    assert!(!within_distance(&k, &c, 1.0f64.next_down()).unwrap());
    for (x, y) in [(&c, &k), (&k, &c)] {
        let d = cga_collide::query::distance(x, y).unwrap();
        assert!(
            d.distance - d.error_bound <= 1.0 && 1.0 <= d.distance + d.error_bound,
            "{d:?}"
        );
        assert!(d.error_bound < 1e-9, "{d:?}");
    }
}

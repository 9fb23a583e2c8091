//! Constructed tangencies with known truth, the same moved by one ulp either way, containment,
//! degenerate shapes, scales `2^±300`, and agreement with a brute-force rational oracle.

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

use super::cores::Core;
use super::feature;
use super::{distance, intersects, within_distance};
use crate::query::exact_distance_triangle_triangle;
use crate::shape::{Ball, Capsule, ConvexHull, Cuboid, HalfSpace, Segment, Shape, Triangle};

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

fn cuboid(c: Point3<f64>, axes: [Vector3<f64>; 3]) -> Shape {
    Cuboid::new(c, axes).unwrap().into()
}

fn aabb(c: Point3<f64>, h: f64) -> Shape {
    Cuboid::axis_aligned(c, v(h, h, h)).unwrap().into()
}

fn capsule(a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    Capsule::new(a, b, r).unwrap().into()
}

fn ball(c: Point3<f64>, r: f64) -> Shape {
    Ball::new(c, r).unwrap().into()
}

fn hull(points: &[Point3<f64>]) -> Shape {
    ConvexHull::new(points.to_vec()).unwrap().into()
}

fn half(point: Point3<f64>, normal: Vector3<f64>) -> Shape {
    HalfSpace::new(point, normal).unwrap().into()
}

/// Both argument orders agree on `intersects`, and `distance` agrees with it.
fn meets(a: &Shape, b: &Shape) -> bool {
    let answer = intersects(a, b);
    assert_eq!(answer, intersects(b, a), "order matters for {a:?} {b:?}");
    assert_eq!(answer, within_distance(a, b, 0.0));
    for (x, y) in [(a, b), (b, a)] {
        let d = distance(x, y);
        assert!(d.error_bound.is_finite() && d.distance.is_finite(), "{d:?}");
        if answer {
            assert!(d.distance <= d.error_bound, "{d:?} for meeting shapes");
        } else {
            assert!(d.distance + d.error_bound > 0.0, "{d:?} for apart shapes");
        }
    }
    answer
}

/// The shape scaled by `2^k` (exact for the values used here).
fn scaled(s: &Shape, k: i32) -> Shape {
    let f = 2f64.powi(k);
    let sp = |q: &Point3<f64>| q * f;
    match s {
        Shape::Ball(b) => ball(sp(b.centre()), b.radius() * f),
        Shape::Capsule(c) => capsule(sp(c.a()), sp(c.b()), c.radius() * f),
        Shape::Cuboid(c) => cuboid(sp(c.centre()), c.half_axes().map(|h| h * f)),
        Shape::ConvexHull(h) => hull(&h.points().iter().map(sp).collect::<Vec<_>>()),
        Shape::HalfSpace(h) => half(sp(h.point()), *h.normal()),
        Shape::Triangle(t) => {
            let [a, b, c] = t.vertices();
            Triangle::new(sp(a), sp(b), sp(c)).unwrap().into()
        }
        Shape::Segment(g) => Segment::new(sp(g.a()), sp(g.b())).unwrap().into(),
        other => other.clone(),
    }
}

/// `meets` at scales `2^-300`, `1` and `2^300`, all giving `expected`.
fn check_at_scales(a: &Shape, b: &Shape, expected: bool) {
    for k in [-300, 0, 300] {
        assert_eq!(
            meets(&scaled(a, k), &scaled(b, k)),
            expected,
            "scale 2^{k}: {a:?} {b:?}"
        );
    }
}

#[test]
fn cuboid_face_on_a_half_space() {
    let ground = half(p(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0));
    check_at_scales(&aabb(p(0.0, 0.0, 1.0), 1.0), &ground, true);
    check_at_scales(&aabb(p(0.0, 0.0, 1f64.next_up()), 1.0), &ground, false);
    check_at_scales(&aabb(p(0.0, 0.0, 1f64.next_down()), 1.0), &ground, true);
    // Deep inside, and the half-space's other side.
    assert!(meets(&aabb(p(0.0, 0.0, -5.0), 1.0), &ground));
    let sky = half(p(0.0, 0.0, 3.0), v(0.0, 0.0, -1.0));
    assert!(!meets(&aabb(p(0.0, 0.0, 1.0), 1.0), &sky));
    assert!(meets(&aabb(p(0.0, 0.0, 2.0), 1.0), &sky));
}

#[test]
fn tilted_normal_tangency_is_exact() {
    // Plane x + y + z = 3 through the corner (1, 1, 1) of the unit box.
    let plane = |d: f64| half(p(d, 0.0, 0.0), v(-1.0, -1.0, -1.0));
    let unit = aabb(p(0.0, 0.0, 0.0), 1.0);
    check_at_scales(&unit, &plane(3.0), true);
    check_at_scales(&unit, &plane(3f64.next_up()), false);
    check_at_scales(&unit, &plane(3f64.next_down()), true);
}

#[test]
fn cuboid_corners_are_exact_sums() {
    // A's right face is 1 + 2^-62, B's left face 1 + 2^-61: apart, although both round to 1.
    let t = 2f64.powi(-62);
    let a = cuboid(
        p(0.0, 0.0, 0.0),
        [v(1.0, 0.0, 0.0), v(t, 0.0, 0.0), v(0.0, 1.0, 1.0)],
    );
    let e = 2f64.powi(-52);
    let b = |left: f64| {
        cuboid(
            p(1.0 + e, 0.0, 0.0),
            [v(e - left, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0)],
        )
    };
    assert!(!meets(&a, &b(2.0 * t)));
    assert!(meets(&a, &b(t)), "exactly touching");
    let ground = half(p(1.0, 0.0, 0.0), v(-1.0, 0.0, 0.0)); // x >= 1
    assert!(meets(&a, &ground));
    let beyond = half(p(1.0 + e, 0.0, 0.0), v(-1.0, 0.0, 0.0));
    assert!(!meets(&a, &beyond));
}

#[test]
fn box_edge_on_a_box() {
    let a = aabb(p(0.0, 0.0, 0.0), 1.0);
    // A square prism turned 45°: its corner c − U + V = c + (−2, 0, 0) is an edge along z.
    let b = |cx: f64| {
        cuboid(
            p(cx, 0.5, 0.0),
            [v(1.0, 1.0, 0.0), v(-1.0, 1.0, 0.0), v(0.0, 0.0, 1.0)],
        )
    };
    check_at_scales(&a, &b(3.0), true);
    check_at_scales(&a, &b(3f64.next_up()), false);
    check_at_scales(&a, &b(3f64.next_down()), true);
    // Edge on edge: the same prism lifted so that only its edges' ends meet A's top edge.
    let c = |cz: f64| {
        cuboid(
            p(3.0, 0.0, cz),
            [v(1.0, 1.0, 0.0), v(-1.0, 1.0, 0.0), v(0.0, 0.0, 1.0)],
        )
    };
    check_at_scales(&a, &c(2.0), true);
    check_at_scales(&a, &c(2f64.next_up()), false);
}

#[test]
fn capsule_tangent_to_a_cuboid_face() {
    let a = aabb(p(0.0, 0.0, 0.0), 1.0);
    let cap = |r: f64| capsule(p(-1.0, 0.0, 3.0), p(1.0, 0.0, 3.0), r);
    check_at_scales(&a, &cap(2.0), true);
    check_at_scales(&a, &cap(2f64.next_down()), false);
    check_at_scales(&a, &cap(2f64.next_up()), true);
    // Crossing the edge diagonally: distance to the edge (x = 1, z = 1) is √2 from (2, 0, 2).
    let diag = |r: f64| capsule(p(2.0, -5.0, 2.0), p(2.0, 5.0, 2.0), r);
    assert!(meets(&a, &diag(2f64.sqrt().next_up())));
    assert!(!meets(&a, &diag(2f64.sqrt().next_down())));
}

#[test]
fn hull_vertex_on_a_ball() {
    let tetra = hull(&[
        p(0.0, 0.0, 1.0),
        p(1.0, 0.0, -1.0),
        p(-1.0, 1.0, -1.0),
        p(-1.0, -1.0, -1.0),
    ]);
    let b = |z: f64| ball(p(0.0, 0.0, z), 2.0);
    check_at_scales(&tetra, &b(3.0), true);
    check_at_scales(&tetra, &b(3f64.next_up()), false);
    check_at_scales(&tetra, &b(3f64.next_down()), true);
}

#[test]
fn hull_faces_touching_and_apart() {
    let square = |z: f64| {
        hull(&[
            p(0.0, 0.0, z),
            p(1.0, 0.0, z),
            p(1.0, 1.0, z),
            p(0.0, 1.0, z),
            p(0.5, 0.5, z + 1.0),
        ])
    };
    let a = aabb(p(0.5, 0.5, 0.0), 1.0);
    check_at_scales(&a, &square(1.0), true);
    check_at_scales(&a, &square(1f64.next_up()), false);
    check_at_scales(&a, &square(1f64.next_down()), true);
    // The smallest subnormal gap (at unit scale only: scaling would flush it to zero).
    let low = aabb(p(0.5, 0.5, -1.0), 1.0);
    assert!(!meets(&low, &square(0f64.next_up())));
    assert!(meets(&low, &square(0.0)));
}

#[test]
fn containment_counts_as_meeting() {
    let big = aabb(p(0.0, 0.0, 0.0), 10.0);
    check_at_scales(&big, &aabb(p(1.0, 2.0, 3.0), 1.0), true);
    check_at_scales(
        &big,
        &capsule(p(-1.0, 0.0, 0.0), p(1.0, 0.0, 0.0), 0.0),
        true,
    );
    check_at_scales(
        &capsule(p(-1.0, 0.0, 0.0), p(1.0, 0.0, 0.0), 50.0),
        &big,
        true,
    );
    let h = hull(&[
        p(-5.0, -5.0, -5.0),
        p(5.0, 0.0, 0.0),
        p(0.0, 5.0, 0.0),
        p(0.0, 0.0, 5.0),
    ]);
    check_at_scales(&h, &hull(&[p(0.0, 0.0, 0.0)]), true);
    check_at_scales(&big, &h, true);
    let d = distance(&big, &h);
    assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
}

#[test]
fn degenerate_shapes() {
    let unit = aabb(p(0.0, 0.0, 0.0), 1.0);
    // A flat cuboid with dependent half axes: the segment x ∈ [2, 4], y = z = 0 ... shifted.
    let rod = |x: f64| {
        cuboid(
            p(x, 0.0, 0.0),
            [v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0), v(0.0, 0.0, 0.0)],
        )
    };
    check_at_scales(&unit, &rod(4.0), true);
    check_at_scales(&unit, &rod(4f64.next_up()), false);
    let point_box = cuboid(p(1.0, 1.0, 1.0), [v(0.0, 0.0, 0.0); 3]);
    check_at_scales(&unit, &point_box, true);
    let collinear = |x: f64| hull(&[p(x, 0.0, 0.0), p(x + 1.0, 0.0, 0.0), p(x + 2.0, 0.0, 0.0)]);
    check_at_scales(&unit, &collinear(1.0), true);
    check_at_scales(&unit, &collinear(1f64.next_up()), false);
    let flat = |z: f64| {
        hull(&[
            p(-3.0, -3.0, z),
            p(3.0, -3.0, z),
            p(0.0, 3.0, z),
            p(0.0, 0.0, z),
        ])
    };
    check_at_scales(&unit, &flat(1.0), true);
    check_at_scales(&unit, &flat(1f64.next_up()), false);
    // Two flat shapes crossing each other (no full-dimensional overlap anywhere).
    let wall = cuboid(
        p(0.0, 0.0, 0.0),
        [v(0.0, 2.0, 0.0), v(0.0, 0.0, 2.0), v(0.0, 0.0, 0.0)],
    );
    check_at_scales(&wall, &flat(0.0), true);
    check_at_scales(&wall, &flat(5.0), false);
    let zero_capsule = capsule(p(1.0, 1.0, 1.0), p(1.0, 1.0, 1.0), 0.0);
    check_at_scales(&unit, &zero_capsule, true);
    let degenerate_triangle: Shape =
        Triangle::new(p(2.0, 0.0, 0.0), p(3.0, 0.0, 0.0), p(4.0, 0.0, 0.0))
            .unwrap()
            .into();
    check_at_scales(&rod(5.0), &degenerate_triangle, true);
    check_at_scales(&unit, &degenerate_triangle, false);
}

#[test]
fn subnormal_and_huge_values() {
    let tiny = f64::from_bits(1); // the smallest subnormal
    let a = aabb(p(0.0, 0.0, 0.0), tiny);
    assert!(meets(&a, &aabb(p(2.0 * tiny, 0.0, 0.0), tiny)));
    assert!(!meets(&a, &aabb(p(3.0 * tiny, 0.0, 0.0), tiny)));
    assert!(meets(&a, &half(p(tiny, 0.0, 0.0), v(-1.0, 0.0, 0.0))));
    assert!(!meets(
        &a,
        &half(p(2.0 * tiny, 0.0, 0.0), v(-tiny, 0.0, 0.0))
    ));
    let big = 2f64.powi(498);
    let b = aabb(p(0.0, 0.0, 0.0), big);
    assert!(meets(&b, &aabb(p(2.0 * big, 0.0, 0.0), big)));
    assert!(!meets(&b, &aabb(p((2.0 * big).next_up(), 0.0, 0.0), big)));
    assert!(meets(
        &b,
        &capsule(p(big, big, big), p(-big, -big, -big), big)
    ));
    assert!(meets(&b, &half(p(big, 0.0, 0.0), v(-big, -big, 0.0))));
    assert!(!meets(
        &b,
        &half(p(big.next_up(), 0.0, 0.0), v(-big, 0.0, 0.0))
    ));
}

#[test]
fn half_spaces_against_each_other() {
    let below = half(p(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0));
    let above = |z: f64| half(p(0.0, 0.0, z), v(0.0, 0.0, -3.0));
    assert!(meets(&below, &above(0.0)));
    assert!(!meets(&below, &above(0f64.next_up())));
    assert!(meets(&below, &above(-1.0)));
    assert!(within_distance(&below, &above(2.0), 2.0));
    assert!(!within_distance(&below, &above(2.0), 2f64.next_down()));
    // Nearly opposite normals always meet somewhere.
    let tilted = half(p(0.0, 0.0, 100.0), v(0.0, 1e-300, -1.0));
    assert!(meets(&below, &tilted));
    assert!(meets(&below, &half(p(0.0, 0.0, 9.0), v(0.0, 0.0, 2.0))));
    let d = distance(&below, &above(2.0));
    assert!((d.distance - 2.0).abs() <= d.error_bound);
}

#[test]
fn clearance_is_closed() {
    let a = aabb(p(0.0, 0.0, 0.0), 1.0);
    let b = capsule(p(4.0, -1.0, 0.0), p(4.0, 1.0, 0.0), 1.0);
    assert!(within_distance(&a, &b, 2.0));
    assert!(within_distance(&b, &a, 2.0));
    assert!(!within_distance(&a, &b, 2f64.next_down()));
    let d = distance(&a, &b);
    assert!((d.distance - 2.0).abs() <= d.error_bound && d.error_bound < 1e-12);
    assert!((d.witness_a.x - 1.0).abs() < 1e-12 && (d.witness_b.x - 3.0).abs() < 1e-12);
}

// ---------------------------------------------------------------- the brute-force oracle

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap()
}

/// The points spanning the core and the radius (the corners are exact: small integers).
fn core_points(s: &Shape) -> (Vec<Point3<f64>>, f64) {
    match s {
        Shape::Ball(b) => (vec![*b.centre()], b.radius()),
        Shape::Capsule(c) => (vec![*c.a(), *c.b()], c.radius()),
        Shape::Segment(g) => (vec![*g.a(), *g.b()], 0.0),
        Shape::Triangle(t) => (t.vertices().to_vec(), 0.0),
        Shape::ConvexHull(h) => (h.points().to_vec(), 0.0),
        Shape::Cuboid(c) => {
            let [u, w, x] = c.half_axes();
            let mut out = Vec::new();
            for i in 0..8 {
                let sg = |k: usize| if i >> k & 1 == 1 { 1.0 } else { -1.0 };
                out.push(c.centre() + u * sg(0) + w * sg(1) + x * sg(2));
            }
            (out, 0.0)
        }
        _ => unreachable!(),
    }
}

fn det3(a: [Rational; 3], b: [Rational; 3], c: [Rational; 3]) -> Rational {
    &a[0] * (&b[1] * &c[2] - &b[2] * &c[1]) - &a[1] * (&b[0] * &c[2] - &b[2] * &c[0])
        + &a[2] * (&b[0] * &c[1] - &b[1] * &c[0])
}

fn rel(a: &Point3<f64>, o: &Point3<f64>) -> [Rational; 3] {
    [q(a.x) - q(o.x), q(a.y) - q(o.y), q(a.z) - q(o.z)]
}

/// Exact: is `x` in one of the tetrahedra of `pts` (its hull, when the hull is solid)?
fn in_some_tetrahedron(x: &Point3<f64>, pts: &[Point3<f64>]) -> bool {
    let n = pts.len();
    let zero = <Rational as Ring>::zero();
    let orient = |a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>, d: &Point3<f64>| {
        det3(rel(b, a), rel(c, a), rel(d, a))
    };
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                for l in k + 1..n {
                    let t = [&pts[i], &pts[j], &pts[k], &pts[l]];
                    let whole = orient(t[0], t[1], t[2], t[3]);
                    if whole == zero {
                        continue;
                    }
                    let ok = (0..4).all(|m| {
                        let mut u = t;
                        u[m] = x;
                        let part = orient(u[0], u[1], u[2], u[3]);
                        (part >= zero) == (whole > zero) || part == zero
                    });
                    if ok {
                        return true;
                    }
                }
            }
        }
    }
    false
}

/// Triangles covering the boundary of the core: the cuboid's twelve face triangles (whose
/// union covers a flat cuboid too), every triple of points otherwise.
fn boundary(s: &Shape, pts: &[Point3<f64>]) -> Vec<Triangle> {
    let mut out = Vec::new();
    if matches!(s, Shape::Cuboid(_)) {
        for axis in 0..3 {
            for side in [0, 1 << axis] {
                let free: Vec<usize> = (0..3).filter(|&k| k != axis).map(|k| 1 << k).collect();
                let c = [
                    side,
                    side | free[0],
                    side | free[0] | free[1],
                    side | free[1],
                ];
                out.push(Triangle::new(pts[c[0]], pts[c[1]], pts[c[2]]).unwrap());
                out.push(Triangle::new(pts[c[0]], pts[c[2]], pts[c[3]]).unwrap());
            }
        }
        return out;
    }
    for i in 0..pts.len() {
        for j in i..pts.len() {
            for k in j..pts.len() {
                out.push(Triangle::new(pts[i], pts[j], pts[k]).unwrap());
            }
        }
    }
    out
}

/// The exact squared distance between the cores, by every pair of boundary triangles and
/// containment of a vertex.
fn oracle_core_d2(sa: &Shape, a: &[Point3<f64>], sb: &Shape, b: &[Point3<f64>]) -> Rational {
    if a.iter().any(|x| in_some_tetrahedron(x, b)) || b.iter().any(|x| in_some_tetrahedron(x, a)) {
        return <Rational as Ring>::zero();
    }
    let (ta, tb) = (boundary(sa, a), boundary(sb, b));
    let mut best: Option<Rational> = None;
    for x in &ta {
        for y in &tb {
            let d = exact_distance_triangle_triangle(x, y).distance2;
            if best.as_ref().is_none_or(|b| d < *b) {
                best = Some(d);
            }
        }
    }
    best.unwrap()
}

/// The exact answer to `within_distance(a, b, c)`.
fn oracle_within(a: &Shape, b: &Shape, c: f64) -> bool {
    let zero = <Rational as Ring>::zero();
    match (a, b) {
        (Shape::HalfSpace(h), other) | (other, Shape::HalfSpace(h))
            if !matches!(other, Shape::HalfSpace(_)) =>
        {
            let (pts, r) = core_points(other);
            let n = rel(&Point3::from(*h.normal()), &Point3::origin());
            let nn = &n[0] * &n[0] + &n[1] * &n[1] + &n[2] * &n[2];
            let s = q(r) + q(c);
            pts.iter().any(|x| {
                let d = rel(x, h.point());
                let side = &d[0] * &n[0] + &d[1] * &n[1] + &d[2] * &n[2];
                side <= zero || &side * &side <= &s * &s * &nn
            })
        }
        (Shape::HalfSpace(_), Shape::HalfSpace(_)) => unreachable!(),
        _ => {
            let ((pa, ra), (pb, rb)) = (core_points(a), core_points(b));
            let s = q(ra) + q(rb) + q(c);
            oracle_core_d2(a, &pa, b, &pb) <= &s * &s
        }
    }
}

fn coord() -> impl Strategy<Value = f64> {
    (-6i32..=6).prop_map(|x| f64::from(x) / 2.0)
}

fn point() -> impl Strategy<Value = Point3<f64>> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| p(x, y, z))
}

fn vector() -> impl Strategy<Value = Vector3<f64>> {
    point().prop_map(|x| x.coords)
}

fn radius() -> impl Strategy<Value = f64> {
    (0i32..=4).prop_map(|x| f64::from(x) / 2.0)
}

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        (point(), radius()).prop_map(|(c, r)| ball(c, r)),
        (point(), point(), radius()).prop_map(|(a, b, r)| capsule(a, b, r)),
        (point(), vector(), vector(), vector())
            .prop_map(|(c, u, w, x)| cuboid(c, [u / 2.0, w / 2.0, x / 2.0])),
        prop::collection::vec(point(), 1..5).prop_map(|pts| hull(&pts)),
        (point(), point(), point()).prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap().into()),
        (point(), point()).prop_map(|(a, b)| Segment::new(a, b).unwrap().into()),
        (point(), vector())
            .prop_filter("a normal", |(_, n)| *n != Vector3::zeros())
            .prop_map(|(x, n)| half(x, n)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn agrees_with_the_brute_force_oracle(a in shape(), b in shape(), c in radius()) {
        prop_assume!(!matches!((&a, &b), (Shape::HalfSpace(_), Shape::HalfSpace(_))));
        for clearance in [0.0, c] {
            let truth = oracle_within(&a, &b, clearance);
            prop_assert_eq!(within_distance(&a, &b, clearance), truth, "{:?} {:?} {}", a, b, clearance);
            prop_assert_eq!(within_distance(&b, &a, clearance), truth);
        }
        let d = distance(&a, &b);
        prop_assert!(d.error_bound.is_finite() && d.distance >= 0.0);
        prop_assert!(within_distance(&a, &b, d.distance + d.error_bound));
        if d.distance > d.error_bound {
            prop_assert!(!within_distance(&a, &b, d.distance - d.error_bound));
        }
    }
}

/// The exact answer of the rational search for two grown cores.
fn rational_within(a: &Core, b: &Core, c: f64) -> bool {
    let d2 = super::gjk::exact_distance2(a, b, &[]);
    let s = q(a.radius) + q(b.radius) + q(c);
    d2 <= &s * &s
}

#[test]
fn the_feature_stage_decides_constructed_contacts() {
    // Flush faces, an edge on a face, a vertex on a ball, a capsule on a face: touching, and
    // one ulp apart, each decided by the feature stage without the rational search.
    let a = aabb(p(0.0, 0.0, 0.0), 1.0);
    let pairs = [
        (aabb(p(0.5, 0.25, 2.0), 1.0), 0.0, true),
        (aabb(p(0.5, 0.25, 2f64.next_up()), 1.0), 0.0, false),
        (capsule(p(-1.0, 0.0, 3.0), p(1.0, 0.0, 3.0), 2.0), 0.0, true),
        (
            capsule(p(-1.0, 0.0, 3.0), p(1.0, 0.0, 3.0), 2f64.next_down()),
            0.0,
            false,
        ),
        (ball(p(2.0, 2.0, 2.0), 3f64.sqrt()), 0.0, false),
        (ball(p(3.0, 0.0, 0.0), 1.0), 1.0, true),
    ];
    for (b, c, expected) in pairs {
        let (ca, cb) = (Core::of(&a).unwrap(), Core::of(&b).unwrap());
        let found = super::gjk::search(&ca, &cb);
        let answer = feature::decide(&ca, &cb, found.pairs(), [ca.radius, cb.radius, c]);
        assert_eq!(answer, Some(expected), "{b:?} at clearance {c}");
        assert_eq!(within_distance(&a, &b, c), expected);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Whatever simplex it is given (the search's, or any pairs of core points), the feature
    /// stage's answer, when it gives one, is the exact one.
    #[test]
    fn the_feature_stage_is_never_wrong(
        a in shape(),
        b in shape(),
        c in radius(),
        picks in prop::collection::vec((0usize..8, 0usize..8), 1..5),
    ) {
        let (Some(ca), Some(cb)) = (Core::of(&a), Core::of(&b)) else {
            return Ok(());
        };
        let truth = rational_within(&ca, &cb, c);
        let reach = [ca.radius, cb.radius, c];
        let found = super::gjk::search(&ca, &cb);
        if let Some(answer) = feature::decide(&ca, &cb, found.pairs(), reach) {
            prop_assert_eq!(answer, truth, "{:?} {:?} {}", a, b, c);
        }
        let mut pairs: Vec<(usize, usize)> =
            picks.iter().map(|&(i, j)| (i % ca.len(), j % cb.len())).collect();
        pairs.dedup();
        if let Some(answer) = feature::decide(&ca, &cb, &pairs, reach) {
            prop_assert_eq!(answer, truth, "{:?} {:?} {} {:?}", a, b, c, pairs);
        }
    }
}

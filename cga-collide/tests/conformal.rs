//! Conformal primitives, versors and meet classification: known geometry for every variant,
//! agreement of the versors with nalgebra, and agreement of the exact classification with an
//! independent Euclidean computation in exact rationals.

use cga_collide::conformal::meet::{
    line_line, line_plane, line_sphere, plane_plane, sphere_plane, sphere_sphere, LineLine,
    LinePlane, LineSphere, Meet, PlanePlane, SpherePlane, SphereSphere,
};
use cga_collide::conformal::{
    Circle, FlatPoint, Line, Plane, Point, PointPair, Reflection, Sphere, Transform, Versor,
};
use cga_collide::ga_core::scalar::{rational_from_f64, Rational};
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::Error;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;

fn p3(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}
fn v3(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}
fn close(a: &Point3<f64>, b: &Point3<f64>, tol: f64) -> bool {
    (a - b).norm() <= tol
}

// ---------------------------------------------------------------------------------------------
// Constructors and extraction.

#[test]
fn constructors_reject_bad_input() {
    let o = Point3::origin();
    let nan = p3(0.0, f64::NAN, 0.0);
    assert!(matches!(
        Line::from_points(o, nan),
        Err(Error::NonFiniteInput {
            argument: "b.y",
            ..
        })
    ));
    assert!(matches!(
        Line::from_points(o, o),
        Err(Error::Degenerate { .. })
    ));
    assert!(matches!(
        Line::from_point_direction(o, Vector3::zeros()),
        Err(Error::Degenerate { .. })
    ));
    // Collinear, decided exactly even with non-representable-looking coordinates.
    assert!(Plane::from_points(o, p3(0.1, 0.2, 0.3), p3(0.2, 0.4, 0.6)).is_err());
    // 0.1 + 0.2 != 0.3 in f64: these three points are NOT exactly collinear.
    let a = p3(0.1, 0.1, 0.1);
    let b = p3(0.2, 0.2, 0.2);
    let c = p3(0.1 + 0.2, 0.3, 0.3);
    assert!(Plane::from_points(a, b, c).is_ok());
    assert!(matches!(
        Plane::from_normal_offset(Vector3::zeros(), 1.0),
        Err(Error::Degenerate { .. })
    ));
    assert!(matches!(
        Plane::from_normal_offset(Vector3::x(), f64::INFINITY),
        Err(Error::NonFiniteInput { argument: "d", .. })
    ));
    assert!(Sphere::from_centre_radius(o, -1.0).is_err());
    assert!(Sphere::from_centre_radius(o, f64::NAN).is_err());
    // Coplanar and concyclic points.
    assert!(Sphere::from_points([o, p3(1., 0., 0.), p3(0., 1., 0.), p3(3., 3., 0.)]).is_err());
    assert!(Sphere::from_points([
        p3(1., 0., 0.),
        p3(-1., 0., 0.),
        p3(0., 1., 0.),
        p3(0., -1., 0.)
    ])
    .is_err());
    assert!(Circle::from_points(o, p3(1., 1., 1.), p3(2., 2., 2.)).is_err());
    assert!(Circle::from_points(o, o, p3(2., 2., 2.)).is_err());
    assert!(PointPair::from_points(o, o).is_err());
    assert!(Point::new(nan).is_err());
    assert!(FlatPoint::new(nan).is_err());
    assert!(Versor::dilator(0.0).is_err());
    assert!(Versor::rotor(Vector3::zeros(), 1.0).is_err());
    assert!(Versor::translator(v3(f64::NAN, 0., 0.)).is_err());
    // Error messages say what and where.
    let e = Line::from_points(o, nan).unwrap_err().to_string();
    assert!(e.contains("Line::from_points") && e.contains("b.y"), "{e}");
}

#[test]
fn extraction_round_trips() {
    let s = Sphere::from_points([
        p3(3., 2., 1.),
        p3(1., 2., 1.),
        p3(2., 3., 1.),
        p3(2., 2., 2.),
    ])
    .unwrap();
    assert!(close(&s.centre(), &p3(2., 2., 1.), 1e-12));
    assert!((s.radius().unwrap() - 1.0).abs() < 1e-12);
    for q in [p3(3., 2., 1.), p3(2., 2., 0.), p3(2., 1., 1.)] {
        assert!(s.contains(&q));
    }
    assert!(!s.contains(&p3(2., 2., 1.)));
    // IPNS ↔ OPNS.
    let t = Sphere::from_blade(*s.blade()).unwrap();
    assert!(close(&t.centre(), &s.centre(), 1e-12));
    let u = Sphere::from_ipns(s.ipns()).unwrap();
    assert!((u.radius_squared() - 1.0).abs() < 1e-12);
    let pl = Plane::from_points(p3(0., 0., 1.), p3(1., 0., 1.), p3(0., 1., 1.)).unwrap();
    // (c − a) × (b − a) = y × x = −z.
    assert!((pl.normal() - v3(0., 0., -1.)).norm() < 1e-15);
    assert!((pl.offset() + 1.0).abs() < 1e-15);
    let back = Plane::from_blade(*pl.blade()).unwrap();
    assert!((back.normal() - pl.normal()).norm() < 1e-15);
    assert!(Plane::from_ipns(
        Sphere::from_centre_radius(Point3::origin(), 1.0)
            .unwrap()
            .ipns()
    )
    .is_err());
    // Line IPNS/OPNS and exact blades.
    let l = Line::from_points(p3(1., 2., 3.), p3(2., 4., 7.)).unwrap();
    assert_eq!(l.ipns().undual(), *l.blade());
    let ex = l.exact_blade();
    assert_eq!(ex.e145, rational_from_f64(l.blade().e145).unwrap());
    assert!(l.contains(&p3(3., 6., 11.)));
    assert!(!l.contains(&p3(3., 6., 11.000000000000002)));
    // Circle through three points on the unit circle around (1, 1, 1) in the plane x = 1.
    let c = Circle::from_points(p3(1., 2., 1.), p3(1., 1., 2.), p3(1., 0., 1.)).unwrap();
    assert!(close(&c.centre(), &p3(1., 1., 1.), 1e-12));
    assert!((c.radius().unwrap() - 1.0).abs() < 1e-12);
    assert!((c.normal().x.abs() - 1.0).abs() < 1e-12);
    let c2 = Circle::from_centre_normal_radius(p3(1., 1., 1.), v3(2., 0., 0.), 1.0).unwrap();
    assert!(close(&c2.centre(), &p3(1., 1., 1.), 1e-12));
    assert!((c2.radius_squared() - 1.0).abs() < 1e-12);
    // Point pair and flat point.
    let pp = PointPair::from_points(p3(0., 0., 0.), p3(0., 0., 4.)).unwrap();
    assert!(close(&pp.centre(), &p3(0., 0., 2.), 1e-12));
    assert!((pp.radius_squared() - 4.0).abs() < 1e-12);
    assert_eq!(pp.ipns().undual(), *pp.blade());
    let f = FlatPoint::new(p3(-1., 2., 5.)).unwrap();
    assert_eq!(f.position(), Some(p3(-1., 2., 5.)));
}

// ---------------------------------------------------------------------------------------------
// Every variant, with known geometry.

#[test]
fn line_line_variants() {
    let x = Line::from_point_direction(p3(0., 0., 0.), v3(1., 0., 0.)).unwrap();
    let through = Line::from_points(p3(2., -1., 0.), p3(2., 1., 0.)).unwrap();
    match line_line(&x, &through) {
        LineLine::Point(p) => assert!(close(&p, &p3(2., 0., 0.), 1e-12)),
        other => panic!("{other:?}"),
    }
    // A crossing given by a point of the first line (spanning point on L1).
    let from_on = Line::from_point_direction(p3(5., 0., 0.), v3(0., 1., 1.)).unwrap();
    assert!(
        matches!(line_line(&x, &from_on), LineLine::Point(p) if close(&p, &p3(5., 0., 0.), 1e-12))
    );
    let par = Line::from_points(p3(0., 3., 4.), p3(-7., 3., 4.)).unwrap();
    assert!(
        matches!(line_line(&x, &par), LineLine::Parallel { distance } if (distance - 5.0).abs() < 1e-12)
    );
    let same = Line::from_points(p3(-2., 0., 0.), p3(9., 0., 0.)).unwrap();
    assert_eq!(line_line(&x, &same), LineLine::Coincident);
    assert_eq!(x.meet(&x), LineLine::Coincident);
    let skew = Line::from_point_direction(p3(0., 0., -2.), v3(1., 1., 0.)).unwrap();
    assert!(
        matches!(line_line(&x, &skew), LineLine::Skew { distance } if (distance - 2.0).abs() < 1e-12)
    );
}

#[test]
fn line_plane_variants() {
    let p = Plane::from_points(p3(0., 0., 2.), p3(1., 0., 2.), p3(0., 1., 2.)).unwrap();
    let l = Line::from_points(p3(1., 1., 0.), p3(2., 3., 1.)).unwrap();
    assert!(matches!(line_plane(&l, &p), LinePlane::Point(x) if close(&x, &p3(3., 5., 2.), 1e-12)));
    let par = Line::from_point_direction(p3(0., 0., 5.), v3(1., 2., 0.)).unwrap();
    assert!(
        matches!(line_plane(&par, &p), LinePlane::Parallel { distance } if (distance - 3.0).abs() < 1e-12)
    );
    let inside = Line::from_points(p3(4., 4., 2.), p3(-1., 7., 2.)).unwrap();
    assert_eq!(line_plane(&inside, &p), LinePlane::Contained);
    assert_eq!(p.meet(&inside), LinePlane::Contained);
}

#[test]
fn line_sphere_variants() {
    let s = Sphere::from_centre_radius(p3(1., 1., 1.), 2.0).unwrap();
    let l = Line::from_point_direction(p3(1., 1., 1.), v3(0., 0., -1.)).unwrap();
    match line_sphere(&l, &s) {
        LineSphere::TwoPoints(a, b) => {
            assert!(close(&a, &p3(1., 1., 3.), 1e-12), "{a}");
            assert!(close(&b, &p3(1., 1., -1.), 1e-12), "{b}");
        }
        other => panic!("{other:?}"),
    }
    let t = Line::from_points(p3(3., 1., 0.), p3(3., 1., 5.)).unwrap();
    assert!(
        matches!(line_sphere(&t, &s), LineSphere::Tangent(x) if close(&x, &p3(3., 1., 1.), 1e-12))
    );
    let far = Line::from_points(p3(3.5, 1., 0.), p3(3.5, 1., 5.)).unwrap();
    assert_eq!(line_sphere(&far, &s), LineSphere::Disjoint);
    // Imaginary spheres are met nowhere; a point sphere on the line is a tangency.
    let im = Sphere::from_centre_squared_radius(p3(1., 1., 1.), -1.0).unwrap();
    assert_eq!(line_sphere(&l, &im), LineSphere::Disjoint);
    let dot = Sphere::from_centre_radius(p3(1., 1., -7.), 0.0).unwrap();
    assert!(matches!(dot.meet(&l), LineSphere::Tangent(x) if close(&x, &p3(1., 1., -7.), 1e-12)));
    // A sphere through four points.
    let s4 = Sphere::from_points([
        p3(1., 0., 0.),
        p3(-1., 0., 0.),
        p3(0., 1., 0.),
        p3(0., 0., 1.),
    ])
    .unwrap();
    let y1 = Line::from_point_direction(p3(0., 1., 0.), v3(1., 0., 0.)).unwrap();
    assert!(matches!(line_sphere(&y1, &s4), LineSphere::Tangent(_)));
}

#[test]
fn plane_plane_variants() {
    let a = Plane::from_points(p3(0., 0., 0.), p3(1., 0., 0.), p3(0., 1., 1.)).unwrap(); // y = z
    let b = Plane::from_normal_offset(v3(0., 0., 1.), 3.0).unwrap();
    match plane_plane(&a, &b) {
        PlanePlane::Line(l) => {
            assert!(l.direction().cross(&v3(1., 0., 0.)).norm() < 1e-12);
            assert!(close(&l.support_point(), &p3(0., 3., 3.), 1e-12));
        }
        other => panic!("{other:?}"),
    }
    let c = Plane::from_normal_offset(v3(0., 2., -2.), 4.0).unwrap(); // y − z = 2
    assert!(
        matches!(plane_plane(&a, &c), PlanePlane::Parallel { distance } if (distance - 2f64.sqrt()).abs() < 1e-12)
    );
    let d = Plane::from_normal_offset(v3(0., -5., 5.), 0.0).unwrap();
    assert_eq!(plane_plane(&a, &d), PlanePlane::Coincident);
}

#[test]
fn sphere_plane_variants() {
    let s = Sphere::from_centre_radius(p3(0., 0., 0.), 5.0).unwrap();
    let p = Plane::from_normal_offset(v3(0., 0., 1.), 3.0).unwrap();
    match sphere_plane(&s, &p) {
        SpherePlane::Circle(c) => {
            assert!(close(&c.centre(), &p3(0., 0., 3.), 1e-12));
            assert!((c.radius().unwrap() - 4.0).abs() < 1e-12);
            assert!((c.normal().z.abs() - 1.0).abs() < 1e-12);
        }
        other => panic!("{other:?}"),
    }
    let t = Plane::from_normal_offset(v3(0., -2., 0.), 10.0).unwrap(); // y = −5
    assert!(
        matches!(sphere_plane(&s, &t), SpherePlane::Tangent(x) if close(&x, &p3(0., -5., 0.), 1e-12))
    );
    let far = Plane::from_normal_offset(v3(1., 0., 0.), 5.5).unwrap();
    assert_eq!(sphere_plane(&s, &far), SpherePlane::Disjoint);
    assert_eq!(far.meet(&s), SpherePlane::Disjoint);
    let im = Sphere::from_centre_squared_radius(Point3::origin(), -25.0).unwrap();
    assert_eq!(sphere_plane(&im, &p), SpherePlane::Disjoint);
}

#[test]
fn sphere_sphere_variants() {
    let a = Sphere::from_centre_radius(p3(0., 0., 0.), 5.0).unwrap();
    let b = Sphere::from_centre_radius(p3(6., 0., 0.), 5.0).unwrap();
    match sphere_sphere(&a, &b) {
        SphereSphere::Circle(c) => {
            assert!(close(&c.centre(), &p3(3., 0., 0.), 1e-12));
            assert!((c.radius().unwrap() - 4.0).abs() < 1e-12);
        }
        other => panic!("{other:?}"),
    }
    let ext = Sphere::from_centre_radius(p3(0., 8., 0.), 3.0).unwrap();
    assert!(
        matches!(sphere_sphere(&a, &ext), SphereSphere::TangentExternal(x) if close(&x, &p3(0., 5., 0.), 1e-12))
    );
    let int = Sphere::from_centre_radius(p3(0., 0., 2.), 3.0).unwrap();
    assert!(
        matches!(sphere_sphere(&a, &int), SphereSphere::TangentInternal(x) if close(&x, &p3(0., 0., 5.), 1e-12))
    );
    assert!(matches!(int.meet(&a), SphereSphere::TangentInternal(_)));
    let same = Sphere::from_points([
        p3(5., 0., 0.),
        p3(-5., 0., 0.),
        p3(0., 5., 0.),
        p3(0., 0., 5.),
    ])
    .unwrap();
    assert_eq!(sphere_sphere(&a, &same), SphereSphere::Coincident);
    let far = Sphere::from_centre_radius(p3(0., 0., 20.), 3.0).unwrap();
    assert_eq!(sphere_sphere(&a, &far), SphereSphere::Disjoint);
    let nest = Sphere::from_centre_radius(p3(1., 1., 1.), 1.0).unwrap();
    assert_eq!(sphere_sphere(&a, &nest), SphereSphere::Nested);
    assert_eq!(sphere_sphere(&nest, &a), SphereSphere::Nested);
    let im = Sphere::from_centre_squared_radius(p3(1., 0., 0.), -1.0).unwrap();
    assert_eq!(sphere_sphere(&a, &im), SphereSphere::Disjoint);
    // Point sphere on a sphere: external tangency at that point.
    let dot = Sphere::from_centre_radius(p3(5., 0., 0.), 0.0).unwrap();
    assert!(
        matches!(sphere_sphere(&a, &dot), SphereSphere::TangentExternal(x) if close(&x, &p3(5., 0., 0.), 1e-12))
    );
}

#[test]
fn tangency_survives_extreme_scales() {
    // Exact classification at 2^±500: every f64 product over/underflows, the exact path decides.
    for k in [-500i32, -60, 0, 60, 500] {
        let s = 2f64.powi(k);
        let a = Sphere::from_centre_radius(p3(0., 0., 0.), 5.0 * s).unwrap();
        let b = Sphere::from_centre_radius(p3(0., 8. * s, 0.), 3.0 * s).unwrap();
        assert!(
            matches!(sphere_sphere(&a, &b), SphereSphere::TangentExternal(_)),
            "k = {k}"
        );
        let c =
            Sphere::from_centre_radius(p3(0., 8. * s, 0.), 3.0 * s * (1.0 + f64::EPSILON)).unwrap();
        assert!(
            matches!(sphere_sphere(&a, &c), SphereSphere::Circle(_)),
            "k = {k}"
        );
        let l = Line::from_points(p3(5. * s, 0., 0.), p3(5. * s, 3. * s, 7. * s)).unwrap();
        assert!(
            matches!(line_sphere(&l, &a), LineSphere::Tangent(_)),
            "k = {k}"
        );
        let m = Line::from_points(p3(3. * s, 4. * s, -s), p3(3. * s, 4. * s, s)).unwrap();
        let p = Plane::from_normal_offset(v3(3., 4., 0.), 25.0 * s).unwrap();
        assert_eq!(line_plane(&m, &p), LinePlane::Contained, "k = {k}");
    }
}

// ---------------------------------------------------------------------------------------------
// Versors agree with nalgebra.

fn coord() -> impl Strategy<Value = f64> {
    -10.0f64..10.0
}
fn point() -> impl Strategy<Value = Point3<f64>> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| p3(x, y, z))
}
fn unit_vector() -> impl Strategy<Value = Vector3<f64>> {
    (coord(), coord(), coord())
        .prop_filter("nonzero", |(x, y, z)| x * x + y * y + z * z > 0.01)
        .prop_map(|(x, y, z)| v3(x, y, z).normalize())
}
fn isometry() -> impl Strategy<Value = Isometry3<f64>> {
    (point(), unit_vector(), -7.0f64..7.0).prop_map(|(t, axis, angle)| {
        Isometry3::from_parts(
            Translation3::from(t.coords),
            UnitQuaternion::from_scaled_axis(axis * angle),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn versors_agree_with_nalgebra(iso in isometry(), iso2 in isometry(), a in point(), b in point(),
                                   c in point(), r in 0.1f64..5.0, k in 0.2f64..5.0, n in unit_vector(), d in coord()) {
        let tol = 1e-9;
        let v = Versor::from(iso);
        // Points.
        let pa = Point::new(a).unwrap().transform(&v).unwrap();
        prop_assert!(close(&pa.position().unwrap(), &(iso * a), tol));
        // Composition.
        let w = v.then(&Versor::from(iso2));
        let pw = Point::new(a).unwrap().transform(&w).unwrap();
        prop_assert!(close(&pw.position().unwrap(), &(iso2 * iso * a), tol));
        // Lines: direction and incidence.
        prop_assume!((b - a).norm() > 0.1);
        let l = Line::from_points(a, b).unwrap().transform(&v).unwrap();
        let dir = iso.rotation * (b - a).normalize();
        prop_assert!((l.direction() - dir).norm() < tol);
        let ia = iso * a;
        let foot = l.support_point() + l.direction() * (ia - l.support_point()).dot(&l.direction());
        prop_assert!(close(&foot, &ia, tol));
        // Planes: normal and offset.
        let pl = Plane::from_normal_offset(n, d).unwrap().transform(&v).unwrap();
        let n2 = iso.rotation * n;
        prop_assert!((pl.normal() - n2).norm() < tol);
        let on = iso * Point3::from(n * d);
        prop_assert!((pl.offset() - n2.dot(&on.coords)).abs() < tol);
        // Spheres: centre and radius.
        let s = Sphere::from_centre_radius(c, r).unwrap().transform(&v).unwrap();
        prop_assert!(close(&s.centre(), &(iso * c), tol));
        prop_assert!((s.radius().unwrap() - r).abs() < tol);
        // Rotor about an axis through the origin = nalgebra's rotation.
        let rot = Versor::rotor(n, d).unwrap();
        let pr = Point::new(a).unwrap().transform(&rot).unwrap();
        prop_assert!(close(&pr.position().unwrap(), &(UnitQuaternion::from_scaled_axis(n * d) * a), tol));
        // Dilator about a centre.
        let dil = Versor::dilator_about(c, k).unwrap();
        let sd = Sphere::from_centre_radius(a, r).unwrap().transform(&dil).unwrap();
        prop_assert!(close(&sd.centre(), &(c + (a - c) * k), tol * 10.0));
        prop_assert!((sd.radius().unwrap() - k * r).abs() < tol * 10.0);
        // Reflection in a plane: x ↦ x − 2 (n·x − d) n.
        let m = Reflection::new(&Plane::from_normal_offset(n, d).unwrap());
        let refl = |x: Point3<f64>| x - n * (2.0 * (n.dot(&x.coords) - d));
        let pm = Point::new(a).unwrap().reflect(&m).unwrap();
        prop_assert!(close(&pm.position().unwrap(), &refl(a), tol));
        let sm = Sphere::from_centre_radius(c, r).unwrap().reflect(&m).unwrap();
        prop_assert!(close(&sm.centre(), &refl(c), tol));
        let lm = Line::from_points(a, b).unwrap().reflect(&m).unwrap();
        let rd = (refl(b) - refl(a)).normalize();
        prop_assert!((lm.direction() - rd).norm() < tol);
        // Rounds: circle centre and point pair points.
        let circ = Circle::from_centre_normal_radius(c, n, r).unwrap().transform(&v).unwrap();
        prop_assert!(close(&circ.centre(), &(iso * c), tol));
        prop_assert!((circ.radius().unwrap() - r).abs() < tol);
        let pp = PointPair::from_points(a, b).unwrap().transform(&v).unwrap();
        let (x, y) = pp.points().unwrap();
        prop_assert!(close(&x, &(iso * a), tol) && close(&y, &(iso * b), tol));
        let fp = FlatPoint::new(a).unwrap().transform(&v).unwrap();
        prop_assert!(close(&fp.position().unwrap(), &(iso * a), tol));
    }
}

// ---------------------------------------------------------------------------------------------
// Classification = independent Euclidean computation in exact rationals.

type Q = Rational;

fn q(x: f64) -> Q {
    rational_from_f64(x).unwrap()
}
fn qp(p: &Point3<f64>) -> [Q; 3] {
    [q(p.x), q(p.y), q(p.z)]
}
fn qv(v: &Vector3<f64>) -> [Q; 3] {
    [q(v.x), q(v.y), q(v.z)]
}
fn sub(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}
fn dot(a: &[Q; 3], b: &[Q; 3]) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}
fn cross(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}
fn is_zero3(a: &[Q; 3]) -> bool {
    a.iter().all(Zero::is_zero)
}
fn scale3(k: &Q, a: &[Q; 3]) -> [Q; 3] {
    [k * &a[0], k * &a[1], k * &a[2]]
}

/// A line as test data: point `p` and direction `d` (exact), built either way.
#[derive(Debug, Clone)]
enum TLine {
    Points(Point3<f64>, Point3<f64>),
    PointDir(Point3<f64>, Vector3<f64>),
}
impl TLine {
    fn build(&self) -> Line {
        match self {
            TLine::Points(a, b) => Line::from_points(*a, *b).unwrap(),
            TLine::PointDir(p, d) => Line::from_point_direction(*p, *d).unwrap(),
        }
    }
    fn exact(&self) -> ([Q; 3], [Q; 3]) {
        match self {
            TLine::Points(a, b) => (qp(a), sub(&qp(b), &qp(a))),
            TLine::PointDir(p, d) => (qp(p), qv(d)),
        }
    }
    fn valid(&self) -> bool {
        match self {
            TLine::Points(a, b) => a != b,
            TLine::PointDir(_, d) => *d != Vector3::zeros(),
        }
    }
}

#[derive(Debug, Clone)]
enum TPlane {
    Points(Point3<f64>, Point3<f64>, Point3<f64>),
    NormalOffset(Vector3<f64>, f64),
}
impl TPlane {
    fn exact(&self) -> ([Q; 3], Q) {
        match self {
            TPlane::Points(a, b, c) => {
                let n = cross(&sub(&qp(b), &qp(a)), &sub(&qp(c), &qp(a)));
                let d = dot(&n, &qp(a));
                (n, d)
            }
            TPlane::NormalOffset(n, d) => (qv(n), q(*d)),
        }
    }
    fn build(&self) -> Option<Plane> {
        match self {
            TPlane::Points(a, b, c) => Plane::from_points(*a, *b, *c).ok(),
            TPlane::NormalOffset(n, d) => Plane::from_normal_offset(*n, *d).ok(),
        }
    }
}

#[derive(Debug, Clone)]
struct TSphere {
    c: Point3<f64>,
    r: f64,
    imaginary: bool,
}
impl TSphere {
    fn build(&self) -> Sphere {
        if self.imaginary {
            Sphere::from_centre_squared_radius(self.c, -self.r).unwrap()
        } else {
            Sphere::from_centre_radius(self.c, self.r).unwrap()
        }
    }
    fn exact(&self) -> ([Q; 3], Q) {
        let r = q(self.r);
        (qp(&self.c), if self.imaginary { -r } else { &r * &r })
    }
}

fn oracle_ll(a: &TLine, b: &TLine) -> &'static str {
    let (p1, d1) = a.exact();
    let (p2, d2) = b.exact();
    let c = cross(&d1, &d2);
    let w = sub(&p2, &p1);
    if !is_zero3(&c) {
        if dot(&w, &c).is_zero() {
            "point"
        } else {
            "skew"
        }
    } else if is_zero3(&cross(&w, &d1)) {
        "coincident"
    } else {
        "parallel"
    }
}
fn kind_ll(x: &LineLine) -> &'static str {
    match x {
        LineLine::Point(_) => "point",
        LineLine::Parallel { .. } => "parallel",
        LineLine::Coincident => "coincident",
        LineLine::Skew { .. } => "skew",
    }
}
fn oracle_lp(l: &TLine, p: &TPlane) -> &'static str {
    let (x, d) = l.exact();
    let (n, off) = p.exact();
    if !dot(&n, &d).is_zero() {
        "point"
    } else if dot(&n, &x) == off {
        "contained"
    } else {
        "parallel"
    }
}
fn kind_lp(x: &LinePlane) -> &'static str {
    match x {
        LinePlane::Point(_) => "point",
        LinePlane::Parallel { .. } => "parallel",
        LinePlane::Contained => "contained",
    }
}
fn oracle_ls(l: &TLine, s: &TSphere) -> &'static str {
    let (x, d) = l.exact();
    let (c, rho) = s.exact();
    let m = cross(&sub(&c, &x), &d);
    let disc = rho * dot(&d, &d) - dot(&m, &m);
    if disc.is_positive() {
        "two"
    } else if disc.is_zero() {
        "tangent"
    } else {
        "disjoint"
    }
}
fn kind_ls(x: &LineSphere) -> &'static str {
    match x {
        LineSphere::TwoPoints(..) => "two",
        LineSphere::Tangent(_) => "tangent",
        LineSphere::Disjoint => "disjoint",
    }
}
fn oracle_pp(a: &TPlane, b: &TPlane) -> &'static str {
    let (n1, d1) = a.exact();
    let (n2, d2) = b.exact();
    if !is_zero3(&cross(&n1, &n2)) {
        "line"
    } else if is_zero3(&sub(&scale3(&d1, &n2), &scale3(&d2, &n1))) {
        "coincident"
    } else {
        "parallel"
    }
}
fn kind_pp(x: &PlanePlane) -> &'static str {
    match x {
        PlanePlane::Line(_) => "line",
        PlanePlane::Parallel { .. } => "parallel",
        PlanePlane::Coincident => "coincident",
    }
}
fn oracle_sp(s: &TSphere, p: &TPlane) -> &'static str {
    let (c, rho) = s.exact();
    let (n, off) = p.exact();
    let h = dot(&n, &c) - off;
    let disc = rho * dot(&n, &n) - &h * &h;
    if disc.is_positive() {
        "circle"
    } else if disc.is_zero() {
        "tangent"
    } else {
        "disjoint"
    }
}
fn kind_sp(x: &SpherePlane) -> &'static str {
    match x {
        SpherePlane::Circle(_) => "circle",
        SpherePlane::Tangent(_) => "tangent",
        SpherePlane::Disjoint => "disjoint",
    }
}
fn oracle_ss(a: &TSphere, b: &TSphere) -> &'static str {
    let (c1, r1) = a.exact();
    let (c2, r2) = b.exact();
    if r1.is_negative() || r2.is_negative() {
        return "disjoint";
    }
    let w = sub(&c2, &c1);
    let dd = dot(&w, &w);
    if dd.is_zero() && r1 == r2 {
        return "coincident";
    }
    // Circle iff (r1 − r2)² < d² < (r1 + r2)² iff A² < 4 r1² r2² with A = d² − r1² − r2².
    let a = dd - &r1 - &r2;
    let four = Q::from_integer(4.into());
    let disc = four * &r1 * &r2 - &a * &a;
    if disc.is_positive() {
        "circle"
    } else if disc.is_zero() {
        if a.is_negative() {
            "internal"
        } else {
            "external"
        }
    } else if a.is_negative() {
        "nested"
    } else {
        "disjoint"
    }
}
fn kind_ss(x: &SphereSphere) -> &'static str {
    match x {
        SphereSphere::Circle(_) => "circle",
        SphereSphere::TangentExternal(_) => "external",
        SphereSphere::TangentInternal(_) => "internal",
        SphereSphere::Coincident => "coincident",
        SphereSphere::Disjoint => "disjoint",
        SphereSphere::Nested => "nested",
    }
}

/// Small integers, so that tangent, parallel, coincident and incident configurations are
/// frequent.
fn small() -> impl Strategy<Value = f64> {
    (-3i32..=3).prop_map(f64::from)
}
fn ipoint() -> impl Strategy<Value = Point3<f64>> {
    (small(), small(), small()).prop_map(|(x, y, z)| p3(x, y, z))
}
fn ivec() -> impl Strategy<Value = Vector3<f64>> {
    ipoint().prop_map(|p| p.coords)
}

/// A scale `2^k` (exact) and an optional one-ulp nudge: adversarial magnitudes from about
/// 1e-150 to 1e150 and near-degenerate perturbations of exact configurations.
#[derive(Debug, Clone, Copy)]
struct Warp {
    k: i32,
    nudge: bool,
}
fn warp() -> impl Strategy<Value = Warp> {
    (
        prop_oneof![
            Just(0),
            Just(0),
            Just(-30),
            Just(40),
            Just(-500),
            Just(500),
            -3i32..3
        ],
        any::<u8>(),
    )
        .prop_map(|(k, n)| Warp {
            k,
            nudge: n % 5 == 0,
        })
}
impl Warp {
    fn s(&self) -> f64 {
        2f64.powi(self.k)
    }
    fn p(&self, p: Point3<f64>) -> Point3<f64> {
        p * self.s()
    }
    fn v(&self, v: Vector3<f64>) -> Vector3<f64> {
        v * self.s()
    }
    fn x(&self, x: f64) -> f64 {
        x * self.s()
    }
    /// The last coordinate, nudged by one ulp when asked.
    fn last(&self, p: Point3<f64>) -> Point3<f64> {
        self.nudge(self.p(p))
    }
    /// Nudges the last coordinate by one ulp when asked (no scaling).
    fn nudge(&self, mut p: Point3<f64>) -> Point3<f64> {
        if self.nudge {
            p.z = if p.z == 0.0 {
                f64::from_bits(1)
            } else {
                p.z * (1.0 + f64::EPSILON)
            };
        }
        p
    }
}

fn tline() -> impl Strategy<Value = TLine> {
    (ipoint(), ipoint(), any::<bool>()).prop_map(|(a, b, two)| {
        if two {
            TLine::Points(a, b)
        } else {
            TLine::PointDir(a, b.coords)
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn line_line_matches_oracle(a in tline(), b0 in tline(), mode in 0u8..4, t in small(), u in small(), w in warp()) {
        prop_assume!(a.valid());
        let (p, d) = match &a { TLine::Points(x, y) => (*x, y - x), TLine::PointDir(x, d) => (*x, *d) };
        // Adversarial second lines: through a point of `a`, parallel to `a`, or on `a`.
        let b = match mode {
            0 => b0,
            1 => match b0 { TLine::Points(_, y) => TLine::Points(p + d * t, y), TLine::PointDir(_, e) => TLine::PointDir(p + d * t, e) },
            2 => TLine::PointDir(match b0 { TLine::Points(x, _) | TLine::PointDir(x, _) => x }, d * (u + 4.0)),
            _ => TLine::Points(p + d * t, p + d * (t + u + 4.0)),
        };
        prop_assume!(b.valid());
        let warp_line = |l: &TLine, last: bool| match l {
            TLine::Points(x, y) => TLine::Points(w.p(*x), if last { w.last(*y) } else { w.p(*y) }),
            TLine::PointDir(x, e) => TLine::PointDir(if last { w.last(*x) } else { w.p(*x) }, w.v(*e)),
        };
        let (a, b) = (warp_line(&a, false), warp_line(&b, true));
        prop_assume!(a.valid() && b.valid());
        prop_assert_eq!(kind_ll(&line_line(&a.build(), &b.build())), oracle_ll(&a, &b), "{:?} {:?}", a, b);
    }

    #[test]
    fn line_plane_matches_oracle(l0 in tline(), pa in ipoint(), pb in ipoint(), pc in ipoint(), n in ivec(), off in small(),
                                 by_points in any::<bool>(), mode in 0u8..3, t in small(), w in warp()) {
        let plane = if by_points { TPlane::Points(w.p(pa), w.p(pb), w.p(pc)) } else { TPlane::NormalOffset(n, w.x(off)) };
        let Some(pl) = plane.build() else { return Ok(()); };
        let l = match (mode, &plane) {
            (1, TPlane::Points(a, b, c)) => TLine::Points(*a + (b - a) * t, w.nudge(*c)),
            (1, TPlane::NormalOffset(n, _)) => TLine::PointDir(w.last(p3(t, 1.0, 2.0)), n.cross(&v3(1.0, t, 2.0))),
            (2, TPlane::Points(a, b, c)) => TLine::PointDir(w.nudge(*a), (b - a) + (c - a) * t),
            _ => match l0 { TLine::Points(x, y) => TLine::Points(w.p(x), w.last(y)), TLine::PointDir(x, e) => TLine::PointDir(w.last(x), e) },
        };
        prop_assume!(l.valid());
        prop_assert_eq!(kind_lp(&line_plane(&l.build(), &pl)), oracle_lp(&l, &plane), "{:?} {:?}", l, plane);
    }

    #[test]
    fn line_sphere_matches_oracle(l in tline(), c in ipoint(), r in 0i32..4, imaginary in any::<u8>(), w in warp(),
                                  mode in 0u8..3, axis in 0usize..3, e in ivec()) {
        // Mode 1: through c + r e_axis, orthogonal to e_axis (tangent); mode 2: through c.
        let l = match mode {
            0 => l,
            m => {
                let mut u = Vector3::zeros();
                u[axis] = f64::from(r);
                let mut dir = e;
                dir[axis] = 0.0;
                TLine::PointDir(if m == 1 { c + u } else { c }, dir)
            }
        };
        prop_assume!(l.valid());
        let s = TSphere { c: w.p(c), r: w.x(f64::from(r)), imaginary: imaginary % 7 == 0 };
        let l = match l { TLine::Points(x, y) => TLine::Points(w.p(x), w.last(y)), TLine::PointDir(x, e) => TLine::PointDir(w.last(x), e) };
        prop_assume!(l.valid());
        prop_assert_eq!(kind_ls(&line_sphere(&l.build(), &s.build())), oracle_ls(&l, &s), "{:?} {:?}", l, s);
    }

    #[test]
    fn plane_plane_matches_oracle(a in ipoint(), b in ipoint(), c in ipoint(), n in ivec(), off in small(), k in small(),
                                  mode in 0u8..3, w in warp()) {
        let p1 = TPlane::Points(w.p(a), w.p(b), w.p(c));
        let p2 = match mode {
            0 => TPlane::NormalOffset(n, w.x(off)),
            _ => {
                // Parallel or coincident with p1: a multiple of its normal.
                let (nn, dd) = p1.exact();
                let f = |x: &Q| x.to_f64().unwrap_or(f64::NAN);
                let nf = v3(f(&nn[0]), f(&nn[1]), f(&nn[2]));
                let df = if mode == 1 { f(&dd) } else { f(&dd) + w.x(off) };
                prop_assume!(nf.iter().all(|x| x.is_finite()) && df.is_finite());
                TPlane::NormalOffset(nf * (k + 4.0), df * (k + 4.0))
            }
        };
        let (Some(x), Some(y)) = (p1.build(), p2.build()) else { return Ok(()); };
        prop_assert_eq!(kind_pp(&plane_plane(&x, &y)), oracle_pp(&p1, &p2), "{:?} {:?}", p1, p2);
    }

    #[test]
    fn sphere_plane_matches_oracle(c in ipoint(), r in 0i32..4, imaginary in any::<u8>(), a in ipoint(), b in ipoint(), d in ipoint(),
                                   n in ivec(), off in small(), by_points in any::<bool>(), w in warp()) {
        let s = TSphere { c: w.last(c), r: w.x(f64::from(r)), imaginary: imaginary % 7 == 0 };
        // Every third case: an axis plane at distance r from the centre (tangent) scaled by `off`.
        let plane = if imaginary % 3 == 1 {
            let axis = usize::from(imaginary / 3 % 3);
            let mut nn = Vector3::zeros();
            nn[axis] = off + 4.0;
            let side = if by_points { 1.0 } else { -1.0 };
            TPlane::NormalOffset(nn, (off + 4.0) * w.x(c[axis] + side * f64::from(r)))
        } else if by_points {
            TPlane::Points(w.p(a), w.p(b), w.p(d))
        } else {
            TPlane::NormalOffset(n, w.x(off))
        };
        let Some(pl) = plane.build() else { return Ok(()); };
        prop_assert_eq!(kind_sp(&sphere_plane(&s.build(), &pl)), oracle_sp(&s, &plane), "{:?} {:?}", s, plane);
    }

    #[test]
    fn sphere_sphere_matches_oracle(c1 in ipoint(), c2 in ipoint(), r1 in 0i32..5, r2 in 0i32..5, imaginary in any::<u8>(),
                                    axis in 0usize..3, mode in 0u8..3, w in warp()) {
        // Modes 1 and 2 put the centres on an axis at distance r1 + r2 or |r1 − r2| (tangent).
        let c2 = match mode {
            0 => c2,
            _ => {
                let dist = if mode == 1 { r1 + r2 } else { (r1 - r2).abs() };
                let mut e = Vector3::zeros();
                e[axis] = f64::from(dist);
                c1 + e
            }
        };
        let a = TSphere { c: w.p(c1), r: w.x(f64::from(r1)), imaginary: imaginary % 11 == 0 };
        let b = TSphere { c: w.last(c2), r: w.x(f64::from(r2)), imaginary: false };
        prop_assert_eq!(kind_ss(&sphere_sphere(&a.build(), &b.build())), oracle_ss(&a, &b), "{:?} {:?}", a, b);
        prop_assert_eq!(kind_ss(&sphere_sphere(&b.build(), &a.build())), oracle_ss(&b, &a));
    }

    /// General position with random f64 coordinates (no structure at all).
    #[test]
    fn random_f64_inputs_match_oracle(a in point(), b in point(), c in point(), d in point(), r1 in 0.0f64..8.0, r2 in 0.0f64..8.0,
                                      n in unit_vector(), off in coord()) {
        let la = TLine::Points(a, b);
        let lb = TLine::PointDir(c, d.coords);
        prop_assume!(la.valid() && lb.valid());
        let pl = TPlane::NormalOffset(n, off);
        let pm = TPlane::Points(a, c, d);
        let s1 = TSphere { c, r: r1, imaginary: false };
        let s2 = TSphere { c: d, r: r2, imaginary: false };
        prop_assert_eq!(kind_ll(&line_line(&la.build(), &lb.build())), oracle_ll(&la, &lb));
        prop_assert_eq!(kind_lp(&line_plane(&la.build(), &pl.build().unwrap())), oracle_lp(&la, &pl));
        prop_assert_eq!(kind_ls(&line_sphere(&la.build(), &s1.build())), oracle_ls(&la, &s1));
        if let Some(m) = pm.build() {
            prop_assert_eq!(kind_pp(&plane_plane(&pl.build().unwrap(), &m)), oracle_pp(&pl, &pm));
        }
        prop_assert_eq!(kind_sp(&sphere_plane(&s1.build(), &pl.build().unwrap())), oracle_sp(&s1, &pl));
        prop_assert_eq!(kind_ss(&sphere_sphere(&s1.build(), &s2.build())), oracle_ss(&s1, &s2));
    }
}

// ---------------------------------------------------------------------------------------------
// The geometry carried by the variants agrees with Euclidean formulas (f64, relative tolerance).

fn on_line(x: &Point3<f64>, l: &Line, tol: f64) -> bool {
    let p = l.support_point();
    let d = l.direction();
    (x - p).cross(&d).norm() <= tol
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn meet_geometry_is_right(a in point(), b in point(), c in point(), d in point(), r1 in 0.5f64..8.0, r2 in 0.5f64..8.0,
                              n in unit_vector(), off in coord(), t in -2.0f64..2.0) {
        let tol = 1e-7;
        prop_assume!((b - a).norm() > 0.1);
        let la = Line::from_points(a, b).unwrap();
        let pl = Plane::from_normal_offset(n, off).unwrap();
        // Line–line through a common point.
        let x0 = a + (b - a) * t;
        prop_assume!((d - x0).norm() > 0.1 && (d - x0).normalize().cross(&la.direction()).norm() > 0.05);
        let lb = Line::from_points(d, x0).unwrap();
        match line_line(&la, &lb) {
            LineLine::Point(x) => prop_assert!(close(&x, &x0, tol), "{x} {x0}"),
            // x0 is rounded, so the two lines are usually skew by a hair: exactly classified.
            LineLine::Skew { distance } => prop_assert!(distance < tol),
            other => prop_assert!(false, "{:?}", other),
        }
        // Line–plane.
        if let LinePlane::Point(x) = line_plane(&la, &pl) {
            prop_assert!((n.dot(&x.coords) - off).abs() <= tol * (1.0 + x.coords.norm()));
            prop_assert!(on_line(&x, &la, tol * (1.0 + x.coords.norm())));
        }
        // Line–sphere.
        let s1 = Sphere::from_centre_radius(c, r1).unwrap();
        if let LineSphere::TwoPoints(p, q) = line_sphere(&la, &s1) {
            for x in [p, q] {
                prop_assert!(((x - c).norm() - r1).abs() <= tol);
                prop_assert!(on_line(&x, &la, tol));
            }
            prop_assert!((q - p).dot(&la.direction()) >= 0.0);
        }
        // Plane–plane.
        if let Ok(pm) = Plane::from_points(a, c, d) {
            if let PlanePlane::Line(l) = plane_plane(&pl, &pm) {
                let s = l.support_point();
                prop_assert!(pl.normal().dot(&s.coords) - pl.offset() <= tol * (1.0 + s.coords.norm()));
                prop_assert!((pm.normal().dot(&s.coords) - pm.offset()).abs() <= tol * (1.0 + s.coords.norm()));
                prop_assert!(l.direction().dot(&pl.normal()).abs() <= tol);
                prop_assert!(l.direction().dot(&pm.normal()).abs() <= tol);
            }
        }
        // Sphere–plane: centre is the projection, r² = R² − h².
        if let SpherePlane::Circle(k) = sphere_plane(&s1, &pl) {
            let h = n.dot(&c.coords) - off;
            prop_assert!(close(&k.centre(), &(c - n * h), tol));
            prop_assert!((k.radius_squared() - (r1 * r1 - h * h)).abs() <= tol * r1 * r1);
            prop_assert!((k.normal().dot(&n).abs() - 1.0).abs() <= tol);
        }
        // Sphere–sphere: the radical plane.
        let s2 = Sphere::from_centre_radius(d, r2).unwrap();
        if let SphereSphere::Circle(k) = sphere_sphere(&s1, &s2) {
            let w = d - c;
            let dist = w.norm();
            let x = (dist * dist + r1 * r1 - r2 * r2) / (2.0 * dist);
            prop_assert!(close(&k.centre(), &(c + w * (x / dist)), tol * (1.0 + dist)));
            prop_assert!((k.radius_squared() - (r1 * r1 - x * x)).abs() <= tol * (1.0 + r1 * r1));
        }
    }

    /// Tangent points of exact tangencies lie on both objects.
    #[test]
    fn tangent_points_are_right(c in ipoint(), r in 1i32..4, r2 in 1i32..4, axis in 0usize..3, e in ivec(), internal in any::<bool>()) {
        let r = f64::from(r);
        let r2 = f64::from(r2);
        let mut u = Vector3::zeros();
        u[axis] = 1.0;
        let s = Sphere::from_centre_radius(c, r).unwrap();
        let touch = c + u * r;
        // Line tangent at `touch`.
        let mut dir = e;
        dir[axis] = 0.0;
        if dir != Vector3::zeros() {
            let l = Line::from_point_direction(touch, dir).unwrap();
            match line_sphere(&l, &s) {
                LineSphere::Tangent(x) => prop_assert!(close(&x, &touch, 1e-9), "{x} {touch}"),
                other => prop_assert!(false, "{:?}", other),
            }
        }
        // Plane tangent at `touch`.
        let p = Plane::from_normal_offset(u * 2.0, 2.0 * touch[axis]).unwrap();
        match sphere_plane(&s, &p) {
            SpherePlane::Tangent(x) => prop_assert!(close(&x, &touch, 1e-9), "{x} {touch}"),
            other => prop_assert!(false, "{:?}", other),
        }
        // Sphere tangent at `touch`, from outside or inside.
        prop_assume!(!(internal && r == r2));
        let c2 = if internal { c + u * (r - r2) } else { c + u * (r + r2) };
        let s2 = Sphere::from_centre_radius(c2, r2).unwrap();
        match (sphere_sphere(&s, &s2), internal) {
            (SphereSphere::TangentExternal(x), false) => prop_assert!(close(&x, &touch, 1e-9), "{x} {touch}"),
            (SphereSphere::TangentInternal(x), true) => prop_assert!(close(&x, &touch, 1e-9), "{x} {touch}"),
            other => prop_assert!(false, "{:?}", other),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// The ball side test equals the exact comparison of |x − c|² with r².
    #[test]
    fn sphere_side_matches_oracle(c in ipoint(), r in 0i32..4, x in ipoint(), w in warp(), by_points in any::<bool>()) {
        let rr = f64::from(r);
        let s = if by_points && r > 0 {
            let cs = w.p(c);
            let k = w.x(rr);
            Sphere::from_points([cs + v3(k, 0., 0.), cs - v3(k, 0., 0.), cs + v3(0., k, 0.), cs - v3(0., 0., k)]).unwrap()
        } else {
            Sphere::from_centre_radius(w.p(c), w.x(rr)).unwrap()
        };
        let xs = w.last(x);
        let d = sub(&qp(&xs), &qp(&w.p(c)));
        let r2 = q(w.x(rr)) * q(w.x(rr));
        let expected = r2.cmp(&dot(&d, &d));
        prop_assert_eq!(s.side(&xs), expected);
    }
}

// ---------------------------------------------------------------------------------------------
// The bounded sphere (a shape of the pair queries) and the conformal sphere.

#[test]
fn bounded_and_conformal_spheres_convert_both_ways() {
    for (c, r) in [
        (p3(1.0, -2.0, 0.5), 3.0),
        (p3(0.0, 0.0, 0.0), 0.0),
        (p3(1e150, 0.0, -1e-150), 2.5e149),
    ] {
        let bounded = cga_collide::Sphere::new(c, r).unwrap();
        let conformal = Sphere::from(bounded);
        assert_eq!((conformal.centre(), conformal.radius()), (c, Some(r)));
        // Back without loss.
        assert_eq!(cga_collide::Sphere::try_from(conformal), Ok(bounded));
    }
    // From four points: the f64 centre and radius of the exact sphere.
    let s = Sphere::from_points([
        p3(1.0, 0.0, 0.0),
        p3(-1.0, 0.0, 0.0),
        p3(0.0, 1.0, 0.0),
        p3(0.0, 0.0, 1.0),
    ])
    .unwrap();
    let bounded = cga_collide::Sphere::try_from(s).unwrap();
    assert!(close(bounded.centre(), &Point3::origin(), 1e-15));
    assert!((bounded.radius() - 1.0).abs() < 1e-15);
    // An imaginary sphere has no surface to convert to.
    let imaginary = Sphere::from_centre_squared_radius(Point3::origin(), -4.0).unwrap();
    let err = cga_collide::Sphere::try_from(imaginary).unwrap_err();
    assert!(matches!(err, Error::Degenerate { .. }), "{err}");
    assert!(err.to_string().contains("imaginary"), "{err}");
}

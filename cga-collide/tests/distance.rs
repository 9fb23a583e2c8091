//! Minimum distance: the exact rational distance of the oracle lies within the reported
//! certified bound; the exact variant equals the oracle; meshes agree with brute force.

use cga_collide::collider::Collider;
use cga_collide::ga_core::scalar::{rational_from_f64, Rational, Real};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query;
use cga_collide::testing::oracle;
use cga_collide::{Ball, Segment, Sphere, TriMesh, Triangle};
use proptest::prelude::*;

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        2 => (-3i32..=3).prop_map(f64::from),
        3 => -3.0f64..3.0,
        1 => (-3.0f64..3.0).prop_map(|x| x * 1e-7),
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

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap()
}

/// `d - e <= true distance <= d + e`, checked on squares in exact rationals.
fn within_bound(d: &query::CertifiedDistance, exact2: &Rational) -> Result<(), TestCaseError> {
    let hi = q(d.distance) + q(d.error_bound);
    prop_assert!(exact2 <= &(&hi * &hi), "above the bound: {:?}", d);
    let lo = q(d.distance) - q(d.error_bound);
    if lo > q(0.0) {
        prop_assert!(exact2 >= &(&lo * &lo), "below the bound: {:?}", d);
    }
    // The bound is tight for these well-scaled inputs.
    prop_assert!(d.error_bound <= 1e-12, "loose bound {:?}", d);
    Ok(())
}

fn dist2(a: &Point3<f64>, b: &Point3<f64>) -> f64 {
    (a - b).norm_squared()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn segment_segment(a in segment(), b in segment()) {
        let exact = oracle::hulls_distance2(&[*a.a(), *a.b()], &[*b.a(), *b.b()]);
        let d = query::distance_segment_segment(&a, &b);
        within_bound(&d, &exact)?;
        prop_assert!((dist2(&d.witness_a, &d.witness_b).sqrt() - d.distance).abs() <= 1e-12);
        prop_assert_eq!(query::exact_distance_segment_segment(&a, &b).distance2, exact);
    }

    #[test]
    fn segment_triangle(a in segment(), b in triangle()) {
        let exact = oracle::hulls_distance2(&[*a.a(), *a.b()], b.vertices());
        within_bound(&query::distance_segment_triangle(&a, &b), &exact)?;
        prop_assert_eq!(query::exact_distance_segment_triangle(&a, &b).distance2, exact);
    }

    #[test]
    fn triangle_triangle(a in triangle(), b in triangle()) {
        let exact = oracle::hulls_distance2(a.vertices(), b.vertices());
        let d = query::distance_triangle_triangle(&a, &b);
        within_bound(&d, &exact)?;
        let e = query::exact_distance_triangle_triangle(&a, &b);
        prop_assert_eq!(&e.distance2, &exact);
        // The exact witnesses realise the exact distance.
        let w: Rational = (0..3)
            .map(|k| (&e.witness_a[k] - &e.witness_b[k]).pow(2))
            .fold(q(0.0), |s, x| s + x);
        prop_assert_eq!(w, exact);
    }
}

/// The nearest pair by brute force over every triangle pair, exactly.
fn brute_exact(a: &Collider, b: &Collider) -> Rational {
    let mut best: Option<Rational> = None;
    for i in 0..a.mesh().num_triangles() {
        for j in 0..b.mesh().num_triangles() {
            let d =
                oracle::hulls_distance2(&a.mesh().corners(i as u32), &b.mesh().corners(j as u32));
            if best.as_ref().is_none_or(|b| &d < b) {
                best = Some(d);
            }
        }
    }
    best.unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2))]

    #[test]
    fn mesh_distance_within_its_bound(
        t in (-2.5f64..2.5, -2.5f64..2.5, -2.5f64..2.5),
        r in (-3.2f64..3.2, -3.2f64..3.2, -3.2f64..3.2),
    ) {
        let cube = Collider::new(
            TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.)).unwrap());
        let moved = cube
            .placed(&Isometry3::new(Vector3::new(t.0, t.1, t.2), Vector3::new(r.0, r.1, r.2)))
            .unwrap();
        let exact = brute_exact(&cube, &moved);
        let d = cube.distance(&moved).unwrap();
        within_bound(&d, &exact)?;
        let (i, j) = d.triangles.unwrap();
        let pair = oracle::hulls_distance2(&cube.mesh().corners(i),
                                           &moved.mesh().corners(j));
        prop_assert!((Real::to_f64(&pair).sqrt() - d.distance).abs() <= d.error_bound);
        let e = cube.exact_distance(&moved).unwrap();
        prop_assert_eq!(e.distance2, exact);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// Translations only, by multiples of 1/4: parallel faces, so many triangle pairs tie for
    /// the minimum (and touching placements give 0). The pruning must not lose the minimum.
    #[test]
    fn mesh_distance_with_ties_within_its_bound(
        t in (-12i32..=12, -12i32..=12, -12i32..=12),
    ) {
        let cube = Collider::new(
            TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.)).unwrap());
        let v = Vector3::new(f64::from(t.0), f64::from(t.1), f64::from(t.2)) * 0.25;
        let moved = cube.placed(&Isometry3::translation(v.x, v.y, v.z)).unwrap();
        // Brute force with the exact pairwise distance (checked against the oracle above).
        let tri = |c: &Collider, i| {
            let [a, b, c] = c.mesh().corners(i as u32);
            Triangle::new(a, b, c).unwrap()
        };
        let exact = (0..12)
            .flat_map(|i| (0..12).map(move |j| (i, j)))
            .map(|(i, j)| query::exact_distance_triangle_triangle(&tri(&cube, i), &tri(&moved, j)).distance2)
            .min()
            .unwrap();
        let d = cube.distance(&moved).unwrap();
        within_bound(&d, &exact)?;
        prop_assert_eq!(cube.exact_distance(&moved).unwrap().distance2, exact);
    }
}

#[test]
fn touching_and_intersecting_have_bound_zero() {
    let p = |x, y, z| Point3::new(x, y, z);
    let a = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
    let b = Triangle::new(p(1., 0., 0.), p(2., 0., 1.), p(2., 1., 0.)).unwrap();
    let d = query::distance_triangle_triangle(&a, &b);
    assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
    let c = Triangle::new(p(0.2, 0.2, -1.), p(0.2, 0.2, 1.), p(3., 3., 0.)).unwrap();
    let d = query::distance_triangle_triangle(&a, &c);
    assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
}

#[test]
fn bunny_against_a_moved_copy_agrees_with_brute_force_pair() {
    let bunny = TriMesh::bunny00().unit();
    let a = Collider::new(bunny.clone());
    let b = a.placed(&Isometry3::translation(1.2, 0.1, 0.0)).unwrap();
    let d = a.distance(&b).unwrap();
    assert!(d.distance > 0.0 && d.error_bound < 1e-12 * d.distance.max(1.0));
    // No pair is closer than the certified lower end, and some pair is within the upper end.
    assert!(!a.within_distance(&b, d.distance - 2.0 * d.error_bound));
    assert!(a.within_distance(&b, d.distance + d.error_bound));
}

// ---------------------------------------------------------------- balls and spheres

fn radius() -> impl Strategy<Value = f64> {
    prop_oneof![(0i32..=3).prop_map(f64::from), 0.0f64..3.0]
}

fn ball() -> impl Strategy<Value = Ball> {
    (point(), radius()).prop_map(|(c, r)| Ball::new(c, r).unwrap())
}

fn sphere() -> impl Strategy<Value = Sphere> {
    (point(), radius()).prop_map(|(c, r)| Sphere::new(c, r).unwrap())
}

/// The true distance written as `max(0, √x1 − r1, r2 − √x2)` (terms optional), exact rationals:
/// checks `d - e <= true <= d + e` on squares, without any square root.
struct Radial {
    /// `(x1, r1)`: the gap outside, `√x1 − r1`.
    outside: Option<(Rational, Rational)>,
    /// `(x2, r2)`: the gap inside, `r2 − √x2`.
    inside: Option<(Rational, Rational)>,
}

impl Radial {
    /// `true distance <= t`.
    fn at_most(&self, t: &Rational) -> bool {
        let zero = q(0.0);
        self.outside.as_ref().is_none_or(|(x, r)| {
            let s = t + r;
            s >= zero && x <= &(&s * &s)
        }) && self.inside.as_ref().is_none_or(|(x, r)| {
            let s = r - t;
            s <= zero || x >= &(&s * &s)
        })
    }

    /// `true distance >= t` (for `t > 0`).
    fn at_least(&self, t: &Rational) -> bool {
        let zero = q(0.0);
        self.outside.as_ref().is_some_and(|(x, r)| {
            let s = t + r;
            s <= zero || x >= &(&s * &s)
        }) || self.inside.as_ref().is_some_and(|(x, r)| {
            let s = r - t;
            s >= zero && x <= &(&s * &s)
        })
    }

    fn check(&self, d: &query::CertifiedDistance) -> Result<(), TestCaseError> {
        // The witnesses are (up to rounding) as far apart as the distance.
        let w = dist2(&d.witness_a, &d.witness_b).sqrt();
        prop_assert!((w - d.distance).abs() <= 1e-9, "witnesses {:?}", d);
        let (dd, e) = (q(d.distance), q(d.error_bound));
        prop_assert!(self.at_most(&(&dd + &e)), "above the bound: {:?}", d);
        let lo = &dd - &e;
        if lo > q(0.0) {
            prop_assert!(self.at_least(&lo), "below the bound: {:?}", d);
        }
        prop_assert!(d.error_bound <= 1e-12, "loose bound {:?}", d);
        Ok(())
    }
}

/// `w` lies in the ball (`solid`) or on the sphere of centre `c` and radius `r`, up to rounding.
fn on(w: &Point3<f64>, c: &Point3<f64>, r: f64, solid: bool) -> Result<(), TestCaseError> {
    let d = dist2(w, c).sqrt();
    let slack = 1e-9 * (1.0 + r + d);
    prop_assert!(
        d <= r + slack && (solid || d >= r - slack),
        "{w} vs ({c}, {r})"
    );
    Ok(())
}

fn centres2(a: &Point3<f64>, b: &Point3<f64>) -> Rational {
    oracle::hulls_distance2(&[*a], &[*b])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn ball_ball(a in ball(), b in ball()) {
        let x = centres2(a.centre(), b.centre());
        let d = query::distance_ball_ball(&a, &b);
        Radial { outside: Some((x, q(a.radius()) + q(b.radius()))), inside: None }.check(&d)?;
        on(&d.witness_a, a.centre(), a.radius(), true)?;
        on(&d.witness_b, b.centre(), b.radius(), true)?;
    }

    #[test]
    fn ball_sphere(a in ball(), b in sphere()) {
        // Distances from b's centre to the ball: [max(0, d − ra), d + ra].
        let x = centres2(a.centre(), b.centre());
        Radial {
            outside: Some((x.clone(), q(a.radius()) + q(b.radius()))),
            inside: Some((x, q(b.radius()) - q(a.radius()))),
        }
        .check(&query::distance_ball_sphere(&a, &b))?;
        let d = query::distance_ball_sphere(&a, &b);
        on(&d.witness_a, a.centre(), a.radius(), true)?;
        on(&d.witness_b, b.centre(), b.radius(), false)?;
    }

    #[test]
    fn sphere_sphere(a in sphere(), b in sphere()) {
        let x = centres2(a.centre(), b.centre());
        let (ra, rb) = (q(a.radius()), q(b.radius()));
        let (big, small) = if ra >= rb { (ra.clone(), rb.clone()) } else { (rb.clone(), ra.clone()) };
        Radial { outside: Some((x.clone(), &ra + &rb)), inside: Some((x, big - small)) }
            .check(&query::distance_sphere_sphere(&a, &b))?;
        let d = query::distance_sphere_sphere(&a, &b);
        on(&d.witness_a, a.centre(), a.radius(), false)?;
        on(&d.witness_b, b.centre(), b.radius(), false)?;
    }

    #[test]
    fn segment_and_triangle_with_balls_and_spheres(
        s in segment(),
        t in triangle(),
        c in point(),
        r in radius(),
    ) {
        let (ball, sphere) = (Ball::new(c, r).unwrap(), Sphere::new(c, r).unwrap());
        for (pts, to_ball, to_sphere) in [
            (vec![*s.a(), *s.b()], query::distance_segment_ball(&s, &ball),
             query::distance_segment_sphere(&s, &sphere)),
            (t.vertices().to_vec(), query::distance_triangle_ball(&t, &ball),
             query::distance_triangle_sphere(&t, &sphere)),
        ] {
            let (near, far) = oracle::hull_distance2(&pts, &c);
            Radial { outside: Some((near.clone(), q(r))), inside: None }.check(&to_ball)?;
            Radial { outside: Some((near, q(r))), inside: Some((far, q(r))) }.check(&to_sphere)?;
            on(&to_ball.witness_b, &c, r, true)?;
            on(&to_sphere.witness_b, &c, r, false)?;
            // The witnesses are (up to rounding) as far apart as the distance.
            for d in [&to_ball, &to_sphere] {
                let w = dist2(&d.witness_a, &d.witness_b).sqrt();
                prop_assert!((w - d.distance).abs() <= 1e-9, "witnesses {:?}", d);
            }
        }
    }
}

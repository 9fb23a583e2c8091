//! The exact tests against Möller / Euclidean references in general position, and against the
//! independent exact oracle on adversarial input.

use cga_collide::exact::predicates::{
    BallBall, EdgeSide, LineDistance, LineLineReach, NormalY, Orient2d, Orient3d, PlaneDistance,
    SphereSphere,
};
use cga_collide::exact::{exact_sign, ErrF64, ExactKernel, Expansion, Kernel, Predicate};
use cga_collide::nalgebra::Point3;
use cga_collide::testing::adversarial::{adversarial_set, triangle_pairs};
use cga_collide::testing::baseline;
use cga_collide::testing::oracle::{self, Shape};
use cga_collide::testing::{rational_exact_sign, FloatKernel, IntersectsWith};
use cga_collide::{Ball, Intersects, Segment, Sphere, Triangle};
use proptest::prelude::*;

fn pf() -> impl Strategy<Value = Point3<f64>> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_map(|(x, y, z)| Point3::new(x, y, z))
}
fn tf() -> impl Strategy<Value = Triangle> {
    (pf(), pf(), pf()).prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap())
}
fn sf() -> impl Strategy<Value = Segment> {
    (pf(), pf()).prop_map(|(a, b)| Segment::new(a, b).unwrap())
}
fn ballf() -> impl Strategy<Value = Ball> {
    (pf(), 0.0f64..1.0).prop_map(|(c, r)| Ball::new(c, r).unwrap())
}
fn pi() -> impl Strategy<Value = Point3<f64>> {
    (-3i32..=3, -3i32..=3, -3i32..=3)
        .prop_map(|(x, y, z)| Point3::new(x as f64, y as f64, z as f64))
}
fn ti() -> impl Strategy<Value = Triangle> {
    (pi(), pi(), pi()).prop_map(|(a, b, c)| Triangle::new(a, b, c).unwrap())
}

#[test]
fn fixed_adversarial_set_has_zero_disagreements() {
    let set = adversarial_set(2026, 100);
    assert_eq!(set.len(), 900);
    let mut wrong = Vec::new();
    let mut float_wrong = 0;
    for c in &set {
        let t = c.truth();
        if c.intersects_with::<ExactKernel>() != t || c.intersects_swapped() != t {
            wrong.push(*c);
        }
        float_wrong += (c.intersects_with::<FloatKernel>() != t) as usize;
    }
    assert!(
        wrong.is_empty(),
        "{} disagreements, first: {:?}",
        wrong.len(),
        wrong[0]
    );
    // The set is adversarial: plain f64 evaluation must get a good number of cases wrong.
    assert!(
        float_wrong > 20,
        "only {float_wrong} float failures: the set is too easy"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(250))]

    /// Random adversarial cases of all nine kinds (coplanar, touching, shared features,
    /// degenerate, tangent, one-ulp perturbations, scales 1e-150..1e150) against the oracle.
    #[test]
    fn adversarial_cases_agree_with_oracle(seed in any::<u64>()) {
        for c in adversarial_set(seed, 1) {
            let t = c.truth();
            prop_assert_eq!(c.intersects_with::<ExactKernel>(), t, "{:?}", c);
            prop_assert_eq!(c.intersects_swapped(), t, "swapped {:?}", c);
        }
        for (a, b) in triangle_pairs(seed, 3) {
            let t = oracle::intersects(&Shape::from(&a), &Shape::from(&b));
            prop_assert_eq!(a.intersects(&b), t, "{:?} {:?}", a, b);
        }
    }

    /// Small integer triangles: very many coplanar, collinear, shared and degenerate cases.
    #[test]
    fn integer_triangles_agree_with_oracle(a in ti(), b in ti(), s in pi(), e in pi(), r in 0i32..4) {
        let t = oracle::intersects(&Shape::from(&a), &Shape::from(&b));
        prop_assert_eq!(a.intersects(&b), t, "{:?} {:?}", a, b);
        let seg = Segment::new(s, e).unwrap();
        let t = oracle::intersects(&Shape::from(&seg), &Shape::from(&a));
        prop_assert_eq!(seg.intersects(&a), t, "{:?} {:?}", seg, a);
        let ball = Ball::new(s, r as f64).unwrap();
        let sphere = Sphere::from(ball);
        prop_assert_eq!(a.intersects(&ball), oracle::intersects(&Shape::from(&a), &Shape::from(&ball)));
        prop_assert_eq!(a.intersects(&sphere), oracle::intersects(&Shape::from(&a), &Shape::from(&sphere)));
        let seg2 = Segment::new(e, b.vertices()[0]).unwrap();
        prop_assert_eq!(seg.intersects(&seg2), oracle::intersects(&Shape::from(&seg), &Shape::from(&seg2)));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// General position: the exact tests agree with the Euclidean references.
    #[test]
    fn general_position_agrees_with_references(a in tf(), b in tf(), s in sf(), ball in ballf()) {
        prop_assert_eq!(a.intersects(&b), baseline::moller_tri_tri(&a, &b), "{:?} {:?}", a, b);
        prop_assert_eq!(s.intersects(&a), baseline::moller_trumbore_segment_triangle(&s, &a));
        prop_assert_eq!(s.intersects(&ball), baseline::segment_ball(&s, &ball));
        prop_assert_eq!(a.intersects(&ball), baseline::triangle_ball(&a, &ball));
        let sphere = Sphere::from(ball);
        prop_assert_eq!(s.intersects(&sphere), baseline::segment_sphere(&s, &sphere));
        prop_assert_eq!(a.intersects(&sphere), baseline::triangle_sphere(&a, &sphere));
        let other = Ball::new(b.vertices()[0], 0.7).unwrap();
        prop_assert_eq!(ball.intersects(&other), baseline::ball_ball(&ball, &other));
        prop_assert_eq!(sphere.intersects(&Sphere::from(other)), baseline::sphere_sphere(&sphere, &Sphere::from(other)));
        // The plain-f64 variant of the same algorithm agrees too in general position.
        prop_assert_eq!(a.intersects_with::<FloatKernel>(&b), a.intersects(&b));
    }

    /// Whenever the f64 filter claims a sign, it is the exact sign.
    #[test]
    fn filter_is_sound(x in proptest::array::uniform12(-4i32..4), k in 0usize..12, ulps in -3i64..3, scale in prop::sample::select(vec![1e-150, 1e-40, 1.0, 3.0e40, 1e150])) {
        let mut v: [f64; 12] = core::array::from_fn(|i| x[i] as f64 * scale);
        v[k] = f64::from_bits((v[k].to_bits() as i64 + ulps) as u64);
        let e: [ErrF64; 12] = core::array::from_fn(|i| ErrF64::exact(v[i]));
        if let Some(s) = Orient3d::eval(&e).sign() {
            prop_assert_eq!(s, exact_sign::<Orient3d, 12>(&v));
        }
        prop_assert_eq!(ExactKernel::sign::<Orient3d, 12>(&v), exact_sign::<Orient3d, 12>(&v));
        // The integer-scaled exact path agrees with plain rational evaluation.
        prop_assert_eq!(exact_sign::<Orient3d, 12>(&v), rational_exact_sign::<Orient3d, 12>(&v));
        let w: [f64; 8] = core::array::from_fn(|i| (x[i] as f64).abs() * scale);
        prop_assert_eq!(ExactKernel::sign::<SphereSphere, 8>(&w), rational_exact_sign::<SphereSphere, 8>(&w));
    }

    /// The allocation-free exact stage (floating-point expansions, and the hand-written
    /// orientations) agrees with big integers wherever it answers, on exact zeros and near
    /// misses of many predicates (degrees 2 to 6) at every scale; and the full staged decision
    /// equals the big-integer sign everywhere.
    #[test]
    fn expansions_agree_with_big_integers(
        x in proptest::array::uniform16(-6i32..6),
        k in 0usize..16,
        ulps in -2i64..3,
        fraction in prop::sample::select(vec![0.0, 0.1, 1.0 / 3.0, 0.7]),
        scale in prop::sample::select(vec![1e-150, 1e-40, 1.0, 7.3, 3.0e40, 1e150]),
    ) {
        // A coarse grid (many exact zeros: coplanar, collinear, tangent), one coordinate off by
        // an inexact fraction and a few ulps (near misses, inexact differences).
        let mut v: [f64; 16] = core::array::from_fn(|i| x[i] as f64 * scale);
        v[k] = f64::from_bits(((v[k] + fraction * scale).to_bits() as i64 + ulps) as u64);
        fn check<P: Predicate<N>, const N: usize>(v: &[f64; 16]) -> Result<(), TestCaseError> {
            let x: [f64; N] = core::array::from_fn(|i| v[i]);
            let want = exact_sign::<P, N>(&x);
            let e: [Expansion; N] = core::array::from_fn(|i| Expansion::from_f64(x[i]));
            if let Some(got) = P::eval(&e).sign() {
                prop_assert_eq!(got, want, "expansion, {:?}", x);
            }
            if let Some(got) = P::exact_sign_direct(&x) {
                prop_assert_eq!(got, want, "hand-written, {:?}", x);
            }
            prop_assert_eq!(ExactKernel::sign::<P, N>(&x), want, "staged, {:?}", x);
            Ok(())
        }
        check::<Orient3d, 12>(&v)?;
        check::<Orient2d, 6>(&v)?;
        check::<NormalY, 9>(&v)?;
        check::<EdgeSide, 12>(&v)?;
        check::<SphereSphere, 8>(&v)?;
        check::<BallBall, 8>(&v)?;
        check::<LineDistance, 10>(&v)?;
        check::<PlaneDistance, 13>(&v)?;
        check::<LineLineReach, 13>(&v)?;
    }
}

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

#[test]
fn touching_and_degenerate_examples() {
    let t = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
    // Vertex on the hypotenuse, from above: touches.
    let u = Triangle::new(p(0.5, 0.5, 0.), p(1., 1., 1.), p(2., 0.5, 1.)).unwrap();
    assert!(t.intersects(&u));
    // One ulp above: does not.
    let up = Triangle::new(
        p(0.5, 0.5, f64::from_bits(1)),
        p(1., 1., 1.),
        p(2., 0.5, 1.),
    )
    .unwrap();
    assert!(!t.intersects(&up));
    // Coplanar, sharing only the vertex (1, 0, 0).
    let c = Triangle::new(p(1., 0., 0.), p(2., 0., 0.), p(1., -1., 0.)).unwrap();
    assert!(t.intersects(&c));
    // Degenerate triangle (a segment) crossing the interior, and a point triangle outside.
    let d = Triangle::new(p(0.2, 0.2, -1.), p(0.2, 0.2, 1.), p(0.2, 0.2, 0.)).unwrap();
    assert!(t.intersects(&d));
    let q = Triangle::new(p(1., 1., 0.), p(1., 1., 0.), p(1., 1., 0.)).unwrap();
    assert!(!t.intersects(&q));
    // Zero-length segment on the edge.
    let s = Segment::new(p(0.5, 0., 0.), p(0.5, 0., 0.)).unwrap();
    assert!(s.intersects(&t) && t.intersects(&s));
    // Tangent spheres and a triangle tangent to a sphere (3-4-5 distances).
    let s1 = Sphere::new(p(0., 0., 0.), 2.).unwrap();
    let s2 = Sphere::new(p(0., 3., 4.), 3.).unwrap();
    assert!(s1.intersects(&s2));
    assert!(
        !s1.intersects(&Sphere::new(p(0., 3., 4.), f64::from_bits(3f64.to_bits() - 1)).unwrap())
    );
    let above = Sphere::new(p(0.25, 0.25, 1.), 1.).unwrap();
    assert!(t.intersects(&above) && above.intersects(&t));
    assert!(
        !t.intersects(&Sphere::new(p(0.25, 0.25, 1.), f64::from_bits(1f64.to_bits() - 1)).unwrap())
    );
    // Triangle strictly inside a sphere does not meet the surface but meets the ball.
    let big = Sphere::new(p(0.2, 0.2, 0.), 10.).unwrap();
    assert!(!t.intersects(&big) && t.intersects(&Ball::from(big)));
    // Radius-0 sphere is a point.
    assert!(t.intersects(&Sphere::new(p(0.3, 0.3, 0.), 0.).unwrap()));
    assert!(!t.intersects(&Ball::new(p(0.3, 0.3, 1e-300), 0.).unwrap()));
}

#[test]
fn extreme_scales() {
    for scale in [1e-150, 1e-100, 1.0, 1e100, 1e150] {
        let t = Triangle::new(p(0., 0., 0.), p(scale, 0., 0.), p(0., scale, 0.)).unwrap();
        let u = Triangle::new(
            p(scale / 2., scale / 2., 0.),
            p(scale, scale, scale),
            p(2. * scale, scale / 2., scale),
        )
        .unwrap();
        assert!(t.intersects(&u), "scale {scale}");
        let z = f64::from_bits(1).max(scale * 1e-300);
        let v = Triangle::new(
            p(scale / 2., scale / 2., z),
            p(scale, scale, scale),
            p(2. * scale, scale / 2., scale),
        )
        .unwrap();
        assert!(!t.intersects(&v), "scale {scale}");
        let b = Ball::new(p(scale / 4., scale / 4., scale), scale).unwrap();
        assert!(
            t.intersects(&b) && t.intersects(&Sphere::from(b)),
            "scale {scale}"
        );
    }
}

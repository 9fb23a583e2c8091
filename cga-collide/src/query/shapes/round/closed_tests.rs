//! The closed forms against the exact method: every answer they give must be the exact one,
//! on random pairs and on pairs built to touch (then moved by a hair either way); and they
//! must answer most generic pairs (else they are no fast path).

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

use super::closed::within;
use super::exact_answer;
use crate::shape::{Capsule, Cone, Cylinder, HalfSpace, Shape};
use crate::{Ball, Segment};

fn pt(v: &[f64]) -> Point3<f64> {
    Point3::new(v[0], v[1], v[2])
}

/// A cylinder or a cone on the axis `a → b` of radius `r`.
fn round(cone: bool, a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    if cone {
        Cone::new(a, b, r).unwrap().into()
    } else {
        Cylinder::new(a, b, r).unwrap().into()
    }
}

/// The closed form's answer (both orders) is `None` or the exact one; returns whether it
/// answered.
fn agrees(a: &Shape, b: &Shape, c: f64) -> Result<bool, TestCaseError> {
    let exact = exact_answer("within_distance", a, b, c).unwrap();
    let mut answered = false;
    for (p, q) in [(a, b), (b, a)] {
        if let Some(proved) = within(p, q, c) {
            prop_assert_eq!(proved, exact, "{:?} {:?} c = {}", p, q, c);
            answered = true;
        }
    }
    Ok(answered)
}

/// A unit vector perpendicular to `u`.
fn across(u: &Vector3<f64>) -> Vector3<f64> {
    let w = if u.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    u.cross(&w).normalize()
}

fn coords() -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(-2.0f64..2.0, 3)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn random_pairs_agree_with_the_exact_method(
        cone in any::<bool>(),
        a in coords(), b in coords(), r in 0.1f64..1.5,
        p in coords(), q in coords(), s in 0.0f64..1.0,
        c in prop::sample::select(vec![0.0, 0.25, 1.0]),
    ) {
        let solid = round(cone, pt(&a), pt(&b), r);
        let others: Vec<Shape> = vec![
            Ball::new(pt(&p), s).unwrap().into(),
            Capsule::new(pt(&p), pt(&q), s).unwrap().into(),
            Segment::new(pt(&p), pt(&q)).unwrap().into(),
            HalfSpace::new(pt(&p), Vector3::new(q[0], q[1], q[2] + 0.01)).unwrap().into(),
        ];
        for other in &others {
            agrees(&solid, other, c)?;
        }
    }

    #[test]
    fn touching_pairs_and_a_hair_either_way_agree(
        cone in any::<bool>(),
        a in coords(), b in coords(), r in 0.1f64..1.5,
        // Where on the profile the contact is: along the side or slant (0..1), on a cap (1..2).
        place in 0.0f64..2.0, s in 0.0f64..1.0,
        hair in prop::sample::select(vec![0.0, 1e-15, -1e-15, 1e-9, -1e-9]),
    ) {
        let (a, b) = (pt(&a), pt(&b));
        prop_assume!((b - a).norm() > 0.1);
        let solid = round(cone, a, b, r);
        let axis = (b - a).normalize();
        let side = across(&axis);
        let h = (b - a).norm();
        // A boundary point of the profile and its outward normal in the meridian plane.
        let (t, rho, normal) = if place < 1.0 {
            if cone {
                let slant = Vector3::new(-r, h, 0.0).normalize(); // (axial, radial)
                (place * h, place * r, slant)
            } else {
                (place * h, r, Vector3::new(0.0, 1.0, 0.0))
            }
        } else {
            (h, (place - 1.0) * r, Vector3::new(1.0, 0.0, 0.0))
        };
        let on = a + axis * t + side * rho;
        let out = axis * normal.x + side * normal.y;
        let gap = s + hair;
        let ball: Shape = Ball::new(on + out * gap, s).unwrap().into();
        agrees(&solid, &ball, 0.0)?;
        // A capsule tangent to the surface there (across the meridian plane), its segment
        // `s + hair` out.
        let along = axis.cross(&side);
        let centre = on + out * gap;
        let capsule: Shape = Capsule::new(centre - along, centre + along, s).unwrap().into();
        agrees(&solid, &capsule, 0.0)?;
        let segment: Shape = Segment::new(on + out * hair - along, on + out * hair + along).unwrap().into();
        agrees(&solid, &segment, 0.0)?;
        // The half-space beyond a plane `hair` out from the boundary point (normal `−out`,
        // so it holds what lies outside the solid there): touching, or an ulp or two apart
        // either way.
        let plane: Shape = HalfSpace::new(on + out * hair, -out).unwrap().into();
        agrees(&solid, &plane, 0.0)?;
    }
}

#[test]
fn most_generic_pairs_are_answered() {
    let mut rng = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
    };
    let (mut answered, mut total) = (0, 0);
    for i in 0..200 {
        let mut p = || Point3::new(next(), next(), next());
        let solid = round(i % 2 == 0, p(), p(), 0.5);
        let (x, y) = (p(), p());
        for other in [
            Shape::from(Ball::new(x, 0.3).unwrap()),
            Capsule::new(x, y, 0.3).unwrap().into(),
            HalfSpace::new(x, y - Point3::origin()).unwrap().into(),
        ] {
            total += 1;
            answered += usize::from(within(&solid, &other, 0.0).is_some());
        }
    }
    assert!(answered * 100 >= total * 95, "{answered} of {total}");
}

#[test]
fn degenerate_and_huge_inputs_are_left_undecided_or_right() {
    let big = 1e150;
    let cyl = round(
        false,
        Point3::new(-big, 0.0, 0.0),
        Point3::new(big, 0.0, 0.0),
        big,
    );
    let ball: Shape = Ball::new(Point3::new(0.0, 3.0 * big, 0.0), big)
        .unwrap()
        .into();
    if let Some(p) = within(&cyl, &ball, 0.0) {
        assert!(!p);
    }
    let tiny = 1e-150;
    let cone = round(true, Point3::origin(), Point3::new(0.0, 0.0, tiny), tiny);
    let ball: Shape = Ball::new(Point3::new(0.0, 0.0, 0.5 * tiny), 0.0)
        .unwrap()
        .into();
    assert_eq!(
        within(&cone, &ball, 0.0).unwrap_or(true),
        exact_answer("intersects", &cone, &ball, 0.0).unwrap()
    );
}

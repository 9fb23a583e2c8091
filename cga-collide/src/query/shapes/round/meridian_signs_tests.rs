//! The integer-sign ball test against the rational one ([`super::meridian`], reached through
//! the exact method): exact tangencies on every part of the profile, moved by an ulp either
//! way, and random pairs near and far.

use nalgebra::Point3;
use proptest::prelude::*;

use super::exact_answer;
use super::meridian_signs::within;
use crate::shape::{Cone, Cylinder, Shape};
use crate::Ball;

fn cylinder(a: [f64; 3], b: [f64; 3], r: f64) -> Shape {
    Cylinder::new(a.into(), b.into(), r).unwrap().into()
}

fn cone(apex: [f64; 3], base: [f64; 3], r: f64) -> Shape {
    Cone::new(apex.into(), base.into(), r).unwrap().into()
}

fn ball(c: [f64; 3], r: f64) -> Shape {
    Ball::new(Point3::from(c), r).unwrap().into()
}

fn same_as_exact(a: &Shape, b: &Shape, c: f64) {
    let exact = exact_answer("within_distance", a, b, c).unwrap();
    assert_eq!(within(a, b, c), Some(exact), "{a:?} {b:?} c = {c}");
    assert_eq!(within(b, a, c), Some(exact), "{b:?} {a:?} c = {c}");
}

/// Exactly touching pairs (dyadic data): the ball's radius is the exact distance.
fn tangencies() -> Vec<(Shape, [f64; 3], f64)> {
    let cyl = cylinder([0.0, 0.0, 0.0], [0.0, 0.0, 2.0], 1.0);
    // Apex at the origin, base at z = 4, radius 3: the slant has the direction (4, 3) / 5.
    let k = cone([0.0, 0.0, 0.0], [0.0, 0.0, 4.0], 3.0);
    vec![
        (cyl.clone(), [2.0, 0.0, 1.0], 1.0),           // side
        (cyl.clone(), [0.5, 0.0, 3.0], 1.0),           // cap
        (cyl.clone(), [4.0, 0.0, 6.0], 5.0),           // rim (3-4-5 from (1, 0, 2))
        (cyl.clone(), [0.0, 0.0, -0.25], 0.25),        // bottom cap centre
        (k.clone(), [5.5, 0.0, -1.0], 5.0),            // slant, interior foot at (1.5, 0, 2)
        (k.clone(), [0.0, 0.0, -0.5], 0.5),            // apex along the axis
        (k.clone(), [-3.0, 0.0, -4.0], 5.0),           // apex, off the axis
        (k.clone(), [1.0, 0.0, 4.5], 0.5),             // base disc
        (k.clone(), [3.0 + 4.0, 0.0, 4.0 + 3.0], 5.0), // rim (3-4-5 from (3, 0, 4))
        (k, [1.0, 0.0, 2.0], 0.0),                     // a point inside
    ]
}

#[test]
fn exact_tangencies_and_one_ulp_either_way() {
    for (solid, centre, r) in tangencies() {
        for radius in [r, r.next_up(), r.next_down().max(0.0)] {
            same_as_exact(&solid, &ball(centre, radius), 0.0);
            // The same touching through the clearance instead of the radius.
            same_as_exact(&solid, &ball(centre, 0.0), radius);
        }
        for scale in [2f64.powi(-300), 2f64.powi(300)] {
            let moved = ball(centre.map(|v| v * scale), (r * scale).next_down().max(0.0));
            let scaled = match &solid {
                Shape::Cylinder(c) => cylinder(
                    (c.a().coords * scale).into(),
                    (c.b().coords * scale).into(),
                    c.radius() * scale,
                ),
                Shape::Cone(c) => cone(
                    (c.apex().coords * scale).into(),
                    (c.base().coords * scale).into(),
                    c.radius() * scale,
                ),
                _ => unreachable!(),
            };
            same_as_exact(&scaled, &moved, 0.0);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_balls_agree(
        is_cone in any::<bool>(),
        a in prop::array::uniform3(-2.0f64..2.0), b in prop::array::uniform3(-2.0f64..2.0),
        r in 0.0f64..1.5, v in prop::array::uniform3(-3.0f64..3.0), s in 0.0f64..2.0,
        c in prop::sample::select(vec![0.0, 0.5]),
    ) {
        prop_assume!(a != b);
        let solid = if is_cone { cone(a, b, r) } else { cylinder(a, b, r) };
        let exact = exact_answer("within_distance", &solid, &ball(v, s), c).unwrap();
        prop_assert_eq!(within(&solid, &ball(v, s), c), Some(exact));
    }
}

//! The certified distance of the curved pairs without an exact distance method, checked
//! against the exact clearance tests where those decide every clearance (a cylinder or cone
//! against a segment or a capsule, two parallel cylinders), against `intersects` for the
//! polytope pairs, and against closed forms on constructed pairs.

use nalgebra::{Point3, Vector3};
use proptest::prelude::*;

use super::bounded_distance::distance;
use super::exact_answer;
use crate::query::CertifiedDistance;
use crate::shape::{Capsule, Cone, Cuboid, Cylinder, Shape};
use crate::{Segment, Triangle};

fn cylinder(a: [f64; 3], b: [f64; 3], r: f64) -> Shape {
    Cylinder::new(a.into(), b.into(), r).unwrap().into()
}

fn cone(apex: [f64; 3], base: [f64; 3], r: f64) -> Shape {
    Cone::new(apex.into(), base.into(), r).unwrap().into()
}

fn within(a: &Shape, b: &Shape, c: f64) -> bool {
    exact_answer("within_distance", a, b, c).expect("an exact method decides this pair")
}

/// The exact clearance tests agree with `d ± e`: within `d + e`, not within below `d − e`.
fn agrees_with_exact(a: &Shape, b: &Shape, d: &CertifiedDistance) {
    assert!(d.distance.is_finite() && d.error_bound >= 0.0, "{d:?}");
    let hi = d.distance + d.error_bound;
    assert!(within(a, b, hi), "not within {hi}: {a:?} {b:?} {d:?}");
    let lo = (d.distance - d.error_bound).next_down();
    if lo >= 0.0 {
        assert!(!within(a, b, lo), "within {lo}: {a:?} {b:?} {d:?}");
    }
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-2.0..2.0f64)
}

fn round_shape() -> impl Strategy<Value = Shape> {
    (point(), point(), 0.05..1.0f64, any::<bool>()).prop_filter_map(
        "an axis of positive length",
        |(a, b, r, is_cone)| {
            let d = Vector3::from(b) - Vector3::from(a);
            (d.norm() > 0.1).then(|| {
                if is_cone {
                    cone(a, b, r)
                } else {
                    cylinder(a, b, r)
                }
            })
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Against a segment or a capsule the exact method decides every clearance.
    #[test]
    fn segments_and_capsules_agree_with_the_exact_clearance(
        round in round_shape(), p in point(), q in point(), r in 0.0..0.5f64,
    ) {
        let other: Shape = if r == 0.0 || p == q {
            Segment::new(p.into(), q.into()).unwrap().into()
        } else {
            Capsule::new(p.into(), q.into(), r).unwrap().into()
        };
        // A pair the bounds cannot settle is refused (the caller's `UnsupportedPair`); an
        // answer must hold the exact distance. How tight it is depends on the search's
        // convergence and is measured on the constructed gaps below.
        if let Some(d) = distance(&round, &other) {
            agrees_with_exact(&round, &other, &d);
        }
    }

    /// Two parallel cylinders: decided exactly at every clearance (coordinates on a grid of
    /// `1/64`, so the axes are exactly parallel).
    #[test]
    fn parallel_cylinders_agree_with_the_exact_clearance(
        a in prop::array::uniform3(-64..64i32), b in prop::array::uniform3(-64..64i32),
        along in -32..32i32, len in 8..64i32, ra in 2..40i32, rb in 2..40i32,
    ) {
        let grid = |k: i32| f64::from(k) / 64.0;
        let axis = [0.0, 0.25, 0.5];
        let at = |p: [i32; 3], t: i32| core::array::from_fn::<f64, 3, _>(|k| grid(p[k]) + grid(t) * axis[k]);
        let first = cylinder(at(a, 0), at(a, len), grid(ra));
        let second = cylinder(at(b, along), at(b, along + len), grid(rb));
        // Exactly touching pairs of the grid may be refused (no proved common point, no
        // witnesses proved inside); every answer must hold the exact distance.
        if let Some(d) = distance(&first, &second) {
            agrees_with_exact(&first, &second, &d);
        }
    }

    /// Against triangles and cuboids: a positive lower end means they do not meet, a proved
    /// zero that they do.
    #[test]
    fn polytopes_agree_with_intersects(
        round in round_shape(), p in point(), q in point(), s in point(), h in 0.05..1.0f64,
    ) {
        let shapes: Vec<Shape> = [
            Triangle::new(p.into(), q.into(), s.into()).ok().map(Shape::from),
            Cuboid::axis_aligned(p.into(), Vector3::new(h, 0.5 * h, 2.0 * h)).ok().map(Shape::from),
        ]
        .into_iter()
        .flatten()
        .collect();
        for other in shapes {
            let Some(d) = distance(&round, &other) else { continue };
            let meets = within(&round, &other, 0.0);
            if d.distance - d.error_bound > 0.0 {
                prop_assert!(!meets, "{:?} {:?} {:?}", round, other, d);
            }
            if d.distance == 0.0 && d.error_bound == 0.0 {
                prop_assert!(meets, "{:?} {:?} {:?}", round, other, d);
            }
        }
    }
}

/// A cylinder lying on a box, a cone standing above a triangle and two crossed cylinders,
/// each at a known gap, at scales `1` and `2^±40`.
#[test]
fn constructed_gaps_are_inside_their_bounds() {
    for scale in [1.0, 2f64.powi(40), 2f64.powi(-40)] {
        let s = |p: [f64; 3]| p.map(|x| x * scale);
        for gap in [0.5, 1e-3, 2f64.powi(-30)] {
            let g = gap * scale;
            let lying = cylinder(
                s([-1.0, 0.0, 0.5 + gap]),
                s([1.0, 0.0, 0.5 + gap]),
                0.5 * scale,
            );
            let block: Shape = Cuboid::axis_aligned(
                Point3::from(s([0.0, 0.0, -1.0])),
                Vector3::new(2.0, 2.0, 1.0) * scale,
            )
            .unwrap()
            .into();
            let standing = cone(s([0.0, 0.0, gap]), s([0.0, 0.0, 1.0 + gap]), 0.5 * scale);
            let floor: Shape = Triangle::new(
                Point3::from(s([-1.0, -1.0, 0.0])),
                Point3::from(s([2.0, -1.0, 0.0])),
                Point3::from(s([-1.0, 2.0, 0.0])),
            )
            .unwrap()
            .into();
            let crossed = cylinder(
                s([0.0, -1.0, 1.0 + gap]),
                s([0.0, 1.0, 1.0 + gap]),
                0.5 * scale,
            );
            let under = cylinder(s([-1.0, 0.0, 0.0]), s([1.0, 0.0, 0.0]), 0.5 * scale);
            for (a, b) in [(&lying, &block), (&standing, &floor), (&crossed, &under)] {
                for (x, y) in [(a, b), (b, a)] {
                    let d = distance(x, y).expect("measured");
                    assert!(
                        (d.distance - g).abs() <= d.error_bound,
                        "{gap} {scale} {d:?}"
                    );
                    assert!(d.error_bound <= 1e-9 * scale, "{gap} {scale} {d:?}");
                }
            }
        }
    }
}

/// Overlapping pairs are at distance exactly `0`; touching ones get a bound that holds `0`.
#[test]
fn overlapping_is_zero_and_touching_holds_zero() {
    let under = cylinder([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], 0.5);
    let deep = cylinder([0.0, -1.0, 0.5], [0.0, 1.0, 0.5], 0.5);
    let d = distance(&under, &deep).unwrap();
    assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
    let touching = cylinder([0.0, -1.0, 1.0], [0.0, 1.0, 1.0], 0.5);
    let d = distance(&under, &touching).unwrap();
    assert!(
        d.distance - d.error_bound <= 0.0 && d.error_bound <= 1e-9,
        "{d:?}"
    );
}

/// Two cylinders crossing at an angle, their common perpendicular meeting both axes inside,
/// `gap` apart along it: `(a, b, exact gap)`.
fn crossed(
    centre: [f64; 3],
    angle: f64,
    tilt: f64,
    along: [f64; 2],
    radii: [f64; 2],
    gap: f64,
) -> (Shape, Shape) {
    // Axis `u` in the xy-plane, `v` at `angle` from it in a plane tilted by `tilt`; the
    // perpendicular of both is `n`.
    let u = Vector3::new(1.0, 0.0, 0.0);
    let v = Vector3::new(
        angle.cos(),
        angle.sin() * tilt.cos(),
        angle.sin() * tilt.sin(),
    );
    let n = u.cross(&v).normalize();
    let c = Vector3::from(centre);
    let fa = c;
    let fb = c + n * (radii[0] + radii[1] + gap);
    let a = cylinder(
        (fa - u * along[0]).into(),
        (fa + u * (2.0 - along[0])).into(),
        radii[0],
    );
    let b = cylinder(
        (fb - v * along[1]).into(),
        (fb + v * (2.0 - along[1])).into(),
        radii[1],
    );
    (a, b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Crossed cylinders take the closed form of the curved sides: tight (within `1e-12`),
    /// and around the constructed gap (the inputs' rounding moves it by a few ulps).
    #[test]
    fn crossed_cylinders_take_the_closed_form(
        centre in point(), angle in 0.2..2.9f64, tilt in -1.5..1.5f64,
        along in prop::array::uniform2(0.3..1.7f64), radii in prop::array::uniform2(0.05..0.5f64),
        gap in 1e-6..1.0f64,
    ) {
        let (a, b) = crossed(centre, angle, tilt, along, radii, gap);
        let scale = super::filter::unit_scale(super::body::magnitude(&a).max(super::body::magnitude(&b)));
        let bodies = (super::bounded_distance::body(&a, scale).unwrap(), super::bounded_distance::body(&b, scale).unwrap());
        prop_assert!(super::bounded_distance::lateral(&bodies.0, &bodies.1).is_some());
        for (x, y) in [(&a, &b), (&b, &a)] {
            let d = distance(x, y).expect("measured");
            prop_assert!(d.error_bound <= 1e-12, "{:?}", d);
            prop_assert!((d.distance - gap).abs() <= d.error_bound + 1e-13, "{} {:?}", gap, d);
        }
    }

    /// The short search's lower bound never passes the certified distance's upper end.
    #[test]
    fn the_short_lower_bound_is_below_the_distance(
        round in round_shape(), other in round_shape(), p in point(), q in point(), s in point(),
    ) {
        let triangle: Shape = match Triangle::new(p.into(), q.into(), s.into()) {
            Ok(t) => t.into(),
            Err(_) => return Ok(()),
        };
        for b in [&other, &triangle] {
            let (Some(lower), Some(d)) = (super::bounded_distance::lower(&round, b), distance(&round, b)) else {
                continue;
            };
            prop_assert!(lower <= d.distance + d.error_bound, "{} {:?} {:?} {:?}", lower, d, round, b);
        }
    }
}

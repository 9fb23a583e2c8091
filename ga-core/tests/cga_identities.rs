//! Conformal identities of the generated Cl(4,1), in f64 and exactly.

use ga_core::cga::{self, n_0, n_inf, up, up_generic, Bivector, Multivector, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::Point3;
use proptest::prelude::*;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

#[test]
fn null_vectors_and_their_product() {
    let ni: Vector<Rational> = n_inf();
    let no: Vector<Rational> = n_0();
    assert_eq!(ni.scalar_product(&ni), r(0, 1));
    assert_eq!(no.scalar_product(&no), r(0, 1));
    assert_eq!(ni.scalar_product(&no), r(-1, 1));
    // The geometric squares are zero as multivectors too.
    assert_eq!(ni.clone() * ni, Rotor::zero());
    assert_eq!(no.clone() * no, Rotor::zero());
}

#[test]
fn pseudoscalar_squares_to_minus_one() {
    let i = cga::I::<f64>();
    assert_eq!(i * i, -1.0);
    assert_eq!(cga::e12345::<f64>(), i);
}

#[test]
fn vector_times_vector_has_25_terms() {
    // The geometric product of two vectors: 5 x 5 blade pairs, all nonzero in Cl(4,1).
    let a = Vector::new(1.0, 2.0, 3.0, 4.0, 5.0);
    let b = Vector::new(-2.0, 0.5, 1.0, 3.0, -1.0);
    let p = a * b;
    // scalar part = a·b with e5² = -1
    assert_eq!(p.s, -2.0 + 1.0 + 3.0 + 12.0 + 5.0);
    assert_eq!(p.e12, 1.0 * 0.5 - 2.0 * -2.0);
}

#[test]
fn display_uses_canonical_names() {
    let v = Vector::new(2.0, 0.0, 0.0, 0.0, 0.0)
        + Bivector::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5);
    assert_eq!(v.to_string(), "2·e1 - 0.5·e45");
    assert_eq!(Multivector::<f64>::zero().to_string(), "0");
    // Once printed `2e12 - 1e13 + 1e23`, which reads as three numbers in scientific notation.
    let b = Bivector::new(2.0, -1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    assert_eq!(b.to_string(), "2·e12 - 1·e13 + 1·e23");
    let mut c = [0.0; 32];
    (c[0], c[6], c[7], c[10]) = (3.0, 2.0, -1.0, 1.0);
    assert_eq!(
        Multivector::from_coefficients(c).to_string(),
        "3 + 2·e12 - 1·e13 + 1·e23"
    );
    assert_eq!(
        format!("{:?}", Vector::new(1.0, 0.0, 0.0, 0.0, -1.0)),
        "1.0·e1 - 1.0·e5"
    );
}

#[test]
fn dense_coefficients_round_trip() {
    let c: [f64; 32] = core::array::from_fn(|i| i as f64);
    let m = Multivector::from_coefficients(c);
    assert_eq!(m.coefficients(), c);
    assert_eq!(m.e12345, 31.0);
    assert_eq!(m.e1, 1.0);
    assert_eq!(m.e45, 15.0);
    assert_eq!(cga::BLADE_NAMES[26], "e1234");
}

proptest! {
    #[test]
    fn up_inner_product_is_half_squared_distance(
        x in prop::array::uniform3(-100i64..100), y in prop::array::uniform3(-100i64..100)
    ) {
        let px = up_generic(r(x[0], 3), r(x[1], 7), r(x[2], 1));
        let py = up_generic(r(y[0], 3), r(y[1], 7), r(y[2], 1));
        let d2 = (0..3).map(|i| {
            let d = [r(x[0] - y[0], 3), r(x[1] - y[1], 7), r(x[2] - y[2], 1)][i].clone();
            d.clone() * d
        }).fold(r(0, 1), |a, b| a + b);
        prop_assert_eq!(px.scalar_product(&py), -d2 / r(2, 1));
        prop_assert_eq!(px.scalar_product(&n_inf()), r(-1, 1));
    }

    #[test]
    fn up_then_down_round_trips(x in -1e6f64..1e6, y in -1e6f64..1e6, z in -1e6f64..1e6) {
        let p = Point3::new(x, y, z);
        let q = cga::down(&up(&p)).unwrap();
        prop_assert!((p - q).norm() <= 1e-9 * (1.0 + p.coords.norm()));
    }
}

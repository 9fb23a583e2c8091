//! `inverse()` of the generated types is never wrong: over exact rationals it is the true
//! inverse or `None` exactly when there is none in the type (checked against the dense
//! reference's Gaussian elimination); in `f64` a returned value is an inverse to working
//! accuracy, and a well-conditioned element always gets one. `versor_inverse()` is the plain
//! versor formula.

use ga_core::cga::{self, Even, Multivector, Odd, Rotor, Vector};
use ga_core::reference::{DenseMultivector, Signature};
use ga_core::scalar::{Rational, Ring};
use proptest::prelude::*;

fn sig() -> Signature {
    Signature::new(&[1, 1, 1, 1, -1]).unwrap()
}

fn dense<T: Ring>(m: impl Into<Multivector<T>>) -> DenseMultivector<T> {
    DenseMultivector::from_canonical(&sig(), m.into().coefficients().to_vec()).unwrap()
}

fn rational() -> impl Strategy<Value = Rational> {
    prop_oneof![
        1 => Just(Rational::from_i64(0)),
        3 => (-4i64..=4, 1i64..=3).prop_map(|(n, d)| Rational::new(n.into(), d.into())),
    ]
}

/// Mostly-small integer coefficients make singular and non-versor elements common.
fn exact_multivector() -> impl Strategy<Value = Multivector<Rational>> {
    prop::collection::vec(rational(), 32)
        .prop_map(|c| Multivector::from_coefficients(c.try_into().unwrap()))
}

fn f64_multivector() -> impl Strategy<Value = Multivector<f64>> {
    prop::collection::vec(-2.0f64..2.0, 32)
        .prop_map(|c| Multivector::from_coefficients(c.try_into().unwrap()))
}

/// The true inverse of `x` as an element of the type with blades `keep`, by the reference.
fn reference_inverse(
    x: &DenseMultivector<Rational>,
    keep: impl Fn(usize) -> bool,
) -> Option<DenseMultivector<Rational>> {
    x.general_inverse().filter(|inv| inv.project(&keep) == *inv)
}

fn is_even(mask: usize) -> bool {
    mask.count_ones().is_multiple_of(2)
}

proptest! {
    // Exact elimination on 32 x 32 rational matrices is slow (about 0.1 s a case in release):
    // few cases, small coefficients (singular cases are common).
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn exact_dense_inverse_is_true_or_none(x in exact_multivector()) {
        let dx = dense(x.clone());
        match x.inverse() {
            Some(y) => {
                let unit = DenseMultivector::one(&sig());
                prop_assert_eq!(dense(x.clone() * y.clone()), unit.clone());
                prop_assert_eq!(dense(y.clone() * x.clone()), unit);
            }
            None => prop_assert!(dx.general_inverse().is_none(), "x = {x} is invertible"),
        }
    }

    #[test]
    fn exact_sparse_inverses_match_the_reference(x in exact_multivector()) {
        let rotor = Rotor::from_multivector(&x);
        let even = Even::from_multivector(&x);
        let odd = Odd::from_multivector(&x);
        let vector = Vector::from_multivector(&x);
        let grades02 = |m: usize| m.count_ones() == 0 || m.count_ones() == 2;
        prop_assert_eq!(rotor.inverse().map(dense), reference_inverse(&dense(rotor), grades02));
        prop_assert_eq!(even.inverse().map(dense), reference_inverse(&dense(even), is_even));
        prop_assert_eq!(odd.inverse().map(dense), reference_inverse(&dense(odd), |m| !is_even(m)));
        prop_assert_eq!(
            vector.inverse().map(dense),
            reference_inverse(&dense(vector.clone()), |m| m.count_ones() == 1)
        );
        // For vectors (always blades) the versor formula is the inverse.
        prop_assert_eq!(vector.inverse(), vector.versor_inverse());
    }

}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn f64_inverse_is_an_inverse_and_exists_when_well_conditioned(x in f64_multivector()) {
        let dx = dense(x);
        let reference = dx.general_inverse();
        match x.inverse() {
            Some(y) => {
                let scale = 1e-11 * (1.0 + max_abs(&dx) * max_abs(&dense(y)));
                let unit = DenseMultivector::one(&sig());
                prop_assert!(max_abs(&(&dense(x * y) - &unit)) <= scale);
                prop_assert!(max_abs(&(&dense(y * x) - &unit)) <= scale);
            }
            None => {
                // Only a singular or badly conditioned element may be refused.
                if let Some(inv) = reference {
                    prop_assert!(max_abs(&dx) * max_abs(&inv) > 1e3, "refused x = {x}");
                }
            }
        }
    }

    #[test]
    fn f64_rotors_and_versors(
        a in prop::array::uniform5(-2.0f64..2.0),
        b in prop::array::uniform5(-2.0f64..2.0),
    ) {
        let (a, b) = (Vector::new(a[0], a[1], a[2], a[3], a[4]), Vector::new(b[0], b[1], b[2], b[3], b[4]));
        let r: Rotor<f64> = a * b;
        prop_assume!(r.norm_squared().abs() > 1e-3);
        // A versor: the checked inverse is the versor formula's answer.
        prop_assert_eq!(r.inverse(), r.versor_inverse());
    }
}

fn max_abs(m: &DenseMultivector<f64>) -> f64 {
    m.coefficients().iter().fold(0.0, |acc, c| acc.max(c.abs()))
}

#[test]
fn a_non_versor_where_the_versor_formula_is_wrong() {
    let q = |n: i64| Rational::from_i64(n);
    // 1 + e12 + e34 is in the even subalgebra but not a versor: X X̃ has an e1234 part.
    let x = Even::from(Rotor::new(
        q(1),
        q(1),
        q(0),
        q(0),
        q(0),
        q(0),
        q(0),
        q(0),
        q(1),
        q(0),
        q(0),
    ));
    let wrong = x.versor_inverse().unwrap();
    assert_ne!(dense(x.clone() * wrong), DenseMultivector::one(&sig()));
    let y = x.inverse().unwrap();
    assert_eq!(dense(x.clone() * y.clone()), DenseMultivector::one(&sig()));
    assert_eq!(dense(y * x.clone()), DenseMultivector::one(&sig()));
    // As a rotor-shaped element (grades 0 and 2), its inverse needs the grade-4 blade e1234.
    let r = Rotor::from_multivector(&Multivector::from(x));
    assert_eq!(r.inverse(), None);
    assert!(Multivector::from(r).inverse().is_some());
}

/// `1 + e1`: a zero divisor, `(1 + e1)(1 - e1) = 0`.
fn one_plus_e1<T: Ring>() -> Multivector<T> {
    Multivector::from_coefficients(core::array::from_fn(|i| {
        if i < 2 {
            T::one()
        } else {
            T::zero()
        }
    }))
}

#[test]
fn singular_and_non_finite_elements_have_none() {
    assert_eq!(cga::n_inf::<f64>().inverse(), None);
    assert_eq!(one_plus_e1::<f64>().inverse(), None);
    assert_eq!(one_plus_e1::<Rational>().inverse(), None);
    assert!(dense(one_plus_e1::<Rational>()).general_inverse().is_none());
    assert_eq!(Multivector::<f64>::zero().inverse(), None);
    assert_eq!(Vector::new(f64::NAN, 1.0, 0.0, 0.0, 0.0).inverse(), None);
    let inf = Multivector::from(Vector::new(f64::INFINITY, 1.0, 0.0, 0.0, 0.0));
    assert_eq!(inf.inverse(), None);
}

//! The macro at its limits: six generators with a mixed, degenerate signature, and basis names of
//! the user's choice. Checked against the run-time dense reference, exactly.

use ga_core::reference::{DenseMultivector, Signature};
use ga_core::scalar::Rational;
use proptest::prelude::*;

mod six {
    ga_macros::algebra! {
        name: six,
        signature: [+1, +1, +1, -1, -1, 0],
        types: {
            Vector: grade 1,
            Bivector: grade 2,
            Trivector: grade 3,
        },
        dense: Multivector,
    }
}

mod named {
    ga_macros::algebra! {
        name: named,
        signature: [+1, -1],
        basis: [plus, minus],
        types: { Vector: grade 1, Spinor: grades 0 2 },
    }
}

fn rational(n: i64) -> Rational {
    Rational::new(n.into(), 3.into())
}

fn dense(m: impl Into<six::Multivector<Rational>>) -> DenseMultivector<Rational> {
    let signature = Signature::new(&[1, 1, 1, -1, -1, 0]).unwrap();
    DenseMultivector::from_canonical(&signature, m.into().coefficients().to_vec()).unwrap()
}

fn coefficients() -> impl Strategy<Value = Vec<i64>> {
    prop::collection::vec(-9i64..=9, 64)
}

/// A multivector with the coefficients `c` on the blades whose grade passes `keep` (the grade of
/// a canonical name `eijk` is its length minus one; `1` is grade 0).
fn multivector(c: &[i64], keep: impl Fn(usize) -> bool) -> six::Multivector<Rational> {
    six::Multivector::from_coefficients(core::array::from_fn(|i| {
        if keep(six::BLADE_NAMES[i].len() - 1) {
            rational(c[i])
        } else {
            rational(0)
        }
    }))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn six_generator_products_match_the_reference(a in coefficients(), b in coefficients()) {
        let va = six::Vector::from_multivector(&multivector(&a, |g| g == 1));
        let bb = six::Bivector::from_multivector(&multivector(&b, |g| g == 2));
        let tb = six::Trivector::from_multivector(&multivector(&b, |g| g == 3));
        let da = dense(va.clone());
        let db = dense(bb.clone());
        let dt = dense(tb.clone());
        prop_assert_eq!(dense(va.clone() * bb.clone()), da.geometric(&db));
        prop_assert_eq!(dense(bb.clone() ^ tb.clone()), db.wedge(&dt));
        prop_assert_eq!(dense(va.clone() | tb.clone()), da.left_contraction(&dt));
        // Grades 3 and 2 in six dimensions meet in grade -1: the result is zero by grade.
        let nothing: ga_core::Zero<Rational> = tb.clone() & bb.clone();
        prop_assert_eq!(nothing.value(), rational(0));
        prop_assert!(dt.regressive(&db).is_zero());
        prop_assert_eq!(dense(va.dual()), da.dual());
        let full_a = multivector(&a, |_| true);
        let full_b = multivector(&b, |_| true);
        prop_assert_eq!(dense(full_a.clone() * full_b.clone()), dense(full_a.clone()).geometric(&dense(full_b.clone())));
        prop_assert_eq!(dense(full_a.clone() & full_b.clone()), dense(full_a.clone()).regressive(&dense(full_b.clone())));
        prop_assert_eq!(dense(full_a.undual()), dense(full_a.clone()).undual());
    }
}

#[test]
fn six_generators_have_64_blades_in_canonical_order() {
    assert_eq!(six::BLADE_NAMES.len(), 64);
    assert_eq!(six::BLADE_NAMES[1], "e1");
    assert_eq!(six::BLADE_NAMES[63], "e123456");
    assert_eq!(six::SIGNATURE, [1, 1, 1, -1, -1, 0]);
    // e6 squares to zero, e4 to -1.
    assert_eq!(six::e6::<f64>() | six::e6::<f64>(), 0.0);
    assert_eq!(six::e4::<f64>() | six::e4::<f64>(), -1.0);
}

#[test]
fn user_basis_names_name_fields_and_printing() {
    let v = named::Vector::new(2.0, -0.5);
    assert_eq!(v.plus, 2.0);
    assert_eq!(v.to_string(), "2·plus - 0.5·minus");
    let s: named::Spinor<f64> = v * named::Vector::new(0.0, 1.0);
    assert_eq!(s.plus_minus, 2.0);
    assert_eq!(named::BLADE_NAMES, ["1", "plus", "minus", "plus_minus"]);
}

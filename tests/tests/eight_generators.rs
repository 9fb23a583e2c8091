//! The macro past six generators: Cl(6,2), 256 blades, with no dense type. Only the declared
//! types and the products between them whose result a declared type holds are generated.
//! Checked exactly (rationals) against the run-time dense reference, which supports up to ten
//! generators.

use ga_core::prelude::*;
use ga_core::reference::{DenseMultivector, Signature};
use ga_core::scalar::Rational;
use proptest::prelude::*;

mod cl62 {
    ga_macros::algebra! {
        name: cl62,
        signature: [+1, +1, +1, +1, +1, +1, -1, -1],
        types: {
            Vector: grade 1,
            Bivector: grade 2,
            Trivector: grade 3,
            Rotor: grades 0 2,
            Odd: grades 1 3,
            Pseudoscalar: grade 8,
        },
    }
}
use cl62::{Bivector, Odd, Pseudoscalar, Rotor, Trivector, Vector};

fn sig() -> Signature {
    Signature::new(&[1, 1, 1, 1, 1, 1, -1, -1]).unwrap()
}

/// A generated value in the reference, through its blade masks.
fn dense<const N: usize>(
    masks: [u32; N],
    coefficients: [Rational; N],
) -> DenseMultivector<Rational> {
    let mut d = DenseMultivector::zero(&sig());
    for (m, c) in masks.into_iter().zip(coefficients) {
        d.set(m as usize, c).unwrap();
    }
    d
}

macro_rules! to_dense {
    ($x:expr, $ty:ident) => {
        dense($ty::<Rational>::BLADE_MASKS, $x.clone().into_coefficients())
    };
}

fn coefficients<const N: usize>() -> impl Strategy<Value = [Rational; N]> {
    prop::collection::vec(
        prop_oneof![1 => Just(0i64), 3 => -6i64..=6].prop_map(|n| Rational::from_integer(n.into())),
        N,
    )
    .prop_map(|v| v.try_into().unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn products_match_the_reference(
        a in coefficients::<8>(),
        b in coefficients::<8>(),
        c in coefficients::<28>(),
        t in coefficients::<56>(),
    ) {
        let (va, vb) = (Vector::from_coefficients(a), Vector::from_coefficients(b));
        let bc = Bivector::from_coefficients(c);
        let tt = Trivector::from_coefficients(t);
        let (da, db, dc, dt) = (to_dense!(va, Vector), to_dense!(vb, Vector), to_dense!(bc, Bivector), to_dense!(tt, Trivector));
        let r: Rotor<Rational> = va.clone() * vb.clone();
        prop_assert_eq!(to_dense!(r, Rotor), da.geometric(&db));
        let w: Trivector<Rational> = va.clone() ^ bc.clone();
        prop_assert_eq!(to_dense!(w, Trivector), da.wedge(&dc));
        let l: Vector<Rational> = va.clone() | bc.clone();
        prop_assert_eq!(to_dense!(l, Vector), da.left_contraction(&dc));
        let rc: Bivector<Rational> = tt.right_contraction(&va);
        prop_assert_eq!(to_dense!(rc, Bivector), dt.right_contraction(&da));
        let o: Odd<Rational> = r.clone() * va.clone();
        prop_assert_eq!(to_dense!(o, Odd), to_dense!(r, Rotor).geometric(&da));
        prop_assert_eq!(va.scalar_product(&vb), da.scalar_product(&db));
        // Vector and pseudoscalar: the regressive product of a vector with I is the vector.
        let i = Pseudoscalar::<Rational>::new(Rational::from_integer(1.into()));
        let reg: Vector<Rational> = va.clone() & i.clone();
        prop_assert_eq!(to_dense!(reg, Vector), da.regressive(&to_dense!(i, Pseudoscalar)));
        // The sandwich of a vector by a versor (two vectors) and the duals.
        prop_assert_eq!(to_dense!(r.sandwich_unit(&vb), Vector), (&(&to_dense!(r, Rotor) * &db) * &to_dense!(r, Rotor).reverse()).grade(1));
        prop_assert_eq!(to_dense!(tt.reverse(), Trivector), dt.reverse());
        let s = va.clone() + vb.clone();
        prop_assert_eq!(to_dense!(s, Vector), &da + &db);
        // The checked inverse (the even subalgebra has 128 blades): true inverse or none.
        match r.inverse() {
            Some(y) => prop_assert_eq!(to_dense!(r, Rotor) * to_dense!(y, Rotor), DenseMultivector::one(&sig())),
            None => {
                let dr = to_dense!(r, Rotor);
                let rotor_shaped = |m: usize| m.count_ones() == 0 || m.count_ones() == 2;
                prop_assert!(dr.general_inverse().filter(|inv| inv.project(rotor_shaped) == *inv).is_none());
            }
        }
    }
}

#[test]
fn eight_generators_have_256_blades() {
    assert_eq!(cl62::BLADE_NAMES.len(), 256);
    assert_eq!(cl62::BLADE_NAMES[255], "e12345678");
    assert_eq!(Odd::<f64>::BLADES.len(), 64);
    // e7 squares to -1.
    assert_eq!(cl62::e7::<f64>() | cl62::e7::<f64>(), -1.0);
}

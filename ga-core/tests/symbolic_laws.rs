//! Laws of the symbolic scalar `Poly` and agreement of the two independent Cl(4,1) products
//! over it: the generated `cga` code and the dense reference (`reference::DenseMultivector`).

use ga_core::cga::Multivector;
use ga_core::prelude::*;
use ga_core::reference::{DenseMultivector, Signature};
use ga_core::scalar::Rational;
use ga_core::symbolic::Poly;
use proptest::prelude::*;

const VARS: [&str; 3] = ["law_x", "law_y", "law_z"];

/// A small random polynomial in three variables.
fn poly() -> impl Strategy<Value = Poly> {
    prop::collection::vec((-5i64..=5, 0u32..3, 0u32..3, 0u32..3), 0..5).prop_map(|terms| {
        terms
            .into_iter()
            .map(|(c, i, j, k)| {
                Poly::from(c)
                    * Poly::var(VARS[0]).pow(i)
                    * Poly::var(VARS[1]).pow(j)
                    * Poly::var(VARS[2]).pow(k)
            })
            .sum()
    })
}

fn point() -> impl Strategy<Value = Vec<(&'static str, Rational)>> {
    prop::collection::vec((-20i64..=20, 1i64..=7), 3).prop_map(|v| {
        VARS.iter()
            .zip(v)
            .map(|(n, (a, b))| (*n, Rational::new(a.into(), b.into())))
            .collect()
    })
}

fn cl41() -> Signature {
    Signature::new(&[1, 1, 1, 1, -1]).expect("Cl(4,1)")
}

/// A sparse multivector with a few polynomial coefficients.
fn multivector() -> impl Strategy<Value = DenseMultivector<Poly>> {
    prop::collection::vec((0usize..32, poly()), 0..4).prop_map(|terms| {
        terms
            .into_iter()
            .fold(DenseMultivector::zero(&cl41()), |acc, (m, p)| {
                acc + DenseMultivector::blade(&cl41(), m, p).expect("mask below 32")
            })
    })
}

fn to_cga(a: &DenseMultivector<Poly>) -> Multivector<Poly> {
    let c: [Poly; 32] = a.to_canonical().try_into().expect("32 coefficients");
    Multivector::from_coefficients(c)
}
fn from_cga(m: Multivector<Poly>) -> DenseMultivector<Poly> {
    DenseMultivector::from_canonical(&cl41(), m.into_coefficients().to_vec())
        .expect("32 coefficients")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn ring_laws(p in poly(), q in poly(), r in poly()) {
        prop_assert_eq!(&(&p + &q) + &r, &p + &(&q + &r));
        prop_assert_eq!(&p * &q, &q * &p);
        prop_assert_eq!(&(&p * &q) * &r, &p * &(&q * &r));
        prop_assert_eq!(&p * &(&q + &r), &(&p * &q) + &(&p * &r));
        prop_assert!((&p - &p).is_zero());
        prop_assert_eq!(-(-p.clone()), p.clone());
    }

    #[test]
    fn evaluation_is_a_ring_homomorphism(p in poly(), q in poly(), at in point()) {
        let ev = |x: &Poly| x.eval_rational(&at).expect("all variables bound");
        prop_assert_eq!(ev(&(&p * &q)), ev(&p) * ev(&q));
        prop_assert_eq!(ev(&(&p - &q)), ev(&p) - ev(&q));
        // Substituting the values as constants gives the same constant.
        let consts: Vec<(&str, Poly)> = at.iter().map(|(n, v)| (*n, Poly::constant(v.clone()))).collect();
        prop_assert_eq!(p.subs_all(&consts).as_constant(), Some(ev(&p)));
    }

    #[test]
    fn printing_round_trips(p in poly()) {
        prop_assert_eq!(Poly::parse(&p.to_string()).expect("printed form parses"), p);
    }

    #[test]
    fn generated_products_agree_with_the_reference(a in multivector(), b in multivector()) {
        let (ca, cb) = (to_cga(&a), to_cga(&b));
        prop_assert_eq!(from_cga(ca.geometric(&cb)), a.geometric(&b));
        prop_assert_eq!(from_cga(ca.wedge(&cb)), a.wedge(&b));
        prop_assert_eq!(from_cga(ca.left_contraction(&cb)), a.left_contraction(&b));
        prop_assert_eq!(from_cga(ca.reverse()), a.reverse());
    }
}

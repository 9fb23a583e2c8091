//! The generated algebras `ga_core::vga3` (Cl(3,0)) and `ga_core::pga3` (Cl(3,0,1)) against the
//! independent dense reference `ga_core::reference::DenseMultivector`, and the conformal
//! identities of `ga_core::cga` (its pairs are in `generated_vs_reference_cga.rs`).
//!
//! For every ordered pair of declared types (the dense type included) and every product, for
//! every type and every unary operation, the generated result equals the reference computed on
//! the same (projected) inputs: exactly over rationals, within a tight relative tolerance in
//! `f64`. Operators are checked against the methods. The pairs are enumerated by a cartesian
//! `macro_rules!` over the type list, and the list itself is checked against the declaration in
//! the algebra's source file, so that a declared type cannot be forgotten.
//!
//! A failing case reports every mismatch it found: the pair, the operation, and for each blade
//! the expected (reference) and the generated coefficient.

#[macro_use]
mod gvr_harness;
use gvr_harness::*;

algebra_suite! {
    mod vga3_suite for vga3,
    signature: [1, 1, 1],
    source: include_str!("../../ga-core/src/vga3.rs"),
    types: [Vector, Bivector, Pseudoscalar, Rotor, Odd],
    dense: Multivector,
    versors: [Vector, Rotor, Odd, Multivector],
    exact_products: yes,
    exact_versors: yes,
}

algebra_suite! {
    mod pga3_suite for pga3,
    signature: [0, 1, 1, 1],
    source: include_str!("../../ga-core/src/pga3.rs"),
    types: [Vector, Bivector, Trivector, Pseudoscalar, Motor, Odd],
    dense: Multivector,
    versors: [Vector, Motor, Odd, Multivector],
    exact_products: yes,
    exact_versors: yes,
}

// ---------------------------------------------------------------------------------------------
// Conformal identities of Cl(4,1), exactly and in f64, checked on the generated code and on
// the reference (for the same generated points).

mod conformal {
    use super::*;
    use ga_core::cga::{self, n_0, n_inf, up, up_generic};
    use nalgebra::Point3;

    fn sig() -> Signature {
        Signature::new(&[1, 1, 1, 1, -1]).unwrap()
    }

    /// A generated Cl(4,1) value in the reference.
    fn cr<T: Scalar, X: Into<cga::Multivector<T>>>(x: X, s: &Signature) -> Dm<T> {
        Dm::from_canonical(s, x.into().coefficients().to_vec()).unwrap()
    }

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    fn small_rational() -> impl Strategy<Value = Rational> {
        (-20i64..=20, 1i64..=5).prop_map(|(n, d)| q(n, d))
    }

    #[test]
    fn null_basis_and_pseudoscalar() {
        let s = sig();
        let ni: cga::Vector<Rational> = n_inf();
        let no: cga::Vector<Rational> = n_0();
        let zero = Dm::<Rational>::zero(&s);
        assert_eq!(cr(&ni * &ni, &s), zero, "n_inf² = 0");
        assert_eq!(cr(&no * &no, &s), zero, "n_0² = 0");
        assert_eq!(ni.scalar_product(&no), q(-1, 1), "n_inf·n_0 = -1");
        assert_eq!(&ni | &no, q(-1, 1), "n_inf⌋n_0 = -1");
        let (rni, rno) = (cr(ni.clone(), &s), cr(no.clone(), &s));
        assert!((&rni * &rni).is_zero() && (&rno * &rno).is_zero());
        assert_eq!(rni.scalar_product(&rno), q(-1, 1));
        // n_inf = e4 + e5 and n_0 = (e5 - e4)/2 as blades.
        assert_eq!(rni.get(0b01000), q(1, 1));
        assert_eq!(rni.get(0b10000), q(1, 1));
        assert_eq!(rno.get(0b01000), q(-1, 2));
        assert_eq!(rno.get(0b10000), q(1, 2));
        // I² = -1, generated and reference.
        let i = cga::I::<Rational>();
        assert_eq!(&i * &i, q(-1, 1), "I² = -1");
        let ri = cr(i.clone(), &s);
        assert_eq!(&ri * &ri, Dm::scalar(&s, q(-1, 1)));
        assert_eq!(ri, Dm::pseudoscalar(&s));
        assert_eq!(cga::I::<f64>() * cga::I::<f64>(), -1.0);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn up_identities_exact(
            x in proptest::array::uniform3(small_rational()),
            y in proptest::array::uniform3(small_rational()),
        ) {
            let s = sig();
            let [x1, x2, x3] = x.clone();
            let [y1, y2, y3] = y.clone();
            let px = up_generic(x1, x2, x3);
            let py = up_generic(y1, y2, y3);
            let d2 = x.iter().zip(&y).fold(q(0, 1), |acc, (a, b)| {
                let d = a.clone() - b.clone();
                acc + d.clone() * d
            });
            let expected = -(d2 / q(2, 1));
            prop_assert_eq!(px.scalar_product(&py), expected.clone(), "up(x)·up(y)");
            prop_assert_eq!(&px | &py, expected.clone(), "up(x)⌋up(y)");
            prop_assert_eq!(cr(px.clone(), &s).scalar_product(&cr(py.clone(), &s)), expected);
            let ni: cga::Vector<Rational> = n_inf();
            prop_assert_eq!(px.scalar_product(&ni), q(-1, 1), "up(x)·n_inf");
            prop_assert_eq!(cr(px.clone(), &s).scalar_product(&cr(ni.clone(), &s)), q(-1, 1));
            prop_assert_eq!(px.scalar_product(&px), q(0, 1), "up(x) is null");
        }

        #[test]
        fn up_identities_f64(
            x in proptest::array::uniform3(-100.0f64..100.0),
            y in proptest::array::uniform3(-100.0f64..100.0),
        ) {
            let (px, py) = (Point3::from(x), Point3::from(y));
            let (ux, uy) = (up(&px), up(&py));
            let expected = -0.5 * (px - py).norm_squared();
            // The products of the ½|x|² components are of order |x|²|y|²/4: the rounding
            // error scales with the square of the coordinates' size.
            let scale = (1.0 + px.coords.norm_squared() + py.coords.norm_squared()).powi(2);
            prop_assert!((ux.scalar_product(&uy) - expected).abs() <= 1e-14 * scale);
            prop_assert!((ux.scalar_product(&n_inf()) + 1.0).abs() <= 1e-14 * scale);
            let s = sig();
            let r = cr(ux, &s).scalar_product(&cr(uy, &s));
            prop_assert!((r - expected).abs() <= 1e-14 * scale);
        }
    }
}

//! The null-basis conformal algebra `cga_null` against the dense reference, through the exact
//! change of basis `cga_null::to_cga`: every product, sum, sandwich and unary operation of the
//! generated code, on random rational inputs, must equal the reference's on the converted
//! inputs, exactly. The pseudoscalar `e1∧e2∧e3∧eo∧ei` is `-e12345`, so duals, unduals and the
//! regressive product carry that sign.

use ga_core::cga_null::{self as null, to_cga};
use ga_core::prelude::*;
use ga_core::reference::{DenseMultivector, Signature};
use ga_core::scalar::Rational;
use proptest::prelude::*;

type Dense = DenseMultivector<Rational>;

fn signature() -> Signature {
    Signature::new(&[1, 1, 1, 1, -1]).expect("Cl(4,1)")
}

/// A null-basis value (a declared type, or a scalar result) as a reference multivector in
/// `e1 … e5`.
trait ToDense {
    fn to_null(self) -> null::Multivector<Rational>;
}

impl ToDense for Rational {
    fn to_null(self) -> null::Multivector<Rational> {
        let mut m = null::Multivector::zero();
        m.s = self;
        m
    }
}

/// A product that is zero by grade.
impl ToDense for ga_core::Zero<Rational> {
    fn to_null(self) -> null::Multivector<Rational> {
        self.into()
    }
}

macro_rules! to_dense {
    ($($t:ident),*) => {$(
        impl ToDense for null::$t<Rational> {
            fn to_null(self) -> null::Multivector<Rational> {
                self.into()
            }
        }
    )*};
}
to_dense!(
    Vector,
    Plane,
    Bivector,
    Line,
    FlatPoint,
    Trivector,
    Quadvector,
    Pseudoscalar,
    Rotor,
    Translator,
    Motor,
    Even,
    Odd
);

impl ToDense for null::Multivector<Rational> {
    fn to_null(self) -> null::Multivector<Rational> {
        self
    }
}

fn dense(m: impl ToDense) -> Dense {
    let c = to_cga(&m.to_null()).coefficients().to_vec();
    Dense::from_canonical(&signature(), c).expect("32 coefficients")
}

fn rationals(n: usize) -> impl Strategy<Value = Vec<Rational>> {
    prop::collection::vec((-40i64..=40, 1i64..=4), n).prop_map(|v| {
        v.into_iter()
            .map(|(p, q)| Rational::new(p.into(), q.into()))
            .collect()
    })
}

macro_rules! pair_test {
    ($name:ident, $a:ident, $b:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            #[test]
            fn $name(
                x in rationals(null::$a::<Rational>::BLADES.len()),
                y in rationals(null::$b::<Rational>::BLADES.len()),
            ) {
                let a = null::$a::from_coefficients(x.try_into().unwrap());
                let b = null::$b::from_coefficients(y.try_into().unwrap());
                let (da, db) = (dense(a.clone()), dense(b.clone()));
                prop_assert_eq!(dense(a.geometric(&b)), da.geometric(&db));
                prop_assert_eq!(dense(a.wedge(&b)), da.wedge(&db));
                prop_assert_eq!(dense(a.left_contraction(&b)), da.left_contraction(&db));
                prop_assert_eq!(dense(a.right_contraction(&b)), da.right_contraction(&db));
                prop_assert_eq!(Rational::from(a.scalar_product(&b)), da.scalar_product(&db));
                // I_null = -I: dual and undual each flip the sign, so the regressive product
                // undual(dual(a) ∧ dual(b)) flips once.
                prop_assert_eq!(dense(a.regressive(&b)), -da.regressive(&db));
                prop_assert_eq!(dense(a.clone() + b.clone()), da.clone() + db.clone());
                prop_assert_eq!(dense(a.clone() - b.clone()), da.clone() - db.clone());
                let full = da.sandwich_unit(&db);
                // The sandwich projected onto b's type: compare in the null basis.
                let full = null::from_cga(&ga_core::cga::Multivector::from_coefficients(
                    full.to_canonical().try_into().unwrap()));
                let mut kept = full.coefficients();
                for (c, mask) in kept.iter_mut().zip(null::Multivector::<Rational>::BLADE_MASKS) {
                    if !null::$b::<Rational>::BLADE_MASKS.contains(&mask) {
                        *c = Rational::zero();
                    }
                }
                let projected = null::Multivector::from_coefficients(kept);
                prop_assert_eq!(a.sandwich_unit(&b).to_null(), projected);
            }
        }
    };
}

pair_test!(vector_vector, Vector, Vector);
pair_test!(motor_motor, Motor, Motor);
pair_test!(motor_vector, Motor, Vector);
pair_test!(motor_line, Motor, Line);
pair_test!(line_line, Line, Line);
pair_test!(rotor_translator, Rotor, Translator);
pair_test!(translator_flat_point, Translator, FlatPoint);
pair_test!(vector_plane, Vector, Plane);
pair_test!(bivector_trivector, Bivector, Trivector);
pair_test!(even_odd, Even, Odd);
pair_test!(quadvector_pseudoscalar, Quadvector, Pseudoscalar);
pair_test!(dense_dense, Multivector, Multivector);

// Every grade pair of ga-benchmark's conformal binary operations (grades 1 to 5).
pair_test!(grades_vector_bivector, Vector, Bivector);
pair_test!(grades_vector_trivector, Vector, Trivector);
pair_test!(grades_vector_quadvector, Vector, Quadvector);
pair_test!(grades_vector_pseudoscalar, Vector, Pseudoscalar);
pair_test!(grades_bivector_vector, Bivector, Vector);
pair_test!(grades_bivector_bivector, Bivector, Bivector);
pair_test!(grades_bivector_quadvector, Bivector, Quadvector);
pair_test!(grades_bivector_pseudoscalar, Bivector, Pseudoscalar);
pair_test!(grades_trivector_vector, Trivector, Vector);
pair_test!(grades_trivector_bivector, Trivector, Bivector);
pair_test!(grades_trivector_trivector, Trivector, Trivector);
pair_test!(grades_trivector_quadvector, Trivector, Quadvector);
pair_test!(grades_trivector_pseudoscalar, Trivector, Pseudoscalar);
pair_test!(grades_quadvector_vector, Quadvector, Vector);
pair_test!(grades_quadvector_bivector, Quadvector, Bivector);
pair_test!(grades_quadvector_trivector, Quadvector, Trivector);
pair_test!(grades_quadvector_quadvector, Quadvector, Quadvector);
pair_test!(grades_pseudoscalar_vector, Pseudoscalar, Vector);
pair_test!(grades_pseudoscalar_bivector, Pseudoscalar, Bivector);
pair_test!(grades_pseudoscalar_trivector, Pseudoscalar, Trivector);
pair_test!(grades_pseudoscalar_quadvector, Pseudoscalar, Quadvector);
pair_test!(grades_pseudoscalar_pseudoscalar, Pseudoscalar, Pseudoscalar);

macro_rules! unary_test {
    ($name:ident, $a:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(24))]
            #[test]
            fn $name(x in rationals(null::$a::<Rational>::BLADES.len())) {
                let a = null::$a::from_coefficients(x.try_into().unwrap());
                let da = dense(a.clone());
                prop_assert_eq!(dense(a.reverse()), da.reverse());
                prop_assert_eq!(dense(a.grade_involution()), da.grade_involution());
                prop_assert_eq!(dense(a.conjugate()), da.conjugate());
                prop_assert_eq!(dense(a.dual()), -da.dual());
                prop_assert_eq!(dense(a.undual()), -da.undual());
                prop_assert_eq!(a.norm_squared(), da.norm_squared());
                for k in 0..=5 {
                    prop_assert_eq!(dense(a.grade(k)), da.grade(k));
                }
                if let Some(inv) = a.versor_inverse() {
                    let n = da.norm_squared();
                    prop_assert_eq!(dense(inv), da.reverse().scale(&(Rational::from_integer(1.into()) / n)));
                }
            }
        }
    };
}

unary_test!(unary_vector, Vector);
unary_test!(unary_motor, Motor);
unary_test!(unary_line, Line);
unary_test!(unary_flat_point, FlatPoint);
unary_test!(unary_even, Even);
unary_test!(unary_odd, Odd);
unary_test!(unary_dense, Multivector);

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// The change of basis is exact both ways.
    #[test]
    fn change_of_basis_round_trips(x in rationals(32)) {
        let m = null::Multivector::from_coefficients(x.try_into().unwrap());
        prop_assert_eq!(null::from_cga(&to_cga(&m)), m);
    }
}

#[test]
fn null_vectors_and_points() {
    let r = |n: i64| Rational::from_integer(n.into());
    let (eo, ei) = (null::eo::<Rational>(), null::ei::<Rational>());
    assert_eq!(eo.scalar_product(&ei), r(-1));
    assert_eq!(ei.scalar_product(&ei), r(0));
    // The same point in both bases.
    let p = null::up_generic(r(1), r(2), r(3));
    let q = ga_core::cga::up_generic(r(1), r(2), r(3));
    assert_eq!(to_cga(&p.clone().into()), q.into());
    // A motor times a motor is a motor, exactly, with no `e4`/`e5` cancellation.
    let t = null::Motor::translator([r(1), r(0), r(0)]);
    let m: null::Motor<Rational> = t.clone() * t;
    assert_eq!(
        null::down_generic(&m.sandwich_unit(&p)),
        Some([r(3), r(2), r(3)])
    );
}

//! The generated products on SIMD lanes equal the scalar products lane by lane, bit for bit
//! (same operations in the same order; Rust does not contract `a * b + c` into FMA).

use ga_core::cga::{Bivector, Even, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::lanes::{F32x8, F64x4};
use proptest::prelude::*;

/// Packs `items[i]` into lane `i` of every coefficient.
macro_rules! pack {
    ($ty:ident, $lane:ty, $items:expr) => {{
        let items = &$items;
        $ty::from_coefficients(core::array::from_fn(|k| {
            <$lane>::from_fn(|i| items[i].coefficients()[k])
        }))
    }};
}

proptest! {
    #[test]
    fn f64x4_products_equal_scalar_products_lane_by_lane(
        a in prop::array::uniform4(prop::array::uniform5(-1e3f64..1e3)),
        b in prop::array::uniform4(prop::array::uniform5(-1e3f64..1e3)),
        r in prop::array::uniform4(prop::array::uniform11(-2.0f64..2.0)),
        e in prop::array::uniform4(prop::array::uniform16(-2.0f64..2.0)),
    ) {
        let (a, b, r, e) = (
            a.map(Vector::from_coefficients),
            b.map(Vector::from_coefficients),
            r.map(Rotor::from_coefficients),
            e.map(Even::from_coefficients),
        );
        let la = pack!(Vector, F64x4, a);
        let lb = pack!(Vector, F64x4, b);
        let lr = pack!(Rotor, F64x4, r);
        let le = pack!(Even, F64x4, e);
        let gp = la * lb;
        let wedge: Bivector<F64x4> = la ^ lb;
        let dot = la.scalar_product(&lb);
        let sandwich = lr.sandwich_unit(&la);
        let ee = le * le;
        let inv = le.versor_inverse();
        for i in 0..4 {
            prop_assert_eq!(gp.map(|c| c.lanes()[i]), a[i] * b[i]);
            prop_assert_eq!(wedge.map(|c| c.lanes()[i]), a[i] ^ b[i]);
            prop_assert_eq!(dot.lanes()[i], a[i].scalar_product(&b[i]));
            prop_assert_eq!(sandwich.map(|c| c.lanes()[i]), r[i].sandwich_unit(&a[i]));
            prop_assert_eq!(ee.map(|c| c.lanes()[i]), e[i] * e[i]);
            if let (Some(li), Some(si)) = (inv, e[i].versor_inverse()) {
                prop_assert_eq!(li.map(|c| c.lanes()[i]), si);
            }
        }
    }

    #[test]
    fn f32x8_products_equal_scalar_products_lane_by_lane(
        a in prop::array::uniform8(prop::array::uniform5(-1e3f32..1e3)),
        b in prop::array::uniform8(prop::array::uniform5(-1e3f32..1e3)),
    ) {
        let a = a.map(Vector::from_coefficients);
        let b = b.map(Vector::from_coefficients);
        let la = pack!(Vector, F32x8, a);
        let lb = pack!(Vector, F32x8, b);
        let gp = la * lb;
        let r = gp.reverse();
        let sandwich = gp.sandwich_unit(&la);
        for i in 0..8 {
            prop_assert_eq!(gp.map(|c| c.lanes()[i]), a[i] * b[i]);
            prop_assert_eq!(r.map(|c| c.lanes()[i]), (a[i] * b[i]).reverse());
            prop_assert_eq!(sandwich.map(|c| c.lanes()[i]), (a[i] * b[i]).sandwich_unit(&a[i]));
        }
    }
}

#[test]
fn lane_semantics() {
    let x = F64x4::from([1.0, 0.0, -2.0, 4.0]);
    assert_eq!(x.lanes(), [1.0, 0.0, -2.0, 4.0]);
    assert_eq!(x.lane(3), Some(4.0));
    assert_eq!(x.lane(4), None);
    assert!(x.any_zero());
    assert!(!x.is_zero());
    assert!(F64x4::zero().is_zero());
    assert_eq!(x.abs().lanes(), [1.0, 0.0, 2.0, 4.0]);
    assert_eq!(
        F64x4::from([4.0, 9.0, 0.25, 1.0]).sqrt().lanes(),
        [2.0, 3.0, 0.5, 1.0]
    );
    // Division by a partly zero value divides lane by lane, as f64 does.
    let q = F64x4::one() / x;
    assert_eq!(q.lanes()[1], f64::INFINITY);
    assert!(!q.all_finite());
    assert!(F64x4::zero().checked_recip().is_none());
    assert_eq!(x.pivot_score(), 4.0);
    assert_eq!(
        F64x4::from([1.0, f64::NAN, 0.0, 0.0]).pivot_score(),
        f64::INFINITY
    );
    assert_eq!(F32x8::from_i64(3).lanes(), [3.0; 8]);
    assert_ne!(F64x4::splat(f64::NAN), F64x4::splat(f64::NAN));
    // The dense inverse runs on lanes (here the same element in every lane).
    let s = Even::new(
        2.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0,
    );
    let l = s.map(F64x4::splat);
    let m = ga_core::cga::Multivector::from(l)
        .general_inverse()
        .unwrap();
    let ms = ga_core::cga::Multivector::from(s)
        .general_inverse()
        .unwrap();
    assert_eq!(m.coefficients().map(|c| c.lanes()[2]), ms.coefficients());
}

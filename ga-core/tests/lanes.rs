//! The generated products on SIMD lanes equal the scalar products lane by lane, bit for bit
//! (same operations in the same order; Rust does not contract `a * b + c` into FMA).

use ga_core::cga::{Bivector, Even, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::lanes::{F32x8, F64x4};
use proptest::prelude::*;

/// Packs `items[i]` into lane `i` of every field.
macro_rules! pack {
    ($lane:ty, $ty:ident { $($f:ident),* }, $items:expr) => {{
        let items = &$items;
        $ty { $($f: <$lane>::from_fn(|i| items[i].$f)),* }
    }};
}

/// Lane `i` of every field.
macro_rules! unpack {
    ($ty:ident { $($f:ident),* }, $v:expr, $i:expr) => {
        $ty { $($f: $v.$f.lanes()[$i]),* }
    };
}

fn vec64(c: [f64; 5]) -> Vector<f64> {
    Vector::new(c[0], c[1], c[2], c[3], c[4])
}

fn rotor64(c: [f64; 11]) -> Rotor<f64> {
    Rotor::new(
        c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10],
    )
}

fn even64(c: [f64; 16]) -> Even<f64> {
    Even::new(
        c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12], c[13],
        c[14], c[15],
    )
}

proptest! {
    #[test]
    fn f64x4_products_equal_scalar_products_lane_by_lane(
        a in prop::array::uniform4(prop::array::uniform5(-1e3f64..1e3)),
        b in prop::array::uniform4(prop::array::uniform5(-1e3f64..1e3)),
        r in prop::array::uniform4(prop::array::uniform11(-2.0f64..2.0)),
        e in prop::array::uniform4(prop::array::uniform16(-2.0f64..2.0)),
    ) {
        let (a, b, r, e) = (a.map(vec64), b.map(vec64), r.map(rotor64), e.map(even64));
        let la = pack!(F64x4, Vector { e1, e2, e3, e4, e5 }, a);
        let lb = pack!(F64x4, Vector { e1, e2, e3, e4, e5 }, b);
        let lr = pack!(F64x4, Rotor { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45 }, r);
        let le = pack!(F64x4, Even { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45, e1234, e1235, e1245, e1345, e2345 }, e);
        let gp = la * lb;
        let wedge: Bivector<F64x4> = la ^ lb;
        let dot = la.scalar_product(&lb);
        let sandwich = lr.sandwich_unit(&la);
        let ee = le * le;
        let inv = le.versor_inverse();
        for i in 0..4 {
            prop_assert_eq!(unpack!(Rotor { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45 }, gp, i), a[i] * b[i]);
            prop_assert_eq!(unpack!(Bivector { e12, e13, e14, e15, e23, e24, e25, e34, e35, e45 }, wedge, i), a[i] ^ b[i]);
            prop_assert_eq!(dot.lanes()[i], a[i].scalar_product(&b[i]));
            prop_assert_eq!(unpack!(Vector { e1, e2, e3, e4, e5 }, sandwich, i), r[i].sandwich_unit(&a[i]));
            prop_assert_eq!(unpack!(Even { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45, e1234, e1235, e1245, e1345, e2345 }, ee, i), e[i] * e[i]);
            if let (Some(li), Some(si)) = (inv, e[i].versor_inverse()) {
                prop_assert_eq!(unpack!(Even { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45, e1234, e1235, e1245, e1345, e2345 }, li, i), si);
            }
        }
    }

    #[test]
    fn f32x8_products_equal_scalar_products_lane_by_lane(
        a in prop::array::uniform8(prop::array::uniform5(-1e3f32..1e3)),
        b in prop::array::uniform8(prop::array::uniform5(-1e3f32..1e3)),
    ) {
        let a = a.map(|c| Vector::new(c[0], c[1], c[2], c[3], c[4]));
        let b = b.map(|c| Vector::new(c[0], c[1], c[2], c[3], c[4]));
        let la = pack!(F32x8, Vector { e1, e2, e3, e4, e5 }, a);
        let lb = pack!(F32x8, Vector { e1, e2, e3, e4, e5 }, b);
        let gp = la * lb;
        let r = gp.reverse();
        let sandwich = gp.sandwich_unit(&la);
        for i in 0..8 {
            prop_assert_eq!(unpack!(Rotor { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45 }, gp, i), a[i] * b[i]);
            prop_assert_eq!(unpack!(Rotor { s, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45 }, r, i), (a[i] * b[i]).reverse());
            prop_assert_eq!(unpack!(Vector { e1, e2, e3, e4, e5 }, sandwich, i), (a[i] * b[i]).sandwich_unit(&a[i]));
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
    let l = pack!(
        F64x4,
        Even {
            s,
            e12,
            e13,
            e14,
            e15,
            e23,
            e24,
            e25,
            e34,
            e35,
            e45,
            e1234,
            e1235,
            e1245,
            e1345,
            e2345
        },
        [s; 4]
    );
    let m = ga_core::cga::Multivector::from(l)
        .general_inverse()
        .unwrap();
    let ms = ga_core::cga::Multivector::from(s)
        .general_inverse()
        .unwrap();
    assert_eq!(m.coefficients().map(|c| c.lanes()[2]), ms.coefficients());
}

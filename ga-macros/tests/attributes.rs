//! The `attributes` key puts its attributes on every generated struct, and every struct is
//! `#[repr(C)]`: its coefficients in canonical blade order, with no padding for `f64`.

mod plane {
    ga_macros::algebra! {
        name: plane,
        signature: [+1, +1],
        types: { Vector: grade 1, Rotor: grades 0 2 },
        attributes: [#[derive(PartialOrd)], #[cfg_attr(all(), derive(Ord))]],
    }
}

#[test]
fn attributes_reach_every_struct() {
    use plane::{Multivector, Rotor, Vector};
    // `PartialOrd` and `Ord` come from the `attributes` key (the macro derives neither).
    assert!(Vector::new(1.0, 0.0) < Vector::new(2.0, 0.0));
    assert!(Rotor::new(0.0, 1.0) < Rotor::new(1.0, 0.0));
    fn ordered<X: Ord + Copy>(a: X, b: X) -> bool {
        a.max(b) == b
    }
    assert!(ordered(Vector::new(1, 2), Vector::new(1, 3)));
    let zero = Multivector::<i32>::from_coefficients([0; 4]);
    assert!(zero <= Multivector::from_coefficients([0, 0, 0, 1]));
}

#[test]
fn structs_are_repr_c() {
    use core::mem::{align_of, size_of};
    assert_eq!(size_of::<plane::Vector<f64>>(), 2 * size_of::<f64>());
    assert_eq!(size_of::<plane::Multivector<f32>>(), 4 * size_of::<f32>());
    assert_eq!(align_of::<plane::Rotor<f64>>(), align_of::<f64>());
}

//! `bytemuck::Pod` and `Zeroable` for the generated types over `f64` and `f32` (feature
//! `bytemuck`).
//!
//! `bytemuck`'s derive does not support generic structs, so the impls are written here, for
//! the concrete types `X<f64>` and `X<f32>` only. This is the crate's only unsafe code. Why it
//! is sound: `Pod` needs a `Copy`, `'static`, `#[repr(C)]` (or transparent) type with no
//! padding whose every bit pattern is valid, and `Zeroable` that all-zero bits are valid.
//! Every generated struct is `#[repr(C)]` (the macro emits it) with fields that are all the
//! same float type, so there is no padding between or after them; the `const` assertions
//! below check at compile time that each size is exactly the number of blades times the
//! size of the float. Every bit pattern of `f64`/`f32` is a valid float (possibly NaN), and
//! all-zero bits are `0.0`. The structs are `Copy` when the scalar is.
//!
//! ```
//! use ga_core::cga::Vector;
//! let points = [Vector::new(1.0f32, 2.0, 3.0, 4.0, 5.0), Vector::new(6.0, 7.0, 8.0, 9.0, 10.0)];
//! let flat: &[f32] = bytemuck::cast_slice(&points);
//! assert_eq!(flat, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0]);
//! ```
#![allow(unsafe_code)]

use core::mem::size_of;

macro_rules! pod {
    ($($module:ident :: $ty:ident),* $(,)?) => {$(
        pod!(@one $module :: $ty, f64);
        pod!(@one $module :: $ty, f32);
    )*};
    (@one $module:ident :: $ty:ident, $float:ty) => {
        const _: () = assert!(
            size_of::<crate::$module::$ty<$float>>()
                == crate::$module::$ty::<$float>::BLADES.len() * size_of::<$float>()
        );
        // SAFETY: see the module documentation: `#[repr(C)]`, only `$float` fields, size
        // checked above to have no padding; all-zero bits are `0.0`.
        unsafe impl bytemuck::Zeroable for crate::$module::$ty<$float> {}
        // SAFETY: as above; every bit pattern of `$float` is valid, and the type is `Copy` and
        // `'static`.
        unsafe impl bytemuck::Pod for crate::$module::$ty<$float> {}
    };
}

pod!(
    cga::Vector,
    cga::Bivector,
    cga::Trivector,
    cga::Quadvector,
    cga::Pseudoscalar,
    cga::Rotor,
    cga::Even,
    cga::Odd,
    cga::Multivector,
    vga3::Vector,
    vga3::Bivector,
    vga3::Pseudoscalar,
    vga3::Rotor,
    vga3::Odd,
    vga3::Multivector,
    pga3::Vector,
    pga3::Bivector,
    pga3::Trivector,
    pga3::Pseudoscalar,
    pga3::Motor,
    pga3::Odd,
    pga3::Multivector,
);

//! The Euclidean geometric algebra Cl(3,0) of 3D space: a second algebra from the same macro.
//!
//! ```
//! use ga_core::vga3::*;
//! use ga_core::prelude::*;
//! // A rotor turning e1 into e2 by 90° about e3.
//! let h = std::f64::consts::FRAC_1_SQRT_2;
//! let r = Rotor::new(h, -h, 0.0, 0.0);
//! let v = r.sandwich_unit(&Vector::new(1.0, 0.0, 0.0));
//! assert!(approx::abs_diff_eq!(v, Vector::new(0.0, 1.0, 0.0), epsilon = 1e-15));
//! ```

ga_macros::algebra! {
    name: vga3,
    signature: [+1, +1, +1],
    types: {
        /// A vector of Euclidean 3-space.
        Vector: grade 1,
        /// A bivector (oriented plane element).
        Bivector: grade 2,
        /// A multiple of the pseudoscalar `e123`.
        Pseudoscalar: grade 3,
        /// A rotor: scalar plus bivector (the quaternions).
        Rotor: grades 0 2,
        /// Odd elements: vectors plus pseudoscalar.
        Odd: grades 1 3,
    },
    dense: Multivector,
    // Optional interop features of ga-core (see docs/toolkit.md).
    attributes: [#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]],
}

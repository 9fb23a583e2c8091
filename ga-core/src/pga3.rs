//! Projective geometric algebra Cl(3,0,1): a degenerate signature from the same macro. `e0`
//! squares to zero; dual and regressive product use the complement (Poincaré duality).
//!
//! ```
//! use ga_core::pga3::*;
//! use ga_core::prelude::*;
//! // Planes x = 1 and y = 2 (a e0 + b e1 + c e2 + d e3 means a + b x + c y + d z = 0) meet in a line.
//! let px = Vector::new(-1.0, 1.0, 0.0, 0.0);
//! let py = Vector::new(-2.0, 0.0, 1.0, 0.0);
//! let line = px ^ py;
//! assert_ne!(line, Bivector::zero());
//! // The regressive product of the line with itself is zero.
//! assert_eq!(line.regressive(&line), 0.0);
//! ```

ga_macros::algebra! {
    name: pga3,
    signature: [0, +1, +1, +1],
    basis: [e0, e1, e2, e3],
    types: {
        /// Planes.
        Vector: grade 1,
        /// Lines.
        Bivector: grade 2,
        /// Points.
        Trivector: grade 3,
        /// Multiples of the pseudoscalar `e0123`.
        Pseudoscalar: grade 4,
        /// Motors (rotations and translations): grades 0, 2, 4.
        Motor: grades 0 2 4,
        /// Odd elements: grades 1, 3.
        Odd: grades 1 3,
    },
    dense: Multivector,
    // Optional interop features of ga-core (see docs/toolkit.md).
    attributes: [#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]],
}

//! The conformal geometric algebra Cl(4,1) of 3D Euclidean space.
//!
//! Basis `e1 e2 e3 e4 e5` with `e1² = e2² = e3² = e4² = +1` and `e5² = -1`; the thesis writes
//! `e = e4`, `ē = e5`. `n_inf = e4 + e5`, `n_0 = (e5 - e4)/2`, and a Euclidean point `x` is
//! represented by `up(x) = x + ½|x|² n_inf + n_0`.
//!
//! ```
//! use ga_core::cga::{self, up};
//! use ga_core::prelude::*;
//! use nalgebra::Point3;
//!
//! let a = up(&Point3::new(1.0, 2.0, 3.0));
//! let b = up(&Point3::new(4.0, 6.0, 3.0));
//! // up(x)·up(y) = -½|x - y|²
//! assert_eq!(a.scalar_product(&b), -12.5);
//! assert_eq!(a.scalar_product(&cga::n_inf()), -1.0);
//! ```

use nalgebra::Point3;

use crate::scalar::{Field, Real, Ring};

ga_macros::algebra! {
    name: cga,
    signature: [+1, +1, +1, +1, -1],
    basis: [e1, e2, e3, e4, e5],
    types: {
        /// A grade-1 element: conformal points, spheres and planes (inner forms).
        Vector: grade 1,
        /// A grade-2 element: point pairs (outer form), lines and circles (inner form).
        Bivector: grade 2,
        /// A grade-3 element: lines and circles (outer form), point pairs (inner form).
        Trivector: grade 3,
        /// A grade-4 element: spheres and planes (outer form).
        Quadvector: grade 4,
        /// A multiple of the pseudoscalar `I = e12345`.
        Pseudoscalar: grade 5,
        /// Scalar plus bivector: rotors, translators and dilators (each a product of two vectors).
        Rotor: grades 0 2,
        /// The even subalgebra: motors and every other product of rotors, translators and dilators.
        Even: grades 0 2 4,
        /// The odd elements: reflections and other odd versors.
        Odd: grades 1 3 5,
    },
    dense: Multivector,
    // Optional interop features of ga-core (see docs/toolkit.md).
    attributes: [#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]],
    // WGSL for the single-grade types (module `cga::wgsl`), used by cga-collide's GPU batches.
    wgsl: [Vector, Bivector, Trivector, Quadvector, Pseudoscalar],
}

/// The point at infinity `n_inf = e4 + e5` (the thesis's `n`).
pub fn n_inf<T: Ring>() -> Vector<T> {
    Vector::new(T::zero(), T::zero(), T::zero(), T::one(), T::one())
}

/// The origin `n_0 = (e5 - e4) / 2` (the thesis's `-n̄/2`).
pub fn n_0<T: Field>() -> Vector<T> {
    let half = T::one() / T::from_i64(2);
    Vector::new(T::zero(), T::zero(), T::zero(), -half.clone(), half)
}

/// The unit pseudoscalar `I = e12345`, with `I² = -1`.
pub fn pseudoscalar<T: Ring>() -> Pseudoscalar<T> {
    Pseudoscalar::new(T::one())
}

/// The unit pseudoscalar `I = e12345` (the same as [`pseudoscalar`]).
#[allow(non_snake_case)]
pub fn I<T: Ring>() -> Pseudoscalar<T> {
    pseudoscalar()
}

/// The conformal point `up(x) = x + ½|x|² n_inf + n_0` for coordinates in any field.
pub fn up_generic<T: Field>(x: T, y: T, z: T) -> Vector<T> {
    let half = T::one() / T::from_i64(2);
    let h = half.clone() * (x.clone() * x.clone() + y.clone() * y.clone() + z.clone() * z.clone());
    // x + h (e4 + e5) + ½ (e5 - e4)
    Vector::new(x, y, z, h.clone() - half.clone(), h + half)
}

/// The conformal point of a Euclidean point: `up(x) = x + ½|x|² n_inf + n_0`.
pub fn up(p: &Point3<f64>) -> Vector<f64> {
    up_generic(p.x, p.y, p.z)
}

/// The Euclidean point of a conformal point (any nonzero multiple of `up(x)`): `None` when the
/// weight `-X·n_inf` is zero (a point at infinity, a plane, or a non-point) or not finite.
///
/// ```
/// use ga_core::cga::{down, up};
/// use nalgebra::Point3;
/// let p = Point3::new(1.5, -2.0, 0.25);
/// assert_eq!(down(&(up(&p) * 3.0)), Some(p));
/// ```
pub fn down(v: &Vector<f64>) -> Option<Point3<f64>> {
    down_generic(v).map(|[x, y, z]| Point3::new(x, y, z))
}

/// [`down`] for any real scalar: the coordinates `[x, y, z]`.
pub fn down_generic<T: Real>(v: &Vector<T>) -> Option<[T; 3]> {
    // -X·n_inf = e5 - e4 coefficient difference: X·(e4 + e5) = X4 - X5.
    let weight = v.e5.clone() - v.e4.clone();
    if weight.is_zero() || !weight.is_finite() {
        return None;
    }
    let inv = T::one() / weight;
    let coords = [
        v.e1.clone() * inv.clone(),
        v.e2.clone() * inv.clone(),
        v.e3.clone() * inv,
    ];
    coords.iter().all(Real::is_finite).then_some(coords)
}

impl<T: Ring> From<nalgebra::Vector3<T>> for Vector<T>
where
    T: nalgebra::Scalar,
{
    /// The Euclidean vector `x e1 + y e2 + z e3` (a direction, not a conformal point).
    fn from(v: nalgebra::Vector3<T>) -> Self {
        Vector::new(v.x.clone(), v.y.clone(), v.z.clone(), T::zero(), T::zero())
    }
}

//! The conformal algebra of 3D space in the null basis `e1, e2, e3, eo, ei` (`eo = n_0`, the
//! origin; `ei = n_inf`, the point at infinity), with `eo · ei = -1`, `eo² = ei² = 0`.
//!
//! It is the same algebra as [`cga`] (Cl(4,1)) in another basis:
//! `eo = (e5 - e4)/2` and `ei = e4 + e5`, so `e4 = ei/2 - eo` and `e5 = ei/2 + eo`.
//! [`to_cga`] and [`from_cga`] convert exactly (over any field). Here the conformal objects are
//! closed at blade level: a translator is `1 + t ei`-type blades only, a motor has 8 blades and
//! motor × motor is a motor, and `ei² = 0` holds by construction rather than as a cancellation
//! between the `e4` and `e5` parts.
//!
//! Blade names join the basis suffixes: `e12`, `e1i` (= `e1 ∧ ei`), `eoi` (= `eo ∧ ei`),
//! `e123oi` (the pseudoscalar `I = e1 ∧ e2 ∧ e3 ∧ eo ∧ ei`, which is `-e12345` of
//! [`cga`], with `I² = -1`). The dual is `A I⁻¹` with this `I`.
//!
//! ```
//! use ga_core::cga_null::{self, Motor, Vector};
//! use ga_core::prelude::*;
//!
//! let p = cga_null::up_generic(1.0, 2.0, 3.0);
//! let q = cga_null::up_generic(4.0, 6.0, 3.0);
//! assert_eq!(p.scalar_product(&q), -12.5); // -½|p - q|²
//! let t = Motor::translator([1.0, 0.0, 0.0]);
//! let m: Motor<f64> = t * t; // closed: still a motor
//! assert_eq!(cga_null::down_generic(&m.sandwich_unit(&p)), Some([3.0, 2.0, 3.0]));
//! ```

use crate::cga;
use crate::scalar::{Field, Real, Ring};

/// The declaration of [`cga_null`](crate::cga_null), shared by the algebra (generated below) and by
/// [`cga_null_expressions!`](crate::cga_null_expressions), which generates fused functions over
/// its types.
#[doc(hidden)]
#[macro_export]
macro_rules! __ga_core_cga_null_declaration {
    ($generator:ident { $($extra:tt)* }) => {
        $crate::__ga_macros::$generator! {
            name: cga_null,
            metric: [
                [1, 0, 0, 0, 0],
                [0, 1, 0, 0, 0],
                [0, 0, 1, 0, 0],
                [0, 0, 0, 0, -1],
                [0, 0, 0, -1, 0],
            ],
            basis: [e1, e2, e3, eo, ei],
            types: {
                /// A grade-1 element: conformal points and spheres (`x + ½|x|² ei + eo`), planes.
                Vector: grade 1,
                /// A plane `n + d ei` (inner form): no `eo` part.
                Plane: [e1, e2, e3, ei],
                /// A grade-2 element: point pairs (outer form), lines and circles (inner form).
                Bivector: grade 2,
                /// A dual line (a rotation or screw axis): `e12, e13, e23` and `e1i, e2i, e3i`.
                Line: [e12, e13, e23, e1i, e2i, e3i],
                /// A flat point `x ∧ ei`-type bivector: `e1i, e2i, e3i, eoi`.
                FlatPoint: [e1i, e2i, e3i, eoi],
                /// A grade-3 element: lines and circles (outer form).
                Trivector: grade 3,
                /// A grade-4 element: spheres and planes (outer form).
                Quadvector: grade 4,
                /// A multiple of the pseudoscalar `I = e1 ∧ e2 ∧ e3 ∧ eo ∧ ei`.
                Pseudoscalar: grade 5,
                /// A rotation about an axis through the origin: scalar and `e12, e13, e23`.
                Rotor: [1, e12, e13, e23],
                /// A translation: scalar and `e1i, e2i, e3i`.
                Translator: [1, e1i, e2i, e3i],
                /// A rigid motion: rotor, translator and `e123i` blades; motor × motor is a motor.
                Motor: [1, e12, e13, e23, e1i, e2i, e3i, e123i],
                /// The even subalgebra (dilations, transversions and every other even versor).
                Even: grades 0 2 4,
                /// The odd elements: reflections and other odd versors.
                Odd: grades 1 3 5,
            },
            dense: Multivector,
            attributes: [#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]],
            $($extra)*
        }
    };
}

/// Generates functions whose bodies are whole expressions over [`cga_null`](crate::cga_null)'s types, each
/// expanded symbolically into one straight-line function generic over the scalar (see
/// `docs/generator.md`, "Expressions"). The types are named without generics and `T` is the
/// scalar; multivector arguments are taken by reference, scalars by value.
///
/// ```
/// use ga_core::cga_null::{self, Motor, Vector};
///
/// ga_core::cga_null_expressions! {
///     /// A motor applied to a point: one kernel, the motor's zeros folded, the grade-3 part of
///     /// `M X M̃` (zero for a versor) not computed.
///     pub fn apply(#[versor] m: Motor, x: Vector) -> Vector { m * x * m.reverse() }
/// }
///
/// let m = Motor::translator([1.0, 2.0, 3.0]);
/// let x = cga_null::up_generic(1.0, 0.0, 0.0);
/// assert_eq!(apply(&m, &x), ga_core::ops::SandwichUnit::sandwich_unit(&m, &x));
/// ```
#[macro_export]
macro_rules! cga_null_expressions {
    ($($functions:tt)*) => {
        $crate::__ga_core_cga_null_declaration!(expressions {
            path: $crate::cga_null,
            functions: { $($functions)* },
        });
    };
}

crate::__ga_core_cga_null_declaration!(algebra {});

// `eo()`, `ei()` and every other blade constructor are generated (`ei()` is a `Plane`).

/// The conformal point `x + ½|x|² ei + eo` (the same vector as [`cga::up_generic`]).
pub fn up_generic<T: Field>(x: T, y: T, z: T) -> Vector<T> {
    let half = T::one() / T::from_i64(2);
    let h = half * (x.clone() * x.clone() + y.clone() * y.clone() + z.clone() * z.clone());
    Vector::new(x, y, z, T::one(), h)
}

/// The Euclidean coordinates of a conformal point (any nonzero multiple of one): `None` when
/// its weight `-X·ei` (the `eo` coefficient) is zero or not finite.
pub fn down_generic<T: Real>(v: &Vector<T>) -> Option<[T; 3]> {
    let weight = v.eo.clone();
    if weight.is_zero() || !weight.is_finite() {
        return None;
    }
    let inv = T::one() / weight;
    let c = [
        v.e1.clone() * inv.clone(),
        v.e2.clone() * inv.clone(),
        v.e3.clone() * inv,
    ];
    c.iter().all(Real::is_finite).then_some(c)
}

impl<T: Ring> Motor<T> {
    /// The translator by `t`: `1 - ½ t ei` (moves `x` to `x + t`).
    pub fn translator(t: [T; 3]) -> Self
    where
        T: Field,
    {
        let half = T::one() / T::from_i64(2);
        let [x, y, z] = t;
        let mut m = Motor::zero();
        m.s = T::one();
        m.e1i = -(half.clone() * x);
        m.e2i = -(half.clone() * y);
        m.e3i = -(half * z);
        m
    }
}

/// The image of one basis vector of this basis in [`cga`]'s basis.
fn vector_to_cga<T: Field>(i: usize) -> cga::Vector<T> {
    let half = T::one() / T::from_i64(2);
    let mut c = [T::zero(), T::zero(), T::zero(), T::zero(), T::zero()];
    match i {
        3 => {
            // eo = (e5 - e4) / 2
            c[3] = -half.clone();
            c[4] = half;
        }
        4 => {
            // ei = e4 + e5
            c[3] = T::one();
            c[4] = T::one();
        }
        _ => c[i] = T::one(),
    }
    cga::Vector::from_coefficients(c)
}

/// The image of one basis vector of [`cga`] in this basis.
fn vector_from_cga<T: Field>(i: usize) -> Vector<T> {
    let half = T::one() / T::from_i64(2);
    let mut c = [T::zero(), T::zero(), T::zero(), T::zero(), T::zero()];
    match i {
        3 => {
            // e4 = ei/2 - eo
            c[3] = -T::one();
            c[4] = half;
        }
        4 => {
            // e5 = ei/2 + eo
            c[3] = T::one();
            c[4] = half;
        }
        _ => c[i] = T::one(),
    }
    Vector::from_coefficients(c)
}

/// Exact change of basis to [`cga`] (`e1 … e5`): each blade `f1 ∧ … ∧ fk` maps to the outer
/// product of the images of its factors.
pub fn to_cga<T: Field>(m: &Multivector<T>) -> cga::Multivector<T> {
    let mut out = cga::Multivector::zero();
    for (coefficient, mask) in m
        .coefficients()
        .into_iter()
        .zip(Multivector::<T>::BLADE_MASKS)
    {
        if coefficient.is_zero() {
            continue;
        }
        let mut image = cga::Multivector::zero();
        image.s = T::one();
        for i in (0..5).filter(|i| mask & (1 << i) != 0) {
            image = image ^ cga::Multivector::from(vector_to_cga::<T>(i));
        }
        let scaled = cga::Multivector::from_coefficients(
            image.coefficients().map(|c| c * coefficient.clone()),
        );
        out = out + scaled;
    }
    out
}

/// Exact change of basis from [`cga`]: the inverse of [`to_cga`].
pub fn from_cga<T: Field>(m: &cga::Multivector<T>) -> Multivector<T> {
    let mut out = Multivector::zero();
    for (coefficient, mask) in m
        .coefficients()
        .into_iter()
        .zip(cga::Multivector::<T>::BLADE_MASKS)
    {
        if coefficient.is_zero() {
            continue;
        }
        let mut image = Multivector::zero();
        image.s = T::one();
        for i in (0..5).filter(|i| mask & (1 << i) != 0) {
            image = image ^ Multivector::from(vector_from_cga::<T>(i));
        }
        let scaled =
            Multivector::from_coefficients(image.coefficients().map(|c| c * coefficient.clone()));
        out = out + scaled;
    }
    out
}

//! What the primitives share: their blades rebuilt from `f64` data in any certified scalar
//! (the thesis's point embedding `F(x) = 2 up(x)`), checks of constructor inputs, and the
//! extraction of Euclidean data (positions, centres, directions) from `f64` blades.

use core::cmp::Ordering;

use ga_core::cga::{Bivector, Multivector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use crate::error::Error;
use crate::exact::{decide, CertifiedScalar, ErrF64};

// ---------------------------------------------------------------------------------------------
// Blades rebuilt in any certified scalar.

/// All 32 coefficients of a blade of any type.
pub(crate) fn coeffs<T: Ring, X: Into<Multivector<T>>>(x: X) -> [T; 32] {
    let m: Multivector<T> = x.into();
    m.coefficients()
}

/// The thesis's conformal point `F(x) = 2x + |x|² n_inf − n̄ = 2 up(x)`, in any ring.
pub(crate) fn embed<T: CertifiedScalar>(p: &Point3<f64>) -> Vector<T> {
    let (x, y, z) = (T::lift(p.x), T::lift(p.y), T::lift(p.z));
    let sq = x.clone() * x.clone() + y.clone() * y.clone() + z.clone() * z.clone();
    let two = T::from_i64(2);
    Vector::new(
        two.clone() * x,
        two.clone() * y,
        two * z,
        sq.clone() - T::one(),
        sq + T::one(),
    )
}

/// A Euclidean direction `d1 e1 + d2 e2 + d3 e3`, in any ring.
pub(crate) fn direction<T: CertifiedScalar>(d: &Vector3<f64>) -> Vector<T> {
    Vector::new(
        T::lift(d.x),
        T::lift(d.y),
        T::lift(d.z),
        T::zero(),
        T::zero(),
    )
}

pub(crate) fn n_inf<T: Ring>() -> Vector<T> {
    ga_core::cga::n_inf()
}

// ---------------------------------------------------------------------------------------------
// Input checks.

pub(crate) fn finite(
    constructor: &'static str,
    argument: &'static str,
    v: f64,
) -> Result<(), Error> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFiniteInput {
            constructor,
            argument,
            value: v,
        })
    }
}

pub(crate) fn finite3(
    constructor: &'static str,
    names: [&'static str; 3],
    v: &Vector3<f64>,
) -> Result<(), Error> {
    for (name, x) in names.into_iter().zip(v.iter()) {
        finite(constructor, name, *x)?;
    }
    Ok(())
}

pub(crate) fn finite_blade<X: Into<Multivector<f64>>>(
    constructor: &'static str,
    blade: X,
) -> Result<(), Error> {
    for c in coeffs(blade) {
        finite(constructor, "blade", c)?;
    }
    Ok(())
}

pub(crate) fn degenerate(constructor: &'static str, reason: &'static str) -> Error {
    Error::Degenerate {
        constructor,
        reason,
    }
}

pub(crate) fn checked_point3(
    constructor: &'static str,
    what: &'static str,
    p: Point3<f64>,
) -> Result<Point3<f64>, Error> {
    if p.iter().all(|x| x.is_finite()) {
        Ok(p)
    } else {
        Err(degenerate(constructor, what))
    }
}

// ---------------------------------------------------------------------------------------------
// Extraction helpers (f64).

/// The Euclidean point of a homogeneous point or of the centre vector of a round:
/// `x = (X₁, X₂, X₃) / (−X·n_inf)`.
pub(crate) fn down(v: &Vector<f64>) -> Option<Point3<f64>> {
    ga_core::cga::down(v)
}

/// The location of a flat point blade `F ∝ up(x) ∧ n_inf`.
pub(crate) fn flat_point_location(f: &Bivector<f64>) -> Option<Point3<f64>> {
    let w = -f.e45;
    let p = Point3::new(
        (f.e14 + f.e15) * 0.5 / w,
        (f.e24 + f.e25) * 0.5 / w,
        (f.e34 + f.e35) * 0.5 / w,
    );
    (w != 0.0 && p.iter().all(|x| x.is_finite())).then_some(p)
}

/// The centre of a round (point pair, circle, sphere) blade `X`: `down(X n_inf X)`.
pub(crate) fn round_centre<X>(x: &X) -> Option<Point3<f64>>
where
    X: Copy + Into<Multivector<f64>>,
{
    let m: Multivector<f64> = (*x).into();
    let c = m * Multivector::from(n_inf::<f64>()) * m;
    down(&Vector::from_multivector(&c))
}

pub(crate) fn unit(v: Vector3<f64>) -> Vector3<f64> {
    let n = v.norm();
    if n > 0.0 && n.is_finite() {
        v / n
    } else {
        // Rescale first: the norm may have overflowed or underflowed.
        let m = v.amax();
        if m > 0.0 && m.is_finite() {
            let w = v / m;
            w / w.norm()
        } else {
            v
        }
    }
}

pub(crate) fn euclidean_part(v: &Vector<f64>) -> Vector3<f64> {
    Vector3::new(v.e1, v.e2, v.e3)
}

/// A primitive whose inner (IPNS) form is a vector `V`: the point `x` lies on it iff
/// `F(x) · V = 0` (planes and spheres).
pub(crate) trait InnerVector {
    /// The inner vector rebuilt exactly from the primitive's `f64` data, in `T`.
    fn inner_vector<T: CertifiedScalar>(&self) -> Vector<T>;
}

/// Whether `x` lies on `primitive` (`F(x) · V = 0`), decided exactly: certified `f64` first,
/// exact rationals if the sign is uncertain. Non-finite points lie on nothing.
pub(crate) fn on_inner_vector<X: InnerVector>(primitive: &X, x: &Point3<f64>) -> bool {
    if !x.iter().all(|c| c.is_finite()) {
        return false;
    }
    let on = |sign: Option<Ordering>| sign.map(|s| s == Ordering::Equal);
    decide(
        || {
            on(embed::<ErrF64>(x)
                .scalar_product(&primitive.inner_vector())
                .certain_sign())
        },
        || {
            on(embed::<Rational>(x)
                .scalar_product(&primitive.inner_vector())
                .certain_sign())
        },
        false,
    )
}

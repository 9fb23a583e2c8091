//! Conversions to and from other math crates, behind optional features of `ga-core`.
//!
//! * `glam`: `DVec3`/`Vec3` ⇄ conformal points ([`crate::cga::up`] /
//!   [`crate::cga::down`]) and `vga3` vectors; `DQuat` ⇄ rotors of `vga3` and
//!   `cga`; rigid `DAffine3` ⇄ `cga` motors (`Even`). See `interop::glam` (enabled by the
//!   feature).
//! * `mint`: `mint::Vector3`/`Point3`/`Quaternion` ⇄ the same types, for any crate speaking
//!   `mint`.
//! * `bytemuck`: `Pod` and `Zeroable` for every generated type over `f64` and `f32`, so
//!   slices of multivectors cast to slices of coefficients (GPU buffers, files); see
//!   `interop::bytemuck` (enabled by the feature).
//! * `serde`: `Serialize` and `Deserialize` for every generated type (a struct with one field
//!   per blade, named as the blade: `s`, `e1`, `e12`, …), for any scalar that has them.
//!
//! Rotations use the same convention everywhere: the unit quaternion `w + x i + y j + z k`
//! (rotation by `θ` about the unit axis `a`: `w = cos θ/2`, `(x, y, z) = a sin θ/2`) is the
//! rotor `w - x e23 + y e13 - z e12`, so that `R v R̃` rotates `v` as `q v q*` does.

#[cfg(feature = "bytemuck")]
pub mod bytemuck;
#[cfg(feature = "glam")]
pub mod glam;
#[cfg(feature = "mint")]
pub mod mint;

/// Why a conversion between this crate's types and another crate's failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InteropError {
    /// A conformal rotor or motor has parts other than a rotation (translation, dilation,
    /// transversion), so it is not a quaternion.
    #[error("the rotor is not a rotation about the origin: its {blade} coefficient is {value}; only a pure rotation converts to a quaternion (convert a motor to an affine transform instead)")]
    NotARotation {
        /// The first offending blade.
        blade: &'static str,
        /// Its coefficient.
        value: f64,
    },
    /// The versor does not map points to points rigidly (it dilates, inverts, or is not a
    /// versor), or its coefficients are not finite.
    #[error("not a rigid motion: {0}; only rotations and translations convert (remove dilations, inversions and reflections first)")]
    NotRigid(&'static str),
    /// The affine map's linear part is not a rotation (orthonormal with determinant +1, up to
    /// a relative error of 1e-9).
    #[error("the linear part is not a rotation (largest deviation of MᵀM from I: {deviation:e}, determinant {determinant}); remove scaling, shear and reflection, or orthonormalise the matrix")]
    NotARotationMatrix {
        /// `max |MᵀM - I|`.
        deviation: f64,
        /// `det M`.
        determinant: f64,
    },
}

#[cfg(any(feature = "glam", feature = "mint"))]
use crate::cga;

#[cfg(any(feature = "glam", feature = "mint"))]
/// The rotor of the unit quaternion `(x, y, z, w)` (see the [module](self) convention).
pub(crate) fn cga_rotor_from_xyzw(x: f64, y: f64, z: f64, w: f64) -> cga::Rotor<f64> {
    let mut r = cga::Rotor::zero();
    r.s = w;
    r.e12 = -z;
    r.e13 = y;
    r.e23 = -x;
    r
}

#[cfg(any(feature = "glam", feature = "mint"))]
/// `(x, y, z, w)` of a conformal rotor that is a rotation about the origin.
pub(crate) fn xyzw_from_cga_rotor(r: &cga::Rotor<f64>) -> Result<[f64; 4], InteropError> {
    for (blade, value) in [
        ("e14", r.e14),
        ("e15", r.e15),
        ("e24", r.e24),
        ("e25", r.e25),
        ("e34", r.e34),
        ("e35", r.e35),
        ("e45", r.e45),
    ] {
        if value != 0.0 {
            return Err(InteropError::NotARotation { blade, value });
        }
    }
    Ok([-r.e23, r.e13, -r.e12, r.s])
}

#[cfg(feature = "glam")]
/// Checks that the columns form a rotation matrix (relative tolerance 1e-9).
pub(crate) fn check_rotation(cols: [[f64; 3]; 3]) -> Result<(), InteropError> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let mut deviation = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let target = if i == j { 1.0 } else { 0.0 };
            deviation = deviation.max((dot(cols[i], cols[j]) - target).abs());
        }
    }
    let [a, b, c] = cols;
    let cross = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let determinant = dot(cross, c);
    if deviation <= 1e-9 && determinant > 0.0 {
        Ok(())
    } else {
        Err(InteropError::NotARotationMatrix {
            deviation,
            determinant,
        })
    }
}

#[cfg(feature = "glam")]
/// The motor `T(t) R` (rotation `R` about the origin, then translation by `t`).
pub(crate) fn motor_from_rotation_translation(xyzw: [f64; 4], t: [f64; 3]) -> cga::Even<f64> {
    let [x, y, z, w] = xyzw;
    let r = cga_rotor_from_xyzw(x, y, z, w);
    let tr = cga::Rotor::translator(t);
    tr * r
}

#[cfg(feature = "glam")]
/// The unit quaternion `(x, y, z, w)` and translation `t` of a rigid conformal motor
/// `M = λ T(t) R`, `λ > 0`.
///
/// `T(t) R = R - ½ t R n_inf`: the part of `M` without `e4`, `e5` is `λR` exactly, and the
/// `eᵢ4` and `e1234` coefficients are those of `-½ λ t R` (an odd Euclidean element), so both
/// are read off without the cancellation of mapping points. The answer is then checked by
/// rebuilding `λ T(t) R` (relative tolerance 1e-9), which rejects dilations, transversions and
/// non-versors.
pub(crate) fn rotation_translation_of_motor(
    m: &cga::Even<f64>,
) -> Result<([f64; 4], [f64; 3]), InteropError> {
    use crate::ops::Geometric;
    use crate::vga3;
    let coeffs = cga::Multivector::from(*m).coefficients();
    if !coeffs.iter().all(|c| c.is_finite()) {
        return Err(InteropError::NotRigid("a coefficient is not finite"));
    }
    let r = vga3::Rotor::new(m.s, m.e12, m.e13, m.e23);
    let n = r.norm_squared();
    if n <= 0.0 || n.is_nan() {
        return Err(InteropError::NotRigid("the rotation part is zero"));
    }
    // Y = t R (times λ), from Y e4 = -2 (eᵢ4 and e1234 parts).
    let y = vga3::Odd::new(-2.0 * m.e14, -2.0 * m.e24, -2.0 * m.e34, -2.0 * m.e1234);
    let t = y.geometric(&r.reverse());
    let t = [t.e1 / n, t.e2 / n, t.e3 / n];
    let rebuilt = cga::Multivector::from(
        cga::Rotor::translator(t) * cga_rotor_from_xyzw(-m.e23, m.e13, -m.e12, m.s),
    )
    .coefficients();
    let size = coeffs.iter().fold(0.0f64, |a, c| a.max(c.abs()));
    let off = coeffs
        .iter()
        .zip(rebuilt)
        .fold(0.0f64, |a, (c, d)| a.max((c - d).abs()));
    if off > 1e-9 * size {
        return Err(InteropError::NotRigid("the motor is not a rigid motion"));
    }
    let k = 1.0 / n.sqrt();
    Ok(([-m.e23 * k, m.e13 * k, -m.e12 * k, m.s * k], t))
}

//! `glam` conversions (feature `glam`).
//!
//! ```
//! use ga_core::interop::glam::{down_dvec3, up_dvec3};
//! use glam::{DAffine3, DQuat, DVec3};
//!
//! let p = DVec3::new(1.0, -2.0, 0.5);
//! assert_eq!(down_dvec3(&up_dvec3(p)), Some(p));
//!
//! // A rigid motion to a conformal motor and back.
//! let rigid = DAffine3::from_rotation_translation(DQuat::from_rotation_z(0.3), DVec3::new(1.0, 2.0, 3.0));
//! let motor = ga_core::cga::Even::from_affine(&rigid).unwrap();
//! let back = motor.to_affine().unwrap();
//! assert!(back.abs_diff_eq(rigid, 1e-14));
//! ```

use glam::{DAffine3, DQuat, DVec3, Vec3};
use nalgebra::Point3;

use super::{
    cga_rotor_from_xyzw, check_rotation, motor_from_rotation_translation,
    rotation_translation_of_motor, xyzw_from_cga_rotor, InteropError,
};
use crate::{cga, vga3};

/// The conformal point `up(p)`.
pub fn up_dvec3(p: DVec3) -> cga::Vector<f64> {
    cga::up(&Point3::new(p.x, p.y, p.z))
}

/// The conformal point of an `f32` point (widened exactly to `f64`).
pub fn up_vec3(p: Vec3) -> cga::Vector<f64> {
    up_dvec3(p.as_dvec3())
}

/// The Euclidean point of a conformal point, `None` where [`cga::down`] is `None`.
pub fn down_dvec3(v: &cga::Vector<f64>) -> Option<DVec3> {
    cga::down(v).map(|p| DVec3::new(p.x, p.y, p.z))
}

impl From<DVec3> for vga3::Vector<f64> {
    fn from(v: DVec3) -> Self {
        vga3::Vector::new(v.x, v.y, v.z)
    }
}

impl From<Vec3> for vga3::Vector<f64> {
    /// Widens exactly to `f64`.
    fn from(v: Vec3) -> Self {
        v.as_dvec3().into()
    }
}

impl From<vga3::Vector<f64>> for DVec3 {
    fn from(v: vga3::Vector<f64>) -> Self {
        DVec3::new(v.e1, v.e2, v.e3)
    }
}

impl From<DQuat> for vga3::Rotor<f64> {
    /// The rotor `w - x e23 + y e13 - z e12` (see [`crate::interop`] for the convention).
    fn from(q: DQuat) -> Self {
        vga3::Rotor::new(q.w, -q.z, q.y, -q.x)
    }
}

impl From<vga3::Rotor<f64>> for DQuat {
    /// The inverse of `From<DQuat>`: `(x, y, z, w) = (-e23, e13, -e12, s)`.
    fn from(r: vga3::Rotor<f64>) -> Self {
        DQuat::from_xyzw(-r.e23, r.e13, -r.e12, r.s)
    }
}

impl From<DQuat> for cga::Rotor<f64> {
    /// The rotation about the origin, as a conformal rotor.
    fn from(q: DQuat) -> Self {
        cga_rotor_from_xyzw(q.x, q.y, q.z, q.w)
    }
}

impl TryFrom<cga::Rotor<f64>> for DQuat {
    type Error = InteropError;
    /// Fails unless the rotor is a rotation about the origin (the coefficients of
    /// `e14 e15 e24 e25 e34 e35 e45` exactly zero).
    fn try_from(r: cga::Rotor<f64>) -> Result<Self, InteropError> {
        let [x, y, z, w] = xyzw_from_cga_rotor(&r)?;
        Ok(DQuat::from_xyzw(x, y, z, w))
    }
}

impl cga::Even<f64> {
    /// The motor of a rigid `DAffine3` (rotation then translation): `T(t) R`. Fails when the
    /// linear part is not a rotation (relative tolerance 1e-9).
    pub fn from_affine(a: &DAffine3) -> Result<Self, InteropError> {
        let m = a.matrix3;
        check_rotation([
            m.x_axis.to_array(),
            m.y_axis.to_array(),
            m.z_axis.to_array(),
        ])?;
        let q = DQuat::from_mat3(&m);
        Ok(motor_from_rotation_translation(
            q.to_array(),
            a.translation.to_array(),
        ))
    }

    /// The rigid `DAffine3` of a motor `λ T(t) R` (`λ > 0`; any positive multiple gives the
    /// same map). Fails when the versor is not a rigid motion (a dilation, transversion,
    /// non-versor, or non-finite coefficients).
    pub fn to_affine(&self) -> Result<DAffine3, InteropError> {
        let (xyzw, t) = rotation_translation_of_motor(self)?;
        Ok(DAffine3::from_rotation_translation(
            DQuat::from_array(xyzw),
            DVec3::from_array(t),
        ))
    }
}

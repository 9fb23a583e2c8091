//! `mint` conversions (feature `mint`): the interchange types many math crates accept.
//!
//! ```
//! use ga_core::interop::mint::{down_point, up_point};
//! let p = mint::Point3 { x: 1.0, y: 2.0, z: 3.0 };
//! assert_eq!(down_point(&up_point(p)), Some(p));
//! ```

use nalgebra::Point3;

use super::{cga_rotor_from_xyzw, xyzw_from_cga_rotor, InteropError};
use crate::{cga, vga3};

/// The conformal point `up(p)`.
pub fn up_point(p: mint::Point3<f64>) -> cga::Vector<f64> {
    cga::up(&Point3::new(p.x, p.y, p.z))
}

/// The Euclidean point of a conformal point, `None` where [`cga::down`] is `None`.
pub fn down_point(v: &cga::Vector<f64>) -> Option<mint::Point3<f64>> {
    cga::down(v).map(|p| mint::Point3 {
        x: p.x,
        y: p.y,
        z: p.z,
    })
}

impl<T> From<mint::Vector3<T>> for vga3::Vector<T> {
    fn from(v: mint::Vector3<T>) -> Self {
        vga3::Vector::new(v.x, v.y, v.z)
    }
}

impl<T> From<vga3::Vector<T>> for mint::Vector3<T> {
    fn from(v: vga3::Vector<T>) -> Self {
        mint::Vector3 {
            x: v.e1,
            y: v.e2,
            z: v.e3,
        }
    }
}

impl<T: core::ops::Neg<Output = T>> From<mint::Quaternion<T>> for vga3::Rotor<T> {
    /// The rotor `w - x e23 + y e13 - z e12` (see [`crate::interop`]).
    fn from(q: mint::Quaternion<T>) -> Self {
        vga3::Rotor::new(q.s, -q.v.z, q.v.y, -q.v.x)
    }
}

impl<T: core::ops::Neg<Output = T>> From<vga3::Rotor<T>> for mint::Quaternion<T> {
    fn from(r: vga3::Rotor<T>) -> Self {
        mint::Quaternion {
            v: mint::Vector3 {
                x: -r.e23,
                y: r.e13,
                z: -r.e12,
            },
            s: r.s,
        }
    }
}

impl From<mint::Quaternion<f64>> for cga::Rotor<f64> {
    /// The rotation about the origin, as a conformal rotor.
    fn from(q: mint::Quaternion<f64>) -> Self {
        cga_rotor_from_xyzw(q.v.x, q.v.y, q.v.z, q.s)
    }
}

impl TryFrom<cga::Rotor<f64>> for mint::Quaternion<f64> {
    type Error = InteropError;
    /// Fails unless the rotor is a rotation about the origin.
    fn try_from(r: cga::Rotor<f64>) -> Result<Self, InteropError> {
        let [x, y, z, s] = xyzw_from_cga_rotor(&r)?;
        Ok(mint::Quaternion {
            v: mint::Vector3 { x, y, z },
            s,
        })
    }
}

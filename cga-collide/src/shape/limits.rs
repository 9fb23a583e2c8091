//! What every primitive constructor checks: finite coordinates and radii, radii `>= 0`, and
//! magnitudes within [`MAX_MAGNITUDE`], so that every sum, product and square the exact tests
//! form stays finite.

use nalgebra::{Point3, Vector3};

use crate::error::Error;

/// The largest magnitude a primitive's coordinate, vector component or radius may have:
/// `2^500` (about `3.27e150`). Below it, squared distances of sums of a few coordinates are
/// finite `f64` values, so every certified bound is finite. Non-zero values may be as small as
/// the smallest subnormal; the exact tests work on the rationals the `f64` values denote.
pub const MAX_MAGNITUDE: f64 = 3.273390607896142e150;

fn check_value(
    shape: &'static str,
    argument: &'static str,
    axis: &'static str,
    value: f64,
) -> Result<(), Error> {
    if !value.is_finite() {
        return Err(Error::NonFiniteCoordinate {
            shape,
            argument,
            axis,
            value,
        });
    }
    if value.abs() > MAX_MAGNITUDE {
        return Err(Error::CoordinateOutOfRange {
            shape,
            argument,
            value,
            limit: MAX_MAGNITUDE,
        });
    }
    Ok(())
}

/// A point argument: finite coordinates within [`MAX_MAGNITUDE`].
pub(crate) fn check_point(
    shape: &'static str,
    argument: &'static str,
    p: &Point3<f64>,
) -> Result<(), Error> {
    check_vector(shape, argument, &p.coords)
}

/// A vector argument (an axis, a normal): finite components within [`MAX_MAGNITUDE`].
pub(crate) fn check_vector(
    shape: &'static str,
    argument: &'static str,
    v: &Vector3<f64>,
) -> Result<(), Error> {
    for (axis, value) in ["x", "y", "z"].into_iter().zip(v.iter()) {
        check_value(shape, argument, axis, *value)?;
    }
    Ok(())
}

/// A radius: finite, `>= 0`, within [`MAX_MAGNITUDE`].
pub(crate) fn check_radius(shape: &'static str, r: f64) -> Result<(), Error> {
    if !r.is_finite() {
        return Err(Error::NonFiniteRadius { shape, value: r });
    }
    if r < 0.0 {
        return Err(Error::NegativeRadius { shape, value: r });
    }
    if r > MAX_MAGNITUDE {
        return Err(Error::CoordinateOutOfRange {
            shape,
            argument: "radius",
            value: r,
            limit: MAX_MAGNITUDE,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_is_two_to_the_500() {
        assert_eq!(MAX_MAGNITUDE, 2f64.powi(500));
    }

    #[test]
    fn out_of_range_values_are_named() {
        let e = check_radius("Capsule", 1e200).unwrap_err();
        assert!(matches!(
            e,
            Error::CoordinateOutOfRange {
                argument: "radius",
                ..
            }
        ));
        assert!(check_point("Cone", "apex", &Point3::new(0.0, -1e160, 0.0)).is_err());
        assert!(check_point("Cone", "apex", &Point3::new(0.0, 5e-324, 0.0)).is_ok());
    }
}

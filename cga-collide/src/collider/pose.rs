//! Poses as the queries take them: a rigid motion `nalgebra::Isometry3<f64>` per mesh, a
//! [`PosePair`] per query of a batch, and [`pose_from_degrees`], the convention of the command
//! line (`--rotate ax,ay,az --translate tx,ty,tz`) as a function, so that a pose written for one
//! is the same pose in the other, and [`pose_from_matrix`], the one check of a pose given as a
//! matrix `[R | t]` (scene files, the Python binding's 4×4 poses).

use nalgebra::{Isometry3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};

use crate::error::Error;
pub use crate::shape::PosePair;

/// The rigid motion that rotates by `degrees[0]` about the x axis, then by `degrees[1]` about
/// the y axis, then by `degrees[2]` about the z axis (fixed axes, right-handed, counter-clockwise
/// looking down the axis), then translates by `translation`: `x ↦ Rz Ry Rx x + t`. This is the
/// convention of the `cga` command line's `--rotate` and `--translate`.
///
/// ```
/// use cga_collide::collider::pose_from_degrees;
/// use cga_collide::nalgebra::Point3;
/// let pose = pose_from_degrees([0.0, 0.0, 90.0], [1.0, 0.0, 0.0]);
/// let p = pose * Point3::new(1.0, 0.0, 0.0); // turned onto +y, then moved along +x
/// assert!((p - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-15);
/// ```
pub fn pose_from_degrees(degrees: [f64; 3], translation: [f64; 3]) -> Isometry3<f64> {
    let [ax, ay, az] = degrees.map(f64::to_radians);
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), az)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), ay)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), ax);
    let [tx, ty, tz] = translation;
    Isometry3::from_parts(Translation3::new(tx, ty, tz), rotation)
}

/// How far the rotation part `R` of a pose given as a matrix may be from a rotation:
/// `max |RᵀR − I|` over the entries. Rounding of a rotation written with 7 or more significant
/// digits stays well inside it; a matrix further from orthonormal is a mistake (a scale, a
/// shear), not rounding, and is refused rather than replaced by the nearest rotation.
pub const ROTATION_TOLERANCE: f64 = 1e-6;

/// The rigid motion `x ↦ R x + t` of a 3×3 matrix `rotation` (row `i`, column `j` is
/// `rotation[(i, j)]`) and a `translation`, after checking that `R` is a rotation: every entry
/// finite, `max |RᵀR − I| <=` [`ROTATION_TOLERANCE`] and `det R > 0` (no reflection).
///
/// # Errors
/// [`Error::NonFinitePose`] for a NaN or infinite entry; [`Error::NotARotation`] for a matrix
/// that scales, shears or reflects (it is never swapped for the nearest rotation, which would
/// answer a question about different shapes).
///
/// ```
/// use cga_collide::collider::pose_from_matrix;
/// use cga_collide::nalgebra::{Matrix3, Point3};
/// let quarter = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
/// let pose = pose_from_matrix(&quarter, [1.0, 0.0, 0.0])?;
/// assert!((pose * Point3::new(1.0, 0.0, 0.0) - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-15);
/// assert!(pose_from_matrix(&(quarter * 2.0), [0.0; 3]).is_err()); // a scale
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn pose_from_matrix(
    rotation: &Matrix3<f64>,
    translation: [f64; 3],
) -> Result<Isometry3<f64>, Error> {
    if !rotation.iter().chain(&translation).all(|x| x.is_finite()) {
        return Err(Error::NonFinitePose);
    }
    let gram = rotation.transpose() * rotation - Matrix3::identity();
    let deviation = gram.iter().fold(0.0f64, |acc, x| acc.max(x.abs()));
    let determinant = rotation.determinant();
    if deviation > ROTATION_TOLERANCE || determinant <= 0.0 {
        return Err(Error::NotARotation {
            deviation,
            determinant,
        });
    }
    let q = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*rotation));
    let [tx, ty, tz] = translation;
    Ok(Isometry3::from_parts(Translation3::new(tx, ty, tz), q))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_reflections_and_zeros_are_not_rotations() {
        let id = Matrix3::identity();
        let reflection = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        for m in [id * 2.0, reflection, Matrix3::zeros(), id * (1.0 + 1e-5)] {
            assert!(
                matches!(
                    pose_from_matrix(&m, [0.0; 3]),
                    Err(Error::NotARotation { .. })
                ),
                "{m}"
            );
        }
        let mut nan = id;
        nan[(1, 2)] = f64::NAN;
        assert_eq!(pose_from_matrix(&nan, [0.0; 3]), Err(Error::NonFinitePose));
        assert_eq!(
            pose_from_matrix(&id, [0.0, f64::INFINITY, 0.0]),
            Err(Error::NonFinitePose)
        );
    }

    #[test]
    fn rotations_rounded_to_seven_digits_are_taken_as_they_are() {
        let pose = pose_from_degrees([10.0, 20.0, 30.0], [1.0, 2.0, 3.0]);
        let m = pose.rotation.to_rotation_matrix().into_inner();
        let rounded = m.map(|x| (x * 1e7).round() / 1e7);
        let back = pose_from_matrix(&rounded, [1.0, 2.0, 3.0]).unwrap();
        assert!(back.rotation.angle_to(&pose.rotation) < 1e-6);
        assert_eq!(back.translation.vector, Vector3::new(1.0, 2.0, 3.0));
    }
}

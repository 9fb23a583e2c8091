//! `--rotate` and `--translate` (the pose of mesh B). The convention, "degrees about x, then y,
//! then z, then a translation", is the library's [`pose_from_degrees`], so a pose written for the
//! command line is the same pose in a program.

use cga_collide::collider::pose_from_degrees;
use cga_collide::nalgebra::Isometry3;
use clap::Args;

use crate::args::parse_triple;

/// The pose of mesh B, flattened into every subcommand that moves it.
#[derive(Args, Debug, Clone, Copy, Default)]
pub struct PoseArgs {
    /// Rotate B by these degrees about x, then y, then z.
    #[arg(long, value_name = "AX,AY,AZ", value_parser = parse_triple, allow_hyphen_values = true)]
    pub rotate: Option<[f64; 3]>,
    /// Then translate B.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_triple, allow_hyphen_values = true)]
    pub translate: Option<[f64; 3]>,
}

impl PoseArgs {
    /// The isometry (identity parts where an option is not given).
    pub fn isometry(&self) -> Isometry3<f64> {
        pose_from_degrees(
            self.rotate.unwrap_or([0.0; 3]),
            self.translate.unwrap_or([0.0; 3]),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_collide::nalgebra::Point3;

    #[test]
    fn rotates_about_x_then_y_then_z_then_translates() {
        let iso = pose_from_degrees([90.0, 90.0, 0.0], [1.0, 2.0, 3.0]);
        // y -> z about x, then z -> x about y.
        let p = iso * Point3::new(0.0, 1.0, 0.0);
        assert!((p - Point3::new(2.0, 2.0, 3.0)).norm() < 1e-12, "{p}");
        assert_eq!(PoseArgs::default().isometry(), Isometry3::identity());
    }
}

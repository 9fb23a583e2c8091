//! Oriented boxes around placed meshes: a rotated mesh's world box is loose, and most link
//! pairs of a robot are apart but have overlapping world boxes. Two oriented boxes proved
//! apart on one of the 15 separating axes set the pair aside before the exact test.

use nalgebra::{Isometry3, Matrix3, Point3, Vector3};

use crate::bounding::Aabb;

/// A box in a pose: centre, rotation (columns are its axes) and half extents.
#[derive(Debug, Clone, Copy)]
pub(super) struct Obb {
    centre: Point3<f64>,
    axes: Matrix3<f64>,
    half: Vector3<f64>,
}

impl Obb {
    /// The mesh's local box `b` placed by `pose`.
    pub fn new(b: &Aabb, pose: &Isometry3<f64>) -> Obb {
        let lo = Vector3::from(b.min);
        let hi = Vector3::from(b.max);
        Obb {
            centre: pose * Point3::from((lo + hi) / 2.0),
            axes: *pose.rotation.to_rotation_matrix().matrix(),
            half: (hi - lo) / 2.0,
        }
    }

    /// Whether the two boxes are proved apart by more than `c` (conservative: every `f64`
    /// error, and the placement rule's rounding of each placed vertex, is far below the
    /// margin, so boxes that may hold points within `c` are never reported apart).
    pub fn apart(&self, o: &Obb, c: f64) -> bool {
        let r = self.axes.transpose() * o.axes;
        let abs = r.map(f64::abs);
        let d = o.centre - self.centre;
        let t = self.axes.transpose() * d;
        let (a, b) = (self.half, o.half);
        let scale = 1.0 + d.amax() + a.amax() + b.amax() + c;
        let margin = c + 1e-9 * scale;
        let separated = |dist: f64, ra: f64, rb: f64| dist.abs() > ra + rb + margin;
        for i in 0..3 {
            let rb = b[0] * abs[(i, 0)] + b[1] * abs[(i, 1)] + b[2] * abs[(i, 2)];
            if separated(t[i], a[i], rb) {
                return true;
            }
        }
        for j in 0..3 {
            let ra = a[0] * abs[(0, j)] + a[1] * abs[(1, j)] + a[2] * abs[(2, j)];
            let dist = t[0] * r[(0, j)] + t[1] * r[(1, j)] + t[2] * r[(2, j)];
            if separated(dist, ra, b[j]) {
                return true;
            }
        }
        // Edge-edge axes A_i × B_j (not unit: the test compares in the same scale, and the
        // margin is scaled by the axis length, which is at most 1).
        for i in 0..3 {
            let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
            for j in 0..3 {
                let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
                let ra = a[i1] * abs[(i2, j)] + a[i2] * abs[(i1, j)];
                let rb = b[j1] * abs[(i, j2)] + b[j2] * abs[(i, j1)];
                let dist = t[i2] * r[(i1, j)] - t[i1] * r[(i2, j)];
                // An upper bound on |A_i × B_j| despite the rounding of r (whose square root
                // magnifies it near parallel axes).
                let len = ((1.0 - r[(i, j)] * r[(i, j)]).max(0.0).sqrt() + 1e-7).min(1.0);
                if dist.abs() > ra + rb + margin * len + 1e-12 * scale {
                    return true;
                }
            }
        }
        false
    }
}

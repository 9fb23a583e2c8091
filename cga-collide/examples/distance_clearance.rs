//! Distance and clearance between meshes: "are they within c?" decided exactly, and the
//! minimum distance with nearest points and a proved error bound.
//!
//! Run: `cargo run --release -p cga-collide --example distance_clearance`.

use cga_collide::nalgebra::{Isometry3, Point3};

use cga_collide::collider::Collider;
use cga_collide::TriMesh;

pub fn main() -> Result<(), Box<dyn std::error::Error>> {
    let unit =
        |lo: f64| TriMesh::cuboid(Point3::new(lo, 0.0, 0.0), Point3::new(lo + 1.0, 1.0, 1.0));
    let a = Collider::new(unit(0.0)?);
    // A second unit cube, placed so that the gap between them is exactly 0.25.
    let b = Collider::new(unit(0.0)?).placed(&Isometry3::translation(1.25, 0.0, 0.0))?;

    // Clearance is closed: a distance of exactly c counts.
    assert!(a.within_distance(&b, 0.25));
    assert!(!a.within_distance(&b, 0.2499999999999999));

    let d = a.distance(&b).expect("both meshes have triangles");
    println!(
        "distance {} (± {:e}) between {} and {}, triangles {:?}",
        d.distance, d.error_bound, d.witness_a, d.witness_b, d.triangles
    );
    assert!((d.distance - 0.25).abs() <= d.error_bound);
    Ok(())
}

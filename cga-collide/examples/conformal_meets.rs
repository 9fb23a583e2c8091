//! Conformal primitives and their exact meets: build lines, planes and spheres from points or
//! from Euclidean data, classify how they meet, move them with versors.
//!
//! Run: `cargo run -p cga-collide --example conformal_meets`.

use cga_collide::conformal::meet::{LinePlane, LineSphere, Meet, SphereSphere};
use cga_collide::conformal::{Line, Plane, Sphere, Transform, Versor};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::Error;

pub fn main() -> Result<(), Error> {
    // A line through two points (outer form P1 ∧ P2 ∧ n_inf) and a unit sphere (inner form).
    let line = Line::from_points(Point3::new(-2.0, 0.0, 1.0), Point3::new(2.0, 0.0, 1.0))?;
    let sphere = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
    // The line touches the sphere at (0, 0, 1): tangency is decided exactly, not within a tolerance.
    match line.meet(&sphere) {
        LineSphere::Tangent(p) => println!("line touches the sphere at {p}"),
        other => println!("unexpected: {other:?}"),
    }

    // A plane z = 1 contains the line.
    let plane = Plane::from_normal_offset(Vector3::z(), 1.0)?;
    assert_eq!(line.meet(&plane), LinePlane::Contained);

    // Two spheres at a huge scale still meet exactly tangentially: every f64 product would
    // overflow, so the certified filter defers to exact rationals.
    let k = 2f64.powi(400);
    let a = Sphere::from_centre_radius(Point3::origin(), 5.0 * k)?;
    let b = Sphere::from_centre_radius(Point3::new(0.0, 8.0 * k, 0.0), 3.0 * k)?;
    assert!(matches!(a.meet(&b), SphereSphere::TangentExternal(_)));
    println!("spheres of radius 5·2^400 and 3·2^400 at distance 8·2^400: externally tangent");

    // Versors: a rigid motion from nalgebra, applied to the sphere.
    let motion = Isometry3::new(Vector3::new(0.0, 0.0, 5.0), Vector3::y() * 0.5);
    let moved = sphere.transform(&Versor::from(motion))?;
    println!(
        "moved sphere: centre {}, radius {:?}",
        moved.centre(),
        moved.radius()
    );
    Ok(())
}

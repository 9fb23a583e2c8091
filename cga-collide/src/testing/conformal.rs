//! Hooks into the certified filter of the conformal meets ([`crate::conformal::meet`]): which
//! cases it decides alone, and how often plain `f64` would be wrong.

pub use crate::conformal::meet::filter_stats::{filter_tallies, FilterTally};
use crate::conformal::Sphere;

/// Which path decided a sphere–sphere classification: `true` if the certified `f64` evaluation
/// was enough, `false` if the exact rational recomputation was needed (the answer of
/// [`crate::conformal::meet::sphere_sphere`] is the same either way).
///
/// ```
/// use cga_collide::conformal::Sphere;
/// use cga_collide::nalgebra::Point3;
/// use cga_collide::testing::conformal::sphere_sphere_filtered;
/// let a = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
/// let b = Sphere::from_centre_radius(Point3::new(1.5, 0.1, 0.0), 1.0)?;
/// assert!(sphere_sphere_filtered(&a, &b)); // a transversal circle: decided in f64
/// let c = Sphere::from_centre_radius(Point3::new(2.0, 0.0, 0.0), 1.0)?;
/// assert!(!sphere_sphere_filtered(&a, &c)); // tangency: needs the exact path
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn sphere_sphere_filtered(a: &Sphere, b: &Sphere) -> bool {
    crate::conformal::meet::sphere_sphere_filtered(a, b)
}

//! Whether a point lies in the closed solid bounded by a closed triangle mesh, exactly.
//!
//! The point is inside when it lies on a triangle, or when a ray from it crosses the surface an
//! odd number of times. The ray runs along `+x` and is perturbed symbolically (simulation of
//! simplicity in the `(y, z)` projection), so rays through edges and vertices are counted
//! consistently and no retry with another direction is ever needed; every sign is an exact
//! predicate. The answer is the solid's for a closed mesh (every edge used by an even number
//! of triangles); for other meshes it is the even–odd rule of that one ray.

use core::cmp::Ordering;

use nalgebra::Point3;

use crate::exact::predicates::{Orient2d, Orient3d};
use crate::exact::{ExactKernel, Kernel};
use crate::query::Intersects;
use crate::shape::{Segment, Triangle};

/// Whether `p` lies in the closed solid bounded by `triangles` (a closed mesh): on a
/// triangle, or inside by ray parity (see the module docs). Exact.
///
/// ```
/// use cga_collide::nalgebra::Point3;
/// use cga_collide::query::point_in_solid;
/// use cga_collide::TriMesh;
/// let cube = TriMesh::unit_cube();
/// let tris = || (0..cube.num_triangles()).map(|i| cube.triangle(i));
/// assert!(point_in_solid(tris(), &Point3::new(0.5, 0.5, 0.5)));
/// assert!(point_in_solid(tris(), &Point3::new(1.0, 0.5, 0.5))); // on the surface
/// assert!(!point_in_solid(tris(), &Point3::new(1.5, 0.5, 0.5)));
/// ```
pub fn point_in_solid<I>(triangles: I, p: &Point3<f64>) -> bool
where
    I: IntoIterator<Item = [Point3<f64>; 3]>,
{
    let Ok(point) = Segment::new(*p, *p) else {
        return false; // a non-finite point is in no solid
    };
    let mut odd = false;
    for t in triangles {
        if Triangle::new(t[0], t[1], t[2]).is_ok_and(|tri| tri.intersects(&point)) {
            return true;
        }
        odd ^= ray_crosses_triangle(&t, p);
    }
    odd
}

/// `orient2d(a, b, p')` in the `(y, z)` projection for the perturbed point
/// `p' = p + (0, ε, ε²)`, `ε → 0⁺` (never zero unless `a` and `b` project to one point).
fn orient2d_perturbed(a: &Point3<f64>, b: &Point3<f64>, p: &Point3<f64>) -> Ordering {
    let s = ExactKernel::sign::<Orient2d, 6>(&[a.y, a.z, b.y, b.z, p.y, p.z]);
    if s != Ordering::Equal {
        return s;
    }
    // d/dε = -(b_z - a_z), d/dε² = b_y - a_y
    match a.z.partial_cmp(&b.z) {
        Some(Ordering::Equal) | None => b.y.partial_cmp(&a.y).unwrap_or(Ordering::Equal),
        Some(o) => o,
    }
}

/// Whether the ray from `p` along `+x`, perturbed symbolically (see the module docs), crosses the
/// triangle `[a, b, c]` (which does not contain `p`).
pub fn ray_crosses_triangle(t: &[Point3<f64>; 3], p: &Point3<f64>) -> bool {
    let [a, b, c] = t;
    let area = ExactKernel::sign::<Orient2d, 6>(&[a.y, a.z, b.y, b.z, c.y, c.z]);
    if area == Ordering::Equal {
        return false; // zero-area projection: the perturbed ray misses it
    }
    if orient2d_perturbed(a, b, p) != area
        || orient2d_perturbed(b, c, p) != area
        || orient2d_perturbed(c, a, p) != area
    {
        return false;
    }
    // In front of p: sign(x* - p_x) = -sign(orient3d(a, b, c, p)) · sign(n_x), n_x = area.
    let o3 = ExactKernel::sign::<Orient3d, 12>(&[
        a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, p.x, p.y, p.z,
    ]);
    o3 != Ordering::Equal && o3 != area
}

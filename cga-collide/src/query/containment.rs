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

use ga_core::scalar::{rational_from_f64, Rational, Real, Ring};

use crate::exact::predicates::{Orient2d, Orient3d};
use crate::exact::{rational_sign, ExactKernel, Kernel, Predicate};
use crate::query::Intersects;
use crate::shape::{Segment, Triangle};

/// Whether `p` lies in the closed solid bounded by `triangles` (a closed mesh): on a
/// triangle, or inside by ray parity (see the module docs). Exact. Every triangle is tested:
/// callers holding a box tree run [`ray_crosses_triangle`] on its candidates instead.
pub(crate) fn point_in_solid<I>(triangles: I, p: &Point3<f64>) -> bool
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
/// `p' = p + (0, ε, ε²)`, `ε → 0⁺` (never zero unless `a` and `b` project to one point), given
/// the unperturbed sign `s`.
fn perturbed(s: Ordering, a: &Point3<f64>, b: &Point3<f64>) -> Ordering {
    if s != Ordering::Equal {
        return s;
    }
    // d/dε = -(b_z - a_z), d/dε² = b_y - a_y
    match a.z.partial_cmp(&b.z) {
        Some(Ordering::Equal) | None => b.y.partial_cmp(&a.y).unwrap_or(Ordering::Equal),
        Some(o) => o,
    }
}

/// The crossing test of the perturbed ray with the triangle `t`, given the point's exact
/// predicates: `orient2d(t[i], t[j], p)` in the `(y, z)` projection and `orient3d(a, b, c, p)`.
fn crosses(
    t: &[Point3<f64>; 3],
    orient2d: impl Fn(usize, usize) -> Ordering,
    orient3d: impl FnOnce() -> Ordering,
) -> bool {
    let [a, b, c] = t;
    let area = ExactKernel::sign::<Orient2d, 6>(&[a.y, a.z, b.y, b.z, c.y, c.z]);
    if area == Ordering::Equal {
        return false; // zero-area projection: the perturbed ray misses it
    }
    if (0..3).any(|i| {
        let j = (i + 1) % 3;
        perturbed(orient2d(i, j), &t[i], &t[j]) != area
    }) {
        return false;
    }
    // In front of p: sign(x* - p_x) = -sign(orient3d(a, b, c, p)) · sign(n_x), n_x = area.
    let o3 = orient3d();
    o3 != Ordering::Equal && o3 != area
}

/// Whether the ray from `p` along `+x`, perturbed symbolically (see the module docs), crosses the
/// triangle `[a, b, c]` (which does not contain `p`).
pub fn ray_crosses_triangle(t: &[Point3<f64>; 3], p: &Point3<f64>) -> bool {
    let [a, b, c] = t;
    crosses(
        t,
        |i, j| {
            let (u, v) = (t[i], t[j]);
            ExactKernel::sign::<Orient2d, 6>(&[u.y, u.z, v.y, v.z, p.y, p.z])
        },
        || {
            ExactKernel::sign::<Orient3d, 12>(&[
                a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, p.x, p.y, p.z,
            ])
        },
    )
}

/// Whether the exact point `p`, which lies on none of `triangles`, is inside the solid they
/// bound (a closed mesh), by the parity of the same perturbed ray as [`point_in_solid`], with
/// every sign evaluated in rationals. Triangles whose boxes the ray cannot reach are skipped
/// by an `f64` test widened well beyond the rounding of `p`.
pub(crate) fn exact_point_in_solid<I>(triangles: I, p: &[Rational; 3]) -> bool
where
    I: IntoIterator<Item = [Point3<f64>; 3]>,
{
    let approx = p.clone().map(|x| x.to_f64());
    let slack = |x: f64| 1e-9 * x.abs() + 1e-300;
    let q = |x: f64| rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero);
    let mut odd = false;
    for t in triangles {
        let max = |k: usize| t.iter().map(|v| v[k]).fold(f64::NEG_INFINITY, f64::max);
        let min = |k: usize| t.iter().map(|v| v[k]).fold(f64::INFINITY, f64::min);
        let reachable = max(0) >= approx[0] - slack(approx[0])
            && (1..3).all(|k| {
                min(k) <= approx[k] + slack(approx[k]) && max(k) >= approx[k] - slack(approx[k])
            });
        // NaN approximations (never from a finite rational) would skip nothing.
        if !reachable && approx.iter().all(|x| x.is_finite()) {
            continue;
        }
        let v = t.map(|v| [q(v.x), q(v.y), q(v.z)]);
        let sign = |r: Rational| rational_sign(&r);
        odd ^= crosses(
            &t,
            |i, j| {
                let (u, w) = (&v[i], &v[j]);
                sign(Orient2d::eval(&[
                    u[1].clone(),
                    u[2].clone(),
                    w[1].clone(),
                    w[2].clone(),
                    p[1].clone(),
                    p[2].clone(),
                ]))
            },
            || {
                let points = [&v[0], &v[1], &v[2], p];
                let x: [Rational; 12] = core::array::from_fn(|k| points[k / 3][k % 3].clone());
                sign(Orient3d::eval(&x))
            },
        );
    }
    odd
}

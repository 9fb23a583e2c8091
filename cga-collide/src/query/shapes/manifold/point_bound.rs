//! A proved upper bound of the distance from a contact point to a shape, in plain `f64`: the
//! fast path of each manifold point's `error_bound` (the exact point–shape distance decides the
//! shapes this does not cover).
//!
//! The bound is `|p − q̃| + |q̃ − q|` for a point `q` of the shape built from exact parameters
//! (a clamp of the point's coordinates in the shape's own frame: any parameters in range give a
//! point of the shape) and `q̃` its rounded value, with a proved bound of the rounding. When `p`
//! is proved inside the shape, or `q̃` was formed without rounding and equals `p`, the bound is
//! exactly `0`. It is used only when every nonzero input lies within `2^±250`, so each rounding
//! is relative.
//!
//! A solid hull has no clamp: a point is given `0` when it is proved strictly inside every
//! boundary triangle's plane (each `orient3d` sign certain under Shewchuk's static error bound);
//! otherwise, as for a triangle, the point of the boundary triangle it is farthest outside that
//! lies under it along that triangle's normal, when the projection falls inside the triangle
//! (barycentric parameters checked exactly; else the exact distance decides).

use crate::query::shapes::rounded_f64::{cross, dot, tame, P3, U};
use crate::shape::Shape;
use nalgebra::Point3;

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

/// `x + y` and whether it was exact (Knuth's two-sum).
fn sum_exact(x: f64, y: f64) -> (f64, bool) {
    let s = x + y;
    let z = s - x;
    let err = (x - (s - z)) + (y - z);
    (s, err == 0.0)
}

/// `x · y` and whether it was exact.
fn product_exact(x: f64, y: f64) -> (f64, bool) {
    let p = x * y;
    (p, x.mul_add(y, -p) == 0.0)
}

/// `|v|` rounded up, for a vector of rounded components.
fn norm_up(v: &P3) -> f64 {
    (dot(v, v).sqrt() * (1.0 + 8.0 * U)).next_up()
}

/// The rounded point `base + Σ t_m axis_m`, whether every operation was exact, and a proved
/// componentwise bound of its rounding error.
fn combine(base: &P3, terms: &[(f64, P3)]) -> (P3, bool, P3) {
    let mut point = *base;
    let mut exact = true;
    let mut size: P3 = base.map(f64::abs);
    for (t, axis) in terms {
        for k in 0..3 {
            let (prod, e1) = product_exact(*t, axis[k]);
            let (s, e2) = sum_exact(point[k], prod);
            point[k] = s;
            exact &= e1 && e2;
            size[k] += (t * axis[k]).abs();
        }
    }
    let n = terms.len() as f64;
    let err = size.map(|x| x * (2.0 * n + 2.0) * U * (1.0 + 4.0 * U));
    (point, exact, err)
}

/// `|p − q̃| + |err|` rounded up, or `0` when `q̃` is exact and equal to `p`.
fn gap(p: &P3, q: &P3, exact: bool, err: &P3) -> f64 {
    if exact && p == q {
        return 0.0;
    }
    let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    // Each difference is within `u` of the exact one, relatively.
    ((norm_up(&d) * (1.0 + 2.0 * U)).next_up() + norm_up(err)).next_up()
}

/// A proved upper bound of the distance from `p` to `shape`, or `None` for the shapes it does
/// not cover (flat hulls, cylinders, cones), for points whose projection misses the triangle
/// used (triangles, solid hulls) and for extreme magnitudes.
pub(in crate::query::shapes) fn upper_distance(p: &Point3<f64>, shape: &Shape) -> Option<f64> {
    let p = p3(p);
    if !tame(&p) {
        return None;
    }
    match shape {
        Shape::Ball(b) => {
            let c = p3(b.centre());
            let r = b.radius();
            tame(&c).then_some(())?;
            tame(&[r]).then_some(())?;
            let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
            let len = (norm_up(&d) * (1.0 + 2.0 * U)).next_up();
            Some(if len <= r {
                0.0
            } else {
                ((len - r) * (1.0 + 2.0 * U)).next_up()
            })
        }
        Shape::Capsule(c) => segment(&p, &p3(c.a()), &p3(c.b()), c.radius()),
        Shape::Segment(s) => segment(&p, &p3(s.a()), &p3(s.b()), 0.0),
        Shape::Cuboid(c) => {
            let centre = p3(c.centre());
            let axes = c.half_axes().map(|a| [a.x, a.y, a.z]);
            tame(&centre).then_some(())?;
            tame(axes.as_flattened()).then_some(())?;
            cuboid(&p, &centre, &axes)
        }
        Shape::HalfSpace(h) => {
            let (q, n) = (p3(h.point()), [h.normal().x, h.normal().y, h.normal().z]);
            tame(&q).then_some(())?;
            tame(&n).then_some(())?;
            let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
            let s = dot(&d, &n);
            let err = 4.0
                * U
                * (d[0].abs() * n[0].abs() + d[1].abs() * n[1].abs() + d[2].abs() * n[2].abs())
                * (1.0 + 4.0 * U);
            let high = s + err;
            if high <= 0.0 {
                return Some(0.0);
            }
            let len = dot(&n, &n).sqrt() * (1.0 - 8.0 * U);
            Some((high * (1.0 + 4.0 * U) / len * (1.0 + 4.0 * U)).next_up())
        }
        Shape::ConvexHull(h) if h.dimension() == 3 => {
            let corners: Vec<P3> = h.corners().iter().map(p3).collect();
            tame(corners.as_flattened()).then_some(())?;
            // Inside every plane: 0. Else the point over the plane it is farthest outside.
            let mut farthest: Option<(f64, [&P3; 3])> = None;
            for t in h.triangles() {
                let [a, b, c] = t.map(|i| &corners[i as usize]);
                if below_plane(a, b, c, &p) {
                    continue;
                }
                let n = cross(&sub(b, a), &sub(c, a));
                let height = dot(&n, &sub(&p, a)) / dot(&n, &n).sqrt();
                if farthest.is_none_or(|(best, _)| height > best) {
                    farthest = Some((height, [a, b, c]));
                }
            }
            match farthest {
                None => Some(0.0),
                Some((_, [a, b, c])) => over_triangle(&p, a, b, c),
            }
        }
        Shape::Triangle(t) => {
            let [a, b, c] = t.vertices();
            let (a, b, c) = (p3(a), p3(b), p3(c));
            tame(&[a, b, c].concat()).then_some(())?;
            over_triangle(&p, &a, &b, &c)
        }
        _ => None,
    }
}

fn sub(a: &P3, b: &P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The distance from `p` to the point of the triangle `abc` under it, when `p`'s projection on
/// the triangle's plane falls inside the triangle (in `f64`); else `None`. The point is
/// `a + s (b − a) + t (c − a)` with the rounded `s, t ≥ 0`, `s + t ≤ 1` checked exactly, so it
/// lies in the triangle; its rounding is bounded as for segments.
fn over_triangle(p: &P3, a: &P3, b: &P3, c: &P3) -> Option<f64> {
    let (d1, d2, r) = (sub(b, a), sub(c, a), sub(p, a));
    let (d11, d12, d22) = (dot(&d1, &d1), dot(&d1, &d2), dot(&d2, &d2));
    let (r1, r2) = (dot(&r, &d1), dot(&r, &d2));
    let det = d11 * d22 - d12 * d12;
    if det.is_nan() || det <= 0.0 {
        return None;
    }
    let s = (d22 * r1 - d12 * r2) / det;
    let t = (d11 * r2 - d12 * r1) / det;
    // s + t ≤ 1 exactly: the rounded sum below 1, or equal to 1 with a non-positive error.
    let sum = s + t;
    let low_part = (s - (sum - (sum - s))) + (t - (sum - s));
    let in_triangle = s >= 0.0 && t >= 0.0 && (sum < 1.0 || (sum == 1.0 && low_part <= 0.0));
    if !in_triangle {
        return None;
    }
    let (q, exact, err) = combine(a, &[(s, d1), (t, d2)]);
    let err: P3 = core::array::from_fn(|k| err[k] + 2.0 * U * (d1[k].abs() + d2[k].abs()));
    let exact = exact && sub_exact(a, b, &d1) && sub_exact(a, c, &d2);
    Some(gap(p, &q, exact, &err))
}

/// Whether `orient3d(a, b, c, p) = ((b − a) × (c − a)) · (p − a)` is proved negative: `p`
/// strictly on the inner side of an outward, counter-clockwise boundary triangle. The `f64`
/// determinant must exceed Shewchuk's bound `(7 + 56ε)ε · permanent` (`ε = 2^-53`), valid
/// here because tame inputs neither underflow nor overflow.
fn below_plane(a: &P3, b: &P3, c: &P3, p: &P3) -> bool {
    const BOUND: f64 = (7.0 + 56.0 * U) * U;
    let [bx, by, bz] = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let [cx, cy, cz] = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let [px, py, pz] = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let (bc_xy, cb_xy) = (bx * cy, cx * by);
    let (cp_xy, pc_xy) = (cx * py, px * cy);
    let (pb_xy, bp_xy) = (px * by, bx * py);
    let det = pz * (bc_xy - cb_xy) + bz * (cp_xy - pc_xy) + cz * (pb_xy - bp_xy);
    let permanent = pz.abs() * (bc_xy.abs() + cb_xy.abs())
        + bz.abs() * (cp_xy.abs() + pc_xy.abs())
        + cz.abs() * (pb_xy.abs() + bp_xy.abs());
    det < -BOUND * permanent
}

/// The point `a + t (b − a)` nearest `p` (t clamped to `[0, 1]`), minus the radius.
pub(in crate::query::shapes) fn segment(p: &P3, a: &P3, b: &P3, radius: f64) -> Option<f64> {
    tame(a).then_some(())?;
    tame(b).then_some(())?;
    tame(&[radius]).then_some(())?;
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let dd = dot(&d, &d);
    let t = if dd > 0.0 {
        (dot(&[p[0] - a[0], p[1] - a[1], p[2] - a[2]], &d) / dd).clamp(0.0, 1.0)
    } else {
        0.0
    };
    // q = (1 − t) a + t b exactly on the segment; formed as a + t (b − a) with `b − a` rounded,
    // whose error adds `u |b − a|` per component.
    let (q, exact, err) = combine(a, &[(t, d)]);
    let err: P3 = core::array::from_fn(|k| err[k] + 2.0 * U * d[k].abs());
    let g = gap(p, &q, exact && sub_exact(a, b, &d), &err);
    Some(if g <= radius {
        0.0
    } else {
        ((g - radius) * (1.0 + 2.0 * U)).next_up()
    })
}

/// Whether `d = b − a` was computed exactly.
fn sub_exact(a: &P3, b: &P3, d: &P3) -> bool {
    (0..3).all(|k| sum_exact(b[k], -a[k]) == (d[k], true))
}

/// The cuboid `c + Σ t_m axis_m`, `|t_m| ≤ 1`: `0` when `p`'s exact parameters (Cramer's rule)
/// are proved inside, else the clamped parameters' point.
pub(in crate::query::shapes) fn cuboid(p: &P3, c: &P3, axes: &[P3; 3]) -> Option<f64> {
    let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    let d_err: P3 = d.map(|x| x.abs() * U * 1.01);
    let mut params = [0.0; 3];
    let mut inside = true;
    for m in 0..3 {
        // t_m = d · (a_i × a_j) / (a_m · (a_i × a_j)) with (i, j) the other two axes.
        let (i, j) = ((m + 1) % 3, (m + 2) % 3);
        let n = cross(&axes[i], &axes[j]);
        let n_size: P3 = [
            (axes[i][1] * axes[j][2]).abs() + (axes[i][2] * axes[j][1]).abs(),
            (axes[i][2] * axes[j][0]).abs() + (axes[i][0] * axes[j][2]).abs(),
            (axes[i][0] * axes[j][1]).abs() + (axes[i][1] * axes[j][0]).abs(),
        ];
        let num = dot(&d, &n);
        let den = dot(&axes[m], &n);
        let num_err = 8.0
            * U
            * (0..3)
                .map(|k| (d[k].abs() + d_err[k]) * n_size[k])
                .sum::<f64>()
            + (0..3).map(|k| d_err[k] * n_size[k]).sum::<f64>();
        let den_err = 8.0 * U * (0..3).map(|k| axes[m][k].abs() * n_size[k]).sum::<f64>();
        inside &= (num.abs() + num_err) * (1.0 + 4.0 * U) < (den.abs() - den_err) * (1.0 - 4.0 * U);
        params[m] = if den != 0.0 {
            (num / den).clamp(-1.0, 1.0)
        } else {
            0.0
        };
    }
    if inside {
        return Some(0.0);
    }
    let (q, exact, err) = combine(
        c,
        &[
            (params[0], axes[0]),
            (params[1], axes[1]),
            (params[2], axes[2]),
        ],
    );
    Some(gap(p, &q, exact, &err))
}

#[cfg(test)]
mod tests {
    use nalgebra::Point3;
    use proptest::prelude::*;

    use super::upper_distance;
    use crate::query::shapes::{distance, intersects};
    use crate::shape::{ConvexHull, Shape};
    use crate::{Ball, Triangle};

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]
        /// A point the `f64` test calls inside a solid hull (bound `0`) is in it exactly, any
        /// other bound of a hull or a triangle is at least the exact distance, and a point
        /// well inside a hull is called inside.
        #[test]
        fn hull_points_proved_inside_are_inside(
            corners in proptest::collection::vec(proptest::array::uniform3(-1.0f64..1.0), 4..16),
            probes in proptest::collection::vec(proptest::array::uniform3(-1.0f64..1.0), 32),
        ) {
            let hull = ConvexHull::new(corners.iter().map(|p| Point3::from(*p)).collect()).unwrap();
            prop_assume!(hull.dimension() == 3);
            let shape = Shape::from(hull.clone());
            let facet = Shape::from(Triangle::new(
                Point3::from(corners[0]), Point3::from(corners[1]), Point3::from(corners[2]),
            ).unwrap());
            for p in probes.iter().map(|p| Point3::from(*p)) {
                let point = Shape::from(Ball::new(p, 0.0).unwrap());
                for target in [&shape, &facet] {
                    let Some(bound) = upper_distance(&p, target) else { continue };
                    if bound == 0.0 {
                        prop_assert!(intersects(&point, target).unwrap(), "{:?}", p);
                    } else {
                        let d = distance(&point, target).unwrap();
                        prop_assert!(d.distance - d.error_bound <= bound, "{:?} {:?} {}", p, d, bound);
                    }
                }
            }
            // The centroid of the corners is strictly inside and proved so.
            let n = hull.corners().len() as f64;
            let centroid = hull.corners().iter().fold(Point3::origin(), |s, c| s + c.coords / n);
            prop_assert_eq!(upper_distance(&centroid, &shape), Some(0.0));
        }
    }
}

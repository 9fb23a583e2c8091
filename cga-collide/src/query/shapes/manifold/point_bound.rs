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
/// not cover (triangles, hulls, cylinders, cones) and for extreme magnitudes.
pub(super) fn upper_distance(p: &Point3<f64>, shape: &Shape) -> Option<f64> {
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
        _ => None,
    }
}

/// The point `a + t (b − a)` nearest `p` (t clamped to `[0, 1]`), minus the radius.
fn segment(p: &P3, a: &P3, b: &P3, radius: f64) -> Option<f64> {
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
fn cuboid(p: &P3, c: &P3, axes: &[P3; 3]) -> Option<f64> {
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

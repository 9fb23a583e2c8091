//! Inner polytopes of cylinders and cones: hulls of `f64` points each checked exactly to lie
//! in the solid, so that the hull is a subset of it.
//!
//! A rim point `c + r·w/|w|` computed in `f64` may round to just outside the solid (the cap
//! plane and the rim are irrational in general); it is then pulled towards a point well inside
//! by factors `1 − 2^-k` until the exact test admits it, or dropped. The cap centres, the apex
//! and the base centre lie in the solid exactly and are always kept, so the set is never empty.

use ga_core::scalar::{Rational, Ring};
use nalgebra::{Point3, Vector3};

use super::body::{q, qv, Body, P3};
use crate::exact::vector::{cross, dot, sub};

fn pt(p: &P3) -> Point3<f64> {
    Point3::new(p[0], p[1], p[2])
}

/// Exactly: does the round body contain `p`? (`true` for polytopal bodies, which are never
/// asked.)
pub(super) fn contains(body: &Body, p: &P3) -> bool {
    let Some((from, to, radius, _)) = axis(body) else {
        return true;
    };
    // With `d` the axis and `x = p − from`: `t = x·d` between `0` and `d·d` (between the caps,
    // or the apex and the base), and the squared distance from the axis `|x × d|²/d·d` within
    // the radius there (`r²`, or `r²·(t/d·d)²` for a cone).
    let (from, d) = (qv(&from), sub(&qv(&to), &qv(&from)));
    let x = sub(&qv(p), &from);
    let (t, dd) = (dot(&x, &d), dot(&d, &d));
    let c = cross(&x, &d);
    let r = q(radius);
    let inside_slab = t >= <Rational as Ring>::zero() && t <= dd;
    inside_slab
        && match body {
            Body::Cone { .. } => dot(&c, &c) * dd <= &r * &r * &t * &t,
            _ => dot(&c, &c) <= &r * &r * dd,
        }
}

/// The axis `(from, to)` of a round body, its radius and a point well inside it.
fn axis(body: &Body) -> Option<(P3, P3, f64, Point3<f64>)> {
    match body {
        Body::Polytopal { .. } => None,
        Body::Cylinder { a, b, radius } => Some((*a, *b, *radius, pt(a) + (pt(b) - pt(a)) * 0.5)),
        Body::Cone { apex, base, radius } => Some((
            *apex,
            *base,
            *radius,
            pt(apex) + (pt(base) - pt(apex)) * 0.75,
        )),
    }
}

/// `p`, or `p` pulled towards `centre` just enough to be admitted exactly; `None` if no pull
/// tried is enough.
fn admit(body: &Body, p: Point3<f64>, centre: &Point3<f64>) -> Option<P3> {
    let as_p3 = |x: Point3<f64>| [x.x, x.y, x.z];
    if contains(body, &as_p3(p)) {
        return Some(as_p3(p));
    }
    for k in [53, 52, 50, 46, 42, 36, 30, 24, 16, 8] {
        let s = 1.0 - 0.5f64.powi(k);
        let x = centre + (p - centre) * s;
        if x.iter().all(|c| c.is_finite()) && contains(body, &as_p3(x)) {
            return Some(as_p3(x));
        }
    }
    None
}

/// The rim points of a round body in the directions `dirs` (each the part of the direction
/// across the axis, scaled to the radius), admitted exactly. For a cylinder both caps, for a
/// cone its base.
pub(super) fn rim_points(body: &Body, dirs: &[Vector3<f64>]) -> Vec<P3> {
    let Some((from, to, r, centre)) = axis(body) else {
        return Vec::new();
    };
    let d = pt(&to) - pt(&from);
    let dd = d.norm_squared();
    let caps: &[P3] = match body {
        Body::Cylinder { a, b, .. } => &[*a, *b],
        _ => &[to],
    };
    let mut out = Vec::new();
    if !(dd > 0.0 && dd.is_finite()) {
        return out;
    }
    for dir in dirs {
        let w = dir - d * (dir.dot(&d) / dd);
        // Rounding noise in a direction is dropped (any point admitted below is valid), so
        // that an axis-aligned direction gives the exact rim point where there is one.
        let len = w.norm();
        let w = w.map(|c| if c.abs() <= 1e-12 * len { 0.0 } else { c });
        let len = w.norm();
        if !(len > 1e-9 * dir.norm() && len.is_finite()) {
            continue;
        }
        let w = w * (r / len);
        for cap in caps {
            if let Some(p) = admit(body, pt(cap) + w, &centre) {
                out.push(p);
            }
        }
    }
    out
}

/// The starting points of a round body: its exact axis points and `count` rim points evenly
/// spread around each cap disc.
pub(super) fn initial(body: &Body, count: usize) -> Vec<P3> {
    let Some((from, to, _, _)) = axis(body) else {
        return Vec::new();
    };
    let d = pt(&to) - pt(&from);
    // A frame across the axis: `d` crossed with its least aligned coordinate axis.
    let k = (0..3)
        .min_by(|&i, &j| d[i].abs().total_cmp(&d[j].abs()))
        .unwrap_or(0);
    let u = d.cross(&Vector3::ith(k, 1.0));
    let u = u / u.norm();
    let w = d.cross(&u);
    let w = w / w.norm();
    let dirs: Vec<Vector3<f64>> = (0..count)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / count as f64;
            u * t.cos() + w * t.sin()
        })
        .collect();
    let mut out = vec![from, to];
    out.extend(rim_points(body, &dirs));
    out
}

/// Rim points around the one extreme along `n`: along `n` and turned from it by `±spread`
/// radians about the axis.
pub(super) fn around(body: &Body, n: &Vector3<f64>, spread: f64) -> Vec<P3> {
    let Some((from, to, _, _)) = axis(body) else {
        return Vec::new();
    };
    let d = pt(&to) - pt(&from);
    let dd = d.norm_squared();
    let across = n - d * (n.dot(&d) / dd);
    let len = across.norm();
    if !(len > 0.0 && len.is_finite()) {
        return Vec::new();
    }
    let u = across / len;
    let t = d.cross(&u);
    let t = t / t.norm();
    let dirs = [
        u,
        u * spread.cos() + t * spread.sin(),
        u * spread.cos() - t * spread.sin(),
    ];
    rim_points(body, &dirs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn admitted_points_are_inside_exactly() {
        let body = Body::Cylinder {
            a: [0.1, 0.2, 0.3],
            b: [0.7, -0.4, 1.9],
            radius: 0.3,
        };
        let pts = initial(&body, 16);
        assert!(pts.len() >= 2 + 2 * 15, "{}", pts.len());
        assert!(pts.iter().all(|p| contains(&body, p)));
        // A point just behind the first cap is not.
        assert!(!contains(
            &body,
            &[0.1 - 0.6e-9, 0.2 + 0.6e-9, 0.3 - 1.6e-9]
        ));
        let cone = Body::Cone {
            apex: [0.0, 0.0, 1.0],
            base: [0.0; 3],
            radius: 0.5,
        };
        assert!(contains(&cone, &[0.5, 0.0, 0.0]));
        assert!(!contains(&cone, &[0.5, 0.0, 1e-300]));
        assert!(contains(&cone, &[0.25, 0.0, 0.5]));
        assert!(!contains(&cone, &[0.25f64.next_up(), 0.0, 0.5]));
    }
}

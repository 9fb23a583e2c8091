//! The point of a simplex (one to four points) nearest the origin in plain `f64`, for the
//! floating-point search's steps only: Ericson's Voronoi-region tests on fixed-size arrays, no
//! allocation and no sub-simplex enumeration. Nothing here is a decision: the search's result
//! is checked by the certificates, then the exact stages ([`super::simplex`] is the exact
//! version, written over any ring). The round shapes' filter runs its search on it too.

use super::cores::P3;

/// Weights over the input points (zero for the points not used), the subset used (bit `i`
/// for point `i`), the nearest point and its squared norm.
#[derive(Clone, Copy, Debug)]
pub(in crate::query::shapes) struct Nearest {
    pub(in crate::query::shapes) weights: [f64; 4],
    pub(in crate::query::shapes) used: u8,
    pub(in crate::query::shapes) point: P3,
    pub(in crate::query::shapes) norm2: f64,
}

#[inline(always)]
fn dot(a: &P3, b: &P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
fn sub(a: &P3, b: &P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline(always)]
fn cross(a: &P3, b: &P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The nearest point given by weights (summing to 1) over the points `idx`.
fn combine(p: &[P3], idx: &[usize], w: &[f64]) -> Nearest {
    let mut weights = [0.0; 4];
    let mut used = 0u8;
    let mut point = [0.0; 3];
    for (&i, &wi) in idx.iter().zip(w) {
        weights[i] = wi;
        used |= 1 << i;
        for k in 0..3 {
            point[k] += wi * p[i][k];
        }
    }
    Nearest {
        weights,
        used,
        point,
        norm2: dot(&point, &point),
    }
}

fn vertex(p: &[P3], i: usize) -> Nearest {
    combine(p, &[i], &[1.0])
}

/// The nearest point of the segment `p[i] p[j]`.
fn segment(p: &[P3], i: usize, j: usize) -> Nearest {
    let e = sub(&p[j], &p[i]);
    let ee = dot(&e, &e);
    let t = -dot(&p[i], &e);
    if t <= 0.0 || ee <= 0.0 || !ee.is_finite() {
        vertex(p, i)
    } else if t >= ee {
        vertex(p, j)
    } else {
        let t = t / ee;
        combine(p, &[i, j], &[1.0 - t, t])
    }
}

fn nearer(x: Nearest, y: Nearest) -> Nearest {
    if y.norm2 < x.norm2 {
        y
    } else {
        x
    }
}

/// The nearest point of the triangle `p[i] p[j] p[k]` (Ericson, Real-Time Collision
/// Detection, 5.1.5, with the query point at the origin).
fn triangle(p: &[P3], i: usize, j: usize, k: usize) -> Nearest {
    let (a, b, c) = (&p[i], &p[j], &p[k]);
    let ab = sub(b, a);
    let ac = sub(c, a);
    let d1 = -dot(&ab, a);
    let d2 = -dot(&ac, a);
    if d1 <= 0.0 && d2 <= 0.0 {
        return vertex(p, i);
    }
    let d3 = -dot(&ab, b);
    let d4 = -dot(&ac, b);
    if d3 >= 0.0 && d4 <= d3 {
        return vertex(p, j);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return segment(p, i, j);
    }
    let d5 = -dot(&ab, c);
    let d6 = -dot(&ac, c);
    if d6 >= 0.0 && d5 <= d6 {
        return vertex(p, k);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return segment(p, i, k);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return segment(p, j, k);
    }
    let total = va + vb + vc;
    if total.is_nan() || total <= 0.0 || !total.is_finite() {
        // A flat or overflowing triangle: its edges hold the nearest point.
        return nearer(nearer(segment(p, i, j), segment(p, i, k)), segment(p, j, k));
    }
    combine(p, &[i, j, k], &[va / total, vb / total, vc / total])
}

/// The nearest point of the tetrahedron `p[0..4]`: the origin when every face has it on the
/// inner side, else the nearest point of the faces it lies outside of.
fn tetrahedron(p: &[P3]) -> Nearest {
    const FACES: [[usize; 4]; 4] = [[0, 1, 2, 3], [0, 1, 3, 2], [0, 2, 3, 1], [1, 2, 3, 0]];
    let mut best: Option<Nearest> = None;
    let mut signs = [0.0; 4];
    for (f, &[i, j, k, opposite]) in FACES.iter().enumerate() {
        let n = cross(&sub(&p[j], &p[i]), &sub(&p[k], &p[i]));
        let origin_side = -dot(&n, &p[i]);
        let other_side = dot(&n, &sub(&p[opposite], &p[i]));
        signs[f] = origin_side;
        // A flat tetrahedron (`other_side` zero) sends every face to the face test.
        let product = origin_side * other_side;
        if product.is_nan() || product <= 0.0 {
            let t = triangle(p, i, j, k);
            best = Some(best.map_or(t, |b| nearer(b, t)));
        }
    }
    if let Some(b) = best {
        return b;
    }
    // Inside: the barycentric weights are the signed volumes with the origin in turn.
    let volume = |f: usize| {
        let [i, j, k, opposite] = FACES[f];
        let n = cross(&sub(&p[j], &p[i]), &sub(&p[k], &p[i]));
        (signs[f], dot(&n, &sub(&p[opposite], &p[i])), opposite)
    };
    let mut weights = [0.0; 4];
    for f in 0..4 {
        let (part, whole, opposite) = volume(f);
        weights[opposite] = part / whole;
    }
    Nearest {
        weights,
        used: 0b1111,
        point: [0.0; 3],
        norm2: 0.0,
    }
}

/// The point of the convex hull of `points` (one to four) nearest the origin, in `f64`.
pub(in crate::query::shapes) fn nearest_to_origin(points: &[P3]) -> Nearest {
    match points.len() {
        0 | 1 => Nearest {
            weights: [1.0, 0.0, 0.0, 0.0],
            used: 1,
            point: points.first().copied().unwrap_or([0.0; 3]),
            norm2: points.first().map_or(0.0, |p| dot(p, p)),
        },
        2 => segment(points, 0, 1),
        3 => triangle(points, 0, 1, 2),
        _ => tetrahedron(&points[..4]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_interior_and_ends() {
        let p = [[-1.0, 1.0, 0.0], [1.0, 1.0, 0.0]];
        let n = nearest_to_origin(&p);
        assert_eq!(n.used, 0b11);
        assert_eq!(n.point, [0.0, 1.0, 0.0]);
        let p = [[1.0, 1.0, 0.0], [2.0, 1.0, 0.0]];
        assert_eq!(nearest_to_origin(&p).used, 0b01);
    }

    #[test]
    fn triangle_face_edge_vertex() {
        let p = [[-1.0, -1.0, 1.0], [2.0, -1.0, 1.0], [-1.0, 2.0, 1.0]];
        let n = nearest_to_origin(&p);
        assert_eq!(n.used, 0b111);
        assert!((n.norm2 - 1.0).abs() < 1e-15);
        let p = [[1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]];
        let n = nearest_to_origin(&p);
        assert_eq!(n.used, 0b011);
        assert_eq!(n.point, [1.0, 0.0, 0.0]);
        let p = [[1.0, 1.0, 0.0], [2.0, 1.0, 0.0], [1.0, 2.0, 0.0]];
        assert_eq!(nearest_to_origin(&p).used, 0b001);
    }

    #[test]
    fn tetrahedron_inside_and_outside() {
        let p = [
            [1.0, 0.0, -1.0],
            [-1.0, 1.0, -1.0],
            [-1.0, -1.0, -1.0],
            [0.0, 0.0, 1.0],
        ];
        let n = nearest_to_origin(&p);
        assert_eq!((n.used, n.norm2), (0b1111, 0.0));
        assert!((n.weights.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        assert!(n.weights.iter().all(|&w| w > 0.0));
        let lifted = p.map(|q| [q[0], q[1], q[2] + 2.0]);
        let n = nearest_to_origin(&lifted);
        assert_eq!(n.used, 0b0111);
        assert!((n.norm2 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn flat_inputs_stay_finite() {
        let p = [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 0.0]];
        let n = nearest_to_origin(&p);
        assert_eq!(n.point, [1.0, 0.0, 0.0]);
        let p = [
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
        ];
        let n = nearest_to_origin(&p);
        assert!(n.norm2.is_finite());
        assert!((n.norm2 - 1.0).abs() < 1e-15);
    }
}

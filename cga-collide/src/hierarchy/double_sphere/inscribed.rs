//! Inner spheres of a convex polyhedron given by its face planes.
//!
//! * [`centroid_sphere`]: the paper's inner sphere, centred at the centroid, radius the
//!   smallest distance from the centroid to a face plane.
//! * [`chebyshev_sphere`]: the largest inscribed sphere (the Chebyshev centre), the linear
//!   programme `max r` subject to `n_f·c + r <= d_f` for every face (unit normals), solved by a
//!   dense simplex method (Bland's rule, so it terminates) on the shifted variables
//!   `c = c0 + y⁺ - y⁻`, `r >= 0`, which start feasible at `y = 0, r = 0` because the start
//!   point `c0` is inside. Its radius is then recomputed from the centre like the centroid one,
//!   and if it came out smaller than the centroid sphere (a numerical failure of the simplex)
//!   the centroid sphere is returned instead, so it is never worse.

use nalgebra::{Point3, Vector3};

/// The smallest slack `d_f - n_f·c` over the planes (unit normals): the radius of the largest
/// ball centred at `c` inside the planes (negative if `c` is outside one).
pub fn depth(planes: &[(Vector3<f64>, f64)], c: &Point3<f64>) -> f64 {
    planes
        .iter()
        .map(|(n, d)| d - n.dot(&c.coords))
        .fold(f64::INFINITY, f64::min)
}

/// The paper's inner sphere: centre `centroid`, radius its depth (clamped at 0).
pub fn centroid_sphere(
    planes: &[(Vector3<f64>, f64)],
    centroid: &Point3<f64>,
) -> (Point3<f64>, f64) {
    (*centroid, depth(planes, centroid).max(0.0))
}

/// The largest ball inside the planes (see the module docs); `start` must be inside.
pub fn chebyshev_sphere(planes: &[(Vector3<f64>, f64)], start: &Point3<f64>) -> (Point3<f64>, f64) {
    let fallback = centroid_sphere(planes, start);
    let Some(y) = simplex_chebyshev(planes, start) else {
        return fallback;
    };
    let c = start + y;
    let r = depth(planes, &c);
    if r > fallback.1 {
        (c, r)
    } else {
        fallback
    }
}

/// Maximises `r` subject to `n_f·y + r <= d_f - n_f·start`, `r >= 0`; returns the optimal `y`.
fn simplex_chebyshev(planes: &[(Vector3<f64>, f64)], start: &Point3<f64>) -> Option<Vector3<f64>> {
    let m = planes.len();
    // Columns: y1+, y1-, y2+, y2-, y3+, y3-, r, slacks (m), rhs.
    let cols = 7 + m + 1;
    let rhs = cols - 1;
    let mut t = vec![0.0f64; (m + 1) * cols];
    let mut basis: Vec<usize> = (0..m).map(|i| 7 + i).collect();
    for (i, (n, d)) in planes.iter().enumerate() {
        let row = &mut t[i * cols..(i + 1) * cols];
        for k in 0..3 {
            row[2 * k] = n[k];
            row[2 * k + 1] = -n[k];
        }
        row[6] = 1.0;
        row[7 + i] = 1.0;
        row[rhs] = (d - n.dot(&start.coords)).max(0.0);
    }
    // Objective row: maximise r  <=>  reduced cost -1 on r.
    t[m * cols + 6] = -1.0;
    let eps = 1e-12;
    for _ in 0..10_000 {
        // Bland: the first column with a negative reduced cost.
        let Some(col) = (0..rhs).find(|&j| t[m * cols + j] < -eps) else {
            let mut y = Vector3::zeros();
            for (i, &b) in basis.iter().enumerate() {
                if b < 6 {
                    let v = t[i * cols + rhs];
                    y[b / 2] += if b % 2 == 0 { v } else { -v };
                }
            }
            return Some(y);
        };
        // Ratio test, ties broken by the smallest basic variable (Bland).
        let mut best: Option<(usize, f64)> = None;
        for i in 0..m {
            let a = t[i * cols + col];
            if a > eps {
                let ratio = t[i * cols + rhs] / a;
                best = match best {
                    None => Some((i, ratio)),
                    Some((bi, br)) => {
                        if ratio < br - 1e-15 || (ratio <= br + 1e-15 && basis[i] < basis[bi]) {
                            Some((i, ratio))
                        } else {
                            Some((bi, br))
                        }
                    }
                };
            }
        }
        let (prow, _) = best?; // unbounded: not a bounded polytope
        let pivot = t[prow * cols + col];
        for j in 0..cols {
            t[prow * cols + j] /= pivot;
        }
        for i in 0..=m {
            if i != prow {
                let f = t[i * cols + col];
                if f != 0.0 {
                    for j in 0..cols {
                        t[i * cols + j] -= f * t[prow * cols + j];
                    }
                }
            }
        }
        basis[prow] = col;
    }
    None
}

/// Brute force for tests: the best centre among all vertices of the LP's feasible region
/// (every 4 planes' solution of `n_f·c + r = d_f` that satisfies all constraints).
#[cfg(any(test, feature = "testing"))]
pub fn chebyshev_brute(planes: &[(Vector3<f64>, f64)]) -> (Point3<f64>, f64) {
    let m = planes.len();
    let mut best = (Point3::origin(), f64::NEG_INFINITY);
    for a in 0..m {
        for b in a + 1..m {
            for c in b + 1..m {
                for d in c + 1..m {
                    let idx = [a, b, c, d];
                    let mat =
                        nalgebra::Matrix4::from_fn(
                            |i, j| {
                                if j < 3 {
                                    planes[idx[i]].0[j]
                                } else {
                                    1.0
                                }
                            },
                        );
                    let rhs = nalgebra::Vector4::from_fn(|i, _| planes[idx[i]].1);
                    if let Some(x) = mat.lu().solve(&rhs) {
                        let p = Point3::new(x[0], x[1], x[2]);
                        let r = depth(planes, &p);
                        if (r - x[3]).abs() < 1e-9 && r > best.1 {
                            best = (p, r);
                        }
                    }
                }
            }
        }
    }
    best
}

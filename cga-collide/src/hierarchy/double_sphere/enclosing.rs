//! The smallest enclosing ball of a finite point set (Welzl's randomised algorithm), computed in
//! `f64` and then made rigorous: the returned radius is the largest distance from the computed
//! centre to an input point, rounded upwards, so the ball provably contains every point
//! whatever the rounding inside Welzl's recursion did. Minimality holds up to that rounding
//! (the tests compare with a brute force over all 2-, 3- and 4-point support sets).

use nalgebra::{Matrix3, Point3, Vector3};

use super::CentreRadius;

/// Relative upward rounding applied to computed distances: `sqrt(dx² + dy² + dz²)` in `f64`
/// errs by less than `4·2^-53` relatively, so multiplying by `1 + 2^-49` (and rounding that
/// product) bounds the exact distance from above.
pub(crate) const DIST_UP: f64 = 1.0 + 1.0 / 562_949_953_421_312.0; // 1 + 2^-49

/// The exact-distance upper bound `|p - c|` rounded up.
#[inline]
pub(crate) fn dist_up(p: &Point3<f64>, c: &Point3<f64>) -> f64 {
    (p - c).norm() * DIST_UP
}

/// The smallest ball through the support points `r` (at most 4) with its centre in their affine
/// hull; affinely dependent points (within a relative tolerance) are dropped.
fn ball_of_support(r: &[Point3<f64>]) -> CentreRadius {
    match r.len() {
        0 => CentreRadius {
            centre: Point3::origin(),
            radius: -1.0,
        },
        1 => CentreRadius {
            centre: r[0],
            radius: 0.0,
        },
        _ => {
            let p0 = r[0];
            // Independent directions, Gram–Schmidt style selection with a tolerance.
            let scale = r.iter().map(|p| (p - p0).norm()).fold(0.0, f64::max);
            let mut dirs: Vec<Vector3<f64>> = Vec::new();
            let mut ortho: Vec<Vector3<f64>> = Vec::new();
            for p in &r[1..] {
                let d = p - p0;
                let mut o = d;
                for q in &ortho {
                    o -= q * q.dot(&o);
                }
                let n = o.norm();
                if n > 1e-10 * scale.max(f64::MIN_POSITIVE) {
                    dirs.push(d);
                    ortho.push(o / n);
                }
            }
            let k = dirs.len();
            // Centre p0 + Σ λ_i d_i with |c - p_i|² = |c - p0|²: 2 (d_i·d_j) λ_j = |d_i|².
            let mut g = Matrix3::<f64>::identity();
            let mut b = Vector3::<f64>::zeros();
            for i in 0..k {
                for j in 0..k {
                    g[(i, j)] = 2.0 * dirs[i].dot(&dirs[j]);
                }
                b[i] = dirs[i].norm_squared();
            }
            let lambda = g.lu().solve(&b).unwrap_or_else(Vector3::zeros);
            let mut c = p0.coords;
            for i in 0..k {
                c += dirs[i] * lambda[i];
            }
            let centre = Point3::from(c);
            let radius = r.iter().map(|p| (p - centre).norm()).fold(0.0, f64::max);
            CentreRadius { centre, radius }
        }
    }
}

fn contains(b: &CentreRadius, p: &Point3<f64>) -> bool {
    b.radius >= 0.0 && (p - b.centre).norm() <= b.radius * (1.0 + 1e-12) + 1e-300
}

fn welzl(points: &[Point3<f64>], n: usize, support: &mut Vec<Point3<f64>>) -> CentreRadius {
    if n == 0 || support.len() == 4 {
        return ball_of_support(support);
    }
    let p = points[n - 1];
    let ball = welzl(points, n - 1, support);
    if contains(&ball, &p) {
        return ball;
    }
    support.push(p);
    let ball = welzl(points, n - 1, support);
    support.pop();
    ball
}

/// The smallest ball containing `points` (Welzl's algorithm in `f64` on a deterministic
/// shuffle; the radius is then recomputed as the largest distance to a point, rounded up, so
/// that containment is guaranteed). An empty input gives the radius `-1` ball at the origin.
pub fn smallest_enclosing_ball(points: &[Point3<f64>]) -> CentreRadius {
    if points.is_empty() {
        return ball_of_support(&[]);
    }
    // Deterministic shuffle (splitmix) so that the expected linear time holds on structured
    // inputs.
    let mut pts = points.to_vec();
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    for i in (1..pts.len()).rev() {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        pts.swap(i, (z % (i as u64 + 1)) as usize);
    }
    let mut support = Vec::with_capacity(4);
    let ball = welzl(&pts, pts.len(), &mut support);
    let centre = ball.centre;
    let radius = points
        .iter()
        .map(|p| dist_up(p, &centre))
        .fold(0.0, f64::max);
    CentreRadius { centre, radius }
}

/// Brute force for tests: the smallest among the balls of all 1- to 4-point support sets that
/// contain every point (within a relative tolerance). `O(n⁵)`: small inputs only.
#[cfg(any(test, feature = "testing"))]
pub fn smallest_enclosing_ball_brute(points: &[Point3<f64>]) -> CentreRadius {
    let n = points.len();
    let mut best = CentreRadius {
        centre: Point3::origin(),
        radius: f64::INFINITY,
    };
    let mut consider = |s: &[Point3<f64>]| {
        let b = ball_of_support(s);
        if b.radius < best.radius
            && points
                .iter()
                .all(|p| (p - b.centre).norm() <= b.radius * (1.0 + 1e-9) + 1e-12)
        {
            best = b;
        }
    };
    for i in 0..n {
        consider(&[points[i]]);
        for j in i + 1..n {
            consider(&[points[i], points[j]]);
            for k in j + 1..n {
                consider(&[points[i], points[j], points[k]]);
                for l in k + 1..n {
                    consider(&[points[i], points[j], points[k], points[l]]);
                }
            }
        }
    }
    best
}

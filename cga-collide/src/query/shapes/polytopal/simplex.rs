//! The point of a simplex (at most four points) nearest the origin, written once over [`Real`]:
//! in `f64` it steers the search, in exact rationals it is the exact answer.
//!
//! Every non-empty subset of the points is tried (Johnson's sub-simplices): the origin is
//! projected on the subset's affine hull by solving its Gram system with Cramer's rule, and
//! the projection counts when it lies in the subset's convex hull (all barycentric weights
//! `>= 0`). The nearest of the counted projections is the answer: every point of the hull
//! lies in the relative interior of a sub-simplex of affinely independent points
//! (Carathéodory), so the nearest point is one of them; dependent subsets (zero Gram
//! determinant) are skipped.

use ga_core::scalar::Real;

/// The result: the subset used (bit `i` for point `i`), the nearest point and its squared
/// norm.
pub(super) struct Nearest<R> {
    pub(super) used: u8,
    pub(super) point: [R; 3],
    pub(super) norm2: R,
}

fn dot<R: Real>(a: &[R; 3], b: &[R; 3]) -> R {
    a[0].clone() * b[0].clone() + a[1].clone() * b[1].clone() + a[2].clone() * b[2].clone()
}

fn det2<R: Real>(a: R, b: R, c: R, d: R) -> R {
    a * d - b * c
}

fn det3<R: Real>(m: &[[R; 3]; 3]) -> R {
    let minor = |r1: usize, r2: usize, c1: usize, c2: usize| {
        det2(
            m[r1][c1].clone(),
            m[r1][c2].clone(),
            m[r2][c1].clone(),
            m[r2][c2].clone(),
        )
    };
    m[0][0].clone() * minor(1, 2, 1, 2) - m[0][1].clone() * minor(1, 2, 0, 2)
        + m[0][2].clone() * minor(1, 2, 0, 1)
}

/// Weights (numerators over the common denominator `det > 0`) of the origin's projection on
/// the affine hull of `p`, or `None` when the points are dependent. `dependent(det, scale)`
/// says when a determinant counts as zero (exactly zero for exact rings, relatively tiny for
/// floats).
fn project<R: Real>(p: &[&[R; 3]], dependent: &dyn Fn(&R, &R) -> bool) -> Option<(Vec<R>, R)> {
    let m = p.len() - 1;
    let zero = R::zero();
    if m == 0 {
        return Some((vec![R::one()], R::one()));
    }
    let e: Vec<[R; 3]> = p[1..]
        .iter()
        .map(|q| core::array::from_fn(|k| q[k].clone() - p[0][k].clone()))
        .collect();
    let g = |i: usize, j: usize| dot(&e[i], &e[j]);
    let b: Vec<R> = e.iter().map(|ei| zero.clone() - dot(ei, p[0])).collect();
    let (det, nums): (R, Vec<R>) = match m {
        1 => (g(0, 0), vec![b[0].clone()]),
        2 => {
            let (g00, g01, g11) = (g(0, 0), g(0, 1), g(1, 1));
            let det = det2(g00.clone(), g01.clone(), g01.clone(), g11.clone());
            let n0 = det2(b[0].clone(), g01.clone(), b[1].clone(), g11);
            let n1 = det2(g00, b[0].clone(), g01, b[1].clone());
            (det, vec![n0, n1])
        }
        _ => {
            let gm: [[R; 3]; 3] = core::array::from_fn(|i| core::array::from_fn(|j| g(i, j)));
            let det = det3(&gm);
            let nums = (0..3)
                .map(|c| {
                    let mut mc = gm.clone();
                    for (r, row) in mc.iter_mut().enumerate() {
                        row[c] = b[r].clone();
                    }
                    det3(&mc)
                })
                .collect();
            (det, nums)
        }
    };
    let diag = (0..m).fold(R::one(), |acc, i| acc * g(i, i));
    if det <= zero || dependent(&det, &diag) {
        return None;
    }
    let mut weights = Vec::with_capacity(m + 1);
    let rest = nums.iter().fold(det.clone(), |acc, n| acc - n.clone());
    weights.push(rest);
    weights.extend(nums);
    Some((weights, det))
}

/// The point of the convex hull of `points` (one to four) nearest the origin. When four
/// independent points hold the origin, the answer is the origin itself (exactly zero).
pub(super) fn nearest_to_origin<R: Real>(
    points: &[[R; 3]],
    dependent: &dyn Fn(&R, &R) -> bool,
) -> Nearest<R> {
    let zero = R::zero();
    let mut best: Option<Nearest<R>> = None;
    for used in 1u8..(1 << points.len()) {
        let idx: Vec<usize> = (0..points.len()).filter(|i| used >> i & 1 == 1).collect();
        let subset: Vec<&[R; 3]> = idx.iter().map(|&i| &points[i]).collect();
        let Some((nums, det)) = project(&subset, dependent) else {
            continue;
        };
        if nums.iter().any(|w| *w < zero) {
            continue;
        }
        let mut weights: [R; 4] = core::array::from_fn(|_| zero.clone());
        for (&i, n) in idx.iter().zip(&nums) {
            weights[i] = n.clone() / det.clone();
        }
        let point: [R; 3] = if idx.len() == 4 {
            core::array::from_fn(|_| zero.clone())
        } else {
            core::array::from_fn(|k| {
                idx.iter().fold(zero.clone(), |acc, &i| {
                    acc + weights[i].clone() * points[i][k].clone()
                })
            })
        };
        let norm2 = dot(&point, &point);
        if best.as_ref().is_none_or(|b| norm2 < b.norm2) {
            best = Some(Nearest { used, point, norm2 });
        }
    }
    // A single point always projects onto itself, so `best` is set; the fallback keeps the
    // function total.
    best.unwrap_or_else(|| Nearest {
        used: 1,
        point: points
            .first()
            .cloned()
            .unwrap_or_else(|| core::array::from_fn(|_| zero.clone())),
        norm2: points.first().map_or(zero.clone(), |p| dot(p, p)),
    })
}

//! A brute-force exact oracle for the tests, independent of the code under test.
//!
//! It shares no predicate with [`crate::query`]: intersection of two convex hulls of
//! points is decided as the feasibility of the linear system `Σ αᵢ aᵢ = Σ βⱼ bⱼ`,
//! `Σ α = Σ β = 1`, `α, β >= 0`, by enumerating every basic solution (every subset of columns,
//! solved by exact rational Gaussian elimination, kept if the columns are independent and the
//! solution non-negative; a feasible system has such a basic solution by Carathéodory).
//! Distances to a hull are minimised by enumerating the projections of the point on the affine
//! hulls of all vertex subsets (normal equations solved exactly) and keeping those that fall
//! inside their face. Everything is `BigRational`; it is slow (tens of microseconds to
//! milliseconds per query) and meant for tests only.

use crate::exact::vector::{dot, sub};
use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::Point3;
use num_traits::Signed;

use crate::shape::{Ball, Segment, Sphere, Triangle};

fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

fn qp(p: &Point3<f64>) -> [Rational; 3] {
    [q(p.x), q(p.y), q(p.z)]
}

/// Solves `m x = rhs` (rows of `m`, `m[r].len()` unknowns) exactly; `Some(x)` iff the system is
/// consistent and its columns are linearly independent (unique solution).
fn solve_unique(mut m: Vec<Vec<Rational>>, mut rhs: Vec<Rational>) -> Option<Vec<Rational>> {
    let rows = m.len();
    let cols = m.first().map_or(0, |r| r.len());
    let mut piv_row = 0;
    let mut pivots = Vec::new();
    for c in 0..cols {
        let Some(r) = (piv_row..rows).find(|&r| !Ring::is_zero(&m[r][c])) else {
            return None; // dependent column
        };
        m.swap(piv_row, r);
        rhs.swap(piv_row, r);
        for r2 in 0..rows {
            if r2 != piv_row && !Ring::is_zero(&m[r2][c]) {
                let f = m[r2][c].clone() / m[piv_row][c].clone();
                let pivot_row = m[piv_row].clone();
                for (dst, v) in m[r2].iter_mut().zip(pivot_row).skip(c) {
                    *dst -= &f * v;
                }
                let v = rhs[piv_row].clone();
                rhs[r2] -= f * v;
            }
        }
        pivots.push(piv_row);
        piv_row += 1;
    }
    // Consistency: the remaining rows must have zero right-hand side.
    if rhs[piv_row..].iter().any(|v| !Ring::is_zero(v)) {
        return None;
    }
    Some(
        (0..cols)
            .map(|c| rhs[pivots[c]].clone() / m[pivots[c]][c].clone())
            .collect(),
    )
}

/// Whether the convex hulls of `a` and `b` (each non-empty) share a point, exactly.
pub fn hulls_intersect(a: &[Point3<f64>], b: &[Point3<f64>]) -> bool {
    // Columns: alpha_i -> (a_i, 1, 0), beta_j -> (-b_j, 0, 1); right-hand side (0, 0, 0, 1, 1).
    let mut columns: Vec<[Rational; 5]> = Vec::new();
    let one = <Rational as Ring>::one();
    let zero = <Rational as Ring>::zero();
    for p in a {
        let [x, y, z] = qp(p);
        columns.push([x, y, z, one.clone(), zero.clone()]);
    }
    for p in b {
        let [x, y, z] = qp(p);
        columns.push([-x, -y, -z, zero.clone(), one.clone()]);
    }
    let n = columns.len();
    let rhs = vec![
        zero.clone(),
        zero.clone(),
        zero.clone(),
        one.clone(),
        one.clone(),
    ];
    for mask in 1u32..(1 << n) {
        let sel: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
        if sel.len() > 5 {
            continue;
        }
        let m: Vec<Vec<Rational>> = (0..5)
            .map(|r| sel.iter().map(|&c| columns[c][r].clone()).collect())
            .collect();
        if let Some(x) = solve_unique(m, rhs.clone()) {
            if x.iter().all(|v| !v.is_negative()) {
                return true;
            }
        }
    }
    false
}

/// Squared distances from `c` to the convex hull of `pts`: (minimum, maximum), exactly.
pub fn hull_distance2(pts: &[Point3<f64>], c: &Point3<f64>) -> (Rational, Rational) {
    let v: Vec<[Rational; 3]> = pts.iter().map(qp).collect();
    rational_hull_distance2(&v, &qp(c))
}

/// [`hull_distance2`] for rational points.
fn rational_hull_distance2(v: &[[Rational; 3]], c: &[Rational; 3]) -> (Rational, Rational) {
    let c = c.clone();
    let max = v
        .iter()
        .map(|p| dot(&sub(p, &c), &sub(p, &c)))
        .max()
        .unwrap_or_else(<Rational as Ring>::zero);
    let mut min: Option<Rational> = None;
    let n = v.len();
    for mask in 1u32..(1 << n) {
        let sel: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
        if sel.len() > 4 {
            continue; // more than 4 points are affinely dependent in 3D
        }
        let s0 = &v[sel[0]];
        let e: Vec<[Rational; 3]> = sel[1..].iter().map(|&i| sub(&v[i], s0)).collect();
        let w = sub(&c, s0);
        let k = e.len();
        let lambda = if k == 0 {
            Some(Vec::new())
        } else {
            let g: Vec<Vec<Rational>> = (0..k)
                .map(|i| (0..k).map(|j| dot(&e[i], &e[j])).collect())
                .collect();
            let h: Vec<Rational> = (0..k).map(|i| dot(&w, &e[i])).collect();
            solve_unique(g, h)
        };
        let Some(lambda) = lambda else { continue };
        let sum: Rational = lambda
            .iter()
            .fold(<Rational as Ring>::zero(), |acc, l| acc + l);
        if lambda.iter().any(|l| l.is_negative()) || sum > <Rational as Ring>::one() {
            continue;
        }
        let mut x = s0.clone();
        for (l, ei) in lambda.iter().zip(&e) {
            for d in 0..3 {
                x[d] += l * &ei[d];
            }
        }
        let d2 = dot(&sub(&x, &c), &sub(&x, &c));
        if min.as_ref().is_none_or(|m| &d2 < m) {
            min = Some(d2);
        }
    }
    (min.unwrap_or_else(<Rational as Ring>::zero), max)
}

/// A shape as the oracle sees it: a convex hull of points, or a ball / sphere.
#[derive(Debug, Clone)]
pub enum Shape {
    /// The convex hull of these points (segment: 2, triangle: 3).
    Hull(Vec<Point3<f64>>),
    /// A solid ball.
    Ball(Point3<f64>, f64),
    /// A spherical surface.
    Sphere(Point3<f64>, f64),
}

impl From<&Segment> for Shape {
    fn from(s: &Segment) -> Shape {
        Shape::Hull(vec![*s.a(), *s.b()])
    }
}
impl From<&Triangle> for Shape {
    fn from(t: &Triangle) -> Shape {
        Shape::Hull(t.vertices().to_vec())
    }
}
impl From<&Ball> for Shape {
    fn from(b: &Ball) -> Shape {
        Shape::Ball(*b.centre(), b.radius())
    }
}
impl From<&Sphere> for Shape {
    fn from(s: &Sphere) -> Shape {
        Shape::Sphere(*s.centre(), s.radius())
    }
}

/// Whether two shapes intersect, exactly (see the module documentation for the method).
pub fn intersects(a: &Shape, b: &Shape) -> bool {
    match (a, b) {
        (Shape::Hull(p), Shape::Hull(r)) => hulls_intersect(p, r),
        (Shape::Hull(p), Shape::Ball(c, r)) | (Shape::Ball(c, r), Shape::Hull(p)) => {
            let r2 = q(*r) * q(*r);
            hull_distance2(p, c).0 <= r2
        }
        (Shape::Hull(p), Shape::Sphere(c, r)) | (Shape::Sphere(c, r), Shape::Hull(p)) => {
            let r2 = q(*r) * q(*r);
            let (min, max) = hull_distance2(p, c);
            min <= r2 && r2 <= max
        }
        (Shape::Ball(c1, r1), Shape::Ball(c2, r2)) => {
            let d = sub(&qp(c1), &qp(c2));
            let s = q(*r1) + q(*r2);
            dot(&d, &d) <= &s * &s
        }
        (Shape::Sphere(c1, r1), Shape::Sphere(c2, r2)) => {
            let d = sub(&qp(c1), &qp(c2));
            let d2 = dot(&d, &d);
            let s = q(*r1) + q(*r2);
            let t = q(*r1) - q(*r2);
            d2 <= &s * &s && d2 >= &t * &t
        }
        // Ball against sphere is not one of the tested pairs; answer it anyway.
        (Shape::Ball(c1, r1), Shape::Sphere(c2, r2))
        | (Shape::Sphere(c2, r2), Shape::Ball(c1, r1)) => {
            // The surface meets the ball iff |c1 - c2| <= r1 + r2 and |c1 - c2| + r1 >= r2.
            let d = sub(&qp(c1), &qp(c2));
            let d2 = dot(&d, &d);
            let s = q(*r1) + q(*r2);
            let far = d2 <= &s * &s;
            let t = q(*r2) - q(*r1);
            far && (t.is_negative() || d2 >= &t * &t)
        }
    }
}

/// The exact squared distance between the convex hulls of `a` and `b` (each non-empty): the
/// squared distance from the origin to the hull of the differences `aᵢ - bⱼ`.
pub fn hulls_distance2(a: &[Point3<f64>], b: &[Point3<f64>]) -> Rational {
    let diffs: Vec<[Rational; 3]> = a
        .iter()
        .flat_map(|p| b.iter().map(move |r| sub(&qp(p), &qp(r))))
        .collect();
    let zero = <Rational as Ring>::zero;
    rational_hull_distance2(&diffs, &[zero(), zero(), zero()]).0
}

/// Whether `dist(a, b) <= c`, exactly (`c` finite and non-negative). Hulls by
/// [`hulls_distance2`]; a ball is within `c` of a set iff the set's nearest point to the centre
/// is within `r + c`; a sphere surface is within `c` of a connected set iff the set's distances
/// from the centre, an interval `[m, M]`, come within `c` of `r`.
pub fn within_distance(a: &Shape, b: &Shape, c: f64) -> bool {
    let c = q(c);
    // `lo <= d` for a non-negative distance `d` with `d² = d2`.
    let at_least = |d2: &Rational, lo: Rational| !lo.is_positive() || d2 >= &(&lo * &lo);
    let at_most = |d2: &Rational, hi: Rational| !hi.is_negative() && d2 <= &(&hi * &hi);
    match (a, b) {
        (Shape::Hull(p), Shape::Hull(r)) => hulls_distance2(p, r) <= &c * &c,
        (Shape::Hull(p), Shape::Ball(o, r)) | (Shape::Ball(o, r), Shape::Hull(p)) => {
            at_most(&hull_distance2(p, o).0, q(*r) + c)
        }
        (Shape::Hull(p), Shape::Sphere(o, r)) | (Shape::Sphere(o, r), Shape::Hull(p)) => {
            let (m, big_m) = hull_distance2(p, o);
            at_most(&m, q(*r) + &c) && at_least(&big_m, q(*r) - c)
        }
        (Shape::Ball(c1, r1), Shape::Ball(c2, r2)) => {
            let d = sub(&qp(c1), &qp(c2));
            at_most(&dot(&d, &d), q(*r1) + q(*r2) + c)
        }
        (Shape::Sphere(c1, r1), Shape::Sphere(c2, r2)) => {
            let d = sub(&qp(c1), &qp(c2));
            let d2 = dot(&d, &d);
            let gap = (q(*r1) - q(*r2)).abs();
            at_most(&d2, q(*r1) + q(*r2) + &c) && at_least(&d2, gap - c)
        }
        (Shape::Ball(c1, r1), Shape::Sphere(c2, r2))
        | (Shape::Sphere(c2, r2), Shape::Ball(c1, r1)) => {
            let d = sub(&qp(c1), &qp(c2));
            let d2 = dot(&d, &d);
            at_most(&d2, q(*r1) + q(*r2) + &c) && at_least(&d2, q(*r2) - q(*r1) - c)
        }
    }
}

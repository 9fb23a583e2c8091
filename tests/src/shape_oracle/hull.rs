//! The exact squared distance between the convex hulls of two finite point sets.
//!
//! Method (independent of the product's): a nearest pair `x ∈ hull(P)`, `y ∈ hull(Q)` can be
//! written with affinely independent supports `S ⊆ P`, `T ⊆ Q`, `|S| + |T| <= 5` (a vertex of
//! the polytope of barycentric weights that realise `x − y = z*`). For such supports the nearest
//! pair of the affine hulls is the unique solution of a small linear system; it is the global
//! answer exactly when its weights are `>= 0` and the optimality conditions hold for every
//! point (`z·p >= z·x` for `p ∈ P`, `z·q <= z·y` for `q ∈ Q`, with `z = x − y`). Every candidate
//! is checked in exact rationals; `f64` only orders the candidates so the right one comes first.

// Small fixed-size linear algebra reads clearest with explicit indices.
#![allow(clippy::needless_range_loop)]

use num_traits::{Signed, Zero};

use super::exact::{dot, sub, P3, Q};

/// The distinct points, in order of first appearance.
pub fn distinct(points: &[P3]) -> Vec<P3> {
    let mut out: Vec<P3> = Vec::new();
    for p in points {
        if !out.contains(p) {
            out.push(p.clone());
        }
    }
    out
}

fn subsets(n: usize, max: usize) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut stack: Vec<Vec<usize>> = (0..n).map(|i| vec![i]).collect();
    while let Some(s) = stack.pop() {
        if s.len() < max {
            for j in s[s.len() - 1] + 1..n {
                let mut t = s.clone();
                t.push(j);
                stack.push(t);
            }
        }
        out.push(s);
    }
    out
}

/// Solves `m x = r` (k <= 3) by Gaussian elimination; `None` when singular.
fn solve_exact(mut m: Vec<Vec<Q>>, mut r: Vec<Q>) -> Option<Vec<Q>> {
    let k = r.len();
    for col in 0..k {
        let pivot = (col..k).find(|&i| !m[i][col].is_zero())?;
        m.swap(col, pivot);
        r.swap(col, pivot);
        for i in 0..k {
            if i != col && !m[i][col].is_zero() {
                let f = &m[i][col] / &m[col][col];
                for j in col..k {
                    let v = &f * &m[col][j];
                    m[i][j] -= v;
                }
                let v = &f * &r[col];
                r[i] -= v;
            }
        }
    }
    Some((0..k).map(|i| &r[i] / &m[i][i]).collect())
}

fn solve_f64(mut m: [[f64; 3]; 3], mut r: [f64; 3], k: usize) -> Option<[f64; 3]> {
    let scale = m
        .iter()
        .take(k)
        .flat_map(|row| row.iter().take(k))
        .fold(0.0f64, |a, b| a.max(b.abs()));
    for col in 0..k {
        let pivot = (col..k).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[pivot][col].abs() <= scale * 1e-12 {
            return None;
        }
        m.swap(col, pivot);
        r.swap(col, pivot);
        for i in 0..k {
            if i != col {
                let f = m[i][col] / m[col][col];
                for j in col..k {
                    m[i][j] -= f * m[col][j];
                }
                r[i] -= f * r[col];
            }
        }
    }
    let mut x = [0.0; 3];
    for i in 0..k {
        x[i] = r[i] / m[i][i];
    }
    Some(x)
}

type F3 = [f64; 3];

fn fsub(a: &F3, b: &F3) -> F3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn fdot(a: &F3, b: &F3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The affine-hull nearest pair of supports `s ⊆ P`, `t ⊆ Q` in f64: (ordering key).
fn candidate_key(p: &[F3], q: &[F3], s: &[usize], t: &[usize]) -> (u8, f64) {
    let w = fsub(&p[s[0]], &q[t[0]]);
    let mut cols: Vec<F3> = s[1..].iter().map(|&i| fsub(&p[i], &p[s[0]])).collect();
    cols.extend(t[1..].iter().map(|&j| fsub(&q[t[0]], &q[j])));
    let k = cols.len();
    let mut m = [[0.0; 3]; 3];
    let mut r = [0.0; 3];
    for i in 0..k {
        for j in 0..k {
            m[i][j] = fdot(&cols[i], &cols[j]);
        }
        r[i] = -fdot(&cols[i], &w);
    }
    let Some(c) = solve_f64(m, r, k) else {
        return (2, 0.0);
    };
    let mut z = w;
    for (i, col) in cols.iter().enumerate() {
        for d in 0..3 {
            z[d] += c[i] * col[d];
        }
    }
    let a = s.len() - 1;
    let tol = 1e-9;
    let lam0 = 1.0 - c[..a].iter().sum::<f64>();
    let mu0 = 1.0 - c[a..k].iter().sum::<f64>();
    let feasible = lam0 >= -tol && mu0 >= -tol && c[..k].iter().all(|x| *x >= -tol);
    (if feasible { 0 } else { 1 }, fdot(&z, &z))
}

/// The exact check of one support pair: `Some(|z|²)` when it gives the global nearest pair.
fn check_exact(p: &[P3], q: &[P3], s: &[usize], t: &[usize]) -> Option<Q> {
    let w = sub(&p[s[0]], &q[t[0]]);
    let mut cols: Vec<P3> = s[1..].iter().map(|&i| sub(&p[i], &p[s[0]])).collect();
    cols.extend(t[1..].iter().map(|&j| sub(&q[t[0]], &q[j])));
    let k = cols.len();
    let m: Vec<Vec<Q>> = (0..k)
        .map(|i| (0..k).map(|j| dot(&cols[i], &cols[j])).collect())
        .collect();
    let r: Vec<Q> = (0..k).map(|i| -dot(&cols[i], &w)).collect();
    let c = solve_exact(m, r)?;
    let a = s.len() - 1;
    let one = Q::from_integer(1.into());
    let lam0 = &one - c[..a].iter().fold(Q::zero(), |acc, x| acc + x);
    let mu0 = &one - c[a..].iter().fold(Q::zero(), |acc, x| acc + x);
    if lam0.is_negative() || mu0.is_negative() || c.iter().any(Signed::is_negative) {
        return None;
    }
    let mut z = w;
    for (ci, col) in c.iter().zip(&cols) {
        for d in 0..3 {
            z[d] += ci * &col[d];
        }
    }
    if !z.iter().all(Zero::is_zero) {
        // x = s0 + Σ λi (si − s0); y = x − z.
        let mut x = p[s[0]].clone();
        for (ci, &i) in c[..a].iter().zip(&s[1..]) {
            let e = sub(&p[i], &p[s[0]]);
            for d in 0..3 {
                x[d] += ci * &e[d];
            }
        }
        let y = sub(&x, &z);
        let zx = dot(&z, &x);
        let zy = dot(&z, &y);
        if p.iter().any(|pi| dot(&z, pi) < zx) || q.iter().any(|qj| dot(&z, qj) > zy) {
            return None;
        }
    }
    Some(dot(&z, &z))
}

fn approx(points: &[P3], shift: i32) -> Vec<F3> {
    use num_traits::ToPrimitive;
    let two = Q::from_integer(2.into());
    let factor = if shift >= 0 {
        num_traits::pow(two, shift as usize)
    } else {
        num_traits::pow(two, (-shift) as usize).recip()
    };
    points
        .iter()
        .map(|p| {
            let c = |x: &Q| (x * &factor).to_f64().unwrap_or(0.0);
            [c(&p[0]), c(&p[1]), c(&p[2])]
        })
        .collect()
}

/// The binary exponent that brings the largest coordinate near 1 (for the f64 ordering only).
fn normalising_shift(points: &[P3]) -> i32 {
    use num_traits::ToPrimitive;
    let mut best: Option<i64> = None;
    for p in points {
        for x in p {
            if x.is_zero() {
                continue;
            }
            let e = x.numer().bits() as i64 - x.denom().bits() as i64;
            best = Some(best.map_or(e, |b| b.max(e)));
        }
    }
    (-best.unwrap_or(0)).to_i32().unwrap_or(0)
}

/// The exact squared distance between `hull(p)` and `hull(q)` (both non-empty).
pub fn distance2(p: &[P3], q: &[P3]) -> Q {
    let p = distinct(p);
    let q = distinct(q);
    let mut all = p.clone();
    all.extend(q.iter().cloned());
    let shift = normalising_shift(&all);
    let (pf, qf) = (approx(&p, shift), approx(&q, shift));
    let sp = subsets(p.len(), 4);
    let sq = subsets(q.len(), 4);
    let mut candidates: Vec<((u8, f64), usize, usize)> = Vec::new();
    for (i, s) in sp.iter().enumerate() {
        for (j, t) in sq.iter().enumerate() {
            if s.len() + t.len() <= 5 {
                candidates.push((candidate_key(&pf, &qf, s, t), i, j));
            }
        }
    }
    candidates.sort_by(|a, b| a.0 .0.cmp(&b.0 .0).then(a.0 .1.total_cmp(&b.0 .1)));
    for (_, i, j) in candidates {
        if let Some(d2) = check_exact(&p, &q, &sp[i], &sq[j]) {
            return d2;
        }
    }
    unreachable!("some support pair always certifies the nearest pair")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape_oracle::exact::int;

    fn pt(x: i64, y: i64, z: i64) -> P3 {
        [int(x), int(y), int(z)]
    }

    #[test]
    fn simple_distances() {
        let cube: Vec<P3> = (0..8)
            .map(|m| pt(m & 1, (m >> 1) & 1, (m >> 2) & 1))
            .collect();
        // A point above the top face, over the face's interior: distance 2.
        let d = distance2(&cube, &[pt(0, 0, 3), pt(1, 1, 3)]);
        assert_eq!(d, int(4));
        // Edge against edge, crossed: (x = 2, z = 2) line along y vs top-right edge.
        let d = distance2(&cube, &[pt(2, -5, 2), pt(2, 5, 2)]);
        assert_eq!(d, int(2));
        // A segment through the cube: 0.
        let d = distance2(&cube, &[pt(-1, 0, 0), pt(2, 1, 1)]);
        assert_eq!(d, int(0));
        // A tetrahedron swallowing the cube's corner.
        let d = distance2(&cube, &[pt(1, 1, 1)]);
        assert_eq!(d, int(0));
        // Parallel faces one apart.
        let shifted: Vec<P3> = cube
            .iter()
            .map(|p| [p[0].clone() + int(2), p[1].clone(), p[2].clone()])
            .collect();
        assert_eq!(distance2(&cube, &shifted), int(1));
    }
}

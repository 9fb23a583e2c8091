//! A small exact-friendly linear solver, used for the general (non-versor) inverse.

use crate::scalar::Field;

/// Solves `M x = e_k` where column `j` of `M` is `columns[j]` and `e_k` is the `k`-th unit
/// vector. Gaussian elimination with partial pivoting by [`Field::pivot_score`] (largest
/// magnitude for floats, any nonzero entry for exact types). `None` when `M` is singular (for
/// floats: when a pivot is exactly zero).
pub fn solve_columns<T: Field, C: AsRef<[T]>>(columns: &[C], k: usize) -> Option<Vec<T>> {
    let n = columns.len();
    // Row-major augmented matrix [M | e_k].
    let mut m: Vec<Vec<T>> = (0..n)
        .map(|i| {
            let mut row: Vec<T> = columns.iter().map(|c| c.as_ref()[i].clone()).collect();
            row.push(if i == k { T::one() } else { T::zero() });
            row
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&a, &b| m[a][col].pivot_score().total_cmp(&m[b][col].pivot_score()))?;
        if m[pivot][col].is_zero() {
            return None;
        }
        m.swap(col, pivot);
        let inv = m[col][col].checked_recip()?;
        for entry in m[col].iter_mut().skip(col) {
            *entry = entry.clone() * inv.clone();
        }
        let pivot_row = m[col].clone();
        for (r, row) in m.iter_mut().enumerate() {
            if r == col || row[col].is_zero() {
                continue;
            }
            let factor = row[col].clone();
            for (entry, p) in row.iter_mut().zip(&pivot_row).skip(col) {
                *entry = entry.clone() - factor.clone() * p.clone();
            }
        }
    }
    Some(
        m.into_iter()
            .map(|mut row| row.pop().unwrap_or_else(T::zero))
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Rational;

    #[test]
    fn solves_a_small_exact_system() {
        // M = [[2, 1], [1, 1]] (columns [2,1] and [1,1]); M x = e0 gives x = [1, -1].
        let r = |n: i64| Rational::from_integer(n.into());
        let cols = vec![vec![r(2), r(1)], vec![r(1), r(1)]];
        assert_eq!(solve_columns(&cols, 0).unwrap(), vec![r(1), r(-1)]);
        let singular = vec![vec![r(1), r(1)], vec![r(2), r(2)]];
        assert!(solve_columns(&singular, 0).is_none());
    }
}

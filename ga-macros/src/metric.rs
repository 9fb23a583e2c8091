//! Blade products for a general symmetric bilinear form (the `metric` key): the basis vectors
//! need not be orthogonal, e.g. the conformal null pair `n0 · n∞ = -1`. Blades are outer
//! products of basis vectors in ascending order, so a blade is still a bitmask, but the
//! geometric product of two blades is a sum of blades with integer coefficients.

use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};

use crate::blade::{self, Blade};

/// A sum of blades with integer coefficients, sorted by blade mask.
pub type Terms = Vec<(i32, Blade)>;

/// The bilinear form `B(e_i, e_j) = matrix[i][j]` (symmetric, integer entries) and a memo of
/// the blade products computed so far.
pub struct Form {
    matrix: Vec<Vec<i32>>,
    memo: RefCell<HashMap<(Blade, Blade), Terms>>,
}

impl Form {
    pub fn new(matrix: Vec<Vec<i32>>) -> Self {
        Form {
            matrix,
            memo: RefCell::new(HashMap::new()),
        }
    }

    /// `e_i ⌋ e_c = Σ_k (-1)^k B(e_i, e_{j_k}) e_{c \ j_k}` over the ascending factors `j_k`.
    fn contract(&self, i: usize, c: Blade) -> Terms {
        blade::indices(c)
            .into_iter()
            .enumerate()
            .filter_map(|(k, j)| {
                let m = self.matrix[i][j];
                let sign = if k.is_multiple_of(2) { 1 } else { -1 };
                (m != 0).then_some((sign * m, c & !(1 << j)))
            })
            .collect()
    }

    /// `e_i e_c = e_i ⌋ e_c + e_i ∧ e_c`.
    fn vector_times(&self, i: usize, c: Blade) -> Terms {
        let mut out = self.contract(i, c);
        if c & (1 << i) == 0 {
            let below = (c & ((1 << i) - 1)).count_ones();
            out.push((if below.is_multiple_of(2) { 1 } else { -1 }, c | (1 << i)));
        }
        out
    }

    /// The geometric product `e_a e_b`: with `i` the lowest factor of `a` and `r` the rest,
    /// `e_a = e_i ∧ e_r = e_i e_r - e_i ⌋ e_r`, so `e_a e_b = e_i (e_r e_b) - (e_i ⌋ e_r) e_b`.
    pub fn geometric(&self, a: Blade, b: Blade) -> Terms {
        if a == 0 {
            return vec![(1, b)];
        }
        if let Some(t) = self.memo.borrow().get(&(a, b)) {
            return t.clone();
        }
        let i = a.trailing_zeros() as usize;
        let rest = a & !(1 << i);
        let mut acc: BTreeMap<Blade, i32> = BTreeMap::new();
        for (c, p) in self.geometric(rest, b) {
            for (c2, q) in self.vector_times(i, p) {
                *acc.entry(q).or_default() += c * c2;
            }
        }
        for (c, r) in self.contract(i, rest) {
            for (c2, q) in self.geometric(r, b) {
                *acc.entry(q).or_default() -= c * c2;
            }
        }
        let out: Terms = acc
            .into_iter()
            .filter(|&(_, c)| c != 0)
            .map(|(b, c)| (c, b))
            .collect();
        self.memo.borrow_mut().insert((a, b), out.clone());
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn diagonal(sig: &[i32]) -> Form {
        let n = sig.len();
        Form::new(
            (0..n)
                .map(|i| (0..n).map(|j| if i == j { sig[i] } else { 0 }).collect())
                .collect(),
        )
    }

    #[test]
    fn diagonal_form_matches_the_bitmask_product() {
        let sig = [1, 1, 1, 1, -1];
        let form = diagonal(&sig);
        for a in 0..32 {
            for b in 0..32 {
                let (s, out) = blade::geometric(a, b, &sig);
                assert_eq!(form.geometric(a, b), vec![(s, out)], "e{a:b} e{b:b}");
            }
        }
    }

    #[test]
    fn null_pair_products() {
        // e1, n0, ni with n0·ni = -1.
        let form = Form::new(vec![vec![1, 0, 0], vec![0, 0, -1], vec![0, -1, 0]]);
        let (n0, ni) = (0b010, 0b100);
        assert_eq!(form.geometric(n0, n0), vec![]);
        // n0 ni = n0·ni + n0∧ni = -1 + n0∧ni
        assert_eq!(form.geometric(n0, ni), vec![(-1, 0), (1, n0 | ni)]);
        // ni n0 = -1 - n0∧ni
        assert_eq!(form.geometric(ni, n0), vec![(-1, 0), (-1, n0 | ni)]);
        // (n0∧ni)² = 1
        assert_eq!(form.geometric(n0 | ni, n0 | ni), vec![(1, 0)]);
        // n0 (n0∧ni) = (n0·n0) ni - (n0·ni) n0 = n0
        assert_eq!(form.geometric(n0, n0 | ni), vec![(1, n0)]);
    }
}

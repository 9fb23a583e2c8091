//! The small blade algebra the macro uses at expansion time: blades as bitmasks (bit `i` is
//! generator `i`), the reordering sign, metric products, complements and canonical order.

/// A basis blade: bit `i` set means generator `i` is a factor (factors in ascending order).
pub type Blade = u32;

/// The grade of a blade.
pub fn grade(b: Blade) -> usize {
    b.count_ones() as usize
}

/// The generator indices of a blade, ascending.
pub fn indices(b: Blade) -> Vec<usize> {
    (0..32).filter(|i| b & (1 << i) != 0).collect()
}

/// `+1` or `-1`: the sign of the permutation that sorts `e_a e_b` (both ascending) into `e_{a^b}`
/// order, ignoring the metric. Counts, for every factor of `b`, the factors of `a` above it.
pub fn reorder_sign(a: Blade, b: Blade) -> i32 {
    let mut swaps = 0;
    let mut a = a >> 1;
    while a != 0 {
        swaps += (a & b).count_ones();
        a >>= 1;
    }
    if swaps % 2 == 0 {
        1
    } else {
        -1
    }
}

/// The geometric product of two basis blades: `(sign, blade)`, sign 0 when a null generator
/// is squared.
pub fn geometric(a: Blade, b: Blade, signature: &[i32]) -> (i32, Blade) {
    let mut sign = reorder_sign(a, b);
    for (i, &m) in signature.iter().enumerate() {
        if (a & b) & (1 << i) != 0 {
            sign *= m;
        }
    }
    (sign, a ^ b)
}

/// All blades of an `n`-generator algebra in canonical order: by grade, then lexicographic on
/// the ascending index lists.
pub fn canonical_order(n: usize) -> Vec<Blade> {
    let mut blades: Vec<Blade> = (0..(1u32 << n)).collect();
    blades.sort_by_key(|&b| (grade(b), indices(b)));
    blades
}

/// The sign change of reversion for a blade of grade `k`: `(-1)^(k(k-1)/2)`.
pub fn reverse_sign(b: Blade) -> i32 {
    let k = grade(b);
    if (k * k.saturating_sub(1) / 2).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// The sign change of the grade involution: `(-1)^k`.
pub fn involution_sign(b: Blade) -> i32 {
    if grade(b).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// The sign change of Clifford conjugation: `(-1)^(k(k+1)/2)`.
pub fn conjugate_sign(b: Blade) -> i32 {
    reverse_sign(b) * involution_sign(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn canonical_order_of_five() {
        let names: Vec<String> = canonical_order(5)
            .into_iter()
            .map(|b| indices(b).iter().map(|i| (i + 1).to_string()).collect())
            .collect();
        assert_eq!(
            names.join(" "),
            " 1 2 3 4 5 12 13 14 15 23 24 25 34 35 45 123 124 125 134 135 145 234 235 245 345 \
             1234 1235 1245 1345 2345 12345"
        );
    }

    #[test]
    fn anticommuting_vectors() {
        let sig = [1, 1, 1, 1, -1];
        assert_eq!(geometric(0b01, 0b10, &sig), (1, 0b11));
        assert_eq!(geometric(0b10, 0b01, &sig), (-1, 0b11));
        assert_eq!(geometric(0b10000, 0b10000, &sig), (-1, 0));
        // e12 e12 = -1
        assert_eq!(geometric(0b11, 0b11, &sig), (-1, 0));
        // I^2 = -1 in Cl(4,1)
        assert_eq!(geometric(0b11111, 0b11111, &sig), (-1, 0));
    }
}

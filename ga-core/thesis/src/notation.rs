//! The thesis's notation for Cl(4,1): blade names, signs and print order.
//!
//! The thesis (Cap. II, Apéndice A) writes the conformal basis as `e1, e2, e3, e, ē` with
//! `e = e4`, `ē = e5`, `n = e + ē` (our `n_inf`), `n̄ = e − ē` (so our `n_0 = −n̄/2`), a point
//! as `X = 2x + x²n − n̄` (= `2·up(x)`), the pseudoscalar `I = e1e2e3eē` (= our `e12345`) and
//! the dual `A* = IA` (= `−A I⁻¹`, the negative of our `dual`, since `I` is central and
//! `I² = −1`). Bivectors are written `e1e2, e2e3, e3e1` (cyclic), and the conformal vectors
//! come last: `e3e1ē = −e135`.
//!
//! This module names blades both ways and fixes the thesis's print order; printing a
//! multivector in either notation builds on it.

use ga_core::reference::{blade_name, canonical_order, reorder_sign};

/// The 32 blade bitmasks (`e1` = bit 0 … `e5` = bit 4) in canonical order: by grade, then
/// lexicographic on indices (`1, e1, …, e5, e12, e13, …, e12345`).
pub fn canonical_masks() -> [u8; 32] {
    let mut out = [0u8; 32];
    for (o, m) in out.iter_mut().zip(canonical_order(5)) {
        *o = u8::try_from(m).unwrap_or_else(|_| unreachable!("5-bit masks"));
    }
    out
}

/// Canonical name of a blade (`1`, `e1`, `e135`, `e12345`).
pub fn canonical_name(mask: u8) -> String {
    blade_name(usize::from(mask), &["e1", "e2", "e3", "e4", "e5"])
}

/// The thesis's spelling of a blade and the sign relating it to ours:
/// `blade(mask) = sign · (thesis blade)`. Euclidean part `e1, e2, e3, e1e2, e2e3, e3e1,
/// e1e2e3`, then `e`, then `ē`; the scalar is `1`.
pub fn thesis_name(mask: u8) -> (i32, String) {
    let euclid = mask & 0b111;
    let seq: Vec<u8> = match euclid {
        0 => vec![],
        0b001 => vec![0],
        0b010 => vec![1],
        0b100 => vec![2],
        0b011 => vec![0, 1],
        0b110 => vec![1, 2],
        0b101 => vec![2, 0],
        _ => vec![0, 1, 2],
    };
    let mut seq = seq;
    if mask & 0b01000 != 0 {
        seq.push(3);
    }
    if mask & 0b10000 != 0 {
        seq.push(4);
    }
    if seq.is_empty() {
        return (1, "1".into());
    }
    let names = ["e1", "e2", "e3", "e", "ē"];
    let name: String = seq.iter().map(|&i| names[i as usize]).collect();
    // Product of the sequence = sign · blade(mask); the sign is its own inverse.
    let mut acc = 0u8;
    let mut sign = 1;
    for &i in &seq {
        sign *= i32::from(reorder_sign(usize::from(acc), 1 << i));
        acc |= 1 << i;
    }
    (sign, name)
}

/// Order in which [`Notation::Thesis`] prints blades: by grade, Euclidean part first.
pub(crate) fn thesis_order() -> Vec<u8> {
    let mut masks: Vec<u8> = (0u8..32).collect();
    let euclid_rank = |m: u8| match m & 0b111 {
        0 => 0,
        0b001 => 1,
        0b010 => 2,
        0b100 => 3,
        0b011 => 4,
        0b110 => 5,
        0b101 => 6,
        _ => 7,
    };
    masks.sort_by_key(|&m| (m.count_ones(), m >> 3, euclid_rank(m)));
    masks
}

/// How blades are spelled when printing a multivector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notation {
    /// Our canonical names (`e135`) and signs, canonical blade order.
    Canonical,
    /// The thesis's names (`e3e1ē`) and signs, in its usual order.
    Thesis,
    /// The thesis's null basis: Euclidean blades times `1`, `n`, `n̄` or `n∧n̄` (using
    /// `e = (n + n̄)/2`, `ē = (n − n̄)/2`, `eē = −½ n∧n̄`), so that the point `2·up(x)` prints as
    /// the thesis's `2x + x²n − n̄`.
    ThesisNull,
}

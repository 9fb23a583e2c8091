//! A symbolic derivation with `Poly`: expand the conformal inner product of two points and
//! check that `up(a) · up(b) = -½ |a - b|²` as a polynomial identity.
//!
//! Run: `cargo run -p ga-core --example symbolic_derivation`.

use ga_core::cga;
use ga_core::prelude::*;
use ga_core::symbolic::Poly;

pub fn main() {
    // One variable per coordinate.
    let a = ["a1", "a2", "a3"].map(Poly::var);
    let b = ["b1", "b2", "b3"].map(Poly::var);
    // up(x) = x + ½|x|² n_inf + n_0 with n_inf = e4 + e5 and n_0 = (e5 − e4)/2, written out
    // over polynomials (a ring: no division needed besides the constant ½).
    let half = Poly::ratio(1, 2).expect("2 is not zero");
    let up = |x: &[Poly; 3]| {
        let h = &half * &(x[0].pow(2) + x[1].pow(2) + x[2].pow(2));
        cga::Vector::new(
            x[0].clone(),
            x[1].clone(),
            x[2].clone(),
            &h - &half,
            &h + &half,
        )
    };
    // The generated products work on any ring: here, exact multivariate polynomials.
    let (up_a, up_b) = (up(&a), up(&b));
    let inner = up_a.scalar_product(&up_b);
    println!("up(a)·up(b) = {}", inner.to_plain());

    // -½ |a - b|², built by hand.
    let minus_half = -&half;
    let d2 = (0..3)
        .map(|i| (&a[i] - &b[i]).pow(2))
        .fold(Poly::from(0), |s, t| s + t);
    let expected = &minus_half * &d2;
    assert_eq!(inner, expected, "the identity holds for every a, b");
    println!("= -1/2 |a - b|²  (LaTeX: {})", expected.to_latex());

    // Substitute numbers to check one case exactly.
    let at = inner.eval_f64(&[
        ("a1", 1.0),
        ("a2", 2.0),
        ("a3", 3.0),
        ("b1", 4.0),
        ("b2", 6.0),
        ("b3", 3.0),
    ]);
    assert_eq!(at.expect("every variable has a value"), -12.5);
}

//! Declaring your own algebra with `algebra!` and using it: 2D projective geometric algebra
//! Cl(2,0,1), where points are bivectors and the rotor `exp(-θ/2 e12)` rotates the plane.
//!
//! Run: `cargo run -p ga-core --example declare_algebra`.

use ga_core::prelude::*;

/// The generated module: one struct per declared type, every product as straight-line code.
mod pga2 {
    ga_macros::algebra! {
        name: pga2,
        signature: [0, +1, +1],          // e1² = 0 (the ideal line), e2² = e3² = +1
        types: {
            /// A line `a e1 + b e2 + c e3` (the line `b x + c y + a = 0`).
            Line: grade 1,
            /// A point: `x e31 + y e12 + w e23`-style bivector.
            Point: grade 2,
            /// Rotations and translations.
            Motor: grades 0 2,
        },
        dense: Multivector,
    }
}

pub fn main() {
    use pga2::{Line, Motor};

    // Two lines: x = 1 (e2 + (-1) e1) and y = 2 (e3 + (-2) e1).
    let x1 = Line::new(-1.0, 1.0, 0.0);
    let y2 = Line::new(-2.0, 0.0, 1.0);
    // Their meet (outer product) is the point where they cross: a `Point` (grade 2),
    // inferred by the macro from the nonzero terms.
    let p = x1 ^ y2;
    println!("x = 1 meets y = 2 at {p}");

    // A rotor by 90° about the origin, applied with the sandwich product.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let r = Motor::new(h, 0.0, 0.0, h); // cos 45° + sin 45° e23
    let q = r.sandwich_unit(&p);
    println!("rotated by 90°: {q}");
    assert!((q.norm_squared() - p.norm_squared()).abs() < 1e-12);

    // The same code runs on exact rationals: any scalar implementing the ring traits.
    let r = |n: i64| ga_core::scalar::Rational::from_i64(n);
    let exact = Line::new(r(-1), r(1), r(0));
    println!(
        "exact line: {exact}, names of the blades: {:?}",
        pga2::BLADE_NAMES
    );
}

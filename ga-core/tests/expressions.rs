//! Expression-level generation (`functions` / `cga_null_expressions!`): each fused function
//! equals the product-by-product evaluation of the same expression, in `f64` (to rounding) and
//! exactly over `Rational`.

use ga_core::cga_null::{self, Line, Motor, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use proptest::prelude::*;

ga_core::cga_null_expressions! {
    /// `M X M̃` for a versor `M`, projected by the versor rule on grade 1.
    fn apply(#[versor] m: Motor, x: Vector) -> Vector { m * x * m.reverse() }
    /// The same with the generated method (projection on `Vector`'s blades).
    fn apply_method(m: Motor, x: Vector) -> Vector { m.sandwich_unit(&x) }
    /// Composition of motors.
    fn compose(a: Motor, b: Motor) -> Motor { a * b }
    /// The conformal point of a Euclidean one.
    fn up(x: T, y: T, z: T) -> Vector {
        x * e1() + y * e2() + z * e3() + eo() + (x * x + y * y + z * z) / 2 * ei()
    }
    /// ga-benchmark's 4th-order exponential series of a line.
    fn expp(x: Line) -> Motor {
        let x2 = x * x;
        let x3 = x2 * x;
        1 + x + x2 / 2 + x3 / 6 + x3 * x / 24
    }
    /// The same series for an argument declared a blade (`x x` is a scalar).
    fn expp_blade(#[blade] x: Line) -> Motor {
        let x2 = x * x;
        let x3 = x2 * x;
        1 + x + x2 / 2 + x3 / 6 + x3 * x / 24
    }
    /// A chain step: the joint motor about a line and the line it moves.
    fn step(#[versor] m: Motor, l: Line, next: Line, angle: T) -> (Motor, Line) {
        let r = expp(l * (angle / 2));
        (r * m, (r * m).sandwich_unit(&next))
    }
    /// The example of docs/generator.md.
    fn doc_step(#[versor] m: Motor, angle: T) -> (Motor, Line) {
        let r = expp_blade(!(eo() ^ e3() ^ ei()) * (angle / 2));
        let axis: Line = e12() + 114.2 * e1() * ei(); // checked: fits `Line`
        (r * m, (r * m).sandwich_unit(&axis))
    }
    /// Folded constants: the dual line through two constant points.
    fn z_axis() -> Line { !(up(0, 0, 0) ^ up(0, 0, 1) ^ ei()) }
    fn translate_x(t: T) -> Motor { 1 - t / 2 * e1() * ei() }
}

fn motor_of(c: [i64; 8]) -> Motor<f64> {
    Motor::from_coefficients(c.map(|x| x as f64 / 8.0))
}

/// A versor: the product of a rotor and a translator (exact over `Rational`).
fn versor<T: Field>(r: [T; 4], t: [T; 3]) -> Motor<T> {
    Motor::from(Rotor::from_coefficients(r)) * Motor::translator(t)
}

fn q(n: i64) -> Rational {
    Rational::new(n.into(), 16.into())
}

fn close(a: &[f64], b: &[f64]) -> bool {
    let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * scale)
}

proptest! {
    #[test]
    fn fused_sandwich_equals_products_exactly(
        r in proptest::array::uniform4(-16i64..16),
        t in proptest::array::uniform3(-16i64..16),
        x in proptest::array::uniform3(-16i64..16),
    ) {
        let m = versor(r.map(q), t.map(q));
        let p = cga_null::up_generic(q(x[0]), q(x[1]), q(x[2]));
        let full = m.clone() * p.clone() * m.reverse();
        let by_products = Vector::from_multivector(&full.into());
        prop_assert_eq!(apply(&m, &p), by_products);
        prop_assert_eq!(apply_method(&m, &p), m.sandwich_unit(&p));
        prop_assert_eq!(up(q(x[0]), q(x[1]), q(x[2])), p);
    }

    #[test]
    fn fused_composition_and_series_equal_products(
        a in proptest::array::uniform8(-16i64..16),
        b in proptest::array::uniform8(-16i64..16),
        l in proptest::array::uniform6(-16i64..16),
        n in proptest::array::uniform6(-16i64..16),
        angle in -16i64..16,
    ) {
        let (ma, mb) = (Motor::from_coefficients(a.map(q)), Motor::from_coefficients(b.map(q)));
        prop_assert_eq!(compose(&ma, &mb), ma.clone() * mb.clone());
        let line = Line::from_coefficients(l.map(q));
        let x2: Motor<Rational> = line.clone() * line.clone();
        let x3: Motor<Rational> = x2.clone() * line.clone();
        let x4: Motor<Rational> = x3.clone() * line.clone();
        let mut one = Motor::zero();
        one.s = q(16);
        let series = one + Motor::from(line.clone()) + x2.scale(&q(8)) + x3.scale(&Rational::new(1.into(), 6.into())) + x4.scale(&Rational::new(1.into(), 24.into()));
        prop_assert_eq!(expp(&line), series.clone());
        // A true line (a blade): the dual of `P ∧ Q ∧ ei`.
        let (p1, p2) = (cga_null::up_generic(q(l[0]), q(l[1]), q(l[2])), cga_null::up_generic(q(l[3]), q(l[4]), q(l[5])));
        let blade = Line::from_multivector(&(!(p1 ^ p2 ^ cga_null::ei())).into());
        let b2: Motor<Rational> = blade.clone() * blade.clone();
        let b3: Motor<Rational> = b2.clone() * blade.clone();
        let b4: Motor<Rational> = b3.clone() * blade.clone();
        let mut one = Motor::zero();
        one.s = q(16);
        let blade_series = one + Motor::from(blade.clone()) + b2.scale(&q(8)) + b3.scale(&Rational::new(1.into(), 6.into())) + b4.scale(&Rational::new(1.into(), 24.into()));
        prop_assert_eq!(expp_blade(&blade), blade_series);
        let next = Line::from_coefficients(n.map(q));
        let half = q(angle) / q(32);
        let r = expp(&line.scale(&half));
        let (m, moved) = step(&ma, &line, &next, q(angle));
        prop_assert_eq!(m.clone(), r.clone() * ma.clone());
        prop_assert_eq!(moved, (r * ma).sandwich_unit(&next));
        // f64: the same to rounding.
        let mf = motor_of(a);
        let xf = cga_null::up_generic(1.5, -2.0, 0.25);
        let mut fused = apply_method(&mf, &xf).coefficients().to_vec();
        let reference = mf.sandwich_unit(&xf).coefficients().to_vec();
        fused.truncate(5);
        prop_assert!(close(&fused, &reference));
    }
}

#[test]
fn constants_fold() {
    let z: Line<f64> = z_axis();
    let direct: Line<f64> = {
        let p = cga_null::up_generic(0.0, 0.0, 0.0) ^ cga_null::up_generic(0.0, 0.0, 1.0);
        let t: cga_null::Trivector<f64> = p ^ cga_null::ei::<f64>();
        Line::from_multivector(&(!t).into())
    };
    assert_eq!(z, direct);
    let (moved, line) = doc_step(&Motor::translator([1.0, 0.0, 0.0]), 0.5);
    assert!(moved.s.is_finite() && line.e12.is_finite());
    let m = translate_x(2.0);
    assert_eq!(m, Motor::translator([2.0, 0.0, 0.0]));
}

#[test]
fn symbolic_and_lane_scalars() {
    use ga_core::scalar::lanes::F64x4;
    use ga_core::symbolic::Poly;
    let names = ["s", "a", "b", "c", "d", "e", "f", "g"];
    let m = Motor::from_coefficients(names.map(Poly::var));
    let x = Vector::from_coefficients(["x1", "x2", "x3", "xo", "xi"].map(Poly::var));
    // The fused kernels are the same polynomials as the product-by-product evaluation.
    assert_eq!(apply_method(&m, &x), m.sandwich_unit(&x));
    assert_eq!(compose(&m, &m.reverse()), m.clone() * m.reverse());
    let full = m.clone() * x.clone() * m.reverse();
    assert_eq!(apply(&m, &x), Vector::from_multivector(&full.into()));
    // Four values at once.
    let lanes = up(F64x4::splat(1.0), F64x4::splat(2.0), F64x4::splat(3.0));
    assert_eq!(lanes, cga_null::up_generic(1.0, 2.0, 3.0).map(F64x4::splat));
}

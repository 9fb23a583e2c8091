//! Exponentials, logarithms and square roots of versors: closed forms against series, round
//! trips in the principal range, edge cases, and exactness over rationals.

use ga_core::cga::{self, down, up, Bivector, Even, Multivector, Rotor, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use ga_core::{pga3, vga3};
use nalgebra::Point3;
use proptest::prelude::*;

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

fn dist(a: &Multivector<f64>, b: &Multivector<f64>) -> f64 {
    a.coefficients()
        .iter()
        .zip(b.coefficients())
        .fold(0.0, |m, (x, y)| m.max((x - y).abs()))
}

fn even_dist(a: &Even<f64>, b: &Even<f64>) -> f64 {
    dist(&(*a).into(), &(*b).into())
}

fn biv_dist(a: &Bivector<f64>, b: &Bivector<f64>) -> f64 {
    dist(&(*a).into(), &(*b).into())
}

/// `Σ Bᵏ/k!` summed term by term in the sparse even type (no scaling): the plain series.
fn series_exp(b: &Bivector<f64>) -> Even<f64> {
    let x: Even<f64> = (*b).into();
    let mut one = Even::zero();
    one.s = 1.0;
    let mut term = one;
    let mut sum = one;
    for k in 1..80 {
        term = (term * x).scale(&(1.0 / k as f64));
        sum = sum + term;
    }
    sum
}

fn bivector(c: [f64; 10]) -> Bivector<f64> {
    let [a, b, c2, d, e, f, g, h, i, j] = c;
    Bivector::new(a, b, c2, d, e, f, g, h, i, j)
}

fn one_even() -> Even<f64> {
    let mut one = Even::zero();
    one.s = 1.0;
    one
}

// ---------------------------------------------------------------- Cl(4,1)

proptest! {
    #[test]
    fn cga_exp_matches_the_series_and_the_dense_exp(c in prop::array::uniform10(-1.5f64..1.5)) {
        let b = bivector(c);
        let closed = b.exp();
        let series = series_exp(&b);
        prop_assert!(even_dist(&closed, &series) < 1e-12, "{closed:?} vs {series:?}");
        let dense = Multivector::from(b).exp();
        prop_assert!(dist(&closed.into(), &dense) < 1e-12);
        // exp(B) is a unit versor.
        prop_assert!((closed.norm_squared() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn cga_log_inverts_exp_in_the_principal_range(c in prop::array::uniform10(-0.4f64..0.4)) {
        // Coefficients below 0.4 keep every rotation component below angle π.
        let b = bivector(c);
        let back = b.exp().log().unwrap();
        prop_assert!(biv_dist(&back, &b) < 1e-12, "{back:?} vs {b:?}");
        let dense = Multivector::from(b.exp()).log().unwrap();
        prop_assert!(dist(&dense, &b.into()) < 1e-12);
    }

    #[test]
    fn cga_exp_inverts_log_for_every_versor(c in prop::array::uniform10(-3.0f64..3.0), scale in 0.1f64..10.0) {
        let v = b_exp_scaled(bivector(c), scale);
        let size = Multivector::from(v).coefficients().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if let Some(l) = v.log() {
            let back = l.exp().scale(&scale);
            prop_assert!(even_dist(&back, &v) < 1e-9 * size * size, "{back:?} vs {v:?}");
        }
    }

    #[test]
    fn cga_log_of_a_product_of_two_vectors(a in prop::array::uniform5(-2.0f64..2.0), b in prop::array::uniform5(-2.0f64..2.0)) {
        let (a, b) = (Vector::new(a[0], a[1], a[2], a[3], a[4]), Vector::new(b[0], b[1], b[2], b[3], b[4]));
        let v: Even<f64> = (a * b).into();
        let n = v.norm_squared();
        if let Some(l) = v.log() {
            let back = l.exp().scale(&n.sqrt());
            let size = Multivector::from(v).coefficients().iter().fold(1.0f64, |m, x| m.max(x.abs()));
            prop_assert!(even_dist(&back, &v) < 1e-8 * size * size, "{back:?} vs {v:?}");
        } else {
            // Only non-versors (negative norm) or minus an exponential have no logarithm.
            prop_assert!(n <= 0.0 || v.s < 0.0, "{v:?}");
        }
    }

    #[test]
    fn cga_sqrt_squares_back_and_halves_the_log(c in prop::array::uniform10(-0.4f64..0.4)) {
        let b = bivector(c);
        let v = b.exp();
        let q = v.sqrt().unwrap();
        prop_assert!(even_dist(&(q * q), &v) < 1e-12);
        prop_assert!(even_dist(&q, &b.scale(&0.5).exp()) < 1e-12);
    }

    #[test]
    fn cga_split_into_commuting_blades(c in prop::array::uniform10(-2.0f64..2.0)) {
        let b = bivector(c);
        let Some((p, m)) = b.split() else { return Ok(()) };
        prop_assert!(biv_dist(&(p + m), &b) < 1e-9);
        let pm: Even<f64> = p * m;
        let mp: Even<f64> = m * p;
        prop_assert!(even_dist(&pm, &mp) < 1e-8);
        for x in [p, m] {
            let sq: Even<f64> = x * x;
            let mut scalar = Even::zero();
            scalar.s = sq.s;
            prop_assert!(even_dist(&sq, &scalar) < 1e-8, "{x:?}² = {sq:?}");
        }
        prop_assert!(even_dist(&b.exp(), &(p.exp() * m.exp())) < 1e-8);
    }
}

fn b_exp_scaled(b: Bivector<f64>, scale: f64) -> Even<f64> {
    b.exp().scale(&scale)
}

#[test]
fn cga_zero_bivector_and_identity() {
    assert_eq!(Bivector::<f64>::zero().exp(), one_even());
    assert_eq!(one_even().log(), Some(Bivector::zero()));
    assert_eq!(one_even().sqrt(), Some(one_even()));
    let exact_one = Even::<Rational>::from(Rotor::translator([r(0, 1), r(0, 1), r(0, 1)]));
    assert_eq!(exact_one.log(), Some(Bivector::zero()));
}

#[test]
fn cga_translators_and_transversions_are_exact_over_rationals() {
    let t = [r(1, 3), r(-5, 2), r(7, 1)];
    let tr = Rotor::translator(t.clone());
    let l = tr.log().unwrap();
    // log T = -½ t ∧ n_inf, and back.
    let mut expected = Rotor::translator(t.clone());
    expected.s = r(0, 1);
    assert_eq!(Rotor::from(l.clone()), expected);
    assert_eq!(l.exp(), Even::from(tr.clone()));
    // √T = T(t/2).
    let half = t.clone().map(|x| x / r(2, 1));
    assert_eq!(tr.sqrt(), Some(Rotor::translator(half.clone())));
    // A translator moves points exactly.
    let p = cga::up_generic(r(1, 1), r(2, 1), r(3, 1));
    let moved = tr.sandwich_unit(&p);
    assert_eq!(moved, cga::up_generic(r(4, 3), r(-1, 2), r(10, 1)));

    let k = Rotor::transversion(t.clone());
    let lk = k.log().unwrap();
    assert_eq!(lk.exp(), Even::from(k.clone()));
    assert_eq!(k.sqrt(), Some(Rotor::transversion(half)));
    // Null bivectors: exp(N) = 1 + N exactly.
    let n = Bivector::from_multivector(&Multivector::from(Rotor::transversion(t)));
    let mut one_plus = Even::from(n.clone());
    one_plus.s = r(1, 1);
    assert_eq!(n.exp(), one_plus);
}

#[test]
fn cga_transversion_is_the_inverted_translation() {
    let b = [0.3, -0.2, 0.5];
    let k = Rotor::transversion(b);
    for x in [[1.0, 2.0, -1.0], [0.0, 0.0, 0.0], [-0.5, 0.25, 3.0]] {
        let moved = down(&k.sandwich_unit(&up(&Point3::from(x)))).unwrap();
        let bx = b[0] * x[0] + b[1] * x[1] + b[2] * x[2];
        let x2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        let b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
        let d = 1.0 + 2.0 * bx + b2 * x2;
        let expected = Point3::new(
            (x[0] + x2 * b[0]) / d,
            (x[1] + x2 * b[1]) / d,
            (x[2] + x2 * b[2]) / d,
        );
        assert!((moved - expected).norm() < 1e-14, "{moved} vs {expected}");
    }
}

#[test]
fn cga_dilator_scales_about_the_origin() {
    let d = Rotor::dilator(2.5).unwrap();
    let p = down(&d.sandwich_unit(&up(&Point3::new(1.0, -2.0, 0.5)))).unwrap();
    assert!((p - Point3::new(2.5, -5.0, 1.25)).norm() < 1e-14, "{p}");
    let l = d.log().unwrap();
    assert!((l.e45 + 2.5f64.ln() / 2.0).abs() < 1e-15);
    assert!(Rotor::dilator(0.0).is_none());
    assert!(Rotor::dilator(f64::NAN).is_none());
    assert!(Rotor::<f64>::rotation([0.0, 0.0, 0.0], 1.0).is_none());
}

#[test]
fn cga_rotation_by_pi_and_the_branch_cut() {
    let r = Rotor::rotation([1.0, 2.0, 2.0], std::f64::consts::PI).unwrap();
    assert!(r.s.abs() < 1e-16);
    let l = r.log().unwrap();
    assert!(even_dist(&l.exp(), &r.into()) < 1e-15);
    // A rotation by π, applied twice, is the rotation by 2π: R² = -1, on the cut.
    let minus_one: Even<f64> = r * r;
    assert!(
        minus_one.log().is_none() || {
            // rounding may leave a tiny bivector part: then any answer must still exponentiate back
            let l = minus_one.log().unwrap();
            even_dist(&l.exp(), &minus_one) < 1e-12
        }
    );
    let mut exact_minus_one = Even::<f64>::zero();
    exact_minus_one.s = -1.0;
    assert_eq!(exact_minus_one.log(), None);
    assert_eq!(exact_minus_one.sqrt(), None);
    // Two rotations by π in orthogonal planes: e1234, not unique.
    let mut e1234 = Even::<f64>::zero();
    e1234.e1234 = 1.0;
    assert_eq!(e1234.log(), None);
    // Minus a translator has no logarithm; minus a dilator with a rotation part does.
    let minus_t = -Even::from(Rotor::translator([1.0, 0.0, 0.0]));
    assert_eq!(minus_t.log(), None);
    let rot_dil = bivector([2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.7]);
    let v = -rot_dil.exp();
    let l = v.log().unwrap();
    assert!(even_dist(&l.exp(), &v) < 1e-14);
}

#[test]
fn cga_non_versors_and_bad_input_have_no_logarithm() {
    let mut not_versor = one_even();
    not_versor.e12 = 1.0;
    not_versor.e34 = 1.0;
    assert_eq!(not_versor.log(), None);
    assert_eq!(Even::<f64>::zero().log(), None);
    let mut nan = one_even();
    nan.e13 = f64::NAN;
    assert_eq!(nan.log(), None);
    assert_eq!(nan.sqrt(), None);
    // e1 e5 has ⟨V Ṽ⟩₀ = -1: a versor, but not an exponential.
    let e15: Even<f64> = (cga::e1::<f64>() * cga::e5::<f64>()).into();
    assert_eq!(e15.log(), None);
    // An odd versor has no logarithm.
    assert_eq!(Multivector::from(cga::e1::<f64>()).log(), None);
}

#[test]
fn cga_isoclinic_rotation_round_trips_without_a_split() {
    for theta in [0.3, 1.0, 1.5, 2.5, 3.0] {
        let b = bivector([theta, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, theta, 0.0, 0.0]);
        assert!(b.split().is_none());
        let v = b.exp();
        assert!(even_dist(&v, &series_exp(&b)) < 1e-13);
        let back = v.log().unwrap();
        // Two rotation planes: principal when |θ₁| + |θ₂| < π. exp(π(e12 + e34)) = 1, so
        // beyond that the logarithm is θ - π.
        let expected = if 2.0 * theta < std::f64::consts::PI {
            b
        } else {
            b.scale(&(1.0 - std::f64::consts::PI / theta))
        };
        assert!(biv_dist(&back, &expected) < 1e-12, "{theta}: {back:?}");
        assert!(even_dist(&back.exp(), &v) < 1e-13);
    }
}

#[test]
fn cga_screw_and_loxodromic_cases() {
    // Rotation in e12 + translation along e3: dual plane.
    let screw = bivector([1.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.8, 0.8, 0.0]);
    // Rotation in e12 + dilation (e45): complex plane.
    let lox = bivector([1.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.9]);
    // Two rotations: split plane.
    let two = bivector([1.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0]);
    for b in [screw, lox, two] {
        let v = b.exp();
        assert!(even_dist(&v, &series_exp(&b)) < 1e-13);
        assert!(biv_dist(&v.log().unwrap(), &b) < 1e-13);
        let q = v.sqrt().unwrap();
        assert!(even_dist(&(q * q), &v) < 1e-13);
    }
}

#[test]
fn cga_dense_exp_of_non_versors() {
    // exp(a) for a vector a with a² = s > 0: cosh √s + a sinh √s / √s.
    let a = Vector::new(0.3, 0.4, 0.0, 1.2, 0.0);
    let s: f64 = a.scalar_product(&a);
    let e = Multivector::from(a).exp();
    let root = s.sqrt();
    assert!((e.s - root.cosh()).abs() < 1e-14);
    assert!((e.e1 - 0.3 * root.sinh() / root).abs() < 1e-14);
    // Exact for nilpotent input over rationals.
    let n = Multivector::from(cga::n_inf::<Rational>());
    let mut one_plus = n.clone();
    one_plus.s = r(1, 1);
    assert_eq!(n.exp(), one_plus);
}

// ---------------------------------------------------------------- Cl(3,0)

proptest! {
    #[test]
    fn vga3_round_trips(c in prop::array::uniform3(-1.7f64..1.7), s in 0.1f64..5.0) {
        let b = vga3::Bivector::new(c[0], c[1], c[2]);
        // |B| < π/2·√3·... < π: principal.
        let rot = b.exp();
        let back = rot.log().unwrap();
        prop_assert!((back - b).norm_squared().abs() < 1e-24);
        let dense = vga3::Multivector::from(b).exp();
        prop_assert!(approx::abs_diff_eq!(vga3::Multivector::from(rot), dense, epsilon = 1e-13));
        let q = rot.scale(&s).sqrt().unwrap();
        prop_assert!(approx::abs_diff_eq!(q * q, rot.scale(&s), epsilon = 1e-12));
        prop_assert!(approx::abs_diff_eq!(q.scale(&(1.0 / s.sqrt())), b.scale(&0.5).exp(), epsilon = 1e-13));
    }
}

#[test]
fn vga3_edge_cases() {
    let one = vga3::Rotor::new(1.0, 0.0, 0.0, 0.0);
    assert_eq!(vga3::Bivector::zero().exp(), one);
    assert_eq!(one.log(), Some(vga3::Bivector::zero()));
    // Rotation by π in e12: R = -e12 (exp(-π/2 e12)).
    let pi = vga3::Rotor::new(0.0, -1.0, 0.0, 0.0);
    let l = pi.log().unwrap();
    assert!((l.e12 + std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    assert_eq!(vga3::Rotor::new(-1.0, 0.0, 0.0, 0.0).log(), None);
    assert_eq!(vga3::Rotor::new(-1.0, 0.0, 0.0, 0.0).sqrt(), None);
    assert_eq!(vga3::Rotor::<f64>::zero().log(), None);
    assert_eq!(vga3::Rotor::new(f64::INFINITY, 0.0, 0.0, 0.0).log(), None);
    // Exact where the values are rational: √(e12-rotation by π) is not rational, but √1 is.
    let one_q = vga3::Rotor::new(r(4, 1), r(0, 1), r(0, 1), r(0, 1));
    assert_eq!(
        one_q.sqrt(),
        Some(vga3::Rotor::new(r(2, 1), r(0, 1), r(0, 1), r(0, 1)))
    );
}

// ---------------------------------------------------------------- Cl(3,0,1)

fn pga_biv(c: [f64; 6]) -> pga3::Bivector<f64> {
    pga3::Bivector::new(c[0], c[1], c[2], c[3], c[4], c[5])
}

proptest! {
    #[test]
    fn pga3_round_trips(c in prop::array::uniform6(-1.7f64..1.7)) {
        let b = pga_biv(c);
        let m = b.exp();
        let dense = pga3::Multivector::from(b).exp();
        prop_assert!(approx::abs_diff_eq!(pga3::Multivector::from(m), dense, epsilon = 1e-12));
        prop_assert!(approx::abs_diff_eq!(m.log().unwrap(), b, epsilon = 1e-12));
        let q = m.sqrt().unwrap();
        prop_assert!(approx::abs_diff_eq!(q * q, m, epsilon = 1e-12));
        prop_assert!(approx::abs_diff_eq!(q, b.scale(&0.5).exp(), epsilon = 1e-12));
    }

    #[test]
    fn pga3_exp_inverts_log(c in prop::array::uniform6(-6.0f64..6.0)) {
        let m = pga_biv(c).exp();
        if let Some(l) = m.log() {
            prop_assert!(approx::abs_diff_eq!(l.exp(), m, epsilon = 1e-10));
        }
    }
}

#[test]
fn pga3_translations_are_exact_and_rotations_by_pi_work() {
    let d = pga3::Bivector::new(r(1, 2), r(-3, 1), r(5, 7), r(0, 1), r(0, 1), r(0, 1));
    let m = d.exp();
    let one_plus = pga3::Motor::new(
        r(1, 1),
        r(1, 2),
        r(-3, 1),
        r(5, 7),
        r(0, 1),
        r(0, 1),
        r(0, 1),
        r(0, 1),
    );
    assert_eq!(m, one_plus);
    assert_eq!(m.log(), Some(d.clone()));
    assert_eq!(m.sqrt(), Some(d.scale(&r(1, 2)).exp()));
    // Rotation by π about a line off the origin: exp(π/2 (e12 + e0-part)).
    let b = pga_biv([0.3, -0.4, 0.0, std::f64::consts::FRAC_PI_2, 0.0, 0.0]);
    let m = b.exp();
    assert!(m.s.abs() < 1e-16);
    let back = m.log().unwrap();
    assert!(approx::abs_diff_eq!(back.exp(), m, epsilon = 1e-15));
    // Rotation by 2π: the cut.
    let minus = pga3::Motor::new(-1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    assert_eq!(minus.log(), None);
    // Not a motor: ⟨M M̃⟩₄ ≠ 0.
    let bad = pga3::Motor::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    assert_eq!(bad.log(), None);
}

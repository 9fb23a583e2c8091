//! The predicates are the conformal quantities of the thesis: checks against the generated
//! algebra `ga_core::cga` in exact arithmetic.

use cga_collide::exact::predicates::{BallBall, Orient3d, Orient3dCga, PointPower, SphereSphere};
use cga_collide::exact::Predicate;
use ga_core::cga::{n_inf, up_generic, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use proptest::prelude::*;

fn r(x: i32) -> Rational {
    Rational::from_i64(x as i64)
}

fn up(p: &[i32]) -> Vector<Rational> {
    up_generic(r(p[0]), r(p[1]), r(p[2]))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// up(a) ∧ up(b) ∧ up(c) ∧ up(d) ∧ n_inf = orient3d(a, b, c, d) · e12345 (untranslated,
    /// unscaled), and the translated, scaled form used by `Orient3dCga` is 16 times that.
    #[test]
    fn orient3d_is_the_conformal_wedge(x in proptest::array::uniform12(-9i32..9)) {
        let q: [Rational; 12] = core::array::from_fn(|i| r(x[i]));
        let o = Orient3d::eval(&q);
        let w = up(&x[0..3]).wedge(&up(&x[3..6])).wedge(&up(&x[6..9])).wedge(&up(&x[9..12])).wedge(&n_inf::<Rational>());
        prop_assert_eq!(w.e12345.clone(), o.clone());
        prop_assert_eq!(Orient3dCga::eval(&q), o * r(16));
    }

    /// Point power, sphere–sphere B² and ball–ball are the conformal inner products.
    #[test]
    fn sphere_predicates_are_inner_products(x in proptest::array::uniform8(-9i32..9)) {
        let q: [Rational; 8] = core::array::from_fn(|i| r(x[i]));
        let (c1, r1, c2, r2) = (&x[0..3], r(x[3]), &x[4..7], r(x[7]));
        let s1 = up(c1) - n_inf::<Rational>().scale(&(r1.clone() * r1.clone() / r(2)));
        let s2 = up(c2) - n_inf::<Rational>().scale(&(r2.clone() * r2.clone() / r(2)));
        // (S1·S2)² - S1² S2² with the normalised dual spheres, times 16 for the scaling by 2.
        let b2 = s1.scalar_product(&s2) * s1.scalar_product(&s2) - s1.scalar_product(&s1) * s2.scalar_product(&s2);
        prop_assert_eq!(SphereSphere::eval(&q), b2 * r(16));
        let bb = s1.scalar_product(&s2) + r1.clone() * r2.clone();
        prop_assert_eq!(BallBall::eval(&q), bb * r(4));
        // up(p)·S = -½(|p - c|² - r²).
        let p7 = [q[4].clone(), q[5].clone(), q[6].clone(), q[0].clone(), q[1].clone(), q[2].clone(), r1.clone()];
        prop_assert_eq!(PointPower::eval(&p7), up(c2).scalar_product(&s1) * r(-4));
    }
}

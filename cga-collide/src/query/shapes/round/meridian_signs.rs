//! A ball (or point) against a cylinder or cone, exact, as signs of integer polynomials in the
//! `f64` inputs: the same meridian half-plane test as [`super::meridian`], with every square
//! root squared away by hand so that each comparison is one polynomial predicate decided by the
//! crate's staged signs ([`ExactKernel`]: an error-bounded `f64` filter, `f64` expansions, then
//! big integers with a common power-of-two denominator; no rationals, no gcds).
//!
//! With `u` the axis, `o` its origin (cylinder `a`, cone apex), `v` the centre and `e` the
//! ball's radius plus the clearance: `T = (v − o)·u`, `L = u·u`, `X = |(v − o) × u|²`. Scaled by
//! `√L`, the point is `(T, √X)` in the half-plane, the rim `(L, r√L)`, and the distance
//! squared is compared with `e²L`.
//! * cylinder: axial excess `A` (`−T`, `T − L` or `0`); within iff `A² ≤ e²L` when
//!   `X ≤ r²L`, else iff `E = e²L − A² ≥ 0` and `√X − r√L ≤ √E`, that is
//!   `F = X − r²L − E ≤ 0` or `F² ≤ 4r²LE`;
//! * cone (triangle `(0, 0), (L, 0), (L, r√L)`): inside iff `0 ≤ T ≤ L` and `XL ≤ r²T²`;
//!   else within iff within of the base edge (the cylinder test with `A = T − L`) or of the
//!   slant edge `O R`: nearest `O` when `T√L + r√X ≤ 0` (`T² + X ≤ e²L`), nearest `R` (on the
//!   base edge) when `r√X ≥ (L + r² − T)√L`, else `G ≤ 2rT√(LX)` with
//!   `G = LX + r²T² − e²L(L + r²)`.

use core::cmp::Ordering;

use ga_core::scalar::Ring;

use crate::exact::vector::{cross, dot, sub};
use crate::exact::{ExactKernel, Kernel, Predicate};
use crate::shape::Shape;

/// The inputs: origin (3), axis end (3), radius, centre (3), ball radius, clearance.
type Inputs = [f64; 12];

/// The predicate number `K` of the module's table, with the axial excess `A` chosen by `A`
/// (`0`: none, `1`: `−T`, `2`: `T − L`).
struct Meridian<const K: u8, const A: u8>;

impl<const K: u8, const A: u8> Predicate<12> for Meridian<K, A> {
    #[inline(always)]
    fn eval<R: Ring>(x: &[R; 12]) -> R {
        let at = |i: usize| [x[i].clone(), x[i + 1].clone(), x[i + 2].clone()];
        let (o, end, v) = (at(0), at(3), at(7));
        let u = sub(&end, &o);
        let rel = sub(&v, &o);
        let c = cross(&rel, &u);
        let t = dot(&rel, &u);
        let l = dot(&u, &u);
        let x2 = dot(&c, &c);
        let r2 = x[6].clone() * x[6].clone();
        let e = x[10].clone() + x[11].clone();
        let e2l = || e.clone() * e.clone() * l.clone();
        let sq = |v: R| v.clone() * v;
        // Only the terms a predicate uses are built (big integers are not free).
        let a2 = || match A {
            0 => R::zero(),
            1 => sq(t.clone()),
            _ => sq(t.clone() - l.clone()),
        };
        let room = || e2l() - a2();
        let f = || x2.clone() - r2.clone() * l.clone() - room();
        let m = || l.clone() + r2.clone() - t.clone();
        let g = || {
            l.clone() * x2.clone() + r2.clone() * sq(t.clone()) - e2l() * (l.clone() + r2.clone())
        };
        let four = || R::from_i64(4);
        match K {
            0 => t,
            1 => t - l,
            2 => x2 - r2 * l,
            3 => a2() - e2l(),
            4 => f(),
            5 => sq(f()) - four() * r2.clone() * l.clone() * room(),
            6 => x2 * l - r2 * sq(t),
            7 => r2 * x2 - sq(t) * l,
            8 => sq(t) + x2 - e2l(),
            9 => m(),
            10 => r2.clone() * x2 - sq(m()) * l,
            11 => g(),
            _ => sq(g()) - four() * r2.clone() * sq(t.clone()) * l.clone() * x2.clone(),
        }
    }
}

fn sign<const K: u8, const A: u8>(x: &Inputs) -> Ordering {
    ExactKernel::sign::<Meridian<K, A>, 12>(x)
}

/// Within `e` of the solid of radius `r` about the axis with the axial excess `A` (the
/// cylinder's test; the cone's base edge with `A = 2`).
fn rim_within<const A: u8>(x: &Inputs) -> bool {
    if sign::<2, 0>(x) != Ordering::Greater {
        return sign::<3, A>(x) != Ordering::Greater;
    }
    if sign::<3, A>(x) == Ordering::Greater {
        return false;
    }
    sign::<4, A>(x) != Ordering::Greater || sign::<5, A>(x) != Ordering::Greater
}

fn cylinder_within(x: &Inputs) -> bool {
    if sign::<0, 0>(x) == Ordering::Less {
        rim_within::<1>(x)
    } else if sign::<1, 0>(x) == Ordering::Greater {
        rim_within::<2>(x)
    } else {
        rim_within::<0>(x)
    }
}

fn cone_within(x: &Inputs) -> bool {
    let t = sign::<0, 0>(x);
    if t != Ordering::Less
        && sign::<1, 0>(x) != Ordering::Greater
        && sign::<6, 0>(x) != Ordering::Greater
    {
        return true;
    }
    if rim_within::<2>(x) {
        return true;
    }
    let past_apex = t == Ordering::Greater || sign::<7, 0>(x) == Ordering::Greater;
    if !past_apex {
        return sign::<8, 0>(x) != Ordering::Greater;
    }
    if sign::<9, 0>(x) != Ordering::Greater || sign::<10, 0>(x) != Ordering::Less {
        // The nearest point of the slant is the rim, on the base edge: already not within.
        return false;
    }
    let g = sign::<11, 0>(x);
    match t {
        Ordering::Equal => g != Ordering::Greater,
        Ordering::Greater => g != Ordering::Greater || sign::<12, 0>(x) != Ordering::Greater,
        Ordering::Less => g != Ordering::Greater && sign::<12, 0>(x) != Ordering::Less,
    }
}

/// The exact answer for a cylinder or cone against a ball, or `None` for other pairs and a
/// zero-length axis.
pub(super) fn within(a: &Shape, b: &Shape, c: f64) -> Option<bool> {
    let (round, ball) = match (a, b) {
        (Shape::Ball(ball), r) | (r, Shape::Ball(ball)) => (r, ball),
        _ => return None,
    };
    let (cone, o, end, r) = match round {
        Shape::Cylinder(k) => (false, k.a(), k.b(), k.radius()),
        Shape::Cone(k) => (true, k.apex(), k.base(), k.radius()),
        _ => return None,
    };
    if o == end {
        return None;
    }
    let v = ball.centre();
    let x: Inputs = [
        o.x,
        o.y,
        o.z,
        end.x,
        end.y,
        end.z,
        r,
        v.x,
        v.y,
        v.z,
        ball.radius(),
        c,
    ];
    Some(if cone {
        cone_within(&x)
    } else {
        cylinder_within(&x)
    })
}

//! A segment within a distance `e` of a cylinder or cone, exactly; with `e` grown by a
//! capsule's radius this decides the capsule pairs.
//!
//! The points within `e` of a solid of revolution are those whose meridian coordinates
//! `(τ, ρ)` (axial, radial; real units) are within `e` of its profile polygon (the rectangle
//! `[0, h] × [0, r]` of a cylinder, the triangle `(0,0), (h,0), (h,r)` of a cone, `h` the axis
//! length): inside the polygon, or in an edge's strip (the foot on the edge and within `e` of
//! its line), or within `e` of a vertex. Along the segment `p(t) = p₀ + t(p₁ − p₀)` the axial
//! coordinate scaled by `h`, `T = (p − o)·d`, is linear in `t` and `ρ² = Y = |(p − o) × d|² / h²`
//! is quadratic, all with rational coefficients (`h² = L` is rational), and `τ = T/h`. Every
//! piece above is a condition on `T`, `Y` and `√Y = ρ`; a condition `a <= b·√Y` is the union of
//! three polynomial ones (`b >= 0, a <= 0`; `b >= 0, a² <= b²Y`; `a <= 0, b²Y <= a²`). So the
//! question is a union of "is there `t ∈ [0, 1]` where these polynomials are `<= 0`", each
//! decided exactly ([`exists_all_non_positive`]).

use ga_core::scalar::Rational;
use num_traits::{One, Zero};

use super::exact3::{cross, dot, sub, Profile, Round, V3};
use super::univariate::{exists_all_non_positive, Poly};

/// A conjunction of `p <= 0` conditions.
type Clause = Vec<Poly>;

/// `a <= b·√y` as three clauses, one of which holds iff it does (`y >= 0` throughout).
fn below_root(a: &Poly, b: &Poly, y: &Poly) -> [Clause; 3] {
    let minus_b = b.scale(&-Rational::one());
    let gap = a.mul(a).sub(&b.mul(b).mul(y));
    [
        vec![minus_b.clone(), a.clone()],
        vec![minus_b, gap.clone()],
        vec![a.clone(), gap.scale(&-Rational::one())],
    ]
}

/// Every clause of `x` joined with every clause of `y` (the conjunction of two unions).
fn and(x: &[Clause], y: &[Clause]) -> Vec<Clause> {
    x.iter()
        .flat_map(|cx| {
            y.iter().map(move |cy| {
                let mut c = cx.clone();
                c.extend(cy.iter().cloned());
                c
            })
        })
        .collect()
}

/// The conditions along the segment, in the solid's meridian coordinates.
struct Along {
    /// `T(t) = (p(t) − o)·d`.
    t: Poly,
    /// `X(t) = |(p(t) − o) × d|² = L·ρ²`.
    x: Poly,
    /// `Y(t) = X / L = ρ²`.
    y: Poly,
    l: Rational,
}

impl Along {
    fn new(round: &Round, p0: &V3, p1: &V3) -> Along {
        let w = sub(p0, &round.origin);
        let v = sub(p1, p0);
        let d = &round.axis;
        let t = Poly::linear(dot(&w, d), dot(&v, d));
        let (wd, vd) = (cross(&w, d), cross(&v, d));
        let two = Rational::from_integer(2.into());
        let x = Poly::quadratic(dot(&wd, &wd), two * dot(&wd, &vd), dot(&vd, &vd));
        let l = round.length2.clone();
        let y = x.scale(&(Rational::one() / &l));
        Along { t, x, y, l }
    }

    fn k(&self, c: Rational) -> Poly {
        Poly::constant(c)
    }

    /// `lo <= T <= hi` (either side may be left open with `None`).
    fn axial(&self, lo: Option<&Rational>, hi: Option<&Rational>) -> Clause {
        let mut c = Vec::new();
        if let Some(lo) = lo {
            c.push(self.k(lo.clone()).sub(&self.t));
        }
        if let Some(hi) = hi {
            c.push(self.t.sub(&self.k(hi.clone())));
        }
        c
    }

    /// `ρ <= radius`.
    fn radial(&self, radius: &Rational) -> Poly {
        self.y.sub(&self.k(radius * radius))
    }

    /// Within `e` of the point at `T = at`, `ρ = rho` in the meridian half-plane:
    /// `(τ − at/h)² + (ρ − rho)² <= e²`, i.e. `(T − at)²/L + Y + rho² − e² <= 2·rho·√Y`.
    fn near_vertex(&self, at: &Rational, rho: &Rational, e: &Rational) -> Vec<Clause> {
        let dt = self.t.sub(&self.k(at.clone()));
        let a = dt
            .mul(&dt)
            .scale(&(Rational::one() / &self.l))
            .add(&self.y)
            .add(&self.k(rho * rho - e * e));
        let two = Rational::from_integer(2.into());
        below_root(&a, &self.k(two * rho), &self.y).to_vec()
    }

    /// Within `e` beyond the cap plane at `T = at` (outward along `outward = ±1`), the foot on
    /// the cap: `0 <= ±(T − at) <= e·h` and `ρ <= radius`.
    fn beyond_cap(&self, at: &Rational, outward: bool, radius: &Rational, e: &Rational) -> Clause {
        let dt = self.t.sub(&self.k(at.clone()));
        let inward = if outward {
            dt.scale(&-Rational::one())
        } else {
            dt.clone()
        };
        vec![
            inward,
            dt.mul(&dt).sub(&self.k(e * e * &self.l)),
            self.radial(radius),
        ]
    }
}

/// The clauses of "within `e` of the cylinder".
fn cylinder(a: &Along, r: &Rational, e: &Rational) -> Vec<Clause> {
    let zero = Rational::zero();
    let l = a.l.clone();
    let mut side = a.axial(Some(&zero), Some(&l));
    side.push(a.radial(&(r + e)));
    let mut out = vec![
        side,
        a.beyond_cap(&zero, false, r, e),
        a.beyond_cap(&l, true, r, e),
    ];
    out.extend(a.near_vertex(&zero, r, e));
    out.extend(a.near_vertex(&l, r, e));
    out
}

/// The clauses of "within `e` of the cone" (apex at `T = 0`, base at `T = L`).
fn cone(a: &Along, r: &Rational, e: &Rational) -> Vec<Clause> {
    let zero = Rational::zero();
    let l = a.l.clone();
    let one = Rational::one();
    // Inside: 0 <= T <= L and ρ <= r·τ/h, i.e. L²Y <= r²T² (T >= 0).
    let mut inside = a.axial(Some(&zero), Some(&l));
    inside.push(a.x.scale(&l).sub(&a.t.mul(&a.t).scale(&(r * r))));
    // The strip of the axis edge: 0 <= T <= L, ρ <= e.
    let mut axis = a.axial(Some(&zero), Some(&l));
    axis.push(a.radial(e));
    let mut out = vec![inside, axis, a.beyond_cap(&l, true, r, e)];
    out.extend(a.near_vertex(&zero, &zero, e));
    out.extend(a.near_vertex(&l, &zero, e));
    out.extend(a.near_vertex(&l, r, e));
    // The strip of the slant edge from (0, 0) to (h, r): with the edge's length s = √(L + r²),
    // the foot is at (τ·h + ρ·r)/s² = (T + r√Y)/s² ∈ [0, 1], and the distance to its line is
    // |ρh − τr|/s <= e, i.e. (L√Y − rT)² <= e²·L·s², i.e. L·X + r²T² − e²L·s² <= 2LrT·√Y.
    let s2 = &l + r * r;
    let rk = a.k(r.clone());
    let foot_low = below_root(&a.t.scale(&-one.clone()), &rk, &a.y);
    let foot_high = below_root(&a.t.sub(&a.k(s2.clone())), &rk.scale(&-one), &a.y);
    let near_line = below_root(
        &a.x.scale(&l)
            .add(&a.t.mul(&a.t).scale(&(r * r)))
            .sub(&a.k(e * e * &l * &s2)),
        &a.t.scale(&(Rational::from_integer(2.into()) * &l * r)),
        &a.y,
    );
    out.extend(and(&and(&foot_low, &foot_high), &near_line));
    out
}

/// Exact: is the segment `[p0, p1]` within `e >= 0` of the cylinder or cone?
pub(crate) fn within(round: &Round, p0: &V3, p1: &V3, e: &Rational) -> bool {
    let a = Along::new(round, p0, p1);
    let clauses = match round.profile {
        Profile::Cylinder => cylinder(&a, &round.radius, e),
        Profile::Cone => cone(&a, &round.radius, e),
    };
    let (lo, hi) = (Rational::zero(), Rational::one());
    clauses.iter().any(|c| exists_all_non_positive(c, &lo, &hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::shapes::round::{meridian, section};
    use crate::shape::{Cone, Cylinder};
    use nalgebra::Point3;

    fn r(n: i64) -> Rational {
        Rational::from_integer(n.into())
    }

    fn v(x: f64, y: f64, z: f64) -> V3 {
        super::super::exact3::point(&Point3::new(x, y, z))
    }

    fn cylinder() -> Round {
        let c = Cylinder::new(Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 0.0, 8.0), 2.0);
        Round::cylinder(&c.expect("valid"))
    }

    fn cone() -> Round {
        let c = Cone::new(Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 0.0, 4.0), 3.0);
        Round::cone(&c.expect("valid"))
    }

    fn just_below(e: &Rational) -> Rational {
        e - Rational::new(1.into(), (1i64 << 50).into())
    }

    /// `within` is true at `e` and false just below it.
    fn exactly_at(round: &Round, p0: &V3, p1: &V3, e: &Rational) {
        assert!(within(round, p0, p1, e), "not within {e}");
        assert!(
            !within(round, p0, p1, &just_below(e)),
            "within less than {e}"
        );
    }

    #[test]
    fn beside_above_and_at_the_rim_of_a_cylinder() {
        let c = cylinder();
        // Parallel to the side, 1 away.
        exactly_at(&c, &v(3.0, 0.0, 1.0), &v(3.0, 0.0, 5.0), &r(1));
        // Across above the cap, 1 away.
        exactly_at(&c, &v(-5.0, 1.0, 9.0), &v(5.0, 1.0, 9.0), &r(1));
        // Past the rim: nearest at (3, 0, 8.75), 1 out and 3/4 up from the rim: 5/4 away.
        exactly_at(
            &c,
            &v(3.0, -5.0, 8.75),
            &v(3.0, 7.0, 8.75),
            &Rational::new(5.into(), 4.into()),
        );
        // Through the solid.
        assert!(within(&c, &v(-9.0, 0.5, 3.0), &v(9.0, 0.5, 3.0), &r(0)));
    }

    #[test]
    fn along_a_generator_and_past_the_apex_of_a_cone() {
        let c = cone();
        // The generator from the apex to (3, 0, 4) has the outward normal (4, 0, −3)/5: the
        // segment through (0.75, 0, 1) and (2.25, 0, 3) moved by (4, 0, −3) is 5 away.
        exactly_at(&c, &v(4.75, 0.0, -2.0), &v(6.25, 0.0, 0.0), &r(5));
        // Below the apex, across the axis: 2 away.
        exactly_at(&c, &v(-1.0, 0.0, -2.0), &v(1.0, 0.0, -2.0), &r(2));
        // Beyond the base, 1/2 away.
        exactly_at(
            &c,
            &v(-1.0, 1.0, 4.5),
            &v(1.0, 1.0, 4.5),
            &Rational::new(1.into(), 2.into()),
        );
    }

    /// Small-integer pairs, so that touching is common: a segment of one point agrees with the
    /// point test, and a segment at distance 0 with the polytope test.
    #[test]
    fn agrees_with_the_point_and_polytope_tests() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: i64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % (2 * m as u64 + 1)) as i64 - m
        };
        for i in 0..300 {
            let mut p = || v(next(4) as f64, next(4) as f64, next(4) as f64);
            let (a, b, p0, p1) = (p(), p(), p(), p());
            if a == b {
                continue;
            }
            let radius = next(3).unsigned_abs().max(1) as f64;
            let f = |x: &V3| {
                Point3::new(
                    num_traits::ToPrimitive::to_f64(&x[0]).unwrap_or(0.0),
                    num_traits::ToPrimitive::to_f64(&x[1]).unwrap_or(0.0),
                    num_traits::ToPrimitive::to_f64(&x[2]).unwrap_or(0.0),
                )
            };
            let round = if i % 2 == 0 {
                Round::cylinder(&Cylinder::new(f(&a), f(&b), radius).expect("valid"))
            } else {
                Round::cone(&Cone::new(f(&a), f(&b), radius).expect("valid"))
            };
            let e = Rational::new(next(6).unsigned_abs().into(), 2.into());
            assert_eq!(
                within(&round, &p0, &p0, &e),
                meridian::point_within(&round, &p0, &e),
                "point {i}"
            );
            assert_eq!(
                within(&round, &p0, &p1, &r(0)),
                section::meets_polytope(&round, &[p0.clone(), p1.clone()]),
                "segment {i}"
            );
        }
    }
}

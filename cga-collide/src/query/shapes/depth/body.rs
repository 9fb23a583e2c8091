//! The shapes of a pair with a cylinder or a cone, as the curved depth search sees them:
//! their support functions, bounded with outward rounding or decided exactly.
//!
//! The support function `h_S(n) = max over x ∈ S of x·n` of
//! * a polytopal shape (core ⊕ ball(s)) is `max over the core's points of p·n + s·|n|`;
//! * the cylinder of axis `[a, b]`, radius `r`, is `max(a·n, b·n) + r·|n × d| / |d|` with
//!   `d = b − a` (each cap disc reaches `r` times the length of `n`'s part across the axis);
//! * the cone of apex `p`, base centre `c`, radius `r`, is `max(p·n, c·n + r·|n × d| / |d|)`
//!   with `d = c − p` (the hull of the apex and the base disc).
//!
//! Each is a maximum of *branches* `q + √S` with `q` and `S ≥ 0` exact rationals when `n` is
//! an `f64` vector (`S = r²·|n × d|² / |d|²`, or `s²·n·n`), which is what the exact test
//! [`gap_is_nonpositive`] uses.

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::{Point3, Vector3};
use num_traits::Signed;

use super::polytope::Core;
use crate::exact::vector::{cross, dot, sub};
use crate::query::shapes::round::interval::{dot3, lift, norm2, Iv, WHOLE};
use crate::query::shapes::round::Body as Filtered;
use crate::shape::{Segment, Shape};

pub(super) type P3 = [f64; 3];

/// A shape of the pair, or `None` from [`Body::of`] for half-spaces and hulls too large for
/// the polytope depth.
pub(super) enum Body {
    /// A polytopal shape, taken as it is (its own inner polytope).
    Polytopal { shape: Shape, core: Core },
    /// The cylinder of axis `[a, b]` and a positive radius.
    Cylinder { a: P3, b: P3, radius: f64 },
    /// The cone of apex `apex`, base centre `base` and a positive radius.
    Cone { apex: P3, base: P3, radius: f64 },
}

fn p3(p: &Point3<f64>) -> P3 {
    [p.x, p.y, p.z]
}

/// `x` exactly (`0` for the non-finite values the shapes never hold).
pub(super) fn q(x: f64) -> Rational {
    rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
}

pub(super) fn qv(p: &P3) -> [Rational; 3] {
    p.map(q)
}

/// One branch `q + √s` of a support function, exactly.
pub(super) struct Branch {
    pub(super) q: Rational,
    pub(super) s: Rational,
}

impl Body {
    pub(super) fn of(shape: &Shape) -> Option<Body> {
        let polytopal = |shape: Shape| Core::of(&shape).map(|core| Body::Polytopal { shape, core });
        let segment = |a: &Point3<f64>, b: &Point3<f64>| {
            Segment::new(*a, *b).ok().and_then(|s| polytopal(s.into()))
        };
        match shape {
            Shape::HalfSpace(_) => None,
            Shape::Cylinder(c) if c.radius() == 0.0 => segment(c.a(), c.b()),
            Shape::Cone(c) if c.radius() == 0.0 => segment(c.apex(), c.base()),
            Shape::Cylinder(c) => Some(Body::Cylinder {
                a: p3(c.a()),
                b: p3(c.b()),
                radius: c.radius(),
            }),
            Shape::Cone(c) => Some(Body::Cone {
                apex: p3(c.apex()),
                base: p3(c.base()),
                radius: c.radius(),
            }),
            other => polytopal(other.clone()),
        }
    }

    /// The largest magnitude of its coordinates and radius (the scale of its rounding).
    pub(super) fn scale(&self) -> f64 {
        let m = |p: &P3| p.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        match self {
            Body::Polytopal { core, .. } => core.points.iter().fold(core.radius, |s, p| {
                p.parts().iter().fold(s, |s, t| s.max(m(t)))
            }),
            Body::Cylinder { a, b, radius } => m(a).max(m(b)).max(*radius),
            Body::Cone { apex, base, radius } => m(apex).max(m(base)).max(*radius),
        }
    }

    /// A proved interval of `h(n)` (a cylinder's or cone's is the filter's).
    pub(super) fn support(&self, n: &P3) -> Iv {
        match self {
            Body::Polytopal { core, .. } => {
                let ni = lift(n);
                let best = core
                    .points
                    .iter()
                    .map(|p| {
                        p.parts()
                            .iter()
                            .fold(Iv::point(0.0), |x, t| x.add(dot3(&lift(t), &ni)))
                    })
                    .reduce(Iv::max)
                    .unwrap_or(WHOLE);
                best.add(Iv::point(core.radius).mul(norm2(&ni).sqrt()))
            }
            Body::Cylinder { a, b, radius } => Filtered::Cylinder(*a, *b, *radius).support_value(n),
            Body::Cone { apex, base, radius } => {
                Filtered::Cone(*apex, *base, *radius).support_value(n)
            }
        }
    }

    /// The branches of `h(n)`, exactly.
    pub(super) fn branches(&self, n: &P3) -> Vec<Branch> {
        let nq = qv(n);
        let rim = |from: &P3, to: &P3, r: f64| {
            let d = sub(&qv(to), &qv(from));
            let c = cross(&nq, &d);
            let r = q(r);
            &r * &r * dot(&c, &c) / dot(&d, &d)
        };
        let zero = <Rational as Ring>::zero;
        match self {
            Body::Polytopal { core, .. } => {
                let r = q(core.radius);
                let s = &r * &r * dot(&nq, &nq);
                core.points
                    .iter()
                    .map(|p| Branch {
                        q: dot(&p.lift(&q), &nq),
                        s: s.clone(),
                    })
                    .collect()
            }
            Body::Cylinder { a, b, radius } => {
                let s = rim(a, b, *radius);
                vec![
                    Branch {
                        q: dot(&qv(a), &nq),
                        s: s.clone(),
                    },
                    Branch {
                        q: dot(&qv(b), &nq),
                        s,
                    },
                ]
            }
            Body::Cone { apex, base, radius } => vec![
                Branch {
                    q: dot(&qv(apex), &nq),
                    s: zero(),
                },
                Branch {
                    q: dot(&qv(base), &nq),
                    s: rim(apex, base, *radius),
                },
            ],
        }
    }

    /// A point of the shape extreme along `n` (rounded).
    pub(super) fn support_point(&self, n: &Vector3<f64>) -> Point3<f64> {
        let pt = |p: &P3| Point3::new(p[0], p[1], p[2]);
        let across = |from: &P3, to: &P3| {
            let d = pt(to) - pt(from);
            let w = n - d * (n.dot(&d) / d.norm_squared());
            let len = w.norm();
            if len > 0.0 && len.is_finite() {
                w / len
            } else {
                Vector3::zeros()
            }
        };
        match self {
            Body::Polytopal { core, .. } => {
                let best = core
                    .points
                    .iter()
                    .map(|p| pt(&p.approx()))
                    .max_by(|x, y| x.coords.dot(n).total_cmp(&y.coords.dot(n)))
                    .unwrap_or_else(Point3::origin);
                best + n * core.radius
            }
            Body::Cylinder { a, b, radius } => {
                let cap = if pt(a).coords.dot(n) >= pt(b).coords.dot(n) {
                    a
                } else {
                    b
                };
                pt(cap) + across(a, b) * *radius
            }
            Body::Cone { apex, base, radius } => {
                let rim = pt(base) + across(apex, base) * *radius;
                if pt(apex).coords.dot(n) >= rim.coords.dot(n) {
                    pt(apex)
                } else {
                    rim
                }
            }
        }
    }
}

/// Exactly: `q + √s1 + √s2 ≤ 0` (`s1, s2 ≥ 0`).
fn sum_nonpositive(q: &Rational, s1: &Rational, s2: &Rational) -> bool {
    if q.is_positive() {
        return false;
    }
    // √s1 + √s2 ≤ t with t = −q ≥ 0  ⇔  2√(s1·s2) ≤ t² − s1 − s2 =: w  ⇔  w ≥ 0, 4·s1·s2 ≤ w².
    let t = -q.clone();
    let w = &t * &t - s1 - s2;
    if w.is_negative() {
        return false;
    }
    let four = q_int(4);
    four * s1 * s2 <= &w * &w
}

fn q_int(k: i32) -> Rational {
    q(f64::from(k))
}

/// Exactly: is `h_A(n) + h_B(−n) ≤ 0`? (For shapes that meet it is then `0`: they touch, and
/// translating `B` along `n` by any amount separates their interiors.)
pub(super) fn gap_is_nonpositive(a: &Body, b: &Body, n: &P3) -> bool {
    let ba = a.branches(n);
    let bb = b.branches(&n.map(|x| -x));
    ba.iter().all(|x| {
        bb.iter()
            .all(|y| sum_nonpositive(&(&x.q + &y.q), &x.s, &y.s))
    })
}

/// A proved upper bound of `(h_A(n) + h_B(−n)) / |n|` (`+∞` when unknown).
pub(super) fn gap_upper(a: &Body, b: &Body, n: &P3) -> f64 {
    let h = a.support(n).add(b.support(&n.map(|x| -x)));
    // (Never NaN: an unknown bound is the whole line.)
    h.div_positive(norm2(&lift(n)).sqrt()).hi
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_surd_sums_are_signed_exactly() {
        // −3 + √4 + √1 = 0; −3 + √4 + √1.0000001 > 0; −3 + √4 + √0.99 < 0.
        assert!(sum_nonpositive(&q(-3.0), &q(4.0), &q(1.0)));
        assert!(!sum_nonpositive(&q(-3.0), &q(4.0), &q(1.0000001)));
        assert!(sum_nonpositive(&q(-3.0), &q(4.0), &q(0.99)));
        assert!(!sum_nonpositive(&q(0.5), &q(0.0), &q(0.0)));
        assert!(sum_nonpositive(&q(0.0), &q(0.0), &q(0.0)));
    }
}

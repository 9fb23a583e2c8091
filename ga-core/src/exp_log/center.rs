//! Arithmetic in the two-dimensional commutative algebra `{a + b J}` where a bivector's square
//! (and a versor's scalar-plus-4-vector part) lives.
//!
//! For a bivector `B`, `B² = α + β` with `α` a scalar and `β` a 4-vector that commutes with
//! `B`; in Cl(4,1) `β²` is a scalar, in Cl(3,0,1) `β = m e0123` squares to zero. So `B²`, and
//! every power series in `B²`, lies in the plane spanned by `1` and a unit `J ∥ β` with
//! `J² ∈ {+1, -1, 0}`: the split-complex, complex or dual numbers. `exp(B) = C(B²) + B S(B²)`
//! with `C(x) = cosh √x`, `S(x) = sinh √x / √x` (entire functions of `x`), and the logarithm
//! inverts this. Every function is evaluated in the right number system: the split case on
//! the two idempotent components `(1 ± J)/2`, the complex case with complex arithmetic, the
//! dual case with first derivatives. When `β = 0` only the real line is involved.

use crate::scalar::{Elementary, Ring};

/// How the unit `J` squares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `J² = +1` (or no `J` at all: then `b = 0` throughout).
    Split,
    /// `J² = -1`.
    Complex,
    /// `J² = 0`.
    Dual,
}

/// `a + b J`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Z<T> {
    pub a: T,
    pub b: T,
}

impl<T: Ring> Z<T> {
    pub fn new(a: T, b: T) -> Self {
        Z { a, b }
    }
}

fn two<T: Ring>() -> T {
    T::from_i64(2)
}

fn half<T: Elementary>() -> T {
    T::one() / two()
}

/// Below this `|x|`, series replace formulas that cancel (`(C - S)/2x`, `asinh r / r` …).
fn series_threshold<T: Elementary>() -> T {
    T::from_f64(1e-4)
}

/// `(C(x), S(x))` on the real line. Exact at `x = 0`.
fn cs_real<T: Elementary>(x: &T) -> (T, T) {
    if x.is_zero() {
        return (T::one(), T::one());
    }
    if *x < T::zero() {
        let a = (-x.clone()).sqrt();
        (a.cos(), a.sin() / a)
    } else {
        let a = x.sqrt();
        (a.cosh(), a.sinh() / a)
    }
}

/// `S'(x) = (C - S) / 2x`, by its series near zero (`1/6` exactly at zero).
fn ds_real<T: Elementary>(x: &T, c: &T, s: &T) -> T {
    if x.abs() < series_threshold() {
        // S(x) = Σ x^k / (2k+1)!  ⇒  S'(x) = 1/6 + x/60 + x²/1680 + x³/90720.
        let f = |n: i64| T::one() / T::from_i64(n);
        f(6) + x.clone() * (f(60) + x.clone() * (f(1680) + x.clone() * f(90720)))
    } else {
        (c.clone() - s.clone()) / (two::<T>() * x.clone())
    }
}

/// The series `1 - w/6 + 3w²/40 - 5w³/112` of `asinh(√w)/√w` (= `asin(√-w)/√-w`) and its
/// derivative, for small `|w|`.
fn log_series<T: Elementary>(w: &T) -> (T, T) {
    let f = |p: i64, q: i64| T::from_i64(p) / T::from_i64(q);
    let value = T::one() + w.clone() * (f(-1, 6) + w.clone() * (f(3, 40) + w.clone() * f(-5, 112)));
    let slope = f(-1, 6) + w.clone() * (f(3, 20) + w.clone() * f(-15, 112));
    (value, slope)
}

/// The factor `F` with `log(c + W) = F W` for a simple versor `c + W` (`W² = w`, `c² - w = 1`):
/// `θ / sin θ` with `θ = atan2(√-w, c)` for `w < 0`, `asinh(√w)/√w` for `w > 0` (needs
/// `c > 0`), `1` for `w = 0` (needs `c > 0`). `None` on the branch cut (`c ≤ 0` where the
/// logarithm is not unique or does not exist).
fn log_real<T: Elementary>(c: &T, w: &T) -> Option<T> {
    if w.abs() < series_threshold() && *c > T::zero() {
        return Some(log_series(w).0);
    }
    if *w < T::zero() {
        let s = (-w.clone()).sqrt();
        Some(s.atan2(c) / s)
    } else if *w > T::zero() && *c > T::zero() {
        let s = w.sqrt();
        Some(s.asinh() / s)
    } else {
        None
    }
}

/// Complex numbers `re + i im` over a real scalar (only what the complex case needs).
#[derive(Clone, Debug)]
struct Cx<T> {
    re: T,
    im: T,
}

impl<T: Elementary> Cx<T> {
    fn new(re: T, im: T) -> Self {
        Cx { re, im }
    }
    fn real(re: T) -> Self {
        Cx::new(re, T::zero())
    }
    fn add(&self, o: &Self) -> Self {
        Cx::new(
            self.re.clone() + o.re.clone(),
            self.im.clone() + o.im.clone(),
        )
    }
    fn mul(&self, o: &Self) -> Self {
        Cx::new(
            self.re.clone() * o.re.clone() - self.im.clone() * o.im.clone(),
            self.re.clone() * o.im.clone() + self.im.clone() * o.re.clone(),
        )
    }
    fn norm2(&self) -> T {
        self.re.clone() * self.re.clone() + self.im.clone() * self.im.clone()
    }
    fn abs(&self) -> T {
        self.norm2().sqrt()
    }
    fn recip(&self) -> Option<Self> {
        let n = self.norm2();
        if n.is_zero() {
            return None;
        }
        Some(Cx::new(self.re.clone() / n.clone(), -self.im.clone() / n))
    }
    fn div(&self, o: &Self) -> Option<Self> {
        Some(self.mul(&o.recip()?))
    }
    /// The principal square root (branch cut on the negative real axis).
    fn sqrt(&self) -> Self {
        let r = self.abs();
        if r.is_zero() {
            return Cx::real(T::zero());
        }
        if self.re >= T::zero() {
            let t = ((r + self.re.clone()) * half()).sqrt();
            let im = self.im.clone() / (two::<T>() * t.clone());
            Cx::new(t, im)
        } else {
            let t = ((r - self.re.clone()) * half()).sqrt();
            let re = self.im.abs() / (two::<T>() * t.clone());
            let im = if self.im < T::zero() { -t } else { t };
            Cx::new(re, im)
        }
    }
    /// The principal logarithm (imaginary part in `(-π, π]`).
    fn ln(&self) -> Self {
        Cx::new(self.norm2().ln() * half(), self.im.atan2(&self.re))
    }
    fn cosh_sinh(&self) -> (Self, Self) {
        let (ch, sh) = (self.re.cosh(), self.re.sinh());
        let (c, s) = (self.im.cos(), self.im.sin());
        (
            Cx::new(ch.clone() * c.clone(), sh.clone() * s.clone()),
            Cx::new(sh * c, ch * s),
        )
    }
    /// Horner evaluation of `Σ coeffs[k] z^k`.
    fn poly(&self, coeffs: &[T]) -> Self {
        let mut acc = Cx::real(T::zero());
        for c in coeffs.iter().rev() {
            acc = acc.mul(self).add(&Cx::real(c.clone()));
        }
        acc
    }
}

fn z_to_cx<T: Elementary>(z: &Z<T>) -> Cx<T> {
    Cx::new(z.a.clone(), z.b.clone())
}

fn cx_to_z<T: Elementary>(c: Cx<T>) -> Z<T> {
    Z::new(c.re, c.im)
}

/// Split case: applies a real function to the components `a ± b` and recombines.
fn split_map<T: Elementary>(z: &Z<T>, f: impl Fn(&T) -> Option<T>) -> Option<Z<T>> {
    let p = f(&(z.a.clone() + z.b.clone()))?;
    let m = f(&(z.a.clone() - z.b.clone()))?;
    Some(Z::new((p.clone() + m.clone()) * half(), (p - m) * half()))
}

/// `(C(x), S(x))` for `x = B²`, so that `exp(B) = C + B S`.
pub(crate) fn exp_parts<T: Elementary>(kind: Kind, x: &Z<T>) -> (Z<T>, Z<T>) {
    match kind {
        Kind::Split => {
            let c = split_map(x, |v| Some(cs_real(v).0));
            let s = split_map(x, |v| Some(cs_real(v).1));
            // Both maps are total; the fallbacks are never taken.
            (
                c.unwrap_or_else(|| Z::new(T::one(), T::zero())),
                s.unwrap_or_else(|| Z::new(T::one(), T::zero())),
            )
        }
        Kind::Dual => {
            let (c0, s0) = cs_real(&x.a);
            let ds = ds_real(&x.a, &c0, &s0);
            let dc = s0.clone() * half();
            (Z::new(c0, dc * x.b.clone()), Z::new(s0, ds * x.b.clone()))
        }
        Kind::Complex => {
            let z = z_to_cx(x);
            if z.abs() < series_threshold() {
                let f = |n: i64| T::one() / T::from_i64(n);
                let c = z.poly(&[T::one(), f(2), f(24), f(720), f(40320)]);
                let s = z.poly(&[T::one(), f(6), f(120), f(5040), f(362880)]);
                return (cx_to_z(c), cx_to_z(s));
            }
            let r = z.sqrt();
            let (ch, sh) = r.cosh_sinh();
            // r ≠ 0 here (|z| is above the series threshold).
            let s = sh.div(&r).unwrap_or_else(|| Cx::real(T::one()));
            (cx_to_z(ch), cx_to_z(s))
        }
    }
}

/// The factor `F` with `log(c + W) = F W` for a unit versor whose scalar-plus-4-vector part is
/// `c` and whose bivector part `W` squares to `w`. `None` where the logarithm is not unique
/// (a component is a rotation by 2π: `c = -1`, `w = 0`) or does not exist (a component with
/// `c ≤ -1` and `w ≥ 0`: minus a boost or a translation, not an exponential).
pub(crate) fn log_factor<T: Elementary>(kind: Kind, c: &Z<T>, w: &Z<T>) -> Option<Z<T>> {
    match kind {
        Kind::Split => {
            let fp = log_real(&(c.a.clone() + c.b.clone()), &(w.a.clone() + w.b.clone()))?;
            let fm = log_real(&(c.a.clone() - c.b.clone()), &(w.a.clone() - w.b.clone()))?;
            Some(Z::new(
                (fp.clone() + fm.clone()) * half(),
                (fp - fm) * half(),
            ))
        }
        Kind::Dual => {
            let (c0, c1, w0, w1) = (&c.a, &c.b, &w.a, &w.b);
            if w0.abs() < series_threshold() && *c0 > T::zero() {
                let (v, d) = log_series(w0);
                return Some(Z::new(v, d * w1.clone()));
            }
            if *w0 < T::zero() {
                // F = θ/s with s = √-w, θ = atan2(s, c), all as dual numbers.
                let s0 = (-w0.clone()).sqrt();
                let s1 = -w1.clone() / (two::<T>() * s0.clone());
                let th0 = s0.atan2(c0);
                let th1 = (c0.clone() * s1.clone() - s0.clone() * c1.clone())
                    / (c0.clone() * c0.clone() + s0.clone() * s0.clone());
                let f0 = th0.clone() / s0.clone();
                let f1 = (th1 * s0.clone() - th0 * s1) / (s0.clone() * s0);
                Some(Z::new(f0, f1))
            } else if *w0 > T::zero() && *c0 > T::zero() {
                // F = asinh(s)/s with s = √w.
                let s0 = w0.sqrt();
                let s1 = w1.clone() / (two::<T>() * s0.clone());
                let a0 = s0.asinh();
                let a1 = s1.clone() / (T::one() + s0.clone() * s0.clone()).sqrt();
                let f0 = a0.clone() / s0.clone();
                let f1 = (a1 * s0.clone() - a0 * s1) / (s0.clone() * s0);
                Some(Z::new(f0, f1))
            } else {
                None
            }
        }
        Kind::Complex => {
            let (cz, wz) = (z_to_cx(c), z_to_cx(w));
            if wz.abs() < series_threshold() {
                if cz.re <= T::zero() {
                    return None;
                }
                let f = |p: i64, q: i64| T::from_i64(p) / T::from_i64(q);
                return Some(cx_to_z(wz.poly(&[
                    T::one(),
                    f(-1, 6),
                    f(3, 40),
                    f(-5, 112),
                ])));
            }
            // F = ln(c + √w) / √w (even in the sign of √w).
            let r = wz.sqrt();
            let u = cz.add(&r);
            if u.norm2().is_zero() {
                return None;
            }
            Some(cx_to_z(u.ln().div(&r)?))
        }
    }
}

/// The principal square root in the algebra, `None` when it does not exist or is not
/// invertible (a component `≤ 0`).
pub(crate) fn sqrt<T: Elementary>(kind: Kind, z: &Z<T>) -> Option<Z<T>> {
    match kind {
        Kind::Split => split_map(z, |v| (*v > T::zero()).then(|| v.sqrt())),
        Kind::Dual => {
            if z.a <= T::zero() {
                return None;
            }
            let r = z.a.sqrt();
            let d = z.b.clone() / (two::<T>() * r.clone());
            Some(Z::new(r, d))
        }
        Kind::Complex => {
            let r = z_to_cx(z).sqrt();
            (!r.norm2().is_zero()).then(|| cx_to_z(r))
        }
    }
}

/// The inverse in the algebra, `None` for a zero divisor.
pub(crate) fn recip<T: Elementary>(kind: Kind, z: &Z<T>) -> Option<Z<T>> {
    match kind {
        Kind::Split => split_map(z, |v| v.checked_recip()),
        Kind::Dual => {
            let r = z.a.checked_recip()?;
            Some(Z::new(r.clone(), -z.b.clone() * r.clone() * r))
        }
        Kind::Complex => Some(cx_to_z(z_to_cx(z).recip()?)),
    }
}

/// `|x| ≤ 64 ε · scale`: rounding noise for floats, exactly zero for exact types.
pub(crate) fn negligible<T: Elementary>(x: &T, scale: &T) -> bool {
    x.abs() <= T::from_i64(64) * T::epsilon() * scale.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Evaluates `Σ xᵏ/(2k)!` and `Σ xᵏ/(2k+1)!` in the algebra directly from their series.
    fn series(kind: Kind, x: &Z<f64>) -> (Z<f64>, Z<f64>) {
        let jj = match kind {
            Kind::Split => 1.0,
            Kind::Complex => -1.0,
            Kind::Dual => 0.0,
        };
        let mul =
            |p: &Z<f64>, q: &Z<f64>| Z::new(p.a * q.a + jj * p.b * q.b, p.a * q.b + p.b * q.a);
        let (mut c, mut s) = (Z::new(0.0, 0.0), Z::new(0.0, 0.0));
        let mut pow = Z::new(1.0, 0.0);
        let mut fact_even = 1.0;
        for k in 0..40 {
            let fact_odd = fact_even * (2 * k + 1) as f64;
            c = Z::new(c.a + pow.a / fact_even, c.b + pow.b / fact_even);
            s = Z::new(s.a + pow.a / fact_odd, s.b + pow.b / fact_odd);
            pow = mul(&pow, x);
            fact_even = fact_odd * (2 * k + 2) as f64;
        }
        (c, s)
    }

    #[test]
    fn exp_parts_agree_with_the_series_in_all_three_systems() {
        for kind in [Kind::Split, Kind::Complex, Kind::Dual] {
            for (a, b) in [
                (0.0, 0.0),
                (-2.0, 0.5),
                (1.5, -0.7),
                (-0.3, 1.2),
                (1e-6, 2e-6),
            ] {
                let x = Z::new(a, b);
                let (c, s) = exp_parts(kind, &x);
                let (cs, ss) = series(kind, &x);
                for (u, v) in [(c.a, cs.a), (c.b, cs.b), (s.a, ss.a), (s.b, ss.b)] {
                    assert!((u - v).abs() < 1e-12, "{kind:?} {a} {b}: {u} vs {v}");
                }
            }
        }
    }

    #[test]
    fn sqrt_and_recip_invert_multiplication() {
        for (kind, jj) in [(Kind::Split, 1.0), (Kind::Complex, -1.0), (Kind::Dual, 0.0)] {
            let z = Z::new(2.0f64, 0.5);
            let r = sqrt(kind, &z).unwrap();
            let sq = Z::new(r.a * r.a + jj * r.b * r.b, 2.0 * r.a * r.b);
            assert!((sq.a - z.a).abs() < 1e-14 && (sq.b - z.b).abs() < 1e-14);
            let i = recip(kind, &z).unwrap();
            let one = Z::new(i.a * z.a + jj * i.b * z.b, i.a * z.b + i.b * z.a);
            assert!((one.a - 1.0).abs() < 1e-14 && one.b.abs() < 1e-14);
        }
    }
}

//! Cl(4,1): translators, rotors, dilators, transversions and general even versors.
//!
//! A bivector squares to `B² = α + β` (scalar plus 4-vector, `β = 2 B₊ ∧ B₋`), and `β²` is a
//! scalar, so `B²` lies in the plane `{a + b J}` with `J ∥ β`, `J² ∈ {+1, -1, 0}` (see
//! [`crate::exp_log`]). The simple versors (rotors, translators, dilators, transversions,
//! `β = 0`) only need the real line.

use super::center::{self, Kind, Z};
use crate::cga::{Bivector, Even, Quadvector, Rotor};
use crate::ops::{Geometric, ScalarProduct};
use crate::scalar::{Elementary, Field, Ring};

fn even_parts<T: Ring>(e: Even<T>) -> (T, Bivector<T>, Quadvector<T>) {
    (
        e.s,
        Bivector::new(
            e.e12, e.e13, e.e14, e.e15, e.e23, e.e24, e.e25, e.e34, e.e35, e.e45,
        ),
        Quadvector::new(e.e1234, e.e1235, e.e1245, e.e1345, e.e2345),
    )
}

fn even_from<T: Ring>(s: T, b: Bivector<T>, q: Quadvector<T>) -> Even<T> {
    Even::from(Rotor::new(
        s, b.e12, b.e13, b.e14, b.e15, b.e23, b.e24, b.e25, b.e34, b.e35, b.e45,
    )) + Even::from(q)
}

fn quad_coeffs<T: Clone>(q: &Quadvector<T>) -> [T; 5] {
    [
        q.e1234.clone(),
        q.e1235.clone(),
        q.e1245.clone(),
        q.e1345.clone(),
        q.e2345.clone(),
    ]
}

/// `Σ qₖ²`, the Euclidean size of the coefficients (not the metric square).
fn coeff_norm2<T: Ring>(q: &Quadvector<T>) -> T {
    quad_coeffs(q)
        .into_iter()
        .fold(T::zero(), |acc, x| acc + x.clone() * x)
}

/// The unit `J` of the plane a 4-vector `q` spans with `1`: `None` (only the real line) when
/// `q` is zero up to rounding against `scale` (the size of the squares it came from);
/// otherwise `J = q/√|q²|` with its kind, or the dual kind with `J = q/|q|` when `q² = 0` up
/// to rounding. (Rounding noise must not pick a plane: minus a boost would get a spurious
/// rotation by π in it.)
fn unit_of<T: Elementary>(q: &Quadvector<T>, scale: &T) -> Option<(Kind, Quadvector<T>)> {
    let e2 = coeff_norm2(q);
    if e2.is_zero() || quad_coeffs(q).iter().all(|x| center::negligible(x, scale)) {
        return None;
    }
    let qq = q.scalar_product(q);
    if center::negligible(&qq, &e2) {
        return Some((Kind::Dual, q.scale(&(T::one() / e2.sqrt()))));
    }
    let kind = if qq > T::zero() {
        Kind::Split
    } else {
        Kind::Complex
    };
    Some((kind, q.scale(&(T::one() / qq.abs().sqrt()))))
}

/// The coordinate `y₁` of `y ≈ y₁ J` (least squares on the coefficients).
fn coord<T: Field>(y: &Quadvector<T>, j: &Quadvector<T>) -> T {
    let dot = quad_coeffs(y)
        .into_iter()
        .zip(quad_coeffs(j))
        .fold(T::zero(), |acc, (a, b)| acc + a * b);
    dot / coeff_norm2(j)
}

/// `(Σ |bₖ|)²`: the scale of rounding errors in products of `b` with itself.
fn biv_size2<T: Elementary>(b: &Bivector<T>) -> T {
    let s = biv_coeffs(b)
        .into_iter()
        .fold(T::zero(), |a, x| a + x.abs());
    s.clone() * s
}

/// `(Σ |coefficients|)²` of `s + b + q`.
fn versor_size2<T: Elementary>(s: &T, q: &Quadvector<T>, b: &Bivector<T>) -> T {
    let size = quad_coeffs(q)
        .into_iter()
        .chain(biv_coeffs(b))
        .fold(s.abs(), |a, x| a + x.abs());
    size.clone() * size
}

fn biv_coeffs<T: Clone>(b: &Bivector<T>) -> [T; 10] {
    [
        b.e12.clone(),
        b.e13.clone(),
        b.e14.clone(),
        b.e15.clone(),
        b.e23.clone(),
        b.e24.clone(),
        b.e25.clone(),
        b.e34.clone(),
        b.e35.clone(),
        b.e45.clone(),
    ]
}

/// The bivector part of `B J`.
fn times<T: Ring>(b: &Bivector<T>, j: &Quadvector<T>) -> Bivector<T> {
    even_parts(b.geometric(j)).1
}

/// `(⟨B²⟩₀, ⟨B²⟩₄)`.
fn square<T: Ring>(b: &Bivector<T>) -> (T, Quadvector<T>) {
    let (s, _, q) = even_parts(b.geometric(b));
    (s, q)
}

/// The plane of `J` (or the real line) and the coordinates of `s + q` in it.
fn in_plane<T: Elementary>(unit: &Option<(Kind, Quadvector<T>)>, s: T, q: &Quadvector<T>) -> Z<T> {
    match unit {
        Some((_, j)) => Z::new(s, coord(q, j)),
        None => Z::new(s, T::zero()),
    }
}

fn kind_of<T>(unit: &Option<(Kind, Quadvector<T>)>) -> Kind {
    unit.as_ref().map_or(Kind::Split, |(k, _)| *k)
}

/// `a X + b (X J)` for `z = a + b J`.
fn apply<T: Ring>(z: &Z<T>, x: &Bivector<T>, unit: &Option<(Kind, Quadvector<T>)>) -> Bivector<T> {
    match unit {
        Some((_, j)) => x.scale(&z.a) + times(x, j).scale(&z.b),
        None => x.scale(&z.a),
    }
}

/// `a + b J` as an even element.
fn scalar_quad<T: Ring>(z: &Z<T>, unit: &Option<(Kind, Quadvector<T>)>) -> (T, Quadvector<T>) {
    match unit {
        Some((_, j)) => (z.a.clone(), j.scale(&z.b)),
        None => (z.a.clone(), Quadvector::zero()),
    }
}

impl<T: Elementary> Bivector<T> {
    /// `exp(B) = C(B²) + B S(B²)` with `C(x) = cosh √x`, `S(x) = sinh √x / √x` evaluated on
    /// `B² = α + β` (see [`crate::exp_log`]): a unit even versor (`V Ṽ = 1`).
    ///
    /// For a simple bivector (`B ∧ B = 0`) this is `cos|B| + B sin|B|/|B|` (`B² < 0`:
    /// rotations), `cosh|B| + B sinh|B|/|B|` (`B² > 0`: dilations, boosts) or `1 + B`
    /// (`B² = 0`: translations, transversions; exact over any ring). A general bivector
    /// (`B ∧ B ≠ 0`) gives the product `exp(B₊) exp(B₋)` of its commuting parts (see
    /// [`split`](Self::split)) without computing them, so it is stable also where the split
    /// is not unique.
    ///
    /// ```
    /// use ga_core::cga::Bivector;
    /// // A screw: a rotation in e12 and a translation along e3 (e3 ∧ n_inf = e34 + e35).
    /// let b = Bivector::new(0.7f64, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.0);
    /// let v = b.exp();
    /// assert!((v.norm_squared() - 1.0).abs() < 1e-15);
    /// assert!(approx::abs_diff_eq!(v.log().unwrap(), b, epsilon = 1e-15));
    /// ```
    pub fn exp(&self) -> Even<T> {
        let (alpha, beta) = square(self);
        let unit = unit_of(&beta, &biv_size2(self));
        let x = in_plane(&unit, alpha, &beta);
        let (c, s) = center::exp_parts(kind_of(&unit), &x);
        let (cs, cq) = scalar_quad(&c, &unit);
        even_from(cs, apply(&s, self, &unit), cq)
    }

    /// The invariant decomposition `B = B₊ + B₋` into commuting simple bivectors (`B₊ B₋ =
    /// B₋ B₊ = B₊ ∧ B₋`, `B±²` scalars `μ₊ ≥ μ₋`): `B± = B (μ± - β/2) / (μ± - μ∓)` with
    /// `μ± = (α ± √(α² - β²))/2` for `B² = α + β`. Then `exp(B) = exp(B₊) exp(B₋)`.
    ///
    /// A simple `B` (`β = 0`) gives `(B, 0)`. `None` when the split is not unique
    /// (`μ₊ = μ₋` up to rounding, e.g. the isoclinic `e12 + e34`) or `B` is not finite.
    ///
    /// ```
    /// use ga_core::cga::Bivector;
    /// use ga_core::prelude::*;
    /// // A rotation in e12 and a boost in e45.
    /// let b = Bivector::new(2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5);
    /// let (p, m) = b.split().unwrap();
    /// assert!(approx::abs_diff_eq!(p, Bivector::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5), epsilon = 1e-15));
    /// assert!(approx::abs_diff_eq!(m, Bivector::new(2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), epsilon = 1e-15));
    /// ```
    pub fn split(&self) -> Option<(Bivector<T>, Bivector<T>)> {
        let (alpha, beta) = square(self);
        let e2 = coeff_norm2(&beta);
        if unit_of(&beta, &biv_size2(self)).is_none() {
            return Some((self.clone(), Bivector::zero()));
        }
        let gamma = beta.scalar_product(&beta);
        let disc = alpha.clone() * alpha.clone() - gamma;
        if !disc.is_finite()
            || center::negligible(&disc, &(alpha.clone() * alpha.clone() + e2))
            || disc < T::zero()
        {
            return None;
        }
        let root = disc.sqrt();
        let half = T::one() / T::from_i64(2);
        let mu_p = (alpha.clone() + root.clone()) * half.clone();
        let mu_m = (alpha - root.clone()) * half.clone();
        let b_beta_half = times(self, &beta).scale(&half);
        let part =
            |mu: &T, denom: T| (self.scale(mu) - b_beta_half.clone()).scale(&(T::one() / denom));
        Some((part(&mu_p, root.clone()), part(&mu_m, -root)))
    }
}

impl<T: Elementary> Even<T> {
    /// The principal logarithm of an even versor: the bivector `B` with `exp(B) = V / |V|`,
    /// where `|V|² = ⟨V Ṽ⟩₀ > 0`.
    ///
    /// Principal range: a rotation part of `B` (a commuting component with `B±² < 0`) has
    /// angle `|B±| < π` (rotation angle below 2π), and when both components are rotations
    /// (two orthogonal Euclidean planes, e.g. `θ₁ e12 + θ₂ e34`) `|θ₁| + |θ₂| < π`, because
    /// `exp(π(e12 + e34)) = 1`. Boosts, dilations, translations and transversions have no
    /// range limit. The scale of `V` is dropped.
    ///
    /// `None` when: `V` is not a versor up to rounding (`⟨V Ṽ⟩₀ ≤ 0`, not finite, or
    /// `⟨V Ṽ⟩₄` not negligible against the coefficients); or `V / |V|` is on the branch cut,
    /// where the logarithm is not unique (a rotation part by 2π, e.g. `-1`, or `e1234`, a
    /// rotation by π in two orthogonal planes); or it has none (minus a translation or minus a
    /// dilation alone: `-1 - t`, `-exp(d e45)`; note `-exp(b e45)` *with* a rotation part
    /// exists and is returned). Near the cut the answer is ill-conditioned.
    ///
    /// Translators and transversions (`V = 1 + N`, `N² = 0`) give exactly `N` over rationals.
    pub fn log(&self) -> Option<Bivector<T>> {
        let (c0, cq, w) = self.normalized_parts()?;
        let size2 = versor_size2(&c0, &cq, &w);
        let (w0, wq) = square(&w);
        // The plane {1, J}: from whichever 4-vector is larger (both lie in it for versors).
        let q = if coeff_norm2(&cq) >= coeff_norm2(&wq) {
            &cq
        } else {
            &wq
        };
        let unit = unit_of(q, &size2);
        let c = in_plane(&unit, c0, &cq);
        let w2 = in_plane(&unit, w0, &wq);
        let f = center::log_factor(kind_of(&unit), &c, &w2)?;
        Some(apply(&f, &w, &unit))
    }

    /// The principal square root of an even versor: `Q` with `Q² = V` and `log Q = ½ log V`,
    /// `√|V| (1 + V̂) N⁻¹` with `N² = 2(1 + ⟨V̂⟩₀ + ⟨V̂⟩₄)` (`N = Q + Q̃` commutes with `Q`).
    /// `None` where [`log`](Self::log) is `None` (not a versor, or on the branch cut) and
    /// where `N` is not invertible. Exact over rationals for translators and transversions
    /// (`√(1 + N) = 1 + N/2`).
    pub fn sqrt(&self) -> Option<Even<T>> {
        let lambda = self.norm_squared().sqrt();
        let (c0, cq, w) = self.normalized_parts()?;
        let unit = unit_of(&cq, &versor_size2(&c0, &cq, &w));
        let c = in_plane(&unit, c0.clone(), &cq);
        let two = T::from_i64(2);
        let n2 = Z::new(two.clone() * (T::one() + c.a), two * c.b);
        let kind = kind_of(&unit);
        let ninv = center::recip(kind, &center::sqrt(kind, &n2)?)?;
        let one_plus = even_from(T::one() + c0, w, cq);
        let (ns, nq) = scalar_quad(&ninv, &unit);
        let q = one_plus.geometric(&even_from(ns, Bivector::zero(), nq));
        Some(q.scale(&lambda.sqrt()))
    }

    /// `V / |V|` as `(⟨V̂⟩₀, ⟨V̂⟩₄, ⟨V̂⟩₂)`, `None` unless `V` is a versor up to rounding.
    fn normalized_parts(&self) -> Option<(T, Quadvector<T>, Bivector<T>)> {
        let n = self.norm_squared();
        if n <= T::zero() || !n.is_finite() {
            return None;
        }
        let (_, _, vv4) = even_parts(self.geometric(&self.reverse()));
        let (s, b, q) = even_parts(self.clone());
        let scale = versor_size2(&s, &q, &b);
        if !quad_coeffs(&vv4)
            .iter()
            .all(|x| center::negligible(x, &scale))
        {
            return None;
        }
        let inv = T::one() / n.sqrt();
        Some((s * inv.clone(), q.scale(&inv), b.scale(&inv)))
    }
}

impl<T: Elementary> Rotor<T> {
    /// The principal logarithm of a simple versor (rotor, translator, dilator, transversion,
    /// or a product of two vectors): see [`Even::log`], of which this is the special case
    /// `⟨V⟩₄ = 0`. `None` also when the bivector part is not a blade (then `V` is not a
    /// versor).
    ///
    /// ```
    /// use ga_core::cga::Rotor;
    /// let t = Rotor::translator([1.0, -2.0, 0.5]);
    /// let b = t.log().unwrap();
    /// assert_eq!(b.exp(), t.into());
    /// ```
    pub fn log(&self) -> Option<Bivector<T>> {
        Even::from(self.clone()).log()
    }

    /// The principal square root of a simple versor, `√|V| (1 + V̂)/√(2(1 + ⟨V̂⟩₀))`:
    /// see [`Even::sqrt`].
    pub fn sqrt(&self) -> Option<Rotor<T>> {
        let q = Even::from(self.clone()).sqrt()?;
        let (s, b, _) = even_parts(q);
        Some(Rotor::new(
            s, b.e12, b.e13, b.e14, b.e15, b.e23, b.e24, b.e25, b.e34, b.e35, b.e45,
        ))
    }
}

impl<T: Field> Rotor<T> {
    /// The translator by `t`: `T = exp(-½ t n_inf) = 1 - ½ t ∧ n_inf`, with `T up(x) T̃ =
    /// up(x + t)`. Ring operations only: exact over rationals.
    ///
    /// ```
    /// use ga_core::cga::{down, up, Rotor};
    /// use ga_core::prelude::*;
    /// use nalgebra::Point3;
    /// let t = Rotor::translator([1.0, 2.0, 3.0]);
    /// let p = t.sandwich_unit(&up(&Point3::new(0.5, 0.5, 0.5)));
    /// assert_eq!(down(&p), Some(Point3::new(1.5, 2.5, 3.5)));
    /// ```
    pub fn translator(t: [T; 3]) -> Self {
        // t ∧ n_inf = Σ tᵢ (eᵢ4 + eᵢ5).
        let h = T::one() / T::from_i64(2);
        let [x, y, z] = t.map(|c| -(c * h.clone()));
        Rotor::new(
            T::one(),
            T::zero(),
            T::zero(),
            x.clone(),
            x,
            T::zero(),
            y.clone(),
            y,
            z.clone(),
            z,
            T::zero(),
        )
    }

    /// The transversion by `b`: `K = exp(n_0 ∧ b) = 1 + n_0 ∧ b`, the translation by `b`
    /// conjugated by the inversion in the unit sphere: it fixes the origin and maps `x` to
    /// `(x + |x|² b) / (1 + 2 b·x + |b|²|x|²)`. Exact over rationals.
    pub fn transversion(b: [T; 3]) -> Self {
        // n_0 ∧ b = ½ Σ bᵢ (e5 - e4) ∧ eᵢ = ½ Σ bᵢ (eᵢ4 - eᵢ5).
        let h = T::one() / T::from_i64(2);
        let [x, y, z] = b.map(|c| c * h.clone());
        Rotor::new(
            T::one(),
            T::zero(),
            T::zero(),
            x.clone(),
            -x,
            T::zero(),
            y.clone(),
            -y,
            z.clone(),
            -z,
            T::zero(),
        )
    }
}

impl<T: Elementary> Rotor<T> {
    /// The rotation by `angle` about the axis `axis` through the origin (right-handed):
    /// `exp(-½ angle · a e123)` for the unit axis `a`, the plane bivector `a e123 = a₁ e23 -
    /// a₂ e13 + a₃ e12`. `None` for a zero or non-finite axis.
    ///
    /// ```
    /// use ga_core::cga::{down, up, Rotor};
    /// use ga_core::prelude::*;
    /// use nalgebra::Point3;
    /// let r = Rotor::rotation([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2).unwrap();
    /// let p = down(&r.sandwich_unit(&up(&Point3::new(1.0, 0.0, 0.0)))).unwrap();
    /// assert!((p - Point3::new(0.0, 1.0, 0.0)).norm() < 1e-15);
    /// ```
    pub fn rotation(axis: [T; 3], angle: T) -> Option<Self> {
        let n2 = axis
            .iter()
            .fold(T::zero(), |a, x| a + x.clone() * x.clone());
        if n2 <= T::zero() || !n2.is_finite() {
            return None;
        }
        let half = angle * (T::one() / T::from_i64(2));
        let k = -(half.sin() / n2.sqrt());
        let [a1, a2, a3] = axis;
        let z = T::zero();
        Some(Rotor::new(
            half.cos(),
            a3 * k.clone(),
            -(a2 * k.clone()),
            z.clone(),
            z.clone(),
            a1 * k,
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z,
        ))
    }

    /// The dilation by `factor > 0` about the origin: `D = exp(-½ ln(factor) · e45)`, with
    /// `down(D up(x) D̃) = factor · x`. `None` unless `factor` is positive and finite.
    /// (`e45 = n_inf ∧ n_0`.)
    pub fn dilator(factor: T) -> Option<Self> {
        if factor <= T::zero() || !factor.is_finite() {
            return None;
        }
        let g = -(factor.ln() * (T::one() / T::from_i64(2)));
        let z = T::zero();
        Some(Rotor::new(
            g.cosh(),
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z.clone(),
            z,
            g.sinh(),
        ))
    }
}

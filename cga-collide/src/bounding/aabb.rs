//! The axis-aligned box of the hierarchies, in `f64`: built from the vertex coordinates with
//! `min`/`max`, which is exact, so a triangle's box contains the triangle and a union contains
//! its parts. The segment and ball/sphere tests round, and are widened by a relative slack far
//! larger than their rounding error, so they never reject a box that the exact real segment or
//! ball meets.

use nalgebra::Point3;

#[inline(always)]
fn mn(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

#[inline(always)]
fn mx(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// An axis-aligned box `[min, max]` (closed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: [f64; 3],
    /// Largest corner.
    pub max: [f64; 3],
}

impl Aabb {
    /// The empty box (`min = +∞`, `max = -∞`), identity of [`union`](Self::union).
    pub const EMPTY: Aabb = Aabb {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
    };

    /// The smallest box holding the points (exact).
    pub fn of_points(points: &[Point3<f64>]) -> Aabb {
        let mut b = Aabb::EMPTY;
        for p in points {
            b.grow(p);
        }
        b
    }

    /// Extends the box to hold `p` (exact).
    #[inline]
    pub fn grow(&mut self, p: &Point3<f64>) {
        for k in 0..3 {
            self.min[k] = mn(self.min[k], p[k]);
            self.max[k] = mx(self.max[k], p[k]);
        }
    }

    /// The smallest box holding both (exact).
    #[inline]
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: [
                mn(self.min[0], o.min[0]),
                mn(self.min[1], o.min[1]),
                mn(self.min[2], o.min[2]),
            ],
            max: [
                mx(self.max[0], o.max[0]),
                mx(self.max[1], o.max[1]),
                mx(self.max[2], o.max[2]),
            ],
        }
    }

    /// Whether the closed boxes share a point (exact).
    #[inline]
    pub fn overlaps(&self, o: &Aabb) -> bool {
        self.min[0] <= o.max[0]
            && o.min[0] <= self.max[0]
            && self.min[1] <= o.max[1]
            && o.min[1] <= self.max[1]
            && self.min[2] <= o.max[2]
            && o.min[2] <= self.max[2]
    }

    /// Half the surface area (the SAH weight); 0 for the empty box.
    pub fn half_area(&self) -> f64 {
        let d = [
            self.max[0] - self.min[0],
            self.max[1] - self.min[1],
            self.max[2] - self.min[2],
        ];
        if d.iter().any(|x| x.is_nan() || *x < 0.0) {
            return 0.0;
        }
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    }

    /// Conservative test: `false` only if the closed segment `[p, q]` (exact reals) misses the
    /// box. A slab test in `f64` whose parameter interval is widened far beyond its rounding.
    pub fn may_meet_segment(&self, p: &Point3<f64>, q: &Point3<f64>) -> bool {
        for k in 0..3 {
            if p[k].max(q[k]) < self.min[k] || p[k].min(q[k]) > self.max[k] {
                return false;
            }
        }
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for k in 0..3 {
            let d = q[k] - p[k];
            if d == 0.0 {
                continue; // p[k] == q[k], inside the slab by the test above
            }
            if !d.is_finite() {
                return true;
            }
            let ta = (self.min[k] - p[k]) / d;
            let tb = (self.max[k] - p[k]) / d;
            let (lo, hi) = if ta <= tb { (ta, tb) } else { (tb, ta) };
            if lo.is_nan() || hi.is_nan() {
                return true;
            }
            t0 = t0.max(lo);
            t1 = t1.min(hi);
        }
        if !(t0.is_finite() && t1.is_finite()) {
            return true;
        }
        // Each t carries a relative error of a few ulps; 1e-9 relative (plus an absolute term
        // for underflow) is a wide margin.
        t0 <= t1 + (t0.abs() + t1.abs()) * 1e-9 + 1e-300
    }

    /// Squared distances from `c` to the nearest and the farthest point of the box, in `f64`.
    fn distances2(&self, c: &Point3<f64>) -> (f64, f64) {
        let (mut near, mut far) = (0.0, 0.0);
        for k in 0..3 {
            let below = self.min[k] - c[k];
            let above = c[k] - self.max[k];
            let n = below.max(above).max(0.0);
            let f = (c[k] - self.min[k]).max(self.max[k] - c[k]);
            near += n * n;
            far += f * f;
        }
        (near, far)
    }

    /// Whether the closed box meets the ray from `p` along `+x` (exact: comparisons only); the
    /// candidates of the ray-parity point-in-solid test.
    #[inline]
    pub fn meets_x_ray(&self, p: &Point3<f64>) -> bool {
        self.min[1] <= p.y
            && p.y <= self.max[1]
            && self.min[2] <= p.z
            && p.z <= self.max[2]
            && self.max[0] >= p.x
    }

    /// Conservative test: `false` only if the closed ball (centre `c`, radius `r`) misses the
    /// box.
    pub fn may_meet_ball(&self, c: &Point3<f64>, r: f64) -> bool {
        let (near, _) = self.distances2(c);
        let r2 = r * r;
        !(near.is_finite() && r2.is_finite()) || near * (1.0 - 1e-9) <= r2 * (1.0 + 1e-9) + 1e-300
    }

    /// Conservative test: `false` only if the sphere *surface* (centre `c`, radius `r`) misses
    /// the box, i.e. the box is away from the ball or strictly inside it.
    pub fn may_meet_sphere(&self, c: &Point3<f64>, r: f64) -> bool {
        let (near, far) = self.distances2(c);
        let r2 = r * r;
        if !(near.is_finite() && far.is_finite() && r2.is_finite()) {
            return true;
        }
        near * (1.0 - 1e-9) <= r2 * (1.0 + 1e-9) + 1e-300
            && far * (1.0 + 1e-9) + 1e-300 >= r2 * (1.0 - 1e-9)
    }
}

/// The box of a triangle of a mesh (exact).
#[inline]
pub fn triangle_box(vertices: &[Point3<f64>], t: &[u32; 3]) -> Aabb {
    let (a, b, c) = (
        &vertices[t[0] as usize],
        &vertices[t[1] as usize],
        &vertices[t[2] as usize],
    );
    Aabb {
        min: [
            mn(mn(a.x, b.x), c.x),
            mn(mn(a.y, b.y), c.y),
            mn(mn(a.z, b.z), c.z),
        ],
        max: [
            mx(mx(a.x, b.x), c.x),
            mx(mx(a.y, b.y), c.y),
            mx(mx(a.z, b.z), c.z),
        ],
    }
}

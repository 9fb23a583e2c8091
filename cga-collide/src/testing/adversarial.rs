//! Deterministic adversarial inputs: coplanar and collinear configurations, touching at a
//! vertex or along an edge, shared vertices and edges, a triangle in the other's plane,
//! degenerate triangles and segments, tangent spheres, one-ulp perturbations of all of these,
//! and coordinates scaled from `1e-150` to `1e150`.
//!
//! Used by the property tests, by the `adversarial_table` example (the README table) and by the
//! near-degenerate benchmarks. Base configurations use small integers and dyadic combinations
//! so that touching is exact; a random axis permutation, sign flips, translation and scale
//! (powers of two keep exactness, powers of ten round) are applied on top.

use nalgebra::Point3;

use crate::exact::Kernel;
use crate::query::intersects::IntersectsWith;
use crate::query::Intersects;
use crate::shape::{Ball, Segment, Sphere, Triangle};

/// A small deterministic pseudo-random generator (SplitMix64).
#[derive(Debug, Clone)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// A uniform integer in `lo..=hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % ((hi - lo + 1) as u64)) as i64
    }
    /// A uniform float in `[lo, hi)`.
    pub fn float(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }
    /// One element of a non-empty slice.
    pub fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[(self.next_u64() % xs.len() as u64) as usize]
    }
    /// A point with uniform coordinates in `[-1, 1)`.
    pub fn point(&mut self) -> Point3<f64> {
        Point3::new(
            self.float(-1.0, 1.0),
            self.float(-1.0, 1.0),
            self.float(-1.0, 1.0),
        )
    }
    fn ipoint(&mut self, r: i64) -> [f64; 3] {
        [
            self.int(-r, r) as f64,
            self.int(-r, r) as f64,
            self.int(-r, r) as f64,
        ]
    }
}

/// The scales applied to adversarial configurations.
pub const SCALES: [f64; 9] = [
    1e-150,
    8.636168555094445e-78,
    1e-20,
    1e-3,
    1.0,
    1e3,
    1e20,
    1.157920892373162e77,
    1e150,
];

type P = [f64; 3];

fn lerp(a: &P, b: &P, num: f64, den: f64) -> P {
    // a + (b - a) * num / den with small dyadic weights: exact for small integer inputs.
    [
        a[0] + (b[0] - a[0]) * num / den,
        a[1] + (b[1] - a[1]) * num / den,
        a[2] + (b[2] - a[2]) * num / den,
    ]
}

/// A rigid-ish exact-friendly transform: axis permutation, sign flips, integer translation,
/// then a scale.
#[derive(Debug, Clone, Copy)]
struct Transform {
    perm: [usize; 3],
    sign: [f64; 3],
    shift: P,
    scale: f64,
}

impl Transform {
    fn random(rng: &mut SplitMix64) -> Self {
        let perms = [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ];
        Transform {
            perm: rng.pick(&perms),
            sign: [
                rng.pick(&[1.0, -1.0]),
                rng.pick(&[1.0, -1.0]),
                rng.pick(&[1.0, -1.0]),
            ],
            shift: rng.ipoint(6),
            scale: rng.pick(&SCALES),
        }
    }
    fn apply(&self, p: &P) -> Point3<f64> {
        let q: Vec<f64> = (0..3)
            .map(|i| (p[self.perm[i]] * self.sign[i] + self.shift[i]) * self.scale)
            .collect();
        Point3::new(q[0], q[1], q[2])
    }
    fn len(&self, r: f64) -> f64 {
        r * self.scale
    }
}

/// Moves one coordinate of one point by `k` ulps (`k` in -2..=2, possibly 0).
fn nudge(rng: &mut SplitMix64, pts: &mut [Point3<f64>]) {
    let i = rng.int(0, pts.len() as i64 - 1) as usize;
    let axis = rng.int(0, 2) as usize;
    let k = rng.int(-2, 2);
    let mut x = pts[i].coords[axis];
    for _ in 0..k.abs() {
        x = if k > 0 { x.next_up() } else { x.next_down() };
    }
    pts[i].coords[axis] = x;
}

fn nudge_len(rng: &mut SplitMix64, r: f64) -> f64 {
    match rng.int(0, 4) {
        0 => r.next_up(),
        1 => r.next_down().max(0.0),
        _ => r,
    }
}

/// A triangle pair in a special position (before transformation), by kind.
fn base_triangle_pair(rng: &mut SplitMix64) -> ([P; 3], [P; 3]) {
    let a = [rng.ipoint(4), rng.ipoint(4), rng.ipoint(4)];
    let kind = rng.int(0, 9);
    let r = rng.ipoint(4);
    let s = rng.ipoint(4);
    let b = match kind {
        // Shared vertex.
        0 => [a[0], r, s],
        // Shared edge.
        1 => [a[0], a[1], r],
        // Vertex on an edge of the other.
        2 => [lerp(&a[0], &a[1], 1.0, 2.0), r, s],
        // Vertex inside the other (dyadic barycentric point).
        3 => [lerp(&lerp(&a[0], &a[1], 1.0, 4.0), &a[2], 1.0, 2.0), r, s],
        // Coplanar: combinations of the first triangle's vertices.
        4 => [
            lerp(&a[0], &a[1], rng.int(-4, 8) as f64, 4.0),
            lerp(&a[1], &a[2], rng.int(-4, 8) as f64, 4.0),
            lerp(&a[2], &a[0], rng.int(-4, 8) as f64, 4.0),
        ],
        // Edge through an edge: both ends of an edge of b on the two sides, crossing a's edge.
        5 => {
            let m = lerp(&a[0], &a[1], 1.0, 2.0);
            let d = [r[0] - m[0], r[1] - m[1], r[2] - m[2]];
            [[m[0] - d[0], m[1] - d[1], m[2] - d[2]], r, s]
        }
        // Degenerate (collinear or repeated) second triangle touching the first.
        6 => [a[1], lerp(&a[1], &r, 1.0, 2.0), r],
        7 => [a[2], a[2], r],
        // In the plane of the first but outside / overlapping by an edge line.
        8 => [
            lerp(&a[0], &a[1], 2.0, 1.0),
            lerp(&a[0], &a[1], 3.0, 1.0),
            lerp(&a[0], &a[2], -1.0, 1.0),
        ],
        // General integer position.
        _ => [r, s, rng.ipoint(4)],
    };
    (a, b)
}

/// One adversarial test case.
#[derive(Debug, Clone, Copy)]
pub enum Case {
    /// Segment–segment.
    SegSeg(Segment, Segment),
    /// Segment–triangle.
    SegTri(Segment, Triangle),
    /// Segment–sphere.
    SegSphere(Segment, Sphere),
    /// Segment–ball.
    SegBall(Segment, Ball),
    /// Triangle–triangle.
    TriTri(Triangle, Triangle),
    /// Triangle–sphere.
    TriSphere(Triangle, Sphere),
    /// Triangle–ball.
    TriBall(Triangle, Ball),
    /// Sphere–sphere.
    SphereSphere(Sphere, Sphere),
    /// Ball–ball.
    BallBall(Ball, Ball),
}

/// Runs `$e` with `$a`, `$b` bound to the two shapes of any case.
macro_rules! on_pair {
    ($case:expr, $a:ident, $b:ident => $e:expr) => {
        match $case {
            Case::SegSeg($a, $b) => $e,
            Case::SegTri($a, $b) => $e,
            Case::SegSphere($a, $b) => $e,
            Case::SegBall($a, $b) => $e,
            Case::TriTri($a, $b) => $e,
            Case::TriSphere($a, $b) => $e,
            Case::TriBall($a, $b) => $e,
            Case::SphereSphere($a, $b) => $e,
            Case::BallBall($a, $b) => $e,
        }
    };
}

impl Case {
    /// A short name of the pair kind.
    pub fn kind(&self) -> &'static str {
        match self {
            Case::SegSeg(..) => "segment–segment",
            Case::SegTri(..) => "segment–triangle",
            Case::SegSphere(..) => "segment–sphere",
            Case::SegBall(..) => "segment–ball",
            Case::TriTri(..) => "triangle–triangle",
            Case::TriSphere(..) => "triangle–sphere",
            Case::TriBall(..) => "triangle–ball",
            Case::SphereSphere(..) => "sphere–sphere",
            Case::BallBall(..) => "ball–ball",
        }
    }

    /// The true answer, from the independent exact oracle ([`crate::testing::oracle`]), which shares no
    /// code with the tests it checks.
    pub fn truth(&self) -> bool {
        use crate::testing::oracle::{self, Shape};
        on_pair!(self, a, b => oracle::intersects(&Shape::from(a), &Shape::from(b)))
    }

    /// The library's test of the pair with the sign kernel `K` (`a.intersects_with::<K>(b)`).
    pub fn intersects_with<K: Kernel>(&self) -> bool {
        on_pair!(self, a, b => a.intersects_with::<K>(b))
    }

    /// The library's exact test with the arguments swapped (`b.intersects(a)`); both orders
    /// must give the same answer.
    pub fn intersects_swapped(&self) -> bool {
        on_pair!(self, a, b => b.intersects(a))
    }
}

fn tri(t: &Transform, p: &[P; 3]) -> Option<Triangle> {
    Triangle::new(t.apply(&p[0]), t.apply(&p[1]), t.apply(&p[2])).ok()
}

/// Adversarial triangle pairs (`n` of them, deterministic in `seed`).
pub fn triangle_pairs(seed: u64, n: usize) -> Vec<(Triangle, Triangle)> {
    let mut rng = SplitMix64(seed);
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (a, b) = base_triangle_pair(&mut rng);
        let tr = Transform::random(&mut rng);
        let (Some(t1), Some(t2)) = (tri(&tr, &a), tri(&tr, &b)) else {
            continue;
        };
        let mut v = [
            t1.vertices()[0],
            t1.vertices()[1],
            t1.vertices()[2],
            t2.vertices()[0],
            t2.vertices()[1],
            t2.vertices()[2],
        ];
        if rng.int(0, 2) == 0 {
            nudge(&mut rng, &mut v);
        }
        let (Ok(t1), Ok(t2)) = (
            Triangle::new(v[0], v[1], v[2]),
            Triangle::new(v[3], v[4], v[5]),
        ) else {
            continue;
        };
        if rng.int(0, 1) == 0 {
            out.push((t1, t2));
        } else {
            out.push((t2, t1));
        }
    }
    out
}

/// Pythagorean quadruples `(x, y, z, l)` with `x² + y² + z² = l²`.
const QUADS: [[f64; 4]; 6] = [
    [1.0, 2.0, 2.0, 3.0],
    [2.0, 3.0, 6.0, 7.0],
    [1.0, 4.0, 8.0, 9.0],
    [2.0, 6.0, 9.0, 11.0],
    [0.0, 3.0, 4.0, 5.0],
    [2.0, 10.0, 11.0, 15.0],
];

fn quad_dir(rng: &mut SplitMix64) -> (P, f64) {
    let q = rng.pick(&QUADS);
    let s = [
        rng.pick(&[1.0, -1.0]),
        rng.pick(&[1.0, -1.0]),
        rng.pick(&[1.0, -1.0]),
    ];
    ([q[0] * s[0], q[1] * s[1], q[2] * s[2]], q[3])
}

/// A sphere/ball centre and radius in a special position with respect to the segment or
/// triangle with vertices `v` (before transformation): touching at a vertex, tangent to an
/// edge line or the plane, containing the shape with a vertex on the surface, and so on.
fn special_sphere(rng: &mut SplitMix64, v: &[P]) -> (P, f64) {
    let (d, l) = quad_dir(rng);
    let k = rng.int(1, 3) as f64;
    match rng.int(0, 5) {
        // A vertex on the surface, centre away along an integer direction of integer length.
        0 | 1 => {
            let p = v[rng.int(0, v.len() as i64 - 1) as usize];
            ([p[0] + k * d[0], p[1] + k * d[1], p[2] + k * d[2]], k * l)
        }
        // Centre at a vertex or edge midpoint, radius an exact distance to another vertex.
        2 => {
            let c = lerp(&v[0], &v[v.len() - 1], rng.int(0, 2) as f64, 2.0);
            let p = v[rng.int(0, v.len() as i64 - 1) as usize];
            let dd = (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2) + (p[2] - c[2]).powi(2);
            (c, dd.sqrt())
        }
        // Tangent to the plane z = const through the shape when it is flat (or just nearby).
        3 => {
            let c = lerp(&v[0], &v[1 % v.len()], 1.0, 2.0);
            (c, k)
        }
        // Zero radius on a vertex.
        4 => (v[0], 0.0),
        _ => (rng.ipoint(5), rng.int(0, 6) as f64),
    }
}

fn sphere_pair(rng: &mut SplitMix64) -> (P, f64, P, f64) {
    let c1 = rng.ipoint(4);
    let (d, l) = quad_dir(rng);
    let k = rng.int(1, 3) as f64;
    let c2 = [c1[0] + k * d[0], c1[1] + k * d[1], c1[2] + k * d[2]];
    let dist = k * l;
    let r1 = rng.int(0, (2.0 * dist) as i64) as f64;
    let r2 = match rng.int(0, 4) {
        0 => (dist - r1).abs(), // externally or internally tangent
        1 => r1 + dist,         // internally tangent, larger
        2 => r1,                // equal radii
        3 => rng.int(0, 3 * dist as i64) as f64,
        _ => 0.0,
    };
    if rng.int(0, 5) == 0 {
        (c1, r1, c1, r2) // concentric
    } else {
        (c1, r1, c2, r2)
    }
}

/// The fixed adversarial set: `per_kind` cases of each of the nine pair kinds.
pub fn adversarial_set(seed: u64, per_kind: usize) -> Vec<Case> {
    let mut rng = SplitMix64(seed);
    let mut out = Vec::new();
    for (t1, t2) in triangle_pairs(seed ^ 0x5151, per_kind) {
        out.push(Case::TriTri(t1, t2));
    }
    let mut counts = [0usize; 8];
    while counts.iter().any(|&c| c < per_kind) {
        let (a, b) = base_triangle_pair(&mut rng);
        let tr = Transform::random(&mut rng);
        let (Some(t1), Some(t2)) = (tri(&tr, &a), tri(&tr, &b)) else {
            continue;
        };
        let seg_of =
            |t: &Triangle, i: usize| Segment::new(t.vertices()[i], t.vertices()[(i + 1) % 3]).ok();
        let which = rng.int(0, 7) as usize;
        if counts[which] >= per_kind {
            continue;
        }
        let case = match which {
            0 => {
                let (Some(s1), Some(s2)) = (seg_of(&t1, 0), seg_of(&t2, rng.int(0, 2) as usize))
                else {
                    continue;
                };
                let mut v = [*s1.a(), *s1.b(), *s2.a(), *s2.b()];
                if rng.int(0, 2) == 0 {
                    nudge(&mut rng, &mut v);
                }
                match (Segment::new(v[0], v[1]), Segment::new(v[2], v[3])) {
                    (Ok(a), Ok(b)) => Case::SegSeg(a, b),
                    _ => continue,
                }
            }
            1 => {
                let Some(s) = seg_of(&t2, rng.int(0, 2) as usize) else {
                    continue;
                };
                let mut v = [
                    *s.a(),
                    *s.b(),
                    t1.vertices()[0],
                    t1.vertices()[1],
                    t1.vertices()[2],
                ];
                if rng.int(0, 2) == 0 {
                    nudge(&mut rng, &mut v);
                }
                match (Segment::new(v[0], v[1]), Triangle::new(v[2], v[3], v[4])) {
                    (Ok(s), Ok(t)) => Case::SegTri(s, t),
                    _ => continue,
                }
            }
            2..=5 => {
                let flat: Vec<P> = if which <= 3 {
                    vec![a[0], a[1]]
                } else {
                    a.to_vec()
                };
                let (c, r) = special_sphere(&mut rng, &flat);
                let c = tr.apply(&c);
                let r = nudge_len(&mut rng, tr.len(r));
                let pts: Vec<Point3<f64>> = flat.iter().map(|p| tr.apply(p)).collect();
                let (Ok(sp), Ok(ba)) = (Sphere::new(c, r), Ball::new(c, r)) else {
                    continue;
                };
                match which {
                    2 => Case::SegSphere(Segment::new(pts[0], pts[1]).expect("finite"), sp),
                    3 => Case::SegBall(Segment::new(pts[0], pts[1]).expect("finite"), ba),
                    4 => {
                        Case::TriSphere(Triangle::new(pts[0], pts[1], pts[2]).expect("finite"), sp)
                    }
                    _ => Case::TriBall(Triangle::new(pts[0], pts[1], pts[2]).expect("finite"), ba),
                }
            }
            _ => {
                let (c1, r1, c2, r2) = sphere_pair(&mut rng);
                let (c1, c2) = (tr.apply(&c1), tr.apply(&c2));
                let (r1, r2) = (nudge_len(&mut rng, tr.len(r1)), tr.len(r2));
                if which == 6 {
                    match (Sphere::new(c1, r1), Sphere::new(c2, r2)) {
                        (Ok(a), Ok(b)) => Case::SphereSphere(a, b),
                        _ => continue,
                    }
                } else {
                    match (Ball::new(c1, r1), Ball::new(c2, r2)) {
                        (Ok(a), Ok(b)) => Case::BallBall(a, b),
                        _ => continue,
                    }
                }
            }
        };
        counts[which] += 1;
        out.push(case);
    }
    out
}

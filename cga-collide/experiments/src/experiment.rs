//! The experiment of the double-sphere paper (§5, Tables 2 and 3), run on the exact
//! hierarchy of [`cga_collide::hierarchy::double_sphere`] and checked, placement by placement, against the
//! independent exact reference [`cga_collide::testing::convex::ConvexMeshRef::collides_solid`].
//!
//! Two convex polyhedra (circumradius 1, see [`cga_collide::shape::polyhedron`]) are placed with their
//! centres uniformly at random inside an *experiment sphere* and with uniformly random
//! orientations (Arvo's fast random rotation matrices, which the paper cites). The sphere's
//! radius is chosen ([`calibrate_radius`]) so that about 25 % ("large") or 75 % ("small") of
//! the placements collide. For every placement the hierarchy answers (timed) and the reference
//! answers; any disagreement is a [`Mismatch`].
//!
//! Every placement is generated from its own seed (`seed`, index), so the result does not
//! depend on the number of threads and any placement can be replayed with [`placement`].
//!
//! ```
//! use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
//! use cga_experiments::experiment::{calibrate_radius, run, Variant};
//! use cga_collide::shape::polyhedron::ConvexPolyhedron;
//!
//! let (a, b) = (ConvexPolyhedron::cube(), ConvexPolyhedron::octahedron());
//! let radius = calibrate_radius(&a, &b, 0.5, 2_000, 7);
//! let variants = [Variant {
//!     a: DoubleSphereTree::build(&a, 3, InnerSphereKind::Centroid)?,
//!     b: DoubleSphereTree::build(&b, 3, InnerSphereKind::Centroid)?,
//! }];
//! let result = run(&variants, radius, 1_000, 7, &|_| {});
//! assert_eq!(result.mismatches.len(), 0);
//! let colliding = result.reference_collisions as f64 / 1_000.0;
//! assert!((0.35..0.65).contains(&colliding));
//! # Ok::<(), cga_collide::Error>(())
//! ```

use std::f64::consts::PI;
use std::time::Instant;

use nalgebra::{Isometry3, Matrix3, Point3, Rotation3, Translation3, UnitQuaternion};
use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};
use rayon::prelude::*;

use cga_collide::hierarchy::double_sphere::{Decision, DoubleSphereTree};
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::testing::convex::{Certificate, ConvexMeshRef};

/// The four pairs of the paper's experiment, in the order of its tables.
pub const PAPER_PAIRS: [(&str, &str); 4] = [
    ("truncated_octahedron", "diamond"),
    ("truncated_octahedron", "rh"),
    ("octahedron", "diamond"),
    ("cube", "cube"),
];

/// One row of the paper's Tables 2 and 3 (its §5): for the large experiment sphere (25 %
/// collisions) and the small one (75 %), the collisions decided by inner spheres and by faces,
/// and the mean time of each in µs (C++, g++ 4.0.3, Xeon 2.8 GHz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperRow {
    /// `[large inner, large faces, small inner, small faces]` (Table 3).
    pub counts: [u64; 4],
    /// `[large inner, large faces, small inner, small faces]` in µs (Table 2).
    pub micros: [f64; 4],
}

/// The paper's Tables 2 and 3, rows in the order of [`PAPER_PAIRS`]. Its counts add up to
/// about 25 % and 75 % of 100,000 placements (although its text says 1,000,000 runs).
pub const PAPER_TABLES: [PaperRow; 4] = [
    PaperRow {
        counts: [15229, 10273, 54842, 21803],
        micros: [3.99, 127.62, 3.07, 118.13],
    },
    PaperRow {
        counts: [19067, 6297, 62718, 12359],
        micros: [5.69, 375.18, 3.86, 379.59],
    },
    PaperRow {
        counts: [15984, 10384, 55204, 21167],
        micros: [1.83, 45.50, 1.65, 42.73],
    },
    PaperRow {
        counts: [15859, 12310, 51688, 24735],
        micros: [3.91, 12.70, 2.85, 13.29],
    },
];

/// A pair of trees to evaluate (e.g. one level and inner-sphere kind); several variants are
/// run on the very same placements.
#[derive(Debug, Clone)]
pub struct Variant {
    /// The first solid's tree.
    pub a: DoubleSphereTree,
    /// The second solid's tree.
    pub b: DoubleSphereTree,
}

/// Every [`Decision`], in the order of [`Tally::count`].
pub const DECISIONS: [Decision; 6] = [
    Decision::OuterSpheres,
    Decision::NoContact,
    Decision::InternalLabels,
    Decision::InnerSpheres,
    Decision::Faces,
    Decision::Containment,
];

fn decision_index(d: Decision) -> usize {
    DECISIONS
        .iter()
        .position(|&x| x == d)
        .expect("DECISIONS lists every decision")
}

/// Counts and times of one variant over the placements.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tally {
    /// Placements decided by each decision (indexed as [`DECISIONS`]).
    pub count: [u64; 6],
    /// Total query time in nanoseconds per decision (indexed as [`DECISIONS`]).
    pub nanos: [u64; 6],
    /// Sphere–sphere tests made.
    pub sphere_tests: u64,
    /// Triangle–triangle tests made.
    pub triangle_tests: u64,
}

impl Tally {
    fn add(&mut self, other: &Tally) {
        for k in 0..6 {
            self.count[k] += other.count[k];
            self.nanos[k] += other.nanos[k];
        }
        self.sphere_tests += other.sphere_tests;
        self.triangle_tests += other.triangle_tests;
    }

    fn sum(&self, ds: &[Decision]) -> (u64, u64) {
        ds.iter().fold((0, 0), |(c, t), &d| {
            let k = decision_index(d);
            (c + self.count[k], t + self.nanos[k])
        })
    }

    /// Collisions decided by spheres: inner spheres meeting, or two internal nodes (whose
    /// outer spheres lie inside the solids) meeting. The paper's "inner spheres" column.
    pub fn by_inner(&self) -> u64 {
        self.sum(&[Decision::InnerSpheres, Decision::InternalLabels])
            .0
    }

    /// Collisions decided by face tests (the paper's "faces" column), containment included.
    pub fn by_faces(&self) -> u64 {
        self.sum(&[Decision::Faces, Decision::Containment]).0
    }

    /// All collisions found.
    pub fn collisions(&self) -> u64 {
        self.by_inner() + self.by_faces()
    }

    /// All placements.
    pub fn placements(&self) -> u64 {
        self.count.iter().sum()
    }

    /// Mean time in µs of the queries decided by spheres, by faces, and of the non-colliding
    /// ones (`NaN` for an empty class).
    pub fn mean_micros(&self) -> [f64; 3] {
        let mean = |(c, t): (u64, u64)| {
            if c == 0 {
                f64::NAN
            } else {
                t as f64 / c as f64 / 1000.0
            }
        };
        [
            mean(self.sum(&[Decision::InnerSpheres, Decision::InternalLabels])),
            mean(self.sum(&[Decision::Faces, Decision::Containment])),
            mean(self.sum(&[Decision::OuterSpheres, Decision::NoContact])),
        ]
    }

    /// Mean time of all queries in µs.
    pub fn mean_micros_all(&self) -> f64 {
        self.nanos.iter().sum::<u64>() as f64 / self.placements().max(1) as f64 / 1000.0
    }
}

/// A placement where a hierarchy disagreed with the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct Mismatch {
    /// Index of the placement (replay it with [`placement`]).
    pub index: u64,
    /// Index of the variant that disagreed.
    pub variant: usize,
    /// The reference's (exact) answer.
    pub expected: bool,
    /// How the hierarchy decided.
    pub decided_by: Decision,
}

/// The result of [`run`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ExperimentResult {
    /// One tally per variant.
    pub tallies: Vec<Tally>,
    /// Placements the reference says collide.
    pub reference_collisions: u64,
    /// How the reference decided: `[separated, common point, exhaustive]`.
    pub reference_certificates: [u64; 3],
    /// Total reference time in nanoseconds.
    pub reference_nanos: u64,
    /// Every disagreement (there must be none).
    pub mismatches: Vec<Mismatch>,
}

impl ExperimentResult {
    fn merge(mut self, other: ExperimentResult) -> ExperimentResult {
        if self.tallies.is_empty() {
            return other;
        }
        for (t, o) in self.tallies.iter_mut().zip(&other.tallies) {
            t.add(o);
        }
        self.reference_collisions += other.reference_collisions;
        for k in 0..3 {
            self.reference_certificates[k] += other.reference_certificates[k];
        }
        self.reference_nanos += other.reference_nanos;
        self.mismatches.extend(other.mismatches);
        self
    }
}

/// A uniformly random rotation from three uniform numbers in `[0, 1)`, by Arvo's method
/// ("Fast random rotation matrices", Graphics Gems III, 1992): a rotation by `2πx₁` about the
/// z axis followed by the reflection `2vvᵀ - I` that takes the pole to a uniformly random
/// direction `v` (from `x₂`, `x₃`).
pub fn arvo_rotation(x: [f64; 3]) -> UnitQuaternion<f64> {
    let theta = 2.0 * PI * x[0];
    let phi = 2.0 * PI * x[1];
    let z = x[2];
    let r = z.sqrt();
    let v = nalgebra::Vector3::new(phi.cos() * r, phi.sin() * r, (1.0 - z).sqrt());
    let (s, c) = theta.sin_cos();
    let rz = Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
    let m = (2.0 * v * v.transpose() - Matrix3::identity()) * rz;
    UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m))
}

/// A uniformly random point in the ball of `radius` around the origin (by rejection).
fn in_ball(rng: &mut StdRng, radius: f64) -> Translation3<f64> {
    loop {
        let p: [f64; 3] = core::array::from_fn(|_| 2.0 * rng.random::<f64>() - 1.0);
        if p[0] * p[0] + p[1] * p[1] + p[2] * p[2] <= 1.0 {
            return Translation3::new(radius * p[0], radius * p[1], radius * p[2]);
        }
    }
}

/// SplitMix64's mixing function: decorrelates the per-placement seeds.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The poses of the two solids in placement `index` of an experiment with this `seed` and
/// experiment-sphere `radius`.
pub fn placement(seed: u64, index: u64, radius: f64) -> (Isometry3<f64>, Isometry3<f64>) {
    let mut rng = StdRng::seed_from_u64(mix(seed ^ mix(index)));
    let pose = |rng: &mut StdRng| {
        let t = in_ball(rng, radius);
        let q = arvo_rotation(core::array::from_fn(|_| rng.random::<f64>()));
        Isometry3::from_parts(t, q)
    };
    let a = pose(&mut rng);
    let b = pose(&mut rng);
    (a, b)
}

/// A solid's vertices under a pose, computed as the hierarchy computes them (`pose * v`).
fn place(poly: &ConvexPolyhedron, pose: &Isometry3<f64>, out: &mut Vec<Point3<f64>>) {
    out.clear();
    out.extend(poly.vertices().iter().map(|v| pose * v));
}

/// The solids' meshes in their own frames (checked once; placements reuse their triangles).
fn body_meshes<'p>(
    a: &'p ConvexPolyhedron,
    b: &'p ConvexPolyhedron,
) -> (ConvexMeshRef<'p>, ConvexMeshRef<'p>) {
    let mesh = |p: &'p ConvexPolyhedron| {
        ConvexMeshRef::new(p.vertices(), p.triangles())
            .expect("a ConvexPolyhedron is a valid closed mesh")
    };
    (mesh(a), mesh(b))
}

/// The exact answer for one placement.
fn reference(
    a: &ConvexPolyhedron,
    b: &ConvexPolyhedron,
    meshes: &(ConvexMeshRef<'_>, ConvexMeshRef<'_>),
    poses: &(Isometry3<f64>, Isometry3<f64>),
    buffers: &mut (Vec<Point3<f64>>, Vec<Point3<f64>>),
) -> (bool, Certificate) {
    place(a, &poses.0, &mut buffers.0);
    place(b, &poses.1, &mut buffers.1);
    let (ma, mb) = match (
        meshes.0.with_vertices(&buffers.0),
        meshes.1.with_vertices(&buffers.1),
    ) {
        (Ok(ma), Ok(mb)) => (ma, mb),
        // Finite poses of valid polyhedra give valid meshes.
        _ => unreachable!("a placed polyhedron is a valid mesh"),
    };
    let v = ma.collides_solid(&mb);
    (v.intersect, v.certificate)
}

/// Placements per parallel work item (and per progress report).
const CHUNK: u64 = 2048;

/// Runs `placements` placements of the variants' solids (all variants must be trees of the
/// same two polyhedra) in an experiment sphere of `radius`, checking every answer of every
/// variant against the exact reference. `progress` is called with the number of placements
/// finished since its last call.
pub fn run(
    variants: &[Variant],
    radius: f64,
    placements: u64,
    seed: u64,
    progress: &(dyn Fn(u64) + Sync),
) -> ExperimentResult {
    let Some(first) = variants.first() else {
        return ExperimentResult::default();
    };
    let (pa, pb) = (first.a.polyhedron(), first.b.polyhedron());
    let meshes = body_meshes(pa, pb);
    let chunks = placements.div_ceil(CHUNK);
    (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut buffers = (Vec::new(), Vec::new());
            let mut out = ExperimentResult {
                tallies: vec![Tally::default(); variants.len()],
                ..ExperimentResult::default()
            };
            let end = ((c + 1) * CHUNK).min(placements);
            for index in c * CHUNK..end {
                let poses = placement(seed, index, radius);
                let start = Instant::now();
                let (expected, certificate) = reference(pa, pb, &meshes, &poses, &mut buffers);
                out.reference_nanos += start.elapsed().as_nanos() as u64;
                out.reference_collisions += u64::from(expected);
                out.reference_certificates[match certificate {
                    Certificate::Separated => 0,
                    Certificate::CommonPoint => 1,
                    Certificate::Exhaustive => 2,
                }] += 1;
                for (k, v) in variants.iter().enumerate() {
                    let start = Instant::now();
                    let outcome = v.a.collides_at(&poses.0, &v.b, &poses.1);
                    let nanos = start.elapsed().as_nanos() as u64;
                    let t = &mut out.tallies[k];
                    let d = decision_index(outcome.decided_by);
                    t.count[d] += 1;
                    t.nanos[d] += nanos;
                    t.sphere_tests += u64::from(outcome.sphere_tests);
                    t.triangle_tests += u64::from(outcome.triangle_tests);
                    if outcome.collides != expected {
                        out.mismatches.push(Mismatch {
                            index,
                            variant: k,
                            expected,
                            decided_by: outcome.decided_by,
                        });
                    }
                }
            }
            progress(end - c * CHUNK);
            out
        })
        .reduce(ExperimentResult::default, ExperimentResult::merge)
}

/// The experiment-sphere radius at which a fraction `target` of the placements collide,
/// estimated on `samples` placements (seeded by `seed`) with the exact reference.
///
/// For fixed unit samples (positions drawn in the unit ball and scaled by the radius, fixed
/// orientations) whether a placement collides is monotone in the radius: the translations
/// `t` with `A ∩ (B + t) ≠ ∅` form the convex set `A - B`, which contains the origin since both
/// solids contain their centre, and `t` moves along a ray from the origin as the radius grows.
/// So the fraction is monotone and bisection finds the radius.
pub fn calibrate_radius(
    a: &ConvexPolyhedron,
    b: &ConvexPolyhedron,
    target: f64,
    samples: u64,
    seed: u64,
) -> f64 {
    let target = target.clamp(0.0, 1.0);
    let meshes = body_meshes(a, b);
    let fraction = |radius: f64| -> f64 {
        let hits: u64 = (0..samples)
            .into_par_iter()
            .map_init(
                || (Vec::new(), Vec::new()),
                |buffers, i| {
                    let poses = placement(seed ^ 0x5eed_ca1b, i, radius);
                    u64::from(reference(a, b, &meshes, &poses, buffers).0)
                },
            )
            .sum();
        hits as f64 / samples.max(1) as f64
    };
    let (mut lo, mut hi) = (0.0, 2.0);
    while fraction(hi) > target && hi < 1e6 {
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..24 {
        let mid = 0.5 * (lo + hi);
        if fraction(mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arvo_rotations_are_rotations() {
        for x in [
            [0.0, 0.0, 0.0],
            [0.3, 0.7, 0.2],
            [0.99, 0.5, 0.999],
            [0.5, 0.25, 1.0],
        ] {
            let m = arvo_rotation(x).to_rotation_matrix();
            let det = m.matrix().determinant();
            assert!((det - 1.0).abs() < 1e-12, "{x:?}: det {det}");
        }
    }

    #[test]
    fn arvo_rotations_move_the_pole_uniformly() {
        // The image of a fixed axis is uniform on the sphere: its z coordinate is uniform in
        // [-1, 1], so its mean is about 0 and its mean square about 1/3.
        let n = 20_000;
        let mut rng = StdRng::seed_from_u64(1);
        let (mut m1, mut m2) = (0.0, 0.0);
        for _ in 0..n {
            let q = arvo_rotation(core::array::from_fn(|_| rng.random::<f64>()));
            let z = (q * nalgebra::Vector3::x()).z;
            m1 += z;
            m2 += z * z;
        }
        let (m1, m2) = (m1 / n as f64, m2 / n as f64);
        assert!(m1.abs() < 0.02, "mean {m1}");
        assert!((m2 - 1.0 / 3.0).abs() < 0.02, "mean square {m2}");
    }

    #[test]
    fn placements_are_reproducible_and_inside_the_sphere() {
        for i in 0..100 {
            let (a, b) = placement(42, i, 3.0);
            assert_eq!((a, b), placement(42, i, 3.0));
            assert!(a.translation.vector.norm() <= 3.0 && b.translation.vector.norm() <= 3.0);
        }
        assert_ne!(placement(42, 0, 3.0), placement(42, 1, 3.0));
        assert_ne!(placement(42, 0, 3.0), placement(43, 0, 3.0));
    }
}

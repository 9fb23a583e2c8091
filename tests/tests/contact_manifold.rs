//! The product's contact manifolds (`query::contact_manifold`) checked independently: every
//! point within its certified bound of both shapes (and so of their intersection where the
//! bound is 0) by the exact shape oracle (`workspace_tests::shape_oracle::depth`) or, for
//! cylinders, an exact test written here; for axis-aligned boxes the exact distance to the
//! intersection box itself; unit normals, at most four points, determinism, refusals.

use std::cmp::Ordering;

use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query::{
    contact_manifold, contact_manifold_at, contact_manifold_batch, ContactManifold,
    SignedDistanceKind, MAX_POINTS_PER_REGION,
};
use cga_collide::shape::{Capsule, Cuboid, Cylinder, HalfSpace, PosePair, Shape};
use cga_collide::{Ball, Error};
use num_traits::{Signed, Zero};
use workspace_tests::shape_oracle::depth;
use workspace_tests::shape_oracle::exact::{dot, p3, q, sub, Q};
use workspace_tests::shape_oracle::generate::{random_shape, rng, POLYTOPAL};

/// Exact: is `p` within `e` of the solid cylinder `c`? (Sufficient test: it splits the
/// distance into its radial and axial parts and bounds a square root from below.)
fn within_cylinder(p: &Point3<f64>, c: &Cylinder, e: f64) -> bool {
    let (a, b) = (p3(c.a()), p3(c.b()));
    let (w, x) = (sub(&b, &a), sub(&p3(p), &a));
    let (ww, xw, xx) = (dot(&w, &w), dot(&x, &w), dot(&x, &x));
    // Axial excess times |w|: below the bottom cap or above the top one.
    let excess = if xw.is_negative() {
        -xw.clone()
    } else if xw > ww {
        &xw - &ww
    } else {
        Q::zero()
    };
    let excess2 = &excess * &excess / &ww;
    let radial2 = &xx - &xw * &xw / &ww;
    let (r, e) = (q(c.radius()), q(e));
    let rest = &e * &e - &excess2;
    if rest.is_negative() {
        return false;
    }
    // A lower bound of √rest, checked exactly.
    let mut s = rest.to_f64_lossy().sqrt() * (1.0 - 1e-12);
    while s > 0.0 && q(s) * q(s) > rest {
        s *= 0.5;
    }
    let reach = &r + q(s);
    radial2 <= &reach * &reach
}

trait Lossy {
    fn to_f64_lossy(&self) -> f64;
}
impl Lossy for Q {
    fn to_f64_lossy(&self) -> f64 {
        num_traits::ToPrimitive::to_f64(self).unwrap_or(f64::MAX)
    }
}

/// Exact: is `p` within `e` of `shape`?
fn within(p: &Point3<f64>, shape: &Shape, e: f64) -> bool {
    if let Shape::Cylinder(c) = shape {
        return within_cylinder(p, c, e);
    }
    let point: Shape = Ball::new(*p, 0.0).unwrap().into();
    let truth = depth::signed_distance(&point, shape)
        .unwrap_or_else(|| panic!("the oracle judges a point against {}", shape.kind()));
    truth.sign() != Ordering::Greater || truth.contains(e / 2.0, e / 2.0)
}

/// Every stated property of one manifold of `a` and `b` with the given margin.
fn check(a: &Shape, b: &Shape, margin: f64, m: &ContactManifold) {
    let n = m.normal;
    assert!(
        (n.norm_squared() - 1.0).abs() <= 1e-15,
        "normal not unit: {n:?}"
    );
    assert!(!m.points.is_empty() && m.points.len() <= MAX_POINTS_PER_REGION);
    let meeting = m.signed_distance.unwrap().kind != SignedDistanceKind::Separated;
    for p in &m.points {
        assert!(p.distance <= margin, "{p:?} beyond the margin");
        let slack = 1e-9 * (1.0 + p.point.coords.amax());
        assert!(
            p.distance >= m.signed_distance.unwrap().value - slack,
            "{p:?} deeper than the pair"
        );
        assert!(((p.point_b - p.point_a).dot(&n) - p.distance).abs() <= slack);
        if meeting {
            assert!(
                within(&p.point, a, p.error_bound),
                "{p:?} not within its bound of a"
            );
            assert!(
                within(&p.point, b, p.error_bound),
                "{p:?} not within its bound of b"
            );
        } else {
            assert!(within(&p.point_a, a, p.error_bound), "{p:?}: point_a off a");
            assert!(within(&p.point_b, b, p.error_bound), "{p:?}: point_b off b");
        }
    }
}

fn manifold(a: &Shape, b: &Shape, margin: f64) -> ContactManifold {
    let m = contact_manifold(a, b, margin)
        .expect("answered")
        .expect("within the margin");
    check(a, b, margin, &m);
    // Deterministic: the same answer bit for bit.
    assert_eq!(contact_manifold(a, b, margin).unwrap().as_ref(), Some(&m));
    m
}

fn aabb(c: [f64; 3], h: [f64; 3]) -> Shape {
    Cuboid::axis_aligned(Point3::from(c), Vector3::from(h))
        .unwrap()
        .into()
}

/// The exact squared distance from `p` to the box `[lo, hi]` is at most `e²`.
fn within_box(p: &Point3<f64>, lo: [f64; 3], hi: [f64; 3], e: f64) -> bool {
    let mut d2 = Q::zero();
    for k in 0..3 {
        let (x, l, h) = (q(p[k]), q(lo[k]), q(hi[k]));
        let gap = if x < l {
            l - x
        } else if x > h {
            x - h
        } else {
            Q::zero()
        };
        d2 += &gap * &gap;
    }
    d2 <= q(e) * q(e)
}

#[test]
fn touching_boxes_give_four_points_on_the_shared_face() {
    let (a, b) = (aabb([0.0; 3], [0.5; 3]), aabb([1.0, 0.25, 0.0], [0.5; 3]));
    let m = manifold(&a, &b, 0.0);
    assert_eq!(
        m.signed_distance.unwrap().kind,
        SignedDistanceKind::Touching
    );
    assert_eq!(m.normal, Vector3::x());
    assert_eq!(m.points.len(), 4);
    for p in &m.points {
        assert_eq!(p.distance, 0.0);
        // The intersection of the two boxes is the square x = 0.5, y in [-0.25, 0.5].
        assert!(within_box(
            &p.point,
            [0.5, -0.25, -0.5],
            [0.5, 0.5, 0.5],
            p.error_bound
        ));
    }
}

#[test]
fn box_sunk_into_a_box_face_gives_its_four_corners() {
    let table = aabb([0.0; 3], [2.0, 2.0, 0.5]);
    let block = aabb([0.3, -0.2, 0.8], [0.5; 3]);
    let m = manifold(&table, &block, 0.0);
    assert_eq!(m.points.len(), 4);
    for p in &m.points {
        assert!((p.distance + 0.2).abs() < 1e-15);
        assert!(within_box(
            &p.point,
            [-0.2, -0.7, 0.3],
            [0.8, 0.3, 0.5],
            p.error_bound
        ));
    }
    // Turned about the vertical: still four corners, each as deep.
    let turned = Isometry3::new(Vector3::new(0.3, -0.2, 0.8), Vector3::z() * 0.5);
    let block0 = aabb([0.0; 3], [0.5; 3]);
    let m = contact_manifold_at(&table, &Isometry3::identity(), &block0, &turned, 0.0)
        .unwrap()
        .unwrap();
    check(&table, &block0.placed(&turned).unwrap(), 0.0, &m);
    assert_eq!(m.points.len(), 4);
    for p in &m.points {
        assert!((p.distance + 0.2).abs() < 1e-12);
    }
}

#[test]
fn box_tilted_on_an_edge_gives_the_edge() {
    let table = aabb([0.0; 3], [2.0, 2.0, 0.5]);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    // Turned 45° about x and sunk so its lowest edge is 0.01 below the top face.
    let pose = Isometry3::new(
        Vector3::new(0.0, 0.0, 0.49 + s),
        Vector3::x() * std::f64::consts::FRAC_PI_4,
    );
    let block = aabb([0.0; 3], [0.5; 3]).placed(&pose).unwrap();
    let m = manifold(&table, &block, 0.0);
    assert_eq!(m.points.len(), 2, "{m:?}");
}

#[test]
fn capsules_on_a_box() {
    let table = aabb([0.0; 3], [2.0, 2.0, 0.5]);
    // Lying flat, sunk 0.05: the two ends of its axis.
    let lying: Shape = Capsule::new(
        Point3::new(-1.0, 0.0, 0.7),
        Point3::new(1.0, 0.0, 0.7),
        0.25,
    )
    .unwrap()
    .into();
    let m = manifold(&table, &lying, 0.0);
    assert_eq!(m.points.len(), 2);
    for p in &m.points {
        assert!((p.distance + 0.05).abs() < 1e-12);
    }
    // Standing: one point under its lower end.
    let standing: Shape =
        Capsule::new(Point3::new(0.0, 0.0, 0.7), Point3::new(0.0, 0.0, 2.0), 0.25)
            .unwrap()
            .into();
    let m = manifold(&table, &standing, 0.0);
    assert_eq!(m.points.len(), 1);
}

#[test]
fn cylinder_on_a_face_within_the_margin_and_sunk_into_it() {
    // The round engine decides cylinders against balls, capsules, segments and half-spaces:
    // the face is the top of a half-space.
    let table: Shape = HalfSpace::new(Point3::new(0.0, 0.0, 0.5), Vector3::z())
        .unwrap()
        .into();
    let cyl = |z: f64| -> Shape {
        Cylinder::new(
            Point3::new(0.1, 0.2, z),
            Point3::new(0.1, 0.2, z + 1.0),
            0.4,
        )
        .unwrap()
        .into()
    };
    let m = manifold(&table, &cyl(0.51), 0.05);
    assert_eq!(
        m.signed_distance.unwrap().kind,
        SignedDistanceKind::Separated
    );
    assert_eq!(m.points.len(), 4);
    for p in &m.points {
        assert!((p.distance - 0.01).abs() < 1e-12);
    }
    assert!(contact_manifold(&table, &cyl(0.6), 0.05).unwrap().is_none());
    // Sunk 0.05: the certified curved depth gives the pair's signed distance.
    let m = manifold(&table, &cyl(0.45), 0.0);
    let sd = m.signed_distance.unwrap();
    assert_eq!(sd.kind, SignedDistanceKind::Penetrating);
    assert!(
        (sd.value + 0.05).abs() <= sd.error_bound.max(1e-12),
        "{sd:?}"
    );
    assert!(!m.points.is_empty() && m.points.len() <= 4);
}

#[test]
fn shapes_on_a_half_space() {
    let ground: Shape = HalfSpace::new(Point3::origin(), Vector3::z())
        .unwrap()
        .into();
    let ball: Shape = Ball::new(Point3::new(0.0, 0.0, 0.9), 1.0).unwrap().into();
    let m = manifold(&ground, &ball, 0.0);
    assert_eq!(m.points.len(), 1);
    let block = aabb([0.0, 0.0, 0.4], [0.5; 3]);
    let m = manifold(&ground, &block, 0.0);
    assert_eq!(m.points.len(), 4);
    let m = manifold(&block, &ground, 0.0);
    assert_eq!(m.points.len(), 4);
}

#[test]
fn margin_and_refusals() {
    let (a, b) = (aabb([0.0; 3], [0.5; 3]), aabb([1.25, 0.0, 0.0], [0.5; 3]));
    assert!(contact_manifold(&a, &b, 0.2).unwrap().is_none());
    let m = manifold(&a, &b, 0.3);
    assert_eq!(m.points.len(), 4);
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            contact_manifold(&a, &b, bad),
            Err(Error::InvalidClearance { .. })
        ));
    }
}

#[test]
fn batch_equals_each_pose() {
    let (a, b) = (aabb([0.0; 3], [0.5; 3]), aabb([0.0; 3], [0.5; 3]));
    let poses: Vec<PosePair> = (0..6)
        .map(|k| {
            let t = 0.8 + 0.1 * k as f64;
            PosePair::new(
                Isometry3::identity(),
                Isometry3::new(Vector3::new(t, 0.1, 0.0), Vector3::y() * 0.1 * k as f64),
            )
        })
        .collect();
    let batch = contact_manifold_batch(&a, &b, &poses, 0.05).unwrap();
    for (p, m) in poses.iter().zip(&batch) {
        assert_eq!(m, &contact_manifold_at(&a, &p.a, &b, &p.b, 0.05).unwrap());
    }
}

#[test]
fn random_polytopal_pairs_hold_every_bound() {
    let mut r = rng(36);
    let (mut judged, mut met) = (0, 0);
    for i in 0..400 {
        let ka = POLYTOPAL[i % POLYTOPAL.len()];
        let kb = POLYTOPAL[(i / POLYTOPAL.len()) % POLYTOPAL.len()];
        let a = random_shape(&mut r, ka, &Point3::origin(), false);
        let b = random_shape(&mut r, kb, &Point3::new(0.5, 0.0, 0.0), false);
        let margin = 0.25;
        let Ok(got) = contact_manifold(&a, &b, margin) else {
            continue; // documented refusals (two half-spaces, large hulls)
        };
        if let Some(m) = got {
            if depth::signed_distance(&a, &b).is_none() {
                continue;
            }
            check(&a, &b, margin, &m);
            judged += 1;
            met += usize::from(m.signed_distance.unwrap().kind != SignedDistanceKind::Separated);
        }
    }
    assert!(judged > 100 && met > 50, "judged {judged}, meeting {met}");
}

// ---- Meshes -------------------------------------------------------------------------------

use cga_collide::scene::Scene;
use cga_collide::{Collider, TriMesh};

fn cube_mesh(lo: [f64; 3], hi: [f64; 3]) -> TriMesh {
    TriMesh::cuboid(Point3::from(lo), Point3::from(hi)).unwrap()
}

/// Two meshes in one.
fn joined(a: &TriMesh, b: &TriMesh) -> TriMesh {
    let mut vertices = a.vertices().to_vec();
    vertices.extend_from_slice(b.vertices());
    let shift = a.vertices().len() as u32;
    let mut triangles = a.triangles().to_vec();
    triangles.extend(b.triangles().iter().map(|t| t.map(|v| v + shift)));
    TriMesh::new(vertices, triangles).unwrap()
}

/// Every point of every region within its bound of a triangle of each mesh among the region's
/// pairs (the exact oracle), unit normals, at most four points, determinism.
fn check_meshes(a: &Collider, b: &Collider) -> Vec<ContactManifold> {
    let regions = a.contact_manifolds(b);
    assert_eq!(a.contact_manifolds(b), regions);
    for m in &regions {
        assert!((m.normal.norm_squared() - 1.0).abs() <= 1e-15);
        assert!(!m.points.is_empty() && m.points.len() <= MAX_POINTS_PER_REGION);
        assert!(m.signed_distance.is_none() && !m.triangle_pairs.is_empty());
        for p in &m.points {
            assert_eq!(p.distance, 0.0);
            let on_both = m.triangle_pairs.iter().any(|&(i, j)| {
                within(&p.point, &Shape::from(a.triangle(i)), p.error_bound)
                    && within(&p.point, &Shape::from(b.triangle(j)), p.error_bound)
            });
            assert!(on_both, "{p:?} is not within its bound of the intersection");
        }
    }
    regions
}

#[test]
fn mesh_regions_points_and_normals() {
    let table = Collider::new(cube_mesh([-2.0, -2.0, -1.0], [2.0, 2.0, 0.0]));
    let block = Collider::new(cube_mesh([-0.3, -0.4, -0.25], [0.6, 0.5, 0.75]));
    let regions = check_meshes(&table, &block);
    assert_eq!(regions.len(), 1);
    assert_eq!(regions[0].normal, Vector3::z());
    assert_eq!(regions[0].points.len(), 4);
    // Two blocks in one mesh: two regions.
    let other = cube_mesh([1.0, -0.4, -0.25], [1.5, 0.5, 0.75]);
    let two = Collider::new(joined(block.mesh(), &other));
    let regions = check_meshes(&table, &two);
    assert_eq!(regions.len(), 2);
    // Under poses: a tilted block, and nothing when apart.
    let tilted = Isometry3::new(Vector3::new(0.1, 0.0, 0.2), Vector3::new(0.3, 0.2, 0.1));
    let placed = block.placed(&tilted).unwrap();
    let at = table
        .contact_manifolds_at(&Isometry3::identity(), &block, &tilted)
        .unwrap();
    assert_eq!(at, check_meshes(&table, &placed));
    let apart = Isometry3::translation(0.0, 0.0, 5.0);
    assert!(table
        .contact_manifolds_at(&Isometry3::identity(), &block, &apart)
        .unwrap()
        .is_empty());
}

#[test]
fn scene_manifolds_of_every_touching_pair() {
    let mut scene = Scene::new();
    let floor = scene
        .add_shape(aabb([0.0; 3], [3.0, 3.0, 0.5]), Isometry3::identity())
        .unwrap();
    let crate_ = scene
        .add_shape(
            aabb([0.0; 3], [0.5; 3]),
            Isometry3::translation(0.0, 0.0, 0.95),
        )
        .unwrap();
    let far = scene
        .add_shape(
            aabb([0.0; 3], [0.5; 3]),
            Isometry3::translation(0.0, 0.0, 9.0),
        )
        .unwrap();
    let cube = std::sync::Arc::new(Collider::new(cube_mesh([0.0; 3], [1.0; 3])));
    let m1 = scene
        .add(cube.clone(), Isometry3::translation(10.0, 0.0, 0.0))
        .unwrap();
    let m2 = scene
        .add(cube, Isometry3::translation(10.5, 0.25, 0.25))
        .unwrap();
    let pairs = scene.contact_manifolds().unwrap();
    assert_eq!(pairs.len(), 2);
    assert_eq!((pairs[0].a, pairs[0].b), (floor, crate_));
    assert_eq!(pairs[0].manifolds[0].points.len(), 4);
    assert_eq!((pairs[1].a, pairs[1].b), (m1, m2));
    assert!(pairs.iter().all(|p| p.a != far && p.b != far));
    // A mesh touching a shape is refused, not skipped.
    scene
        .set_pose(far, Isometry3::translation(10.0, 0.0, 0.0))
        .unwrap();
    assert!(matches!(
        scene.contact_manifolds(),
        Err(Error::UnsupportedPair { .. })
    ));
}

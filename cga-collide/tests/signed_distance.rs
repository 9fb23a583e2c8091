//! Signed distance of points to meshes (`Collider::signed_distance[s]`): the sign against the
//! exact ray test on adversarial points (on faces, edges and vertices, and an ulp off each way
//! along the coordinate axes and along the normal), the magnitude against exact clearance
//! tests within its bound, and the fast sign against the exact ray test on random points.

use cga_collide::collider::{Collider, PointDistance};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::shape::Shape;
use cga_collide::{Ball, Error, TriMesh};
use proptest::prelude::*;

fn cube() -> TriMesh {
    TriMesh::cuboid(Point3::new(-1.0, -0.5, 0.25), Point3::new(1.0, 2.0, 3.0)).unwrap()
}

/// A small deterministic generator (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Points on and within an ulp of the surface of `mesh`: for `n` triangles (chosen at random),
/// a vertex, an edge point and a face point (barycentric, rounded to `f64`), each as is, one
/// ulp up and down along each axis, and a few ulps along the normal each way.
fn adversarial(mesh: &TriMesh, n: usize, seed: u64) -> Vec<Point3<f64>> {
    let mut rng = Rng(seed | 1);
    let mut out = Vec::new();
    for _ in 0..n {
        let t = (rng.next() % mesh.num_triangles() as u64) as u32;
        let [a, b, c] = mesh.corners(t);
        let (s, u) = (rng.unit(), rng.unit());
        let (s, u) = if s + u > 1.0 {
            (1.0 - s, 1.0 - u)
        } else {
            (s, u)
        };
        let edge = a + (b - a) * rng.unit();
        let face = a + (b - a) * s + (c - a) * u;
        let normal = (b - a).cross(&(c - a)).normalize();
        for p in [a, edge, face] {
            out.push(p);
            for k in 0..3 {
                let mut up = p;
                up[k] = up[k].next_up();
                let mut down = p;
                down[k] = down[k].next_down();
                out.extend([up, down]);
            }
            let ulp = f64::EPSILON * p.coords.amax().max(f64::MIN_POSITIVE);
            for steps in [1.0, 4.0] {
                out.push(p + normal * (steps * ulp));
                out.push(p - normal * (steps * ulp));
            }
        }
    }
    out
}

/// The magnitude is within its bound of the true distance, by exact clearance tests against
/// the whole mesh: within `d + e`, and (when `d − e > 0`) not within just below `d − e`.
fn check_magnitude(collider: &Collider, p: &Point3<f64>, r: &PointDistance) {
    let ball = Shape::Ball(Ball::new(*p, 0.0).unwrap());
    let d = r.signed_distance.abs();
    let (hi, lo) = (
        (d + r.error_bound).next_up(),
        (d - r.error_bound).next_down(),
    );
    assert!(
        collider.shape_within_distance(&ball, hi).unwrap(),
        "{p:?}: {r:?} above"
    );
    if lo > 0.0 {
        assert!(
            !collider.shape_within_distance(&ball, lo).unwrap(),
            "{p:?}: {r:?} below"
        );
    }
    if r.signed_distance == 0.0 && r.error_bound == 0.0 {
        assert!(r.inside, "{p:?}: {r:?} on the surface");
    }
    if r.signed_distance != 0.0 {
        assert_eq!(r.inside, r.signed_distance < 0.0, "{p:?}: {r:?}");
    }
}

fn check_all(collider: &Collider, points: &[Point3<f64>]) -> usize {
    let answers = collider.signed_distances(points).unwrap();
    assert_eq!(answers.len(), points.len());
    let mut on_surface = 0;
    for (p, r) in points.iter().zip(&answers) {
        assert_eq!(
            r.inside,
            collider.contains_point(p),
            "wrong sign at {p:?}: {r:?}"
        );
        check_magnitude(collider, p, r);
        // The nearest point's triangle is within the bound of the reported distance.
        let tri = Shape::Triangle(collider.triangle(r.triangle));
        let ball = Ball::new(*p, 0.0).unwrap();
        assert!(cga_collide::query::within_distance(
            &Shape::Ball(ball),
            &tri,
            (r.signed_distance.abs() + r.error_bound).next_up()
        )
        .unwrap());
        on_surface += usize::from(r.signed_distance == 0.0);
    }
    on_surface
}

#[test]
fn cube_adversarial_points_have_exact_signs_and_bounded_magnitudes() {
    let c = Collider::new(cube());
    let points = adversarial(c.mesh(), 200, 7);
    let on = check_all(&c, &points);
    // Vertices, edge and face points of an axis-aligned box are exact: on the surface.
    assert!(on >= 200, "{on}");
}

#[test]
fn bunny_adversarial_points_have_exact_signs_and_bounded_magnitudes() {
    let c = Collider::new(TriMesh::bunny());
    assert!(c.mesh().is_closed());
    let points = adversarial(c.mesh(), 60, 11);
    check_all(&c, &points);
}

#[test]
fn inward_oriented_and_open_meshes_follow_the_ray_rule() {
    let m = cube();
    let flipped: Vec<[u32; 3]> = m.triangles().iter().map(|t| [t[0], t[2], t[1]]).collect();
    let inward = Collider::new(TriMesh::new(m.vertices().to_vec(), flipped).unwrap());
    let mut tris = m.triangles().to_vec();
    tris.truncate(10);
    let open = Collider::new(TriMesh::new(m.vertices().to_vec(), tris).unwrap());
    let mut points = adversarial(&m, 100, 3);
    let mut rng = Rng(99);
    points.extend((0..300).map(|_| {
        Point3::new(
            rng.unit() * 4.0 - 2.0,
            rng.unit() * 4.0 - 1.5,
            rng.unit() * 4.0 - 0.5,
        )
    }));
    check_all(&inward, &points);
    check_all(&open, &points);
}

#[test]
fn a_point_on_the_surface_is_inside_at_distance_zero() {
    let c = Collider::new(cube());
    for p in [
        Point3::new(1.0, 2.0, 3.0),  // vertex
        Point3::new(1.0, 0.0, 3.0),  // edge
        Point3::new(0.0, 0.0, 0.25), // face
        Point3::new(-1.0, 1.0, 1.0), // face
    ] {
        let r = c.signed_distance(&p).unwrap();
        assert_eq!(
            (r.signed_distance, r.error_bound, r.inside),
            (0.0, 0.0, true)
        );
        assert_eq!(r.nearest, p);
    }
    let r = c.signed_distance(&Point3::new(3.0, 0.0, 1.0)).unwrap();
    assert!(!r.inside && (r.signed_distance - 2.0).abs() <= r.error_bound);
    assert_eq!(r.nearest, Point3::new(1.0, 0.0, 1.0));
    let r = c.signed_distance(&Point3::new(0.0, 0.0, 1.0)).unwrap();
    assert!(r.inside && (r.signed_distance + 0.5).abs() <= r.error_bound);
}

#[test]
fn bad_points_are_refused_with_their_index() {
    let c = Collider::new(cube());
    let points = [Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, f64::NAN, 0.0)];
    match c.signed_distances(&points) {
        Err(Error::InShapePoint { index: 1, .. }) => {}
        other => panic!("{other:?}"),
    }
    assert!(c
        .signed_distance(&Point3::new(f64::INFINITY, 0.0, 0.0))
        .is_err());
    assert!(c.signed_distance(&Point3::new(1e300, 0.0, 0.0)).is_err());
}

#[test]
fn under_a_pose_the_answers_are_the_placed_meshes() {
    let c = Collider::new(TriMesh::bunny());
    let pose = Isometry3::new(Vector3::new(0.1, -0.2, 0.3), Vector3::new(0.3, 0.2, -0.1));
    let placed = c.placed(&pose).unwrap();
    let points = adversarial(placed.mesh(), 20, 5);
    assert_eq!(
        c.signed_distances_at(&pose, &points).unwrap(),
        placed.signed_distances(&points).unwrap()
    );
    let bad = Isometry3::new(Vector3::new(f64::NAN, 0.0, 0.0), Vector3::zeros());
    assert!(c.signed_distances_at(&bad, &points).is_err());
}

fn bunny() -> &'static Collider {
    static BUNNY: std::sync::OnceLock<Collider> = std::sync::OnceLock::new();
    BUNNY.get_or_init(|| Collider::new(TriMesh::bunny()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The sign taken from the nearest face agrees with the exact ray test.
    #[test]
    fn fast_sign_agrees_with_the_ray_test(
        t in 0u32..1000,
        s in 0.0f64..1.0,
        u in 0.0f64..1.0,
        h in prop_oneof![-1e-3f64..1e-3, -1e-12f64..1e-12, -0.05f64..0.05],
        shift in prop::array::uniform3(-0.2f64..0.2),
    ) {
        let c = bunny();
        let t = t % c.mesh().num_triangles() as u32;
        let [a, b, d] = c.mesh().corners(t);
        let (s, u) = if s + u > 1.0 { (1.0 - s, 1.0 - u) } else { (s, u) };
        let n = (b - a).cross(&(d - a)).normalize();
        let p = a + (b - a) * s + (d - a) * u + n * h;
        let q = p + Vector3::from(shift);
        for p in [p, q] {
            let r = c.signed_distance(&p).unwrap();
            prop_assert_eq!(r.inside, c.contains_point(&p), "{:?}", p);
        }
    }
}

/// Points around the vertices and edge midpoints of `mesh`, off in random directions at
/// several distances (nearest to an edge or a vertex far more often than points near faces).
fn around_edges_and_vertices(mesh: &TriMesh, n: usize, seed: u64) -> Vec<Point3<f64>> {
    let mut rng = Rng(seed | 1);
    let mut out = Vec::new();
    for _ in 0..n {
        let t = (rng.next() % mesh.num_triangles() as u64) as u32;
        let [a, b, _] = mesh.corners(t);
        let size = (b - a).norm();
        for base in [a, a + (b - a) * 0.5] {
            for scale in [1e-9, 1e-3, 0.3, 3.0] {
                let dir = Vector3::new(rng.unit() - 0.5, rng.unit() - 0.5, rng.unit() - 0.5);
                out.push(base + dir * (scale * size));
            }
        }
    }
    out
}

#[test]
fn points_nearest_to_edges_and_vertices_have_exact_signs() {
    let c = Collider::new(cube());
    check_all(&c, &around_edges_and_vertices(c.mesh(), 12, 3));
    let b = bunny();
    let points = around_edges_and_vertices(b.mesh(), 150, 5);
    let answers = b.signed_distances(&points).unwrap();
    for (p, r) in points.iter().zip(&answers) {
        assert_eq!(r.inside, b.contains_point(p), "wrong sign at {p:?}: {r:?}");
    }
}

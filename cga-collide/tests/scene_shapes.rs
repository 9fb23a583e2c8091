//! Scenes that mix solid primitives and meshes: every answer equals the brute force over all
//! pairs with each pair's own exact query (mesh–mesh by the colliders, mesh–shape by
//! `Collider::*shape*_at`, shape–shape by `query::*`), with groups and exclusions applied.

use std::sync::Arc;

use cga_collide::collider::Collider;
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::query;
use cga_collide::scene::{Body, ObjectId, Scene};
use cga_collide::shape::{HalfSpace, Shape};
use cga_collide::{Ball, Error, Segment, TriMesh, Triangle};
use proptest::prelude::*;

fn point(scale: f64) -> impl Strategy<Value = Point3<f64>> {
    (-scale..scale, -scale..scale, -scale..scale).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// An object: a shape (ball, segment, triangle) or a box mesh.
#[derive(Debug, Clone)]
enum Spec {
    Shape(Shape),
    Box(Point3<f64>),
}

fn spec() -> impl Strategy<Value = Spec> {
    prop_oneof![
        (point(1.0), 0.0f64..1.0).prop_map(|(c, r)| Spec::Shape(Ball::new(c, r).unwrap().into())),
        (point(1.5), point(1.5)).prop_map(|(a, b)| Spec::Shape(Segment::new(a, b).unwrap().into())),
        (point(1.5), point(1.5), point(1.5))
            .prop_map(|(a, b, c)| Spec::Shape(Triangle::new(a, b, c).unwrap().into())),
        point(1.0).prop_map(Spec::Box),
    ]
}

fn pose() -> impl Strategy<Value = Isometry3<f64>> {
    (point(3.0), point(3.0)).prop_map(|(t, r)| Isometry3::new(t.coords, r.coords))
}

/// The placed objects the brute force reads.
enum Placed {
    Mesh(Arc<Collider>, Isometry3<f64>),
    Shape(Shape),
}

fn touch(x: &Placed, y: &Placed, solid: bool) -> bool {
    match (x, y) {
        (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) if solid => {
            a.collides_solid_at(pa, b, pb).unwrap()
        }
        (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.collides_at(pa, b, pb).unwrap(),
        (Placed::Mesh(m, p), Placed::Shape(s)) | (Placed::Shape(s), Placed::Mesh(m, p)) => {
            let id = Isometry3::identity();
            if solid {
                m.intersects_shape_solid_at(p, s, &id).unwrap()
            } else {
                m.intersects_shape_at(p, s, &id).unwrap()
            }
        }
        (Placed::Shape(a), Placed::Shape(b)) => query::intersects(a, b).unwrap(),
    }
}

fn within(x: &Placed, y: &Placed, c: f64) -> bool {
    let id = Isometry3::identity();
    match (x, y) {
        (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.within_distance_at(pa, b, pb, c).unwrap(),
        (Placed::Mesh(m, p), Placed::Shape(s)) | (Placed::Shape(s), Placed::Mesh(m, p)) => {
            m.shape_within_distance_at(p, s, &id, c).unwrap()
        }
        (Placed::Shape(a), Placed::Shape(b)) => query::within_distance(a, b, c).unwrap(),
    }
}

fn distance(x: &Placed, y: &Placed) -> (f64, f64) {
    let id = Isometry3::identity();
    let d = match (x, y) {
        (Placed::Mesh(a, pa), Placed::Mesh(b, pb)) => a.distance_at(pa, b, pb).unwrap(),
        (Placed::Mesh(m, p), Placed::Shape(s)) | (Placed::Shape(s), Placed::Mesh(m, p)) => {
            m.distance_to_shape_at(p, s, &id).unwrap()
        }
        (Placed::Shape(a), Placed::Shape(b)) => query::distance(a, b).unwrap(),
    };
    (d.distance, d.error_bound)
}

fn segment_meets(x: &Placed, s: &Segment) -> bool {
    match x {
        Placed::Mesh(m, p) => !m.segment_hits_at(p, s).unwrap().is_empty(),
        Placed::Shape(shape) => query::intersects(&(*s).into(), shape).unwrap(),
    }
}

struct Built {
    scene: Scene,
    ids: Vec<ObjectId>,
    placed: Vec<Placed>,
}

fn build(objects: &[(Spec, Isometry3<f64>)], excluded: &[(usize, usize)], solid: bool) -> Built {
    let cube = Arc::new(Collider::new(
        TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 0.5, 0.75)).unwrap(),
    ));
    let mut scene = Scene::new();
    scene.set_solid(solid);
    let mut ids = Vec::new();
    let mut placed = Vec::new();
    for (spec, pose) in objects {
        match spec {
            Spec::Shape(s) => {
                ids.push(scene.add_shape(s.clone(), *pose).unwrap());
                placed.push(Placed::Shape(s.placed(pose).unwrap()));
            }
            Spec::Box(offset) => {
                let pose = pose * Isometry3::translation(offset.x, offset.y, offset.z);
                ids.push(scene.add(cube.clone(), pose).unwrap());
                placed.push(Placed::Mesh(cube.clone(), pose));
            }
        }
    }
    for &(a, b) in excluded {
        let (a, b) = (a % ids.len(), b % ids.len());
        if a != b {
            scene.exclude_pair(ids[a], ids[b]).unwrap();
        }
    }
    Built { scene, ids, placed }
}

fn excluded(excluded: &[(usize, usize)], n: usize, a: usize, b: usize) -> bool {
    excluded.iter().any(|&(x, y)| {
        let (x, y) = (x % n, y % n);
        (x, y) == (a, b) || (y, x) == (a, b)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn mixed_scenes_answer_as_the_brute_force(
        objects in prop::collection::vec((spec(), pose()), 2..9),
        left_out in prop::collection::vec((0usize..9, 0usize..9), 0..3),
        solid in any::<bool>(),
        c in 0.0f64..1.0,
        ends in (point(4.0), point(4.0)),
    ) {
        let Built { scene, ids, placed } = build(&objects, &left_out, solid);
        let n = ids.len();
        let pairs = || (0..n).flat_map(|a| (a + 1..n).map(move |b| (a, b)))
            .filter(|&(a, b)| !excluded(&left_out, n, a, b));
        let expected: Vec<_> = pairs()
            .filter(|&(a, b)| touch(&placed[a], &placed[b], solid))
            .map(|(a, b)| (ids[a], ids[b]))
            .collect();
        prop_assert_eq!(scene.colliding_pairs().unwrap(), expected.clone());
        for (k, &id) in ids.iter().enumerate() {
            let mut with: Vec<ObjectId> = expected
                .iter()
                .filter_map(|&(a, b)| if a == id { Some(b) } else if b == id { Some(a) } else { None })
                .collect();
            with.sort();
            prop_assert_eq!(scene.colliding_with(id).unwrap(), with, "object {}", k);
        }
        let near: Vec<_> = pairs()
            .filter(|&(a, b)| within(&placed[a], &placed[b], c))
            .map(|(a, b)| (ids[a], ids[b]))
            .collect();
        prop_assert_eq!(scene.pairs_within_distance(c).unwrap(), near);
        // The nearest pair: its certified interval holds the least true distance.
        let least = pairs()
            .map(|(a, b)| distance(&placed[a], &placed[b]))
            .fold((f64::INFINITY, 0.0), |m, d| if d.0 < m.0 { d } else { m });
        match scene.nearest_pair().unwrap() {
            Some((_, _, d)) => prop_assert!(
                (d.distance - least.0).abs() <= d.error_bound + least.1,
                "{:?} vs {:?}", d, least
            ),
            None => prop_assert!(least.0.is_infinite()),
        }
        let (p, q) = ends;
        let segment = Segment::new(p, q).unwrap();
        let hit: Vec<ObjectId> = (0..n)
            .filter(|&k| segment_meets(&placed[k], &segment))
            .map(|k| ids[k])
            .collect();
        prop_assert_eq!(scene.segment_hits(&segment).unwrap(), hit);
    }
}

#[test]
fn shapes_and_colliders_are_asked_for_by_kind() {
    let cube = Arc::new(Collider::new(
        TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap(),
    ));
    let mut scene = Scene::new();
    let mesh = scene.add(cube, Isometry3::identity()).unwrap();
    let ball: Shape = Ball::new(Point3::origin(), 0.5).unwrap().into();
    let shape = scene
        .add_shape(ball.clone(), Isometry3::translation(3.0, 0.0, 0.0))
        .unwrap();
    assert_eq!(scene.shape(shape).unwrap(), &ball);
    assert_eq!(scene.kind(mesh).unwrap(), "mesh");
    assert!(matches!(
        scene.collider(shape),
        Err(Error::WrongObjectKind {
            expected: "mesh",
            found: "ball",
            ..
        })
    ));
    assert!(matches!(
        scene.shape(mesh),
        Err(Error::WrongObjectKind {
            expected: "shape",
            found: "mesh",
            ..
        })
    ));
    // `remove` is for meshes; the shape stays, and `remove_object` takes either.
    assert!(scene.remove(shape).is_err());
    assert_eq!(scene.len(), 2);
    assert!(matches!(scene.remove_object(shape).unwrap(), Body::Shape(s) if s == ball));
    assert!(scene.remove(mesh).is_ok());
    assert!(scene.is_empty());
    // A pose that moves a shape out of range is refused, and nothing moves.
    let id = scene
        .add_shape(ball.clone(), Isometry3::identity())
        .unwrap();
    let far = Isometry3::translation(1e200, 0.0, 0.0);
    assert!(scene.set_pose(id, far).is_err());
    assert_eq!(scene.pose(id).unwrap(), &Isometry3::identity());
    assert!(scene.add_shape(ball, far).is_err());
}

/// A half-space has an unbounded world box: the broad phase pairs it with everything that
/// reaches it, and nothing else (no pair test is asked for objects above the ground, so the
/// answer comes without an exact half-space test).
#[test]
fn a_ground_plane_is_paired_by_the_broad_phase_only_with_what_reaches_it() {
    let mut scene = Scene::new();
    let ground = HalfSpace::new(Point3::origin(), Vector3::z()).unwrap();
    scene
        .add_shape(ground.into(), Isometry3::identity())
        .unwrap();
    let ball: Shape = Ball::new(Point3::origin(), 0.5).unwrap().into();
    // 300 balls above the ground (enough for the grid broad phase), touching each other in a row.
    let ids: Vec<ObjectId> = (0..300)
        .map(|k| {
            scene
                .add_shape(ball.clone(), Isometry3::translation(k as f64, 0.0, 2.0))
                .unwrap()
        })
        .collect();
    let pairs = scene.colliding_pairs().unwrap();
    assert_eq!(pairs.len(), 299);
    assert!(pairs
        .iter()
        .zip(ids.windows(2))
        .all(|(p, w)| *p == (w[0], w[1])));
    assert!(scene.pairs_within_distance(1.0).unwrap().len() >= 299);
}

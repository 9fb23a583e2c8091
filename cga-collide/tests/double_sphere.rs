//! The double-sphere tree of the seed paper 000: Table 1's polyhedra, the tree's invariants and
//! the exactness of `collide` against an independent brute force.

use std::sync::OnceLock;

use cga_collide::double_sphere::enclosing::{
    smallest_enclosing_ball, smallest_enclosing_ball_brute,
};
use cga_collide::double_sphere::inscribed::{chebyshev_brute, depth};
use cga_collide::double_sphere::{
    collide, collide_with, Decision, DoubleSphereTree, InnerSphereKind, Scratch,
};
use cga_collide::mesh::TriMesh;
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::polyhedron::{ConvexPolyhedron, PolyhedronError};
use cga_collide::query::{Collider, Mode};
use cga_collide::{Intersects, Triangle};

const KINDS: [InnerSphereKind; 2] = [InnerSphereKind::Centroid, InnerSphereKind::Chebyshev];
const PAIRS: [(&str, &str); 4] = [
    ("truncated_octahedron", "diamond"),
    ("truncated_octahedron", "rh"),
    ("octahedron", "diamond"),
    ("cube", "cube"),
];

fn poly(name: &str) -> &'static ConvexPolyhedron {
    static P: OnceLock<Vec<(&'static str, ConvexPolyhedron)>> = OnceLock::new();
    let all = P.get_or_init(|| {
        ConvexPolyhedron::NAMES
            .iter()
            .map(|&n| (n, ConvexPolyhedron::by_name(n).unwrap()))
            .collect()
    });
    &all.iter().find(|(n, _)| *n == name).unwrap().1
}

/// Trees for every solid, level 0..=4, both kinds (built once).
fn tree(name: &str, level: usize, kind: InnerSphereKind) -> &'static DoubleSphereTree {
    static T: OnceLock<Vec<(&'static str, usize, InnerSphereKind, DoubleSphereTree)>> =
        OnceLock::new();
    let all = T.get_or_init(|| {
        let mut v = Vec::new();
        for &n in &ConvexPolyhedron::NAMES {
            for l in 0..=4 {
                for k in KINDS {
                    v.push((n, l, k, DoubleSphereTree::build(poly(n), l, k).unwrap()));
                }
            }
        }
        v
    });
    &all.iter()
        .find(|(n, l, k, _)| *n == name && *l == level && *k == kind)
        .unwrap()
        .3
}

#[test]
fn table_1_counts() {
    let want = [
        ("cube", 8, 12, 6),
        ("octahedron", 6, 12, 8),
        ("diamond", 41, 88, 49),
        ("rh", 120, 180, 62),
        ("truncated_octahedron", 24, 36, 14),
    ];
    for (name, v, e, f) in want {
        let p = poly(name);
        assert_eq!(
            (p.num_vertices(), p.num_edges(), p.num_faces()),
            (v, e, f),
            "{name}"
        );
        // Fan triangulation: a k-gon gives k - 2 triangles.
        let t: usize = p.faces().iter().map(|f| f.len() - 2).sum();
        assert_eq!(p.triangles().len(), t);
        assert_eq!(p.triangle_faces().len(), t);
        // Closed: the triangle mesh uses every edge twice.
        assert!(p.to_trimesh().is_closed(), "{name}");
    }
}

#[test]
fn polyhedra_are_convex_outward_and_unit() {
    for name in ConvexPolyhedron::NAMES {
        let p = poly(name);
        assert!(
            p.volume() > 0.0,
            "{name}: outward orientation gives a positive volume"
        );
        let centroid =
            p.vertices().iter().map(|v| v.coords).sum::<Vector3<f64>>() / p.num_vertices() as f64;
        for f in 0..p.num_faces() {
            let n = p.face_normal(f);
            let v0 = p.vertices()[p.faces()[f][0]];
            // Outward: the centroid is behind every face.
            assert!(n.dot(&(centroid - v0.coords)) < 0.0, "{name} face {f}");
            // Convex: every vertex is behind every face plane.
            for v in p.vertices() {
                assert!(n.dot(&(v - v0)) < 1e-12, "{name} face {f}");
            }
        }
        // Circumradius 1 about the origin (the smallest enclosing sphere).
        let b = smallest_enclosing_ball(p.vertices());
        assert!(b.centre.coords.norm() < 1e-9, "{name}: {:?}", b.centre);
        assert!((b.radius - 1.0).abs() < 1e-9, "{name}: {}", b.radius);
        // The triangle map points to the face that contains the triangle.
        for (t, &f) in p.triangle_faces().iter().enumerate() {
            assert!(p.triangles()[t]
                .iter()
                .all(|&i| p.faces()[f].contains(&(i as usize))));
        }
    }
    assert!(matches!(
        ConvexPolyhedron::by_name("dodecahedron"),
        Err(PolyhedronError::UnknownName(_))
    ));
}

#[test]
fn validation_rejects_bad_input() {
    let cube = poly("cube");
    let v = cube.vertices().to_vec();
    let f = cube.faces().to_vec();
    assert!(ConvexPolyhedron::new(v.clone(), f.clone()).is_ok());
    // Open: drop a face.
    let err = ConvexPolyhedron::new(v.clone(), f[1..].to_vec()).unwrap_err();
    assert!(matches!(err, PolyhedronError::BadEdge { .. }), "{err}");
    // Inward face.
    let mut g = f.clone();
    g[0].reverse();
    assert!(ConvexPolyhedron::new(v.clone(), g).is_err());
    // All faces inward: consistent but inside out.
    let g: Vec<Vec<usize>> = f
        .iter()
        .map(|x| x.iter().rev().copied().collect())
        .collect();
    let err = ConvexPolyhedron::new(v.clone(), g).unwrap_err();
    assert!(
        matches!(
            err,
            PolyhedronError::NonConvexFace { .. } | PolyhedronError::NotConvex { .. }
        ),
        "{err}"
    );
    // Non-planar face: push a vertex out.
    let mut w = v.clone();
    w[0].x *= 1.1;
    let err = ConvexPolyhedron::new(w, f.clone()).unwrap_err();
    assert!(matches!(err, PolyhedronError::NonPlanar { .. }), "{err}");
    // Dent: move a vertex inwards along its diagonal (faces stay non-planar -> error).
    let mut w = v.clone();
    w[0] = Point3::from(w[0].coords * 0.5);
    assert!(ConvexPolyhedron::new(w, f.clone()).is_err());
    // Index out of range.
    let mut g = f.clone();
    g[0][0] = 99;
    assert!(matches!(
        ConvexPolyhedron::new(v.clone(), g).unwrap_err(),
        PolyhedronError::IndexOutOfRange { index: 99, .. }
    ));
    // Non-finite.
    let mut w = v.clone();
    w[3].y = f64::NAN;
    assert!(matches!(
        ConvexPolyhedron::new(w, f).unwrap_err(),
        PolyhedronError::NonFinite { vertex: 3, .. }
    ));
}

/// Independent brute force: every pair of transformed triangles with the exact test, plus
/// containment by the mesh collider's exact point-in-solid test.
fn brute(
    a: &ConvexPolyhedron,
    pa: &Isometry3<f64>,
    b: &ConvexPolyhedron,
    pb: &Isometry3<f64>,
) -> bool {
    let ma: TriMesh = a.to_trimesh().transformed(pa).unwrap();
    let mb: TriMesh = b.to_trimesh().transformed(pb).unwrap();
    let ta: Vec<Triangle> = (0..ma.num_triangles())
        .map(|i| {
            let [x, y, z] = ma.triangle(i);
            Triangle::new(x, y, z).unwrap()
        })
        .collect();
    let tb: Vec<Triangle> = (0..mb.num_triangles())
        .map(|i| {
            let [x, y, z] = mb.triangle(i);
            Triangle::new(x, y, z).unwrap()
        })
        .collect();
    if ta.iter().any(|x| tb.iter().any(|y| x.intersects(y))) {
        return true;
    }
    let ca = Collider::new(ma.clone());
    let cb = Collider::new(mb.clone());
    cb.contains_point(&ma.vertices()[0], Mode::Bvh)
        || ca.contains_point(&mb.vertices()[0], Mode::Bvh)
}

fn pose(t: [f64; 3], axis: [f64; 3], angle: f64) -> Isometry3<f64> {
    let axis = Vector3::new(axis[0], axis[1], axis[2]);
    let rot = if axis.norm() > 1e-9 {
        UnitQuaternion::from_axis_angle(&cga_collide::nalgebra::Unit::new_normalize(axis), angle)
    } else {
        UnitQuaternion::identity()
    };
    Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rot)
}

#[test]
fn quick_random_agreement() {
    let mut scratch = Scratch::new();
    let mut rng = cga_collide::adversarial::SplitMix64(42);
    let mut hits = 0;
    for (na, nb) in PAIRS {
        for level in [0, 3] {
            for kind in KINDS {
                let (ta, tb) = (tree(na, level, kind), tree(nb, level, kind));
                for _ in 0..200 {
                    let pa = pose(
                        [0.0; 3],
                        [rng.float(-1., 1.), rng.float(-1., 1.), rng.float(-1., 1.)],
                        rng.float(0., 6.3),
                    );
                    let pb = pose(
                        [rng.float(-2., 2.), rng.float(-2., 2.), rng.float(-2., 2.)],
                        [rng.float(-1., 1.), rng.float(-1., 1.), rng.float(-1., 1.)],
                        rng.float(0., 6.3),
                    );
                    let got = collide_with(&mut scratch, ta, &pa, tb, &pb);
                    let want = brute(poly(na), &pa, poly(nb), &pb);
                    assert_eq!(
                        got.collides, want,
                        "{na} {nb} level {level} {kind:?} {pa:?} {pb:?} {got:?}"
                    );
                    hits += usize::from(want);
                }
            }
        }
    }
    assert!(hits > 100);
    let _ = collide;
    let _ = Decision::Faces;
    let _ = depth;
    let _ = chebyshev_brute;
    let _ = smallest_enclosing_ball_brute;
}

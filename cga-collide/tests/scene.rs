//! Scenes against brute force: every pair question equals the exact pose query over all pairs,
//! on random scenes and on constructed ones where objects touch exactly (shared faces, stacked
//! boxes, edges on faces, one object inside another with the solid semantics), and after every
//! kind of update equals a scene rebuilt from scratch.

use std::sync::Arc;

use cga_collide::collider::{pose_from_degrees, Collider};
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion};
use cga_collide::query::segment_triangle_entry;
use cga_collide::scene::SegmentHit;
use cga_collide::scene::{ObjectId, Scene};
use cga_collide::{Error, Intersects, Segment, TriMesh};
use proptest::prelude::*;

fn cube(side: f64) -> Arc<Collider> {
    let mesh = TriMesh::cuboid(Point3::origin(), Point3::new(side, side, side)).unwrap();
    Arc::new(Collider::new(mesh))
}

/// A few shared colliders: unit cube, a flat slab, a small cube, a subdivided cube.
fn parts() -> Vec<Arc<Collider>> {
    let slab = TriMesh::cuboid(Point3::origin(), Point3::new(2.0, 2.0, 0.5)).unwrap();
    let fine = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0))
        .unwrap()
        .subdivided();
    vec![
        cube(1.0),
        Arc::new(Collider::new(slab)),
        cube(0.25),
        Arc::new(Collider::new(fine)),
    ]
}

/// Poses on the half-integer lattice with quarter turns: faces meet faces exactly, edges lie on
/// faces, boxes stack.
fn lattice_pose() -> impl Strategy<Value = Isometry3<f64>> {
    (
        prop::array::uniform3(-4i32..4),
        prop::array::uniform3(0i32..4),
    )
        .prop_map(|(t, r)| {
            pose_from_degrees(
                r.map(|k| 90.0 * f64::from(k)),
                t.map(|k| 0.5 * f64::from(k)),
            )
        })
}

/// Random rigid poses in a small box (many near misses and crossings).
fn random_pose() -> impl Strategy<Value = Isometry3<f64>> {
    (
        prop::array::uniform3(-2.0f64..2.0),
        prop::array::uniform3(-3.2f64..3.2),
    )
        .prop_map(|(t, r)| {
            Isometry3::from_parts(
                Translation3::new(t[0], t[1], t[2]),
                UnitQuaternion::from_euler_angles(r[0], r[1], r[2]),
            )
        })
}

fn any_pose() -> impl Strategy<Value = Isometry3<f64>> {
    prop_oneof![lattice_pose(), random_pose()]
}

/// The objects of a scene as (part, pose).
fn objects(n: usize) -> impl Strategy<Value = Vec<(usize, Isometry3<f64>)>> {
    prop::collection::vec((0usize..4, any_pose()), 0..n)
}

fn build(parts: &[Arc<Collider>], objects: &[(usize, Isometry3<f64>)]) -> (Scene, Vec<ObjectId>) {
    let mut scene = Scene::new();
    let ids = objects
        .iter()
        .map(|(k, pose)| scene.add(parts[*k].clone(), *pose).unwrap())
        .collect();
    (scene, ids)
}

/// Every pair of the scene's objects, answered by `query` directly.
fn brute(
    scene: &Scene,
    query: impl Fn(&Collider, &Isometry3<f64>, &Collider, &Isometry3<f64>) -> bool,
) -> Vec<(ObjectId, ObjectId)> {
    let ids = scene.ids();
    let mut out = Vec::new();
    for (k, &a) in ids.iter().enumerate() {
        for &b in &ids[k + 1..] {
            let (ca, pa) = (scene.collider(a).unwrap(), scene.pose(a).unwrap());
            let (cb, pb) = (scene.collider(b).unwrap(), scene.pose(b).unwrap());
            if query(ca, pa, cb, pb) {
                out.push((a, b));
            }
        }
    }
    out
}

fn touching(scene: &Scene) -> Vec<(ObjectId, ObjectId)> {
    brute(scene, |a, pa, b, pb| a.collides_at(pa, b, pb).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn pairs_equal_brute_force(objs in objects(14), c in 0.0f64..0.6) {
        let parts = parts();
        let (mut scene, ids) = build(&parts, &objs);
        prop_assert_eq!(scene.colliding_pairs().unwrap(), touching(&scene));
        prop_assert_eq!(
            scene.pairs_within_distance(c).unwrap(),
            brute(&scene, |a, pa, b, pb| a.within_distance_at(pa, b, pb, c).unwrap())
        );
        for &id in &ids {
            let want: Vec<ObjectId> = touching(&scene)
                .into_iter()
                .filter_map(|(a, b)| if a == id { Some(b) } else if b == id { Some(a) } else { None })
                .collect();
            let mut want = want;
            want.sort_unstable();
            prop_assert_eq!(scene.colliding_with(id).unwrap(), want);
        }
        scene.set_solid(true);
        prop_assert_eq!(
            scene.colliding_pairs().unwrap(),
            brute(&scene, |a, pa, b, pb| a.collides_solid_at(pa, b, pb).unwrap())
        );
    }

    #[test]
    fn updates_equal_a_scene_rebuilt_from_scratch(
        objs in objects(12),
        moves in prop::collection::vec((0usize..12, any_pose()), 0..12),
        removals in prop::collection::vec(0usize..12, 0..4),
        added in objects(4),
    ) {
        let parts = parts();
        let (mut scene, ids) = build(&parts, &objs);
        let mut current: Vec<Option<(usize, Isometry3<f64>)>> = objs.iter().copied().map(Some).collect();
        if !ids.is_empty() {
            // One pose at a time, then the rest in one call.
            let (one, many) = moves.split_at(moves.len() / 2);
            for &(k, pose) in one {
                let k = k % ids.len();
                scene.set_pose(ids[k], pose).unwrap();
                current[k].as_mut().unwrap().1 = pose;
            }
            let batch: Vec<(ObjectId, Isometry3<f64>)> =
                many.iter().map(|&(k, pose)| (ids[k % ids.len()], pose)).collect();
            scene.set_poses(&batch).unwrap();
            for &(k, pose) in many {
                current[k % ids.len()].as_mut().unwrap().1 = pose;
            }
            for k in removals {
                let k = k % ids.len();
                if current[k].take().is_some() {
                    scene.remove(ids[k]).unwrap();
                    let refused = matches!(scene.pose(ids[k]), Err(Error::UnknownObject { .. }));
                    prop_assert!(refused, "a removed handle must be refused");
                }
            }
        }
        for &(k, pose) in &added {
            scene.add(parts[k].clone(), pose).unwrap();
        }
        // The same objects, added afresh in slot order.
        let live = scene.ids();
        let rebuilt_objects: Vec<(usize, Isometry3<f64>)> = live
            .iter()
            .map(|&id| {
                let c = scene.collider(id).unwrap();
                let k = parts.iter().position(|p| Arc::ptr_eq(p, c)).unwrap();
                (k, *scene.pose(id).unwrap())
            })
            .collect();
        let (rebuilt, fresh) = build(&parts, &rebuilt_objects);
        let rename = |pairs: Vec<(ObjectId, ObjectId)>| -> Vec<(usize, usize)> {
            pairs
                .into_iter()
                .map(|(a, b)| {
                    let at = |x: ObjectId| live.iter().position(|&l| l == x).unwrap();
                    (at(a), at(b))
                })
                .collect()
        };
        let rename_fresh = |pairs: Vec<(ObjectId, ObjectId)>| -> Vec<(usize, usize)> {
            pairs
                .into_iter()
                .map(|(a, b)| {
                    let at = |x: ObjectId| fresh.iter().position(|&l| l == x).unwrap();
                    (at(a), at(b))
                })
                .collect()
        };
        prop_assert_eq!(
            rename(scene.colliding_pairs().unwrap()),
            rename_fresh(rebuilt.colliding_pairs().unwrap())
        );
        prop_assert_eq!(scene.colliding_pairs().unwrap(), touching(&scene));
    }

    #[test]
    fn nearest_pair_is_the_least_distance(objs in prop::collection::vec((0usize..4, any_pose()), 2..8)) {
        let parts = parts();
        let (scene, ids) = build(&parts, &objs);
        let (a, b, d) = scene.nearest_pair().unwrap().expect("two objects");
        prop_assert!(d.distance.is_finite() && d.error_bound.is_finite());
        if !touching(&scene).is_empty() {
            // Some surfaces meet: a pair whose surfaces meet, at distance exactly 0, proved by
            // a pair of placed triangles that intersect exactly.
            prop_assert_eq!((d.distance, d.error_bound), (0.0, 0.0));
            let (ca, pa) = (scene.collider(a).unwrap(), scene.pose(a).unwrap());
            let (cb, pb) = (scene.collider(b).unwrap(), scene.pose(b).unwrap());
            prop_assert!(ca.collides_at(pa, cb, pb).unwrap());
            let (i, j) = d.triangles.expect("a triangle pair");
            let (ta, tb) = (
                ca.placed(pa).unwrap().mesh().triangle(i),
                cb.placed(pb).unwrap().mesh().triangle(j),
            );
            prop_assert!(ta.intersects(&tb));
            // The witnesses are the triangles' f64 nearest points: together up to rounding.
            prop_assert!((d.witness_a - d.witness_b).norm() <= 1e-9, "{:?}", d);
            // The nearest object to one touching others: the smallest of them, at exactly 0.
            let pairs = touching(&scene);
            for &x in &ids {
                let first = pairs
                    .iter()
                    .filter_map(|&(p, q)| if p == x { Some(q) } else if q == x { Some(p) } else { None })
                    .min();
                if let Some(first) = first {
                    let (n, e) = scene.nearest_to(x).unwrap().expect("another object");
                    prop_assert_eq!((n, e.distance, e.error_bound), (first, 0.0, 0.0));
                }
            }
        }
        let mut least = f64::INFINITY;
        for (k, &x) in ids.iter().enumerate() {
            for &y in &ids[k + 1..] {
                let e = scene
                    .collider(x)
                    .unwrap()
                    .distance_at(scene.pose(x).unwrap(), scene.collider(y).unwrap(), scene.pose(y).unwrap())
                    .unwrap();
                least = least.min(e.distance - e.error_bound);
            }
        }
        prop_assert!(d.distance - d.error_bound <= least + 1e-12, "{a:?} {b:?} {d:?} vs {least}");
        // The nearest object to `a` is at that distance too.
        let (_, to_a) = scene.nearest_to(a).unwrap().expect("another object");
        let gap = (to_a.distance - d.distance).abs();
        prop_assert!(gap <= to_a.error_bound + d.error_bound + 1e-12, "{:?} vs {:?}", to_a, d);
    }
}

#[test]
fn stacked_boxes_and_shared_faces() {
    let unit = cube(1.0);
    let mut scene = Scene::new();
    // A column of three boxes face to face, a fourth beside the middle one (edge contact only
    // with the others through the middle one's face), and one far away.
    let a = scene.add(unit.clone(), Isometry3::identity()).unwrap();
    let b = scene
        .add(unit.clone(), Isometry3::translation(0.0, 0.0, 1.0))
        .unwrap();
    let c = scene
        .add(unit.clone(), Isometry3::translation(0.0, 0.0, 2.0))
        .unwrap();
    let d = scene
        .add(unit.clone(), Isometry3::translation(1.0, 1.0, 1.0))
        .unwrap();
    let far = scene
        .add(unit.clone(), Isometry3::translation(10.0, 0.0, 0.0))
        .unwrap();
    let want = vec![(a, b), (a, d), (b, c), (b, d), (c, d)];
    assert_eq!(scene.colliding_pairs().unwrap(), want);
    assert_eq!(touching(&scene), want);
    assert_eq!(scene.colliding_with(far).unwrap(), vec![]);
    // Touching objects: a nearest pair at distance 0, certified.
    let (p, q, dist) = scene.nearest_pair().unwrap().expect("objects");
    assert!(want.contains(&(p, q)), "{p:?} {q:?}");
    assert_eq!((dist.distance, dist.error_bound), (0.0, 0.0));
    // The nearest object to b: of the three it touches, the smallest handle, at exactly 0.
    let (n, dist) = scene.nearest_to(b).unwrap().expect("objects");
    assert_eq!((n, dist.distance, dist.error_bound), (a, 0.0, 0.0));
    assert_eq!(scene.nearest_to(c).unwrap().map(|(n, _)| n), Some(b));
    // Excluded pairs and groups.
    scene.exclude_pair(b, a).unwrap();
    // d is alone in group 2 and meets only group 2; the column is group 1 and meets group 1.
    scene.set_groups(d, 0b10, 0b10).unwrap();
    for x in [a, b, c, far] {
        scene.set_groups(x, 0b01, 0b01).unwrap();
    }
    assert_eq!(scene.colliding_pairs().unwrap(), vec![(b, c)]);
    scene.include_pair(a, b).unwrap();
    assert_eq!(scene.colliding_pairs().unwrap(), vec![(a, b), (b, c)]);
    // A gap of exactly 1 to the far box from c? No: far is 9 away in x from the column.
    assert_eq!(
        scene
            .pairs_within_distance(8.999)
            .unwrap()
            .iter()
            .filter(|p| p.1 == far)
            .count(),
        0
    );
    assert!(scene
        .pairs_within_distance(9.0)
        .unwrap()
        .contains(&(a, far)));
}

#[test]
fn one_object_inside_another_counts_only_as_a_solid() {
    let mut scene = Scene::new();
    let big = scene.add(cube(10.0), Isometry3::identity()).unwrap();
    let small = scene
        .add(cube(1.0), Isometry3::translation(4.0, 4.0, 4.0))
        .unwrap();
    assert_eq!(scene.colliding_pairs().unwrap(), vec![]);
    scene.set_solid(true);
    assert_eq!(scene.colliding_pairs().unwrap(), vec![(big, small)]);
    // An outside collider: does it fit?
    let probe = cube(0.5);
    assert_eq!(
        scene
            .colliding_at(&probe, &Isometry3::translation(4.5, 4.5, 4.5))
            .unwrap(),
        vec![big, small]
    );
    scene.set_solid(false);
    assert_eq!(
        scene
            .colliding_at(&probe, &Isometry3::translation(9.5, 4.0, 4.0))
            .unwrap(),
        vec![big]
    );
}

#[test]
fn nearest_pair_is_between_surfaces_in_solid_mode() {
    // A box inside a big one (surfaces 0.4 apart), and two boxes 0.1 apart far away: the
    // solids of the first pair overlap, but the nearest surfaces are those of the second.
    let mut scene = Scene::new();
    scene.add(cube(2.0), Isometry3::identity()).unwrap();
    scene
        .add(cube(1.2), Isometry3::translation(0.4, 0.4, 0.4))
        .unwrap();
    let c = scene
        .add(cube(1.0), Isometry3::translation(10.0, 0.0, 0.0))
        .unwrap();
    let d = scene
        .add(cube(1.0), Isometry3::translation(11.1, 0.0, 0.0))
        .unwrap();
    scene.set_solid(true);
    assert_eq!(scene.colliding_pairs().unwrap().len(), 1);
    let (p, q, dist) = scene.nearest_pair().unwrap().expect("objects");
    assert_eq!((p, q), (c, d));
    assert!(
        (dist.distance - 0.1).abs() <= dist.error_bound + 1e-12,
        "{dist:?}"
    );
}

#[test]
fn first_hits_along_a_segment() {
    let unit = cube(1.0);
    let mut scene = Scene::new();
    // A row of boxes along x, two sharing the face x = 3 (both first met there), and one the
    // segment only grazes along an edge.
    let a = scene
        .add(unit.clone(), Isometry3::translation(5.0, 0.0, 0.0))
        .unwrap();
    let b = scene
        .add(unit.clone(), Isometry3::translation(3.0, 0.0, 0.0))
        .unwrap();
    let c = scene
        .add(unit.clone(), Isometry3::translation(2.0, 0.0, 0.0))
        .unwrap();
    let edge = scene
        .add(unit.clone(), Isometry3::translation(0.0, -1.0, -0.5))
        .unwrap();
    let s = Segment::new(Point3::new(-1.0, 0.0, 0.5), Point3::new(9.0, 0.0, 0.5)).unwrap();
    let along = scene.segment_hits_along(&s).unwrap();
    let got: Vec<(ObjectId, String)> = along
        .iter()
        .map(|h| (h.object, h.parameter.to_string()))
        .collect();
    // The grazed box from x = 0 (t = 1/10), c from x = 2 (3/10), b from x = 3 (2/5), a from 5.
    assert_eq!(
        got,
        vec![
            (edge, "1/10".into()),
            (c, "3/10".into()),
            (b, "2/5".into()),
            (a, "3/5".into())
        ]
    );
    assert_eq!(along[1].point, Point3::new(2.0, 0.0, 0.5));
    assert_eq!(
        scene.first_segment_hit(&s).unwrap().map(|h| h.object),
        Some(edge)
    );
    // Starting inside c: the first hit is where the segment leaves it (x = 3), shared by b.
    let inside = Segment::new(Point3::new(2.5, 0.5, 0.5), Point3::new(9.0, 0.5, 0.5)).unwrap();
    let along = scene.segment_hits_along(&inside).unwrap();
    assert_eq!((along[0].object, along[0].parameter_f64()), (b, 0.5 / 6.5));
    assert_eq!(along[1].object, c);
    assert_eq!(along[0].parameter, along[1].parameter);
    // Missing everything.
    let miss = Segment::new(Point3::new(-1.0, 5.0, 0.5), Point3::new(9.0, 5.0, 0.5)).unwrap();
    assert_eq!(scene.first_segment_hit(&miss).unwrap(), None);
}

#[test]
fn segments_handles_and_bad_poses() {
    let unit = cube(1.0);
    let mut scene = Scene::new();
    let a = scene.add(unit.clone(), Isometry3::identity()).unwrap();
    let b = scene
        .add(unit.clone(), Isometry3::translation(3.0, 0.0, 0.0))
        .unwrap();
    let through = Segment::new(Point3::new(-1.0, 0.5, 0.5), Point3::new(5.0, 0.5, 0.5)).unwrap();
    assert_eq!(scene.segment_hits(&through).unwrap(), vec![a, b]);
    let short = Segment::new(Point3::new(-1.0, 0.5, 0.5), Point3::new(0.0, 0.5, 0.5)).unwrap();
    assert_eq!(scene.segment_hits(&short).unwrap(), vec![a]); // touching the face counts
                                                              // A bad pose moves nothing, and says which entry.
    let mut bad = Isometry3::identity();
    bad.translation.vector.x = f64::NAN;
    assert!(scene.set_pose(a, bad).is_err());
    let err = scene
        .set_poses(&[(a, Isometry3::translation(0.5, 0.0, 0.0)), (b, bad)])
        .unwrap_err();
    assert!(matches!(err, Error::InBatch { index: 1, .. }), "{err}");
    assert_eq!(*scene.pose(a).unwrap(), Isometry3::identity());
    assert!(scene.add(unit.clone(), bad).is_err());
    assert_eq!(scene.len(), 2);
    // A removed object's handle is refused, also after its slot is reused.
    scene.remove(a).unwrap();
    let c = scene.add(unit, Isometry3::identity()).unwrap();
    assert_eq!(c.index(), a.index());
    assert!(matches!(scene.pose(a), Err(Error::UnknownObject { .. })));
    assert!(scene.remove(a).is_err());
    assert!(scene.nearest_to(c).unwrap().is_some());
    assert!(Scene::new().nearest_pair().unwrap().is_none());
}

/// Segments with ends on the half-integer lattice (along faces, edges and through corners of
/// the lattice boxes) or anywhere in the scene's box; sometimes a point.
fn segment() -> impl Strategy<Value = Segment> {
    let lattice =
        prop::array::uniform3(-8i32..10).prop_map(|v| Point3::from(v.map(|k| 0.5 * f64::from(k))));
    let random = prop::array::uniform3(-4.0f64..5.0).prop_map(Point3::from);
    let end = prop_oneof![lattice, random];
    (end.clone(), end, 0..8u8)
        .prop_map(|(a, b, k)| Segment::new(a, if k == 0 { a } else { b }).unwrap())
}

/// The first hit of a segment on every object, by brute force over every placed triangle.
fn hits_by_brute_force(scene: &Scene, s: &Segment) -> Vec<SegmentHit> {
    let mut out: Vec<SegmentHit> = Vec::new();
    for id in scene.ids() {
        let placed = scene
            .collider(id)
            .unwrap()
            .placed(scene.pose(id).unwrap())
            .unwrap();
        let first = (0..placed.mesh().num_triangles() as u32)
            .filter_map(|i| segment_triangle_entry(s, &placed.mesh().triangle(i)).map(|t| (t, i)))
            .min();
        if let Some((parameter, triangle)) = first {
            out.push(SegmentHit {
                object: id,
                triangle,
                parameter,
                point: Point3::origin(),
            });
        }
    }
    out.sort_by(|x, y| x.parameter.cmp(&y.parameter).then(x.object.cmp(&y.object)));
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// Every object a segment hits, with its first hit, in order: equal to brute force over
    /// every triangle of every object; the first hit is the first of them.
    #[test]
    fn segment_hits_in_order_equal_brute_force(objs in objects(12), segments in prop::collection::vec(segment(), 1..6)) {
        let parts = parts();
        let (scene, _) = build(&parts, &objs);
        for s in &segments {
            let along = scene.segment_hits_along(s).unwrap();
            let want = hits_by_brute_force(&scene, s);
            let key = |h: &SegmentHit| (h.object, h.triangle, h.parameter.clone());
            prop_assert_eq!(along.iter().map(key).collect::<Vec<_>>(), want.iter().map(key).collect::<Vec<_>>());
            let mut objects: Vec<ObjectId> = along.iter().map(|h| h.object).collect();
            objects.sort_unstable();
            prop_assert_eq!(scene.segment_hits(s).unwrap(), objects);
            prop_assert_eq!(scene.first_segment_hit(s).unwrap(), along.first().cloned());
            for h in &along {
                // The reported point is the exact point of the hit, rounded.
                let t = h.parameter_f64();
                prop_assert!((0.0..=1.0).contains(&t));
                let approx = s.a() + (s.b() - s.a()) * t;
                prop_assert!((approx - h.point).norm() <= 1e-12 * (1.0 + s.a().coords.norm() + s.b().coords.norm()));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    /// Scenes large enough for the grid broad phase (and a floor far larger than a cell, which
    /// is tested against every box): the same pairs as brute force.
    #[test]
    fn large_scenes_agree_with_brute_force(
        objs in prop::collection::vec((0usize..3, any_pose()), 300..340),
        spread in 2.0f64..6.0,
        c in 0.0f64..0.3,
    ) {
        let parts = parts();
        let floor = Arc::new(Collider::new(
            TriMesh::cuboid(Point3::new(-20.0, -20.0, -1.0), Point3::new(20.0, 20.0, 0.0)).unwrap(),
        ));
        let mut scene = Scene::new();
        for (k, pose) in &objs {
            let mut pose = *pose;
            pose.translation.vector *= spread; // from packed to sparse
            scene.add(parts[*k].clone(), pose).unwrap();
        }
        scene.add(floor.clone(), Isometry3::identity()).unwrap();
        scene.add(floor, Isometry3::translation(0.0, 0.0, -0.5)).unwrap();
        prop_assert_eq!(scene.colliding_pairs().unwrap(), touching(&scene));
        prop_assert_eq!(
            scene.pairs_within_distance(c).unwrap(),
            brute(&scene, |a, pa, b, pb| a.within_distance_at(pa, b, pb, c).unwrap())
        );
    }
}

//! The robot model against its fixture arm (`cli/tests/data/robot/toy_arm`): loading, pairs,
//! forward kinematics, every question against a brute force over all part pairs, and errors.

use std::path::PathBuf;

use nalgebra::{Isometry3, Point3, Vector3};

use super::geometry::PairTest;
use super::*;
use crate::shape::Shape;
use crate::Ball;

fn data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cli/tests/data/robot")
}

fn arm() -> Robot {
    let dir = data().join("toy_arm");
    Robot::from_urdf(dir.join("arm.urdf"), &[data()], Some(&dir.join("arm.srdf")))
        .expect("the fixture loads")
}

fn pair(a: &str, b: &str) -> (String, String) {
    (a.to_string(), b.to_string())
}

/// A small deterministic generator (no dependency): configurations within the limits.
fn configs(n: usize) -> Vec<Vec<f64>> {
    let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| {
            vec![
                next() * 6.0 - 3.0,
                next() * 5.0 - 2.5,
                next() * 5.0 - 2.5,
                next() * 0.3 - 0.2,
            ]
        })
        .collect()
}

#[test]
fn loads_joints_links_and_the_allowed_pairs() {
    let robot = arm();
    assert_eq!(
        robot.joint_names(),
        ["shoulder_pan", "shoulder_lift", "elbow", "slide"]
    );
    assert_eq!(robot.joint_limits()[0], None);
    assert_eq!(robot.joint_limits()[3], Some((-0.2, 0.1)));
    // base+column is one body; adjacent bodies and the SRDF's shoulder-fore are left out.
    let mut expected = vec![
        ("base", "upper"),
        ("base", "fore"),
        ("base", "slider"),
        ("base", "tool"),
        ("column", "upper"),
        ("column", "fore"),
        ("column", "slider"),
        ("column", "tool"),
        ("shoulder", "slider"),
        ("shoulder", "tool"),
        ("upper", "slider"),
        ("upper", "tool"),
    ];
    expected.sort();
    let mut got = robot.allowed_pairs();
    got.sort();
    assert_eq!(got, expected);
    let mut fewer = robot.clone();
    fewer.exclude_pair("slider", "base").unwrap();
    assert_eq!(fewer.allowed_pairs().len(), 11);
    assert!(fewer.exclude_pair("slider", "nope").is_err());
}

#[test]
fn forward_kinematics_places_each_link() {
    let robot = arm();
    let q = [std::f64::consts::FRAC_PI_2, 0.0, 0.0, 0.1];
    let poses = robot.link_poses(&q).unwrap();
    // Turned a quarter about z: the slider at x = 0.5 along the forearm is at y = 0.5.
    let slider = poses[robot.link("slider").unwrap()] * Point3::origin();
    assert!((slider - Point3::new(0.0, 0.5, 0.9)).norm() < 1e-12);
    assert!(robot.link_poses(&[0.0; 3]).is_err());
    assert!(robot.link_poses(&[0.0, f64::NAN, 0.0, 0.0]).is_err());
}

#[test]
fn folded_arm_hits_the_base() {
    let robot = arm();
    assert!(!robot.collides(&[0.0; 4], Against::Itself).unwrap());
    let q = [0.0, 1.9, 0.0, 0.0];
    assert_eq!(
        robot.colliding_pairs(&q, Against::Itself).unwrap(),
        [pair("base", "fore"), pair("base", "slider")]
    );
    assert!(robot.collides(&q, Against::Itself).unwrap());
}

/// Every part pair of every tested link pair, decided without the boxes.
fn brute(robot: &Robot, q: &[f64], c: Option<f64>) -> Vec<(String, String)> {
    let posed = robot.pose_parts(q).unwrap();
    let mut out = Vec::new();
    for &(a, b) in &robot.pairs {
        let hit = robot.link_parts[a].clone().any(|i| {
            robot.link_parts[b].clone().any(|j| {
                let t = PairTest {
                    a: (&robot.parts[i].geometry, &posed.parts[i]),
                    b: (&robot.parts[j].geometry, &posed.parts[j]),
                    solid: robot.solid,
                };
                match c {
                    None => t.touches().unwrap(),
                    Some(c) => t.within(c).unwrap(),
                }
            })
        });
        if hit {
            let (x, y) = (robot.link_names[a].clone(), robot.link_names[b].clone());
            out.push(if x <= y { (x, y) } else { (y, x) });
        }
    }
    out.sort();
    out
}

#[test]
fn answers_equal_the_brute_force_over_part_pairs() {
    let robot = arm();
    // The shoulder's cylinder has an exact clearance test only for c = 0.
    let mut measurable = arm();
    measurable.exclude_pair("shoulder", "slider").unwrap();
    measurable.exclude_pair("shoulder", "tool").unwrap();
    let qs = configs(300);
    let mut colliding = 0;
    for q in &qs {
        let pairs = robot.colliding_pairs(q, Against::Itself).unwrap();
        assert_eq!(pairs, brute(&robot, q, None), "q = {q:?}");
        assert_eq!(
            robot.collides(q, Against::Itself).unwrap(),
            !pairs.is_empty()
        );
        assert_eq!(
            measurable
                .pairs_within_distance(q, 0.05, Against::Itself)
                .unwrap(),
            brute(&measurable, q, Some(0.05))
        );
        colliding += usize::from(!pairs.is_empty());
    }
    // The sample has both answers.
    assert!(
        colliding > 10 && colliding < 290,
        "{colliding} of 300 collide"
    );
    let batch = robot.colliding_pairs_batch(&qs, Against::Itself).unwrap();
    for (q, b) in qs.iter().zip(&batch) {
        assert_eq!(*b, robot.colliding_pairs(q, Against::Itself).unwrap());
    }
    let firsts = robot.collides_batch(&qs, Against::Itself).unwrap();
    assert_eq!(
        firsts,
        batch.iter().map(|b| !b.is_empty()).collect::<Vec<_>>()
    );
}

#[test]
fn nearest_is_the_least_pair_distance_within_its_bound() {
    let mut robot = arm();
    // The shoulder's cylinder has no certified distance yet: leave its pairs out.
    robot.exclude_pair("shoulder", "slider").unwrap();
    robot.exclude_pair("shoulder", "tool").unwrap();
    for q in configs(40) {
        let Some(n) = robot.nearest(&q, Against::Itself).unwrap() else {
            panic!("the arm has tested pairs");
        };
        let d = &n.distance;
        let within = robot.pairs_within_distance(&q, d.distance + d.error_bound, Against::Itself);
        assert!(within.unwrap().contains(&n.pair));
        let below = (d.distance - d.error_bound).max(0.0) * 0.999;
        if below > 0.0 {
            assert!(robot
                .pairs_within_distance(&q, below, Against::Itself)
                .unwrap()
                .is_empty());
        }
    }
    let q = [0.0, 1.9, 0.0, 0.0];
    let n = robot.nearest(&q, Against::Itself).unwrap().unwrap();
    assert_eq!(n.distance.distance, 0.0);
}

#[test]
fn environment_objects_are_named_by_their_index() {
    let mut robot = arm();
    let mut scene = Scene::new();
    let ball: Shape = Ball::new(Point3::new(0.3, 0.0, 0.9), 0.05).unwrap().into();
    scene.add_shape(ball, Isometry3::identity()).unwrap();
    let far: Shape =
        crate::shape::Cuboid::axis_aligned(Point3::new(5.0, 0.0, 0.0), Vector3::new(0.1, 1.0, 1.0))
            .unwrap()
            .into();
    scene.add_shape(far, Isometry3::identity()).unwrap();
    robot.set_environment(&scene).unwrap();
    assert_eq!(robot.pairs_checked(Against::Environment), 7 * 2);
    let q = [0.0; 4];
    assert_eq!(
        robot.colliding_pairs(&q, Against::Environment).unwrap(),
        [pair("env:0", "fore")]
    );
    assert!(robot
        .colliding_pairs(&q, Against::Itself)
        .unwrap()
        .is_empty());
    let both = robot
        .colliding_pairs(&[0.0, 1.9, 0.0, 0.0], Against::Both)
        .unwrap();
    assert_eq!(both, [pair("base", "fore"), pair("base", "slider")]);
    let n = robot
        .nearest(&[0.0, -1.0, 0.0, 0.0], Against::Environment)
        .unwrap()
        .unwrap();
    assert!(n.pair.0 == "env:0" || n.pair.1 == "env:0");
}

#[test]
fn solid_meshes_count_a_part_inside() {
    // A ball wholly inside the forearm's bar touches the solid, not the surface.
    let mut robot = arm();
    let mut scene = Scene::new();
    let ball: Shape = Ball::new(Point3::new(0.2, 0.0, 0.9), 0.01).unwrap().into();
    scene.add_shape(ball, Isometry3::identity()).unwrap();
    robot.set_environment(&scene).unwrap();
    assert!(!robot.collides(&[0.0; 4], Against::Environment).unwrap());
    robot.set_solid(true);
    assert!(robot.collides(&[0.0; 4], Against::Environment).unwrap());
}

fn load_error(urdf: &str) -> String {
    Robot::from_urdf_str(urdf, "bad.urdf", ".", &[data()])
        .expect_err("refused")
        .to_string()
}

#[test]
fn errors_name_the_file_line_and_element() {
    let m = load_error("<robot>\n<link name=\"a\"><collision><geometry><box size=\"1 x 1\"/></geometry></collision></link>\n</robot>");
    assert!(m.starts_with("bad.urdf:2: <box>"), "{m}");
    let m = load_error("<robot><link name=\"a\"/>\n<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/><limit lower=\"0\" upper=\"1\"/></joint></robot>");
    assert!(
        m.contains("bad.urdf:2: <joint name=\"j\">") && m.contains("\"b\""),
        "{m}"
    );
    let m = load_error("<robot><link name=\"a\"><collision><geometry><mesh filename=\"package://nope/m.stl\"/></geometry></collision></link></robot>");
    assert!(
        m.contains("<collision>") && m.contains("package://nope/m.stl"),
        "{m}"
    );
    let m = load_error("<robot><link name=\"a\"/><link name=\"b\"/></robot>");
    assert!(m.contains("one root"), "{m}");
    let m = load_error("<robot><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"planar\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>");
    assert!(m.contains("planar"), "{m}");
    let m = load_error("<robot><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>");
    assert!(m.contains("<limit>"), "{m}");
    assert!(load_error("<robot").contains("not valid XML"));
    let mut robot = arm();
    let e = robot.disable_from_srdf(
        "<robot>\n<disable_collisions link1=\"base\" link2=\"ghost\"/></robot>",
        "x.srdf",
    );
    assert!(e
        .unwrap_err()
        .to_string()
        .starts_with("x.srdf:2: <disable_collisions>"));
}

/// Every link × environment object pair, decided on every part without spheres or boxes.
fn brute_environment(robot: &Robot, q: &[f64]) -> Vec<(String, String)> {
    let posed = robot.pose_parts(q).unwrap();
    let mut out = Vec::new();
    for (a, parts) in robot.link_parts.iter().enumerate() {
        for obj in &robot.environment {
            let hit = parts.clone().any(|i| {
                PairTest {
                    a: (&robot.parts[i].geometry, &posed.parts[i]),
                    b: (&obj.geometry, &obj.placed),
                    solid: robot.solid,
                }
                .touches()
                .unwrap()
            });
            if hit {
                let env = format!("env:{}", obj.id.index());
                let link = robot.link_names[a].clone();
                out.push(if link <= env {
                    (link, env)
                } else {
                    (env, link)
                });
            }
        }
    }
    out.sort();
    out
}

/// Configurations a hair from a first contact: a free and a colliding configuration, the
/// segment between them halved 60 times, both ends of the last step kept (the free one
/// within about `1e-18` of the joint ranges of the colliding one). There the spheres and
/// boxes in front of the exact tests decide nothing, so the answers must equal the exact
/// test of every placed part pair; self and against an environment with a cylinder, a cone
/// and a box.
#[test]
fn near_contact_answers_equal_the_exact_test_of_every_placed_pair() {
    let mut robot = arm();
    let mut scene = Scene::new();
    let objects: [Shape; 3] = [
        crate::shape::Cylinder::new(
            Point3::new(0.3, -0.2, 0.6),
            Point3::new(0.3, 0.2, 0.6),
            0.05,
        )
        .unwrap()
        .into(),
        crate::shape::Cone::new(
            Point3::new(-0.3, 0.0, 1.0),
            Point3::new(-0.3, 0.0, 0.7),
            0.1,
        )
        .unwrap()
        .into(),
        crate::shape::Cuboid::axis_aligned(
            Point3::new(0.0, 0.4, 0.8),
            Vector3::new(0.1, 0.05, 0.1),
        )
        .unwrap()
        .into(),
    ];
    for s in objects {
        scene.add_shape(s, Isometry3::identity()).unwrap();
    }
    robot.set_environment(&scene).unwrap();
    let mut checked = 0;
    for against in [Against::Itself, Against::Environment] {
        let qs = configs(400);
        let (hit, free): (Vec<_>, Vec<_>) =
            qs.iter().partition(|q| robot.collides(q, against).unwrap());
        assert!(
            hit.len() >= 20 && free.len() >= 20,
            "{against:?}: {} collide",
            hit.len()
        );
        for (f, h) in free.iter().zip(&hit).take(20) {
            let at = |t: f64| -> Vec<f64> {
                f.iter()
                    .zip(h.iter())
                    .map(|(a, b)| a + t * (b - a))
                    .collect()
            };
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if robot.collides(&at(mid), against).unwrap() {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            for q in [at(lo), at(hi)] {
                let exact = match against {
                    Against::Itself => brute(&robot, &q, None),
                    _ => brute_environment(&robot, &q),
                };
                assert_eq!(
                    robot.colliding_pairs(&q, against).unwrap(),
                    exact,
                    "{against:?} q = {q:?}"
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 80);
}

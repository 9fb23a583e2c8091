//! Motion checks: thin obstacles that 1° steps step over are found, the sweep bound holds for
//! sampled points, and on random motions of the fixture arm a collision is real and "free"
//! agrees with dense sampling.

use std::f64::consts::PI;
use std::path::PathBuf;

use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

use super::geometry::{place, Geometry};
use super::motion_bound::along;
use super::*;
use crate::shape::{Cuboid, Shape};
use crate::Ball;

const DEGREE: f64 = PI / 180.0;

fn data() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cli/tests/data/robot")
}

/// The fixture arm with its environment: a ball beside the upright forearm and a far wall.
fn arm_in_scene() -> Robot {
    let dir = data().join("toy_arm");
    let mut robot = Robot::from_urdf(dir.join("arm.urdf"), &[data()], Some(&dir.join("arm.srdf")))
        .expect("the fixture loads");
    let mut scene = Scene::new();
    let ball: Shape = Ball::new(Point3::new(0.3, 0.0, 0.9), 0.05).unwrap().into();
    scene.add_shape(ball, Isometry3::identity()).unwrap();
    let wall: Shape = Cuboid::axis_aligned(Point3::new(5.0, 0.0, 0.0), Vector3::new(0.1, 1.0, 1.0))
        .unwrap()
        .into();
    scene.add_shape(wall, Isometry3::identity()).unwrap();
    robot.set_environment(&scene).unwrap();
    robot
}

/// A rod 2 mm thick from 0.2 m to 1 m along x of a link turned about z by `pan`; with
/// `fin`, the base holds a plate 1 mm thick at 0.5° (between two 1° steps), where the rod's
/// link is not adjacent to the base.
fn rod_robot(fin: bool) -> Robot {
    let plate = "<collision><origin xyz=\"0.9 0 0\"/>\
        <geometry><box size=\"0.2 0.001 0.1\"/></geometry></collision>";
    let urdf = format!(
        r#"<robot name="rod">
  <link name="base">{}</link>
  <link name="hub"/>
  <link name="rod"><collision><origin xyz="0.6 0 0" rpy="0 1.5707963267948966 0"/>
    <geometry><capsule radius="0.001" length="0.8"/></geometry></collision></link>
  <joint name="lift" type="revolute"><parent link="base"/><child link="hub"/>
    <axis xyz="0 1 0"/><limit lower="-1" upper="1"/></joint>
  <joint name="pan" type="revolute"><parent link="hub"/><child link="rod"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
</robot>"#,
        if fin { plate } else { "" }
    );
    let urdf = if fin {
        // The plate turned to 0.5° about z (the base is the root, so the turn is put in the
        // collision origin).
        urdf.replace(
            "<origin xyz=\"0.9 0 0\"/>",
            &format!(
                "<origin xyz=\"{} {} 0\" rpy=\"0 0 {}\"/>",
                0.9 * (0.5 * DEGREE).cos(),
                0.9 * (0.5 * DEGREE).sin(),
                0.5 * DEGREE
            ),
        )
    } else {
        urdf
    };
    Robot::from_urdf_str(&urdf, "rod.urdf", ".", &[]).expect("the rod robot loads")
}

/// A thin plate in the environment at 0.5° about z, 1 mm thick.
fn thin_plate_scene() -> Scene {
    let mut scene = Scene::new();
    let plate: Shape = Cuboid::axis_aligned(Point3::origin(), Vector3::new(0.1, 0.0005, 0.05))
        .unwrap()
        .into();
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5 * DEGREE);
    let pose = Isometry3::from_parts(Translation3::from(turn * Vector3::new(0.9, 0.0, 0.0)), turn);
    scene.add_shape(plate, pose).unwrap();
    scene
}

/// Discrete checking at `step` resolution: every joint changes by at most `step` between
/// samples.
fn discrete_collides(robot: &Robot, q0: &[f64], q1: &[f64], step: f64, against: Against) -> bool {
    let span = q0
        .iter()
        .zip(q1)
        .map(|(a, b)| (b - a).abs())
        .fold(0.0, f64::max);
    let n = (span / step).ceil().max(1.0) as usize;
    (0..=n).any(|k| {
        let q = along(q0, q1, k as f64 / n as f64);
        robot.collides(&q, against).unwrap()
    })
}

fn options(against: Against) -> MotionOptions {
    MotionOptions {
        against,
        ..MotionOptions::default()
    }
}

fn assert_real_collision(robot: &Robot, answer: &MotionAnswer, against: Against) -> f64 {
    let MotionAnswer::Collides {
        time,
        configuration,
        pairs,
        free_until,
    } = answer
    else {
        panic!("expected a collision, got {answer:?}");
    };
    assert!(*free_until <= *time && (0.0..=1.0).contains(time));
    assert!(!pairs.is_empty());
    assert_eq!(
        &robot.colliding_pairs(configuration, against).unwrap(),
        pairs
    );
    *time
}

#[test]
fn a_thin_plate_in_the_environment_that_one_degree_steps_miss_is_found() {
    let mut robot = rod_robot(false);
    robot.set_environment(&thin_plate_scene()).unwrap();
    let (q0, q1) = ([0.0, 0.0], [0.0, 10.0 * DEGREE]);
    assert!(!discrete_collides(
        &robot,
        &q0,
        &q1,
        DEGREE,
        Against::Environment
    ));
    let answer = robot
        .motion_collision(&q0, &q1, &options(Against::Environment))
        .unwrap();
    let time = assert_real_collision(&robot, &answer, Against::Environment);
    // The rod (1 mm radius) meets the plate (0.5 mm half thickness) at 0.5° of 10° less
    // 0.0015 / 0.8 rad at the plate's inner end: near 0.393°.
    assert!((0.0385..0.0400).contains(&time), "time {time}");
    let MotionAnswer::Collides { pairs, .. } = answer else {
        unreachable!()
    };
    assert_eq!(pairs, [("env:0".to_string(), "rod".to_string())]);
    // Backwards, the first contact is found from the other side.
    let back = robot
        .motion_collision(&q1, &q0, &options(Against::Environment))
        .unwrap();
    let time = assert_real_collision(&robot, &back, Against::Environment);
    assert!((0.9385..0.9400).contains(&time), "time {time}");
}

#[test]
fn a_thin_link_of_the_robot_itself_that_one_degree_steps_miss_is_found() {
    let robot = rod_robot(true);
    assert_eq!(robot.allowed_pairs(), [("base", "rod")]);
    // Both joints move: the lift tilts the rod a little while it pans past the fin.
    let (q0, q1) = ([0.0, -2.0 * DEGREE], [0.01, 9.0 * DEGREE]);
    assert!(!discrete_collides(
        &robot,
        &q0,
        &q1,
        DEGREE,
        Against::Itself
    ));
    let answer = robot
        .motion_collision(&q0, &q1, &options(Against::Itself))
        .unwrap();
    assert_real_collision(&robot, &answer, Against::Itself);
    // Beside the fin the same sweep is certified free.
    let (q0, q1) = ([0.0, 1.0 * DEGREE], [0.01, 20.0 * DEGREE]);
    let answer = robot
        .motion_collision(&q0, &q1, &options(Against::Itself))
        .unwrap();
    assert!(answer.is_free(), "{answer:?}");
}

#[test]
fn the_ends_of_a_motion_are_tested() {
    let mut robot = rod_robot(false);
    robot.set_environment(&thin_plate_scene()).unwrap();
    let through = [0.0, 0.5 * DEGREE];
    let start = robot
        .motion_collision(&through, &[0.0, 5.0 * DEGREE], &options(Against::Both))
        .unwrap();
    assert_eq!(assert_real_collision(&robot, &start, Against::Both), 0.0);
    let end = robot
        .motion_collision(&[0.0, 5.0 * DEGREE], &through, &options(Against::Both))
        .unwrap();
    assert!(assert_real_collision(&robot, &end, Against::Both) > 0.9);
    // A motion that stays put and is free is free.
    let still = [0.0, 3.0 * DEGREE];
    let answer = robot
        .motion_collision(&still, &still, &options(Against::Both))
        .unwrap();
    assert!(answer.is_free());
}

#[test]
fn a_spent_budget_is_undecided_and_bad_input_is_refused() {
    let mut robot = rod_robot(false);
    robot.set_environment(&thin_plate_scene()).unwrap();
    let tight = MotionOptions {
        against: Against::Environment,
        max_configurations: 2,
        ..MotionOptions::default()
    };
    let answer = robot
        .motion_collision(&[0.0, 0.0], &[0.0, 10.0 * DEGREE], &tight)
        .unwrap();
    assert_eq!(
        answer,
        MotionAnswer::Undecided {
            free_until: 0.0,
            limit: MotionLimit::Configurations
        }
    );
    let coarse = MotionOptions {
        against: Against::Environment,
        resolution: 0.5,
        ..MotionOptions::default()
    };
    let answer = robot
        .motion_collision(&[0.0, 0.0], &[0.0, 10.0 * DEGREE], &coarse)
        .unwrap();
    assert!(matches!(
        answer,
        MotionAnswer::Undecided {
            limit: MotionLimit::Resolution,
            ..
        }
    ));
    for bad in [0.0, -1.0, 2.0, f64::NAN] {
        let o = MotionOptions {
            resolution: bad,
            ..MotionOptions::default()
        };
        assert!(robot.motion_collision(&[0.0; 2], &[0.0; 2], &o).is_err());
    }
    let none = MotionOptions {
        max_configurations: 0,
        ..MotionOptions::default()
    };
    assert!(robot.motion_collision(&[0.0; 2], &[0.0; 2], &none).is_err());
    let o = MotionOptions::default();
    assert!(robot.motion_collision(&[0.0; 2], &[0.0; 3], &o).is_err());
    assert!(robot
        .motion_collision(&[0.0; 2], &[f64::NAN, 0.0], &o)
        .is_err());
    let batch =
        robot.motion_collision_batch(&[([0.0; 2], [0.0; 2]), ([0.0; 2], [f64::NAN; 2])], &o);
    assert!(matches!(batch, Err(Error::InBatch { index: 1, .. })));
}

/// A configuration of the fixture arm within its limits from four numbers in `[0, 1)`.
fn arm_config(u: [f64; 4]) -> Vec<f64> {
    vec![
        u[0] * 6.0 - 3.0,
        u[1] * 5.0 - 2.5,
        u[2] * 5.0 - 2.5,
        u[3] * 0.3 - 0.2,
    ]
}

fn unit4() -> impl Strategy<Value = [f64; 4]> {
    [0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64]
}

/// Points of a part's geometry in its frame: a mesh's box corners (which the link's reach
/// covers), a box's corners, and extreme points of the round primitives.
fn points_of(g: &Geometry) -> Vec<Point3<f64>> {
    let corners = |min: [f64; 3], max: [f64; 3]| -> Vec<Point3<f64>> {
        (0..8)
            .map(|k| {
                Point3::new(
                    if k & 1 == 0 { min[0] } else { max[0] },
                    if k & 2 == 0 { min[1] } else { max[1] },
                    if k & 4 == 0 { min[2] } else { max[2] },
                )
            })
            .collect()
    };
    let around = |centres: &[Point3<f64>], r: f64| -> Vec<Point3<f64>> {
        centres
            .iter()
            .flat_map(|c| (0..3).flat_map(move |i| [-r, r].map(|s| c + Vector3::ith(i, s))))
            .collect()
    };
    match g {
        Geometry::Mesh(m) => {
            let b = m.bvh().bounds();
            corners(b.min, b.max)
        }
        Geometry::Shape(Shape::Cuboid(_)) => {
            let b = place(g, Isometry3::identity()).unwrap().bbox;
            corners(b.min, b.max)
        }
        Geometry::Shape(Shape::Ball(b)) => around(&[*b.centre()], b.radius()),
        Geometry::Shape(Shape::Capsule(c)) => around(&[*c.a(), *c.b()], c.radius()),
        // Cylinders along z: the rims' points along x and y.
        Geometry::Shape(Shape::Cylinder(c)) => around(&[*c.a(), *c.b()], c.radius())
            .into_iter()
            .filter(|p| p.z == c.a().z || p.z == c.b().z)
            .collect(),
        _ => Vec::new(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every point of every part's box moves no farther from its place at the stretch's
    /// middle than the link's bound.
    #[test]
    fn the_sweep_bound_holds_for_sampled_points(a in unit4(), b in unit4()) {
        let robot = arm_in_scene();
        let sweeps = robot.link_sweeps().unwrap();
        let (qa, qb) = (arm_config(a), arm_config(b));
        let mid = robot.link_poses(&along(&qa, &qb, 0.5)).unwrap();
        for s in 0..=16 {
            let poses = robot.link_poses(&along(&qa, &qb, s as f64 / 16.0)).unwrap();
            for part in &robot.parts {
                let bound = sweeps[part.link].bound(&qa, &qb);
                for c in points_of(&part.geometry) {
                    let at = poses[part.link] * part.local * c;
                    let from = mid[part.link] * part.local * c;
                    prop_assert!((at - from).norm() <= bound, "link {} moved {} > {}",
                        robot.link_names[part.link], (at - from).norm(), bound);
                }
            }
        }
    }

    /// A reported collision is one at the reported configuration; a free motion has no
    /// collision at 400 samples; nothing before `free_until` collides.
    #[test]
    fn answers_agree_with_dense_sampling(a in unit4(), b in unit4(), short in 0.02..1.0f64) {
        let robot = arm_in_scene();
        let q0 = arm_config(a);
        // Motions of every length: from `q0` part of the way to `b`'s configuration.
        let q1 = along(&q0, &arm_config(b), short);
        let answer = robot.motion_collision(&q0, &q1, &options(Against::Both)).unwrap();
        let samples = 400;
        let collides_at = |t: f64| robot.collides(&along(&q0, &q1, t), Against::Both).unwrap();
        match &answer {
            MotionAnswer::Free => {
                for k in 0..=samples {
                    prop_assert!(!collides_at(k as f64 / samples as f64), "sample {k} collides");
                }
            }
            MotionAnswer::Collides { free_until, .. } => {
                assert_real_collision(&robot, &answer, Against::Both);
                // Before `free_until` (none when it is 0).
                for k in (0..samples).filter(|_| *free_until > 0.0) {
                    let t = k as f64 / samples as f64 * free_until;
                    prop_assert!(!collides_at(t), "t {t} collides before {free_until}");
                }
            }
            MotionAnswer::Undecided { .. } => prop_assert!(false, "undecided: {answer:?}"),
        }
    }
}

"""`Robot.motion_collision`: straight joint-space motions certified free or found colliding,
never a contact missed between samples. Thin obstacles that discrete checking at 1° steps over
are found, on the fixture arm and on the Franka Panda of example-robot-data (skipped when it is
not installed); answers agree with dense sampling."""

import pathlib
import sys

import numpy as np
import pytest

import cga_collide as cc

DATA = pathlib.Path(__file__).resolve().parents[2] / "cli" / "tests" / "data" / "robot"
DEGREE = np.pi / 180


def arm():
    return cc.Robot.from_urdf(
        str(DATA / "toy_arm" / "arm.urdf"),
        package_dirs=[str(DATA)],
        srdf=str(DATA / "toy_arm" / "arm.srdf"),
    )


def discrete_collides(robot, q0, q1, step, against):
    """Discrete checking: every joint changes by at most `step` between samples."""
    n = max(1, int(np.ceil(np.max(np.abs(q1 - q0)) / step)))
    t = np.linspace(0.0, 1.0, n + 1)[:, None]
    return bool(robot.collides_batch((1 - t) * q0 + t * q1, against=against).any())


def test_a_tiny_ball_that_one_degree_steps_miss_is_found():
    robot = arm()
    # The forearm's mesh is a surface: a ball of 0.5 mm on its side face is met only while
    # the pan sweeps that face through it, near 0°, which 1° steps from -4.5° step over.
    q0 = np.array([-4.5 * DEGREE, 0.0, 0.0, 0.0])
    q1 = np.array([5.5 * DEGREE, 0.0, 0.0, 0.0])
    fore = robot.link_poses(np.zeros(4))[robot.link_names.index("fore")]
    side = fore @ [0.35, 0.03, 0.0, 1.0]
    scene = cc.Scene()
    scene.add_shape(cc.Ball(side[:3], 0.0005))
    robot.set_environment(scene)
    assert not discrete_collides(robot, q0, q1, DEGREE, "environment")
    answer = robot.motion_collision(q0, q1, against="environment")
    assert answer.status == "collides" and not answer.is_free
    assert 0.44 <= answer.time <= 0.46
    assert answer.free_until <= answer.time
    assert answer.pairs == [("env:0", "fore")]
    assert robot.colliding_pairs(answer.configuration, against="environment") == answer.pairs
    assert answer.limit is None


def test_answers_agree_with_dense_sampling_and_batches():
    robot = arm()
    scene = cc.Scene()
    scene.add_shape(cc.Ball([0.3, 0.0, 0.9], 0.05))
    robot.set_environment(scene)
    rng = np.random.default_rng(11)
    lim = np.array([[-3, 3], [-2.5, 2.5], [-2.5, 2.5], [-0.2, 0.1]])
    q0s = rng.uniform(lim[:, 0], lim[:, 1], size=(40, 4))
    q1s = q0s + rng.uniform(-0.5, 0.5, size=(40, 4)) * (lim[:, 1] - lim[:, 0])
    answers = robot.motion_collision_batch(q0s, q1s, against="both")
    statuses = set()
    for q0, q1, a in zip(q0s, q1s, answers):
        single = robot.motion_collision(q0, q1, against="both")
        assert (single.status, single.time, single.pairs) == (a.status, a.time, a.pairs)
        statuses.add(a.status)
        t = np.linspace(0.0, 1.0, 301)[:, None]
        dense = robot.collides_batch((1 - t) * q0 + t * q1, against="both")
        if a.is_free:
            assert a.free_until == 1.0 and not dense.any()
        else:
            assert a.status == "collides", a
            assert robot.colliding_pairs(a.configuration, against="both") == a.pairs != []
            np.testing.assert_array_equal(a.configuration, (1 - a.time) * q0 + a.time * q1)
            # Certified free: [0, free_until), empty when the motion starts in contact.
            if a.free_until > 0.0:
                s = t[:-1]
                before = (1 - s * a.free_until) * q0 + s * a.free_until * q1
                assert not robot.collides_batch(before, against="both").any()
            else:
                assert a.time == 0.0 and robot.collides(q0, against="both")
    assert statuses == {"free", "collides"}


def test_budgets_and_errors():
    robot = arm()
    # A free motion whose end is free too: one configuration cannot certify it. (Towards a
    # colliding end, one configuration is enough for an answer: the end itself collides.)
    q0, q1 = np.zeros(4), np.array([0.0, 1.2, 0.0, 0.0])
    assert robot.motion_collision(q0, q1).is_free
    ends_in_contact = robot.motion_collision(q0, np.array([0.0, 2.4, 0.0, 0.0]), max_configurations=1)
    assert ends_in_contact.status == "collides" and ends_in_contact.time == 1.0
    spent = robot.motion_collision(q0, q1, max_configurations=1)
    assert spent.status == "undecided" and spent.limit == "configurations"
    assert spent.time is None and spent.configuration is None and spent.pairs == []
    assert "undecided" in repr(spent)
    with pytest.raises(cc.CgaError):
        robot.motion_collision(q0, q1, resolution=0.0)
    with pytest.raises(ValueError):
        robot.motion_collision(q0, q1, max_configurations=0)
    with pytest.raises(ValueError):
        robot.motion_collision(q0, np.zeros(3))
    with pytest.raises(ValueError):
        robot.motion_collision(q0, q1, against="nothing")
    with pytest.raises(ValueError):
        robot.motion_collision_batch(np.zeros((2, 4)), np.zeros((3, 4)))


def panda():
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "benches"))
    try:
        import robot_pinocchio as bench
    finally:
        sys.path.pop(0)
    try:
        urdf, srdf, share = bench.panda_files()
    except FileNotFoundError:
        pytest.skip("example-robot-data is not installed")
    return cc.Robot.from_urdf(str(urdf), package_dirs=[str(share)], srdf=str(srdf))


def test_thin_obstacles_on_the_panda_that_one_degree_steps_miss_are_found():
    robot = panda()
    lo, hi = robot.joint_limits.T
    rng = np.random.default_rng(5)
    found = 0
    for _ in range(200):
        mid = rng.uniform(lo, hi)
        if robot.collides(mid):
            continue
        # Every arm joint turns by up to 5° one way and 6.5° the other; the fingers stay.
        swing = np.zeros(robot.dof)
        swing[:7] = rng.uniform(-5, 5, size=7) * DEGREE
        q0, q1 = mid - swing, mid + 1.3 * swing
        if discrete_collides(robot, q0, q1, DEGREE / 4, "self"):
            continue
        # A ball of 0.5 mm on the surface of the link nearest to a probe beside the arm at
        # the motion's middle: met near the middle only.
        probe = robot.link_poses(mid)[rng.integers(2, len(robot.link_names))][:3, 3]
        scene = cc.Scene()
        scene.add_shape(cc.Ball(probe + rng.normal(size=3) * 0.1, 0.01))
        robot.set_environment(scene)
        near = robot.nearest(mid, against="environment")
        if near is None or near[1].distance == 0.0:
            continue
        (a, b), d = near
        on_link = d.witness_b if a == "env:0" else d.witness_a
        scene = cc.Scene()
        scene.add_shape(cc.Ball(on_link, 0.0005))
        robot.set_environment(scene)
        if not robot.collides(mid, against="environment"):
            continue
        if discrete_collides(robot, q0, q1, DEGREE, "both"):
            continue
        answer = robot.motion_collision(q0, q1, against="both")
        assert answer.status == "collides", (answer, q0, q1, on_link)
        assert robot.colliding_pairs(answer.configuration, against="both") == answer.pairs
        found += 1
        if found == 5:
            break
    assert found == 5

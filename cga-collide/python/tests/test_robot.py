"""`cga_collide.Robot`: the fixture arm of the command-line tests (primitives of every kind, a
fixed joint, a scaled mesh through package://, an SRDF), numpy in and out, batches equal to
single questions, errors."""

import pathlib

import numpy as np
import pytest

import cga_collide as cc

DATA = pathlib.Path(__file__).resolve().parents[2] / "cli" / "tests" / "data" / "robot"


def arm():
    return cc.Robot.from_urdf(
        str(DATA / "toy_arm" / "arm.urdf"),
        package_dirs=[str(DATA)],
        srdf=str(DATA / "toy_arm" / "arm.srdf"),
    )


def test_loads_the_arm():
    robot = arm()
    assert robot.dof == 4
    assert robot.joint_names == ["shoulder_pan", "shoulder_lift", "elbow", "slide"]
    lim = robot.joint_limits
    assert lim.shape == (4, 2) and lim.dtype == np.float64
    assert np.isinf(lim[0]).all() and list(lim[3]) == [-0.2, 0.1]
    assert len(robot.allowed_pairs()) == 12
    assert robot.pairs_checked() == 12
    poses = robot.link_poses(np.zeros(4))
    assert poses.shape == (len(robot.link_names), 4, 4)


def test_questions_at_a_configuration():
    robot = arm()
    assert not robot.collides(np.zeros(4))
    folded = [0.0, 1.9, 0.0, 0.0]
    assert robot.collides(folded)
    assert robot.colliding_pairs(folded) == [("base", "fore"), ("base", "slider")]
    # The shoulder's cylinder has no certified distance yet: leave its pairs out.
    robot.exclude_pair("shoulder", "slider")
    robot.exclude_pair("shoulder", "tool")
    (pair, d) = robot.nearest(np.zeros(4))
    assert d.distance > 0 and d.error_bound >= 0
    assert pair in robot.pairs_within_distance(np.zeros(4), d.distance + d.error_bound)


def test_batches_equal_single_questions():
    robot = arm()
    rng = np.random.default_rng(3)
    lim = np.array([[-3, 3], [-2.5, 2.5], [-2.5, 2.5], [-0.2, 0.1]])
    qs = rng.uniform(lim[:, 0], lim[:, 1], size=(200, 4))
    hits = robot.collides_batch(qs)
    assert hits.dtype == np.bool_ and hits.shape == (200,)
    pairs = robot.colliding_pairs_batch(qs)
    assert [robot.colliding_pairs(q) for q in qs] == pairs
    assert list(hits) == [bool(p) for p in pairs]
    assert 0 < hits.sum() < 200
    robot.exclude_pair("shoulder", "slider")
    robot.exclude_pair("shoulder", "tool")
    near = robot.nearest_batch(qs[:20])
    assert [n[0] for n in near] == [robot.nearest(q)[0] for q in qs[:20]]
    within = robot.pairs_within_distance_batch(qs[:20], 0.05)
    assert within == [robot.pairs_within_distance(q, 0.05) for q in qs[:20]]


def test_environment_and_solid_meshes():
    robot = arm()
    scene = cc.Scene()
    scene.add_shape(cc.Ball([0.3, 0.0, 0.9], 0.05))
    robot.set_environment(scene)
    assert robot.colliding_pairs(np.zeros(4), against="environment") == [("env:0", "fore")]
    assert robot.colliding_pairs(np.zeros(4)) == []
    inside = cc.Scene()
    inside.add_shape(cc.Ball([0.2, 0.0, 0.9], 0.01))
    robot.set_environment(inside)
    assert not robot.collides(np.zeros(4), against="both")
    robot.set_solid(True)
    assert robot.collides(np.zeros(4), against="both")


def test_errors_name_what_is_wrong(tmp_path):
    robot = arm()
    with pytest.raises(cc.CgaError, match="q"):
        robot.collides(np.zeros(3))
    with pytest.raises(cc.CgaError, match="against"):
        robot.collides(np.zeros(4), against="world")
    with pytest.raises(cc.CgaError, match="not finite"):
        robot.collides([0.0, np.nan, 0.0, 0.0])
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot>\n<link name="a"><collision><geometry><sphere radius="x"/></geometry></collision></link></robot>')
    with pytest.raises(cc.CgaError, match=r"bad.urdf:2: <sphere>"):
        cc.Robot.from_urdf(str(bad))

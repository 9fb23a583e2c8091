"""`cga_collide.Robot` against pinocchio + coal (skipped unless `pin` and the robot's wheel are
installed): the Franka Panda and the UR5 of example-robot-data and the KUKA iiwa of pybullet's
`pybullet_data`, against themselves and against an environment of a table, a box, a ball and a
cylinder. On a few hundred configurations within the joint limits, far from contact, the
colliding link pairs are the same, configuration by configuration
(`cga-collide/benches/robot_pinocchio.py` holds the shared code)."""

import pathlib
import sys

import pytest


def bench():
    pytest.importorskip("pinocchio")
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "benches"))
    try:
        import robot_pinocchio
    finally:
        sys.path.pop(0)
    return robot_pinocchio


@pytest.mark.parametrize("name", ["panda", "ur5", "iiwa"])
@pytest.mark.parametrize("against", ["self", "environment"])
def test_agreement_with_pinocchio(name, against):
    b = bench()
    try:
        robot, urdf, share = b.load(name)
        filter_robot = b.load(name)[0]
    except FileNotFoundError as e:
        pytest.skip(str(e))
    robot.set_environment(b.our_scene())
    filter_robot.set_environment(b.our_scene(capsules=True))
    if against == "self":
        peer = b.Pinocchio(urdf, share, robot.allowed_pairs())
    else:
        peer = b.Pinocchio(urdf, share, [], environment=True)
    qs = b.sample(robot, 300, seed=7)
    result = b.agreement(robot, peer, qs, against=against, filter_robot=filter_robot)
    assert result["far"] > 200
    assert result["mismatches"] == 0, result["examples"]

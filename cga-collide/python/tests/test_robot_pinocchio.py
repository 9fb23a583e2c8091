"""`cga_collide.Robot` against pinocchio + coal on the Franka Panda of example-robot-data
(skipped unless `pin` and `example-robot-data` are installed): on a few hundred configurations
within the joint limits, far from contact, the colliding link pairs are the same, configuration
by configuration (`cga-collide/benches/robot_pinocchio.py` holds the shared code)."""

import pathlib
import sys

import pytest

import cga_collide as cc


def test_agreement_with_pinocchio_on_the_panda():
    pytest.importorskip("pinocchio")
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "benches"))
    try:
        import robot_pinocchio as bench
    finally:
        sys.path.pop(0)
    try:
        urdf, srdf, share = bench.panda_files()
    except FileNotFoundError:
        pytest.skip("example-robot-data is not installed")
    robot = cc.Robot.from_urdf(str(urdf), package_dirs=[str(share)], srdf=str(srdf))
    peer = bench.Pinocchio(urdf, share, robot.allowed_pairs())
    result = bench.agreement(robot, peer, bench.sample(robot, 300, seed=7))
    assert result["far"] > 250
    assert result["mismatches"] == 0, result["examples"]

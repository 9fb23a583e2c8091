"""``cga_collide.contact_manifold``: arrays, counts and agreement with the certified bounds."""

import numpy as np
import pytest

import cga_collide as cc


def box(z: float) -> cc.Cuboid:
    return cc.Cuboid(np.array([0.0, 0.0, z]), np.eye(3) * 0.5)


def test_box_on_box_gives_four_points() -> None:
    table = cc.Cuboid(np.zeros(3), np.diag([2.0, 2.0, 0.5]))
    m = cc.contact_manifold(table, box(0.875))
    assert m is not None and len(m) == 4
    assert m.points.shape == (4, 3) and m.points_a.shape == (4, 3)
    np.testing.assert_array_equal(m.normal, [0.0, 0.0, 1.0])
    np.testing.assert_array_equal(m.distances, [-0.125] * 4)
    np.testing.assert_array_equal(m.error_bounds, [0.0] * 4)
    assert m.signed_distance.kind == "penetrating"


def test_margin_and_errors() -> None:
    assert cc.contact_manifold(box(0.0), box(1.25), margin=0.2) is None
    m = cc.contact_manifold(box(0.0), box(1.25), margin=0.3)
    assert m is not None and m.signed_distance.kind == "separated"
    assert np.all(m.distances <= 0.3)
    with pytest.raises(cc.CgaError):
        cc.contact_manifold(box(0.0), box(1.0), margin=-1.0)


def test_at_poses_equals_placed() -> None:
    pose = np.eye(4)
    pose[2, 3] = 0.9
    m = cc.contact_manifold_at(box(0.0), np.eye(4), box(0.0), pose)
    n = cc.contact_manifold(box(0.0), box(0.9))
    assert m is not None and n is not None
    np.testing.assert_array_equal(m.points, n.points)

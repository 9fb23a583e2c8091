"""cga_collide.trimesh.CollisionManager beyond trimesh's own tests: float64 transforms,
return conventions, agreement with the colliders' exact answers."""

import sys

import numpy as np
import pytest

import cga_collide as cc
from cga_collide.trimesh import CollisionManager, ContactData, DistanceData
from conftest import random_poses, translation

trimesh = pytest.importorskip("trimesh")


@pytest.fixture(scope="module")
def box():
    return trimesh.creation.box(extents=[1.0, 1.0, 1.0])


def test_transforms_stay_float64(box):
    # a gap of 1e-9: float32 cannot hold 1 + 1e-9 and would report a collision
    gap = translation(1.0 + 1e-9)
    assert np.float32(gap[0, 3]) == 1.0
    m = CollisionManager()
    m.add_object("a", box)
    m.add_object("b", box, gap)
    assert m.in_collision_internal() is False
    m.set_transform("b", translation(1.0))  # face to face: touching counts
    assert m.in_collision_internal() is True
    d, names = m.min_distance_internal(return_names=True)
    assert names == ("a", "b") and d <= 0.0
    m.set_transform("b", gap)
    d = m.min_distance_internal()
    assert 0 < d < 2e-9


def test_return_conventions(box):
    m = CollisionManager()
    m.add_object("b", box, translation(0.5))
    m.add_object("a", box)
    ret, names, data = m.in_collision_internal(return_names=True, return_data=True)
    assert ret is True and names == {("a", "b")}
    assert data and all(isinstance(c, ContactData) and c.names == {"a", "b"} for c in data)
    c = data[0]
    assert c.point.shape == (3,) and np.isclose(c.depth, 0.5) and np.isclose(np.linalg.norm(c.normal), 1)
    assert isinstance(c.index("a"), int)
    d, name, dd = m.min_distance_single(box, translation(0, 3.0), return_name=True, return_data=True)
    assert isinstance(dd, DistanceData) and np.isclose(d, 2.0) and name in {"a", "b"}
    assert np.isclose(np.linalg.norm(dd.point(name) - dd.point("__external")), d)
    with pytest.raises(ValueError, match="not in collision manager"):
        m.remove_object("zzz")
    with pytest.raises(ValueError, match="not in collision manager"):
        m.set_transform("zzz", np.eye(4))
    with pytest.raises(cc.CgaError, match="not a rotation"):
        m.set_transform("a", np.diag([2.0, 2.0, 2.0, 1.0]))
    m.add_object("a", box, translation(10.0))  # replaces "a"
    assert m.in_collision_internal() is False
    empty = CollisionManager()
    assert empty.in_collision_internal() is False and empty.min_distance_internal() == float("inf")


def test_agrees_with_colliders(box):
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.7)
    meshes = [box, sphere]
    poses = random_poses(30, seed=41, spread=3.0)
    m = CollisionManager()
    for k, p in enumerate(poses):
        m.add_object(f"o{k:02d}", meshes[k % 2], p)
    cols = [cc.Collider(np.asarray(x.vertices, np.float64), np.asarray(x.faces)) for x in meshes]
    want = {
        (f"o{i:02d}", f"o{j:02d}")
        for i in range(30)
        for j in range(i + 1, 30)
        if cols[i % 2].collides_at(poses[i], cols[j % 2], poses[j])
    }
    ret, names = m.in_collision_internal(return_names=True)
    assert names == want and ret == bool(want)
    probe = translation(0.2, 0.1)
    single = {f"o{i:02d}" for i in range(30) if cols[0].collides_at(probe, cols[i % 2], poses[i])}
    assert m.in_collision_single(box, probe, return_names=True)[1] == single
    other = CollisionManager()
    other.add_object("p", box, probe)
    assert m.in_collision_other(other, return_names=True)[1] == {(n, "p") for n in single}
    # move all at once
    moved = random_poses(30, seed=42, spread=3.0)
    m.set_transforms([f"o{k:02d}" for k in range(30)], moved)
    want = {
        (f"o{i:02d}", f"o{j:02d}")
        for i in range(30)
        for j in range(i + 1, 30)
        if cols[i % 2].collides_at(moved[i], cols[j % 2], moved[j])
    }
    assert m.in_collision_internal(return_names=True)[1] == want


class Square:
    """A flat mesh (two triangles): open, it bounds no solid."""

    vertices = np.array([[-1.0, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]])
    faces = np.array([[0, 1, 2], [0, 2, 3]])


def test_flat_meshes_get_contact_data():
    m = CollisionManager()
    m.add_object("a", Square())
    m.add_object("b", Square(), cc.pose_from_degrees([90.0, 0.0, 0.0]))  # crossing at right angles
    hit, data = m.in_collision_internal(return_data=True)
    assert hit and data
    for c in data:
        assert np.isfinite(c.point).all() and np.isclose(np.linalg.norm(c.normal), 1.0)
        assert c.depth == 0.0 and c.depth_kind == "none"


def test_contact_data_needs_no_scipy(monkeypatch, box):
    monkeypatch.setitem(sys.modules, "scipy.spatial", None)  # `from scipy.spatial import` fails
    monkeypatch.setitem(sys.modules, "scipy", None)
    m = CollisionManager()
    m.add_object("a", box)
    m.add_object("b", box, translation(0.5))
    hit, data = m.in_collision_internal(return_data=True)
    assert hit and data and all(c.depth == 0.5 and c.depth_kind == "exact" for c in data)

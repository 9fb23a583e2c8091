"""Signed distance of points to meshes: `Collider.signed_distance` (negative inside, exact sign,
proved bounds), `cga_collide.trimesh.signed_distance` in trimesh's convention (positive
inside), agreement with the `cga signed-distance` command line and with trimesh on generic
points."""

import json
import subprocess

import numpy as np
import pytest

import cga_collide as cc
from cga_collide import trimesh as drop_in
from conftest import REPO
from test_rust_agreement import cga_binary

BUNNY = REPO / "cga-collide" / "data" / "bunny.obj"


def cube():
    v = np.array([[x, y, z] for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)])
    f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                  [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return v, f


def test_signs_distances_and_nearest_points_of_a_cube():
    c = cc.Collider(*cube())
    up = np.nextafter(1.0, 2.0)
    pts = [[0.5, 0.5, 0.25], [1.0, 0.5, 0.5], [0.0, 0.0, 0.0], [3.0, 0.5, 0.5], [up, 0.5, 0.5]]
    r = c.signed_distance(pts)
    assert len(r) == 5
    assert r.inside.tolist() == [True, True, True, False, False]
    want = np.array([-0.25, 0.0, 0.0, 2.0, up - 1.0])
    assert np.all(np.abs(r.signed_distance - want) <= r.error_bound)
    assert r.signed_distance[1] == 0.0 and r.error_bound[1] == 0.0
    assert r.nearest.shape == (5, 3) and r.triangle.dtype == np.int64
    assert np.allclose(r.nearest[3], [1.0, 0.5, 0.5])
    # trimesh's convention: positive inside, 0 on the surface.
    sd = drop_in.signed_distance(c, pts)
    assert np.array_equal(sd, -r.signed_distance + 0.0)
    assert not np.signbit(sd[1])
    closest, dist, tri = drop_in.closest_point(c, pts)
    assert np.array_equal(closest, r.nearest) and np.array_equal(tri, r.triangle)
    assert drop_in.contains(c, pts).tolist() == [True, True, True, False, False]


def test_bad_points_raise_naming_the_point():
    c = cc.Collider(*cube())
    with pytest.raises(cc.CgaError, match="point 1"):
        c.signed_distance([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0]])
    with pytest.raises(cc.CgaError):
        c.signed_distance(np.zeros((3, 2)))


def test_under_a_pose_the_answers_are_the_placed_meshes():
    c = cc.Collider.load(str(BUNNY))
    pose = cc.pose_from_degrees([10.0, 20.0, 30.0], [0.1, 0.0, -0.2])
    pts = np.random.default_rng(3).uniform(-0.2, 0.2, size=(200, 3))
    v = c.vertices @ pose[:3, :3].T + pose[:3, 3]
    placed = cc.Collider(v, c.faces)
    a, b = c.signed_distance_at(pose, pts), placed.signed_distance(pts)
    assert np.array_equal(a.inside, b.inside)
    assert np.all(np.abs(a.signed_distance - b.signed_distance) <= a.error_bound + b.error_bound)


def test_agrees_with_the_command_line(tmp_path):
    exe = cga_binary()
    if exe is None:
        pytest.skip("no cga binary")
    c = cc.Collider.load(str(BUNNY))
    pts = np.random.default_rng(5).uniform(-0.15, 0.15, size=(300, 3))
    path = tmp_path / "points.txt"
    path.write_text("".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in pts.tolist()))
    out = subprocess.run([exe, "signed-distance", str(BUNNY), str(path), "--json"],
                         capture_output=True, text=True, check=True)
    v = json.loads(out.stdout)
    r = c.signed_distance(pts)
    assert v["points"] == 300
    assert v["inside"] == r.inside.tolist()
    assert v["signed_distance"] == r.signed_distance.tolist()
    assert v["error_bound"] == r.error_bound.tolist()


def test_agrees_with_trimesh_on_generic_points():
    trimesh = pytest.importorskip("trimesh")
    pytest.importorskip("rtree")
    c = cc.Collider.load(str(BUNNY))
    mesh = trimesh.Trimesh(c.vertices, c.faces, process=False)
    lo, hi = c.vertices.min(axis=0), c.vertices.max(axis=0)
    pts = np.random.default_rng(7).uniform(lo - 0.05, hi + 0.05, size=(500, 3))
    ours = drop_in.signed_distance(c, pts)
    theirs = trimesh.proximity.signed_distance(mesh, pts)
    # Generic points: far from the surface relative to rounding, both agree.
    far = np.abs(theirs) > 1e-6
    assert np.array_equal(ours[far] > 0, theirs[far] > 0)
    assert np.allclose(np.abs(ours), np.abs(theirs), rtol=1e-9, atol=1e-12)

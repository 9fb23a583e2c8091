"""Python against the Rust `cga` command line on the same coordinates: bunny00 and armadillo
scaled into the unit box (the operations of `TriMesh::unit`, repeated in numpy) with B
translated, so both sides see bit-identical meshes. The binary is the one the workspace's
release build leaves in `target/release/cga` (CI builds it before the Python tests), or
`$CGA_BIN`; without it the test is skipped."""

import gzip
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import cga_collide as cc
from conftest import REPO


def cga_binary():
    candidates = [os.environ.get("CGA_BIN")]
    target = os.environ.get("CARGO_TARGET_DIR")
    if target:
        candidates.append(os.path.join(target, "release", "cga"))
    candidates.append(str(REPO / "target" / "release" / "cga"))
    for c in candidates:
        if c and pathlib.Path(c).is_file():
            return c
    return None


def read_off(path):
    with gzip.open(path, "rt") as f:
        words = [w for line in f for w in line.split("#", 1)[0].split()]
    nv, nf = int(words[1]), int(words[2])
    verts = np.array(words[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
    pos, tris = 4 + 3 * nv, []
    for _ in range(nf):
        k = int(words[pos])
        idx = [int(w) for w in words[pos + 1:pos + 1 + k]]
        pos += 1 + k
        tris.extend((idx[0], idx[i], idx[i + 1]) for i in range(1, k - 1))
    return verts, np.array(tris, dtype=np.int64)


def unit(v):
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre = (lo + hi) * 0.5
    side = (hi - lo).max()
    return (v - centre) * (1.0 / side)


@pytest.fixture(scope="module")
def meshes():
    data = REPO / "cga-collide" / "data"
    va, ta = read_off(data / "bunny00.off.gz")
    vb, tb = read_off(data / "armadillo.off.gz")
    return (unit(va), ta), (unit(vb), tb)


@pytest.mark.parametrize("translate", [(0.3, 0.05, 0.0), (0.6, 0.0, 0.1), (1.5, 0.0, 0.0)])
def test_pairs_and_class_equal_the_command_line(meshes, translate):
    binary = cga_binary()
    if binary is None:
        pytest.skip("no cga binary (cargo build --release -p cga-cli, or set CGA_BIN)")
    (va, ta), (vb, tb) = meshes
    t = ",".join(repr(x) for x in translate)
    out = subprocess.run(
        [binary, "collide", "bunny00", "armadillo", "--unit", "--translate", t, "--json",
         "--device", "cpu"],
        check=True, capture_output=True, text=True, cwd=REPO,
    )
    rust = json.loads(out.stdout)
    a = cc.Collider(va, ta)
    b = cc.Collider(vb + np.array(translate), tb)
    assert a.intersecting_pairs(b).shape[0] == rust["pairs"]
    assert a.collides(b) == rust["collides"]
    if rust.get("contact") is not None:
        assert a.contact_class(b) == rust["contact"]

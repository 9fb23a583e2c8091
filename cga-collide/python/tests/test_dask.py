"""Scale-out on dask.distributed: a local cluster of two worker processes answers (a) a batch
of poses, with the colliders shipped once per worker (scattered with ``broadcast=True``), and
(b) a folder of meshes checked for self-intersection; the answers equal one process's."""

import os
import sys

import numpy as np
import pytest

import cga_collide as cc
from conftest import REPO, random_poses

distributed = pytest.importorskip("distributed")
cloudpickle = pytest.importorskip("cloudpickle")

# The worker processes cannot import this test module: ship its functions by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


def collide_chunk(a, b, poses_a, poses_b):
    return a.collides_batch(b, poses_a, poses_b)


def self_intersects_file(path):
    c = cc.Collider.load(path)
    return os.path.basename(path), bool(c.self_intersects()), int(c.self_intersections().shape[0])


def worker_pid():
    return os.getpid()


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_two_worker_processes(client):
    pids = set(client.run(worker_pid).values())
    assert len(pids) == 2 and os.getpid() not in pids


def test_batch_of_poses_over_workers(client):
    bunny = cc.Collider.load(str(REPO / "cga-collide" / "data" / "bunny.obj"))
    k = 4000
    pa, pb = random_poses(k, seed=31, spread=6.0), random_poses(k, seed=32, spread=6.0)
    want = bunny.collides_batch(bunny, pa, pb)
    # the collider travels once to every worker; the tasks refer to it by its future
    [shared] = client.scatter([bunny], broadcast=True)
    assert len(client.who_has([shared])[shared.key]) == 2
    chunks = np.array_split(np.arange(k), 8)
    futures = [client.submit(collide_chunk, shared, shared, pa[c], pb[c], pure=False) for c in chunks]
    got = np.concatenate(client.gather(futures))
    assert got.dtype == np.bool_ and np.array_equal(got, want)
    assert 0 < want.sum() < k
    workers = {w for f in futures for w in client.who_has([f])[f.key]}
    assert len(workers) == 2, "both workers should take chunks"


def test_folder_of_meshes_over_workers(client, tmp_path):
    folder = tmp_path / "meshes"
    folder.mkdir()
    rng = np.random.default_rng(33)
    want = {}
    for k in range(8):
        # a box, and in odd files a stray triangle poking through it
        v = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
        v = v * rng.uniform(0.5, 2.0, 3)
        faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                 [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
        if k % 2:
            c = v.mean(axis=0)
            v = np.vstack([v, c + [0.1, 0.1, -5.0], c + [0.2, 0.1, 5.0], c + [0.1, 0.2, 5.0]])
            faces.append([8, 9, 10])
        path = folder / f"mesh{k}.obj"
        path.write_text(
            "".join(f"v {float(x)!r} {float(y)!r} {float(z)!r}\n" for x, y, z in v)
            + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
        )
        want[path.name] = bool(k % 2)
    paths = sorted(str(p) for p in folder.iterdir())
    local = [self_intersects_file(p) for p in paths]
    remote = client.gather(client.map(self_intersects_file, paths, pure=False))
    assert remote == local
    assert {name: hit for name, hit, _ in remote} == want

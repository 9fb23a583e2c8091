#!/usr/bin/env python3
"""Benchmarks of cga_collide from Python, in one run, against coal and python-fcl.

Not part of CI. Needs the package installed and `pip install coal python-fcl trimesh numpy
scipy`. From the repository root:

    python cga-collide/python/bench/bench.py [--repeat N] [--sizes 100,1000] [--batch 100000]

1. Per-pose cost, the Python call included on every side: bunny00 (A, at the identity) against
   armadillo (B), each scaled into the unit box centred at the origin (largest side 1, the
   operations of `TriMesh::unit`), on the 200 poses of B in
   `cga-collide/benches/poses_near_contact.txt` (about half collide). cga_collide
   `collides_at`; coal `collide` (BVHModelOBBRSS, first contact); python-fcl `collide` (its
   BVH model, first contact). Mean microseconds per pose, the best of `--repeat` passes.
2. A batch of `--batch` poses in one `collides_batch` call (the 200 poses, each repeated with
   small random translations), microseconds per pose.
3. Scenes of N icospheres and boxes at random poses (constant density: each object touches a
   few others): trimesh's `CollisionManager` (python-fcl) against the drop-in
   `cga_collide.trimesh.CollisionManager`: build (N `add_object` calls),
   `in_collision_internal`, move every object (N `set_transform` calls) and ask again,
   `min_distance_internal`. Seconds, best of `--repeat`.

Prints JSON; every answer is compared between the libraries and disagreements are counted
(near contact, exact and floating-point answers may differ).
"""

import argparse
import gzip
import json
import os
import time

import numpy as np

import cga_collide as cc

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
DATA = os.path.join(REPO, "cga-collide", "data")
POSES = os.path.join(REPO, "cga-collide", "benches", "poses_near_contact.txt")


def read_off(path):
    with gzip.open(path, "rt") as f:
        words = [w for line in f for w in line.split("#", 1)[0].split()]
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    verts = np.array(words[pos:pos + 3 * nv], dtype=np.float64).reshape(nv, 3)
    pos += 3 * nv
    tris = []
    for _ in range(nf):
        k = int(words[pos])
        idx = [int(w) for w in words[pos + 1:pos + 1 + k]]
        pos += 1 + k
        tris.extend((idx[0], idx[i], idx[i + 1]) for i in range(1, k - 1))
    return verts, np.array(tris, dtype=np.int64)


def unit(verts):
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    centre = (lo + hi) * 0.5
    side = (hi - lo).max()
    return (verts - centre) * (1.0 / side if side > 0 else 1.0)


def read_poses(path):
    """The poses of a `--poses` file (rotation about x, y, z in degrees, then the translation),
    as the command line reads them."""
    out = []
    with open(path) as f:
        for line in f:
            v = line.split("#", 1)[0].replace(",", " ").split()
            if v:
                v = [float(x) for x in v]
                out.append(cc.pose_from_degrees(v[:3], v[3:]))
    return np.array(out)


def best_of(repeat, fn):
    times, result = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t)
    return min(times), result


def per_pose(repeat):
    va, ta = read_off(os.path.join(DATA, "bunny00.off.gz"))
    vb, tb = read_off(os.path.join(DATA, "armadillo.off.gz"))
    va, vb = unit(va), unit(vb)
    poses = read_poses(POSES)
    identity = np.eye(4)
    out = {"poses": len(poses), "triangles": [len(ta), len(tb)]}

    a, b = cc.Collider(va, ta), cc.Collider(vb, tb)
    t, ours = best_of(repeat, lambda: [a.collides_at(identity, b, p) for p in poses])
    out["cga_collide_micros_per_pose"] = t / len(poses) * 1e6
    out["colliding"] = int(sum(ours))

    try:
        import coal

        def coal_model(v, t_):
            m = coal.BVHModelOBBRSS()
            m.beginModel(len(t_), len(v))
            m.addVertices(np.ascontiguousarray(v))
            m.addTriangles(np.ascontiguousarray(t_, dtype=np.int64))
            m.endModel()
            return m

        ma, mb = coal_model(va, ta), coal_model(vb, tb)
        tfs = [coal.Transform3s(p[:3, :3].copy(), p[:3, 3].copy()) for p in poses]
        ident = coal.Transform3s()
        req = coal.CollisionRequest()
        req.num_max_contacts = 1

        def run_coal():
            hits = []
            for tf in tfs:
                res = coal.CollisionResult()
                coal.collide(ma, ident, mb, tf, req, res)
                hits.append(res.isCollision())
            return hits

        t, theirs = best_of(repeat, run_coal)
        out["coal_micros_per_pose"] = t / len(poses) * 1e6
        out["coal_disagreements"] = int(sum(x != y for x, y in zip(ours, theirs)))
        out["coal_version"] = getattr(coal, "__version__", "?")
    except ImportError:
        out["coal"] = "not installed"

    try:
        import fcl

        def fcl_model(v, t_):
            m = fcl.BVHModel()
            m.beginModel(len(v), len(t_))
            m.addSubModel(v, t_)
            m.endModel()
            return m

        oa = fcl.CollisionObject(fcl_model(va, ta), fcl.Transform())
        ob = fcl.CollisionObject(fcl_model(vb, tb), fcl.Transform())
        tfs = [fcl.Transform(p[:3, :3].copy(), p[:3, 3].copy()) for p in poses]
        req = fcl.CollisionRequest(num_max_contacts=1)

        def run_fcl():
            hits = []
            for tf in tfs:
                ob.setTransform(tf)
                res = fcl.CollisionResult()
                hits.append(fcl.collide(oa, ob, req, res) > 0)
            return hits

        t, theirs = best_of(repeat, run_fcl)
        out["python_fcl_micros_per_pose"] = t / len(poses) * 1e6
        out["python_fcl_disagreements"] = int(sum(x != y for x, y in zip(ours, theirs)))
    except ImportError:
        out["python_fcl"] = "not installed"
    return out, (a, b, poses)


def batch(repeat, k, colliders):
    a, b, poses = colliders
    rng = np.random.default_rng(2026)
    many = poses[rng.integers(0, len(poses), size=k)].copy()
    many[:, :3, 3] += rng.uniform(-0.01, 0.01, size=(k, 3))
    identity = np.eye(4)
    t, hits = best_of(repeat, lambda: a.collides_batch(b, identity, many))
    return {"poses": k, "colliding": int(hits.sum()), "micros_per_pose": t / k * 1e6, "seconds": t}


def random_poses(n, rng, side):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    m = np.zeros((n, 4, 4))
    m[:, 0] = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), np.zeros(n)], 1)
    m[:, 1] = np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), np.zeros(n)], 1)
    m[:, 2] = np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), np.zeros(n)], 1)
    m[:, :3, 3] = rng.uniform(0, side, size=(n, 3))
    m[:, 3, 3] = 1
    return m


def scene(repeat, n):
    import trimesh

    meshes = [trimesh.creation.icosphere(subdivisions=2, radius=0.5), trimesh.creation.box(extents=[1, 1, 1])]
    rng = np.random.default_rng(n)
    side = 1.6 * n ** (1 / 3)  # constant density: a few contacts per object
    first, moved = random_poses(n, rng, side), random_poses(n, rng, side)
    out = {"objects": n, "triangles_per_object": [len(m.faces) for m in meshes]}
    answers = {}
    managers = {"trimesh_fcl": trimesh.collision.CollisionManager}
    from cga_collide.trimesh import CollisionManager as Ours

    managers["cga_collide"] = Ours
    for name, cls in managers.items():
        times = {"build": [], "in_collision_internal": [], "move_all_and_ask": [], "min_distance_internal": []}
        for _ in range(repeat):
            t = time.perf_counter()
            m = cls()
            for k in range(n):
                m.add_object(f"o{k}", meshes[k % 2], first[k])
            times["build"].append(time.perf_counter() - t)
            t = time.perf_counter()
            hit, names = m.in_collision_internal(return_names=True)
            times["in_collision_internal"].append(time.perf_counter() - t)
            t = time.perf_counter()
            for k in range(n):
                m.set_transform(f"o{k}", moved[k])
            hit2, names2 = m.in_collision_internal(return_names=True)
            times["move_all_and_ask"].append(time.perf_counter() - t)
            t = time.perf_counter()
            d = m.min_distance_internal()
            times["min_distance_internal"].append(time.perf_counter() - t)
        out[name] = {k: min(v) for k, v in times.items()}
        answers[name] = (names, names2, d)
    ours, theirs = answers["cga_collide"], answers["trimesh_fcl"]
    out["colliding_pairs"] = [len(ours[0]), len(ours[1])]
    out["pair_set_differences"] = [len(ours[0] ^ theirs[0]), len(ours[1] ^ theirs[1])]
    out["min_distance"] = {"cga_collide": ours[2], "trimesh_fcl": float(theirs[2])}
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--batch", type=int, default=100_000)
    ap.add_argument("--sizes", default="100,1000")
    args = ap.parse_args()
    result = {"machine_cores": os.cpu_count()}
    result["per_pose"], colliders = per_pose(args.repeat)
    result["batch"] = batch(args.repeat, args.batch, colliders)
    result["scenes"] = [scene(args.repeat, int(n)) for n in args.sizes.split(",") if n]
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Times coal (the FCL successor) per new pose on the poses of the pose benchmark.

Not part of CI. Needs `pip install coal numpy` and the cga_collide wheel (for
`pose_from_degrees`, the command line's pose formula). Usage, from the repository root:

    python3 cga-collide/benches/coal_poses.py [--poses FILE] [--repeat N]

bunny00 (A) and armadillo (B) from cga-collide/data, each scaled into the unit box centred at
the origin (largest side 1, the f64 operations of `TriMesh::unit`). Both BVHModelOBBRSS models
are built once in their own frames; every pose is given to `coal.collide` as B's transform
(rotation about x, then y, then z in degrees, then the translation: the CLI's `--poses`
formula), A at the identity. Two requests per pose: `num_max_contacts = 1` (first hit) and
unlimited (all pairs). Prints JSON with the mean microseconds per pose of each (best of
`--repeat` passes over all poses; the time of the Python call itself is included, about a
microsecond), the number of colliding poses and the total pair count.
"""
import argparse
import json
import os
import sys
import time

import cga_collide as cc
import coal
import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from coal_bench import model, read_off, unit  # noqa: E402


def read_poses(path):
    out = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].replace(",", " ").split()
            if line:
                v = [float(x) for x in line]
                pose = cc.pose_from_degrees(v[:3], v[3:])
                out.append(coal.Transform3s(np.ascontiguousarray(pose[:3, :3]), pose[:3, 3].copy()))
    return out


def run(ma, mb, poses, max_contacts):
    identity = coal.Transform3s()
    req = coal.CollisionRequest()
    req.num_max_contacts = max_contacts
    collides, pairs = [], 0
    t = time.perf_counter()
    for tf in poses:
        res = coal.CollisionResult()
        coal.collide(ma, identity, mb, tf, req, res)
        collides.append(res.isCollision())
        pairs += res.numContacts()
    return time.perf_counter() - t, collides, pairs


def main():
    here = os.path.dirname(__file__)
    ap = argparse.ArgumentParser()
    ap.add_argument("--poses", default=os.path.join(here, "poses_near_contact.txt"))
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    data = os.path.join(here, "..", "data")
    va, ta = read_off(os.path.join(data, "bunny00.off.gz"))
    vb, tb = read_off(os.path.join(data, "armadillo.off.gz"))
    ma, mb = model(unit(va), ta), model(unit(vb), tb)
    poses = read_poses(args.poses)
    best = {}
    for name, k in [("first_hit", 1), ("all_pairs", 10**7)]:
        times = []
        for _ in range(args.repeat):
            dt, collides, pairs = run(ma, mb, poses, k)
            times.append(dt)
        best[name] = (min(times) / len(poses) * 1e6, collides, pairs)
    print(json.dumps({
        "library": "coal " + getattr(coal, "__version__", "?"),
        "poses": len(poses),
        "colliding": sum(best["first_hit"][1]),
        "pairs": best["all_pairs"][2],
        "first_hit_micros_per_pose": best["first_hit"][0],
        "all_pairs_micros_per_pose": best["all_pairs"][0],
    }, indent=2))


if __name__ == "__main__":
    main()

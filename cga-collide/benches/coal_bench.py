#!/usr/bin/env python3
"""Times coal (the FCL successor) on the exact placement `cga collide` uses, for the README.

Not part of CI. Needs `pip install coal numpy`. Usage, from the repository root:

    python3 cga-collide/benches/coal_bench.py [A.off.gz B.off.gz] [--translate X,Y,Z] [--repeat N]

Defaults: bunny00 vs armadillo from cga-collide/data with `--unit --translate 0.3,0.05,0`,
the placement of the mesh benchmark. Each mesh is scaled into the unit box centred at the origin
(largest side 1) with the same f64 operations as `TriMesh::unit`, then B is translated; coal
gets the transformed vertices with identity poses, so both libraries see identical coordinates.
Prints JSON with coal's pair count and the best time of the all-contacts query.
"""
import argparse
import gzip
import json
import time

import coal
import numpy as np


def read_off(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt") as f:
        words = []
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                words.extend(line.split())
    if words[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    verts = np.array(words[pos:pos + 3 * nv], dtype=np.float64).reshape(nv, 3)
    pos += 3 * nv
    tris = []
    for _ in range(nf):
        k = int(words[pos])
        idx = [int(w) for w in words[pos + 1:pos + 1 + k]]
        pos += 1 + k
        for i in range(1, k - 1):  # fan triangulation, as the Rust loader does
            tris.append((idx[0], idx[i], idx[i + 1]))
    return verts, np.array(tris, dtype=np.int64)


def unit(verts):
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    centre = (lo + hi) * 0.5
    side = (hi - lo).max()
    scale = 1.0 / side if side > 0 else 1.0
    return (verts - centre) * scale


def model(verts, tris):
    m = coal.BVHModelOBBRSS()
    m.beginModel(len(tris), len(verts))
    m.addVertices(np.ascontiguousarray(verts))
    m.addTriangles(np.ascontiguousarray(tris, dtype=np.int64))
    m.endModel()
    return m


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a", nargs="?", default="cga-collide/data/bunny00.off.gz")
    ap.add_argument("b", nargs="?", default="cga-collide/data/armadillo.off.gz")
    ap.add_argument("--translate", default="0.3,0.05,0")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    va, ta = read_off(args.a)
    vb, tb = read_off(args.b)
    va = unit(va)
    vb = unit(vb) + np.array([float(x) for x in args.translate.split(",")])
    t0 = time.perf_counter()
    ma, mb = model(va, ta), model(vb, tb)
    build = time.perf_counter() - t0
    identity = coal.Transform3s()
    best, pairs = float("inf"), None
    for _ in range(args.repeat):
        req = coal.CollisionRequest()
        req.num_max_contacts = 10**7
        res = coal.CollisionResult()
        t = time.perf_counter()
        coal.collide(ma, identity, mb, identity, req, res)
        best = min(best, time.perf_counter() - t)
        pairs = res.numContacts()
    best_first = float("inf")
    for _ in range(args.repeat):
        req = coal.CollisionRequest()
        res = coal.CollisionResult()
        t = time.perf_counter()
        coal.collide(ma, identity, mb, identity, req, res)
        best_first = min(best_first, time.perf_counter() - t)
    print(json.dumps({
        "library": "coal " + getattr(coal, "__version__", "?"),
        "triangles": [len(ta), len(tb)],
        "pairs": pairs,
        "build_millis": build * 1e3,
        "millis": best * 1e3,
        "first_hit_millis": best_first * 1e3,
    }, indent=2))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Times coal's mesh–mesh distance on the placements of `benches/distance.rs` and prints the
distances, for comparison with `cga distance` (same coordinates: both meshes scaled with the
same f64 operations as `TriMesh::unit`, B turned and translated; coal gets the transformed
vertices with identity poses).

`millis` is the best of the repeats, `median_millis` and `mean_millis` the middle and the
average (criterion's figures for `cga` are means). Not part of CI. Needs `pip install coal
numpy`. From the repository root:

    python3 cga-collide/benches/coal_distance.py [--repeat N] [--posed]

With `--posed`, B's model is built once in its own frame and each placement is passed to coal
as a transform (coal's usual way, and the counterpart of `Collider::distance_at`).

The rotation is nalgebra's `Isometry3::new(t, axis_angle)` (scaled axis), rebuilt here with
Rodrigues' formula; tiny differences in the rotated coordinates (last bits) can change the
distance in the last bits, far below the 1e-9 relative agreement checked.
"""
import argparse
import json
import math
import time

import coal
import numpy as np

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coal_bench import model, read_off, unit  # noqa: E402

PLACEMENTS = [
    ([1.2, 0.05, 0.0], [0.0, 0.0, 0.0]),
    ([0.0, 1.1, 0.2], [0.3, 0.0, 0.5]),
    ([0.9, 0.6, -0.3], [0.0, 1.0, 0.0]),
]


def rotation(axis_angle):
    w = np.array(axis_angle, dtype=np.float64)
    angle = math.sqrt(float(w @ w))
    if angle == 0.0:
        return np.eye(3)
    k = w / angle
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * (kx @ kx)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=20)
    ap.add_argument("--posed", action="store_true")
    args = ap.parse_args()
    va, ta = read_off("cga-collide/data/bunny00.off.gz")
    vb0, tb = read_off("cga-collide/data/armadillo.off.gz")
    ma = model(unit(va), ta)
    identity = coal.Transform3s()
    out = []
    local_b = model(unit(vb0), tb) if args.posed else None
    for t, r in PLACEMENTS:
        if args.posed:
            mb = local_b
            pose_b = coal.Transform3s(rotation(r), np.array(t, dtype=np.float64))
        else:
            vb = unit(vb0) @ rotation(r).T + np.array(t)
            mb = model(vb, tb)
            pose_b = identity
        times, dist = [], None
        for _ in range(args.repeat):
            req = coal.DistanceRequest()
            res = coal.DistanceResult()
            t0 = time.perf_counter()
            coal.distance(ma, identity, mb, pose_b, req, res)
            times.append(time.perf_counter() - t0)
            dist = res.min_distance
        times.sort()
        out.append({
            "translate": t,
            "rotate": r,
            "distance": dist,
            "millis": times[0] * 1e3,
            "median_millis": times[len(times) // 2] * 1e3,
            "mean_millis": sum(times) / len(times) * 1e3,
        })
    print(json.dumps({"library": "coal " + getattr(coal, "__version__", "?"), "posed": args.posed,
                      "placements": out}, indent=2))


if __name__ == "__main__":
    main()

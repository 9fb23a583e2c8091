#!/usr/bin/env python3
"""Times coal's `collide` (PyPI `coal`, the FCL successor) on the primitive pair files of
shape_pairs.py, the same files `cga shapes` reads, and counts its wrong answers.

Each pair is converted once (peer_shapes.py says how: Sphere, Box or Convex, Capsule /
Cylinder / Cone about the axis midpoint, Halfspace, Convex from qhull's triangles, TriangleP),
then `collide(geom_a, tf_a, geom_b, tf_b, request, result)` with coal's default
CollisionRequest is called in 5 loops of REPEAT / 5 calls (`result.clear()` before each call,
since coal accumulates contacts); a pair's time per call is the best loop's time / its calls.
Per pair type and family: the median over its pairs (micros_median), the Python call cost
(micros_call_cost: the same loops on two unit spheres 10 apart, whose C++ work is a few dozen
nanoseconds, so this is an upper bound of the cost of the call itself; timed right before
each pair, median) and micros_net, the median over the pairs of (pair time - the call cost
timed next to it). An answer is a collision when collide() reports a contact.

wrong = false_collisions + missed, against each line's `expected`; exact_input_pairs /
wrong_exact_input count only the pairs whose coal input is exactly the JSON solid (no rounding
in the conversion; see peer_shapes.py); errors: pairs where coal raised.

Output: one JSON line per (pair type, family):
  {"who": "coal", "pair", "family", "pairs", "micros_median", "micros_call_cost", "micros_net",
   "wrong", "false_collisions", "missed", "exact_input_pairs", "wrong_exact_input", "errors"}

Needs `pip install coal numpy scipy` (coal 3.0.3 measured). Usage:
  python3 coal_shapes.py FILE.jsonl... [--repeat N] [--wrong FILE]
--wrong FILE writes every wrong pair's JSON line (with coal's answer) there.
"""
import argparse
import json
import os
import sys
import time

import coal
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peer_shapes import convert, group_summary, read_pairs  # noqa: E402


def vec3s(points):
    v = coal.StdVec_Vec3s()
    for p in points:
        v.append(np.asarray(p, dtype=float))
    return v


def geometry(peer):
    p = peer.params
    if peer.kind == "sphere":
        return coal.Sphere(p[0])
    if peer.kind == "box":
        return coal.Box(p[0], p[1], p[2])
    if peer.kind == "capsule":
        return coal.Capsule(p[0], p[1])
    if peer.kind == "cylinder":
        return coal.Cylinder(p[0], p[1])
    if peer.kind == "cone":
        return coal.Cone(p[0], p[1])
    if peer.kind == "halfspace":
        return coal.Halfspace(np.array(p[:3]), p[3])
    if peer.kind == "triangle":
        return coal.TriangleP(np.array(p[0:3]), np.array(p[3:6]), np.array(p[6:9]))
    if peer.kind == "convex":
        tris = coal.StdVec_Triangle()
        for a, b, c in peer.faces:
            tris.append(coal.Triangle(int(a), int(b), int(c)))
        return coal.Convex(vec3s(peer.points), tris)
    if peer.kind == "unsupported":
        raise ValueError("no convex hull could be made of these points")
    raise ValueError(f"coal has no {peer.kind}")


def transform(peer):
    return coal.Transform3s(np.ascontiguousarray(peer.rot), np.ascontiguousarray(peer.t))


def time_loop(ga, ta, gb, tb, request, result, repeat, batches=5):
    """(answer of the first call, microseconds per call): the best of `batches` loops of
    repeat / batches calls (the machine is shared; the best loop is the least disturbed)."""
    collide, clear = coal.collide, result.clear
    clear()
    answer = collide(ga, ta, gb, tb, request, result) > 0
    n = max(1, repeat // batches)
    best = float("inf")
    for _ in range(batches):
        start = time.perf_counter()
        for _ in range(n):
            clear()
            collide(ga, ta, gb, tb, request, result)
        best = min(best, (time.perf_counter() - start) * 1e6 / n)
    return answer, best


class CallCost:
    """The same loops on two unit spheres 10 apart, timed right before each pair, so that
    both see the same machine load (the machine may be shared)."""

    def __init__(self, repeat):
        self.repeat = repeat
        self.sphere = coal.Sphere(1.0)
        self.ta = coal.Transform3s(np.eye(3), np.zeros(3))
        self.tb = coal.Transform3s(np.eye(3), np.array([10.0, 0.0, 0.0]))
        self.req, self.res = coal.CollisionRequest(), coal.CollisionResult()

    def sample(self):
        return time_loop(self.sphere, self.ta, self.sphere, self.tb, self.req, self.res,
                         self.repeat)[1]


def main():
    ap = argparse.ArgumentParser(description="coal on primitive pair files")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--repeat", type=int, default=200)
    ap.add_argument("--wrong", help="write the wrong pairs' lines here")
    args = ap.parse_args()
    request = coal.CollisionRequest()
    result = coal.CollisionResult()
    rows, wrong_lines = [], []
    cost = CallCost(args.repeat)
    for pair, family, expected, case, a, b in read_pairs(args.files):
        pa, pb = convert(a), convert(b)
        exact = pa.exact and pb.exact
        try:
            ga, ta, gb, tb = geometry(pa), transform(pa), geometry(pb), transform(pb)
            call = cost.sample()
            answer, micros = time_loop(ga, ta, gb, tb, request, result, args.repeat)
        except Exception as e:  # coal's exceptions (unsupported pair, EPA failure, ...)
            print(f"coal raised on {pair} {case}: {e}", file=sys.stderr)
            rows.append((pair, family, expected, None, None, exact, None))
            continue
        rows.append((pair, family, expected, answer, micros, exact, call))
        if expected is not None and answer != expected:
            wrong_lines.append({"a": a, "b": b, "expected": expected, "coal": answer,
                                "family": family, "case": case, "exact_input": exact})
    for d in group_summary("coal", rows):
        print(json.dumps(d))
    if args.wrong:
        with open(args.wrong, "w") as f:
            for w in wrong_lines:
                f.write(json.dumps(w) + "\n")


if __name__ == "__main__":
    sys.exit(main())

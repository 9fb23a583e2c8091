#!/usr/bin/env python3
"""Times our `cga_collide.intersects` from Python on the primitive pair files of
shape_pairs.py, exactly as coal_shapes.py times coal's `collide`, so that both sides pay a
Python call and are measured the same way.

Each pair is built once as the package's shape classes (the JSON values as given: no
conversion, no rounding), then `intersects(a, b)` is called in 5 loops of REPEAT / 5 calls; a
pair's time per call is the best loop's time / its calls (fewer calls for a pair
whose first call is slow, so that a loop lasts about 2 ms). Per pair type and family: the
median over its pairs (micros_median), the Python call cost (micros_call_cost: the same loops
on two unit balls 10 apart, whose native work is a few dozen nanoseconds, so this is an upper
bound of the call itself; timed right before each pair, median) and micros_net, the median
over the pairs of (pair time - the call cost timed next to it).

wrong = false_collisions + missed against each line's `expected`; errors: pairs the library
refused (`CgaError`, e.g. a curved pair without an exact test yet).

Output: one JSON line per (pair type, family), the fields of coal_shapes.py with
"who": "cga-py". Needs numpy and the built package (`maturin develop --release` in
cga-collide/python). Usage: python3 cga_py_shapes.py FILE.jsonl... [--repeat N]
"""
import argparse
import json
import os
import sys
import time

import cga_collide as cga
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peer_shapes import group_summary, read_pairs  # noqa: E402


def shape(spec):
    """The package's shape for one JSON SHAPE (the `cga shapes` spelling)."""
    (kind, p), = spec.items()
    a = np.asarray
    if kind == "ball":
        return cga.Ball(a(p["center"], dtype=float), float(p["radius"]))
    if kind == "capsule":
        return cga.Capsule(a(p["a"], dtype=float), a(p["b"], dtype=float), float(p["radius"]))
    if kind == "cylinder":
        return cga.Cylinder(a(p["a"], dtype=float), a(p["b"], dtype=float), float(p["radius"]))
    if kind == "cone":
        return cga.Cone(a(p["apex"], dtype=float), a(p["base"], dtype=float),
                        float(p["radius"]))
    if kind == "cuboid":
        return cga.Cuboid(a(p["center"], dtype=float), a(p["half_axes"], dtype=float))
    if kind == "halfspace":
        return cga.HalfSpace(a(p["point"], dtype=float), a(p["normal"], dtype=float))
    if kind == "convex":
        return cga.ConvexHull(a(p["points"], dtype=float))
    if kind == "triangle":
        return cga.Triangle(*(a(q, dtype=float) for q in p["points"]))
    if kind == "segment":
        return cga.Segment(*(a(q, dtype=float) for q in p["points"]))
    raise ValueError(f"unknown shape kind {kind}")


def time_loop(a, b, repeat, batches=5):
    """(answer of the first call, microseconds per call): the best of `batches` loops of
    repeat / batches calls (the machine may be shared; the best loop is the least
    disturbed)."""
    intersects = cga.intersects
    start = time.perf_counter()
    answer = intersects(a, b)
    first = time.perf_counter() - start
    # Slow pairs (the exact fallback) get fewer calls: a loop lasts about 2 ms at most.
    n = max(1, min(repeat // batches, int(2e-3 / max(first, 1e-9))))
    best = float("inf")
    for _ in range(batches):
        start = time.perf_counter()
        for _ in range(n):
            intersects(a, b)
        best = min(best, (time.perf_counter() - start) * 1e6 / n)
    return answer, best


def main():
    ap = argparse.ArgumentParser(description="cga_collide from Python on primitive pair files")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--repeat", type=int, default=200)
    args = ap.parse_args()
    far_a = cga.Ball(np.zeros(3), 1.0)
    far_b = cga.Ball(np.array([10.0, 0.0, 0.0]), 1.0)
    rows = []
    for pair, family, expected, case, a, b in read_pairs(args.files):
        try:
            sa, sb = shape(a), shape(b)
            call = time_loop(far_a, far_b, args.repeat)[1]
            answer, micros = time_loop(sa, sb, args.repeat)
        except cga.CgaError as e:
            print(f"cga refused {pair} {case}: {e}", file=sys.stderr)
            rows.append((pair, family, expected, None, None, True, None))
            continue
        rows.append((pair, family, expected, answer, micros, True, call))
    for d in group_summary("cga-py", rows):
        print(json.dumps(d))


if __name__ == "__main__":
    sys.exit(main())

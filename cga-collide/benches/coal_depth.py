#!/usr/bin/env python3
"""Penetration depth and signed distance: coal's GJK/EPA (`coal.distance` with
`enable_signed_distance`, PyPI `coal`) against ours (`cga shapes FILE --depth --json`) on the
same primitive pair files, with our certified value as the reference.

Ours is exact up to one rounding with a proved bound (the reference is `signed_distance` ±
`error_bound`, checked against an independent exact reference in the workspace tests); coal's
error on a pair is `|coal − ours|` (to within our bound). Pairs whose coal input is not exactly
the JSON solid (peer_shapes.py `exact`) are left out of the accuracy columns, and pairs we do
not compute (`null`: a cylinder or cone pair whose contact sign is not decided, see
docs/contacts.md; pair types with no exact test at all, listed as `refused_by_ours`) are left
out altogether. Cylinders and cones go to coal as `coal.Cylinder(radius, length)` /
`coal.Cone(radius, length)` centred on the axis midpoint (coal_shapes.py); for pairs with a
cylinder or cone our reference is the certified bracket's midpoint, its bound the half width.

Per pair type, over the pairs: coal's median and largest absolute error, its largest error
relative to max(|ours|, 1e-300) on overlapping pairs, wrong_sign (coal says apart where the
pair overlaps or touches, or overlapping where it is apart by more than coal's own tolerance
1e-9 relative — reported separately as `wrong_sign_any` without that allowance), its time per
call (best of 5 loops, Python call cost of two far spheres subtracted) and ours per pair (the
CLI's `depth_micros_mean`, Rust, no Python).

Output: one JSON line per pair type, then a Markdown table on stderr. Usage:
  python3 coal_depth.py --cga PATH/TO/cga FILE.jsonl... [--repeat N]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import coal
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coal_shapes import geometry, transform  # noqa: E402
from peer_shapes import convert, pair_type, read_pairs  # noqa: E402


def ours(cga, path, refused):
    """Our signed distances, bounds and the CLI's mean time per pair of the line's type, for
    every line of `path` (None where not computed). The CLI runs once per pair type: a file can hold pair types
    the library has no exact test for at all (a cylinder against a cone), which fail the
    whole command; those types are added to `refused` and their lines get None."""
    with open(path) as f:
        lines = [x for x in f if x.strip()]
    by_type = {}
    for k, text in enumerate(lines):
        by_type.setdefault(pair_type(json.loads(text)), []).append(k)
    sd, eb, micros = [None] * len(lines), [None] * len(lines), [None] * len(lines)
    with tempfile.TemporaryDirectory() as tmp:
        for pair, ks in sorted(by_type.items()):
            part = os.path.join(tmp, "pairs.jsonl")
            with open(part, "w") as f:
                f.writelines(lines[k] for k in ks)
            run = subprocess.run([cga, "shapes", part, "--depth", "--json"],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                refused.add(pair)
                continue
            (line,) = [json.loads(x) for x in run.stdout.splitlines() if x.strip()]
            for j, k in enumerate(ks):
                sd[k], eb[k] = line["signed_distance"][j], line["error_bound"][j]
                micros[k] = line["depth_micros_mean"]
    return sd, eb, micros


def coal_signed(ga, ta, gb, tb, repeat):
    req = coal.DistanceRequest()
    req.enable_signed_distance = True
    res = coal.DistanceResult()
    coal.distance(ga, ta, gb, tb, req, res)
    value = res.min_distance
    best = float("inf")
    n = max(1, repeat // 5)
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            res.clear()
            coal.distance(ga, ta, gb, tb, req, res)
        best = min(best, (time.perf_counter() - t) / n)
    return value, best * 1e6


def call_cost(repeat):
    s = coal.Sphere(1.0)
    far = coal.Transform3s(np.eye(3), np.array([10.0, 0.0, 0.0]))
    return coal_signed(s, coal.Transform3s(), s, far, repeat)[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cga", required=True)
    ap.add_argument("--repeat", type=int, default=200)
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    groups = {}
    refused = set()
    for path in args.files:
        sd, eb, our_micros = ours(args.cga, path, refused)
        for k, (pair, _family, _exp, _case, a, b) in enumerate(read_pairs([path])):
            if sd[k] is None:
                continue
            pa, pb = convert(a), convert(b)
            g = groups.setdefault(pair, {"errors": [], "rel": [], "wrong": 0, "wrong_any": 0,
                                         "coal_micros": [], "ours_micros": [], "pairs": 0,
                                         "inexact": 0, "raised": 0})
            g["pairs"] += 1
            g["ours_micros"].append(our_micros[k])
            if not (pa.exact and pb.exact):
                g["inexact"] += 1
                continue
            try:
                ga, gb = geometry(pa), geometry(pb)
                value, micros = coal_signed(ga, transform(pa), gb, transform(pb), args.repeat)
            except Exception:  # noqa: BLE001 - coal raises on some inputs: counted
                g["raised"] += 1
                continue
            cost = call_cost(args.repeat // 4)
            g["coal_micros"].append(max(micros - cost, 0.0))
            err = abs(value - sd[k])
            g["errors"].append(err)
            if sd[k] < 0:
                g["rel"].append(err / max(abs(sd[k]), 1e-300))
            apart = sd[k] - eb[k] > 0
            g["wrong_any"] += int((value > 0) != apart)
            tol = 1e-9 * max(1.0, abs(sd[k]))
            g["wrong"] += int((apart and value < -tol) or (not apart and value > tol))
    rows = []
    if refused:
        print(json.dumps({"refused_by_ours": sorted(refused)}))
    for pair, g in sorted(groups.items()):
        med = lambda xs: float(np.median(xs)) if xs else None  # noqa: E731
        row = {"pair": pair, "pairs": g["pairs"], "judged": len(g["errors"]),
               "inexact_input": g["inexact"], "coal_raised": g["raised"],
               "coal_error_median": med(g["errors"]),
               "coal_error_max": max(g["errors"]) if g["errors"] else None,
               "coal_rel_error_max_overlapping": max(g["rel"]) if g["rel"] else None,
               "coal_wrong_sign": g["wrong"], "coal_wrong_sign_any": g["wrong_any"],
               "coal_micros": med(g["coal_micros"]), "ours_micros": med(g["ours_micros"])}
        rows.append(row)
        print(json.dumps(row))
    f = lambda x: "–" if x is None else f"{x:.2g}"  # noqa: E731
    print("| pair | judged | coal error median | coal error max | coal max rel. error "
          "(overlapping) | coal wrong sign (tol. / any) | coal µs | ours µs |", file=sys.stderr)
    print("|---|---|---|---|---|---|---|---|", file=sys.stderr)
    for r in rows:
        print(f"| {r['pair']} | {r['judged']} | {f(r['coal_error_median'])} | "
              f"{f(r['coal_error_max'])} | {f(r['coal_rel_error_max_overlapping'])} | "
              f"{r['coal_wrong_sign']} / {r['coal_wrong_sign_any']} | {f(r['coal_micros'])} | "
              f"{f(r['ours_micros'])} |", file=sys.stderr)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Exact CCD (`cga ccd`) against Tight Inclusion (`ipctk.TightInclusionCCD`) on the same queries.

Setup (once; any Python >= 3.9):

    python3 -m venv /tmp/venv-ccd && /tmp/venv-ccd/bin/pip install ipctk numpy

Run (from the repository root, after `cargo build --release -p cga-cli --bin cga`):

    /tmp/venv-ccd/bin/python cga-collide/benches/ccd_tight_inclusion.py \
        [--cga target/release/cga] [--limit N] [--repeat 3] [QUERY_DIR_OR_FILES ...]

By default the queries are the 7,279 sample queries of the CCD benchmark (Wang, Ferguson,
Schneider, Jiang, Attene, Panozzo, ACM TOG 2021) kept as fixtures under
`cga-collide/tests/fixtures/ccd/sample-queries/` (`**/vertex-face/*.csv.gz`,
`**/edge-edge/*.csv.gz`: 8 rows `x_num,x_den,y_num,y_den,z_num,z_den,truth` a query, the
four points at t = 0 then at t = 1). Every value is exactly an f64 (power-of-two denominators);
it is converted exactly with `fractions.Fraction` and checked.

Tight Inclusion runs with the paper's settings: `tolerance=1e-6, max_iterations=1_000_000`,
`min_distance=0`, `tmax=1`. ipctk wraps Tight Inclusion in a strategy: it first asks for a
minimum separation of `min((1 - conservative_rescaling) * d0, 1e-4)` (`d0` the distance at
t = 0; any query at distance 0 at t = 0 is a collision), and when that reports a time of impact
below 1e-6 it asks again with separation 0, `no_zero_toi` and no iteration cap. The default
here, `--conservative-rescaling 1.0`, makes the first separation 0, the closest to plain Tight
Inclusion; ipctk's own default 0.8 reports more collisions (pass `--conservative-rescaling 0.8`). Each query is timed `--repeat` times (the minimum is kept, as
`cga ccd --repeat 3` does) around the single ipctk call, the numpy arguments built beforehand.
The Python call overhead is measured apart: the same call on a query whose two primitives are
far apart (rejected by TI at once; this upper-bounds the binding cost), and a no-op Python
function with the same eight arguments (a lower bound). "TI net" subtracts the far-apart
median from every query's time (floored at 0), which favours TI (that call also computes the
initial distance and rejects the query); "net of no-op call" subtracts the no-op's time.

Then `cga ccd --repeat N --json FILES` (answers, false positives/negatives per file) and
`cga ccd --repeat N FILES` (its `all … files` line: mean/median/max over all queries) run on the
same files, once for the yes/no answer alone and once with `--first-contact --tolerance 1e-6`
(each query's earliest contact time to TI's tolerance, the like-for-like work), and one
comparison table is printed.
"""

import argparse
import gzip
import json
import pathlib
import re
import statistics
import subprocess
import sys
import time
from fractions import Fraction

import numpy as np

try:
    import ipctk
except ImportError:  # pragma: no cover
    sys.exit("ipctk is missing: pip install ipctk numpy (see the top of this script)")

REPO = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = REPO / "cga-collide" / "tests" / "fixtures" / "ccd" / "sample-queries"


def exact_float(num, den):
    value = Fraction(int(num), int(den))
    as_float = float(value)
    if Fraction(as_float) != value:
        raise ValueError(f"{num}/{den} is not exactly a double")
    return as_float


def kind_of(path):
    for part in reversed(path.parts):
        if part in ("vertex-face", "edge-edge"):
            return part
    raise ValueError(f"{path}: no vertex-face or edge-edge folder in the path")


def load(path):
    """[(points[8][3] float64, truth bool or None)] of one query file."""
    opener = gzip.open if path.suffix == ".gz" else open
    with opener(path, "rt") as f:
        rows = [line.strip().split(",") for line in f if line.strip()]
    if len(rows) % 8:
        raise ValueError(f"{path}: {len(rows)} rows, not a multiple of 8")
    queries = []
    for q in range(0, len(rows), 8):
        block = rows[q : q + 8]
        pts = np.array(
            [[exact_float(r[2 * k], r[2 * k + 1]) for k in range(3)] for r in block],
            dtype=np.float64,
        )
        truth = bool(int(block[0][6])) if len(block[0]) > 6 else None
        queries.append((pts, truth))
    return queries


def files_from(args):
    if not args:
        args = [str(FIXTURES)]
    out = []
    for a in args:
        p = pathlib.Path(a)
        if p.is_dir():
            out.extend(sorted(p.rglob("*.csv.gz")) + sorted(p.rglob("*.csv")))
        else:
            out.append(p)
    return out


def time_call(fn, args, repeat):
    best = None
    result = None
    for _ in range(repeat):
        t0 = time.perf_counter_ns()
        result = fn(*args)
        dt = time.perf_counter_ns() - t0
        best = dt if best is None else min(best, dt)
    return result, best / 1000.0


def summary(micros):
    return (
        statistics.fmean(micros) if micros else 0.0,
        statistics.median(micros) if micros else 0.0,
        max(micros) if micros else 0.0,
    )


def find_cga(given):
    if given:
        return pathlib.Path(given)
    candidates = [REPO / "target" / "release" / "cga"]
    import os

    if os.environ.get("CARGO_TARGET_DIR"):
        candidates.insert(0, pathlib.Path(os.environ["CARGO_TARGET_DIR"]) / "release" / "cga")
    for c in candidates:
        if c.exists():
            return c
    sys.exit("no release `cga` binary: cargo build --release -p cga-cli --bin cga, or --cga PATH")


def run_cga(cga, files, repeat, extra=()):
    js = subprocess.run(
        [str(cga), "ccd", "--repeat", str(repeat), *extra, "--json", *map(str, files)],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    per_file = [json.loads(line) for line in js.splitlines() if line.strip()]
    text = subprocess.run(
        [str(cga), "ccd", "--repeat", str(repeat), *extra, *map(str, files)],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    m = re.search(
        r"mean ([0-9.]+), median ([0-9.]+), max ([0-9.]+)", text.strip().splitlines()[-1]
    )
    timing = tuple(float(x) for x in m.groups()) if m else None
    return per_file, timing


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("paths", nargs="*", help="query files or folders (default: the fixtures)")
    ap.add_argument("--cga", help="path of the release `cga` binary")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--limit", type=int, help="at most this many queries a file (quick runs)")
    ap.add_argument("--conservative-rescaling", type=float, default=1.0)
    ap.add_argument("--no-cga", action="store_true", help="only run Tight Inclusion")
    args = ap.parse_args()

    files = files_from(args.paths)
    ipctk.set_logger_level(ipctk.LoggerLevel.error)  # no "initial distance 0" warnings
    ti = ipctk.TightInclusionCCD(
        tolerance=1e-6,
        max_iterations=1_000_000,
        conservative_rescaling=args.conservative_rescaling,
    )
    print(f"ipctk {getattr(ipctk, '__version__', '?')}, conservative_rescaling {args.conservative_rescaling}")

    # Python call overhead: a far-apart query (unit boxes 100 apart) and a no-op with 8 arrays.
    far = [np.array(v, dtype=np.float64) for v in
           [[0, 0, 0], [100, 0, 0], [100, 1, 0], [101, 0, 0],
            [0, 0, 1], [100, 0, 1], [100, 1, 1], [101, 0, 1]]]

    def noop(*_a):
        return (False, 1.0)

    def overhead(fn):
        return statistics.median(time_call(fn, far, 1)[1] for _ in range(20001))

    far_vf = overhead(ti.point_triangle_ccd)
    far_ee = overhead(ti.edge_edge_ccd)
    noop_us = overhead(noop)

    ti_micros, ti_net, ti_net_noop, fp, fn_, n_truth, n = [], [], [], 0, 0, 0, 0
    ti_answers = {}
    slowest = (0.0, None)
    t_start = time.time()
    for path in files:
        kind = kind_of(path)
        queries = load(path)
        if args.limit:
            queries = queries[: args.limit]
        call = ti.point_triangle_ccd if kind == "vertex-face" else ti.edge_edge_ccd
        base = far_vf if kind == "vertex-face" else far_ee
        answers = []
        for i, (pts, truth) in enumerate(queries):
            arrays = [np.ascontiguousarray(pts[k]) for k in range(8)]
            (hit, _toi), us = time_call(lambda *a: call(*a, 0.0, 1.0), arrays, args.repeat)
            answers.append(bool(hit))
            ti_micros.append(us)
            ti_net.append(max(us - base, 0.0))
            ti_net_noop.append(max(us - noop_us, 0.0))
            if us > slowest[0]:
                slowest = (us, f"{path}#{i}")
            n += 1
            if truth is not None:
                n_truth += 1
                fp += bool(hit) and not truth
                fn_ += (not hit) and truth
        ti_answers[str(path)] = answers
    ti_wall = time.time() - t_start

    print(f"{len(files)} files, {n} queries ({n_truth} with truth); TI wall time {ti_wall:.1f} s")
    print(
        f"Python call overhead (median of 20001): far-apart vertex-face {far_vf:.2f} µs, "
        f"edge-edge {far_ee:.2f} µs; no-op with 8 arrays {noop_us:.2f} µs"
    )
    print(f"TI slowest query: {slowest[1]} ({slowest[0]:.0f} µs)")

    rows = []
    ti_mean, ti_med, ti_max = summary(ti_micros)
    tn_mean, tn_med, tn_max = summary(ti_net)
    rows.append(("Tight Inclusion (ipctk, with Python call)", fp, fn_, ti_mean, ti_med, ti_max))
    rows.append(("Tight Inclusion, net of far-apart call", fp, fn_, tn_mean, tn_med, tn_max))
    rows.append(("Tight Inclusion, net of no-op call", fp, fn_, *summary(ti_net_noop)))

    if not args.no_cga and not args.limit:
        cga = find_cga(args.cga)
        per_file, timing = run_cga(cga, files, args.repeat)
        cfp = sum(f.get("false_positives", 0) for f in per_file)
        cfn = sum(f.get("false_negatives", 0) for f in per_file)
        disagree = sum(
            a != b
            for f in per_file
            for a, b in zip(f["answers"], ti_answers.get(f["file"], []))
        )
        mean, med, mx = timing
        # Like for like with TI's time of impact: our earliest contact time to the same 1e-6.
        toi_files, toi_timing = run_cga(cga, files, args.repeat, ("--first-contact", "--tolerance", "1e-6"))
        same = all(f["answers"] == g["answers"] for f, g in zip(per_file, toi_files))
        rows.insert(0, ("cga ccd --first-contact (exact, toi to 1e-6)", cfp, cfn, *toi_timing))
        rows.insert(0, ("cga ccd (exact, yes/no only)", cfp, cfn, mean, med, mx))
        print(f"cga ccd: {cga}; answers differing from TI's: {disagree}; "
              f"--first-contact gives the same answers: {same}")
    elif args.limit:
        print("(--limit: cga ccd is not run, it reads whole files)")

    print()
    head = f"| {'method':44} | {'FP':>4} | {'FN':>3} | {'mean µs':>9} | {'median µs':>9} | {'max µs':>10} |"
    print(head)
    print("|" + "|".join("-" * (len(c)) for c in head.split("|")[1:-1]) + "|")
    for name, a, b, mean, med, mx in rows:
        print(f"| {name:44} | {a:>4} | {b:>3} | {mean:>9.2f} | {med:>9.2f} | {mx:>10.1f} |")
    if rows[0][0].startswith("cga"):
        ours = rows[1]  # the first-contact row: the same work as TI's
        print()
        for r in rows[2:]:
            print(
                f"ours / {r[0]}: mean {ours[3] / r[3]:.3f}, median {ours[4] / r[4]:.3f}, "
                f"max {ours[5] / r[5]:.3f}"
            )


if __name__ == "__main__":
    main()

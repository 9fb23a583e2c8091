#!/usr/bin/env python3
"""A Markdown table from the JSON lines of coal_shapes.py, fcl_shapes.sh and `cga shapes`
(the lines of each, concatenated, in any order), one row per pair type.

Per peer ("who": cga native, cga-py from Python, coal from Python, fcl) and family: µs per
pair test (median over the pair type's pairs; for the Python sides the call cost is shown
under the table, and the time net of it in brackets) and,
for the near-contact family, wrong answers as "wrong/pairs" (false collisions + missed; in
brackets the wrong answers among pairs whose peer input is exactly the same solid). Lines of
`cga shapes` ({"file", "pairs", "answers", "micros_mean", ...}) are placed by their file
name (FAMILY/A-B.jsonl) with "who": "cga", their time is micros_median (else micros_mean), and their answers are
checked against the file's `expected` when the file is still there.

Usage: python3 shape_table.py RESULTS.jsonl... [--families generic,near_contact] [--times]
--times: the time columns only, with ours' (native) near-contact time over its generic time.
"""
import argparse
import json
import os
import sys


def rows_of(paths):
    for path in paths:
        with open(path) as f:
            for text in f:
                text = text.strip()
                if not text.startswith("{"):
                    continue
                d = json.loads(text)
                if "who" not in d and "file" in d:  # a `cga shapes` line
                    family = os.path.basename(os.path.dirname(d["file"]))
                    pair = os.path.basename(d["file"]).removesuffix(".jsonl")
                    d = {"who": "cga", "pair": pair, "family": family, "pairs": d["pairs"],
                         "micros_median": d.get("micros_median", d.get("micros_mean")),
                         "micros_call_cost": None,
                         "wrong": wrong_against_file(d["file"], d.get("answers"))}
                yield d


def wrong_against_file(path, answers):
    """Wrong answers of `cga shapes` against the file's `expected` (None if unreadable)."""
    if answers is None or not os.path.exists(path):
        return None
    with open(path) as f:
        expected = [json.loads(t).get("expected") for t in f if t.strip()]
    if len(expected) != len(answers):
        return None
    return sum(1 for e, a in zip(expected, answers) if e is not None and e != a)


def cell_time(d):
    if d is None or d.get("micros_median") is None:
        return "n/a"
    t = f"{d['micros_median']:.2f}"
    if d.get("micros_net") is not None and d["who"] in ("coal", "cga-py"):
        t += f" ({d['micros_net']:.2f})"
    return t


def cell_wrong(d):
    if d is None:
        return "n/a"
    if d.get("wrong") is None:
        return "?"
    w = f"{d['wrong']}/{d['pairs']}"
    if "wrong_exact_input" in d:
        w += f" [{d['wrong_exact_input']}/{d['exact_input_pairs']}]"
    if d.get("errors"):
        w += f", {d['errors']} errors"
    return w


def main():
    ap = argparse.ArgumentParser(description="Markdown table of the shape benchmarks")
    ap.add_argument("files", nargs="+")
    ap.add_argument("--families", default="generic,near_contact")
    ap.add_argument("--times", action="store_true",
                    help="time columns only, and ours' near-contact/generic ratio")
    args = ap.parse_args()
    families = args.families.split(",")
    data, costs = {}, {}
    for d in rows_of(args.files):
        data[(d["who"], d["pair"], d["family"])] = d
        if d.get("micros_call_cost") is not None:
            costs.setdefault(d["who"], []).append(d["micros_call_cost"])
    whos = [w for w in ("cga", "cga-py", "coal", "fcl") if any(k[0] == w for k in data)]
    pairs = sorted({k[1] for k in data})
    head = ["pair"]
    for fam in families:
        for w in whos:
            head.append(f"{w} µs {fam}")
        if not args.times:
            for w in whos:
                head.append(f"{w} wrong {fam}")
    if args.times and "cga" in whos and len(families) > 1:
        head.append(f"cga {families[1]} / {families[0]}")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for pair in pairs:
        row = [pair]
        for fam in families:
            row += [cell_time(data.get((w, pair, fam))) for w in whos]
            if not args.times:
                row += [cell_wrong(data.get((w, pair, fam))) for w in whos]
        if args.times and "cga" in whos and len(families) > 1:
            g, n = (data.get(("cga", pair, f)) for f in families[:2])
            ok = g and n and g.get("micros_median") and n.get("micros_median") is not None
            row.append(f"{n['micros_median'] / g['micros_median']:.1f}×" if ok else "n/a")
        print("| " + " | ".join(row) + " |")
    print()
    for fam in families:
        for w in whos:
            ds = [d for k, d in data.items() if k[0] == w and k[2] == fam]
            if ds and all(d.get("wrong") is not None for d in ds):
                print(f"- {w}, {fam}: {sum(d['wrong'] for d in ds)} wrong of "
                      f"{sum(d['pairs'] for d in ds)}" +
                      (f" ({sum(d['wrong_exact_input'] for d in ds)} of "
                       f"{sum(d['exact_input_pairs'] for d in ds)} on exact inputs)"
                       if all("wrong_exact_input" in d for d in ds) else ""))
    for w, c in costs.items():
        print(f"- {w} call cost (two far spheres, same calling shape; per pair type "
              f"{min(c):.2f} to {max(c):.2f} µs)"
              + (f"; {w}'s net time (pair minus the call cost timed next to it) in brackets"
                 if w in ("coal", "cga-py") else ""))


if __name__ == "__main__":
    sys.exit(main())

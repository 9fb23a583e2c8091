#!/usr/bin/env python3
"""Markdown tables for the CGAL demo-mesh comparison (written by benches/demo_meshes.sh).

Usage: python3 demo_meshes_table.py OUT_DIR [--meshes DIR ...] [--summary]

OUT_DIR holds what demo_meshes.sh wrote:
  ours_self.jsonl, cgal_self.jsonl     one JSON line per mesh (self-intersection)
  ours_pair.jsonl, cgal_pair.jsonl     one JSON line per mesh-mesh item
  {ours,cgal}/self/<mesh>.pairs        the self-intersecting pairs, `i j` a line, sorted
  {ours,cgal}/pair/<a>__<b>.pairs      the mesh-mesh pairs

Pair sets are compared item by item. For meshes one side triangulated (polygon faces), the two
triangulations differ, so only the counts are compared. When the sets of a triangle mesh
differ and its OFF file is found in a --meshes directory, every differing pair is classified:
  duplicate position (a pair only CGAL reports): the two faces share a vertex position under
    different vertex indices (an unwelded mesh; this library shares by position, CGAL by
    vertex index, so CGAL reports faces that merely touch there);
  degenerate face (a pair only this library reports): one face has collinear corners (CGAL
    reports such a face f only as (f, f) and tests it against nothing else; this library
    tests it as the segment it is);
  unexplained: anything else (printed loudly). The classes say what the difference is
    consistent with; they do not re-decide the pair.
--summary prints only the totals, the problems and the 15 worst ratios.
Standard library only.
"""

import json
import os
import sys
from fractions import Fraction


def read_jsonl(path):
    out = []
    if not os.path.exists(path):
        return out
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("{"):
                out.append(json.loads(line))
    return out


def read_pairs(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return {tuple(map(int, line.split())) for line in f if line.strip()}


def read_off(path):
    """Vertices (float triples) and faces (index lists) of an OFF file, or None."""
    try:
        with open(path) as f:
            lines = [ln.split("#")[0].split() for ln in f]
    except OSError:
        return None
    lines = [ln for ln in lines if ln]
    if not lines or not lines[0][0].endswith("OFF"):
        return None
    if len(lines[0]) >= 3:
        counts, k = lines[0][1:], 1
    else:
        counts, k = lines[1], 2
    nv, nf = int(counts[0]), int(counts[1])
    verts = [tuple(float(x) for x in lines[k + i][:3]) for i in range(nv)]
    faces = []
    for i in range(nf):
        ln = lines[k + nv + i]
        n = int(ln[0])
        faces.append([int(x) for x in ln[1 : 1 + n]])
    return verts, faces


def collinear(p, q, r):
    """Exact collinearity of three float points."""
    p, q, r = ([Fraction(c) for c in v] for v in (p, q, r))
    u = [q[i] - p[i] for i in range(3)]
    w = [r[i] - p[i] for i in range(3)]
    return (
        u[1] * w[2] - u[2] * w[1] == 0
        and u[2] * w[0] - u[0] * w[2] == 0
        and u[0] * w[1] - u[1] * w[0] == 0
    )


def classify(mesh, only_ours, only_cgal):
    """Counts of differing pairs by cause (see the module docs). A pair only CGAL reports is
    explained by a duplicate position, one only this library reports by a degenerate face."""
    verts, faces = mesh
    degenerate = {}

    def is_degenerate(f):
        if f not in degenerate:
            c = [verts[x] for x in faces[f]]
            degenerate[f] = len(c) == 3 and collinear(*c)
        return degenerate[f]

    counts = {}

    def add(key):
        counts[key] = counts.get(key, 0) + 1

    for i, j in only_cgal:
        fi, fj = faces[i], faces[j]
        shared_pos = {verts[x] for x in fi} & {verts[x] for x in fj}
        if len(shared_pos) > len(set(fi) & set(fj)):
            add("duplicate position")
        else:
            add("unexplained, only CGAL")
    for i, j in only_ours:
        if is_degenerate(i) or is_degenerate(j):
            add("degenerate face")
        else:
            add("unexplained, only here")
    return counts


def fmt_ms(x):
    if x is None:
        return "-"
    return f"{x:.3f}" if x < 10 else f"{x:.1f}"


def ratio(ours, cgal):
    if ours is None or cgal is None or cgal <= 0:
        return None
    return ours / cgal


def fmt_ratio(r):
    return "-" if r is None else f"{r:.2f}"


def main(argv):
    args = [a for a in argv[1:]]
    summary = "--summary" in args
    mesh_dirs = []
    rest = []
    i = 0
    while i < len(args):
        if args[i] == "--summary":
            pass
        elif args[i] == "--meshes":
            i += 1
            mesh_dirs.append(args[i])
        else:
            rest.append(args[i])
        i += 1
    if len(rest) != 1:
        sys.exit(__doc__)
    out = rest[0]

    def find_mesh(name):
        for d in mesh_dirs:
            p = os.path.join(d, name)
            if os.path.exists(p) and name.lower().endswith(".off"):
                return read_off(p)
        return None

    ours = {d["mesh"]: d for d in read_jsonl(os.path.join(out, "ours_self.jsonl"))}
    cgal = {d["mesh"]: d for d in read_jsonl(os.path.join(out, "cgal_self.jsonl"))}
    names = sorted(set(ours) | set(cgal))
    rows, errors, problems = [], [], []
    for name in names:
        o, c = ours.get(name, {"error": "no result"}), cgal.get(name, {"error": "no result"})
        if "error" in o or "error" in c:
            errors.append((name, o.get("error"), c.get("error")))
            continue
        triangulated = o.get("triangulated") or c.get("triangulated")
        po = read_pairs(os.path.join(out, "ours", "self", name + ".pairs"))
        pc = read_pairs(os.path.join(out, "cgal", "self", name + ".pairs"))
        if triangulated:
            same = "counts " + ("equal" if o["pairs"] == c["pairs"] else "differ") + " (triangulated)"
            if o["pairs"] != c["pairs"]:
                problems.append(
                    f"triangulated (different triangulations, counts only): {name}: "
                    f"{o['pairs']} pairs here, {c['pairs']} in CGAL"
                )
        elif o["triangles"] != c["triangles"]:
            same = "NO: triangle counts differ"
            problems.append(f"{name}: {o['triangles']} triangles here, {c['triangles']} in CGAL")
        elif po is None or pc is None:
            same = "NO: pair file missing"
            problems.append(f"{name}: pair file missing")
        elif po == pc:
            same = "yes"
        else:
            only_o, only_c = po - pc, pc - po
            mesh = find_mesh(name)
            causes = classify(mesh, only_o, only_c) if mesh else {"unexplained (file not parsed)": 1}
            explained = not any(k.startswith("unexplained") for k in causes)
            what = ", ".join(f"{k}: {v}" for k, v in causes.items()) if mesh else "not classified"
            same = f"no (+{len(only_o)} here, +{len(only_c)} CGAL; {what})"
            msg = f"{name}: {len(only_o)} pairs only here, {len(only_c)} only in CGAL ({what})"
            if explained:
                problems.append("explained mismatch: " + msg)
            else:
                problems.append("!!! UNEXPLAINED MISMATCH: " + msg)
                print("!!! UNEXPLAINED PAIR MISMATCH: " + msg, file=sys.stderr)
        if c.get("file_order") is False:
            same += "; CGAL's face order is not the file's"
            problems.append(f"!!! {name}: CGAL's face k is not polygon k of the file (indices not comparable)")
        if c.get("degenerate"):
            same += f"; CGAL: {c['degenerate']} degenerate faces"
        rows.append(
            {
                "name": name,
                "triangles": o["triangles"],
                "pairs_o": o["pairs"],
                "pairs_c": c["pairs"],
                "ours": o["best_ms"],
                "build": o.get("build_ms"),
                "cgal": c["best_ms"],
                "ratio": ratio(o["best_ms"], c["best_ms"]),
                "same": same,
            }
        )
    rows.sort(key=lambda r: -r["cgal"])

    # Mesh-mesh items.
    pour = read_jsonl(os.path.join(out, "ours_pair.jsonl"))
    pcg = {(d["a"], d["b"]): d for d in read_jsonl(os.path.join(out, "cgal_pair.jsonl"))}
    prow = []
    for o in pour:
        key = (o["a"], o["b"])
        c = pcg.get(key, {"error": "no result"})
        if "error" in o or "error" in c:
            errors.append((f"{key[0]} x {key[1]}", o.get("error"), c.get("error")))
            continue
        fname = f"{key[0]}__{key[1]}.pairs"
        po = read_pairs(os.path.join(out, "ours", "pair", fname))
        pc = read_pairs(os.path.join(out, "cgal", "pair", fname))
        if c.get("triangulated"):
            same = "counts " + ("equal" if o["pairs"] == c["pairs"] else "differ") + " (triangulated)"
        elif po is not None and po == pc:
            same = "yes"
        else:
            n_o = len(po - pc) if po is not None and pc is not None else "?"
            n_c = len(pc - po) if po is not None and pc is not None else "?"
            same = f"NO (+{n_o} here, +{n_c} CGAL)"
            msg = f"{key[0]} x {key[1]}: {o['pairs']} pairs here, {c['pairs']} in CGAL"
            problems.append("!!! MESH-MESH MISMATCH: " + msg)
            print("!!! MESH-MESH PAIR MISMATCH: " + msg, file=sys.stderr)
        prow.append((key, o, c, same))

    # Totals.
    so = sum(r["ours"] for r in rows)
    sc = sum(r["cgal"] for r in rows)
    rated = [r for r in rows if r["ratio"] is not None]
    worst = max(rated, key=lambda r: r["ratio"]) if rated else None
    big = [r for r in rated if r["cgal"] >= 1.0]
    worst_big = max(big, key=lambda r: r["ratio"]) if big else None
    slow = [r for r in rated if r["ratio"] > 1.5]
    same_n = sum(1 for r in rows if r["same"].startswith("yes"))

    print("## Self-intersection, one thread: totals\n")
    print("| | value |")
    print("|---|---|")
    print(f"| meshes timed by both | {len(rows)} (pair sets identical: {same_n}) |")
    print(f"| sum of best times, this library | {so:.1f} ms |")
    print(f"| sum of best times, CGAL | {sc:.1f} ms |")
    print(f"| total ratio (ours / CGAL) | {fmt_ratio(ratio(so, sc))} |")
    if worst:
        print(
            f"| worst ratio | {worst['ratio']:.2f} ({worst['name']}, "
            f"{fmt_ms(worst['ours'])} vs {fmt_ms(worst['cgal'])} ms) |"
        )
    if worst_big:
        print(
            f"| worst ratio where CGAL takes >= 1 ms | {worst_big['ratio']:.2f} "
            f"({worst_big['name']}, {fmt_ms(worst_big['ours'])} vs {fmt_ms(worst_big['cgal'])} ms) |"
        )
    print(f"| meshes slower than 1.5x CGAL | {len(slow)} ({sum(1 for r in slow if r['cgal'] >= 1.0)} where CGAL takes >= 1 ms) |")
    if prow:
        po_sum = sum(o["best_ms"] for _, o, _, _ in prow)
        pc_sum = sum(c["best_ms"] for _, _, c, _ in prow)
        print(
            f"| mesh-mesh items: sum ours / sum CGAL | {po_sum:.1f} / {pc_sum:.1f} ms "
            f"(ratio {fmt_ratio(ratio(po_sum, pc_sum))}) |"
        )
    print()

    if errors:
        print("## Not compared (a side could not read the mesh)\n")
        print("| item | this library | CGAL |")
        print("|---|---|---|")
        for name, eo, ec in errors:
            print(f"| {name} | {eo or 'ok'} | {ec or 'ok'} |")
        print()
    if problems:
        print("## Pair differences\n")
        for p in problems:
            print(f"- {p}")
        print()

    if summary:
        print("## 15 worst ratios\n")
        print("| mesh | triangles | ours ms | CGAL ms | ours/CGAL |")
        print("|---|---:|---:|---:|---:|")
        for r in sorted(rated, key=lambda r: -r["ratio"])[:15]:
            print(f"| {r['name']} | {r['triangles']} | {fmt_ms(r['ours'])} | {fmt_ms(r['cgal'])} | {r['ratio']:.2f} |")
        return

    print("## Self-intersection per mesh (best times, one thread; sorted by CGAL time)\n")
    print("| mesh | triangles | pairs (ours / CGAL) | ours ms (build) | CGAL ms | ours/CGAL | same pairs |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for r in rows:
        pairs = str(r["pairs_o"]) if r["pairs_o"] == r["pairs_c"] else f"{r['pairs_o']} / {r['pairs_c']}"
        print(
            f"| {r['name']} | {r['triangles']} | {pairs} | {fmt_ms(r['ours'])} ({fmt_ms(r['build'])}) | "
            f"{fmt_ms(r['cgal'])} | {fmt_ratio(r['ratio'])} | {r['same']} |"
        )
    print()
    if prow:
        print("## Mesh against mesh (best times, one thread, builds included)\n")
        print("| A | B | triangles A / B | pairs | ours ms (build) | CGAL ms | ours/CGAL | same pairs |")
        print("|---|---|---:|---:|---:|---:|---:|---|")
        for (a, b), o, c, same in prow:
            pairs = str(o["pairs"]) if o["pairs"] == c["pairs"] else f"{o['pairs']} / {c['pairs']}"
            print(
                f"| {a} | {b} | {o['triangles_a']} / {o['triangles_b']} | {pairs} | "
                f"{fmt_ms(o['best_ms'])} ({fmt_ms(o.get('build_ms'))}) | {fmt_ms(c['best_ms'])} | "
                f"{fmt_ratio(ratio(o['best_ms'], c['best_ms']))} | {same} |"
            )
        print()


if __name__ == "__main__":
    main(sys.argv)

#!/usr/bin/env python3
"""The shapes of a `cga shapes` JSONL pair file as coal and FCL spell them, shared by
coal_shapes.py and fcl_shapes.sh.

Both peers take a shape in its own frame plus a rigid transform (R, t):
  Sphere(r); Box(2|U|, 2|V|, 2|W|) for a cuboid with orthogonal half axes (rotation from the
  normalised axes), else the convex hull of its 8 corners; Capsule / Cylinder / Cone(r, lz)
  centred at the axis midpoint with local z along the axis (the cone's apex at +lz/2 in both
  libraries); Halfspace(n / |n|, n.p / |n|) meaning {x : n.x <= d}; a convex hull as its hull
  vertices and outward triangles (scipy's qhull); TriangleP(p0, p1, p2); a segment as a
  capsule of radius 0.

`exact` says whether the peer's input describes exactly the solid of the JSON values: every
f64 handed over reproduces, in rational arithmetic, the JSON solid (R exactly orthonormal, the
axis ends / half axes / corners / plane exactly recovered, nothing dropped from a hull).
Where it is False the peer answers about a slightly different solid (the rounding of its own
API, e.g. a 45-degree rotation), so wrong answers are also counted on exact inputs only.

As a script: `python3 peer_shapes.py --fcl-text OUT FILE.jsonl...` writes the text format that
fcl_shapes.cpp reads (described there). Needs numpy and scipy.
"""
import argparse
import json
import os
import sys
from fractions import Fraction

import numpy as np
from scipy.spatial import ConvexHull

TYPES = ["ball", "cuboid", "capsule", "cylinder", "cone", "halfspace", "convex", "triangle",
         "segment"]


def F(x):
    return Fraction(float(x))


def exactly_orthonormal(rot):
    m = [[F(x) for x in row] for row in rot]
    for i in range(3):
        for j in range(3):
            dot = sum(m[k][i] * m[k][j] for k in range(3))
            if dot != (1 if i == j else 0):
                return False
    return True


def frame_with_z(axis):
    """A right-handed rotation whose third column is the unit axis; an exact signed
    permutation when the axis is a coordinate direction."""
    z = np.asarray(axis, dtype=float)
    nz = np.flatnonzero(z)
    if len(nz) == 1:
        k = int(nz[0])
        s = 1.0 if z[k] > 0 else -1.0
        e = np.eye(3)
        x, y = e[(k + 1) % 3], e[(k + 2) % 3] * s
        zz = e[k] * s
        return np.column_stack([x, y, zz])
    helper = np.eye(3)[int(np.argmin(np.abs(z)))]
    x = np.cross(helper, z)
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    return np.column_stack([x, y, z])


class Peer:
    """One shape as the peers take it: kind, parameters, rotation R, translation t, exact."""

    def __init__(self, kind, params, rot=None, t=None, exact=True, points=None, faces=None):
        self.kind, self.params = kind, params
        self.rot = np.eye(3) if rot is None else np.asarray(rot, dtype=float)
        self.t = np.zeros(3) if t is None else np.asarray(t, dtype=float)
        self.exact = exact
        self.points, self.faces = points, faces


def hull(points):
    """Hull vertices and outward triangles (indices into the vertices); exact when no input
    point was dropped. None for a flat or degenerate set."""
    pts = np.unique(np.asarray(points, dtype=float), axis=0)
    # qhull fails on huge or tiny magnitudes (its precision constants): run it on the points
    # scaled by a power of two, which is exact and keeps the hull's combinatorics.
    exponent = np.frexp(np.max(np.abs(pts)))[1] if np.any(pts) else 0
    try:
        h = ConvexHull(np.ldexp(pts, -int(exponent)))
    except Exception:  # qhull refuses flat sets
        return None
    keep = list(h.vertices)
    index = {v: i for i, v in enumerate(keep)}
    verts = pts[keep]
    inner = verts.mean(axis=0)
    faces = []
    for tri in h.simplices:
        a, b, c = (index[int(v)] for v in tri)
        n = np.cross(verts[b] - verts[a], verts[c] - verts[a])
        if n @ (inner - verts[a]) > 0:
            b, c = c, b
        faces.append((a, b, c))
    return verts, faces, len(keep) == len(pts)


def axial(kind, p_minus, p_plus, radius):
    """A capsule / cylinder / cone from its axis ends (p_plus is the cone's apex)."""
    a, b = np.asarray(p_minus, dtype=float), np.asarray(p_plus, dtype=float)
    u = b - a
    lz = float(np.linalg.norm(u))
    rot = frame_with_z(u / lz) if lz > 0 else np.eye(3)
    centre = (a + b) / 2
    exact = exactly_orthonormal(rot)
    if exact:
        for end, sign in ((a, -1), (b, 1)):
            for i in range(3):
                if F(centre[i]) + sign * F(rot[i, 2]) * F(lz) / 2 != F(end[i]):
                    exact = False
    return Peer(kind, [float(radius), lz], rot, centre, exact)


def convert(shape):
    (kind,) = shape.keys()
    s = shape[kind]
    if kind == "ball":
        return Peer("sphere", [float(s["radius"])], t=s["center"])
    if kind == "cuboid":
        c = np.asarray(s["center"], dtype=float)
        axes = [np.asarray(u, dtype=float) for u in s["half_axes"]]
        lengths = [float(np.linalg.norm(u)) for u in axes]
        orthogonal = all(abs(axes[i] @ axes[j]) <= 1e-12 * lengths[i] * lengths[j]
                         for i, j in ((0, 1), (0, 2), (1, 2))) and min(lengths) > 0
        if orthogonal:
            rot = np.column_stack([u / n for u, n in zip(axes, lengths)])
            if np.linalg.det(rot) < 0:  # the solid is symmetric: -W spans the same box
                rot[:, 2] = -rot[:, 2]
            exact = exactly_orthonormal(rot) and all(
                abs(F(rot[i, k]) * F(lengths[k])) == abs(F(axes[k][i]))
                for k in range(3) for i in range(3))
            return Peer("box", [2 * n for n in lengths], rot, c, exact)
        corners, exact = [], True
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                for s3 in (-1, 1):
                    p = c + s1 * axes[0] + s2 * axes[1] + s3 * axes[2]
                    exact &= all(F(p[i]) == F(c[i]) + s1 * F(axes[0][i]) + s2 * F(axes[1][i])
                                 + s3 * F(axes[2][i]) for i in range(3))
                    corners.append(p)
        return convex_peer(corners, exact)
    if kind in ("capsule", "cylinder"):
        return axial(kind, s["a"], s["b"], s["radius"])
    if kind == "segment":
        return axial("capsule", s["points"][0], s["points"][1], 0.0)
    if kind == "cone":
        return axial("cone", s["base"], s["apex"], s["radius"])
    if kind == "halfspace":
        n = np.asarray(s["normal"], dtype=float)
        p = np.asarray(s["point"], dtype=float)
        nn = n / np.linalg.norm(n)
        d = float(nn @ p)
        fn = [F(x) for x in nn]
        exact = (sum(x * x for x in fn) == 1
                 and all(fn[i] * F(n[j]) == fn[j] * F(n[i]) for i in range(3) for j in range(3))
                 and F(d) == sum(fn[i] * F(p[i]) for i in range(3)))
        return Peer("halfspace", [*nn, d], exact=exact)
    if kind == "convex":
        return convex_peer(s["points"], True)
    if kind == "triangle":
        return Peer("triangle", [float(x) for p in s["points"] for x in p])
    raise ValueError(f"unknown shape {kind!r}")


def convex_peer(points, exact):
    h = hull(points)
    if h is None:
        return Peer("unsupported", [], exact=False)
    verts, faces, complete = h
    return Peer("convex", [], exact=exact and complete, points=verts, faces=faces)


def pair_type(line):
    kinds = sorted((next(iter(line["a"])), next(iter(line["b"]))), key=TYPES.index)
    return f"{kinds[0]}-{kinds[1]}"


def read_pairs(paths):
    """(pair type, family, expected or None, case, a, b) for every line of the files; the
    family is the line's own, else the name of the file's folder."""
    for path in paths:
        folder = os.path.basename(os.path.dirname(os.path.abspath(path)))
        with open(path) as f:
            for number, text in enumerate(f, 1):
                if not text.strip():
                    continue
                try:
                    line = json.loads(text)
                    yield (pair_type(line), line.get("family", folder), line.get("expected"),
                           line.get("case", ""), line["a"], line["b"])
                except (KeyError, ValueError, StopIteration) as e:
                    raise SystemExit(f"{path}:{number}: {e}")


def group_summary(who, rows):
    """One output dict per (pair type, family) from rows of (pair, family, expected, answer
    or None on error, micros, exact input, call cost micros timed next to the pair)."""
    groups = {}
    for row in rows:
        groups.setdefault((row[0], row[1]), []).append(row)

    def median(xs):
        return round(float(np.median(xs)), 4) if xs else None

    out = []
    for (pair, family), rs in sorted(groups.items()):
        timed = [r for r in rs if r[4] is not None]
        judged = [r for r in rs if r[2] is not None and r[3] is not None]
        false_col = sum(1 for r in judged if r[3] and not r[2])
        missed = sum(1 for r in judged if r[2] and not r[3])
        out.append({
            "who": who, "pair": pair, "family": family, "pairs": len(rs),
            "micros_median": median([r[4] for r in timed]),
            "micros_call_cost": median([r[6] for r in timed]),
            "micros_net": median([r[4] - r[6] for r in timed]),
            "wrong": false_col + missed, "false_collisions": false_col, "missed": missed,
            "exact_input_pairs": sum(1 for r in rs if r[5]),
            "wrong_exact_input": sum(1 for r in judged if r[5] and r[3] != r[2]),
            "errors": sum(1 for r in rs if r[3] is None)})
    return out


def fmt(x):
    return repr(float(x))


def fcl_text(peer):
    """One shape line: KIND PARAMS... R(9, row-major) t(3)."""
    words = [peer.kind]
    if peer.kind == "convex":
        words += [str(len(peer.points)), str(len(peer.faces))]
        words += [fmt(x) for p in peer.points for x in p]
        words += [str(i) for f in peer.faces for i in f]
    else:
        words += [fmt(x) for x in peer.params]
    words += [fmt(x) for x in peer.rot.reshape(-1)] + [fmt(x) for x in peer.t]
    return " ".join(words)


def main():
    ap = argparse.ArgumentParser(description="write fcl_shapes.cpp's input")
    ap.add_argument("--fcl-text", required=True, help="output file")
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    with open(args.fcl_text, "w") as out:
        for pair, family, expected, case, a, b in read_pairs(args.files):
            pa, pb = convert(a), convert(b)
            exp = -1 if expected is None else int(bool(expected))
            out.write(f"PAIR {pair} {family} {exp} {int(pa.exact and pb.exact)}\n")
            out.write(fcl_text(pa) + "\n" + fcl_text(pb) + "\n")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Write the primitive pair sets for the shape benchmarks (ours: `cga shapes`; peers:
coal_shapes.py and fcl_shapes.sh), one JSONL file per pair type and family.

Each line is `{"a": SHAPE, "b": SHAPE, "expected": bool, "family": ..., "case": ...}` with
SHAPE spelled as `cga shapes` reads it (ball center/radius, cuboid center/half_axes, capsule
a/b/radius, cylinder a/b/radius, cone apex/base/radius, halfspace point/normal, convex
points, triangle points). `a` is the shape whose type comes first in TYPES, so every line of
a file has the same pair type. Every number is written with Python's repr, which reads back
to the same f64; the shapes mean the exact real values of those f64.

Two families, written to OUT/generic/A-B.jsonl and OUT/near_contact/A-B.jsonl:

generic       random sizes, orientations and positions, half intersecting, half not.
              `expected` comes from a floating-point certificate with a wide margin
              (shape_pairs_generic.py: a separating direction with gap >= 1e-7, or a point
              inside both shapes by 1e-7, far above the rounding error of the check); the
              few draws no certificate decides are dropped and drawn again (so no generic
              pair is closer to touching than about 1e-7).
near_contact  configurations whose truth is known by construction (see the comment above
              `dyadic`): a lower and an upper shape exactly touching at z = 1 (face, edge or
              vertex of a box, a cylinder's cap, side or rim, a cone's apex, base or rim, a
              capsule's end or side, a plane, hull faces and vertices, triangles flat, on an
              edge or on a vertex; every pair of these features), and a ball on a cone's rim;
              each exactly touching (touching counts as intersecting), then the upper shape
              moved by k ulps toward (intersecting) and away (disjoint), k = 1, 2, 4.

near_contact_scaled (only with --scaled E1,E2,...) the near-contact lines scaled by 2^E, exact,
              so the same truth at other magnitudes (written to OUT/near_contact_scaled/).

--check N re-decides N near-contact lines per polytopal pair type (cuboid, convex, triangle,
half-space, and ball against half-space) with an independent exact test in rationals and
fails on any disagreement.

Needs numpy only. Fixed seed: the same files on every run (--scaled and --check do not change
the other files).
Usage: python3 shape_pairs.py [-o OUT] [--generic N] [--near-per-type N] [--seed S]
                              [--scaled E1,E2,...] [--check N]
"""
import argparse
import itertools
import json
import math
import os
import sys
from fractions import Fraction

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shape_pairs_generic import generic  # noqa: E402

TYPES = ["ball", "cuboid", "capsule", "cylinder", "cone", "halfspace", "convex", "triangle"]
MOVES = (1, 2, 4)  # k ulps


def pair_name(a, b):
    return f"{a}-{b}"


def shape_type(shape):
    (kind,) = shape.keys()
    return kind


# ---- exact helpers (Fractions of the f64 values: the shapes' exact semantics) ------------

def F(x):
    return Fraction(float(x))


def exact_sum(x, y):
    """x + y in f64, refused unless the f64 sum is exact (constructions stay exact)."""
    s = float(x) + float(y)
    if F(s) != F(x) + F(y):
        raise AssertionError(f"inexact sum {x!r} + {y!r}")
    return s


def rational_sqrt(q):
    """sqrt of a non-negative Fraction when it is rational, else None."""
    n, d = q.numerator, q.denominator
    rn, rd = math.isqrt(n), math.isqrt(d)
    if rn * rn == n and rd * rd == d:
        return Fraction(rn, rd)
    return None


def z_extent(shape):
    """(min z, max z) of the solid, exactly (Fractions; +-inf for unbounded half-spaces).
    Only for the shapes built in `near_contact`, whose extents are rational."""
    kind = shape_type(shape)
    s = shape[kind]
    if kind == "ball":
        z, r = F(s["center"][2]), F(s["radius"])
        return z - r, z + r
    if kind == "cuboid":
        z = F(s["center"][2])
        e = sum(abs(F(u[2])) for u in s["half_axes"])
        return z - e, z + e
    if kind in ("convex", "triangle", "segment"):
        zs = [F(p[2]) for p in s["points"]]
        return min(zs), max(zs)
    if kind == "halfspace":
        n = [F(c) for c in s["normal"]]
        if n[0] != 0 or n[1] != 0:
            return -math.inf, math.inf
        pz = F(s["point"][2])
        return (-math.inf, pz) if n[2] > 0 else (pz, math.inf)
    if kind == "capsule":
        za, zb, r = F(s["a"][2]), F(s["b"][2]), F(s["radius"])
        return min(za, zb) - r, max(za, zb) + r
    # Cylinder and cone: a disc of radius r perpendicular to the axis u spans
    # r * sqrt(ux^2 + uy^2) / |u| in z on each side of its centre.
    if kind == "cylinder":
        p, q = s["a"], s["b"]
        discs = [p, q]
    else:  # cone
        p, q = s["base"], s["apex"]
        discs = [p]
    u = [F(q[i]) - F(p[i]) for i in range(3)]
    ratio = rational_sqrt((u[0] ** 2 + u[1] ** 2) / (u[0] ** 2 + u[1] ** 2 + u[2] ** 2))
    assert ratio is not None, "the construction keeps the disc's z extent rational"
    spread = F(s["radius"]) * ratio
    lo = [F(c[2]) - spread for c in discs]
    hi = [F(c[2]) + spread for c in discs]
    if kind == "cone":
        lo.append(F(s["apex"][2]))
        hi.append(F(s["apex"][2]))
    return min(lo), max(hi)


def map_points(shape, f, g=None):
    """A copy of shape with f applied to every point and g to every direction (half axes,
    normals); radii unchanged."""
    g = g or f
    kind = shape_type(shape)
    s = dict(shape[kind])
    for key in ("center", "a", "b", "apex", "base", "point"):
        if key in s:
            s[key] = f(s[key])
    if "points" in s:
        s["points"] = [f(p) for p in s["points"]]
    if "half_axes" in s:
        s["half_axes"] = [g(u) for u in s["half_axes"]]
    if "normal" in s:
        s["normal"] = g(s["normal"])
    return {kind: s}


def place(local, x0, y0, z0, up):
    """The local shape (its contact feature at the origin, the solid in z >= 0) turned upside
    down when not `up` (z -> -z, exact), then translated by (x0, y0, z0), every sum checked
    exact."""
    sign = 1.0 if up else -1.0

    def flip(v):
        return [float(v[0]), float(v[1]), sign * float(v[2])]

    def move(v):
        v = flip(v)
        return [exact_sum(v[0], x0), exact_sum(v[1], y0), exact_sum(v[2], z0)]

    return map_points(local, move, flip)


def shift_z(shape, dz):
    """The shape translated by dz along z (rigid: only points move, never half axes or
    normals), every coordinate checked exact."""
    return map_points(shape, lambda v: [v[0], v[1], exact_sum(v[2], dz)],
                      lambda v: [float(c) for c in v])


# ---- near-contact families ----------------------------------------------------------------
#
# Every stacked configuration is: a LOWER shape whose highest points (its top patch) are at
# z = 1 and an UPPER shape whose lowest points (its bottom patch) are at z = 1, both patches
# containing the point q = (x0, y0). Then the upper shape is translated by dz along z.
# Truth, exactly: if dz > 0 the plane z = 1 + dz/2 separates them (lower <= 1 < upper), so they
# are disjoint; if dz <= 0, the vertical line through q meets the lower solid in [lo, 1] and
# the upper one in [1 + dz, hi + dz], and these overlap because at least one of the two
# shapes has height at least |dz| at q: every shape built here except a flat horizontal
# triangle has the vertical direction inside its tangent cone at q (face interiors, the
# integer box edge and vertex, the tilted rims, hull vertices, vertical triangles' edges
# and vertices all open upward from q, for a height of the shapes' size, ~2^-7 or more,
# against |dz| <= 2^-50), and two flat triangles are never paired. So `expected` is
# min z(upper) <= max z(lower), which `z_extent` computes in exact rational arithmetic from
# the f64 values and which the builder checks against the intended value. Only plane-point and plane-plane facts are used: the
# extents are maxima of linear functions over the solids, rational for every shape built
# here (axis-aligned, integer-orthogonal or 3-4-5 tilted axes).
#
# All coordinates of an upper shape lie in [1, 2), where the f64 spacing is 2^-52, so moving
# it by dz = +-k * 2^-52 is exact (checked); "k ulps" is that spacing. The lower shape is
# never moved.

def dyadic(rng, lo, hi, bits=6):
    """A random multiple of 2^-bits in [lo, hi]: few significant bits, so sums stay exact."""
    step = 2.0 ** -bits
    return float(rng.integers(math.ceil(lo / step), math.floor(hi / step) + 1)) * step


def polygon_around_origin(rng, n, r_lo, r_hi):
    """n dyadic points roughly on a circle around the origin, in convex position, with the
    origin strictly inside (checked exactly)."""
    while True:
        start = rng.uniform(0, 2 * math.pi)
        pts = []
        for i in range(n):
            t = start + 2 * math.pi * i / n + rng.uniform(-0.3, 0.3) / n
            r = dyadic(rng, r_lo, r_hi)
            pts.append((round(r * math.cos(t) * 64) / 64, round(r * math.sin(t) * 64) / 64))
        ok = True
        for i in range(n):
            (ax, ay), (bx, by), (cx, cy) = pts[i], pts[(i + 1) % n], pts[(i + 2) % n]
            edge = F(bx - ax), F(by - ay)
            # origin strictly left of every edge, next vertex strictly left (convex, CCW)
            if edge[0] * (0 - F(ay)) - edge[1] * (0 - F(ax)) <= 0:
                ok = False
            if edge[0] * (F(cy) - F(ay)) - edge[1] * (F(cx) - F(ax)) <= 0:
                ok = False
        if ok:
            return pts


def local_variants():
    """name -> builder(rng) of a local shape: contact feature at the origin, solid in
    0 <= z < 1, every coordinate dyadic with few bits."""
    def ball(rng):
        r = dyadic(rng, 0.125, 0.45)
        return {"ball": {"center": [0.0, 0.0, r], "radius": r}}

    def cuboid_face(rng):
        a, b, c = dyadic(rng, 0.125, 0.5), dyadic(rng, 0.125, 0.5), dyadic(rng, 0.0625, 0.4)
        ox, oy = dyadic(rng, -a / 2, a / 2), dyadic(rng, -b / 2, b / 2)
        return {"cuboid": {"center": [ox, oy, c],
                           "half_axes": [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]]}}

    def cuboid_sheared(rng):  # non-orthogonal: the bottom face is still the plane z = 0
        a, b2, c = dyadic(rng, 0.125, 0.5), dyadic(rng, 0.125, 0.5), dyadic(rng, 0.0625, 0.4)
        b1, w1, w2 = dyadic(rng, -0.25, 0.25), dyadic(rng, -0.25, 0.25), dyadic(rng, -0.25, 0.25)
        return {"cuboid": {"center": [w1, w2, c],
                           "half_axes": [[a, 0.0, 0.0], [b1, b2, 0.0], [w1, w2, c]]}}

    def cuboid_edge(rng):  # an edge down: integer-orthogonal half axes turned 45 degrees
        a, h = dyadic(rng, 0.125, 0.5), dyadic(rng, 0.0625, 0.2)
        axes = [[a, 0.0, 0.0], [0.0, h, h], [0.0, -h, h]]
        if rng.random() < 0.5:  # the edge along y instead of x
            axes = [[u[1], u[0], u[2]] for u in axes]
        return {"cuboid": {"center": [0.0, 0.0, 2 * h], "half_axes": axes}}

    def cuboid_vertex(rng):  # a vertex down: rows of the rational rotation (1/3)[2 2 -1; ...]
        h = [dyadic(rng, 0.015625, 0.09375) for _ in range(3)]
        u = [[2 * h[0], 2 * h[0], -h[0]], [-h[1], 2 * h[1], 2 * h[1]], [2 * h[2], -h[2], 2 * h[2]]]
        # lowest vertex c + U - V - W (s_i = -sign(u_i z)) at the origin
        c = [-u[0][i] + u[1][i] + u[2][i] for i in range(3)]
        return {"cuboid": {"center": c, "half_axes": u}}

    def capsule_vertical(rng):
        r, length = dyadic(rng, 0.0625, 0.25), dyadic(rng, 0.0625, 0.4)
        return {"capsule": {"a": [0.0, 0.0, r], "b": [0.0, 0.0, r + length], "radius": r}}

    def lying(kind, axis):
        def build(rng):
            r = dyadic(rng, 0.0625, 0.3)
            l1, l2 = dyadic(rng, 0.0625, 0.5), dyadic(rng, 0.0625, 0.5)
            a, b = [0.0, 0.0, r], [0.0, 0.0, r]
            a[axis], b[axis] = -l1, l2
            return {kind: {"a": a, "b": b, "radius": r}}
        return build

    def cylinder_cap(rng):
        r, length = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.5)
        ox, oy = dyadic(rng, -r / 2, r / 2), dyadic(rng, -r / 2, r / 2)
        return {"cylinder": {"a": [ox, oy, 0.0], "b": [ox, oy, length], "radius": r}}

    def tilted_345(rng):
        """(rim point, disc centre, axis end) of a disc of radius 5 rho whose axis is
        (3, 0, 4) eta: its lowest point is the rim point c + 5 rho (4/5, 0, -3/5)."""
        # eta >= 2 rho keeps a cone's slant steeper than vertical at the rim point
        # (4 rho < 3 eta), so the vertical line through that point enters the solid.
        rho = dyadic(rng, 0.0078125, 0.0625, 7)
        eta = dyadic(rng, 2 * rho, 0.1875, 7)  # 3 rho + 4 eta < 1
        sx = 1.0 if rng.random() < 0.5 else -1.0
        centre = [-4 * rho * sx, 0.0, 3 * rho]
        end = [centre[0] + 3 * eta * sx, 0.0, centre[2] + 4 * eta]
        return 5 * rho, centre, end

    def cylinder_rim(rng):
        r, a, b = tilted_345(rng)
        return {"cylinder": {"a": a, "b": b, "radius": r}}

    def cone_apex(rng):
        r, length = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.5)
        return {"cone": {"apex": [0.0, 0.0, 0.0], "base": [0.0, 0.0, length], "radius": r}}

    def cone_base(rng):
        r, length = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.5)
        ox, oy = dyadic(rng, -r / 2, r / 2), dyadic(rng, -r / 2, r / 2)
        return {"cone": {"apex": [ox, oy, length], "base": [ox, oy, 0.0], "radius": r}}

    def cone_rim(rng):
        r, base, apex = tilted_345(rng)
        return {"cone": {"apex": apex, "base": base, "radius": r}}

    def halfspace(rng):  # {z >= 0}; normal not unit length in general
        m = [1.0, 2.0, 3.0, 0.5, 0.375][rng.integers(5)]
        return {"halfspace": {"point": [dyadic(rng, -1, 1), dyadic(rng, -1, 1), 0.0],
                              "normal": [0.0, 0.0, -m]}}

    def convex_box(rng):
        a1, a2, b1, b2 = (dyadic(rng, 0.0625, 0.4) for _ in range(4))
        c = dyadic(rng, 0.0625, 0.4)
        pts = [[x, y, z] for x in (-a1, a2) for y in (-b1, b2) for z in (0.0, c)]
        return {"convex": {"points": pts}}

    def convex_octahedron(rng):
        a1, a2, b1, b2 = (dyadic(rng, 0.0625, 0.4) for _ in range(4))
        h, h2 = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.4)
        pts = [[0.0, 0.0, 0.0], [-a1, 0.0, h], [a2, 0.0, h], [0.0, -b1, h], [0.0, b2, h],
               [0.0, 0.0, h + h2]]
        return {"convex": {"points": pts}}

    def convex_frustum(rng):  # a polygon face down, a smaller polygon on top
        bottom = polygon_around_origin(rng, int(rng.integers(3, 6)), 0.25, 0.5)
        top = polygon_around_origin(rng, int(rng.integers(3, 6)), 0.0625, 0.1875)
        h = dyadic(rng, 0.0625, 0.5)
        pts = [[x, y, 0.0] for x, y in bottom] + [[x, y, h] for x, y in top]
        return {"convex": {"points": pts}}

    def triangle_flat(rng):
        return {"triangle": {"points": [[x, y, 0.0] for x, y in
                                        polygon_around_origin(rng, 3, 0.125, 0.5)]}}

    def vertical_triangle(pts, rng):
        if rng.random() < 0.5:  # in the plane x = 0 instead of y = 0
            pts = [[p[1], p[0], p[2]] for p in pts]
        return {"triangle": {"points": pts}}

    def triangle_edge(rng):
        a, c, h = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.5)
        e = dyadic(rng, -a, c)
        return vertical_triangle([[-a, 0.0, 0.0], [c, 0.0, 0.0], [e, 0.0, h]], rng)

    def triangle_vertex(rng):
        a, c = dyadic(rng, 0.0625, 0.4), dyadic(rng, 0.0625, 0.4)
        h1, h2 = dyadic(rng, 0.0625, 0.5), dyadic(rng, 0.0625, 0.5)
        return vertical_triangle([[0.0, 0.0, 0.0], [-a, 0.0, h1], [c, 0.0, h2]], rng)

    return {
        "ball": {"ball": ball},
        "cuboid": {"face": cuboid_face, "sheared": cuboid_sheared, "edge": cuboid_edge,
                   "vertex": cuboid_vertex},
        "capsule": {"end": capsule_vertical, "lying_x": lying("capsule", 0),
                    "lying_y": lying("capsule", 1)},
        "cylinder": {"cap": cylinder_cap, "lying_x": lying("cylinder", 0),
                     "lying_y": lying("cylinder", 1), "rim": cylinder_rim},
        "cone": {"apex": cone_apex, "base": cone_base, "rim": cone_rim},
        "halfspace": {"plane": halfspace},
        "convex": {"box": convex_box, "octahedron": convex_octahedron, "frustum": convex_frustum},
        "triangle": {"flat": triangle_flat, "edge": triangle_edge, "vertex": triangle_vertex},
    }


def moves():
    """(label, dz, expected) for the exact contact and k ulps toward and away."""
    out = [("touching", 0.0, True)]
    for k in MOVES:
        up = 1.0
        for _ in range(k):
            up = float(np.nextafter(up, 2.0))
        dz = up - 1.0  # k ulps of [1, 2)
        out.append((f"toward_{k}ulp", -dz, True))
        out.append((f"away_{k}ulp", dz, False))
    return out


def ordered(lower_kind, lower, upper_kind, upper):
    """(a, b) in TYPES order."""
    if TYPES.index(lower_kind) <= TYPES.index(upper_kind):
        return lower, upper
    return upper, lower


def stacked_lines(rng, kind_lo, var_lo, build_lo, kind_up, var_up, build_up):
    x0, y0 = dyadic(rng, -4, 4), dyadic(rng, -4, 4)
    lower = place(build_lo(rng), x0, y0, 1.0, up=False)
    upper = place(build_up(rng), x0, y0, 1.0, up=True)
    _, top = z_extent(lower)
    bottom, _ = z_extent(upper)
    assert top == 1 and bottom == 1, (lower, upper)
    for label, dz, want in moves():
        moved = shift_z(upper, dz)
        truth = z_extent(moved)[0] <= z_extent(lower)[1]
        assert truth == want
        a, b = ordered(kind_lo, lower, kind_up, moved)
        yield {"a": a, "b": b, "expected": truth, "family": "near_contact",
               "case": f"{kind_lo}:{var_lo} under {kind_up}:{var_up}, {label}"}


def ball_on_cone_rim_lines(rng):
    """A ball resting on the rim of a cone whose base disc is on top (apex down): the cone
    lies in the vertical cylinder over its base disc and below the base plane, so for a
    centre above the plane and outside the rim the nearest point of the cone is the rim
    point, at squared distance (3s)^2 + (4s + dz)^2 from a centre put at horizontal
    distance R + 3s from the axis and height 4s + dz above the base; the ball of radius 5s
    touches at dz = 0. `expected` is that squared distance <= (5s)^2, in exact rationals."""
    x0, y0 = dyadic(rng, -4, 4), dyadic(rng, -4, 4)
    length = dyadic(rng, 0.125, 0.5)
    big_r = dyadic(rng, 0.0625, 0.4)
    # apex down, the base disc in the plane z = 1
    cone = place({"cone": {"apex": [0.0, 0.0, 0.0], "base": [0.0, 0.0, length],
                           "radius": big_r}}, x0, y0, 1.0 - length, up=True)
    base = cone["cone"]["base"]
    assert base[2] == 1.0
    s = dyadic(rng, 0.015625, 0.0625)
    direction = [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)][rng.integers(4)]
    off = big_r + 3 * s
    centre = [exact_sum(base[0], direction[0] * off), exact_sum(base[1], direction[1] * off),
              exact_sum(1.0, 4 * s)]
    ball = {"ball": {"center": centre, "radius": 5 * s}}
    for label, dz, want in moves():
        moved = shift_z(ball, dz)
        c = [F(x) for x in moved["ball"]["center"]]
        horiz = math.hypot(float(c[0] - F(base[0])), float(c[1] - F(base[1])))
        assert F(horiz) == F(big_r) + 3 * F(s)
        dist2 = (3 * F(s)) ** 2 + (c[2] - F(base[2])) ** 2
        truth = dist2 <= (5 * F(s)) ** 2
        assert truth == want
        yield {"a": moved, "b": cone, "expected": truth, "family": "near_contact",
               "case": f"ball on cone rim, {label}"}


def near_contact(rng, per_type):
    """pair name -> lines: every (lower variant, upper variant) of the pair's two types, in
    both roles, repeated with fresh random sizes until the pair type has at least per_type
    configurations (each gives 1 + 2 * len(MOVES) lines)."""
    variants = local_variants()
    out = {}
    for ka, kb in itertools.combinations_with_replacement(TYPES, 2):
        combos = []
        for lo_kind, up_kind in {(ka, kb), (kb, ka)}:
            for (vl, bl), (vu, bu) in itertools.product(variants[lo_kind].items(),
                                                        variants[up_kind].items()):
                if lo_kind == up_kind == "triangle" and vl == vu == "flat":
                    continue  # both of zero height at q: truth needs more than a plane
                combos.append((lo_kind, vl, bl, up_kind, vu, bu))
        combos.sort(key=lambda c: (c[0], c[1], c[3], c[4]))
        rounds = max(1, math.ceil(per_type / len(combos)))
        lines = []
        for _ in range(rounds):
            for combo in combos:
                lines.extend(stacked_lines(rng, *combo))
        if {ka, kb} == {"ball", "cone"}:
            for _ in range(max(1, per_type // 4)):
                lines.extend(ball_on_cone_rim_lines(rng))
        out[pair_name(ka, kb)] = lines
    return out


# ---- an independent exact check of the near-contact truth, for the polytopal pairs ----------

def exact_vertices(shape):
    """The solid's vertices as exact rationals (cuboid corners as exact sums), or None."""
    kind = shape_type(shape)
    s = shape[kind]
    if kind in ("convex", "triangle", "segment"):
        return [tuple(F(x) for x in p) for p in s["points"]]
    if kind == "cuboid":
        c = [F(x) for x in s["center"]]
        u = [[F(x) for x in v] for v in s["half_axes"]]
        return [tuple(c[i] + a * u[0][i] + b * u[1][i] + d * u[2][i] for i in range(3))
                for a in (-1, 1) for b in (-1, 1) for d in (-1, 1)]
    return None


def sub(p, q):
    return tuple(a - b for a, b in zip(p, q))


def dot(p, q):
    return sum(a * b for a, b in zip(p, q))


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def exact_truth(a, b):
    """Whether the solids meet, decided in rational arithmetic without the construction's
    reasoning: for two polytopes, the separating axis test over every difference of two
    vertices crossed with every other (a superset of the face normals and edge-edge axes, so
    disjoint exactly when one of them separates strictly; when both lie in parallel planes,
    also that normal crossed with every difference); for a half-space, the lowest
    vertex (or a ball's lowest point) against its plane. None for other pairs."""
    if shape_type(b) == "halfspace" and shape_type(a) != "halfspace":
        a, b = b, a
    if shape_type(a) == "halfspace":
        s = a["halfspace"]
        n, p = tuple(F(x) for x in s["normal"]), tuple(F(x) for x in s["point"])
        if shape_type(b) == "ball":
            c, r = tuple(F(x) for x in b["ball"]["center"]), F(b["ball"]["radius"])
            h = dot(sub(c, p), n)  # meets iff h <= r |n|
            return h <= 0 or h * h <= r * r * dot(n, n)
        verts = exact_vertices(b)
        if verts is None:
            return None
        return min(dot(sub(v, p), n) for v in verts) <= 0
    va, vb = exact_vertices(a), exact_vertices(b)
    if va is None or vb is None:
        return None
    diffs = {sub(p, q) for verts in (va, vb) for p in verts for q in verts if p != q}
    diffs = list(diffs)
    axes = [cross(d, e) for i, d in enumerate(diffs) for e in diffs[i + 1:]]
    axes = [x for x in axes if x != (0, 0, 0)]
    if all(cross(x, axes[0]) == (0, 0, 0) for x in axes):
        # both in parallel planes (A - B is flat): its edges' in-plane normals as well
        axes += [cross(axes[0], d) for d in diffs]
    for axis in axes:
        pa, pb = [dot(v, axis) for v in va], [dot(v, axis) for v in vb]
        if max(pa) < min(pb) or max(pb) < min(pa):
            return False
    return True


def check_near_contact(lines, sample, rng):
    """Re-decide up to `sample` polytopal lines with `exact_truth`; returns (checked, wrong)."""
    poly = {"cuboid", "convex", "triangle", "segment"}

    def applies(x):
        kinds = {shape_type(x["a"]), shape_type(x["b"])}
        return kinds <= poly or ("halfspace" in kinds and len(kinds) == 2
                                 and kinds - {"halfspace"} <= poly | {"ball"})
    todo = [x for x in lines if applies(x)]
    picked = [todo[i] for i in rng.permutation(len(todo))[:sample]]
    wrong = [x for x in picked if exact_truth(x["a"], x["b"]) != x["expected"]]
    return len(picked), wrong


def scaled(line, exponent):
    """The line with every coordinate, half axis and radius multiplied by 2^exponent: exact
    (no f64 here comes near overflow or the subnormals for |exponent| <= 900), and scaling
    preserves whether two solids meet, so `expected` is unchanged."""
    factor = 2.0 ** exponent

    def mul(v):
        out = [float(x) * factor for x in v]
        assert all(F(o) == F(x) * F(factor) for o, x in zip(out, v)), "inexact scaling"
        return out

    def shape(sh):
        sh = map_points(sh, mul)
        (kind,) = sh.keys()
        if "radius" in sh[kind]:
            sh[kind]["radius"] = mul([sh[kind]["radius"]])[0]
        return sh

    return {**line, "a": shape(line["a"]), "b": shape(line["b"]),
            "family": "near_contact_scaled", "case": f"{line['case']}, scale 2^{exponent}"}


def to_json(line):
    def clean(v):
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, (list, tuple, np.ndarray)):
            return [clean(x) for x in v]
        if isinstance(v, (bool, np.bool_)):
            return bool(v)
        if isinstance(v, (float, np.floating, int)):
            return float(v)
        return v
    return json.dumps(clean(line))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-o", "--out", default="shape_pairs")
    ap.add_argument("--generic", type=int, default=200, help="generic pairs per pair type")
    ap.add_argument("--near-per-type", type=int, default=24,
                    help="near-contact configurations per pair type (7 lines each)")
    ap.add_argument("--seed", type=int, default=35)
    ap.add_argument("--scaled", default="", metavar="E1,E2,...",
                    help="also write OUT/near_contact_scaled/: the near-contact lines scaled by "
                         "2^E for each E (e.g. -300,-40,40,300)")
    ap.add_argument("--check", type=int, default=0, metavar="N",
                    help="re-decide N near-contact lines per polytopal pair type with an "
                         "independent exact test (slow) and fail on any disagreement")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    summary = {}
    for family in ("generic", "near_contact"):
        os.makedirs(os.path.join(args.out, family), exist_ok=True)
    near = near_contact(rng, args.near_per_type)
    for ka, kb in itertools.combinations_with_replacement(TYPES, 2):
        name = pair_name(ka, kb)
        gen, dropped = generic(rng, ka, kb, args.generic)
        for family, lines in (("generic", gen), ("near_contact", near[name])):
            path = os.path.join(args.out, family, name + ".jsonl")
            with open(path, "w") as f:
                for line in lines:
                    f.write(to_json(line) + "\n")
            summary.setdefault(name, {})[family] = {
                "pairs": len(lines), "intersecting": sum(1 for x in lines if x["expected"])}
        summary[name]["generic"]["undecided_redrawn"] = dropped
        if args.scaled:
            exps = [int(e) for e in args.scaled.split(",")]
            os.makedirs(os.path.join(args.out, "near_contact_scaled"), exist_ok=True)
            with open(os.path.join(args.out, "near_contact_scaled", name + ".jsonl"), "w") as f:
                for e in exps:
                    for line in near[name]:
                        f.write(to_json(scaled(line, e)) + "\n")
    failures = 0
    if args.check:
        check_rng = np.random.default_rng(args.seed + 1)
        for name, lines in near.items():
            checked, wrong = check_near_contact(lines, args.check, check_rng)
            if checked:
                summary[name]["near_contact"]["exact_check"] = {"checked": checked,
                                                                "disagree": len(wrong)}
            for x in wrong:
                failures += 1
                print(f"exact check disagrees: {to_json(x)}", file=sys.stderr)
    for name, s in summary.items():
        print(json.dumps({"pair": name, **s}))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

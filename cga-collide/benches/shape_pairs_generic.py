#!/usr/bin/env python3
"""The generic family of shape_pairs.py: random primitive pairs whose answer a floating-point
certificate with a wide margin decides (a separating direction with gap >= MARGIN, found by
Frank-Wolfe on the Minkowski difference, or a point inside both shapes by MARGIN). Coordinates
are O(1) and the checks' rounding about 1e-15, so MARGIN = 1e-7 leaves no doubt; the draws no
certificate decides are dropped and drawn again. Needs numpy only.
"""
import itertools

import numpy as np

MARGIN = 1e-7


def shape_type(shape):
    (kind,) = shape.keys()
    return kind


def unit(v):
    return v / np.linalg.norm(v)


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.diag(r))


def random_shape(rng, kind, c):
    """A random solid of the kind around centre c, of size about 1."""
    if kind == "ball":
        return {"ball": {"center": list(c), "radius": rng.uniform(0.3, 1.0)}}
    if kind == "cuboid":
        rot = random_rotation(rng)
        axes = [rot[:, i] * rng.uniform(0.2, 1.0) for i in range(3)]
        if rng.random() < 0.25:  # a sheared parallelepiped
            axes[1] = axes[1] + 0.4 * axes[0]
        return {"cuboid": {"center": list(c), "half_axes": [list(u) for u in axes]}}
    if kind in ("capsule", "cylinder", "cone"):
        d = unit(rng.normal(size=3)) * rng.uniform(0.2, 1.5) / 2
        r = rng.uniform(0.1, 0.6)
        if kind == "cone":
            return {"cone": {"apex": list(c + d), "base": list(c - d), "radius": r}}
        return {kind: {"a": list(c - d), "b": list(c + d), "radius": r}}
    if kind == "halfspace":
        return {"halfspace": {"point": list(c), "normal": list(rng.normal(size=3))}}
    if kind == "convex":
        rot, radii = random_rotation(rng), rng.uniform(0.3, 1.0, size=3)
        n = int(rng.integers(6, 15))
        pts = [c + rot @ (radii * unit(rng.normal(size=3))) for _ in range(n)]
        return {"convex": {"points": [list(p) for p in pts]}}
    if kind == "triangle":
        return {"triangle": {"points": [list(c + rng.normal(size=3) * 0.6) for _ in range(3)]}}
    raise ValueError(kind)


def as_float_shape(shape):
    """(kind, dict of numpy arrays) for the float checks."""
    kind = shape_type(shape)
    s = {k: (np.array(v, dtype=float) if isinstance(v, list) else float(v))
         for k, v in shape[kind].items()}
    return kind, s


def hull_planes(points):
    """Facet planes (n, d) with n.x <= d inside, by brute force over triples (random points in
    general position, so no ties)."""
    planes = []
    for i, j, k in itertools.combinations(range(len(points)), 3):
        n = np.cross(points[j] - points[i], points[k] - points[i])
        if np.linalg.norm(n) < 1e-12:
            continue
        n = unit(n)
        side = (points - points[i]) @ n
        if np.all(side <= 1e-12):
            planes.append((n, n @ points[i]))
        elif np.all(side >= -1e-12):
            planes.append((-n, -n @ points[i]))
    return planes


def support(shape, d):
    """A point of the solid maximising x.d (not for half-spaces)."""
    kind, s = shape
    if kind == "ball":
        return s["center"] + s["radius"] * unit(d)
    if kind == "cuboid":
        return s["center"] + sum(np.sign(u @ d) * u for u in s["half_axes"])
    if kind in ("convex", "triangle", "segment"):
        return s["points"][np.argmax(s["points"] @ d)]
    if kind == "capsule":
        end = s["a"] if s["a"] @ d >= s["b"] @ d else s["b"]
        return end + s["radius"] * unit(d)
    if kind == "cylinder":
        u = unit(s["b"] - s["a"])
        end = s["b"] if u @ d >= 0 else s["a"]
        perp = d - (d @ u) * u
        n = np.linalg.norm(perp)
        return end + (s["radius"] * perp / n if n > 0 else 0.0)
    if kind == "cone":
        u = unit(s["apex"] - s["base"])
        perp = d - (d @ u) * u
        n = np.linalg.norm(perp)
        rim = s["base"] + (s["radius"] * perp / n if n > 0 else 0.0)
        return s["apex"] if s["apex"] @ d >= rim @ d else rim
    raise ValueError(kind)


def inside(shape, x, m):
    """x is inside the solid by at least m (float check; m far above its rounding)."""
    kind, s = shape
    if kind == "ball":
        return np.linalg.norm(x - s["center"]) <= s["radius"] - m
    if kind == "cuboid":
        axes = np.array(s["half_axes"]).T
        coords = np.linalg.solve(axes, x - s["center"])
        scale = max(np.linalg.norm(axes[:, i]) for i in range(3))
        return bool(np.all(np.abs(coords) <= 1 - 10 * m / scale))
    if kind == "halfspace":
        return (x - s["point"]) @ unit(s["normal"]) <= -m
    if kind == "convex":
        if "planes" not in s:
            s["planes"] = hull_planes(s["points"])
        return all(n @ x - d <= -m for n, d in s["planes"])
    if kind in ("triangle", "segment"):
        return False
    p, q = (s["a"], s["b"]) if kind != "cone" else (s["base"], s["apex"])
    u = q - p
    t = (x - p) @ u / (u @ u)
    radial = np.linalg.norm(x - p - t * u)
    length = np.linalg.norm(u)
    if kind == "capsule":
        return np.linalg.norm(x - p - min(max(t, 0.0), 1.0) * u) <= s["radius"] - m
    if not (m / length <= t <= 1 - m / length):
        return False
    if kind == "cylinder":
        return radial <= s["radius"] - m
    return radial <= s["radius"] * (1 - t) - 2 * m  # cone: the slant face, with slack


def known_points(shape):
    """Points certainly in the solid (convex combinations of its defining points)."""
    kind, s = shape
    if kind in ("ball", "cuboid"):
        return [s["center"]]
    if kind in ("convex", "triangle", "segment"):
        return [s["points"].mean(axis=0)] + list(s["points"])
    if kind in ("capsule", "cylinder"):
        return [s["a"], s["b"], (s["a"] + s["b"]) / 2]
    if kind == "cone":
        return [s["base"], s["base"] + 0.25 * (s["apex"] - s["base"])]
    return [s["point"] - unit(s["normal"])]


def certify(a_shape, b_shape):
    """True / False when a float certificate with margin decides the pair, else None."""
    a, b = as_float_shape(a_shape), as_float_shape(b_shape)
    if a[0] == "halfspace" and b[0] == "halfspace":
        na, nb = a[1]["normal"], b[1]["normal"]
        if np.linalg.norm(np.cross(na, nb)) > MARGIN:
            return True  # closed half-spaces with non-parallel normals always meet
        if na @ nb > 0:
            return True
        # opposite normals: they meet iff b's boundary is not beyond a's
        gap = (b[1]["point"] - a[1]["point"]) @ unit(na)
        return True if gap <= -MARGIN else False if gap >= MARGIN else None
    if a[0] == "triangle" and b[0] == "triangle":
        return triangles_cross(a[1]["points"], b[1]["points"])
    if b[0] == "halfspace":
        a, b = b, a
    if a[0] == "halfspace":
        n = unit(a[1]["normal"])
        lowest = support(b, -n) @ n - a[1]["point"] @ n
        return True if lowest <= -MARGIN else False if lowest >= MARGIN else None
    # Frank-Wolfe on the Minkowski difference A - B: every direction d tried gives the
    # separation bound -(h_A(d) + h_B(-d)) / |d|; the iterates pa in A, pb in B are candidates
    # for a common point.
    pa, pb = known_points(a)[0], known_points(b)[0]
    for _ in range(200):
        x = pa - pb
        norm = np.linalg.norm(x)
        if norm < 1e-9:
            break
        d = -x / norm
        sa, sb = support(a, d), support(b, -d)
        if (sa - sb) @ d < -MARGIN:
            return False
        step = x - (sa - sb)
        denom = step @ step
        if denom == 0:
            break
        gamma = min(max((x @ step) / denom, 0.0), 1.0)
        pa, pb = pa + gamma * (sa - pa), pb + gamma * (sb - pb)
    for p in known_points(a) + [pa]:
        if inside(b, p, MARGIN):
            return True
    for p in known_points(b) + [pb]:
        if inside(a, p, MARGIN):
            return True
    ca, cb = known_points(a)[0], known_points(b)[0]
    for t in np.linspace(0, 1, 21):
        p = ca + t * (cb - ca)
        if inside(a, p, MARGIN) and inside(b, p, MARGIN):
            return True
    return None


def triangles_cross(t1, t2):
    """True when an edge of one triangle crosses the other's interior with margin (both
    flat, so no point is inside either by a margin); False when a direction separates
    them; else None."""
    for p, q in ((t1, t2), (t2, t1)):
        n = unit(np.cross(q[1] - q[0], q[2] - q[0]))
        for i in range(3):
            e0, e1 = p[i], p[(i + 1) % 3]
            s0, s1 = (e0 - q[0]) @ n, (e1 - q[0]) @ n
            if (s0 <= -MARGIN and s1 >= MARGIN) or (s0 >= MARGIN and s1 <= -MARGIN):
                x = e0 + (s0 / (s0 - s1)) * (e1 - e0)
                # barycentric coordinates of x in q, each at least MARGIN (relative)
                m = np.array([q[1] - q[0], q[2] - q[0], n]).T
                u, v, _ = np.linalg.solve(m, x - q[0])
                if min(u, v, 1 - u - v) >= 1e-6:
                    return True
    normals = [np.cross(t[1] - t[0], t[2] - t[0]) for t in (t1, t2)]
    edges = [t[(i + 1) % 3] - t[i] for t in (t1, t2) for i in range(3)]
    dirs = normals + [np.cross(e, f) for e in edges[:3] for f in edges[3:]]
    for d in dirs:
        if np.linalg.norm(d) < 1e-9:
            continue
        d = unit(d)
        lo1, hi1 = (t1 @ d).min(), (t1 @ d).max()
        lo2, hi2 = (t2 @ d).min(), (t2 @ d).max()
        if lo2 - hi1 >= MARGIN or lo1 - hi2 >= MARGIN:
            return False
    return None


def bounding_radius(shape):
    kind, s = as_float_shape(shape)
    c = known_points((kind, s))[0]
    if kind == "halfspace":
        return 1.0
    pts = {"ball": lambda: [c + s["radius"]],
           "cuboid": lambda: [c + sum(np.abs(u) for u in s["half_axes"])]}.get(kind)
    if pts:
        return float(np.linalg.norm(pts()[0] - c))
    if kind in ("convex", "triangle"):
        return float(max(np.linalg.norm(p - c) for p in s["points"]))
    ends = [s[k] for k in ("a", "b", "apex", "base") if k in s]
    return float(max(np.linalg.norm(e - c) for e in ends) + s["radius"])


def generic(rng, ka, kb, count):
    lines, dropped = [], 0
    wanted = {True: count // 2, False: count - count // 2}
    while len(lines) < count:
        ca = rng.uniform(-2, 2, size=3)
        a = random_shape(rng, ka, ca)
        reach = bounding_radius(a) + (1.0 if kb == "halfspace" else 0.0)
        probe = random_shape(rng, kb, np.zeros(3))
        reach += bounding_radius(probe) if kb != "halfspace" else 0.0
        cb = ca + unit(rng.normal(size=3)) * rng.uniform(0, 0.9) * reach
        b = random_shape(rng, kb, cb)
        if ka == kb == "halfspace" and rng.random() < 0.5:  # opposite normals
            b["halfspace"]["normal"] = [-x for x in a["halfspace"]["normal"]]
        if ka == "halfspace" or kb == "halfspace":
            # put the plane at a random signed distance from the other shape's centre
            hs, other = (a, b) if ka == "halfspace" else (b, a)
            oc = known_points(as_float_shape(other))[0]
            n = unit(np.array(hs["halfspace"]["normal"]))
            hs["halfspace"]["point"] = list(oc + n * rng.uniform(-1.2, 1.2)
                                            * bounding_radius(other))
        truth = certify(a, b)
        if truth is None:
            dropped += 1
            continue
        if wanted[truth] == 0:
            continue  # half intersecting, half not
        wanted[truth] -= 1
        lines.append({"a": a, "b": b, "expected": truth, "family": "generic",
                      "case": f"{ka}-{kb} random"})
    return lines, dropped

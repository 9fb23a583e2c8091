"""Penetration depths of two placed meshes for the trimesh drop-in (``cga_collide.trimesh``).

Three definitions, by what the two meshes are (each decided exactly):

* ``"exact"``: both meshes are **convex** (closed, every edge shared by two consistently
  oriented triangles, every vertex on the inner side of every face's plane, checked with exact
  integer arithmetic) with at most ``MAX_HULL_POINTS`` distinct vertices. The solids are then
  their convex hulls, and the depth is :func:`cga_collide.signed_distance_at` of the two hulls:
  the length of the shortest translation that separates them, within a proved bound of a few
  ulps, with its exact minimising direction (rounded).
* ``"vertex"``: both meshes are **closed** (not both convex, or hulls too large for the exact
  depth). The depth is the largest distance from a vertex of one mesh inside the other solid
  to that solid's surface (:meth:`cga_collide.Collider.signed_distance_at`: exact inside/outside,
  distance within its proved bound). Every translation that separates the two solids moves
  that vertex out, so this is a **certified lower bound** of the penetration depth (exact when
  the deepest point of the overlap is a vertex, as for a corner pushed into a face; ``0`` when
  the surfaces cross with no vertex inside). The normal is the direction that pushes that
  vertex out along its nearest surface point.
* ``"none"``: a mesh is **open** (it bounds no solid): depth ``0``; the normal of each contact
  is its triangle of the second object's face normal, reversed (from the first object towards
  the second).
"""

from __future__ import annotations

from typing import Any, List, Optional, Tuple

import numpy as np

from . import CgaError, Collider, ConvexHull, signed_distance_at

__all__ = ["Depth", "MAX_HULL_POINTS", "pair_depth"]

# The largest hull (distinct points, so at most as many corners) whose exact penetration depth the library computes
# (`cga_collide::query::MAX_HULL_POINTS`).
MAX_HULL_POINTS = 128


class Depth:
    """The penetration depth of two placed meshes ``a`` and ``b`` (see the module docs):
    ``depth >= 0``; ``normal`` the unit direction from ``a`` towards ``b`` (translating ``b`` by
    ``depth * normal`` separates them where ``kind == "exact"``), ``None`` where no direction is
    known (``depth == 0`` and the contacts give their own); ``witness_a``, ``witness_b`` points
    of each, ``(witness_b - witness_a) @ normal == -depth`` up to rounding (``None`` with the
    normal); ``error_bound`` the proved bound on the depth's rounding; ``kind`` ``"exact"``,
    ``"vertex"`` (a certified lower bound) or ``"none"`` (an open mesh)."""

    __slots__ = ("depth", "error_bound", "normal", "witness_a", "witness_b", "kind")

    def __init__(
        self,
        depth: float,
        error_bound: float,
        normal: Optional[np.ndarray],
        witnesses: Optional[Tuple[np.ndarray, np.ndarray]],
        kind: str,
    ):
        self.depth = float(depth)
        self.error_bound = float(error_bound)
        self.normal = normal
        self.witness_a: Optional[np.ndarray] = None
        self.witness_b: Optional[np.ndarray] = None
        if witnesses is not None:
            self.witness_a, self.witness_b = witnesses
        self.kind = kind


class Solid:
    """What a mesh is for depths: convex (with its hull shape), closed, or open."""

    __slots__ = ("hull", "closed")

    def __init__(self, hull: Optional[ConvexHull], closed: bool):
        self.hull = hull
        self.closed = closed

    @staticmethod
    def of(vertices: np.ndarray, faces: np.ndarray) -> "Solid":
        points, inverse = np.unique(vertices, axis=0, return_inverse=True)
        tris = inverse.reshape(-1)[np.asarray(faces, dtype=np.int64)].reshape(-1, 3)
        closed = _is_closed_oriented(tris)
        hull = None
        if closed and len(points) <= MAX_HULL_POINTS and _is_convex(points, tris):
            hull = ConvexHull(points)
        return Solid(hull, closed)


def _is_closed_oriented(tris: np.ndarray) -> bool:
    """Every directed edge of a non-degenerate triangle appears once and its reverse once."""
    tris = tris[(tris[:, 0] != tris[:, 1]) & (tris[:, 1] != tris[:, 2]) & (tris[:, 2] != tris[:, 0])]
    if len(tris) == 0:
        return False
    directed = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    unique, counts = np.unique(directed, axis=0, return_counts=True)
    if (counts != 1).any():
        return False
    forward = {(int(i), int(j)) for i, j in unique}
    return all((j, i) in forward for i, j in forward)


def _exact_integers(points: np.ndarray) -> List[List[int]]:
    """The coordinates as integers, all scaled by one power of two (exact: every float64 is a
    dyadic rational)."""
    ratios = [x.as_integer_ratio() for x in points.ravel().tolist()]
    shift = max(den.bit_length() - 1 for _, den in ratios)
    ints = [num << (shift - (den.bit_length() - 1)) for num, den in ratios]
    return [ints[k : k + 3] for k in range(0, len(ints), 3)]


def _is_convex(points: np.ndarray, tris: np.ndarray) -> bool:
    """Whether every point lies on one side (the same for every face, closed) of every face's
    plane, in exact integer arithmetic; a mesh with no face spanning a plane is not."""
    p = _exact_integers(points)
    sign = 0
    for i, j, k in tris.tolist():
        a, b, c = p[i], p[j], p[k]
        u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
        v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        if n == [0, 0, 0]:
            continue  # a degenerate face spans no plane
        for q in p:
            s = n[0] * (q[0] - a[0]) + n[1] * (q[1] - a[1]) + n[2] * (q[2] - a[2])
            if s == 0:
                continue
            s = 1 if s > 0 else -1
            if sign == 0:
                sign = s
            elif s != sign:
                return False
    return sign != 0


def _placed(collider: Collider, pose: np.ndarray) -> np.ndarray:
    """The mesh's vertices in world coordinates (float64)."""
    return np.asarray(collider.vertices, dtype=np.float64) @ pose[:3, :3].T + pose[:3, 3]


def _deepest_vertex(
    points: np.ndarray, into: Collider, pose: np.ndarray
) -> Optional[Tuple[float, float, np.ndarray, np.ndarray]]:
    """The deepest of ``points`` inside ``into`` at ``pose``: (depth, bound, point, its nearest
    surface point), or ``None`` when no point is strictly inside."""
    r = into.signed_distance_at(pose, points)
    d = np.asarray(r.signed_distance)
    inside = np.asarray(r.inside) & (d < 0.0)
    if not inside.any():
        return None
    k = int(np.argmin(np.where(inside, d, np.inf)))
    return float(-d[k]), float(np.asarray(r.error_bound)[k]), points[k], np.asarray(r.nearest)[k]


def _unit(v: np.ndarray) -> Optional[np.ndarray]:
    n = float(np.linalg.norm(v))
    return v / n if n > 0.0 and np.isfinite(n) else None


def _vertex_depth(ca: Collider, pa: np.ndarray, cb: Collider, pb: np.ndarray) -> Depth:
    """The ``"vertex"`` depth of two closed meshes (see the module docs)."""
    a_in_b = _deepest_vertex(_placed(ca, pa), cb, pb)
    b_in_a = _deepest_vertex(_placed(cb, pb), ca, pa)
    if a_in_b is not None and (b_in_a is None or a_in_b[0] >= b_in_a[0]):
        # a's vertex v inside b, q its nearest point of b's surface: moving b by v - q frees it
        depth, bound, v, q = a_in_b
        normal = _unit(v - q)
        return Depth(depth, bound, normal, (v, q) if normal is not None else None, "vertex")
    if b_in_a is not None:
        # b's vertex w inside a, q its nearest point of a's surface: moving b by q - w frees it
        depth, bound, w, q = b_in_a
        normal = _unit(q - w)
        return Depth(depth, bound, normal, (q, w) if normal is not None else None, "vertex")
    return Depth(0.0, 0.0, None, None, "vertex")


def pair_depth(
    solid_a: Any, ca: Collider, pa: np.ndarray, solid_b: Any, cb: Collider, pb: np.ndarray
) -> Depth:
    """The penetration depth of meshes ``a`` and ``b`` (colliders with their ``Solid``) at
    poses ``pa`` and ``pb``, by the first definition of the module docs that applies."""
    if solid_a.hull is not None and solid_b.hull is not None:
        try:
            sd = signed_distance_at(solid_a.hull, pa, solid_b.hull, pb)
        except CgaError:
            pass  # no exact depth for this pair: the vertex depth below
        else:
            depth = max(-sd.value, 0.0)
            return Depth(
                depth,
                sd.error_bound,
                np.asarray(sd.normal),
                (np.asarray(sd.witness_a), np.asarray(sd.witness_b)),
                "exact",
            )
    if solid_a.closed and solid_b.closed:
        return _vertex_depth(ca, pa, cb, pb)
    return Depth(0.0, 0.0, None, None, "none")


def face_normal(collider: Collider, pose: np.ndarray, triangle: int) -> Optional[np.ndarray]:
    """The unit normal of a triangle (counter-clockwise corners) in world coordinates."""
    corners = np.asarray(collider.vertices)[np.asarray(collider.faces)[triangle]]
    a, b, c = corners @ pose[:3, :3].T
    return _unit(np.cross(b - a, c - a))

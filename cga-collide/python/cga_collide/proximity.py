"""``trimesh.proximity``-style functions on top of :meth:`cga_collide.Collider.signed_distance`:
the signed distance, nearest points and containment of many points, with exact signs.

They take a mesh as trimesh does (anything with ``vertices`` ``(n, 3)`` and ``faces``
``(m, 3)``; a :class:`cga_collide.Collider` is used as it is) and follow trimesh's conventions:
``signed_distance`` is **positive inside** and negative outside, and a point on the surface is
inside at distance ``0``. Unlike trimesh, the sign is exact (the even–odd rule of a ray,
decided with exact predicates; for a closed mesh the solid it bounds), including for points on
or within an ulp of the surface, and the distances carry a proved error bound
(``Collider.signed_distance(points).error_bound``). They are re-exported by
:mod:`cga_collide.trimesh`.
"""

from __future__ import annotations

from typing import Any, Tuple

import numpy as np

from . import Collider, PointDistances

__all__ = ["closest_point", "contains", "point_distances", "signed_distance"]


def _collider(mesh: Any) -> Collider:
    if isinstance(mesh, Collider):
        return mesh
    vertices = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int64)
    return Collider(vertices, faces)


def point_distances(mesh: Any, points: Any) -> PointDistances:
    """Every answer of :meth:`Collider.signed_distance` (the Rust sign: negative inside)."""
    return _collider(mesh).signed_distance(np.asarray(points, dtype=np.float64).reshape(-1, 3))


def signed_distance(mesh: Any, points: Any) -> np.ndarray:
    """The signed distance of each point to the mesh's surface, ``(n,)`` float64, as
    ``trimesh.proximity.signed_distance``: positive inside, negative outside, ``0`` on the
    surface (inside). The sign is exact."""
    d = point_distances(mesh, points).signed_distance
    # Negated, with +0.0 (not -0.0) on the surface.
    return 0.0 - d


def closest_point(mesh: Any, points: Any) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """As ``trimesh.proximity.closest_point``: the nearest surface point of each point
    ``(n, 3)``, its distance ``(n,)`` and its triangle ``(n,)`` int64."""
    r = point_distances(mesh, points)
    return r.nearest, np.abs(r.signed_distance), r.triangle


def contains(mesh: Any, points: Any) -> np.ndarray:
    """As ``trimesh.Trimesh.contains``: whether each point is inside, ``(n,)`` bool, exactly
    (a point on the surface is inside)."""
    return point_distances(mesh, points).inside

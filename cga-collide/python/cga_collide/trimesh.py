"""A drop-in for ``trimesh.collision.CollisionManager`` on top of :class:`cga_collide.Scene`.

``CollisionManager`` has the methods, arguments and return conventions of trimesh's manager
(names, sets of sorted name pairs, ``ContactData`` and ``DistanceData`` objects with the
attributes trimesh documents), with exact yes/no answers and transforms kept in float64
(trimesh's manager casts them to float32 before FCL sees them). It needs neither python-fcl nor
trimesh itself: a mesh is anything with ``vertices`` ``(n, 3)`` and ``faces`` ``(m, 3)``.

Deliberate differences from trimesh's FCL-backed manager (see ``docs/python.md``):

* Collision means the closed surfaces share a point, exactly: touching counts. FCL answers
  near-contact by rounding, after a cast to float32.
* ``ContactData.point`` is a point of the exact intersection of the contact's triangle pair
  (the mean of its corners); FCL picks a point of its own. ``depth`` and ``normal`` are the
  object pair's penetration depth and its direction (from the first object towards the
  second), the same for every contact of the pair: for two convex meshes (checked exactly,
  at most 128 distinct vertices each) the exact penetration depth (the shortest separating
  translation, proved to a few ulps); for other closed meshes the depth of the deepest
  vertex of one inside the other (a certified lower bound of the penetration depth); for open
  meshes, which bound no solid, ``0`` with the contact triangle's face normal.
  ``ContactData.depth_kind`` says which (``"exact"``, ``"vertex"``, ``"none"``). FCL gives
  per-contact estimates.
* When objects collide, ``min_distance_*`` is minus that depth for one colliding pair (the
  first found, as FCL stops at the first colliding pair it meets), not necessarily the deepest.
* A transform must be a rigid motion (rotation and translation, ``max |RᵀR − I| <= 1e-6``):
  scale and shear are refused with a ``CgaError`` rather than silently mishandled.
"""

from __future__ import annotations

import hashlib
from typing import Any, Dict, Iterable, List, Optional, Set, Tuple

import numpy as np

from . import Collider, ObjectId, Scene
from ._trimesh_depth import Depth, Solid, face_normal, pair_depth

__all__ = ["CollisionManager", "ContactData", "DistanceData", "mesh_to_collider"]

_EXTERNAL = "__external"


def _as_transform(transform: Any) -> np.ndarray:
    if transform is None:
        return np.eye(4)
    t = np.array(transform, dtype=np.float64)  # a copy, in float64 (never float32)
    if t.shape != (4, 4):
        raise ValueError("transform must be (4,4)!")
    return t


class _Geometry:
    """A mesh built once: its collider and (lazily) its solid for depths."""

    __slots__ = ("collider", "_vertices", "_faces", "_solid")

    def __init__(self, vertices: np.ndarray, faces: np.ndarray):
        self._vertices = vertices
        self._faces = faces
        self.collider = Collider(vertices, faces)
        self._solid: Optional[Solid] = None

    @property
    def solid(self) -> Solid:
        if self._solid is None:
            self._solid = Solid.of(self._vertices, self._faces)
        return self._solid


def _arrays(mesh: Any) -> Tuple[np.ndarray, np.ndarray]:
    """Copies of the mesh's arrays (a mesh changed after ``add_object`` does not change the
    object)."""
    vertices = np.array(mesh.vertices, dtype=np.float64, order="C", copy=True)
    faces = np.array(mesh.faces, dtype=np.int64, order="C", copy=True)
    return vertices, faces


class _Cache:
    """Geometries by mesh content, so a mesh added many times is built once."""

    def __init__(self) -> None:
        self._by_key: Dict[bytes, _Geometry] = {}

    def get(self, mesh: Any) -> _Geometry:
        vertices, faces = _arrays(mesh)
        h = hashlib.blake2b(digest_size=20)
        h.update(np.asarray(vertices.shape, dtype=np.int64).tobytes())
        h.update(vertices.tobytes())
        h.update(faces.tobytes())
        key = h.digest()
        g = self._by_key.get(key)
        if g is None:
            g = _Geometry(vertices, faces)
            self._by_key[key] = g
        return g


def mesh_to_collider(mesh: Any) -> Collider:
    """A :class:`Collider` of a trimesh mesh (or anything with ``vertices`` and ``faces``)."""
    vertices, faces = _arrays(mesh)
    return Collider(vertices, faces)


class ContactData:
    """One contact between two objects: a pair of intersecting triangles.

    ``names`` is the set of the two object names; ``point`` a point of the exact intersection
    of the two triangles; ``depth`` and ``normal`` the penetration depth of the two objects
    and its direction, as the module docs define them (``depth_kind`` says which definition
    applied); ``index(name)`` the triangle of the named object."""

    def __init__(
        self,
        names: Tuple[str, str],
        indices: Tuple[int, int],
        point: np.ndarray,
        normal: np.ndarray,
        depth: float,
        depth_kind: str = "exact",
    ):
        self.names = set(names)
        self._inds = {names[0]: int(indices[0]), names[1]: int(indices[1])}
        self._point = np.asarray(point, dtype=np.float64)
        self._normal = np.asarray(normal, dtype=np.float64)
        self._depth = float(depth)
        self._depth_kind = depth_kind

    @property
    def normal(self) -> np.ndarray:
        """(3,) float: the unit normal of the contact."""
        return self._normal

    @property
    def point(self) -> np.ndarray:
        """(3,) float: the contact point, in world coordinates."""
        return self._point

    @property
    def depth(self) -> float:
        """float: the penetration depth (``>= 0``)."""
        return self._depth

    @property
    def depth_kind(self) -> str:
        """``"exact"`` (two convex meshes: the exact penetration depth), ``"vertex"`` (closed
        meshes: the deepest vertex, a certified lower bound) or ``"none"`` (an open mesh: 0)."""
        return self._depth_kind

    def index(self, name: str) -> int:
        """The index of the triangle of object ``name`` in this contact."""
        return self._inds[name]

    def __repr__(self) -> str:
        return f"ContactData(names={self.names}, point={self._point}, depth={self._depth})"


class DistanceData:
    """The result of a distance query: ``names``, ``distance``, ``point(name)`` (the nearest
    point on the named object, world coordinates) and ``index(name)`` (its triangle)."""

    def __init__(
        self,
        names: Tuple[str, str],
        indices: Tuple[int, int],
        points: Tuple[np.ndarray, np.ndarray],
        distance: float,
    ):
        self.names = set(names)
        self._inds = {names[0]: int(indices[0]), names[1]: int(indices[1])}
        self._points = {
            names[0]: np.asarray(points[0], dtype=np.float64),
            names[1]: np.asarray(points[1], dtype=np.float64),
        }
        self._distance = float(distance)

    @property
    def distance(self) -> float:
        """float: the distance (negative: penetration depth)."""
        return self._distance

    def index(self, name: str) -> int:
        """The triangle of object ``name`` nearest to the other object."""
        return self._inds[name]

    def point(self, name: str) -> np.ndarray:
        """(3,) float: the nearest point on object ``name``."""
        return self._points[name]

    def __repr__(self) -> str:
        return f"DistanceData(names={self.names}, distance={self._distance})"


class _Placed:
    __slots__ = ("geometry", "transform", "id")

    def __init__(self, geometry: _Geometry, transform: np.ndarray, oid: ObjectId):
        self.geometry = geometry
        self.transform = transform
        self.id = oid


def _depth(a: _Placed, b: _Placed) -> Depth:
    """The penetration depth of two placed objects (``cga_collide._trimesh_depth``)."""
    return pair_depth(
        a.geometry.solid, a.geometry.collider, a.transform,
        b.geometry.solid, b.geometry.collider, b.transform,
    )  # fmt: skip


def _contact_normal(depth: Depth, b: _Placed, triangle_b: int) -> np.ndarray:
    """The pair's normal, or (none known) the reversed normal of ``b``'s contact triangle."""
    if depth.normal is not None:
        return depth.normal
    n = face_normal(b.geometry.collider, b.transform, triangle_b)
    return -n if n is not None else np.array([0.0, 0.0, 1.0])


def _contact_data(a: _Placed, name_a: str, b: _Placed, name_b: str) -> List[ContactData]:
    """Every contact (intersecting triangle pair) of two placed objects, each with the pair's
    penetration depth and normal."""
    depth = _depth(a, b)
    out = []
    for ij, _kind, points in a.geometry.collider.contacts_at(
        a.transform, b.geometry.collider, b.transform
    ):
        normal = _contact_normal(depth, b, ij[1])
        out.append(
            ContactData((name_a, name_b), ij, points.mean(axis=0), normal, depth.depth, depth.kind)
        )
    return out


def _signed(
    a: _Placed, b: _Placed, points: bool = True
) -> Tuple[float, Tuple[int, int], np.ndarray, np.ndarray]:
    """Signed distance of two placed objects, with triangles and points: the certified
    distance when the surfaces are apart, minus the penetration depth when they touch (then
    the points are the depth's witnesses, or one point of the exact contact where the depth has
    none; the triangles are those of one contact when ``points``, else ``-1`` and the points
    NaN: the exact contact geometry costs more than the rest)."""
    ca, cb = a.geometry.collider, b.geometry.collider
    if ca.collides_at(a.transform, cb, b.transform):
        depth = _depth(a, b)
        if not points:
            return -depth.depth, (-1, -1), np.full(3, np.nan), np.full(3, np.nan)
        contacts = ca.contacts_at(a.transform, cb, b.transform)
        ij, _, pts = contacts[0]
        if depth.witness_a is not None and depth.witness_b is not None:
            return -depth.depth, ij, depth.witness_a, depth.witness_b
        p = pts.mean(axis=0)
        return -depth.depth, ij, p, p
    d = ca.distance_at(a.transform, cb, b.transform)
    ij = d.triangles if d.triangles is not None else (-1, -1)
    return d.distance, ij, d.witness_a, d.witness_b


class CollisionManager:
    """A mesh-mesh collision manager with trimesh's interface and exact answers.

    Objects are kept in a :class:`cga_collide.Scene` (a broad phase over world boxes, exact
    pair tests); meshes with the same vertices and faces are built once."""

    def __init__(self) -> None:
        self._scene = Scene()
        self._objs: Dict[str, _Placed] = {}
        self._names: Dict[ObjectId, str] = {}
        self._cache = _Cache()

    # ------------------------------------------------------------------ objects

    def add_object(self, name: str, mesh: Any, transform: Any = None) -> ObjectId:
        """Add an object (replacing any object of the same name); returns its handle."""
        t = _as_transform(transform)
        geometry = self._cache.get(mesh)
        oid = self._scene.add(geometry.collider, t)
        if name in self._objs:
            self._drop(name)
        self._objs[name] = _Placed(geometry, t, oid)
        self._names[oid] = name
        return oid

    def _drop(self, name: str) -> None:
        placed = self._objs.pop(name)
        self._scene.remove(placed.id)
        del self._names[placed.id]

    def remove_object(self, name: str) -> None:
        """Delete an object; ``ValueError`` if there is none of that name."""
        if name not in self._objs:
            raise ValueError(f"{name} not in collision manager!")
        self._drop(name)

    def set_transform(self, name: str, transform: Any) -> None:
        """Replace an object's transform (kept in float64)."""
        if name not in self._objs:
            raise ValueError(f"{name} not in collision manager!")
        t = _as_transform(transform)
        placed = self._objs[name]
        self._scene.set_pose(placed.id, t)
        placed.transform = t

    def set_transforms(self, names: Iterable[str], transforms: Any) -> None:
        """Move many objects in one call (``transforms`` a ``(k, 4, 4)`` array)."""
        names = list(names)
        ts = np.array(transforms, dtype=np.float64)
        if ts.shape != (len(names), 4, 4):
            raise ValueError(f"transforms must be ({len(names)},4,4), got {ts.shape}")
        missing = [n for n in names if n not in self._objs]
        if missing:
            raise ValueError(f"{missing[0]} not in collision manager!")
        self._scene.set_poses([self._objs[n].id for n in names], ts)
        for n, t in zip(names, ts):
            self._objs[n].transform = t

    # ------------------------------------------------------------------ collisions

    @staticmethod
    def _ret(result, names, data, return_names, return_data):
        if return_names and return_data:
            return result, names, data
        if return_names:
            return result, names
        if return_data:
            return result, data
        return result

    def in_collision_single(
        self, mesh: Any, transform: Any = None, return_names: bool = False, return_data: bool = False
    ):
        """Whether ``mesh`` at ``transform`` collides with any object of the manager; with
        ``return_names`` the set of names it collides with, with ``return_data`` a list of
        ``ContactData``."""
        t = _as_transform(transform)
        geometry = self._cache.get(mesh)
        hits = self._scene.colliding_at(geometry.collider, t)
        names: Set[str] = set()
        data: List[ContactData] = []
        if return_names or return_data:
            external = _Placed(geometry, t, None)  # type: ignore[arg-type]
            for oid in hits:
                name = self._names[oid]
                names.add(name)
                if return_data:
                    data.extend(_contact_data(self._objs[name], name, external, _EXTERNAL))
        return self._ret(bool(hits), names, data, return_names, return_data)

    def in_collision_internal(self, return_names: bool = False, return_data: bool = False):
        """Whether any two objects collide; with ``return_names`` the set of colliding name
        pairs (each sorted), with ``return_data`` a list of ``ContactData``."""
        pairs = self._scene.colliding_pairs()
        names: Set[Tuple[str, str]] = set()
        data: List[ContactData] = []
        if return_names or return_data:
            for a, b in pairs:
                na, nb = self._names[a], self._names[b]
                names.add((na, nb) if na <= nb else (nb, na))
                if return_data:
                    data.extend(_contact_data(self._objs[na], na, self._objs[nb], nb))
        return self._ret(bool(pairs), names, data, return_names, return_data)

    def in_collision_other(
        self, other_manager: "CollisionManager", return_names: bool = False, return_data: bool = False
    ):
        """Whether any object of this manager collides with any of ``other_manager``; names
        are ``(name in this manager, name in the other)``."""
        result = False
        names: Set[Tuple[str, str]] = set()
        data: List[ContactData] = []
        for on, op in other_manager._objs.items():
            hits = self._scene.colliding_at(op.geometry.collider, op.transform)
            if not hits:
                continue
            result = True
            if not (return_names or return_data):
                break
            for oid in hits:
                sn = self._names[oid]
                names.add((sn, on))
                if return_data:
                    data.extend(_contact_data(self._objs[sn], sn, op, on))
        return self._ret(result, names, data, return_names, return_data)

    # ------------------------------------------------------------------ distances

    def _nearest_among(
        self, external: _Placed, candidates: Optional[List[str]] = None, points: bool = True
    ) -> Optional[Tuple[float, str, Tuple[int, int], np.ndarray, np.ndarray]]:
        """The signed nearest object of the manager to a placed outside object."""
        hits = self._scene.colliding_at(external.geometry.collider, external.transform)
        if candidates is not None:
            allowed = set(candidates)
            hits = [h for h in hits if self._names[h] in allowed]
        if hits:
            # in collision: one colliding object (the first), as FCL stops at the first
            name = self._names[hits[0]]
            d, ij, pa, pb = _signed(self._objs[name], external, points)
            return d, name, ij, pa, pb
        # apart from everything: the scene's nearest search, with the outside object added
        tmp = self._scene.add(external.geometry.collider, external.transform)
        try:
            near = self._scene.nearest_to(tmp)
        finally:
            self._scene.remove(tmp)
        if near is None:
            return None
        oid, dist = near
        ij = dist.triangles if dist.triangles is not None else (-1, -1)
        # nearest_to measures from the added object: swap to (manager object, outside)
        return dist.distance, self._names[oid], (ij[1], ij[0]), dist.witness_b, dist.witness_a

    def min_distance_single(
        self, mesh: Any, transform: Any = None, return_name: bool = False, return_data: bool = False
    ):
        """The distance from ``mesh`` at ``transform`` to the nearest object (negative when
        they collide); with ``return_name`` that object's name, with ``return_data`` a
        ``DistanceData``."""
        t = _as_transform(transform)
        external = _Placed(self._cache.get(mesh), t, None)  # type: ignore[arg-type]
        best = self._nearest_among(external, points=return_data)
        if best is None:
            return self._ret(float("inf"), None, None, return_name, return_data)
        d, name, ij, pa, pb = best
        data = DistanceData((name, _EXTERNAL), ij, (pa, pb), d)
        return self._ret(d, name, data, return_name, return_data)

    def min_distance_internal(
        self, name: Optional[str] = None, return_names: bool = False, return_data: bool = False
    ):
        """The least distance between two objects (or from object ``name`` to the others),
        negative when some collide; with ``return_names`` the sorted pair of names, with
        ``return_data`` a ``DistanceData``."""
        if name is not None:
            if name not in self._objs:
                raise ValueError(f"{name} not in collision manager!")
            me = self._objs[name]
            touching = self._scene.colliding_with(me.id)
            if touching:
                other = self._names[touching[0]]
                d, ij, pa, pb = _signed(me, self._objs[other], return_data)
            else:
                nearest = self._scene.nearest_to(me.id)
                if nearest is None:
                    return self._ret(float("inf"), None, None, return_names, return_data)
                oid, dist = nearest
                other = self._names[oid]
                d, pa, pb = dist.distance, dist.witness_a, dist.witness_b
                ij = dist.triangles if dist.triangles is not None else (-1, -1)
            pair = (name, other)
        else:
            # The scene's nearest pair: a touching pair (distance 0, the first the broad
            # phase meets) when some objects collide, as FCL stops at the first it meets.
            near = self._scene.nearest_pair()
            if near is None:
                return self._ret(float("inf"), None, None, return_names, return_data)
            a, b, dist = near
            pair = (self._names[a], self._names[b])
            if dist.distance == 0.0:
                d, ij, pa, pb = _signed(self._objs[pair[0]], self._objs[pair[1]], return_data)
            else:
                d, pa, pb = dist.distance, dist.witness_a, dist.witness_b
                ij = dist.triangles if dist.triangles is not None else (-1, -1)
        data = DistanceData(pair, ij, (pa, pb), d)
        return self._ret(d, tuple(sorted(pair)), data, return_names, return_data)

    def min_distance_other(
        self, other_manager: "CollisionManager", return_names: bool = False, return_data: bool = False
    ):
        """The least distance between an object of this manager and one of
        ``other_manager``; names are ``(name in this manager, name in the other)``."""
        best = None
        for on, op in other_manager._objs.items():
            r = self._nearest_among(op, points=return_data)
            if r is not None and (best is None or r[0] < best[0][0]):
                best = (r, on)
        if best is None:
            return self._ret(float("inf"), None, None, return_names, return_data)
        (d, sn, ij, pa, pb), on = best
        data = DistanceData((sn, on), ij, (pa, pb), d)
        return self._ret(d, (sn, on), data, return_names, return_data)


def scene_to_collision(scene: Any) -> Tuple[CollisionManager, Dict[str, ObjectId]]:
    """A manager for the geometry of a ``trimesh.Scene``, as ``trimesh.collision``'s."""
    manager = CollisionManager()
    objects = {}
    for node in scene.graph.nodes_geometry:
        transform, geometry = scene.graph[node]
        objects[node] = manager.add_object(
            name=node, mesh=scene.geometry[geometry], transform=transform
        )
    return manager, objects


# ``trimesh.proximity``-style functions of points against meshes (exact signs).
from .proximity import closest_point, contains, signed_distance  # noqa: E402

__all__ += ["closest_point", "contains", "signed_distance"]

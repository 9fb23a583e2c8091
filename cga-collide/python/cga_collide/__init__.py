"""Exact collision detection in the conformal model: numpy in and out.

Every yes/no answer is exact for the float64 numbers given (touching counts as colliding, no
tolerance anywhere). A :class:`Collider` is a mesh built once; every question about it comes
in three forms, as in the Rust crate: ``a.x(b)`` in one frame, ``a.x_at(pose_a, b, pose_b)``
under ``(4, 4)`` poses, and ``a.x_batch(b, poses_a, poses_b)`` for ``(k, 4, 4)`` arrays of
poses at once. A :class:`Scene` holds many placed colliders. :func:`pose_from_degrees` writes a
pose as the command line's ``--rotate`` and ``--translate`` do.

The solid primitives :class:`Ball`, :class:`Cuboid`, :class:`Capsule`, :class:`Cylinder`,
:class:`Cone`, :class:`HalfSpace`, :class:`ConvexHull`, :class:`Triangle` and :class:`Segment`
(each a :class:`Shape`) are exact closed sets; :func:`intersects`, :func:`within_distance` and
:func:`distance` answer about any two of them, with ``_at`` forms under poses and ``_batch``
forms for ``(k, 4, 4)`` arrays of poses.

Arrays may be anything numpy reads as numbers that float64 holds exactly: float64 arrays in
any memory layout, lists and tuples, integers up to 2^53, float16 and float32. Anything else
(booleans, complex numbers, objects, strings, larger integers) and every refused input is a
:class:`CgaError` (a ``ValueError``) naming the argument, with the library's message.

``cga_collide.motion`` is continuous collision (motion between two poses), with the Rust module's
names; ``Collider.contacts_during`` asks it of two colliders.

``cga_collide.trimesh.CollisionManager`` is a drop-in for ``trimesh.collision.CollisionManager``.
"""

from ._native import (
    MAX_MAGNITUDE,
    ROTATION_TOLERANCE,
    Ball,
    Capsule,
    CgaError,
    Collider,
    ContactManifold,
    Cone,
    ConvexHull,
    Cuboid,
    Cylinder,
    Distance,
    DistanceBatch,
    HalfSpace,
    ObjectId,
    PointDistances,
    Robot,
    RobotMotion,
    Scene,
    Segment,
    Shape,
    SignedDistance,
    Triangle,
    contact_manifold,
    contact_manifold_at,
    distance,
    distance_at,
    distance_batch,
    intersects,
    intersects_at,
    intersects_batch,
    pose_from_degrees,
    signed_distance,
    signed_distance_at,
    within_distance,
    within_distance_at,
    within_distance_batch,
)
from . import motion

__all__ = [
    "Ball",
    "Capsule",
    "CgaError",
    "Collider",
    "ContactManifold",
    "Cone",
    "ConvexHull",
    "Cuboid",
    "Cylinder",
    "Distance",
    "DistanceBatch",
    "HalfSpace",
    "MAX_MAGNITUDE",
    "ObjectId",
    "PointDistances",
    "ROTATION_TOLERANCE",
    "Robot",
    "RobotMotion",
    "Scene",
    "Segment",
    "Shape",
    "SignedDistance",
    "Triangle",
    "contact_manifold",
    "contact_manifold_at",
    "distance",
    "distance_at",
    "distance_batch",
    "intersects",
    "intersects_at",
    "intersects_batch",
    "motion",
    "pose_from_degrees",
    "signed_distance",
    "signed_distance_at",
    "within_distance",
    "within_distance_at",
    "within_distance_batch",
]

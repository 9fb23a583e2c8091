"""Exact collision detection in the conformal model: numpy in and out.

Every yes/no answer is exact for the float64 numbers given (touching counts as colliding, no
tolerance anywhere). A :class:`Collider` is a mesh built once; every question about it comes
in three forms, as in the Rust crate: ``a.x(b)`` in one frame, ``a.x_at(pose_a, b, pose_b)``
under ``(4, 4)`` poses, and ``a.x_batch(b, poses_a, poses_b)`` for ``(k, 4, 4)`` arrays of
poses at once. A :class:`Scene` holds many placed colliders. :func:`pose_from_degrees` writes a
pose as the command line's ``--rotate`` and ``--translate`` do.

Arrays may be anything numpy reads as numbers that float64 holds exactly: float64 arrays in
any memory layout, lists and tuples, integers up to 2^53, float16 and float32. Anything else
(booleans, complex numbers, objects, strings, larger integers) and every refused input is a
:class:`CgaError` (a ``ValueError``) naming the argument, with the library's message.

``cga_collide.motion`` is continuous collision (motion between two poses), with the Rust module's
names; ``Collider.contacts_during`` asks it of two colliders.

``cga_collide.trimesh.CollisionManager`` is a drop-in for ``trimesh.collision.CollisionManager``.
"""

from ._native import (
    ROTATION_TOLERANCE,
    CgaError,
    Collider,
    Distance,
    DistanceBatch,
    ObjectId,
    Scene,
    pose_from_degrees,
)
from . import motion

__all__ = [
    "CgaError",
    "Collider",
    "Distance",
    "DistanceBatch",
    "ObjectId",
    "ROTATION_TOLERANCE",
    "Scene",
    "motion",
    "pose_from_degrees",
]

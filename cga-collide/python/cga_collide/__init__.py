"""Exact collision detection in the conformal model: numpy in and out.

Every yes/no answer is exact for the float64 numbers given (touching counts as colliding, no
tolerance anywhere). A :class:`Collider` is a mesh built once; every question about it comes
in three forms, as in the Rust crate: ``a.x(b)`` in one frame, ``a.x_at(pose_a, b, pose_b)``
under ``(4, 4)`` float64 poses, and ``a.x_batch(b, poses_a, poses_b)`` for ``(k, 4, 4)`` arrays
of poses at once. A :class:`Scene` holds many placed colliders. Errors are :class:`CgaError`
(a ``ValueError``) with the library's message; wrong dtypes are ``TypeError``.

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
]

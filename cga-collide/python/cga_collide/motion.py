"""Continuous collision: primitives and meshes moving between two poses, decided exactly.

The names are those of the Rust module ``cga_collide::motion``. Every point moves linearly,
``p(t) = (1 - t) * p0 + t * p1`` for ``t`` in ``[0, 1]``; the float64 inputs are taken as the
exact numbers they denote, and touching counts.

* A moving point is a ``(2, 3)`` array (start, end); a moving triangle ``(3, 2, 3)``
  (each corner's start and end); a moving edge ``(2, 2, 3)``.
* :func:`vertex_face_touch` and :func:`edge_edge_touch`: do they touch for some ``t``, exactly.
* :func:`vertex_face_first_contact` and :func:`edge_edge_first_contact`: when first, a
  :class:`ContactTime` (``lo <= t <= hi``, at most ``tolerance`` wide; ``safe_time()`` a time
  strictly before contact), or ``None``.
* The ``*_batch`` forms answer a ``(k, 4, 2, 3)`` array of queries in one call (the four
  moving points of each query: the vertex then the triangle's corners, or edge ``a``'s ends then
  edge ``b``'s), over the cores with the GIL released.
* :func:`step_self_contacts`: every vertex-face and edge-edge contact of a deforming mesh over
  one step (a :class:`StepContacts`).
* ``Collider.contacts_during(poses, other, other_poses, tolerance)``: two colliders each moving
  between two ``(4, 4)`` poses (``(2, 4, 4)`` arrays), a :class:`MotionContacts`.

Arrays are read as in :mod:`cga_collide` (anything numpy reads as numbers float64 holds
exactly). Other numbers, wrong shapes, non-finite coordinates, refused poses and tolerances
that are NaN or negative are :class:`cga_collide.CgaError` naming the argument.
"""

from ._native import (
    ContactTime,
    MotionContacts,
    StepContacts,
    edge_edge_first_contact,
    edge_edge_first_contact_batch,
    edge_edge_touch,
    edge_edge_touch_batch,
    step_self_contacts,
    vertex_face_first_contact,
    vertex_face_first_contact_batch,
    vertex_face_touch,
    vertex_face_touch_batch,
)

__all__ = [
    "ContactTime",
    "MotionContacts",
    "StepContacts",
    "edge_edge_first_contact",
    "edge_edge_first_contact_batch",
    "edge_edge_touch",
    "edge_edge_touch_batch",
    "step_self_contacts",
    "vertex_face_first_contact",
    "vertex_face_first_contact_batch",
    "vertex_face_touch",
    "vertex_face_touch_batch",
]

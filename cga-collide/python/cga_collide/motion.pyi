"""Type stubs of cga_collide.motion (continuous collision; the Rust module's names)."""

from typing import List, Optional, Tuple, Union, final

import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike

_Float64Array = npt.NDArray[np.float64]
_Int64Array = npt.NDArray[np.int64]
_BoolArray = npt.NDArray[np.bool_]
_MotionPair = Union[
    Tuple[str, int, int],  # ("vertex_face", v, f) or ("face_vertex", f, v)
    Tuple[str, Tuple[int, int], Tuple[int, int]],  # ("edge_edge", (a0, a1), (b0, b1))
]

@final
class ContactTime:
    """When two primitives first touch: ``lo <= t <= hi`` for the earliest contact time ``t`` in
    ``[0, 1]``. Either ``lo == hi == t`` exactly (``is_exact``), or ``lo < t <= hi``, so ``lo``
    is a time of no contact that a simulation can safely advance to (``safe_time()``).
    """

    @property
    def lo(self) -> float:
        """A lower bound of the earliest contact time (strictly below it unless exact)."""
    @property
    def hi(self) -> float:
        """An upper bound of the earliest contact time."""
    @property
    def width(self) -> float:
        """``hi - lo``."""
    @property
    def is_exact(self) -> bool:
        """Whether the earliest contact time is exactly ``lo`` (``== hi``)."""
    def safe_time(self) -> Optional[float]:
        """The latest known time strictly before contact: ``lo``, or the float64 just below an
        exact contact time; ``None`` when contact is at ``t = 0`` (no time before it in the step).
        """
    def __eq__(self, value: object, /) -> bool: ...

@final
class MotionContacts:
    """What touches while two colliders move (``Collider.contacts_during``).

    ``pairs`` and ``first_pairs`` are lists of tuples, sorted as in Rust:
    ``("vertex_face", v, f)`` (a vertex of the first collider, a face of the second),
    ``("face_vertex", f, v)`` (a face of the first, a vertex of the second) and
    ``("edge_edge", (a0, a1), (b0, b1))`` (an edge of each, as its two vertices, smaller first).
    The same pairs as arrays: ``vertex_face`` and ``face_vertex`` ``(p, 2)`` int64,
    ``edge_edge`` ``(q, 2, 2)`` int64.
    """

    @property
    def pairs(self) -> List[_MotionPair]:
        """Every pair that touches at some ``t`` in ``[0, 1]``, sorted: a list of tuples."""
    @property
    def first_contact(self) -> Optional[ContactTime]:
        """The earliest contact of all (a ``ContactTime``, to the tolerance asked for); ``None``
        when nothing touches.
        """
    @property
    def first_pairs(self) -> List[_MotionPair]:
        """The pairs whose own first contact may be the earliest (those whose contact interval
        meets ``first_contact``'s), as tuples like ``pairs``.
        """
    @property
    def vertex_face(self) -> _Int64Array:
        """The ``("vertex_face", v, f)`` pairs as a ``(p, 2)`` int64 array of ``[v, f]``."""
    @property
    def face_vertex(self) -> _Int64Array:
        """The ``("face_vertex", f, v)`` pairs as a ``(p, 2)`` int64 array of ``[f, v]``."""
    @property
    def edge_edge(self) -> _Int64Array:
        """The ``("edge_edge", a, b)`` pairs as a ``(q, 2, 2)`` int64 array of ``[a, b]``."""
    def __len__(self) -> int: ...

@final
class StepContacts:
    """What touches during a step of a deforming mesh (``step_self_contacts``): ``vertex_face``
    ``(p, 2)`` int64 ``[vertex, face]`` pairs, ``edge_edge`` ``(q, 2, 2)`` int64 pairs of edges
    (each edge as its two vertices, smaller first; the smaller edge first), both sorted;
    ``first_contact`` (a ``ContactTime`` or ``None``); and how many pairs the swept boxes let
    through to the exact test (``vertex_face_candidates``, ``edge_edge_candidates``).
    """

    @property
    def vertex_face(self) -> _Int64Array:
        """``(p, 2)`` int64: ``[vertex, face]`` pairs that touch during the step, sorted."""
    @property
    def edge_edge(self) -> _Int64Array:
        """``(q, 2, 2)`` int64: pairs of edges that touch, sorted."""
    @property
    def first_contact(self) -> Optional[ContactTime]:
        """The earliest contact of all (a ``ContactTime``, to the tolerance asked for); ``None``
        when nothing touches.
        """
    @property
    def vertex_face_candidates(self) -> int:
        """How many vertex–face pairs the swept boxes let through to the exact test."""
    @property
    def edge_edge_candidates(self) -> int:
        """How many edge–edge pairs the swept boxes let through to the exact test."""

def vertex_face_touch(vertex: ArrayLike, face: ArrayLike) -> bool:
    """Whether the moving vertex (``(2, 3)``: start, end) and the moving closed triangle
    ``face`` (``(3, 2, 3)``: each corner's start and end) touch at some ``t`` in ``[0, 1]``,
    exactly (no tolerance; touching counts). A non-finite coordinate raises ``CgaError``.
    """
def edge_edge_touch(a: ArrayLike, b: ArrayLike) -> bool:
    """Whether the moving closed edges ``a`` and ``b`` (``(2, 2, 3)`` each: each end's
    start and end) touch at some ``t`` in ``[0, 1]``, exactly.
    """
def vertex_face_first_contact(
    vertex: ArrayLike, face: ArrayLike, tolerance: float = 1e-9
) -> Optional[ContactTime]:
    """The earliest time the moving vertex touches the moving triangle, a ``ContactTime`` at most
    ``tolerance`` wide (or as narrow as float64 allows; ``0.0`` for the narrowest), or ``None``
    if they never touch in ``[0, 1]``. A tolerance that is NaN or negative raises ``CgaError``.
    """
def edge_edge_first_contact(a: ArrayLike, b: ArrayLike, tolerance: float = 1e-9) -> Optional[ContactTime]:
    """The earliest time the moving edges ``a`` and ``b`` touch, a ``ContactTime`` (see
    ``vertex_face_first_contact`` for ``tolerance``), or ``None``.
    """
def vertex_face_touch_batch(points: ArrayLike) -> _BoolArray:
    """``vertex_face_touch`` for many queries in one call: ``points`` is ``(k, 4, 2, 3)``, each
    query the moving vertex then the triangle's three moving corners; returns a ``(k,)`` bool
    array. Answered over the cores with the GIL released.
    """
def edge_edge_touch_batch(points: ArrayLike) -> _BoolArray:
    """``edge_edge_touch`` for many queries in one call: ``points`` is ``(k, 4, 2, 3)``, each
    query the two ends of edge ``a`` then those of edge ``b``; returns a ``(k,)`` bool array.
    """
def vertex_face_first_contact_batch(points: ArrayLike, tolerance: float = 1e-9) -> _Float64Array:
    """``vertex_face_first_contact`` for many queries (``points`` as in
    ``vertex_face_touch_batch``): a ``(k, 2)`` float64 array of ``[lo, hi]``, NaN where the
    query never touches.
    """
def edge_edge_first_contact_batch(points: ArrayLike, tolerance: float = 1e-9) -> _Float64Array:
    """``edge_edge_first_contact`` for many queries (``points`` as in ``edge_edge_touch_batch``):
    a ``(k, 2)`` float64 array of ``[lo, hi]``, NaN where the query never touches.
    """
def step_self_contacts(
    vertices_start: ArrayLike, faces: ArrayLike, vertices_end: ArrayLike, tolerance: float = 1e-9
) -> StepContacts:
    """Every vertex–face and edge–edge contact of a mesh deforming over one step, exactly: the
    mesh is ``vertices_start`` (``(n, 3)``) and ``faces`` (``(m, 3)`` integers) at
    ``t = 0``, each vertex moving linearly to its row of ``vertices_end`` (``(n, 3)``)
    at ``t = 1``. Pairs that share a vertex are excluded. The first contact time is bounded to
    ``tolerance``. Returns a ``StepContacts``.
    """

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

"""Type stubs of cga_collide (the extension module `cga_collide._native`, re-exported)."""

from fractions import Fraction
from os import PathLike
from typing import List, Literal, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt
from numpy.typing import ArrayLike
from typing_extensions import Self, disjoint_base

from . import motion as motion
from .motion import MotionContacts

_Float64Array = npt.NDArray[np.float64]
_Int64Array = npt.NDArray[np.int64]
_BoolArray = npt.NDArray[np.bool_]
_Mode = Literal["bvh", "brute"]
_ContactClass = Literal["disjoint", "touching", "penetrating", "a_inside_b", "b_inside_a"]
_ContactKind = Literal["point", "segment", "polygon"]
_Contact = Tuple[Tuple[int, int], _ContactKind, _Float64Array]
_ExactPoint = Tuple[Fraction, Fraction, Fraction]
_Object = Union["Shape", "Collider"]
_Against = Literal["self", "environment", "both"]
_Kind = Literal["ball", "cuboid", "capsule", "cylinder", "cone", "halfspace", "convex", "triangle", "segment"]

ROTATION_TOLERANCE: float
"""How far a pose's 3x3 block may be from a rotation: max |RᵀR − I|."""

class CgaError(ValueError):
    """An input the library refused (a mesh, a file, a pose, a batch item, a scene handle): the message says what was wrong and where. A subclass of ValueError."""

@final
class Distance:
    """A certified distance between two meshes (their surfaces) or two shapes (the solids):
    ``distance`` is within ``error_bound`` of the true minimum distance; ``witness_a`` and
    ``witness_b`` are points of each (world coordinates) whose distance is ``distance``;
    ``triangles`` is the pair of triangle indices they lie on (``None`` for shapes, or when not
    known).
    """

    @property
    def distance(self) -> float:
        """The distance found (an upper bound, at most ``error_bound`` above the true distance)."""
    @property
    def error_bound(self) -> float:
        """The proved bound on ``|distance − true distance|``."""
    @property
    def witness_a(self) -> _Float64Array:
        """The witness point on the first mesh or shape, a ``(3,)`` float64 array."""
    @property
    def witness_b(self) -> _Float64Array:
        """The witness point on the second mesh or shape, a ``(3,)`` float64 array."""
    @property
    def triangles(self) -> Optional[Tuple[int, int]]:
        """The triangle pair of the witnesses, or ``None``."""
    def __float__(self) -> float: ...

@final
class PointDistances:
    """The signed distances of ``n`` points to a mesh, as arrays: ``signed_distance`` ``(n,)``
    (negative inside, ``0`` on the surface, which is inside), ``error_bound`` ``(n,)`` (the true
    distance is within it of ``|signed_distance|``, proved), ``inside`` ``(n,)`` bool (exact),
    ``nearest`` ``(n, 3)`` (the nearest surface point) and ``triangle`` ``(n,)`` int64 (its
    triangle).
    """

    @property
    def signed_distance(self) -> _Float64Array:
        """``(n,)`` float64: negative inside, ``0`` on the surface."""
    @property
    def error_bound(self) -> _Float64Array:
        """``(n,)`` float64."""
    @property
    def inside(self) -> _BoolArray:
        """``(n,)`` bool."""
    @property
    def nearest(self) -> _Float64Array:
        """``(n, 3)`` float64."""
    @property
    def triangle(self) -> _Int64Array:
        """``(n,)`` int64."""
    def __len__(self) -> int: ...

@final
class DistanceBatch:
    """The certified distances of a batch, as arrays: ``distance`` and ``error_bound`` ``(k,)``,
    ``witness_a`` and ``witness_b`` ``(k, 3)``, ``triangles`` ``(k, 2)`` int64 (``-1`` where not
    known).
    """

    @property
    def distance(self) -> _Float64Array:
        """``(k,)`` float64."""
    @property
    def error_bound(self) -> _Float64Array:
        """``(k,)`` float64."""
    @property
    def witness_a(self) -> _Float64Array:
        """``(k, 3)`` float64."""
    @property
    def witness_b(self) -> _Float64Array:
        """``(k, 3)`` float64."""
    @property
    def triangles(self) -> _Int64Array:
        """``(k, 2)`` int64, ``-1`` where not known."""
    def __len__(self) -> int: ...

@final
class Collider:
    """A triangle mesh built once (its box tree and the layout the pose queries read), and every
    question about it.

    Build it from arrays, ``Collider(vertices, faces)`` with vertices ``(n, 3)`` numbers and
    faces ``(m, 3)`` integers (0-based), or from a file with ``Collider.load(path)`` (.obj,
    .off, .ply, .stl, optionally .gz). Numbers float64 does not hold exactly, a wrong shape, a
    non-finite coordinate, an index out of range or an empty mesh raise ``CgaError`` (a
    ``ValueError``) naming the argument, vertex or face.

    Every question comes in the crate's three forms: in one frame ``a.x(b)``; under poses
    ``a.x_at(pose_a, b, pose_b)`` with ``(4, 4)`` homogeneous matrices; and many poses
    at once ``a.x_batch(b, poses_a, poses_b)`` with ``(k, 4, 4)`` arrays (either may be one
    ``(4, 4)`` pose used for every query), answered in one call with numpy arrays back. Yes/no
    answers are exact: touching counts as colliding, with no tolerance anywhere.

    ``mode`` is ``"bvh"`` (the default: box tree) or ``"brute"`` (every triangle): a choice of
    speed, never of answer.
    """

    def __new__(cls, vertices: ArrayLike, faces: ArrayLike, mode: _Mode = "bvh") -> Collider: ...
    @staticmethod
    def load(path: Union[str, PathLike[str]], mode: _Mode = "bvh") -> Collider:
        """Reads a mesh file (.obj, .off, .ply, .stl, each optionally .gz; the format from the
        extension) and builds its collider. Errors name the file and line (or byte).
        """
    @staticmethod
    def cuboid(lo: ArrayLike, hi: ArrayLike, mode: _Mode = "bvh") -> Collider:
        """An axis-aligned box from corner ``lo`` to corner ``hi`` (``(3,)`` each)."""
    def with_mode(self, mode: _Mode) -> Collider:
        """The same mesh and trees with another mode (``"bvh"`` or ``"brute"``)."""
    @property
    def mode(self) -> _Mode:
        """``"bvh"`` or ``"brute"``."""
    @property
    def vertices(self) -> _Float64Array:
        """The vertices, a fresh ``(n, 3)`` float64 array."""
    @property
    def faces(self) -> _Int64Array:
        """The faces, a fresh ``(m, 3)`` int64 array."""
    @property
    def num_triangles(self) -> int:
        """Number of triangles."""
    @property
    def bounds(self) -> _Float64Array:
        """The axis-aligned bounds of the mesh, ``(2, 3)`` float64: ``[min, max]``."""
    def is_closed(self) -> bool:
        """Whether the mesh is closed (every edge shared by exactly two triangles)."""
    # surfaces
    def collides(self, other: Collider) -> bool:
        """Whether the two surfaces touch (in one frame), exactly."""
    def collides_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> bool:
        """Whether the surfaces touch with ``self`` at ``pose_a`` and ``other`` at ``pose_b``
        (``(4, 4)`` homogeneous rigid motions).
        """
    def collides_batch(self, other: Collider, poses_a: ArrayLike, poses_b: ArrayLike) -> _BoolArray:
        """``collides_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
        (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array.
        """
    def intersecting_pairs(self, other: Collider) -> _Int64Array:
        """Every intersecting triangle pair ``(i, j)`` (``i`` in ``self``, ``j`` in ``other``),
        sorted, as a ``(p, 2)`` int64 array.
        """
    def intersecting_pairs_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> _Int64Array:
        """``intersecting_pairs`` under poses."""
    def intersecting_pairs_batch(
        self, other: Collider, poses_a: ArrayLike, poses_b: ArrayLike
    ) -> List[_Int64Array]:
        """``intersecting_pairs_at`` for every pose pair: a list of ``(p, 2)`` int64 arrays."""
    # solids
    def collides_solid(self, other: Collider) -> bool:
        """Whether the closed solids share a point (one may be inside the other), in one frame."""
    def collides_solid_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> bool:
        """``collides_solid`` under poses."""
    def collides_solid_batch(self, other: Collider, poses_a: ArrayLike, poses_b: ArrayLike) -> _BoolArray:
        """``collides_solid_at`` for every pose pair: a ``(k,)`` bool array."""
    def contains_point(self, p: ArrayLike) -> bool:
        """Whether the point ``p`` (``(3,)``, finite) is in the closed solid (on the surface
        counts). The mesh should be closed.
        """
    def contains_point_at(self, pose: ArrayLike, p: ArrayLike) -> bool:
        """``contains_point`` with the mesh at ``pose`` and ``p`` in world coordinates."""
    def signed_distance(self, points: ArrayLike) -> PointDistances:
        """The signed distance of every point of ``points`` (``(n, 3)``, finite) to the surface:
        negative inside, ``0`` on the surface (which is inside), with a proved error bound, the
        exact inside/outside (``contains_point``'s even–odd rule), the nearest point and its
        triangle (a ``PointDistances`` of arrays). Spread over the cores.
        """
    def signed_distance_at(self, pose: ArrayLike, points: ArrayLike) -> PointDistances:
        """``signed_distance`` with the mesh at ``pose`` and the points in world coordinates."""
    # distances
    def within_distance(self, other: Collider, c: float) -> bool:
        """Whether the surfaces come within distance ``c`` (closed: exactly ``c`` counts), exactly."""
    def within_distance_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike, c: float) -> bool:
        """``within_distance`` under poses."""
    def within_distance_batch(
        self, other: Collider, poses_a: ArrayLike, poses_b: ArrayLike, c: float
    ) -> _BoolArray:
        """``within_distance_at`` for every pose pair: a ``(k,)`` bool array."""
    def pairs_within_distance(self, other: Collider, c: float) -> _Int64Array:
        """Every triangle pair whose triangles come within ``c``, sorted, ``(p, 2)`` int64."""
    def pairs_within_distance_at(
        self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike, c: float
    ) -> _Int64Array:
        """``pairs_within_distance`` under poses."""
    def distance(self, other: Collider) -> Distance:
        """The certified minimum distance between the surfaces (a ``Distance``), in one frame."""
    def distance_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> Distance:
        """``distance`` under poses (witnesses in world coordinates)."""
    def distance_batch(self, other: Collider, poses_a: ArrayLike, poses_b: ArrayLike) -> DistanceBatch:
        """``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays."""
    def exact_distance(
        self, other: Collider
    ) -> Tuple[Fraction, _ExactPoint, _ExactPoint, Optional[Tuple[int, int]]]:
        """The exact minimum distance: ``(distance2, witness_a, witness_b, triangles)`` with the
        squared distance and the witnesses' coordinates as ``fractions.Fraction``.
        """
    # contacts
    def contact_class(self, other: Collider) -> _ContactClass:
        """How two closed meshes touch: ``"disjoint"``, ``"touching"``, ``"penetrating"``,
        ``"a_inside_b"`` or ``"b_inside_a"``.
        """
    def contact_class_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> _ContactClass:
        """``contact_class`` under poses."""
    def contacts(self, other: Collider) -> List[_Contact]:
        """Every intersecting triangle pair with its exact intersection: a list of
        ``((i, j), kind, points)`` with ``kind`` ``"point"``, ``"segment"`` or ``"polygon"`` and
        ``points`` a ``(c, 3)`` float64 array of its corners (nearest values of the exact ones).
        """
    def contacts_at(self, pose_a: ArrayLike, other: Collider, pose_b: ArrayLike) -> List[_Contact]:
        """``contacts`` under poses (world coordinates)."""
    # motion between two poses (continuous collision; see cga_collide.motion)
    def contacts_during(
        self, poses: ArrayLike, other: Collider, other_poses: ArrayLike, tolerance: float = 1e-9
    ) -> MotionContacts:
        """Every vertex–face and edge–edge pair of ``self`` and ``other`` that touches while
        ``self`` moves from ``poses[0]`` to ``poses[1]`` and ``other`` from ``other_poses[0]`` to
        ``other_poses[1]`` (``(2, 4, 4)`` arrays; each vertex moves linearly between its
        two placed positions), exactly, with the first contact time bounded to ``tolerance``.
        Returns a ``cga_collide.motion.MotionContacts``; a refused pose raises ``CgaError``.
        """
    # self-intersection
    def self_intersections(self) -> _Int64Array:
        """Every pair of non-adjacent triangles of the mesh that intersect, ``(p, 2)`` int64."""
    def self_intersects(self) -> bool:
        """Whether the mesh cuts itself."""
    # shapes
    def segment_hits(self, p: ArrayLike, q: ArrayLike) -> _Int64Array:
        """The triangles the closed segment ``p``–``q`` meets, an int64 array of indices."""
    def segment_hits_at(self, pose: ArrayLike, p: ArrayLike, q: ArrayLike) -> _Int64Array:
        """``segment_hits`` with the mesh at ``pose`` and the segment in world coordinates."""
    def triangle_hits(self, triangle_corners: ArrayLike) -> _Int64Array:
        """The triangles a triangle (``(3, 3)``, one corner per row) meets."""
    def triangle_hits_at(self, pose: ArrayLike, triangle_corners: ArrayLike) -> _Int64Array:
        """``triangle_hits`` with the mesh at ``pose``."""
    def sphere_hits(self, centre: ArrayLike, radius: float) -> _Int64Array:
        """The triangles the sphere surface (``centre`` ``(3,)``, ``radius``) meets."""
    def sphere_hits_at(self, pose: ArrayLike, centre: ArrayLike, radius: float) -> _Int64Array:
        """``sphere_hits`` with the mesh at ``pose``."""
    def ball_hits(self, centre: ArrayLike, radius: float) -> _Int64Array:
        """The triangles the solid ball (``centre`` ``(3,)``, ``radius``) meets."""
    def ball_hits_at(self, pose: ArrayLike, centre: ArrayLike, radius: float) -> _Int64Array:
        """``ball_hits`` with the mesh at ``pose``."""
    # solid primitives
    def shape_hits(self, shape: Shape) -> _Int64Array:
        """The triangles the closed ``shape`` (a ``Shape``) meets, an int64 array of indices, found
        through the box tree (the same as testing every triangle).
        """
    def shape_hits_at(self, pose: ArrayLike, shape: Shape, shape_pose: ArrayLike) -> _Int64Array:
        """``shape_hits`` with the mesh at ``pose`` and the shape placed by ``shape_pose``
        (``Shape.placed``'s rule).
        """
    def intersects_shape(self, shape: Shape) -> bool:
        """Whether the closed ``shape`` meets the surface (a shape inside a closed mesh does not)."""
    def intersects_shape_at(self, pose: ArrayLike, shape: Shape, shape_pose: ArrayLike) -> bool:
        """``intersects_shape`` under poses."""
    def intersects_shape_solid(self, shape: Shape) -> bool:
        """Whether the closed ``shape`` meets the closed solid of the mesh (inside counts). The
        mesh should be closed.
        """
    def intersects_shape_solid_at(self, pose: ArrayLike, shape: Shape, shape_pose: ArrayLike) -> bool:
        """``intersects_shape_solid`` under poses."""
    def shape_within_distance(self, shape: Shape, c: float) -> bool:
        """Whether the closed ``shape`` comes within distance ``c`` of the surface (closed:
        exactly ``c`` counts; ``c`` finite and at least 0), exactly.
        """
    def shape_within_distance_at(
        self, pose: ArrayLike, shape: Shape, shape_pose: ArrayLike, c: float
    ) -> bool:
        """``shape_within_distance`` under poses."""
    def distance_to_shape(self, shape: Shape) -> Distance:
        """The certified minimum distance between the surface and the closed ``shape`` (a
        ``Distance``: ``witness_a`` on the mesh, ``witness_b`` on the shape, ``triangles``
        ``(i, 0)`` with ``i`` the triangle of ``witness_a``).
        """
    def distance_to_shape_at(self, pose: ArrayLike, shape: Shape, shape_pose: ArrayLike) -> Distance:
        """``distance_to_shape`` under poses (witnesses in world coordinates)."""
    # bytes and pickling (the box tree travels with the collider, never rebuilt)
    def to_bytes(self) -> bytes:
        """The collider as bytes (mesh, mode, shape of the box tree); ``Collider.from_bytes``
        reads them back without rebuilding the tree.
        """
    @staticmethod
    def from_bytes(data: bytes) -> Collider:
        """A collider from ``to_bytes``' bytes, without rebuilding its tree."""
    def __reduce__(self) -> Tuple[object, Tuple[bytes]]: ...
    @staticmethod
    def _from_bytes(data: bytes) -> Collider:
        """The collider of bytes from ``__reduce__`` (the Rust ``Collider::to_bytes``), its tree
        not rebuilt; bad bytes raise ``CgaError``.
        """

@final
class ObjectId:
    """A handle to an object of a ``Scene``: hashable, comparable, with ``index`` (its slot:
    0, 1, 2, ... in the order objects are added to a fresh scene). A handle to a removed
    object is refused, never taken for the object that reused its slot.
    """

    @property
    def index(self) -> int:
        """The object's slot."""
    def __int__(self) -> int: ...
    def __hash__(self) -> int: ...
    def __eq__(self, value: object, /) -> bool: ...
    def __lt__(self, value: ObjectId, /) -> bool: ...
    def __le__(self, value: ObjectId, /) -> bool: ...
    def __gt__(self, value: ObjectId, /) -> bool: ...
    def __ge__(self, value: ObjectId, /) -> bool: ...

@final
class Scene:
    """Many objects, each a ``Collider`` (a mesh: its surface) or a ``Shape`` (a solid
    primitive) placed by a pose, and exact answers about every pair of them. One collider can
    be placed many times without copying. A broad phase (sweep and prune over world boxes)
    proposes pairs and each is decided exactly by the pair's pose queries, in parallel, with
    the GIL released.
    """

    def __init__(self) -> None:
        """Initialize self.  See help(type(self)) for accurate signature."""
    def __len__(self) -> int: ...
    def add(self, collider: Collider, pose: Optional[ArrayLike] = None) -> ObjectId:
        """Adds ``collider`` at ``pose`` (``(4, 4)``; ``None`` is the identity) and
        returns its ``ObjectId``. The collider is shared, not copied.
        """
    def add_shape(self, shape: Shape, pose: Optional[ArrayLike] = None) -> ObjectId:
        """Adds the solid ``shape`` (a ``Shape``) at ``pose`` (``(4, 4)``; ``None`` is the
        identity; ``Shape.placed``'s rule) and returns its ``ObjectId``.
        """
    def remove(self, object: ObjectId) -> Union[Collider, Shape]:
        """Removes an object and returns it (the Rust ``remove_object``): its ``Collider``, or its
        ``Shape`` (in its own frame).
        """
    def set_pose(self, object: ObjectId, pose: ArrayLike) -> None:
        """Moves an object to ``pose`` (``(4, 4)``)."""
    def set_poses(self, objects: Sequence[ObjectId], poses: ArrayLike) -> None:
        """Moves many objects at once: ``objects`` a sequence of ``ObjectId`` and ``poses`` a
        ``(k, 4, 4)`` array of the same length. Nothing moves if any pose is refused.
        """
    def pose(self, object: ObjectId) -> _Float64Array:
        """The pose of an object, a ``(4, 4)`` float64 array."""
    def collider(self, object: ObjectId) -> Collider:
        """The collider of a mesh object (``CgaError`` for a shape object)."""
    def shape(self, object: ObjectId) -> Shape:
        """The shape of a shape object, in its own frame (``CgaError`` for a mesh object)."""
    def kind(self, object: ObjectId) -> Union[Literal["mesh"], _Kind]:
        """What an object is: ``"mesh"``, or its shape's ``kind``."""
    def ids(self) -> List[ObjectId]:
        """The handles of every object, in slot order."""
    def exclude_pair(self, a: ObjectId, b: ObjectId) -> None:
        """Leaves the pair ``(a, b)`` out of every pair question (parts that touch by design)."""
    def include_pair(self, a: ObjectId, b: ObjectId) -> None:
        """Undoes ``exclude_pair``."""
    def set_groups(self, object: ObjectId, groups: int, mask: int) -> None:
        """Collision groups: a pair is tested only when each object's ``groups`` meet the other's
        ``mask`` (32-bit masks; by default every object is in every group).
        """
    def set_solid(self, solid: bool) -> None:
        """Whether pairs touch as closed solids (one inside the other counts) rather than
        surfaces.
        """
    def colliding_pairs(self) -> List[Tuple[ObjectId, ObjectId]]:
        """Every pair of objects ``(a, b)`` that touch (surfaces, or solids after ``set_solid``; a
        shape is always its solid), exactly, sorted, as a list of tuples of ``ObjectId``.
        """
    def colliding_with(self, object: ObjectId) -> List[ObjectId]:
        """Every object that touches ``object``, sorted."""
    def colliding_at(self, collider: Union[Collider, Shape], pose: ArrayLike) -> List[ObjectId]:
        """Every object that ``collider`` (a ``Collider`` or a ``Shape``) placed at ``pose`` would
        touch (it is not added).
        """
    def pairs_within_distance(self, c: float) -> List[Tuple[ObjectId, ObjectId]]:
        """Every pair of objects whose surfaces (a shape's solid) come within ``c`` (closed),
        sorted.
        """
    def nearest_pair(self) -> Optional[Tuple[ObjectId, ObjectId, Distance]]:
        """The nearest pair ``(a, b, Distance)``, or ``None`` with fewer than two objects that may
        be paired.
        """
    def nearest_to(self, object: ObjectId) -> Optional[Tuple[ObjectId, Distance]]:
        """The object nearest to ``object`` and the distance, ``(other, Distance)``, or ``None``."""
    def segment_hits(self, p: ArrayLike, q: ArrayLike) -> List[ObjectId]:
        """Every object whose surface the closed segment ``p``–``q`` meets, sorted."""

@final
class Robot:
    """A robot read from a URDF: links with their collision geometry (meshes in STL, OBJ, PLY
    or OFF, scaled; boxes, cylinders, spheres, capsules), joints (revolute, continuous,
    prismatic, fixed). A configuration is one value per movable joint in the order of
    ``joint_names``. Links joined by fixed joints are one body; adjacent bodies, an SRDF's
    ``disable_collisions`` and ``exclude_pair`` pairs are not tested. Meshes are surfaces (as
    in coal and pinocchio) unless ``set_solid(True)``. Pairs are named by link (sorted);
    environment objects as ``"env:<i>"``. ``against`` is ``"self"``, ``"environment"`` or
    ``"both"``. Every answer is exact for the placed parts; batches run over the cores with
    the GIL released.
    """

    @staticmethod
    def from_urdf(path: Union[str, PathLike[str]], package_dirs: Sequence[Union[str, PathLike[str]]] = ..., srdf: Optional[Union[str, PathLike[str]]] = None) -> Robot:
        """Reads the URDF at ``path``; ``package://`` paths are looked up in ``package_dirs``;
        an SRDF's ``disable_collisions`` pairs are left out when ``srdf`` is given.
        """
    @property
    def dof(self) -> int:
        """Number of movable joints (the length of a configuration)."""
    @property
    def joint_names(self) -> List[str]:
        """The movable joints' names, in configuration order."""
    @property
    def link_names(self) -> List[str]:
        """Every link's name, in URDF order."""
    @property
    def joint_limits(self) -> _Float64Array:
        """A ``(dof, 2)`` float64 array of lower and upper limits (``-inf, inf`` for a continuous
        joint). Limits are not enforced by the questions.
        """
    def allowed_pairs(self) -> List[Tuple[str, str]]:
        """The link pairs the self questions test."""
    def pairs_checked(self, against: _Against = "self") -> int:
        """How many pairs a question with ``against`` tests."""
    def exclude_pair(self, a: str, b: str) -> None:
        """Never tests links ``a`` and ``b`` against each other."""
    def set_solid(self, solid: bool) -> None:
        """Meshes are solids (``True``: a part inside a closed mesh touches it) or surfaces."""
    def set_environment(self, scene: Scene) -> None:
        """Takes the scene's objects, as placed now, as the environment (a snapshot)."""
    def link_poses(self, q: ArrayLike) -> _Float64Array:
        """Every link's world pose at ``q``: a ``(links, 4, 4)`` float64 array."""
    def collides(self, q: ArrayLike, against: _Against = "self") -> bool:
        """Whether any tested pair touches at ``q`` (a ``(dof,)`` array; stops at the first)."""
    def collides_batch(self, qs: ArrayLike, against: _Against = "self") -> _BoolArray:
        """``collides`` for each row of a ``(k, dof)`` array: a ``(k,)`` bool array."""
    def colliding_pairs(self, q: ArrayLike, against: _Against = "self") -> List[Tuple[str, str]]:
        """Every touching pair at ``q``: a sorted list of ``(name_a, name_b)``, names sorted."""
    def colliding_pairs_batch(self, qs: ArrayLike, against: _Against = "self") -> List[List[Tuple[str, str]]]:
        """``colliding_pairs`` for each row of a ``(k, dof)`` array."""
    def pairs_within_distance(self, q: ArrayLike, c: float, against: _Against = "self") -> List[Tuple[str, str]]:
        """Every pair within distance ``c`` at ``q`` (exact, closed), sorted."""
    def pairs_within_distance_batch(self, qs: ArrayLike, c: float, against: _Against = "self") -> List[List[Tuple[str, str]]]:
        """``pairs_within_distance`` for each row of a ``(k, dof)`` array."""
    def nearest(self, q: ArrayLike, against: _Against = "self") -> Optional[Tuple[Tuple[str, str], Distance]]:
        """The nearest tested pair at ``q``: ``((name_a, name_b), Distance)`` (certified, the
        witnesses in world coordinates, ``witness_a`` on ``name_a``), or ``None`` when nothing
        is tested.
        """
    def nearest_batch(self, qs: ArrayLike, against: _Against = "self") -> List[Optional[Tuple[Tuple[str, str], Distance]]]:
        """``nearest`` for each row of a ``(k, dof)`` array."""
    def motion_collision(self, q0: ArrayLike, q1: ArrayLike, against: _Against = "self", resolution: float = 1e-06, max_configurations: int = 100000) -> RobotMotion:
        """The straight motion from ``q0`` to ``q1`` (``(dof,)`` arrays): certified free, the
        earliest colliding configuration found, or undecided when ``resolution`` (the shortest
        stretch split, a fraction of the motion) or ``max_configurations`` runs out first: a
        ``RobotMotion``. Never misses a contact between samples.
        """
    def motion_collision_batch(self, q0s: ArrayLike, q1s: ArrayLike, against: _Against = "self", resolution: float = 1e-06, max_configurations: int = 100000) -> List[RobotMotion]:
        """``motion_collision`` for each row pair of two ``(k, dof)`` arrays, over the cores."""
    def __repr__(self) -> str: ...

@final
class RobotMotion:
    """The answer about the straight motion ``q(t) = (1 - t) q0 + t q1``, ``t`` in ``[0, 1]``:
    ``status`` is ``"free"`` (certified for every configuration of the motion, not only
    samples), ``"collides"`` (``configuration`` at ``time`` collides, exactly, with every
    touching pair in ``pairs``; the motion is certified free up to ``free_until``, so the first
    contact lies in ``[free_until, time]``) or ``"undecided"`` (``limit``, ``"resolution"`` or
    ``"configurations"``, ran out first; certified free up to ``free_until``).
    """

    @property
    def status(self) -> Literal["free", "collides", "undecided"]:
        """``"free"``, ``"collides"`` or ``"undecided"``."""
    @property
    def is_free(self) -> bool:
        """Whether the motion is certified free."""
    @property
    def time(self) -> Optional[float]:
        """The time of the colliding configuration, or ``None``."""
    @property
    def configuration(self) -> Optional[_Float64Array]:
        """The colliding configuration, a ``(dof,)`` float64 array, or ``None``."""
    @property
    def pairs(self) -> List[Tuple[str, str]]:
        """Every touching pair at the colliding configuration (sorted), else ``[]``."""
    @property
    def free_until(self) -> float:
        """The motion is certified free on ``[0, free_until]`` (``1.0`` when free)."""
    @property
    def limit(self) -> Optional[Literal["resolution", "configurations"]]:
        """Which budget left the motion undecided (``"resolution"`` or ``"configurations"``), or
        ``None``.
        """
    def __repr__(self) -> str: ...

MAX_MAGNITUDE: float
"""The largest magnitude a shape's coordinate, vector component or radius may have: 2^500."""

@disjoint_base
class Shape:
    """A solid primitive, the base class of ``Ball``, ``Cuboid``, ``Capsule``, ``Cylinder``,
    ``Cone``, ``HalfSpace``, ``ConvexHull``, ``Triangle`` and ``Segment`` (not built itself).

    Every shape is a closed set (touching counts) and is exactly the set that the float64
    numbers given describe, never rounded: a cuboid's corners are exact sums, a cylinder's rim
    is a true circle. Constructors take anything numpy reads as numbers that float64 holds
    exactly; a wrong array shape, a non-finite value, a value beyond ``MAX_MAGNITUDE``, a
    negative radius or a degenerate input the class refuses raise ``CgaError`` naming the
    argument.

    The module functions ``intersects``, ``within_distance`` and ``distance`` take any two
    shapes, in one frame, under poses (``_at``) and for many poses at once (``_batch``).
    Shapes are immutable, compare equal when built from the same numbers, and pickle.
    """

    def __eq__(self, value: object, /) -> bool: ...
    @property
    def kind(self) -> _Kind:
        """The kind's name, as the ``cga shapes`` command line's JSON spells it: ``"ball"``,
        ``"cuboid"``, ``"capsule"``, ``"cylinder"``, ``"cone"``, ``"halfspace"``, ``"convex"``,
        ``"triangle"`` or ``"segment"``.
        """
    def placed(self, pose: ArrayLike) -> Self:
        """This shape moved by ``pose`` (a ``(4, 4)`` rigid motion), as a shape of the same class,
        by the library's placement rule: each defining point is mapped and each defining vector
        rotated in float64, every coordinate rounded once, radii unchanged. Every ``_at`` and
        ``_batch`` answer is the answer for the shapes placed so. Raises ``CgaError`` when a
        placed value leaves the range or a cylinder's or cone's rounded axis ends coincide.
        """
    def __reduce__(self) -> Tuple[object, Tuple[object, ...]]: ...

@final
class Ball(Shape):
    """The closed solid ball of ``centre`` (``(3,)``) and ``radius`` (at least 0; ``0`` is the
    point).
    """

    def __new__(cls, centre: ArrayLike, radius: float) -> Ball: ...
    @property
    def centre(self) -> _Float64Array:
        """The centre, a ``(3,)`` float64 array."""
    @property
    def radius(self) -> float:
        """The radius."""

@final
class Cuboid(Shape):
    """The closed solid ``centre + s1 U + s2 V + s3 W`` with ``|si| <= 1``, for ``centre``
    (``(3,)``) and ``half_axes`` (``(3, 3)``, the half axes ``U``, ``V``, ``W`` as rows): a
    box when the half axes are orthogonal, the parallelepiped they span otherwise, and the
    flat parallelogram, segment or point they span when they are dependent.
    ``Cuboid.axis_aligned(centre, half_extents)`` is the axis-aligned box.
    """

    def __new__(cls, centre: ArrayLike, half_axes: ArrayLike) -> Cuboid: ...
    @staticmethod
    def axis_aligned(centre: ArrayLike, half_extents: ArrayLike) -> Cuboid:
        """The axis-aligned box ``centre ± half_extents`` (``(3,)`` each, every half extent at
        least 0).
        """
    @property
    def centre(self) -> _Float64Array:
        """The centre, a ``(3,)`` float64 array."""
    @property
    def half_axes(self) -> _Float64Array:
        """The half axes, a ``(3, 3)`` float64 array (one per row)."""

@final
class Capsule(Shape):
    """The points within ``radius`` (at least 0) of the closed segment ``a``–``b`` (``(3,)``
    each): a cylinder with round caps; ``a == b`` gives a ball, radius ``0`` the segment.
    """

    def __new__(cls, a: ArrayLike, b: ArrayLike, radius: float) -> Capsule: ...
    @property
    def a(self) -> _Float64Array:
        """The first end of the axis, a ``(3,)`` float64 array."""
    @property
    def b(self) -> _Float64Array:
        """The second end of the axis, a ``(3,)`` float64 array."""
    @property
    def radius(self) -> float:
        """The radius."""

@final
class Cylinder(Shape):
    """The closed solid cylinder of axis segment ``a``–``b`` (``(3,)`` each, distinct) and
    ``radius`` (at least 0), with flat caps: the discs at ``a`` and ``b`` perpendicular to
    ``b - a``. Radius ``0`` gives the segment.
    """

    def __new__(cls, a: ArrayLike, b: ArrayLike, radius: float) -> Cylinder: ...
    @property
    def a(self) -> _Float64Array:
        """The centre of the first cap, a ``(3,)`` float64 array."""
    @property
    def b(self) -> _Float64Array:
        """The centre of the second cap, a ``(3,)`` float64 array."""
    @property
    def radius(self) -> float:
        """The radius."""

@final
class Cone(Shape):
    """The closed solid cone of ``apex`` and the base disc of centre ``base`` (``(3,)`` each,
    distinct) and ``radius`` (at least 0), perpendicular to ``base - apex``: the convex hull
    of the apex and the disc. Radius ``0`` gives the segment ``apex``–``base``.
    """

    def __new__(cls, apex: ArrayLike, base: ArrayLike, radius: float) -> Cone: ...
    @property
    def apex(self) -> _Float64Array:
        """The apex, a ``(3,)`` float64 array."""
    @property
    def base(self) -> _Float64Array:
        """The centre of the base disc, a ``(3,)`` float64 array."""
    @property
    def radius(self) -> float:
        """The radius of the base disc."""

@final
class HalfSpace(Shape):
    """The closed half-space ``{x : (x - point)·normal <= 0}`` of ``point`` (``(3,)``, on the
    boundary plane) and ``normal`` (``(3,)``, outward, not zero; used as given, not
    normalised).
    """

    def __new__(cls, point: ArrayLike, normal: ArrayLike) -> HalfSpace: ...
    @property
    def point(self) -> _Float64Array:
        """A point of the boundary plane, a ``(3,)`` float64 array."""
    @property
    def normal(self) -> _Float64Array:
        """The outward normal as given, a ``(3,)`` float64 array."""

@final
class ConvexHull(Shape):
    """The closed convex hull of ``points`` (``(n, 3)``, at least one), exactly: points inside
    change nothing; one point, collinear or coplanar points give the point, segment or flat
    polygon they span.
    """

    def __new__(cls, points: ArrayLike) -> ConvexHull: ...
    @property
    def points(self) -> _Float64Array:
        """The points as given, a fresh ``(n, 3)`` float64 array."""
    @property
    def corners(self) -> _Float64Array:
        """The hull's corners, exactly (a point one ulp outside a face is a corner, one inside is
        not), a fresh ``(k, 3)`` float64 array: a flat polygon's in boundary order.
        """
    @property
    def triangles(self) -> _Int64Array:
        """For a solid hull, its boundary as triangles of row indices into ``corners``,
        counter-clockwise seen from outside, an ``(m, 3)`` int64 array; ``(0, 3)`` for a point,
        segment or flat polygon.
        """
    @property
    def dimension(self) -> int:
        """0 for a point, 1 for a segment, 2 for a flat polygon, 3 for a solid."""

@final
class Triangle(Shape):
    """The closed triangle ``abc`` (``(3,)`` each; collinear corners give the segment or point
    they span).
    """

    def __new__(cls, a: ArrayLike, b: ArrayLike, c: ArrayLike) -> Triangle: ...
    @property
    def vertices(self) -> _Float64Array:
        """The corners ``a``, ``b``, ``c`` as rows, a ``(3, 3)`` float64 array."""

@final
class Segment(Shape):
    """The closed segment ``a``–``b`` (``(3,)`` each; the point when they coincide)."""

    def __new__(cls, a: ArrayLike, b: ArrayLike) -> Segment: ...
    @property
    def a(self) -> _Float64Array:
        """The first end, a ``(3,)`` float64 array."""
    @property
    def b(self) -> _Float64Array:
        """The second end, a ``(3,)`` float64 array."""

def intersects(a: _Object, b: _Object) -> bool:
    """Whether ``a`` and ``b`` share a point, exactly (touching counts): each a ``Shape`` (a
    closed solid) or a ``Collider`` (its surface, as in the collider's own questions).
    ``CgaError`` if a value is out of range or the library has no exact test for the pair.
    """
def intersects_at(a: _Object, pose_a: ArrayLike, b: _Object, pose_b: ArrayLike) -> bool:
    """``intersects`` with ``a`` placed at ``pose_a`` and ``b`` at ``pose_b`` (``(4, 4)`` rigid
    motions; ``Shape.placed``'s rule for shapes).
    """
def intersects_batch(a: _Object, b: _Object, poses_a: ArrayLike, poses_b: ArrayLike) -> _BoolArray:
    """``intersects_at`` for every pose pair: ``poses_a`` and ``poses_b`` are ``(k, 4, 4)``
    (either may be one ``(4, 4)`` pose); returns a ``(k,)`` bool array. The first refused
    pose raises ``CgaError`` with its index.
    """
def within_distance(a: _Object, b: _Object, c: float) -> bool:
    """Whether ``a`` and ``b`` (shapes or colliders, as for ``intersects``) come within distance
    ``c`` (closed: exactly ``c`` counts), exactly. With a shape, ``c`` must be finite and at
    least 0; between two colliders, as ``Collider.within_distance``, only NaN is refused.
    """
def within_distance_at(a: _Object, pose_a: ArrayLike, b: _Object, pose_b: ArrayLike, c: float) -> bool:
    """``within_distance`` under poses."""
def within_distance_batch(
    a: _Object, b: _Object, poses_a: ArrayLike, poses_b: ArrayLike, c: float
) -> _BoolArray:
    """``within_distance_at`` for every pose pair: a ``(k,)`` bool array."""
def distance(a: _Object, b: _Object) -> Distance:
    """The certified minimum distance between ``a`` and ``b`` (shapes or colliders, as for
    ``intersects``; ``0`` when they meet), a ``Distance`` with a witness point on each.
    ``triangles`` is ``None`` for two shapes and holds ``0`` for a shape's side.
    """
def distance_at(a: _Object, pose_a: ArrayLike, b: _Object, pose_b: ArrayLike) -> Distance:
    """``distance`` under poses (witnesses in world coordinates)."""
def distance_batch(a: _Object, b: _Object, poses_a: ArrayLike, poses_b: ArrayLike) -> DistanceBatch:
    """``distance_at`` for every pose pair: a ``DistanceBatch`` of arrays."""

@final
class SignedDistance:
    """A certified signed distance between two shapes: ``value`` is the distance when they are
    apart and minus the penetration depth (the shortest translation of ``b`` that separates
    them) when they overlap; the true value is within ``error_bound`` of it. ``normal`` is the
    unit direction from ``a`` to ``b``: translating ``b`` by ``-value * normal`` makes them
    touch. ``witness_a`` and ``witness_b`` are points of each with
    ``(witness_b - witness_a) @ normal == value`` up to rounding. ``kind`` is ``"separated"``,
    ``"touching"`` or ``"penetrating"``, decided exactly.
    """

    @property
    def value(self) -> float:
        """The signed distance (negative when the shapes overlap)."""
    @property
    def error_bound(self) -> float:
        """The proved bound on ``|value − true signed distance|``."""
    @property
    def normal(self) -> _Float64Array:
        """The unit normal from ``a`` to ``b``, a ``(3,)`` float64 array."""
    @property
    def witness_a(self) -> _Float64Array:
        """The witness point of ``a``, a ``(3,)`` float64 array."""
    @property
    def witness_b(self) -> _Float64Array:
        """The witness point of ``b``, a ``(3,)`` float64 array."""
    @property
    def kind(self) -> str:
        """``"separated"``, ``"touching"`` or ``"penetrating"``."""
    def __float__(self) -> float: ...

def signed_distance(a: Shape, b: Shape) -> SignedDistance:
    """The certified signed distance of two shapes (``value < 0``: minus the penetration depth)."""
def signed_distance_at(a: Shape, pose_a: ArrayLike, b: Shape, pose_b: ArrayLike) -> SignedDistance:
    """``signed_distance`` of the shapes placed by their ``(4, 4)`` poses."""

@final
class ContactManifold:
    """The contact of two shapes (at most 4 points, one region): ``normal`` ``(3,)`` unit from
    ``a`` to ``b``; ``points`` ``(k, 3)`` halfway between ``points_a`` (on ``a``) and
    ``points_b`` (on ``b``, over ``points_a`` along the normal); ``distances`` ``(k,)``
    ``(points_b - points_a) @ normal`` (negative where they overlap); ``error_bounds`` ``(k,)``
    proved: when the shapes meet each point is within its bound of both shapes (in their
    intersection when it is 0), when apart ``points_a``/``points_b`` are within it of ``a``/``b``;
    ``signed_distance`` the pair's certified ``SignedDistance``.
    """

    @property
    def normal(self) -> _Float64Array:
        """The unit normal from ``a`` to ``b``, ``(3,)`` float64."""
    @property
    def points(self) -> _Float64Array:
        """The contact points, ``(k, 3)`` float64."""
    @property
    def points_a(self) -> _Float64Array:
        """The points on ``a``, ``(k, 3)`` float64."""
    @property
    def points_b(self) -> _Float64Array:
        """The points on ``b``, ``(k, 3)`` float64."""
    @property
    def distances(self) -> _Float64Array:
        """The signed distance of each point along the normal, ``(k,)`` float64."""
    @property
    def error_bounds(self) -> _Float64Array:
        """The proved bound of each point, ``(k,)`` float64."""
    @property
    def signed_distance(self) -> SignedDistance:
        """The pair's certified signed distance."""
    def __len__(self) -> int: ...

def contact_manifold(a: Shape, b: Shape, margin: float = 0.0) -> Optional[ContactManifold]:
    """The contact manifold of two shapes, or ``None`` when they are farther apart than
    ``margin`` (a finite distance ``>= 0``)."""
def contact_manifold_at(
    a: Shape, pose_a: ArrayLike, b: Shape, pose_b: ArrayLike, margin: float = 0.0
) -> Optional[ContactManifold]:
    """``contact_manifold`` of the shapes placed by their ``(4, 4)`` poses."""

def pose_from_degrees(degrees: ArrayLike, translation: Optional[ArrayLike] = None) -> _Float64Array:
    """The ``(4, 4)`` float64 pose that rotates by ``degrees[0]`` about the x axis, then by
    ``degrees[1]`` about the y axis, then by ``degrees[2]`` about the z axis (fixed axes,
    right-handed, counter-clockwise looking down the axis), then translates by ``translation``
    (``None`` for none): ``x -> Rz Ry Rx x + t``. The convention of the ``cga`` command line's
    ``--rotate`` and ``--translate`` and of the Rust ``pose_from_degrees``, so a pose written
    for one is the same pose in the other.
    """

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

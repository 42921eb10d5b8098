"""Collision between placed objects: a numpy box broad phase, then an fcl narrow phase.

The broad phase compares world bounding boxes (of the size box, grown to the mesh's extent
when a mesh pokes out of it) for many candidate poses at once. Pairs whose boxes overlap by
more than :data:`TOUCH` on every axis go to fcl: each mesh becomes one BVH model, built the
first time a pair with it reaches fcl (most never do: building all of them up front cost more
than the whole search on a sparse scene) and cached per mesh, and only its transform changes
per candidate; an object without a mesh
collides as its oriented size box. Boxes that only touch never collide, and a pair linked by
an ``on`` constraint (resting contact) is exempt. fcl tests a mesh's triangles, not the solid
they close, so an object wholly inside a mesh (a crate inside a building, a box inside a
cone) meets no triangle: when one broad box holds the other, a point of the inner object is
tested against the outer mesh by its winding number.

An object the solver will turn later (the source of a ``face to`` whose target is placed after
it) holds the room it turns in: a vertical cylinder around its shape, so any later yaw is as
collision-free as the pose that was checked.

Meshes are in the scene-frame asset frame (footprint centred, bottom at z = 0, front −Y) and
are treated as immutable once handed in.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING, Iterable, Mapping, Sequence

import fcl
import numpy as np

from scenewright.geometry import rotation_matrix
from scenewright.layout.relations import rotated_half, tilt_matrix
from scenewright.scene import Constraint, SceneObject, Vec3

if TYPE_CHECKING:  # any mesh with vertices, faces, bounds and triangles will do (an asset's AssetMesh)
    import trimesh

#: Overlap (m) below which two boxes are touching, not colliding: float round-off only, so a
#: pose the solver accepts never intersects by any independent check.
TOUCH = 1e-6

_BVH: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_TRIANGLES: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _bvh(mesh: trimesh.Trimesh) -> fcl.BVHModel:
    model = _BVH.get(mesh)
    if model is None:
        model = fcl.BVHModel()
        model.beginModel(len(mesh.vertices), len(mesh.faces))
        model.addSubModel(np.asarray(mesh.vertices, dtype=float), np.asarray(mesh.faces, dtype=np.int32))
        model.endModel()
        _BVH[mesh] = model
    return model


def _winding_number(mesh: trimesh.Trimesh, point: np.ndarray) -> float:
    """How many times ``mesh`` wraps ``point`` (1 inside a closed mesh, 0 outside): the sum of
    its triangles' signed solid angles (Van Oosterom and Strackee) over 4π."""
    triangles = _TRIANGLES.get(mesh)
    if triangles is None:
        triangles = _TRIANGLES[mesh] = np.asarray(mesh.triangles, dtype=float)
    a, b, c = (triangles[:, k] - point for k in range(3))
    la, lb, lc = (np.linalg.norm(v, axis=1) for v in (a, b, c))
    det = np.einsum("ij,ij->i", a, np.cross(b, c))
    dot = lambda u, v: np.einsum("ij,ij->i", u, v)  # noqa: E731
    div = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la
    return float(np.arctan2(det, div).sum() / (2.0 * np.pi))


#: Turns about z by yaw (degrees), kept: the solver tries the same few yaws for thousands of
#: candidate poses, and building each matrix anew was a sixth of a dense layout's time.
_TURNS: dict[float, np.ndarray] = {}
_TURNS_KEPT = 4096


def _yaw_rotation(tilt: np.ndarray | None, yaw: float) -> np.ndarray:
    """The turn by ``yaw`` after ``tilt`` (``None``: upright, no tilt); read-only, shared."""
    turn = _TURNS.get(yaw)
    if turn is None:
        if len(_TURNS) >= _TURNS_KEPT:
            _TURNS.clear()
        turn = _TURNS[yaw] = rotation_matrix(Vec3(z=yaw))
        turn.flags.writeable = False
    return turn if tilt is None else turn @ tilt


def resting_pairs(constraints: Iterable[Constraint]) -> set[frozenset[str]]:
    return {frozenset((c.source, c.target)) for c in constraints if c.relation == "on"}


class CollisionWorld:
    """The objects of one scene with their collision shapes; poses change, shapes do not."""

    def __init__(
        self,
        objects: Sequence[SceneObject],
        meshes: Mapping[str, trimesh.Trimesh] | None = None,
        exempt: set[frozenset[str]] = frozenset(),
    ):
        meshes = meshes or {}
        n = len(objects)
        self.ids = [o.id for o in objects]
        #: Each object's rotation without its yaw; the solver turns objects about z only.
        self.tilt = [tilt_matrix(o.rotation) for o in objects]
        self.upright = [bool(np.allclose(t, np.eye(3))) for t in self.tilt]
        #: Exactly untilted: its pose's rotation is the turn alone (the same floats as turn @ I).
        self.plain = [bool(np.array_equal(t, np.eye(3))) for t in self.tilt]
        self.local_half = np.zeros((n, 3))
        #: Translation from the box centre to the shape's origin, in the object's own frame.
        self.offset = np.zeros((n, 3))
        self.has_mesh = np.zeros(n, dtype=bool)
        #: Whether the shape is exactly the (tilted, turned) size box.
        self.is_box = np.zeros(n, dtype=bool)
        self.meshes: list[trimesh.Trimesh | None] = []
        #: fcl objects, made on first use by :meth:`_shape`; ``None`` until then.
        self.shapes: list[fcl.CollisionObject | None] = [None] * n
        #: Each object's last pose as (rotation, translation of the shape's origin).
        self.poses: list[tuple[np.ndarray, np.ndarray]] = [(np.eye(3), np.zeros(3))] * n
        for i, o in enumerate(objects):
            half = np.array(o.size.tuple()) / 2.0
            mesh = meshes.get(o.id)
            if mesh is not None and not len(mesh.faces):
                mesh = None
            self.meshes.append(mesh)
            if mesh is not None:
                self.has_mesh[i] = True
                self.offset[i] = (0.0, 0.0, -half[2])
                bounds = np.asarray(mesh.bounds) + self.offset[i]
                half = np.maximum(half, np.abs(bounds).max(axis=0))
            else:
                self.is_box[i] = True
            self.local_half[i] = half
        index = {x: i for i, x in enumerate(self.ids)}
        self.exempt = np.zeros((n, n), dtype=bool)
        for pair in exempt:
            if len(pair) == 2 and pair <= index.keys():
                a, b = (index[x] for x in pair)
                self.exempt[a, b] = self.exempt[b, a] = True
        self.placed = np.zeros(n, dtype=bool)
        self.lo = np.zeros((n, 3))
        self.hi = np.zeros((n, 3))
        self.axis_aligned = np.zeros(n, dtype=bool)

    def boxes(self, i: int, centres: np.ndarray, yaws: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Broad-phase boxes of object ``i`` at many poses."""
        half = rotated_half(self.local_half[i], self.tilt[i], yaws)
        return centres - half, centres + half

    def _aligned(self, i: int, yaw: float) -> bool:
        return self.is_box[i] and self.upright[i] and abs(yaw / 90.0 - round(yaw / 90.0)) < 1e-9

    def turning_room(self, i: int) -> None:
        """Make ``i``'s shape the vertical cylinder it sweeps turning about its centre."""
        mesh = self.meshes[i]
        if mesh is not None:
            points = np.asarray(mesh.vertices) @ self.tilt[i].T + self.tilt[i] @ self.offset[i]
        else:
            corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * self.local_half[i]
            points = corners @ self.tilt[i].T
        radius = float(np.max(np.hypot(points[:, 0], points[:, 1])))
        half_z = float(np.max(np.abs(points[:, 2])))
        self.shapes[i] = fcl.CollisionObject(fcl.Cylinder(radius, 2 * max(half_z - TOUCH, TOUCH)), fcl.Transform())
        self.meshes[i], self.has_mesh[i], self.is_box[i] = None, False, False
        self.tilt[i], self.upright[i], self.plain[i], self.offset[i] = np.eye(3), True, True, 0.0
        self.local_half[i] = (radius, radius, half_z)

    def _shape(self, i: int) -> fcl.CollisionObject:
        """``i``'s fcl object at its last pose, built now if no pair needed it before."""
        shape = self.shapes[i]
        if shape is None:
            mesh = self.meshes[i]
            if mesh is not None:
                geom = _bvh(mesh)
            else:
                geom = fcl.Box(*np.maximum(2 * self.local_half[i] - 2 * TOUCH, TOUCH))
            shape = self.shapes[i] = fcl.CollisionObject(geom, fcl.Transform(*self.poses[i]))
        return shape

    def _pose(self, i: int, centre: np.ndarray, yaw: float) -> None:
        r = _yaw_rotation(None if self.plain[i] else self.tilt[i], yaw)
        self.poses[i] = (r, np.asarray(centre, dtype=float) + r @ self.offset[i])
        if self.shapes[i] is not None:
            self.shapes[i].setTransform(fcl.Transform(*self.poses[i]))

    def place(self, i: int, centre: np.ndarray, yaw: float) -> None:
        lo, hi = self.boxes(i, np.asarray(centre, dtype=float)[None], np.array([yaw]))
        self.lo[i], self.hi[i] = lo[0], hi[0]
        self.axis_aligned[i] = self._aligned(i, yaw)
        self._pose(i, centre, yaw)
        self.placed[i] = True

    def remove(self, i: int) -> None:
        self.placed[i] = False

    def neighbours(self, i: int) -> np.ndarray:
        """Placed objects ``i`` can collide with (not itself, not a resting-contact partner)."""
        others = self.placed & ~self.exempt[i]
        others[i] = False
        return np.flatnonzero(others)

    def overlaps(self, idx: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """Broad phase: (poses × ``idx``) whether each pose's box overlaps each object's."""
        gap = np.minimum(hi[:, None, :], self.hi[idx][None]) - np.maximum(lo[:, None, :], self.lo[idx][None])
        return np.all(gap > TOUCH, axis=2)

    def colliders(self, i: int, centre: np.ndarray, yaw: float, candidates: Iterable[int]) -> list[int]:
        """Which of the broad-phase ``candidates`` object ``i`` really collides with at this pose."""
        hits = []
        posed = False
        request = fcl.CollisionRequest()
        aligned = self._aligned(i, yaw)
        box = None
        for j in candidates:
            if aligned and self.axis_aligned[j]:
                hits.append(int(j))  # two axis-aligned boxes: the broad phase was exact
                continue
            if not posed:
                self._pose(i, centre, yaw)
                posed = True
            if fcl.collide(self._shape(i), self._shape(int(j)), request, fcl.CollisionResult()):
                hits.append(int(j))
            elif self.has_mesh[i] or self.has_mesh[j]:  # boxes alone are solid to fcl
                if box is None:
                    box = [b[0] for b in self.boxes(i, np.asarray(centre, dtype=float)[None], np.array([yaw]))]
                lo, hi = box
                if (_holds(self.lo[j], self.hi[j], lo, hi) and self._inside(i, j)) or (
                    _holds(lo, hi, self.lo[j], self.hi[j]) and self._inside(j, i)
                ):
                    hits.append(int(j))
        return hits

    def _inside(self, inner: int, outer: int) -> bool:
        """Whether ``inner`` (posed) lies in the solid of ``outer``'s mesh, by one of its points:
        with no triangle crossing, one point inside means all of it is."""
        mesh = self.meshes[outer]
        if mesh is None:
            return False  # a box is solid to fcl: it has already seen this
        rotation, point = self.poses[inner]
        if self.meshes[inner] is not None:  # a vertex: a mesh's origin may lie outside it
            point = rotation @ self.meshes[inner].vertices[0] + point
        frame, origin = self.poses[outer]
        local = frame.T @ (point - origin)
        return _winding_number(mesh, local) > 0.5


def _holds(lo: np.ndarray, hi: np.ndarray, inner_lo: np.ndarray, inner_hi: np.ndarray) -> bool:
    return bool(np.all(lo <= inner_lo) and np.all(inner_hi <= hi))


def colliding_pairs(
    objects: Sequence[SceneObject],
    meshes: Mapping[str, trimesh.Trimesh] | None = None,
    constraints: Sequence[Constraint] = (),
) -> list[tuple[str, str]]:
    """Every pair of objects that intersects (meshes where given, boxes otherwise), sorted.

    A pair linked by an ``on`` constraint rests in contact and is not counted.
    """
    world = CollisionWorld(objects, meshes, resting_pairs(constraints))
    for i, o in enumerate(objects):
        world.place(i, np.array(o.position.tuple()), o.yaw)
    pairs = []
    for i in range(len(objects)):
        idx = world.neighbours(i)
        hit = world.overlaps(idx, world.lo[i : i + 1], world.hi[i : i + 1])
        later = idx[hit[0] & (idx > i)]
        for j in world.colliders(i, np.array(objects[i].position.tuple()), objects[i].yaw, later):
            pairs.append(tuple(sorted((world.ids[i], world.ids[j]))))
    return sorted(pairs)

"""Layout problems with planted solutions, for the benchmark and the property tests.

A problem is made by building a valid layout first: random furniture placed collision-free
in a square region sized for the count (tables with legs as real meshes, cones, boxes),
small objects stacked ``on`` tables and on each other, chairs turned to ``face to`` a table,
lamps hung ``above`` something. The constraints are relations that hold in that layout, each
from a later object to an earlier one (so they are acyclic), and the initial poses handed to
the solver are the planted ones perturbed. Every problem is therefore satisfiable.

:func:`hard_problem` is the same at arbitrary yaws, with two or more relations per object and
pairs of chairs facing each other (a facing cycle); :func:`dense_room` cuts a room into an
exact tiling and shrinks every tile to the floor share asked for, at yaws the solver must find.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from scenewright.geometry import world_box, yaw_towards
from scenewright.layout.relations import check, half_extents
from scenewright.scene import Constraint, SceneObject, Vec3

#: Relations tried when deriving optional constraints, in the order they are considered.
_OPTIONAL = ("near", "left of", "right of", "in front of", "behind", "side of", "far")
#: Clearance kept between planted objects so the planted layout never merely touches.
_CLEARANCE = 0.02


@dataclass
class Problem:
    objects: list[SceneObject]  # initial (perturbed) poses
    constraints: list[Constraint]
    bounds: tuple[float, float]
    meshes: dict[str, trimesh.Trimesh]
    solution: list[SceneObject]  # the planted layout


def table_mesh(size: Vec3, top: float = 0.05, leg: float = 0.06) -> trimesh.Trimesh:
    """A table in the scene-frame asset frame: a top slab on four corner legs."""
    x, y, z = size.tuple()
    parts = [trimesh.creation.box((x, y, top), trimesh.transformations.translation_matrix((0, 0, z - top / 2)))]
    for sx in (-1, 1):
        for sy in (-1, 1):
            at = (sx * (x - leg) / 2, sy * (y - leg) / 2, (z - top) / 2)
            parts.append(trimesh.creation.box((leg, leg, z - top), trimesh.transformations.translation_matrix(at)))
    return trimesh.util.concatenate(parts)


def cone_mesh(size: Vec3) -> trimesh.Trimesh:
    """A cone standing on z = 0 that fills the size box's footprint."""
    return trimesh.creation.cone(radius=min(size.x, size.y) / 2, height=size.z, sections=24)


class _Planter:
    """Builds the planted layout one object at a time, each clear of the ones before."""

    def __init__(self, n: int, rng: np.random.Generator, with_meshes: bool):
        self.rng = rng
        self.side = float(np.sqrt(n * 3.5) + 2.0)
        self.half = self.side / 2.0
        self.objects: list[SceneObject] = []
        self.meshes: dict[str, trimesh.Trimesh] = {}
        self.required: list[Constraint] = []
        self.tables: list[int] = []
        self.supports: list[int] = []  # objects with a flat top small things can go on
        self.with_meshes = with_meshes

    def _free(self, obj: SceneObject, support: str | None = None) -> bool:
        """Whether ``obj`` fits inside the region, clear of every planted object."""
        lo, hi = world_box(obj)
        if np.any(lo[:2] < -self.half) or np.any(hi[:2] > self.half):
            return False
        for other in self.objects:
            if other.id == support:
                continue
            olo, ohi = world_box(other)
            if np.all(np.minimum(hi, ohi) - np.maximum(lo, olo) > -_CLEARANCE):
                return False
        return True

    def _add(self, obj: SceneObject, mesh: trimesh.Trimesh | None = None) -> int:
        self.objects.append(obj)
        if mesh is not None and self.with_meshes:
            self.meshes[obj.id] = mesh
        return len(self.objects) - 1

    def _ground(self, oid: str, size: Vec3, yaw: float, tries: int = 60, near: SceneObject | None = None,
                facing: bool = True):
        for _ in range(tries):
            if near is None:
                xy = self.rng.uniform(-self.half, self.half, 2)
            else:
                xy = np.array(near.position.tuple()[:2]) + self.rng.normal(0, 1.2, 2)
            y = yaw if near is None or not facing else yaw_towards(xy, near.position.tuple()[:2])
            obj = SceneObject(id=oid, name=oid.rsplit("_", 1)[0], size=size, rotation=Vec3(z=y),
                              position=Vec3(x=xy[0], y=xy[1], z=size.z / 2))
            if self._free(obj):
                return obj
        return None

    def _table_yaw(self) -> float:
        return float(self.rng.choice([0.0, 90.0]))

    def table(self, k: int) -> None:
        r = self.rng
        size = Vec3(x=r.uniform(0.8, 2.0), y=r.uniform(0.6, 1.2), z=r.uniform(0.45, 0.9))
        obj = self._ground(f"table_{k}", size, self._table_yaw())
        if obj is not None:
            i = self._add(obj, table_mesh(size))
            self.tables.append(i)
            self.supports.append(i)

    def furniture(self, k: int) -> None:
        r = self.rng
        size = Vec3(x=r.uniform(0.3, 1.6), y=r.uniform(0.3, 1.2), z=r.uniform(0.3, 1.8))
        yaw = float(r.choice([0.0, 90.0, 180.0, 270.0])) if r.random() < 0.7 else float(r.uniform(-180, 180))
        cone = r.random() < 0.25
        if cone:
            size = Vec3(x=size.x, y=size.x, z=size.z)
        obj = self._ground(f"cabinet_{k}", size, yaw)
        if obj is not None:
            i = self._add(obj, cone_mesh(size) if cone else None)
            if not cone and size.z < 1.0:
                self.supports.append(i)

    def chair(self, k: int) -> None:
        if not self.tables:
            return self.furniture(k)
        target = self.objects[int(self.rng.choice(self.tables))]
        obj = self._ground(f"chair_{k}", Vec3(x=0.5, y=0.5, z=0.9), 0.0, near=target)
        if obj is not None:
            self._add(obj)
            self.required.append(Constraint(relation="face to", source=obj.id, target=target.id))

    def _over(self, base: SceneObject, margin: np.ndarray) -> np.ndarray:
        """A random plan point over ``base``'s true (turned) top, ``margin`` in from its edges."""
        a = np.radians(base.yaw)
        turn = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        foot = np.array([base.size.x, base.size.y]) / 2 - margin
        return turn @ self.rng.uniform(-foot, foot) + np.array(base.position.tuple()[:2])

    def small(self, k: int, yaw: float = 0.0) -> None:
        r = self.rng
        size = Vec3(x=r.uniform(0.1, 0.4), y=r.uniform(0.1, 0.4), z=r.uniform(0.05, 0.35))
        if not self.supports:
            return self.furniture(k)
        base = self.objects[int(r.choice(self.supports))]
        margin = np.full(2, np.hypot(size.x, size.y) / 2)  # holds the item at any yaw
        if np.any(np.array([base.size.x, base.size.y]) / 2 <= margin):
            return
        _, top = world_box(base)
        for _ in range(20):
            xy = self._over(base, margin)
            obj = SceneObject(id=f"item_{k}", name="item", size=size, rotation=Vec3(z=yaw),
                              position=Vec3(x=xy[0], y=xy[1], z=top[2] + size.z / 2))
            if self._free(obj, support=base.id):
                i = self._add(obj)
                self.required.append(Constraint(relation="on", source=obj.id, target=base.id))
                if r.random() < 0.5:
                    self.supports.append(i)  # stacked chains
                return

    def lamp(self, k: int) -> None:
        r = self.rng
        grounded = [o for o in self.objects if o.position.z == o.size.z / 2]
        if not grounded:
            return self.furniture(k)
        base = grounded[int(r.integers(len(grounded)))]
        size = Vec3(x=0.4, y=0.4, z=0.3)
        _, bhi = world_box(base)
        for _ in range(10):
            xy = self._over(base, np.zeros(2))
            obj = SceneObject(id=f"lamp_{k}", name="lamp", size=size,
                              position=Vec3(x=xy[0], y=xy[1], z=bhi[2] + 2.0 + r.uniform(0.05, 0.5) + size.z / 2))
            if self._free(obj):
                self._add(obj)
                self.required.append(Constraint(relation="above", source=obj.id, target=base.id))
                return


def planted_problem(n: int, seed: int = 0, *, with_meshes: bool = True, jitter: float = 0.4) -> Problem:
    """A satisfiable problem of about ``n`` objects (placement may leave out a few)."""
    rng = np.random.default_rng(seed)
    p = _Planter(n, rng, with_meshes)
    kinds = {"table": 0.18, "furniture": 0.37, "chair": 0.15, "small": 0.25, "lamp": 0.05}
    names, weights = list(kinds), np.array(list(kinds.values()))
    for k in range(n):
        getattr(p, str(rng.choice(names, p=weights / weights.sum())))(k)
    constraints = list(p.required)
    used = {c.key() for c in constraints}
    for s, src in enumerate(p.objects):
        for _ in range(int(rng.integers(0, 3))):
            if s == 0:
                break
            tgt = p.objects[int(rng.integers(0, s))]
            true = [r for r in _OPTIONAL if check(r, src, tgt)]
            if true:
                relation = true[0] if rng.random() < 0.5 else str(rng.choice(true))
                c = Constraint(relation=relation, source=src.id, target=tgt.id)
                if c.key() not in used:
                    used.add(c.key())
                    constraints.append(c)
    initial = []
    for obj in p.objects:
        xy = np.clip(np.array(obj.position.tuple()[:2]) + rng.normal(0, jitter, 2), -p.half, p.half)
        yaw = obj.yaw + (rng.normal(0, 20) if obj.id.startswith("chair") else 0.0)
        initial.append(obj.model_copy(update={
            "position": Vec3(x=xy[0], y=xy[1], z=obj.position.z + rng.normal(0, 0.05)),
            "rotation": Vec3(z=yaw),
        }))
    return Problem(initial, constraints, (p.side, p.side), p.meshes, p.objects)


class _HardPlanter(_Planter):
    """Every ground object at an arbitrary yaw; chairs in pairs facing each other; small things
    stacked anywhere on a turned support's true top."""

    def _table_yaw(self) -> float:
        return float(self.rng.uniform(-180, 180))

    def furniture(self, k: int) -> None:
        r = self.rng
        size = Vec3(x=r.uniform(0.3, 1.6), y=r.uniform(0.3, 1.2), z=r.uniform(0.3, 1.8))
        cone = r.random() < 0.2
        if cone:
            size = Vec3(x=size.x, y=size.x, z=size.z)
        obj = self._ground(f"cabinet_{k}", size, float(r.uniform(-180, 180)))
        if obj is not None:
            i = self._add(obj, cone_mesh(size) if cone else None)
            if not cone and size.z < 1.0:
                self.supports.append(i)

    def chair(self, k: int) -> None:
        """Two chairs facing each other (a couple at a table when there is one)."""
        r = self.rng
        size = Vec3(x=0.5, y=0.5, z=0.9)
        near = self.objects[int(r.choice(self.tables))] if self.tables and r.random() < 0.6 else None
        a = self._ground(f"chair_{k}a", size, float(r.uniform(-180, 180)), near=near, facing=False)
        if a is None:
            return
        for _ in range(40):
            turn, gap = r.uniform(0, 2 * np.pi), r.uniform(0.9, 2.6)
            xy = np.array(a.position.tuple()[:2]) + gap * np.array([np.cos(turn), np.sin(turn)])
            b = a.model_copy(update={"id": f"chair_{k}b", "position": Vec3(x=xy[0], y=xy[1], z=a.position.z),
                                     "rotation": Vec3(z=yaw_towards(xy, a.position.tuple()[:2]))})
            if not self._free(b):
                continue
            a = a.model_copy(update={"rotation": Vec3(z=yaw_towards(a.position.tuple()[:2], xy))})
            if not self._free(a):
                continue
            self._add(a)
            self._add(b)
            self.required += [Constraint(relation="face to", source=a.id, target=b.id),
                              Constraint(relation="face to", source=b.id, target=a.id)]
            return

    def small(self, k: int, yaw: float = 0.0) -> None:
        super().small(k, float(self.rng.uniform(-180, 180)))


def _relations(p: _Planter, rng: np.random.Generator, least: int, most: int) -> list[Constraint]:
    """The planted layout's required constraints and, per object, optional ones that hold, to
    earlier objects (nearer ones more often), until it has ``least`` to ``most`` relations."""
    constraints = list(p.required)
    used = {c.key() for c in constraints}
    count = {o.id: 0 for o in p.objects}
    for c in constraints:
        count[c.source] += 1
    centres = np.array([o.position.tuple()[:2] for o in p.objects]).reshape(-1, 2)
    for s, src in enumerate(p.objects[1:], start=1):
        want = int(rng.integers(least, most + 1)) - count[src.id]
        dist = np.linalg.norm(centres[:s] - centres[s], axis=1)
        weight = 1.0 / (0.5 + dist)
        for t in rng.choice(s, size=min(s, 8 * max(want, 0)), replace=False, p=weight / weight.sum()):
            if want <= 0:
                break
            tgt = p.objects[int(t)]
            true = [r for r in _OPTIONAL if check(r, src, tgt)]
            if not true:
                continue
            c = Constraint(relation=str(rng.choice(true)), source=src.id, target=tgt.id)
            if c.key() not in used:
                used.add(c.key())
                constraints.append(c)
                want -= 1
    return constraints


def _initial(p: _Planter, rng: np.random.Generator, jitter: float, turn) -> list[SceneObject]:
    """The planted poses perturbed: positions by ``jitter`` (m), yaws by ``turn(obj)`` degrees."""
    out = []
    for obj in p.objects:
        xy = np.clip(np.array(obj.position.tuple()[:2]) + rng.normal(0, jitter, 2), -p.half, p.half)
        out.append(obj.model_copy(update={
            "position": Vec3(x=xy[0], y=xy[1], z=obj.position.z + rng.normal(0, 0.05)),
            "rotation": Vec3(z=obj.yaw + turn(obj)),
        }))
    return out


def hard_problem(n: int, seed: int = 0, *, with_meshes: bool = True, jitter: float = 0.5) -> Problem:
    """A satisfiable problem of about ``n`` objects at arbitrary yaws, two or more relations each
    where the layout offers them, mutual facing pairs and stacks. Initial yaws are the planted
    ones, 20° off for chairs (their facing decides)."""
    rng = np.random.default_rng(seed)
    p = _HardPlanter(n, rng, with_meshes)
    kinds = {"table": 0.15, "furniture": 0.4, "chair": 0.1, "small": 0.3, "lamp": 0.05}
    names, weights = list(kinds), np.array(list(kinds.values()))
    k = 0
    while len(p.objects) < n and k < 3 * n:
        getattr(p, str(rng.choice(names, p=weights / weights.sum())))(k)
        k += 1
    constraints = _relations(p, rng, 2, 3)
    initial = _initial(p, rng, jitter, lambda o: rng.normal(0, 20) if o.id.startswith("chair") else 0.0)
    return Problem(initial, constraints, (p.side, p.side), p.meshes, p.objects)


def _tiling(width: float, depth: float, n: int, rng: np.random.Generator) -> list[tuple[float, float, float, float]]:
    """``n`` rectangles (x0, y0, x1, y1) that exactly tile a width × depth room centred at 0:
    the largest is cut across its longer side until there are ``n``."""
    tiles = [(-width / 2, -depth / 2, width / 2, depth / 2)]
    while len(tiles) < n:
        k = max(range(len(tiles)), key=lambda i: (tiles[i][2] - tiles[i][0]) * (tiles[i][3] - tiles[i][1]))
        x0, y0, x1, y1 = tiles.pop(k)
        f = rng.uniform(0.35, 0.65)
        if x1 - x0 >= y1 - y0:
            cut = x0 + f * (x1 - x0)
            tiles += [(x0, y0, cut, y1), (cut, y0, x1, y1)]
        else:
            cut = y0 + f * (y1 - y0)
            tiles += [(x0, y0, x1, cut), (x0, cut, x1, y1)]
    rng.shuffle(tiles)
    return tiles


def dense_room(n: int, coverage: float, seed: int = 0, *, jitter: float = 0.4) -> Problem:
    """``n`` boxes covering ``coverage`` of a room's floor: an exact tiling of the room with every
    tile shrunk about its centre to that share of its area. Each box stands at a quarter-turn
    yaw; the solver is handed it at a random quarter turn off, so it must search yaws."""
    if not 0.0 < coverage < 1.0:
        raise ValueError(f"coverage must be between 0 and 1, got {coverage}")
    rng = np.random.default_rng(seed)
    width, depth = 6.0, 5.0
    p = _Planter(n, rng, with_meshes=False)
    p.side, p.half = max(width, depth), max(width, depth) / 2  # for the jitter's clip only
    shrink = float(np.sqrt(coverage))
    for k, (x0, y0, x1, y1) in enumerate(_tiling(width, depth, n, rng)):
        quarter = int(rng.integers(4))
        w, d = (x1 - x0) * shrink, (y1 - y0) * shrink
        if quarter % 2:
            w, d = d, w  # turned a quarter, its own x runs along the room's y
        size = Vec3(x=w, y=d, z=float(rng.uniform(0.4, 2.0)))
        p.objects.append(SceneObject(id=f"box_{k}", name="box", size=size, rotation=Vec3(z=90.0 * quarter),
                                     position=Vec3(x=(x0 + x1) / 2, y=(y0 + y1) / 2, z=size.z / 2)))
    constraints = _relations(p, rng, 1, 2)
    initial = _initial(p, rng, jitter, lambda o: 90.0 * int(rng.integers(4)))
    for o in initial:  # inside the room
        half = half_extents(o.size, o.rotation)[:2]
        lim = np.maximum(np.array([width, depth]) / 2 - half, 0.0)
        o.position = Vec3(x=float(np.clip(o.position.x, -lim[0], lim[0])),
                          y=float(np.clip(o.position.y, -lim[1], lim[1])), z=o.position.z)
    return Problem(initial, constraints, (width, depth), {}, p.objects)

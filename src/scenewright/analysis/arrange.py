"""Initial poses from a parse: a first guess the layout solver starts from and refines.

The main object (the one most relations point at) stands at the origin. Every other object is
put where its strongest relation says — on its support, to the named side of its target,
within reach for ``near`` — in the order the relations allow (targets first), and pushed
outward until its footprint is clear of what is already there. Objects facing a target (and
seats next to one) are turned toward it. Objects the text relates to nothing are set in a ring
around the rest. The result is plausible on its own; the solver then enforces the relations
exactly and checks collisions on the meshes.
"""

from __future__ import annotations

import math
from collections import Counter, defaultdict

from scenewright.analysis.catalogue import load_catalogue
from scenewright.analysis.parser import ParsedObject, ParsedRelation, ParsedScene
from scenewright.geometry import front_direction, yaw_towards
from scenewright.scene import SceneObject, Vec3

#: Which relation decides where an object goes, strongest first.
_ANCHOR_ORDER = ("on", "above", "left of", "right of", "in front of", "behind", "side of", "near", "far")
#: Unit direction (x, y) from the target to the source, and the yaw that faces back at the target.
_SIDES = {"left of": ((-1.0, 0.0), 90.0), "right of": ((1.0, 0.0), -90.0),
          "in front of": ((0.0, -1.0), 180.0), "behind": ((0.0, 1.0), 0.0)}  # fmt: skip
_SEATS = {"chair", "armchair", "office_chair", "stool", "sofa", "bench"}
GAP = 0.3
FAR = 9.0
ABOVE = 2.05


class _Placed:
    __slots__ = ("d", "h", "w", "x", "y", "yaw", "z")

    def __init__(self, x: float, y: float, z: float, yaw: float, size: tuple[float, float, float]):
        self.x, self.y, self.z, self.yaw = x, y, z, yaw
        quarter = round(yaw / 90.0) % 2 == 1
        self.w, self.d, self.h = (size[1], size[0], size[2]) if quarter else size

    def overlaps(self, other: _Placed, margin: float = 0.05) -> bool:
        return (
            abs(self.x - other.x) < (self.w + other.w) / 2 + margin
            and abs(self.y - other.y) < (self.d + other.d) / 2 + margin
            and self.z - self.h / 2 < other.z + other.h / 2
            and other.z - other.h / 2 < self.z + self.h / 2
        )


def _main_object(parsed: ParsedScene) -> ParsedObject:
    incoming = Counter(r.target for r in parsed.relations)
    sources_on = {r.source for r in parsed.relations if r.relation in ("on", "above")}
    candidates = [o for o in parsed.objects if o.id not in sources_on] or parsed.objects
    order = {o.id: i for i, o in enumerate(parsed.objects)}
    return max(candidates, key=lambda o: (incoming[o.id], o.size[0] * o.size[1], -order[o.id]))


def _anchor(relations: list[ParsedRelation], flat: set[str]) -> ParsedRelation | None:
    """The relation that places the object; standing on a rug places it only when nothing else does,
    and facing something means standing in front of it when nothing else says where."""
    ranked = [r for r in relations if r.relation in _ANCHOR_ORDER and not (r.relation == "on" and r.target in flat)]
    if ranked:
        return min(ranked, key=lambda r: _ANCHOR_ORDER.index(r.relation))
    ranked = [r for r in relations if r.relation == "on"] or [r for r in relations if r.relation == "face to"]
    return ranked[0] if ranked else None


def _facing(obj: ParsedObject, relations: list[ParsedRelation], anchor: ParsedRelation | None) -> str | None:
    """The id the object should turn toward, if any."""
    for r in relations:
        if r.relation == "face to":
            return r.target
    if anchor is not None and anchor.relation in _SIDES and load_catalogue()[obj.category].shape in _SEATS:
        return anchor.target
    return None


def initial_objects(parsed: ParsedScene) -> list[SceneObject]:
    """Scene objects with a first pose for every object of the parse."""
    if not parsed.objects:
        return []
    by_id = {o.id: o for o in parsed.objects}
    outgoing: dict[str, list[ParsedRelation]] = defaultdict(list)
    for r in parsed.relations:
        outgoing[r.source].append(r)
    placed: dict[str, _Placed] = {}
    side_use: Counter[tuple[str, str]] = Counter()
    flat = {o.id for o in parsed.objects if o.size[2] < 0.1}
    faced_by: dict[str, list[str]] = defaultdict(list)
    for r in parsed.relations:
        if r.relation == "face to":
            faced_by[r.target].append(r.source)
    main = _main_object(parsed)
    placed[main.id] = _Placed(0.0, 0.0, main.size[2] / 2, 0.0, main.size)

    def place(obj: ParsedObject, trail: frozenset[str] = frozenset()) -> None:
        if obj.id in placed:
            return
        anchor = _anchor(outgoing[obj.id], flat)
        if anchor is not None and anchor.target not in placed and anchor.target not in trail:
            place(by_id[anchor.target], trail | {obj.id})
        if anchor is None or anchor.target not in placed:
            facer = next((f for f in faced_by[obj.id] if f in placed), None)
            if facer is None:
                placed[obj.id] = _free_spot(obj, placed)
                return
            # what something faces goes where that thing looks (its front, −Y at yaw 0)
            f = placed[facer]
            fx, fy = (float(v) for v in front_direction(f.yaw))
            reach = (f.d + max(obj.size[0], obj.size[1])) / 2 + 1.5
            p = _Placed(f.x + fx * reach, f.y + fy * reach, obj.size[2] / 2, _normal(f.yaw + 180.0), obj.size)
            placed[obj.id] = _push(p, (fx, fy), placed)
            return
        t = placed[anchor.target]
        facing = _facing(obj, outgoing[obj.id], anchor)
        rel = anchor.relation
        if rel in ("on", "above"):
            n = side_use[(anchor.target, rel)]
            side_use[(anchor.target, rel)] += 1
            dx, dy = _spread(n, t.w, t.d, obj.size)
            z = t.z + t.h / 2 + obj.size[2] / 2 + (ABOVE if rel == "above" else 0.0)
            placed[obj.id] = _Placed(t.x + dx, t.y + dy, z, t.yaw, obj.size)
            return
        if rel == "side of":
            rel = "left of" if side_use[(anchor.target, "left of")] <= side_use[(anchor.target, "right of")] else "right of"
        if rel == "near":
            rel = min(("right of", "left of", "behind", "in front of"), key=lambda s: side_use[(anchor.target, s)])
        if rel == "face to":
            rel = "in front of"
        if rel == "far":
            p = _Placed(t.x, t.y + t.d / 2 + FAR + obj.size[1] / 2, obj.size[2] / 2, 0.0, obj.size)
            placed[obj.id] = _push(p, (0.0, 1.0), placed)
            return
        (dx, dy), face_yaw = _SIDES[rel]
        yaw = face_yaw if facing == anchor.target else 0.0
        n = side_use[(anchor.target, rel)]
        side_use[(anchor.target, rel)] += 1
        probe = _Placed(0, 0, 0, yaw, obj.size)
        along = (probe.d if dx else probe.w) + GAP
        offset = along * ((n + 1) // 2) * (1 if n % 2 else -1)
        x = t.x + dx * ((t.w + probe.w) / 2 + GAP) + (0.0 if dx else offset)
        y = t.y + dy * ((t.d + probe.d) / 2 + GAP) + (offset if dx else 0.0)
        placed[obj.id] = _push(_Placed(x, y, obj.size[2] / 2, yaw, obj.size), (dx, dy), placed)
        _lay_under(obj, outgoing[obj.id], flat, placed, by_id)

    for obj in parsed.objects:
        place(obj)
    objects = []
    for obj in parsed.objects:
        p = placed[obj.id]
        yaw = p.yaw
        target = _facing(obj, outgoing[obj.id], _anchor(outgoing[obj.id], flat))
        if target is not None and target in placed and target != obj.id:
            q = placed[target]
            if (q.x, q.y) != (p.x, p.y):
                yaw = round(yaw_towards((p.x, p.y), (q.x, q.y)), 3)
        objects.append(
            SceneObject(
                id=obj.id,
                name=obj.name,
                category=obj.category,
                position=Vec3(x=round(p.x, 4), y=round(p.y, 4), z=round(p.z, 4)),
                rotation=Vec3(z=_normal(yaw)),
                size=Vec3.of(obj.size),
                visual_description=obj.description,
            )
        )
    return objects


def _lay_under(
    obj: ParsedObject, relations: list[ParsedRelation], flat: set[str], placed: dict[str, _Placed], by_id
) -> None:
    """A rug the object stands on goes under it, and the object onto the rug."""
    for r in relations:
        if r.relation == "on" and r.target in flat and r.target not in placed:
            p = placed[obj.id]
            rug = by_id[r.target]
            placed[r.target] = _Placed(p.x, p.y, rug.size[2] / 2, 0.0, rug.size)
            p.z += rug.size[2]
            return


def _normal(yaw: float) -> float:
    yaw = (yaw + 180.0) % 360.0 - 180.0
    return 0.0 if abs(yaw) < 1e-9 else yaw


def _spread(n: int, w: float, d: float, size: tuple[float, float, float]) -> tuple[float, float]:
    """Offset of the n-th thing put on one support: a small grid over its top."""
    if n == 0:
        return 0.0, 0.0
    cols = max(1, int(w // max(size[0] + 0.05, 0.05)))
    rows = max(1, int(d // max(size[1] + 0.05, 0.05)))
    slots = [(c, r) for r in range(rows) for c in range(cols)]
    c, r = slots[n % len(slots)]
    return (c + 0.5) * w / cols - w / 2, (r + 0.5) * d / rows - d / 2


def _push(p: _Placed, direction: tuple[float, float], placed: dict[str, _Placed]) -> _Placed:
    """Move along ``direction`` until the footprint is clear."""
    dx, dy = direction
    if dx == 0 and dy == 0:
        dx = 1.0
    for _ in range(200):
        if not any(p.overlaps(q) for q in placed.values()):
            return p
        p.x += dx * 0.25
        p.y += dy * 0.25
    return p


def _free_spot(obj: ParsedObject, placed: dict[str, _Placed], yaw: float = 0.0) -> _Placed:
    """The first clear spot on rings around the objects already placed."""
    if not placed:
        return _Placed(0.0, 0.0, obj.size[2] / 2, yaw, obj.size)
    xs = [q.x - q.w / 2 for q in placed.values()] + [q.x + q.w / 2 for q in placed.values()]
    ys = [q.y - q.d / 2 for q in placed.values()] + [q.y + q.d / 2 for q in placed.values()]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    radius = max(max(xs) - min(xs), max(ys) - min(ys)) / 2 + max(obj.size[0], obj.size[1]) / 2 + GAP
    step = max(0.5, max(obj.size[0], obj.size[1]) / 2)
    for ring in range(60):
        r = radius + ring * step
        count = max(8, int(2 * math.pi * r / max(step, 0.5)))
        for k in range(count):
            # start behind and to the sides, keeping the front (−Y, the viewer's side) open
            a = math.pi / 2 + (k // 2 + 1) * (2 * math.pi / count) * (1 if k % 2 else -1) if k else math.pi / 2
            p = _Placed(cx + r * math.cos(a), cy + r * math.sin(a), obj.size[2] / 2, yaw, obj.size)
            if not any(p.overlaps(q) for q in placed.values()):
                return p
    return _Placed(cx + radius + 60 * step, cy, obj.size[2] / 2, yaw, obj.size)

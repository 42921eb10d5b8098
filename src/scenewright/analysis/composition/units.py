"""The arranger's working state: objects grouped into units that move as one.

A unit starts as one connected group of related objects (or one object the text relates to
nothing) in its own frame. The composition rules join units — a chair to its desk, a
nightstand (with the lamp on it) to its bed — and finally set the units out on the ground.
Moving a whole unit keeps every relation inside it, because the text never relates
objects of different units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import Footprint, bbox, clear
from scenewright.analysis.parser import ParsedObject, ParsedRelation
from scenewright.layout import relations as rel
from scenewright.scene import SceneObject, Vec3


@dataclass
class Unit:
    root: str
    ids: list[str]
    #: Only the root and things resting on it: the unit may turn about its root.
    turnable: bool
    #: Joined to another unit by a rule; no longer placed on its own.
    merged: bool = False
    #: What rule made this unit a group (``desk``, ``bed``, ...), for repeated groups.
    group: str = ""
    partners: list[str] = field(default_factory=list)


class Layout:
    """Objects, relations, footprints and units of one arrangement."""

    def __init__(self, objects: list[ParsedObject], relations: list[ParsedRelation]):
        self.objects = objects
        self.by_id = {o.id: o for o in objects}
        self.relations = list(relations)
        self.placed: dict[str, Footprint] = {}
        self.units: list[Unit] = []
        self.unit_of: dict[str, Unit] = {}
        #: Rectangles (x0, y0, x1, y1) nothing scattered may stand on: aisles, roads, the way in.
        self.keep_free: list[tuple[float, float, float, float]] = []
        #: Units already set out on the ground (by ``id``), which later ones must keep clear of.
        self.settled: list[Unit] = []

    # --- questions ------------------------------------------------------------------------

    def kind(self, object_id: str) -> str:
        return roles.kind(self.by_id[object_id].category)

    def on_ground(self, object_id: str) -> bool:
        p = self.placed[object_id]
        return p.bottom < 0.05

    def ground_prints(self, ids) -> list[Footprint]:
        return [self.placed[i] for i in ids if self.on_ground(i) and self.by_id[i].size[2] >= 0.1]

    def free_units(self, kinds: frozenset[str]) -> list[Unit]:
        """Turnable units not joined to anything whose root is of one of ``kinds``, in text order."""
        return [u for u in self.units if not u.merged and u.turnable and self.kind(u.root) in kinds and not u.partners]

    def has_partner(self, host: str, kinds: frozenset[str]) -> bool:
        """Whether the text already relates something of ``kinds`` to ``host``."""
        return any(
            (r.target == host and self.kind(r.source) in kinds) or (r.source == host and self.kind(r.target) in kinds)
            for r in self.relations
            if r.relation not in ("on", "above")
        )

    def hosts(self, kinds: frozenset[str]) -> list[str]:
        """Objects of ``kinds`` standing on the ground, in text order."""
        return [o.id for o in self.objects if roles.kind(o.category) in kinds and self.on_ground(o.id)]

    def scene_object(self, object_id: str) -> SceneObject:
        obj, p = self.by_id[object_id], self.placed[object_id]
        return SceneObject(
            id=obj.id,
            name=obj.name,
            category=obj.category,
            position=Vec3(x=round(p.x, 4), y=round(p.y, 4), z=round(p.z, 4)),
            rotation=Vec3(z=round(p.yaw, 3)),
            size=Vec3.of(obj.size),
            visual_description=obj.description,
        )

    def relations_hold(self, ids: set[str]) -> bool:
        """Whether every relation touching ``ids`` holds at the current poses."""
        touched = [r for r in self.relations if r.source in ids or r.target in ids]
        need = {i for r in touched for i in (r.source, r.target)}
        objects = {i: self.scene_object(i) for i in need}
        return all(rel.check(r.relation, objects[r.source], objects[r.target]) for r in touched)

    def with_load(self, object_id: str) -> list[str]:
        """The object and everything resting on it, however high the stack."""
        out = [object_id]
        for i in out:
            out += [
                r.source for r in self.relations if r.relation in ("on", "above") and r.target == i and r.source not in out
            ]
        return out

    def box(self, unit: Unit) -> tuple[float, float, float, float]:
        return bbox(self.placed[i] for i in unit.ids)

    # --- moves ----------------------------------------------------------------------------

    def move(self, unit: Unit, dx: float, dy: float) -> None:
        for i in unit.ids:
            self.placed[i].x += dx
            self.placed[i].y += dy

    def turn(self, unit: Unit, yaw: float) -> None:
        """Turn a turnable unit about its root to ``yaw``."""
        root = self.placed[unit.root]
        delta = math.radians(yaw - root.yaw)
        c, s = math.cos(delta), math.sin(delta)
        for i in unit.ids:
            p = self.placed[i]
            rx, ry = p.x - root.x, p.y - root.y
            p.x, p.y = root.x + c * rx - s * ry, root.y + s * rx + c * ry
            p.turn(p.yaw + math.degrees(delta))

    def attach(self, member: Unit, host: Unit, x: float, y: float, yaw: float, away: tuple[float, float]) -> bool:
        """Join ``member`` to ``host`` with its root at (x, y) turned to ``yaw``, nudged along
        ``away`` until clear of the host's things; False (and nothing moved) if it never clears."""
        before = {i: (self.placed[i].x, self.placed[i].y, self.placed[i].yaw) for i in member.ids}
        self.turn(member, yaw)
        root = self.placed[member.root]
        self.move(member, x - root.x, y - root.y)
        others = self.ground_prints(host.ids)
        mine = self.ground_prints(member.ids)
        norm = math.hypot(*away) or 1.0
        step = (away[0] / norm * 0.1, away[1] / norm * 0.1)
        for _ in range(40):
            if all(clear(p, others) for p in mine):
                host.ids.extend(member.ids)
                member.merged = True
                host.partners.append(member.root)
                for i in member.ids:
                    self.unit_of[i] = host
                return True
            self.move(member, *step)
        for i, (px, py, pyaw) in before.items():
            self.placed[i].x, self.placed[i].y = px, py
            self.placed[i].turn(pyaw)
        return False

    def top_units(self) -> list[Unit]:
        return [u for u in self.units if not u.merged]

    def settled_prints(self) -> list[Footprint]:
        return [p for u in self.settled for p in self.ground_prints(u.ids)]

    def is_clear(self, unit: Unit, others: list[Footprint], margin: float = 0.05) -> bool:
        return all(clear(p, others, margin) for p in self.ground_prints(unit.ids))

    def settle(self, unit: Unit, direction: tuple[float, float] = (1.0, 0.0), step: float = 0.25) -> None:
        """Move ``unit`` along ``direction`` until clear of the settled units, and settle it."""
        others = self.settled_prints()
        norm = math.hypot(*direction) or 1.0
        for _ in range(400):
            if self.is_clear(unit, others):
                break
            self.move(unit, direction[0] / norm * step, direction[1] / norm * step)
        self.settled.append(unit)

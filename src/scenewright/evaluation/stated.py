"""What the text states, checked in the final layout: relations realised and supports right.

This reads the annotation of the text, never the constraints the analysis stage wrote, so a
relation the parser missed or got wrong counts as not realised. Relations are judged at key
level with the layout engine's own checks (:func:`scenewright.layout.check`): a relation holds
when every instance of the source satisfies it against at least one instance of the target
(another instance, when source and target are the same key). Two or more sides stated for one
pair (*on either side of* → left of + right of, *around* → the four sides) describe a group
spread round the target, which no single instance can satisfy alone: each such side holds when
some source instance stands on it while every instance stands on one of the stated sides.
*Between* holds when the source's centre projects inside the segment joining some pair of
target instances and lies within half the narrower target's width of it, so it stands in the
gap, not beside the pair.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from scenewright.evaluation.annotations import GROUND, UNCHECKED_SUPPORTS, Prompt, assign_keys
from scenewright.geometry import world_box
from scenewright.layout import check
from scenewright.layout.relations import Boxes, RoomTarget, holds, plan_gap, rest_share
from scenewright.scene import Scene, SceneObject

#: Metres a bottom may sit from z = 0 and still stand on the ground (as the physical metrics).
GROUND_TOLERANCE = 0.01


def supports(objects: Sequence[SceneObject]) -> dict[str, tuple[float, list[str]]]:
    """Object id → (bottom height, ids of the objects it rests on by the shared ``on`` check).

    All pairs at once through the layout engine's broadcasting check, so a 150-object scene
    costs one array operation rather than 22 000 single checks.
    """
    if not objects:
        return {}
    corners = [world_box(o) for o in objects]
    lo = np.array([c[0] for c in corners])
    hi = np.array([c[1] for c in corners])
    yaw = np.array([o.yaw for o in objects], dtype=float)
    rest = np.array([rest_share(o) for o in objects])
    on = holds("on", Boxes(lo[:, None], hi[:, None], yaw[:, None]), Boxes(lo[None], hi[None], yaw[None], rest=rest[None]))
    np.fill_diagonal(on, False)
    return {o.id: (float(lo[i, 2]), [objects[j].id for j in np.flatnonzero(on[i])]) for i, o in enumerate(objects)}


def on_ground(bottom: float, hosts: Sequence[str]) -> bool:
    """Bottom at ~0 and resting on no other object (a flat rug at 0 counts as ground)."""
    return abs(bottom) <= GROUND_TOLERANCE and not hosts


def between(source: SceneObject, a: SceneObject, b: SceneObject) -> bool:
    """The source's centre in plan lies in the gap of the pair ``a``–``b``."""
    centre = np.array([source.position.x, source.position.y])
    pa, pb = np.array([a.position.x, a.position.y]), np.array([b.position.x, b.position.y])
    axis = pb - pa
    length = float(np.linalg.norm(axis))
    if length <= 1e-9:
        return False
    axis /= length
    normal = np.array([-axis[1], axis[0]])
    along = float((centre - pa) @ axis)
    lateral = abs(float((centre - pa) @ normal))

    def width(obj: SceneObject) -> float:  # the target's footprint across the segment
        lo, hi = world_box(obj)
        return float(abs(normal[0]) * (hi[0] - lo[0]) + abs(normal[1]) * (hi[1] - lo[1]))

    return 0.0 <= along <= length and lateral <= min(width(a), width(b)) / 2.0


@dataclass
class Stated:
    """Relations the annotation states that hold, and supports that match it, in one layout."""

    realised: int = 0
    relations: int = 0
    supports_right: int = 0
    supports_checked: int = 0
    #: wall / ceiling / air → how many objects the annotation puts there unchecked (air always;
    #: wall and ceiling in a scene without a room)
    supports_skipped: dict[str, int] = field(default_factory=dict)
    not_realised: list[str] = field(default_factory=list)
    wrong_supports: list[str] = field(default_factory=list)
    #: Per instance of a thing stated beside, in front of or behind another, the plan gap (m) to
    #: the nearest instance of that other: a designer puts such things together, and the side
    #: checks alone accept a sink five metres down the wall from the rack it stands "next to".
    side_gaps: list[float] = field(default_factory=list)

    def to_dict(self) -> dict:
        return {
            "relations_realised": [self.realised, self.relations],
            "supports_right": [self.supports_right, self.supports_checked],
            "supports_skipped": dict(self.supports_skipped),
            "not_realised": self.not_realised,
            "wrong_supports": self.wrong_supports,
            "side_gaps": self.side_gaps,
        }


def _instances(scene: Scene, prompt: Prompt) -> dict[str, list[SceneObject]]:
    keys = assign_keys(((o.id, o.category, o.name) for o in scene.objects), prompt.objects)
    out: dict[str, list[SceneObject]] = {k: [] for k in prompt.objects}
    for obj in scene.objects:
        if obj.id in keys:
            out[keys[obj.id]].append(obj)
    return out


def _relation_holds(relation: str, sources: list[SceneObject], targets: list[SceneObject]) -> bool:
    return bool(sources) and all(any(t.id != s.id and check(relation, s, t) for t in targets) for s in sources)


#: Relations that name one side of the target; several for one pair place a group round it.
SIDES = ("left of", "right of", "in front of", "behind")
#: Relations that put the source beside the target (:attr:`Stated.side_gaps`).
BESIDE = (*SIDES, "side of")


def _side_holds(relation: str, sides: set[str], sources: list[SceneObject], targets: list[SceneObject]) -> bool:
    def on(side: str, s: SceneObject) -> bool:
        return any(t.id != s.id and check(side, s, t) for t in targets)

    return any(on(relation, s) for s in sources) and all(any(on(side, s) for side in sides) for s in sources)


def _between_holds(sources: list[SceneObject], first: list[SceneObject], second: list[SceneObject]) -> bool:
    return bool(sources) and all(
        any(len({s.id, a.id, b.id}) == 3 and between(s, a, b) for a in first for b in second) for s in sources
    )


def stated(scene: Scene, prompt: Prompt) -> Stated:
    """Check ``prompt``'s relations and supports in ``scene``'s layout."""
    found = _instances(scene, prompt)
    result = Stated(relations=prompt.stated)
    for source, relation, target in sorted(prompt.relations):
        sides = {r for s, r, t in prompt.relations if (s, t) == (source, target) and r in SIDES}
        if relation in sides and len(sides) > 1:
            held = _side_holds(relation, sides, found[source], found[target])
        else:
            held = _relation_holds(relation, found[source], found[target])
        if held:
            result.realised += 1
        else:
            result.not_realised.append(_why(f"{source} | {relation} | {target}", found, source, target))
    for source, first, second in sorted(prompt.between):
        if _between_holds(found[source], found[first], found[second]):
            result.realised += 1
        else:
            result.not_realised.append(_why(f"{source} | between | {first} | {second}", found, source, first, second))
    result.side_gaps = _side_gaps(prompt, found)
    resting = supports(scene.objects)
    room = None if scene.room is None else RoomTarget.of(scene.room)
    for key, objects in found.items():
        wanted = prompt.support_of(key)
        for obj in objects:
            # With a room, a wall or the ceiling is a support like any other; "air" stays unchecked.
            if wanted in UNCHECKED_SUPPORTS and (room is None or wanted not in ROOM_SUPPORTS):
                result.supports_skipped[wanted] = result.supports_skipped.get(wanted, 0) + 1
                continue
            result.supports_checked += 1
            bottom, hosts = resting[obj.id]
            if wanted in ROOM_SUPPORTS:
                right = bool(holds(ROOM_SUPPORTS[wanted], Boxes.of(obj), room))
                if not right:
                    result.wrong_supports.append(f"{obj.id}: wants the {wanted}, is not {ROOM_SUPPORTS[wanted]}")
                    continue
            elif wanted == GROUND:
                right = on_ground(bottom, hosts)
            else:
                right = any(h.id in hosts for h in found[wanted])
            if right:
                result.supports_right += 1
            else:
                actual = ", ".join(hosts) if hosts else f"bottom at {bottom:.2f} m"
                result.wrong_supports.append(f"{obj.id}: wants {wanted}, rests on {actual}")
    return result


def _side_gaps(prompt: Prompt, found: Mapping[str, list[SceneObject]]) -> list[float]:
    """Each source instance's plan gap to its nearest target instance, once per pair of keys
    related by a :data:`BESIDE` relation (the four sides of *around* count as one pair)."""
    pairs = dict.fromkeys((s, t) for s, r, t in sorted(prompt.relations) if r in BESIDE)
    return [
        round(min(plan_gap(s, t) for t in found[target] if t.id != s.id), 3)
        for source, target in pairs
        for s in found[source]
        if any(t.id != s.id for t in found[target])
    ]


#: Supports an annotation may name that a room provides, and the relation that checks each.
ROOM_SUPPORTS = {"wall": "on wall", "ceiling": "on ceiling"}


def _why(label: str, found: Mapping[str, list[SceneObject]], *keys: str) -> str:
    missing = [k for k in dict.fromkeys(keys) if not found[k]]
    return f"{label} (no {', '.join(missing)} in the scene)" if missing else label

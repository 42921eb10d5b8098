"""Placement priors for a scene with a room: what belongs on a wall, under the ceiling, against a wall.

One function, :func:`room_constraints`, applied to the constraints whichever backend wrote them
(a model writes "a mirror above the sink"; the paper's ``above`` means 2 m above, which no
mirror over a basin is): things hung on walls go ``on wall``, things hung from the ceiling go
``on ceiling``, and an ``above`` of theirs becomes ``near`` (the wall or ceiling gives the
height, the target the place); tall storage with nothing else placing it stands against a wall,
back to it. A thing the constraints already tie to the room, or stand on another, keeps that.
"""

from __future__ import annotations

from typing import Sequence

from scenewright.analysis.composition import roles
from scenewright.analysis.parser.room import CEILING_THINGS, WALL_THINGS
from scenewright.core.relations import ABOVE
from scenewright.scene import CEILING_TARGET, ROOM_RELATIONS, ROOM_TARGET, Constraint, SceneObject

#: Relations that place an object beside another: such a thing stands where they say, not at a wall.
_BESIDE = frozenset({"left of", "right of", "in front of", "behind", "side of"})


def room_constraints(objects: Sequence[SceneObject], constraints: Sequence[Constraint],
                     height: float | None = None) -> list[Constraint]:
    """``constraints`` with the room priors added (see the module docstring). Under a ceiling
    ``height`` m high, a thing ``above`` another that would reach past it (the paper's ``above``
    is :data:`ABOVE` over the target's top: "an oil lantern hangs above the desk") hangs from the
    ceiling near it instead."""
    kinds = {o.id: roles.kind(o.category) if o.category else None for o in objects}
    mounted = {o.id: ("on wall", ROOM_TARGET) for o in objects if o.category in WALL_THINGS}
    mounted |= {o.id: ("on ceiling", CEILING_TARGET) for o in objects if o.category in CEILING_THINGS}
    # What the text itself hangs on a wall or from the ceiling ("a lantern hangs from the ceiling").
    mounted |= {c.source: (c.relation, c.target) for c in constraints if c.relation in ("on wall", "on ceiling")}
    if height is not None:
        constraints = _hung_from_ceiling(objects, constraints, height, set(mounted))
    own: dict[str, set[str]] = {}
    for c in constraints:
        own.setdefault(c.source, set()).add(c.relation)
    out: list[Constraint] = []
    for c in constraints:
        if c.source in mounted and c.relation == "above":
            c = Constraint(relation="near", source=c.source, target=c.target)
        out.append(c)
    for o in objects:
        relations = own.get(o.id, set())
        if relations & set(ROOM_RELATIONS) or "on" in relations:
            continue
        if o.id in mounted:
            relation, target = mounted[o.id]
            out.append(Constraint(relation=relation, source=o.id, target=target))
        elif kinds[o.id] in roles.EDGE_STORAGE and not relations & (_BESIDE | {"above"}):
            out.append(Constraint(relation="against wall", source=o.id, target=ROOM_TARGET))
    return out


def _hung_from_ceiling(objects: Sequence[SceneObject], constraints: Sequence[Constraint], height: float,
                       mounted: set[str]) -> list[Constraint]:
    """Each ``above`` whose source would reach past a ``height`` m ceiling over its target, as
    ``on ceiling`` and ``near`` the target; things already mounted keep theirs (made ``near`` later)."""
    sizes = {o.id: o.size.z for o in objects}
    out: list[Constraint] = []
    for c in constraints:
        if (c.relation == "above" and c.source not in mounted and c.source in sizes and c.target in sizes
                and sizes[c.target] + ABOVE + sizes[c.source] > height):
            out += [Constraint(relation="on ceiling", source=c.source, target=CEILING_TARGET),
                    Constraint(relation="near", source=c.source, target=c.target)]
        else:
            out.append(c)
    return out

"""Placement priors for a scene with a room: what belongs on a wall, under the ceiling, against a wall.

One function, :func:`room_constraints`, applied to the constraints whichever backend wrote them:
things hung on walls go ``on wall``, things hung from the ceiling go ``on ceiling``; tall storage
stands against a wall, back to it, also where the text puts it beside another thing. A thing the
constraints already tie to the room, or stand on another, keeps that.

An ``above`` of a hung thing keeps the paper's meaning (its centre :data:`ABOVE` over the
target's) where the ceiling leaves room for it: a clock on the wall above a cabinet hangs on the
wall the cabinet stands against, over it, so the cabinet (or what it stands on) goes against a
wall too. Where the ceiling is too low ("a mirror above the sink": no mirror over a basin hangs
2 m up), the ``above`` becomes ``near``: the wall or ceiling gives the height, the target the
place. A room nobody gave a height is first made tall enough for what the text hangs above
another (:func:`ceiling_for`), up to :data:`TALLEST`.
"""

from __future__ import annotations

import math
from typing import Sequence

from scenewright.analysis.composition import roles
from scenewright.analysis.parser.room import CEILING_THINGS, hangs_by_kind
from scenewright.core.relations import ABOVE, OPPOSITE_SIDES
from scenewright.layout.relations import FLUSH, lowest_above, rest_share
from scenewright.scene import CEILING_TARGET, ROOM_RELATIONS, ROOM_TARGET, Constraint, SceneObject

#: m, the highest ceiling a room nobody gave a height is raised to for what hangs above another
#: (an old shop's or a townhouse's ceiling).
TALLEST = 3.6


def room_constraints(objects: Sequence[SceneObject], constraints: Sequence[Constraint],
                     height: float | None = None) -> list[Constraint]:
    """``constraints`` with the room priors added (see the module docstring). Under a ceiling
    ``height`` m high, a thing ``above`` another that would reach past it (the paper's ``above``
    is :data:`ABOVE` over the target's top: "an oil lantern hangs above the desk") hangs from the
    ceiling over it instead."""
    kinds = {o.id: roles.kind(o.category) if o.category else None for o in objects}
    constraints = _carried_not_mounted(constraints)
    backed = _backed(constraints)
    mounted = _mounted(objects, constraints)
    reach = _Reach(objects, constraints, mounted)
    if height is not None:
        constraints = _hung_from_ceiling(objects, constraints, height, set(mounted), reach)
    own: dict[str, set[str]] = {}
    sides: dict[str, dict[str, set[str]]] = {}
    for c in constraints:
        own.setdefault(c.source, set()).add(c.relation)
        sides.setdefault(c.source, {}).setdefault(c.relation, set()).add(c.target)
    out: list[Constraint] = []
    at_wall: set[str] = set()  # what a thing on the wall hangs above: it stands at that wall
    for c in constraints:
        if c.source in mounted and c.relation == "above":
            # (over a thing someone stands behind, off the wall, a thing on the wall is only near it:
            # "a sign hangs on the wall above the counter" with a waiter behind the counter)
            off_wall = mounted[c.source][0] == "on wall" and reach.ground(c.target) in backed
            if height is None or not reach.fits(c.source, c.target, height) or off_wall:
                c = Constraint(relation="near", source=c.source, target=c.target)
            elif mounted[c.source][0] == "on wall":
                at_wall.add(reach.ground(c.target))
        out.append(c)
    for o in objects:
        relations = own.get(o.id, set())
        if relations & set(ROOM_RELATIONS) or "on" in relations:
            continue
        if o.id in mounted:
            relation, target = mounted[o.id]
            out.append(Constraint(relation=relation, source=o.id, target=target))
        elif o.id in at_wall or (kinds[o.id] in roles.EDGE_STORAGE and "above" not in relations
                                 and not _between(sides.get(o.id, {})) and o.id not in backed):
            # Tall storage beside another thing stands at a wall all the same: "a bookshelf left
            # of the sofa" stands at the wall left of it, not in the middle of the floor. Between
            # two things it stands in their gap, wherever that is; with someone behind it (a
            # counter, "a baker waits behind it") it stands off the wall.
            out.append(Constraint(relation="against wall", source=o.id, target=ROOM_TARGET))
    return out




def _carried_not_mounted(constraints: Sequence[Constraint]) -> list[Constraint]:
    """``constraints`` without the wall or ceiling mounting of a thing that rests ``on`` another:
    its host carries it, and hangs in its place ("a birdcage with two parrots inside hangs from
    the ceiling": the parrots sit in the cage, not against the ceiling beside it)."""
    carried = {c.source for c in constraints if c.relation == "on"}
    return [c for c in constraints if not (c.source in carried and c.relation in ("on wall", "on ceiling"))]


def _between(sides: dict[str, set[str]]) -> bool:
    """Whether a thing's relations (relation → targets) put it on opposite sides of two things."""
    return any(sides.get(a, set()) and sides.get(b, set()) and sides[a] | sides[b] != sides[a] & sides[b]
               for a, b in OPPOSITE_SIDES)


def ceiling_for(objects: Sequence[SceneObject], constraints: Sequence[Constraint], height: float) -> float:
    """The ceiling height (m) a room nobody gave a height needs: ``height``, or more where a thing
    the text puts ``above`` another needs it to hang there by the paper's measure (a clock above
    a grandfather clock, a scroll above a tall rack), up to :data:`TALLEST`."""
    reach = _Reach(objects, constraints, _mounted(objects, constraints))
    wanted = [reach.top(c.source, c.target) + FLUSH for c in constraints
              if c.relation == "above" and reach.standing(c.source, c.target)]
    need = max([h for h in wanted if h <= TALLEST], default=height)
    return max(height, math.ceil(need * 20 - 1e-6) / 20)  # to 5 cm


def _backed(constraints: Sequence[Constraint]) -> set[str]:
    """What someone stands behind (a counter, "a baker waits behind it"): it stands off the wall."""
    return {c.target for c in constraints if c.relation == "behind"}


def _mounted(objects: Sequence[SceneObject], constraints: Sequence[Constraint]) -> dict[str, tuple[str, str]]:
    """Id → (relation, target) of each thing hung on a wall or from the ceiling: by its category,
    a flat thing above another on the wall over it ("a status screen above each pod", "a
    whiteboard above the bench"), or because the text itself hangs it there ("a lantern hangs
    from the ceiling"). Over a thing someone stands behind (a bar counter), which stands off the
    wall, a flat thing hangs from the ceiling ("neon signs hang above the counter")."""
    above = {c.source for c in constraints if c.relation == "above"}
    backed = _backed(constraints)
    over_backed = {c.source for c in constraints if c.relation == "above" and c.target in backed}
    hung = {o.id for o in objects if hangs_by_kind(o) or (o.id in above and _flat(o))}
    mounted = {i: ("on ceiling", CEILING_TARGET) if i in over_backed else ("on wall", ROOM_TARGET) for i in hung}
    mounted |= {o.id: ("on ceiling", CEILING_TARGET) for o in objects if o.category in CEILING_THINGS}
    return mounted | {c.source: (c.relation, c.target) for c in constraints if c.relation in ("on wall", "on ceiling")}


#: A thing no deeper than this share of its width, and than :data:`FLAT_DEPTH`, is a panel (a
#: screen, a board, a sign): above another it hangs on a wall, not from the ceiling.
FLAT_SHARE, FLAT_DEPTH = 0.35, 0.25


def _flat(o: SceneObject) -> bool:
    return o.size.y <= FLAT_SHARE * o.size.x and o.size.y <= FLAT_DEPTH and o.size.z >= 2 * o.size.y


class _Reach:
    """Where things stand by the ``on`` constraints (a sewing machine on a workbench stands at the
    bench's top), and how high a thing ``above`` another then reaches. A ``mounted`` target hangs
    where its wall or ceiling puts it, so nothing here says what is above it."""

    def __init__(self, objects: Sequence[SceneObject], constraints: Sequence[Constraint], mounted):
        self.size = {o.id: o.size.z for o in objects}
        self.rest = {o.id: rest_share(o) for o in objects}
        self.host = {c.source: c.target for c in constraints if c.relation == "on" and c.target in self.size}
        self.mounted = set(mounted)

    def standing(self, source: str, target: str) -> bool:
        """Whether both are known and ``target`` stands (on the floor or on others), not hung."""
        return source in self.size and target in self.size and self.ground(target) not in self.mounted

    def bottom(self, i: str) -> float:
        """The height of ``i``'s bottom: the rest height of its host, stacked."""
        z, seen = 0.0, {i}
        while i in self.host and self.host[i] not in seen:
            i = self.host[i]
            seen.add(i)
            z += self.rest[i] * self.size[i]
        return z

    def ground(self, i: str) -> str:
        """What ``i`` stands on, down to the floor: itself when it stands there."""
        seen = {i}
        while i in self.host and self.host[i] not in seen:
            i = self.host[i]
            seen.add(i)
        return i

    def load(self, i: str, seen: frozenset[str] = frozenset()) -> float:
        """How high the things stacked ``on`` ``i`` reach over its top (a rack's suitcases); a
        cycle of ``on`` (cleaned away later) stacks nothing twice."""
        seen = seen | {i}
        return max((self.size[s] + self.load(s, seen) for s, h in self.host.items() if h == i and s not in seen),
                   default=0.0)

    def top(self, source: str, target: str) -> float:
        """How high ``source``'s top reaches, with what stands on it, at its lowest ``above`` ``target``."""
        low = self.bottom(target)
        half = self.size[source] / 2.0
        return lowest_above(half, low, low + self.size[target]) + half + self.load(source)

    def fits(self, source: str, target: str, height: float) -> bool:
        """Whether ``source`` can hang ``above`` ``target`` under a ``height`` m ceiling."""
        return self.standing(source, target) and self.top(source, target) + FLUSH <= height


def _hung_from_ceiling(objects: Sequence[SceneObject], constraints: Sequence[Constraint], height: float,
                       mounted: set[str], reach: _Reach) -> list[Constraint]:
    """Each ``above`` whose source would reach past a ``height`` m ceiling over its target, as
    ``on ceiling`` over the target (``above``, where the ceiling leaves room for it; else ``near``);
    things already mounted keep theirs (their ``above`` is weighed later)."""
    sizes = reach.size
    out: list[Constraint] = []
    for c in constraints:
        if (c.relation == "above" and c.source not in mounted and c.source in sizes and c.target in sizes
                and sizes[c.target] + ABOVE + sizes[c.source] > height):
            over = "above" if reach.fits(c.source, c.target, height) else "near"
            out += [Constraint(relation="on ceiling", source=c.source, target=CEILING_TARGET),
                    Constraint(relation=over, source=c.source, target=c.target)]
        else:
            out.append(c)
    return out

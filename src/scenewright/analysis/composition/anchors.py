"""A group the text puts somewhere in the room moves there as one.

"A sofa stands at the back of the room", with a coffee table in front of it and armchairs
either side: a designer pushes the whole lounge back until the sofa meets the back wall, not the
sofa alone (which leaves the coffee table metres away). The arranger composes each group in its
own frame and records, per group, the member the text anchors and where (:func:`anchored`);
once the room is known, :func:`into_room` moves each such group as one so that its anchored
member reaches its anchor — its back to the back wall (``back`` and ``wall``: a wall no side
names is the back one, the wall the viewer faces), into the nearer back corner (``corner``) —
and steps what then pokes through a wall back inside, pushing the things of the group it meets
on along the same way, so the group keeps its arrangement and everything stands in the room.
(``centre`` needs no room: the arranger already stands that member at the origin, the middle of
every room it is given.)

Only the group moves: the arranger sets the other groups out beside or in front of an anchored
one, never behind it (``packing``), so they are not in its way.
"""

from __future__ import annotations

from collections.abc import Sequence

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import Footprint
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.core.protocols import AnchoredGroup
from scenewright.core.relations import BUFFER
from scenewright.scene import Room, SceneObject, Vec3

#: Anchors that send a group to the room's walls.
WALL_ANCHORS = frozenset({"back", "wall", "corner"})
#: m, how far off the wall an anchored member stands (a sofa's back does not touch the plaster).
WALL_CLEARANCE = 0.02
#: m, the room left between two things of a group pushed apart: what the relative relations
#: ask ("a plant behind the stand" stays behind it).
PUSH_GAP = BUFFER + 0.02
#: Rounds of pushing things of a group clear of each other; a group is a few things deep.
PUSH_ROUNDS = 12


def anchored(layout: Layout, unit: Unit) -> AnchoredGroup | None:
    """The unit's member the text anchors to a wall (``back``, ``wall``, ``corner``) and the
    unit's objects, when moving them as one matters: the unit holds more than its member's own
    stack, or the anchor is ``back`` (which no room relation places). The root is preferred,
    else the first anchored member standing on the ground, in text order. A counter the bar
    rule gave stools stands against a wall in a room all the same: it goes there with them."""
    standing = [i for i in unit.ids if layout.on_ground(i) and layout.by_id[i].size[2] >= 0.1]
    members = [i for i in [unit.root, *unit.ids] if i in standing and layout.by_id[i].anchor in WALL_ANCHORS]
    if not members:
        # a counter (storage's kind, which stands against a wall in a room) with the stools a
        # rule lined up before it: the bar goes to the wall with its stools
        root = unit.root
        if layout.kind(root) in roles.BARS & roles.EDGE_STORAGE and any(layout.kind(p) in roles.BAR_SEATS for p in unit.partners):
            return AnchoredGroup(member=root, anchor="wall", ids=tuple(unit.ids))
        return None
    member = members[0]
    anchor = layout.by_id[member].anchor
    if len(standing) == 1 and anchor != "back":
        return None  # one thing alone: its room relation ("against the wall") places it
    return AnchoredGroup(member=member, anchor=anchor, ids=tuple(unit.ids))


def into_room(objects: Sequence[SceneObject], room: Room, groups: Sequence[AnchoredGroup]) -> list[SceneObject]:
    """``objects`` with each anchored group moved as one to its anchor in ``room`` (see the
    module docstring); objects of no group keep their poses."""
    prints = {o.id: _print(o) for o in objects}
    xs, ys = [p[0] for p in room.floor], [p[1] for p in room.floor]
    lo, hi = (min(xs), min(ys)), (max(xs), max(ys))
    for g in groups:
        ids = [i for i in g.ids if i in prints]
        if g.member not in prints or g.anchor not in WALL_ANCHORS:
            continue
        m = prints[g.member]
        stacks = _stacks(ids, prints)
        dy = hi[1] - WALL_CLEARANCE - (m.y + m.d / 2)
        x0, _, x1, _ = _box([prints[i] for i in stacks])
        if g.anchor == "corner":
            left = m.x <= (x0 + x1) / 2
            dx = (lo[0] + WALL_CLEARANCE - (m.x - m.w / 2)) if left else (hi[0] - WALL_CLEARANCE - (m.x + m.w / 2))
        else:  # along the wall, as little as brings the whole group between the side walls
            dx = max(0.0, lo[0] + WALL_CLEARANCE - x0) - max(0.0, x1 - (hi[0] - WALL_CLEARANCE))
        for i in ids:
            prints[i].x += dx
            prints[i].y += dy
        _inside(g.member, stacks, prints, lo, hi)
    return [o.model_copy(update={"position": Vec3(x=round(prints[o.id].x, 4), y=round(prints[o.id].y, 4),
                                                  z=o.position.z)}) for o in objects]


def _print(o: SceneObject) -> Footprint:
    return Footprint(o.position.x, o.position.y, o.position.z, o.rotation.z, (o.size.x, o.size.y, o.size.z))


def _box(prints: Sequence[Footprint]) -> tuple[float, float, float, float]:
    return (min(p.x - p.w / 2 for p in prints), min(p.y - p.d / 2 for p in prints),
            max(p.x + p.w / 2 for p in prints), max(p.y + p.d / 2 for p in prints))


def _stacks(ids: Sequence[str], prints: dict[str, Footprint]) -> dict[str, list[str]]:
    """Each thing of the group standing on the floor, with what stands over it (a TV on its
    stand, a vase on the table): they move together. Flat things (a rug) stay where they lie."""
    ground = [i for i in ids if prints[i].bottom < 0.05 and prints[i].h >= 0.1]
    stacks = {i: [i] for i in ground}
    for i in ids:
        p = prints[i]
        if i in stacks or p.bottom < 0.05:
            continue
        under = [g for g in ground if abs(p.x - prints[g].x) <= prints[g].w / 2 and abs(p.y - prints[g].y) <= prints[g].d / 2
                 and prints[g].bottom < p.bottom]
        if under:
            stacks[min(under, key=lambda g: p.bottom - (prints[g].z + prints[g].h / 2))].append(i)
    return stacks


def _into(p: Footprint, lo: tuple[float, float], hi: tuple[float, float]) -> tuple[float, float]:
    """The step (dx, dy) that brings a footprint poking through a wall back inside."""
    return (max(0.0, lo[0] + WALL_CLEARANCE - (p.x - p.w / 2)) - max(0.0, p.x + p.w / 2 - (hi[0] - WALL_CLEARANCE)),
            max(0.0, lo[1] + WALL_CLEARANCE - (p.y - p.d / 2)) - max(0.0, p.y + p.d / 2 - (hi[1] - WALL_CLEARANCE)))


def _move(stack: list[str], prints: dict[str, Footprint], dx: float, dy: float) -> None:
    for i in stack:
        prints[i].x += dx
        prints[i].y += dy


def _inside(member: str, stacks: dict[str, list[str]], prints: dict[str, Footprint],
            lo: tuple[float, float], hi: tuple[float, float]) -> None:
    """Step each stack that pokes through a wall back inside (and along the wall off the anchored
    member, if it lands on it), then push the stacks it now meets on the same way, round by
    round (the anchored member, at its wall, stays)."""
    moved: dict[str, tuple[float, float]] = {}
    m = prints[member]
    for k, stack in stacks.items():
        p = prints[k]
        dx, dy = _into(p, lo, hi)
        if not (dx or dy):
            continue
        _move(stack, prints, dx, dy)
        if k != member and p.overlaps(m, PUSH_GAP):
            # stepped in onto the anchored member (a piano behind a lamp beside the sofa, now at
            # the wall the sofa stands at): along the wall, off the member's nearer end
            along = 0 if abs(dy) >= abs(dx) else 1
            centre, half, m_centre, m_half = ((p.x, p.w / 2, m.x, m.w / 2) if along == 0 else (p.y, p.d / 2, m.y, m.d / 2))
            side = 1.0 if centre >= m_centre else -1.0
            shift = m_centre + side * (m_half + PUSH_GAP + half) - centre
            _move(stack, prints, *((shift, 0.0) if along == 0 else (0.0, shift)))
            back = _into(p, lo, hi)[along]
            if back:  # no room at that end: the other one
                shift = m_centre - side * (m_half + PUSH_GAP + half) - (centre + shift)
                _move(stack, prints, *((shift, 0.0) if along == 0 else (0.0, shift)))
        moved[k] = (dx, dy)
    for _ in range(PUSH_ROUNDS):
        pushed: dict[str, tuple[float, float]] = {}
        for k, (dx, dy) in moved.items():
            a = prints[k]
            for j in stacks:
                b = prints[j]
                ahead = (b.y - a.y) * dy > 0 if abs(dy) >= abs(dx) else (b.x - a.x) * dx > 0
                if j in (k, member) or j in pushed or not ahead or not a.overlaps(b, PUSH_GAP):
                    continue
                # on along the way ``a`` came, just far enough to clear it
                if abs(dy) >= abs(dx):
                    step = (0.0, (a.y - a.d / 2 - PUSH_GAP - (b.y + b.d / 2)) if dy < 0 else (a.y + a.d / 2 + PUSH_GAP - (b.y - b.d / 2)))
                else:
                    step = ((a.x - a.w / 2 - PUSH_GAP - (b.x + b.w / 2)) if dx < 0 else (a.x + a.w / 2 + PUSH_GAP - (b.x - b.w / 2)), 0.0)
                _move(stacks[j], prints, *step)
                pushed[j] = step
        if not pushed:
            return
        moved = pushed

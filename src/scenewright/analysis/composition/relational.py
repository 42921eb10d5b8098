"""Where the text puts things: first poses from the parser's relations, one connected group
of related objects at a time, in that group's own frame.

The group's main object (the one most relations point at) stands at the origin. Every other
object goes where its strongest relation says — on its support, to the named side of its
target, within reach for ``near`` — targets first, and is pushed outward until its footprint
is clear. Objects facing a target, and seats beside one, are turned toward it. Where a
relation leaves a degree free, the roles decide: a seat near a desk or table, and a person near
what they work at, pull up in front of it, a nightstand beside a bed stands at the bed's head.
"""

from __future__ import annotations

import math
from collections import Counter, defaultdict
from collections.abc import Callable
from dataclasses import replace

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import GAP, Footprint, clear, fits_across, push
from scenewright.analysis.composition.packing import HIDE_MARGIN
from scenewright.analysis.parser import ParsedObject, ParsedRelation
from scenewright.geometry import front_direction, yaw_towards
from scenewright.layout import relations as rel
from scenewright.scene import SceneObject, Vec3

#: Which relation decides where an object goes, strongest first.
ANCHOR_ORDER = ("on", "above", "left of", "right of", "in front of", "behind", "side of", "near", "far")
#: Unit direction (x, y) from the target to the source, and the yaw that faces back at the target.
SIDES = {"left of": ((-1.0, 0.0), 90.0), "right of": ((1.0, 0.0), -90.0),
         "in front of": ((0.0, -1.0), 180.0), "behind": ((0.0, 1.0), 0.0)}  # fmt: skip
#: Sides tried, least used first, for ``near``: a seat near a desk or table pulls up in front.
NEAR_SIDES = ("right of", "left of", "behind", "in front of")
SEAT_NEAR_SIDES = ("in front of", "behind", "left of", "right of")
#: Where the target of a relation stands from its source.
INVERSE = {"left of": "right of", "right of": "left of", "in front of": "behind", "behind": "in front of",
           "side of": "right of", "near": "right of"}  # fmt: skip
FAR = 9.0
#: m, the depth past which a tall thing's side is mostly out of the viewer's sight: what stands
#: beside it stands by its front corner.
FRONT_CORNER_DEPTH = 3.0
ABOVE = 2.05
#: m, the least width of a seat that makes a table turn its long side to it (a bench, a sofa).
LONG_SEAT = 1.2
#: How many things facing one target make a ring, and the least footprint (m²) of a member placed
#: after the target's other neighbours (a tent, a market stall; not a chair or a person).
RING, RING_WIDE = 3, 2.0

#: Places an object the relations leave unplaced next to what is already there.
FreeSpot = Callable[[ParsedObject, dict[str, Footprint]], Footprint]


def main_object(objects: list[ParsedObject], relations: list[ParsedRelation]) -> ParsedObject:
    """The object the others gather around: most pointed at, not resting on anything, largest."""
    incoming = Counter(r.target for r in relations)
    sources_on = {r.source for r in relations if r.relation in ("on", "above")}
    candidates = [o for o in objects if o.id not in sources_on] or objects
    order = {o.id: i for i, o in enumerate(objects)}
    return max(candidates, key=lambda o: (incoming[o.id], o.size[0] * o.size[1], -order[o.id]))


def anchor(relations: list[ParsedRelation], flat: set[str]) -> ParsedRelation | None:
    """The relation that places the object; standing on a rug places it only when nothing else does,
    and facing something means standing in front of it when nothing else says where."""
    ranked = [r for r in relations if r.relation in ANCHOR_ORDER and not (r.relation == "on" and r.target in flat)]
    if ranked:
        return min(ranked, key=lambda r: ANCHOR_ORDER.index(r.relation))
    ranked = [r for r in relations if r.relation == "on"] or [r for r in relations if r.relation == "face to"]
    return ranked[0] if ranked else None


def facing(obj: ParsedObject, relations: list[ParsedRelation], anchored: ParsedRelation | None) -> str | None:
    """The id the object should turn toward, if any."""
    for r in relations:
        if r.relation == "face to":
            return r.target
    if anchored is not None and anchored.relation in SIDES and roles.kind(obj.category) in roles.SEATS:
        return anchored.target
    return None


def turn_yaw(obj: ParsedObject, outgoing: list[ParsedRelation], incoming: list[ParsedRelation],
             by_id: dict[str, ParsedObject], seat_of: dict[str, ParsedObject]) -> float:
    """How a thing starts turned: a bridge between two things, one left and one right of it,
    turns its long side (y at yaw 0) from one to the other; a table with a long seat on either
    side ("two benches on either side of the table", or people on them: "children sit on benches
    on both sides of the table") turns its long sides to them; anything else starts unturned."""
    sides = {r.relation for r in outgoing}
    if roles.kind(obj.category) in roles.SPANS and {"left of", "right of"} <= sides and obj.size[1] > obj.size[0]:
        return 90.0
    seats = [(r.relation, seat_of.get(r.source, by_id[r.source])) for r in incoming if r.source in by_id]
    seated = {relation for relation, o in seats if roles.kind(o.category) in roles.SEATS and o.size[0] >= LONG_SEAT}
    table = roles.kind(obj.category) in roles.TABLES | roles.DESKS
    return 90.0 if table and {"left of", "right of"} <= seated and obj.size[0] > obj.size[1] else 0.0


def place_related(
    objects: list[ParsedObject], relations: list[ParsedRelation], free_spot: FreeSpot
) -> dict[str, Footprint]:
    """First poses of one group of related objects, its main object at the origin."""
    by_id = {o.id: o for o in objects}
    outgoing: dict[str, list[ParsedRelation]] = defaultdict(list)
    faced_by: dict[str, list[str]] = defaultdict(list)
    for r in relations:
        outgoing[r.source].append(r)
        if r.relation == "face to":
            faced_by[r.target].append(r.source)
    incoming: dict[str, list[ParsedRelation]] = defaultdict(list)
    for r in relations:
        incoming[r.target].append(r)
    flat = {o.id for o in objects if o.size[2] < 0.1}
    lent = _lend_sides(outgoing, relations, flat, by_id)
    placed: dict[str, Footprint] = {}
    side_use: Counter[tuple[str, str]] = Counter()
    loads = Counter((r.target, r.relation) for r in relations if r.relation in ("on", "above"))
    main = main_object(objects, relations)

    seat_of = {r.source: by_id[r.target] for r in relations
               if r.relation == "on" and r.target in by_id and roles.kind(by_id[r.target].category) in roles.SEATS}

    def yaw(obj: ParsedObject) -> float:
        return turn_yaw(obj, outgoing[obj.id], incoming[obj.id], by_id, seat_of)

    # what a ring of things faces keeps room round it for them
    room = {t: max(max(by_id[f].size[:2]) for f in fs) + GAP for t, fs in faced_by.items() if len(fs) >= RING}

    placed[main.id] = Footprint(0.0, 0.0, main.size[2] / 2, yaw(main), main.size)

    def beside_source(obj: ParsedObject) -> bool:
        """Place ``obj`` from a relation a placed object has to it (S left of obj: obj right
        of S), when its own relations cannot place it; False if there is none."""
        for r in incoming[obj.id]:
            if r.source in placed and r.relation in INVERSE:
                side = INVERSE[r.relation]
                placed[obj.id] = beside(obj, placed[r.source], r.source, side, False, room.get(r.source, 0.0))
                return True
        return False

    def beside(obj: ParsedObject, t: Footprint, target: str, rel: str, turn: bool, ring_room: float) -> Footprint:
        """``obj`` on the ``rel`` side of ``t``, the n-th there, pushed clear, ``ring_room`` further
        off when one of the two has a ring of things round it the relation puts this one outside
        of (a campfire in front of the tents keeps room for its ring of logs)."""
        (dx, dy), face_yaw = SIDES[rel]
        probe = Footprint(0, 0, 0, face_yaw if turn else yaw(obj), lent.get(obj.id, obj.size))
        n = side_use[(target, rel)]
        side_use[(target, rel)] += 1
        along = (probe.d if dx else probe.w) + GAP
        offset = along * ((n + 1) // 2) * (1 if n % 2 else -1)
        if n == 0 and dx and roles.kind(obj.category) in roles.NIGHTSTANDS and roles.kind(
            by_id[target].category
        ) in roles.BEDS:
            offset = (t.d - probe.d) / 2  # beside the bed's head, not its middle
        elif n == 0 and dx and t.d > FRONT_CORNER_DEPTH and t.h > obj.size[2] + HIDE_MARGIN:
            offset = -(t.d - probe.d) / 2  # by a barn's front corner, not hidden behind its middle
        gap = GAP + ring_room
        x = t.x + dx * ((t.w + probe.w) / 2 + gap) + (0.0 if dx else offset)
        y = t.y + dy * ((t.d + probe.d) / 2 + gap) + (offset if dx else 0.0)
        p = Footprint(x, y, obj.size[2] / 2, probe.yaw, obj.size)
        return push(_slide(p, t, (dx, dy), list(placed.values())), (dx, dy), list(placed.values()))

    def place(obj: ParsedObject, trail: frozenset[str] = frozenset()) -> None:
        if obj.id in placed:
            return
        anchored = anchor(outgoing[obj.id], flat)
        if anchored is not None and anchored.target not in placed and anchored.target not in trail:
            if anchor(outgoing[anchored.target], flat) is None and beside_source(obj):
                return  # its target has nothing to place it by but this object: it follows
            place(by_id[anchored.target], trail | {obj.id})
        if anchored is None or anchored.target not in placed:
            if beside_source(obj):
                return
            facer = next((f for f in faced_by[obj.id] if f in placed), None)
            if facer is None:
                placed[obj.id] = free_spot(obj, placed)
                return
            # what something faces goes where that thing looks (its front, −Y at yaw 0)
            f = placed[facer]
            fx, fy = (float(v) for v in front_direction(f.yaw))
            reach = (f.d + max(obj.size[0], obj.size[1])) / 2 + 1.5
            p = Footprint(f.x + fx * reach, f.y + fy * reach, obj.size[2] / 2, f.yaw + 180.0, obj.size)
            placed[obj.id] = push(p, (fx, fy), list(placed.values()))
            return
        t = placed[anchored.target]
        rel = anchored.relation
        if rel in ("on", "above"):
            n = side_use[(anchored.target, rel)]
            side_use[(anchored.target, rel)] += 1
            dx, dy = _spread_on(n, t, obj.size, loads[(anchored.target, rel)])
            z = t.z + t.h / 2 + obj.size[2] / 2 + (ABOVE if rel == "above" else 0.0)
            placed[obj.id] = Footprint(dx, dy, z, t.yaw, obj.size)
            return
        target_kind = roles.kind(by_id[anchored.target].category)
        seat_at_table = roles.kind(obj.category) in roles.SEATS and target_kind in (
            roles.DESKS | roles.TABLES | roles.COFFEE_TABLES
        )
        # one who works at a desk, a console or a stove stands (or sits) at its front, turned to it
        seat_at_table = seat_at_table or (obj.category == "figure" and target_kind in roles.WORKPLACES)
        if rel == "side of":
            left, right = side_use[(anchored.target, "left of")], side_use[(anchored.target, "right of")]
            rel = "left of" if left <= right else "right of"
        if rel == "near":
            order = SEAT_NEAR_SIDES if seat_at_table else NEAR_SIDES
            rel = min(order, key=lambda s: (side_use[(anchored.target, s)], order.index(s)))
        if rel == "face to":
            rel = "in front of"
        if rel == "far":
            p = Footprint(t.x, t.y + t.d / 2 + FAR + obj.size[1] / 2, obj.size[2] / 2, 0.0, obj.size)
            placed[obj.id] = push(p, (0.0, 1.0), list(placed.values()))
            return
        turn = facing(obj, outgoing[obj.id], anchored) == anchored.target or (
            seat_at_table and anchored.relation == "near"
        )
        placed[obj.id] = beside(obj, t, anchored.target, rel, turn, room.get(obj.id, 0.0))
        _lay_under(obj, outgoing[obj.id], flat, placed, by_id)

    # a wide ring waits for the rest: benches on either side of a campfire hug it, and the tents
    # around it stand beyond them (chairs around a table, a crowd facing a stage keep their turn)
    facers = Counter(r.target for r in relations if r.relation == "face to")
    ring = {r.source for r in relations if r.relation == "face to" and facers[r.target] >= RING
            and by_id[r.source].size[0] * by_id[r.source].size[1] > RING_WIDE}  # fmt: skip
    for obj in sorted(objects, key=lambda o: o.id in ring):
        place(obj)
    resting = {frozenset((r.source, r.target)) for r in relations if r.relation in ("on", "above")}
    for obj in objects:  # turn what faces something toward it, now that both stand
        target = facing(obj, outgoing[obj.id], anchor(outgoing[obj.id], flat))
        if target is not None and target in placed and target != obj.id:
            others = [v for k, v in placed.items() if k != obj.id and frozenset((k, obj.id)) not in resting]
            _turn_clear(obj, placed, placed[target], [v for v in others if v.h >= 0.1], relations, by_id)
    return placed


#: Relations a thing resting on a host lends that host: where the thing is, its host is.
_LENT = (*SIDES, "side of", "near")


def _lend_sides(
    outgoing: dict[str, list[ParsedRelation]], relations: list[ParsedRelation], flat: set[str], by_id
) -> dict[str, tuple[float, float, float]]:
    """A host the text places nowhere, carrying one thing the text places ("four trees grow around
    the pond in planters", "a cat sleeps on a cushion by the stove"), goes where that thing's
    side relations say: the host is placed first, as far out as the wider of the two needs (a
    tree's crown overhangs its planter), and the thing sits on it. Returns those hosts' reach."""
    lent: dict[str, tuple[float, float, float]] = {}
    riders: dict[str, list[str]] = defaultdict(list)
    for r in relations:
        if r.relation == "on" and r.target not in flat:
            riders[r.target].append(r.source)
    for host, on in riders.items():
        # (a seat is left out: its sitter's relations already reach it, and lending them only
        # spreads the seats wider: "four astronauts sit on stools around a table"; a long seat
        # takes what all its sitters share: "children sit on benches on both sides of the table")
        seat = roles.kind(by_id[host].category) in roles.SEATS
        bench = seat and len(on) > 1 and by_id[host].size[0] >= LONG_SEAT
        if len(on) != 1 and not bench or anchor(outgoing[host], flat) is not None or seat and not bench:
            continue
        shared = set.intersection(*({(r.relation, r.target) for r in outgoing[o]} for o in on))
        sides = [replace(r, source=host) for r in outgoing[on[0]]
                 if r.relation in _LENT and r.target != host and (r.relation, r.target) in shared]
        if sides:
            outgoing[host].extend(sides)
            wide, size = by_id[on[0]].size, by_id[host].size
            lent[host] = (max(wide[0], size[0]), max(wide[1], size[1]), size[2])
    return lent


def _slide(p: Footprint, t: Footprint, direction: tuple[float, float], others: list[Footprint]) -> Footprint:
    """``p`` beside ``t`` on the ``direction`` side, slid along that side (never past ``t``'s
    ends) to the clear spot nearest where it is, when its spot is taken: a stool in front of a
    piano whose middle a lamp stands before takes the free end of the keyboard rather than a
    place metres out. Unchanged when no spot along the side is clear."""
    if clear(p, others):
        return p
    dx, _ = direction
    room = ((t.d - p.d) if dx else (t.w - p.w)) / 2
    if room <= 0:
        return p
    home = (p.x, p.y)
    steps = sorted({round(k * 0.05, 2) for k in range(-int(room / 0.05), int(room / 0.05) + 1)} | {-room, room}, key=abs)
    for s in steps:
        base = t.y if dx else t.x
        if dx:
            p.y = base + s
        else:
            p.x = base + s
        if clear(p, others):
            return p
    p.x, p.y = home
    return p


def _turn_clear(obj, placed, target: Footprint, others, relations, by_id) -> None:
    """Turn ``obj`` to face ``target``; where the turned footprint hits a neighbour, step it
    away from that neighbour (turning again) until clear with its relations holding, else
    leave it as it was (the solver then turns it exactly where it finds room)."""
    p = placed[obj.id]
    before = (p.x, p.y, p.yaw)
    mine = [r for r in relations if obj.id in (r.source, r.target) and r.source in placed and r.target in placed]
    for k in range(9):
        if (target.x, target.y) == (p.x, p.y):
            break
        p.turn(round(yaw_towards((p.x, p.y), (target.x, target.y)), 3))
        hit = next((q for q in others if p.overlaps(q)), None)
        if hit is None and all(rel.check(r.relation, _scene(r.source, placed, by_id), _scene(r.target, placed, by_id))
                               for r in mine):  # fmt: skip
            return
        if hit is None or k == 8:
            break
        dx, dy = p.x - hit.x, p.y - hit.y
        norm = math.hypot(dx, dy) or 1.0
        p.x, p.y = before[0] + dx / norm * 0.15 * (k + 1), before[1] + dy / norm * 0.15 * (k + 1)
    p.x, p.y = before[0], before[1]
    p.turn(before[2])


def _scene(object_id: str, placed, by_id) -> SceneObject:
    p, o = placed[object_id], by_id[object_id]
    return SceneObject(id=o.id, name=o.name, category=o.category, position=Vec3(x=p.x, y=p.y, z=p.z),
                       rotation=Vec3(z=p.yaw), size=Vec3.of(o.size))  # fmt: skip


def _lay_under(obj: ParsedObject, relations: list[ParsedRelation], flat: set[str], placed, by_id) -> None:
    """A rug the object stands on goes under it, and the object onto the rug."""
    for r in relations:
        if r.relation == "on" and r.target in flat and r.target not in placed:
            p = placed[obj.id]
            rug = by_id[r.target]
            placed[r.target] = Footprint(p.x, p.y, rug.size[2] / 2, 0.0, rug.size)
            p.z += rug.size[2]
            return


def _spread_on(n: int, t: Footprint, size: tuple[float, float, float], total: int) -> tuple[float, float]:
    """Centre of the n-th of ``total`` things put on one support: a grid over its top
    (:func:`fits_across`), the first of one thing alone (the only one there, or too big for more
    than one, or one of many small ones) in the middle."""
    cols, rows = fits_across(t.w, size[0]), fits_across(t.d, size[1])
    if n == 0 and (total <= 1 or not 1 < cols * rows <= 4):
        return t.x, t.y
    slots = [(c, r) for r in range(rows) for c in range(cols)]
    c, r = slots[n % len(slots)]
    return t.x + (c + 0.5) * t.w / cols - t.w / 2, t.y + (r + 0.5) * t.d / rows - t.d / 2

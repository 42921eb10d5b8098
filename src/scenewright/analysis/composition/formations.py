"""Formations the text states for a group: stacks, rows and rings ("three crates stacked",
"ten chairs in two rows facing the arch", "four lanterns in a circle").

The parser reads a formation as the group's ``formation`` (``stack``, ``row``, ``rows`` with
``formation_lines`` rows, ``circle``) rather than as relations between its members, since the
members are one thing said once. Here a stack becomes each member ``on`` the one below (relations
the solver keeps), and a row or a ring becomes the members' first poses: side by side in as many
rows as the text says, or evenly round a ring facing its middle. A formation whose members the
text relates to one target ("facing the arch") is laid out in front of that target and turned
to it; members that stand alone are set out together and move as one unit from then on. A
formation is only applied where every relation touching its members still holds at the new
poses.
"""

from __future__ import annotations

import math
from collections import defaultdict

from scenewright.analysis.composition.footprint import GAP, Footprint, bbox, fits_across
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.analysis.parser import ParsedObject, ParsedRelation
from scenewright.core.catalogue import load_catalogue
from scenewright.core.relations import BUFFER
from scenewright.geometry import front_direction, yaw_towards

#: Room between the rows of a formation: a seat's legroom, a walkway between stalls.
ROW_GAP = 0.6
#: The highest a stack is piled (m): what one can reach the top of. Taller ones stand in columns
#: side by side ("a dozen barrels stacked against the wall" is a pile, not a tower to the rafters).
STACK_REACH = 2.0
#: Shapes drawn as a line a row can stand along ("parked in a row along the fence").
LINES = frozenset({"fence"})
#: The smallest ring: four stools "in a circle" still leave a middle to sit round.
RING_RADIUS = 1.0


def members(objects: list[ParsedObject]) -> dict[int, list[ParsedObject]]:
    """Phrase group → its objects, for groups that stand in a formation with two or more members."""
    by_group: dict[int, list[ParsedObject]] = defaultdict(list)
    for o in objects:
        if o.formation:
            by_group[o.group].append(o)
    return {g: objs for g, objs in by_group.items() if len(objs) > 1}


def stack_relations(objects: list[ParsedObject], relations: list[ParsedRelation]) -> list[ParsedRelation]:
    """"Three crates stacked": each member on the one below it, in columns no higher than
    :data:`STACK_REACH`, each column's foot beside the one before; "three stacks of crates" stand
    as three columns, each foot where the text puts it. A stack on a host wide enough
    for several ("six crates stacked on a pallet") is a pile of layers: the first layer on the
    host, as many as its top takes, and each member above on the one under it."""
    size = {o.id: o.size for o in objects}
    host = {r.source: r.target for r in relations if r.relation == "on"}
    out: list[ParsedRelation] = []
    for objs in members(objects).values():
        if objs[0].formation != "stack":
            continue
        width, depth, height = objs[0].size
        base = host.get(objs[0].id)
        layer = fits_across(size[base][0], width) * fits_across(size[base][1], depth) if base in size else 1
        if layer > 1:
            out += [
                ParsedRelation(objs[i].id, "on", base if i < layer else objs[i - layer].id, inferred=True)
                for i in range(1, len(objs))
            ]
            continue
        columns = objs[0].formation_lines
        if columns:  # "three stacks of crates": the first few are the feet, each one after on the one a column back
            out += [
                ParsedRelation(objs[i].id, "on", objs[i - columns].id, inferred=True) for i in range(columns, len(objs))
            ]
            continue
        high = max(1, int(STACK_REACH / max(height, 1e-3)))
        out += [
            ParsedRelation(objs[i].id, "on", objs[i - 1].id, inferred=True)
            if i % high
            else ParsedRelation(objs[i].id, "side of", objs[i - high].id, inferred=True)
            for i in range(1, len(objs))
        ]
    return out


def row_relations(objects: list[ParsedObject], relations: list[ParsedRelation]) -> list[ParsedRelation]:
    """"Five vans parked in a row": each member right of the one before, so the row the
    composition sets out still stands when the solver moves its members for their own relations
    (they stood bunched round the fence they were parked along). Members that face a thing, or
    rest on one, are set out by their group (a row of chairs facing a stage) and left alone."""
    held = {r.source for r in relations if r.relation in ("face to", "on", "above")}
    out: list[ParsedRelation] = []
    for objs in members(objects).values():
        ids = {o.id for o in objs}
        if objs[0].formation == "row" and not held & ids:
            out += [ParsedRelation(objs[i].id, "right of", objs[i - 1].id, inferred=True) for i in range(1, len(objs))]
            # "three camels kneel in a row beside a tent": the row on one side of it, not split round it
            beside = {r.source: r.target for r in relations if r.relation == "side of" and r.source in ids}
            if len(set(beside.values())) == 1 and beside.keys() == ids:
                out.append(ParsedRelation(objs[0].id, "right of", next(iter(beside.values())), inferred=True))
    return out


#: Relation pairs by which the parser sets a thing between two others.
_BETWEEN_PAIRS = (("right of", "left of"), ("behind", "in front of"))


def aisles(objects: list[ParsedObject], relations: list[ParsedRelation]) -> dict[str, tuple[str, str]]:
    """Things the text sets between two members of one group in rows ("a robot rolls between the
    rows"), each to the two it stands between: they stand in the aisle the rows leave, so they go
    there once the rows are set out, instead of joining two members into a unit beforehand."""
    group = {o.id: o.group for o in objects if o.formation in ("row", "rows")}
    sides: dict[str, dict[str, str]] = defaultdict(dict)
    for r in relations:
        if r.target in group and r.source not in group:
            sides[r.source][r.relation] = r.target
    out = {}
    for source, by in sides.items():
        for first, second in _BETWEEN_PAIRS:
            a, b = by.get(first), by.get(second)
            if a and b and a != b and group[a] == group[b]:
                out[source] = (a, b)
    return out


def slots(count: int, lines: int, width: float, depth: float,
          gaps: tuple[float, float] = (GAP, ROW_GAP)) -> list[tuple[float, float]]:
    """Centres of ``count`` places ``width`` × ``depth`` in ``lines`` rows, the first row nearest
    the front (−y), each row centred on x = 0 and the block centred on y = 0; ``gaps`` between
    places along a row and between rows."""
    lines = max(1, min(lines, count))
    per = math.ceil(count / lines)
    pitch_x, pitch_y = width + gaps[0], depth + gaps[1]
    out = []
    for k in range(count):
        row, col = divmod(k, per)
        in_row = min(per, count - row * per)
        out.append(((col - (in_row - 1) / 2) * pitch_x, (row - (lines - 1) / 2) * pitch_y))
    return out


def ring(count: int, width: float, depth: float) -> list[tuple[float, float]]:
    """Centres of ``count`` places evenly round a ring wide enough for them, centred on the origin."""
    radius = max(count * (max(width, depth) + GAP) / (2 * math.pi), max(width, depth), RING_RADIUS)
    turns = [2 * math.pi * k / count for k in range(count)]
    return [(radius * math.cos(a), radius * math.sin(a)) for a in turns]


def arrange(layout: Layout, between: dict[str, tuple[str, str]] | None = None) -> None:
    """Rows and rings of every group the text puts in one (stacks are relations already), and
    what stands ``between`` two members of one (:func:`aisles`) in the aisle between them."""
    for objs in members(layout.objects).values():
        if objs[0].formation in ("row", "rows", "circle"):
            _arrange_group(layout, objs, between or {})


def _arrange_group(layout: Layout, objs: list[ParsedObject], between: dict[str, tuple[str, str]]) -> None:
    ids = [o.id for o in objs]
    units = [layout.unit_of[i] for i in ids]
    if not all(layout.on_ground(i) for i in ids):
        return
    target = _common_target(layout.relations, ids)
    distinct = len({id(u) for u in units}) == len(ids)
    own_units = distinct and all(u.root == i and not u.merged for u, i in zip(units, ids))
    inside = {s: pair for s, pair in between.items() if pair[0] in ids}
    if (line := _line_along(layout, ids)) is not None:
        _set_out_along(layout, objs, line)
    elif own_units:
        _set_out_units(layout, objs, units, inside)
        for source, (a, b) in inside.items():
            _into_aisle(layout, source, a, b)
    elif len({id(u) for u in units}) == 1 and all(layout.with_load(i) == [i] for i in ids):
        _set_out_in_unit(layout, objs, target)


def _line_along(layout: Layout, ids: list[str]) -> str | None:
    """The fence (or another thing drawn as one) every member of a row stands by, if one:
    "four vans parked in a row along the fence"."""
    if layout.by_id[ids[0]].formation != "row":
        return None
    by = [{r.target for r in layout.relations if r.source == i and r.relation in ("near", "in front of")} for i in ids]
    common = set.intersection(*by)
    return next((t for t in common if load_catalogue()[layout.by_id[t].category].shape in LINES), None)


def _set_out_along(layout: Layout, objs: list[ParsedObject], line: str) -> None:
    """Members side by side along the front of ``line`` (lengthened to them: ``hosts.lengthen``),
    each with what rests on it, when every relation touching them still holds there."""
    fence = layout.placed[line]
    fx, fy = (float(v) for v in front_direction(fence.yaw))
    ax, ay = -fy, fx  # along the fence, left to right as seen from its front
    loads = {o.id: layout.with_load(o.id) for o in objs}
    moved = [i for o in objs for i in loads[o.id]]
    before = _poses(layout, moved)
    widths = [layout.placed[o.id].w for o in objs]
    offset = -(sum(widths) + GAP * (len(objs) - 1)) / 2
    for o, w in zip(objs, widths):
        p = layout.placed[o.id]
        out = fence.d / 2 + GAP + p.d / 2
        x, y = fence.x + ax * (offset + w / 2) + fx * out, fence.y + ay * (offset + w / 2) + fy * out
        for i in loads[o.id][1:]:  # (what rests on it; the first is the member itself)
            layout.placed[i].x += x - p.x
            layout.placed[i].y += y - p.y
        p.x, p.y = x, y
        offset += w + GAP
    _keep_if_clear(layout, layout.unit_of[objs[0].id], before)


def _common_target(relations: list[ParsedRelation], ids: list[str]) -> str | None:
    """What every member faces, if they all face one thing."""
    faced = {r.target for r in relations if r.source in ids and r.relation == "face to"}
    facing = {r.source for r in relations if r.source in ids and r.relation == "face to"}
    return next(iter(faced)) if len(faced) == 1 and facing == set(ids) else None


def _place_slots(objs: list[ParsedObject], turned: bool, width: float, depth: float) -> list[tuple[float, float]]:
    """Formation places ``width`` × ``depth`` for members; each turned on its own (toward a
    target) takes room for any turn."""
    if turned:
        width = depth = math.hypot(width, depth)
    if objs[0].formation == "circle":
        return ring(len(objs), width, depth)
    return slots(len(objs), _lines(objs[0]), width, depth)


def _lines(obj: ParsedObject) -> int:
    """Rows of a formation: as many as the text says, two for "in rows", else one."""
    return (obj.formation_lines or 2) if obj.formation == "rows" else 1


def _set_out_in_unit(layout: Layout, objs: list[ParsedObject], target: str | None) -> None:
    """Members that share one unit (they face one target): the formation in front of it, turned to it."""
    ids = [o.id for o in objs]
    followers = {i: _followers(layout, i, ids, target) for i in ids}
    moved = [*ids, *(f for i in ids for f in followers[i])]
    before = _poses(layout, moved)
    cx = sum(layout.placed[i].x for i in ids) / len(ids)
    cy = sum(layout.placed[i].y for i in ids) / len(ids)
    # a member takes room for what goes with it ("each with a chair behind it")
    boxes = [bbox(layout.placed[k] for k in (i, *followers[i]) if layout.placed[k].h >= 0.1) for i in ids]
    width, depth = max(b[2] - b[0] for b in boxes), max(b[3] - b[1] for b in boxes)
    local = _place_slots(objs, target is not None or objs[0].formation == "circle", width, depth)
    fx, fy = 0.0, -1.0  # the way the formation's first row looks: toward the viewer
    if target is not None and objs[0].formation != "circle":
        t = layout.placed[target]
        # in front of the target, where it looks (an arch, a stage, a screen face the audience)
        fx, fy = (-float(v) for v in front_direction(t.yaw))
        span = max(y for _, y in local) - min(y for _, y in local) + depth
        reach = (max(t.w, t.d) + span) / 2 + GAP + 0.6
        cx, cy = t.x - fx * reach, t.y - fy * reach
    rx, ry = -fy, fx
    for o, (lx, ly) in zip(objs, local):
        p = layout.placed[o.id]
        # local −y (the first row) goes toward the target, local x along the rows
        x, y = cx + lx * rx - ly * fx, cy + lx * ry - ly * fy
        for f in followers[o.id]:  # (the relations the text states are in the scene's frame: a move keeps them)
            layout.placed[f].x += x - p.x
            layout.placed[f].y += y - p.y
        p.x, p.y = x, y
        if objs[0].formation == "circle":
            p.turn(round(yaw_towards((p.x, p.y), (cx, cy)), 3))
        elif target is not None:
            t = layout.placed[target]
            p.turn(round(yaw_towards((p.x, p.y), (t.x, t.y)), 3))
        for f in followers[o.id]:
            stated = (_AWAY[r.relation] for r in layout.relations
                      if (r.source, r.target) == (f, o.id) and r.relation in _AWAY)
            _step_clear(layout.placed[f], p, next(stated, (layout.placed[f].x - p.x, layout.placed[f].y - p.y)))
    _keep_if_clear(layout, layout.unit_of[ids[0]], before)


def _poses(layout: Layout, ids: list[str]) -> dict[str, tuple[float, float, float]]:
    return {i: (layout.placed[i].x, layout.placed[i].y, layout.placed[i].yaw) for i in ids}


def _keep_if_clear(layout: Layout, unit: Unit, before: dict[str, tuple[float, float, float]]) -> None:
    """Keep the new poses of the things ``before`` holds the old ones of only where none of them
    overlaps another or the rest of ``unit``, and every relation touching them holds; else put them back."""
    standing = [i for i in before if layout.placed[i].h >= 0.1]
    others = [layout.placed[i] for i in unit.ids if i not in before and layout.placed[i].h >= 0.1]
    clear = all(not layout.placed[a].overlaps(q) for a in standing for q in others) and all(
        not layout.placed[a].overlaps(layout.placed[b]) for k, a in enumerate(standing) for b in standing[k + 1 :]
    )
    if not (clear and layout.relations_hold(set(before))):
        for i, (x, y, yaw) in before.items():
            layout.placed[i].x, layout.placed[i].y = x, y
            layout.placed[i].turn(yaw)


#: The way a thing stands from what the text relates it to, in the scene's frame.
_AWAY = {"behind": (0.0, 1.0), "in front of": (0.0, -1.0), "left of": (-1.0, 0.0), "right of": (1.0, 0.0)}


def _step_clear(thing: Footprint, member: Footprint, way: tuple[float, float], step: float = 0.05,
                reach: float = 2.0) -> None:
    """Step ``thing`` along ``way`` until a member turned in place no longer overlaps it (a chair
    behind a desk turned to the teacher stays behind it), at most ``reach``."""
    dx, dy = way
    norm = math.hypot(dx, dy)
    if norm == 0:
        return
    for _ in range(int(reach / step)):
        if not thing.overlaps(member, margin=BUFFER + 0.02):  # (the relations' own buffer)
            return
        thing.x, thing.y = thing.x + dx / norm * step, thing.y + dy / norm * step


def _followers(layout: Layout, member: str, ids: list[str], target: str | None) -> list[str]:
    """What the text relates to ``member`` alone, with what rests on it: it goes where the member
    goes ("twelve desks in rows, each with a chair behind it": each chair with its desk)."""
    out: list[str] = []
    for r in layout.relations:
        if r.target != member or r.source in ids or r.source == target or r.source in out:
            continue
        if {x.target for x in layout.relations if x.source == r.source} == {member}:
            out += [i for i in layout.with_load(r.source) if i not in out]
    return out


def _set_out_units(layout: Layout, objs: list[ParsedObject], units: list[Unit],
                   between: dict[str, tuple[str, str]]) -> None:
    """Members that are each their own unit (with whatever rests on them or was joined to them):
    set out in the formation round the first one's place, then joined into one unit. Rows with
    something ``between`` their members leave it an aisle wide enough."""
    boxes = [layout.box(u) for u in units]
    gaps = [GAP, ROW_GAP]
    for source in between:
        x0, y0, x1, y1 = layout.box(layout.unit_of[source])
        wide = max(x1 - x0, y1 - y0) + 2 * GAP
        gaps = [max(gaps[0], wide), max(gaps[1], wide)]
    width = max(b[2] - b[0] for b in boxes)
    depth = max(b[3] - b[1] for b in boxes)
    formation = objs[0].formation
    if formation == "circle":
        local = ring(len(units), width, depth)
    elif _lines(objs[0]) == 1:  # one row: each as wide as it is ("six washing machines in a row")
        widths = [b[2] - b[0] for b in boxes]
        edges = [sum(widths[:k]) + GAP * k for k in range(len(widths))]
        local = [(x + w / 2, 0.0) for x, w in zip(edges, widths)]
    else:
        local = slots(len(units), _lines(objs[0]), width, depth, (gaps[0], gaps[1]))
    first = layout.placed[units[0].root]
    ox, oy = first.x - local[0][0], first.y - local[0][1]
    for unit, box, (lx, ly) in zip(units, boxes, local):
        if formation == "circle" and unit.turnable:
            root = layout.placed[unit.root]
            layout.turn(unit, round(yaw_towards((ox + lx, oy + ly), (ox, oy)), 3) if (lx, ly) != (0, 0) else root.yaw)
            box = layout.box(unit)
        layout.move(unit, ox + lx - (box[0] + box[2]) / 2, oy + ly - (box[1] + box[3]) / 2)
    host = units[0]
    for unit in units[1:]:
        host.ids.extend(unit.ids)
        host.partners.append(unit.root)
        unit.merged = True
        for i in unit.ids:
            layout.unit_of[i] = host
    host.turnable = False


def _into_aisle(layout: Layout, source: str, a: str, b: str) -> None:
    """The unit of ``source`` moved to stand midway between ``a`` and ``b`` and joined to their
    formation, when it clears it there."""
    unit, host = layout.unit_of[source], layout.unit_of[a]
    if unit is host or layout.unit_of[b] is not host:
        return
    pa, pb, s, root = layout.placed[a], layout.placed[b], layout.placed[source], layout.placed[unit.root]
    x, y = (pa.x + pb.x) / 2 + root.x - s.x, (pa.y + pb.y) / 2 + root.y - s.y
    layout.attach(unit, host, x, y, root.yaw, (pb.x - pa.x, pb.y - pa.y))

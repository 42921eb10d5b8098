"""Water prior: in a scene by a river, a lake or the sea, what floats goes on the water, the rest on land.

The water lies at the back of the scene (+Y, away from the viewer) beyond one straight shore
(:class:`~scenewright.scene.Water`): the land's things are set out as on dry ground, the shore
runs just behind the last of them, and the units made only of floating things (a boat with its
rowers, swans around it) move out beyond it, side by side. A pier, jetty or landing stage
reaches from the shore into the water, and takes what the text put beside or on it along.
Relations still win: a unit that mixes land things and floating things straddles the shore
when its relations set the floating ones behind the rest, and otherwise stays on land, as
the text related them.
"""

from __future__ import annotations

import math
import re

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import GAP, Footprint, bbox
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.analysis.parser import ParsedObject, ParsedRelation
from scenewright.layout import relations as rel

#: Categories of things that float whenever the scene has water.
FLOATING = frozenset({"boat", "buoy"})
#: Head words of vessels the catalogue may file under another category ("a seaplane", "a barge").
VESSELS = frozenset({
    "ferry", "barge", "sampan", "narrowboat", "longship", "seaplane", "punt", "gondola", "trawler", "tugboat",
    "houseboat", "catamaran", "canoe", "kayak", "raft", "yacht", "ship", "steamer", "pontoon", "dinghy",
})  # fmt: skip
#: Head words of things that drift on the water like a boat, whatever their category ("an ice floe").
ADRIFT = frozenset({"floe", "iceberg"})
#: Categories that reach from the shore into the water.
REACHING = frozenset({"pier"})
#: Not up in the air: "a balloon floats above the quay" is no swimmer.
_AIRBORNE = r"(?!\s+(?:above|over|overhead|high|up|through the air|in the (?:air|sky)))"
#: Verbs that put a thing (a swan, a seal, a wading heron, a diving cormorant, an elephant bathing) in the water.
_IN_WATER = (rf"(?:swim(?:s|ming)?|swam|paddl(?:e|es|ed|ing)|wad(?:e|es|ed|ing)|bath(?:e|es|ed|ing)|bob(?:s|bed|bing)?|"
             rf"div(?:e|es|ed|ing)|dove|"
             rf"(?:float|drift|glid)(?:e|es|s|ed|ing)?){_AIRBORNE}")
#: Words that put any thing in the water whatever it does there ("a leopard seal lurks in the water").
_IN_THE_WATER = r"in the (?:water|sea|river|lake|shallows|waves)"
#: Words that put a boat ashore: "pulled up on the shingle", "lies upside down", "a wrecked dinghy".
_ASHORE = r"(?:pulled up|dragged|hauled|beached|stranded|wrecked|upturned|overturned|upside down|lies|lie|lying)"
#: Relations that moor a floating thing along a pier's side.
_ALONGSIDE = frozenset({"left of", "right of", "side of", "near"})
#: Open ground between the land's last thing and the shore, and between the shore and a floating thing.
SHORE_GAP = 1.0
#: How far a pier's near end reaches back over the land, so it joins the shore.
PIER_ON_LAND = 0.5


def _said(name: str, text: str, verbs: str) -> bool:
    """Whether ``text`` says the thing ``name`` (or its plural) does one of ``verbs``, within a few
    words of its name in the same clause ("swans glide", "a mother elephant and her calf bathe",
    "a rowing boat lies upside down"), or as a participle just before it ("a wrecked dinghy",
    "swimming ducks"; not "swans glide past a crate")."""
    noun = re.escape(name.lower())
    after = rf"\b{noun}(?:e?s)?\b(?:\s+[\w']+){{0,3}}?\s+{verbs}\b"
    before = rf"\b(?={verbs})[\w-]+(?:ed|ing)\s+(?:[\w']+\s+)?{noun}(?:e?s)?\b"  # a participle before it
    low = text.lower()
    return bool(re.search(after, low) or re.search(before, low))


def floats(name: str, category: str | None, text: str) -> bool:
    """Whether the thing named ``name`` floats in the scene ``text`` describes: a boat or buoy
    (by category or a vessel's head word) unless the text puts it ashore, an ice floe, or any
    thing the text says swims, paddles, wades, floats, drifts, glides or bathes, or is in the water."""
    if vessel(name, category):
        return not _said(name, text, _ASHORE)
    if not name.strip():
        return False
    return name.lower().split()[-1] in ADRIFT or _said(name, text, _IN_WATER) or _said(name, text, _IN_THE_WATER)


def vessel(name: str, category: str | None) -> bool:
    """A boat, ship or buoy, by its category or its head word."""
    words = name.lower().split()
    return category in FLOATING or bool(words and words[-1] in VESSELS)


def pier_ties(objects: list[ParsedObject], relations: list[ParsedRelation], text: str) -> set[tuple[str, str]]:
    """Relations that tie a dry thing on the ground to a pier ("a barrel beside the jetty") or to
    a boat moored at one ("fishermen unload crates from a trawler moored at the pier"), as
    (source, target): left out when the units are made, so the pier reaches out into the water
    with its boats while the thing waits on the shore by its land end (:func:`by_water`)."""
    piers = {o.id for o in objects if roles.kind(o.category) in REACHING}
    afloat = {o.id for o in objects if floats(o.name, o.category, text)}
    raised = {r.source for r in relations if r.relation in ("on", "above")}
    moored = {
        boat for r in relations if r.relation not in ("on", "above")
        for boat, pier in ((r.source, r.target), (r.target, r.source)) if boat in afloat and pier in piers
    }  # fmt: skip
    return {
        (r.source, r.target) for r in relations
        for pier, other in ((r.target, r.source), (r.source, r.target))
        if pier in piers | moored and other not in piers | afloat | raised and r.relation not in ("on", "above")
    }  # fmt: skip


def by_water(layout: Layout, text: str, ties: set[tuple[str, str]] = frozenset()) -> float:
    """Set the floating units out on the water beyond the land and the piers across the shore,
    and the land units ``ties`` bind to a pier by its land end; the shore line's y. Called once
    the land is arranged."""
    afloat = {o.id for o in layout.objects if floats(o.name, o.category, text)}
    reaching = {o.id for o in layout.objects if layout.kind(o.id) in REACHING}
    water, astride, land = [], [], []
    for unit in layout.top_units():
        _float_back(layout, unit, afloat, reaching)
        grounded = {i for i in unit.ids if layout.on_ground(i)}
        if grounded and grounded <= afloat | reaching:
            water.append(unit)
        elif _split_line(layout, unit, afloat, reaching) is not None:
            astride.append(unit)
        else:
            land.append(unit)
    prints = [p for u in land for p in layout.ground_prints(u.ids)]
    shore = (bbox(prints)[3] if prints else 0.0) + SHORE_GAP
    placed: list[Footprint] = []
    landings: list[Footprint] = []  # piers reaching out, for boats to gather at
    for unit in astride:  # its floating things behind the shore, its land things before it
        layout.move(unit, 0.0, shore - _split_line(layout, unit, afloat, reaching))
        _slide_clear(layout, unit, prints + placed)
        placed += layout.ground_prints(unit.ids)
    # piers first, then the boats that gather at them, then what swims around them
    for unit in sorted(water, key=lambda u: (not set(u.ids) & reaching, not _has_vessel(layout, u))):
        piers = [i for i in unit.ids if i in reaching and layout.on_ground(i)]
        if piers:
            _reach_out(layout, unit, piers[0], afloat)
            y0 = bbox(layout.placed[i] for i in piers)[1] - (shore - PIER_ON_LAND)
        else:
            y0 = bbox(layout.ground_prints(unit.ids))[1] - (shore + SHORE_GAP)
        layout.move(unit, _to_landing(layout, unit, landings), -y0)
        _slide_clear(layout, unit, placed)
        landings += [layout.placed[i] for i in piers]
        placed += layout.ground_prints(unit.ids)
    for unit in land:
        pier = next((b if a in unit.ids else a for a, b in ties if a in unit.ids or b in unit.ids), None)
        if pier is not None and layout.unit_of[pier] is not unit:
            _by_land_end(layout, unit, layout.placed[pier], shore)
    return shore


def _by_land_end(layout: Layout, unit: Unit, pier: Footprint, shore: float) -> None:
    """A land unit moved beside the land end of a pier reaching out from ``shore``, on the
    shore side, where it stays clear of what is already there."""
    x0, y0, x1, y1 = layout.box(unit)
    others = [p for u in layout.top_units() if u is not unit for p in layout.ground_prints(u.ids)]
    for side in (1.0, -1.0):
        dx = pier.x + side * (pier.w / 2 + GAP + (x1 - x0) / 2) - (x0 + x1) / 2
        dy = shore - SHORE_GAP / 2 - y1
        layout.move(unit, dx, dy)
        if layout.is_clear(unit, others, GAP):
            return
        layout.move(unit, -dx, -dy)


def _float_back(layout: Layout, unit: Unit, afloat: set[str], reaching: set[str]) -> None:
    """The unit's floating things (with their loads) moved together to just behind its land
    things, when every relation that held still holds: "near", "face to", a side among the
    floating things themselves do not say which side of the land things the water is ("a
    terrier barks at the swans gliding alongside the narrowboat")."""
    grounded = [i for i in unit.ids if layout.on_ground(i) and i not in reaching]
    wet = [i for i in grounded if i in afloat]
    dry = [i for i in grounded if i not in afloat]
    if not wet or not dry:
        return
    front, back = bbox(layout.placed[i] for i in wet)[1], bbox(layout.placed[i] for i in dry)[3]
    if front >= back:
        return
    moving = list(dict.fromkeys(j for i in wet for j in layout.with_load(i)))
    held = _held(layout, set(moving))
    for j in moving:
        layout.placed[j].y += back + GAP - front
    if not held <= _held(layout, set(moving)):
        for j in moving:
            layout.placed[j].y -= back + GAP - front


def _held(layout: Layout, ids: set[str]) -> set[int]:
    """The relations touching ``ids`` that hold at the current poses, by their index."""
    touched = [(k, r) for k, r in enumerate(layout.relations) if r.source in ids or r.target in ids]
    objects = {i: layout.scene_object(i) for _, r in touched for i in (r.source, r.target)}
    return {k for k, r in touched if rel.check(r.relation, objects[r.source], objects[r.target])}


#: m, the step and the farthest reach of a slide along the shore.
_SLIDE_STEP, _SLIDE_REACH = 0.25, 100.0


def _to_landing(layout: Layout, unit: Unit, landings: list[Footprint]) -> float:
    """How far along x a unit with a boat moves to start at the nearest pier: boats the text
    sets nowhere in particular gather at the landing, as in a harbour ("a sampan" in a ferry
    crossing with a jetty); 0 when there is no pier, the unit has its own, or holds no boat."""
    if not landings or any(layout.kind(i) in REACHING for i in unit.ids):
        return 0.0
    if not _has_vessel(layout, unit):
        return 0.0  # a swan or a seal swims where it was
    x0, _, x1, _ = layout.box(unit)
    centre = (x0 + x1) / 2
    return min((p.x - centre for p in landings), key=abs)


def _has_vessel(layout: Layout, unit: Unit) -> bool:
    return any(vessel(layout.by_id[i].name, layout.by_id[i].category) for i in unit.ids)


def _slide_clear(layout: Layout, unit: Unit, others: list[Footprint]) -> None:
    """Move ``unit`` along the shore to the nearest spot, either way, where it is clear of
    ``others``: a boat stays as near as it can to where its group set it out (by the jetty)."""
    for k in range(int(2 * _SLIDE_REACH / _SLIDE_STEP) + 1):
        dx = (k + 1) // 2 * _SLIDE_STEP * (1 if k % 2 else -1)
        layout.move(unit, dx, 0.0)
        if layout.is_clear(unit, others, GAP):
            return
        layout.move(unit, -dx, 0.0)


def _split_line(layout: Layout, unit: Unit, afloat: set[str], reaching: set[str]) -> float | None:
    """The y of a line across ``unit`` with its floating things all behind it and its land
    things all before it, as its relations set them out ("a dog barks at the swans around the
    boat", the boat behind the dog); ``None`` when the unit is not that way round."""
    grounded = [i for i in unit.ids if layout.on_ground(i) and i not in reaching]
    wet = [layout.placed[i] for i in grounded if i in afloat]
    dry = [layout.placed[i] for i in grounded if i not in afloat]
    if not wet or not dry:
        return None
    front, back = bbox(wet)[1], bbox(dry)[3]
    return (front + back) / 2 if front >= back else None


def _reach_out(layout: Layout, unit: Unit, pier: str, afloat: set[str]) -> None:
    """The pier (with what stands on it) turned to run away from the viewer, and the floating
    things the text puts beside or near it moored along its sides, alternately left and right,
    from its far end in: "two trawlers moored beside the pier"."""
    p = layout.placed[pier]
    if p.w > p.d:
        _turn_about(layout, layout.with_load(pier), p.x, p.y, 90.0)
    beside = {r.source if r.target == pier else r.target for r in layout.relations
              if pier in (r.source, r.target) and r.relation in _ALONGSIDE}
    moored = [i for i in unit.ids if i in beside and i in afloat and layout.on_ground(i)]
    water = p.y - p.d / 2 + PIER_ON_LAND + GAP  # where the water starts, a gap out
    ends = {-1.0: p.y + p.d / 2, 1.0: p.y + p.d / 2}  # where the next boat on each side ends, from the far end
    for k, i in enumerate(moored):
        m = layout.placed[i]
        side = -1.0 if m.x < p.x or (m.x == p.x and k % 2 == 0) else 1.0
        x = p.x + side * (p.w / 2 + m.w / 2 + GAP)
        y = max(ends[side] - m.d / 2, water + m.d / 2)  # a boat longer than the pier stays off the shore
        ends[side] = y - m.d / 2 - GAP
        _shift(layout, i, x - m.x, y - m.y)
    # the unit's other floating things, out of the pier's way to the side they stand on
    taken = [layout.placed[j] for j in layout.with_load(pier)] + [layout.placed[j] for j in moored]
    for i in unit.ids:
        m = layout.placed[i]
        if i in afloat and i not in moored and layout.on_ground(i):
            side = -1.0 if m.x < p.x else 1.0
            for _ in range(200):
                if not any(m.plan_overlaps(q, GAP) for q in taken):
                    break
                _shift(layout, i, side * 0.25, 0.0)
            taken.append(m)


def _shift(layout: Layout, object_id: str, dx: float, dy: float) -> None:
    """Move a thing and everything resting on it."""
    for j in layout.with_load(object_id):
        layout.placed[j].x += dx
        layout.placed[j].y += dy


def _turn_about(layout: Layout, ids: list[str], cx: float, cy: float, degrees: float) -> None:
    """Turn the footprints ``ids`` about (cx, cy) by ``degrees``."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    for i in ids:
        q = layout.placed[i]
        rx, ry = q.x - cx, q.y - cy
        q.x, q.y = cx + c * rx - s * ry, cy + s * rx + c * ry
        q.turn(q.yaw + degrees)

"""Functional groups: what a designer puts together without being told.

Each rule takes the units no relation places and joins them to a host: stools along the
front of a counter (a bar), facing it; a chair in front of each desk, facing it; chairs around each dining table, facing it; a lounge's seats around
the coffee table, facing the focal object (TV, fireplace); nightstands either side of a
bed's head and a chest at its foot; a floor lamp beside a seat; a rug under its group. Every
instance of a host gets its own partners before any host gets a second.
"""

from __future__ import annotations

import math

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import Footprint
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.analysis.parser import ParsedRelation
from scenewright.core.catalogue import load_catalogue
from scenewright.geometry import yaw_towards

#: How far a seat stands from the table it is pulled up to.
SEAT_GAP = 0.1
#: Room between a coffee table and the seats around it.
LOUNGE_GAP = 0.45
#: Width a chair takes along a table's side.
CHAIR_PITCH = 0.65


def _slot(layout: Layout, host: str, member: Unit, lx: float, ly: float, yaw: float) -> bool:
    """Attach ``member`` at (lx, ly) in ``host``'s frame, turned ``yaw`` relative to the host."""
    h = layout.placed[host]
    x, y = h.local_to_world(lx, ly)
    return layout.attach(member, layout.unit_of[host], x, y, h.yaw + yaw, (x - h.x, y - h.y))


def _size(layout: Layout, unit: Unit) -> tuple[float, float, float]:
    return layout.by_id[unit.root].size


def _office_first(layout: Layout, units: list[Unit]) -> list[Unit]:
    return sorted(units, key=lambda u: layout.kind(u.root) != "office_chair")


def desks(layout: Layout) -> None:
    """Each desk gets one chair in front of it, facing it."""
    chairs = _office_first(layout, layout.free_units(roles.CHAIRS))
    for host in layout.hosts(roles.DESKS):
        if not chairs:
            return
        if layout.has_partner(host, roles.SEATS):
            continue
        h = layout.placed[host]
        chair = chairs.pop(0)
        ly = -(h.size[1] / 2 + _size(layout, chair)[1] / 2 + SEAT_GAP)
        if _slot(layout, host, chair, 0.0, ly, 180.0):
            layout.unit_of[host].group = layout.unit_of[host].group or "desk"


#: Width a bar stool takes along a counter.
STOOL_PITCH = 0.6


def bars(layout: Layout) -> None:
    """Stools line the front of each counter (a bar, a kitchen island), side by side, facing
    it, shared out one counter at a time. A counter the text already seats is left alone, and
    so is one the text relates to other things: in a room a counter stands against a wall, and
    only a counter that is its group's own root goes there with what was put before it."""
    stools = layout.free_units(roles.BAR_SEATS)
    counters = [c for c in layout.hosts(roles.BARS)
                if layout.unit_of[c].root == c and not layout.has_partner(c, roles.SEATS)]
    share = _share_out(len(stools), {c: max(1, int(layout.placed[c].size[0] // STOOL_PITCH)) for c in counters})
    for c in counters:
        h = layout.placed[c]
        n = share[c]
        for k in range(n):
            stool = stools.pop(0)
            lx = (k - (n - 1) / 2) * STOOL_PITCH
            ly = -(h.size[1] / 2 + _size(layout, stool)[1] / 2 + SEAT_GAP)
            _slot(layout, c, stool, lx, ly, 180.0)
        if n:
            layout.unit_of[c].group = layout.unit_of[c].group or "bar"


def _share_out(count: int, caps: dict[str, int]) -> dict[str, int]:
    """``count`` seats dealt one host at a time, in order, each host up to its cap."""
    share = {h: 0 for h in caps}
    while count and any(share[h] < caps[h] for h in caps):
        for h in caps:
            if count and share[h] < caps[h]:
                share[h] += 1
                count -= 1
    return share


def _table_slots(h: Footprint, chair: tuple[float, float, float], round_table: bool, count: int):
    """(lx, ly, local yaw) of ``count`` chairs around a table, in the table's frame."""
    if round_table:
        radius = max(h.size[0], h.size[1]) / 2 + chair[1] / 2 + SEAT_GAP
        out = []
        for k in range(count):
            a = math.pi / 2 + 2 * math.pi * k / count
            lx, ly = radius * math.cos(a), radius * math.sin(a)
            out.append((lx, ly, yaw_towards((lx, ly), (0.0, 0.0))))
        return out
    per_side = max(1, int(h.size[0] // CHAIR_PITCH))
    back = h.size[1] / 2 + chair[1] / 2 + SEAT_GAP
    end = h.size[0] / 2 + chair[1] / 2 + SEAT_GAP
    slots = []
    for k in range(per_side):
        lx = (k + 0.5) * h.size[0] / per_side - h.size[0] / 2
        slots += [(lx, back, 0.0), (lx, -back, 180.0)]
    slots.sort(key=lambda s: (abs(s[0]), s[1] < 0))  # the middle of the sides first
    if h.size[1] >= chair[0]:
        slots += [(end, 0.0, -90.0), (-end, 0.0, 90.0)]
    return slots[:count]


def capacity(h: Footprint, chair: tuple[float, float, float], round_table: bool) -> int:
    if round_table:
        radius = max(h.size[0], h.size[1]) / 2 + chair[1] / 2 + SEAT_GAP
        return max(2, int(2 * math.pi * radius // CHAIR_PITCH))
    return 2 * max(1, int(h.size[0] // CHAIR_PITCH)) + (2 if h.size[1] >= chair[0] else 0)


def dining(layout: Layout) -> None:
    """Chairs left over go around the tables, shared out one table at a time, facing them."""
    chairs = layout.free_units(roles.CHAIRS)
    tables = [t for t in layout.hosts(roles.TABLES) if not layout.has_partner(t, roles.SEATS)]
    if not chairs or not tables:
        return
    size = _size(layout, chairs[0])
    caps = {t: capacity(layout.placed[t], size, layout.kind(t) in roles.ROUND_TABLES) for t in tables}
    share = _share_out(len(chairs), caps)
    for t in tables:
        slots = _table_slots(layout.placed[t], size, layout.kind(t) in roles.ROUND_TABLES, share[t])
        for lx, ly, yaw in slots:
            _slot(layout, t, chairs.pop(0), lx, ly, yaw)
        if share[t]:
            layout.unit_of[t].group = layout.unit_of[t].group or "dining"


def lounge(layout: Layout) -> None:
    """Seats around the coffee table facing the focal object; without a coffee table, facing
    the focal object; without either, armchairs turned toward the sofa's front."""
    seats = sorted(layout.free_units(roles.LOUNGE_SEATS), key=lambda u: layout.kind(u.root) != "sofa")
    focal = layout.free_units(roles.FOCAL)
    tables = layout.hosts(roles.COFFEE_TABLES)
    if tables:
        for host in tables:
            h = layout.placed[host]
            slots = []
            if focal and not layout.has_partner(host, roles.FOCAL):
                f = focal.pop(0)
                _slot(layout, host, f, h.size[0] / 2 + 1.4 + _size(layout, f)[1] / 2, 0.0, -90.0)
            else:
                slots.append((1.0, 0.0, -90.0))
            # the first seat (the sofa) faces the focal object across the table; the next two
            # sit side by side behind it, facing the viewer; the front stays open while it can
            pair = 2 if len(seats) >= 3 else 1
            slots = [(-1.0, 0.0, 90.0), *[(0.0, 1.0, 0.0, k, pair) for k in range(pair)], (0.0, -1.0, 180.0), *slots]
            for ux, uy, yaw, *place in slots:
                if not seats:
                    break
                seat = seats.pop(0)
                size = _size(layout, seat)
                reach = (h.size[0] if ux else h.size[1]) / 2 + LOUNGE_GAP + size[1] / 2
                k, n = place or (0, 1)
                along = (k - (n - 1) / 2) * (size[0] + 0.15)
                _slot(layout, host, seat, ux * reach + along, uy * reach, yaw)
            layout.unit_of[host].group = layout.unit_of[host].group or "lounge"
        return
    screens = layout.hosts(roles.FOCAL)
    if screens and seats:
        host = screens[0]
        h = layout.placed[host]
        for k, seat in enumerate(seats[:5]):
            a = math.radians(35.0 * ((k + 1) // 2) * (1 if k % 2 else -1))
            dist = h.size[1] / 2 + 2.2 + _size(layout, seat)[1] / 2
            lx, ly = dist * math.sin(a), -dist * math.cos(a)
            _slot(layout, host, seat, lx, ly, yaw_towards((lx, ly), (0.0, 0.0)))
        layout.unit_of[host].group = layout.unit_of[host].group or "lounge"
        return
    sofas = [s for s in layout.hosts(frozenset({"sofa"}))]
    if sofas:
        host = sofas[0]
        others = [s for s in seats if s.root != host]
        h = layout.placed[host]
        centre = (0.0, -(h.size[1] / 2 + 1.0))
        for k, seat in enumerate(others[:2]):
            side = 1 if k == 0 else -1
            lx, ly = side * (h.size[0] / 2 + 0.3 + _size(layout, seat)[0] / 2), -(h.size[1] / 2 + 1.2)
            _slot(layout, host, seat, lx, ly, yaw_towards((lx, ly), centre))


def bed(layout: Layout) -> None:
    """Nightstands either side of each bed's head, a chest (or ottoman, bench) at its foot."""
    beds = layout.hosts(roles.BEDS)
    if not beds:
        return
    stands = layout.free_units(roles.NIGHTSTANDS)
    feet = layout.free_units(roles.BED_FOOT)
    for side in (-1, 1):
        for host in beds:
            if not stands:
                break
            h = layout.placed[host]
            n = _size(layout, stands[0])
            if _slot(layout, host, stands[0], side * (h.size[0] / 2 + 0.08 + n[0] / 2), (h.size[1] - n[1]) / 2, 0.0):
                stands.pop(0)
                layout.unit_of[host].group = layout.unit_of[host].group or "bed"
    for host in beds:
        if not feet:
            break
        h = layout.placed[host]
        chest = feet.pop(0)
        _slot(layout, host, chest, 0.0, -(h.size[1] / 2 + 0.12 + _size(layout, chest)[1] / 2), 0.0)
        layout.unit_of[host].group = layout.unit_of[host].group or "bed"


def lamps(layout: Layout) -> None:
    """A floor lamp beside a seat, one lamp to a seat, the lounge's seats first."""
    lights = layout.free_units(roles.FLOOR_LAMPS)
    seats = layout.hosts(roles.LOUNGE_SEATS) + layout.hosts(roles.SEATS - roles.LOUNGE_SEATS)
    for host in seats:
        if not lights:
            return
        h = layout.placed[host]
        lamp = _size(layout, lights[0])
        for side in (1, -1):
            lx, ly = side * (h.size[0] / 2 + 0.15 + lamp[0] / 2), (h.size[1] - lamp[1]) / 2
            if _slot(layout, host, lights[0], lx, ly, 0.0):
                lights.pop(0)
                break


def rugs(layout: Layout) -> None:
    """A rug under the group it belongs to: centred under the lounge's coffee table or the
    dining table, at the foot of a bed. What stands wholly on it gets an inferred ``on`` (so
    the solver keeps it there); what would stand half on it steps off its edge, unless that
    breaks a relation the text stated (then the rug is left to lie on its own)."""
    free = layout.free_units(roles.RUGS)
    hosts = layout.hosts(roles.COFFEE_TABLES) + layout.hosts(roles.TABLES) + layout.hosts(roles.BEDS)
    used: set[int] = set()
    for host in hosts:
        if not free:
            return
        unit = layout.unit_of[host]
        if id(unit) in used or any(layout.kind(i) in roles.RUGS for i in unit.ids):
            continue
        h = layout.placed[host]
        rug = free[0]
        r = _size(layout, rug)
        ly = -(h.size[1] + r[1]) / 2 if layout.kind(host) in roles.BEDS else 0.0
        x, y = h.local_to_world(0.0, ly)
        layout.turn(rug, h.yaw)
        p = layout.placed[rug.root]
        layout.move(rug, x - p.x, y - p.y)
        if _lay(layout, unit, rug.root):
            free.pop(0)
            unit.ids.extend(rug.ids)
            rug.merged = True
            layout.unit_of[rug.root] = unit
            used.add(id(unit))


def _lay(layout: Layout, unit: Unit, rug: str) -> bool:
    """Stand the unit's things on the rug or off its edge; False (nothing changed) if a stated
    relation would break."""
    r = layout.placed[rug]
    supported = {x.source for x in layout.relations if x.relation in ("on", "above")}
    standing = [i for i in unit.ids if i not in supported and layout.on_ground(i) and layout.by_id[i].size[2] >= 0.1]
    inside = [i for i in standing if _within(layout.placed[i], r)]
    moved: dict[str, tuple[float, float]] = {}
    for i in standing:
        p = layout.placed[i]
        if i in inside or not p.plan_overlaps(r, margin=-1e-6):
            continue
        # off the nearest edge: along the axis it has least far to go
        exits = {
            (1.0, 0.0): r.x + r.w / 2 - (p.x - p.w / 2), (-1.0, 0.0): p.x + p.w / 2 - (r.x - r.w / 2),
            (0.0, 1.0): r.y + r.d / 2 - (p.y - p.d / 2), (0.0, -1.0): p.y + p.d / 2 - (r.y - r.d / 2),
        }  # fmt: skip
        (ux, uy), far = min(exits.items(), key=lambda kv: kv[1])
        for j in layout.with_load(i):
            layout.placed[j].x += ux * (far + 0.02)
            layout.placed[j].y += uy * (far + 0.02)
            moved[j] = (ux * (far + 0.02), uy * (far + 0.02))
    others = [layout.placed[j] for j in standing]
    crowded = any(layout.placed[i].overlaps(q) for i in moved for q in others if q is not layout.placed[i])
    if crowded or not layout.relations_hold(set(moved)):
        for j, (dx, dy) in moved.items():
            layout.placed[j].x -= dx
            layout.placed[j].y -= dy
        return False
    for i in inside:
        layout.relations.append(ParsedRelation(source=i, relation="on", target=rug, inferred=True))
    for i in {j for i in inside for j in layout.with_load(i)}:
        layout.placed[i].z += r.h
    return True


def _within(a: Footprint, b: Footprint) -> bool:
    return abs(a.x - b.x) + a.w / 2 <= b.w / 2 + 1e-6 and abs(a.y - b.y) + a.d / 2 <= b.d / 2 + 1e-6


RULES = (bed, bars, desks, dining, lounge, lamps, rugs)


def facing_focal(objects, relations: list[ParsedRelation]) -> list[ParsedRelation]:
    """A seat the text puts by a fireplace or a TV ("an armchair by the fireplace") turns to it,
    and so does a person by what they work at ("a cook by the stove"), or the seat they sit on
    ("a controller sits at each console on a swivel chair": the chair turns, and them with it),
    as a designer would set them: one inferred ``face to`` per such seat or person that faces
    nothing yet."""
    kind = {o.id: roles.kind(o.category) for o in objects}
    person = {o.id for o in objects if load_catalogue()[o.category].shape == "figure"}
    seat_of = {r.source: r.target for r in relations if r.relation == "on"}
    facing = {r.source for r in relations if r.relation == "face to"}
    out = []
    for r in relations:
        if r.relation not in ("near", "side of", "left of", "right of"):
            continue
        if kind.get(r.target) in roles.FOCAL and kind.get(r.source) in roles.SEATS:
            turned = r.source
        elif r.relation == "near" and kind.get(r.target) in roles.WORKPLACES and r.source in person:
            turned = seat_of.get(r.source, r.source)
        else:
            continue
        if {r.source, turned} & facing or (turned != r.source and kind.get(turned) not in roles.SEATS):
            continue  # facing something already, or on what turns nobody (a cart, a rug)
        out.append(ParsedRelation(source=turned, relation="face to", target=r.target, inferred=True))
        facing.add(turned)
    return out

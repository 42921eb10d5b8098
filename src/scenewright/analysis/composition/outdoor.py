"""Outdoor priors: stalls around a square or in two rows along a street, their barrels and
crates beside them, vehicles parked along an edge like a road, natural things scattered with Poisson-disc spacing — and the
ways in kept free of all of them.
"""

from __future__ import annotations

import math
import random

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import bbox
from scenewright.analysis.composition.units import Layout, Unit
from scenewright.geometry import yaw_towards

#: Open ground between a square's centrepiece and the stalls around it.
SQUARE_RING = 3.0
#: Width of the walk between two rows of stalls.
STREET = 3.0
#: Width of a road beside parked vehicles, kept free.
ROAD = 3.5
#: Least open ground between two scattered things, beyond their own extents.
SCATTER_GAP = 0.5
#: Half-width of the way in from the viewer's side, kept free.
WAY_IN = 1.2


def square(layout: Layout) -> None:
    """Stalls around a centrepiece (fountain, well, statue), facing it; the front left open."""
    stalls = layout.free_units(roles.STALLS)
    centres = layout.hosts(roles.CENTREPIECES)
    if not stalls or not centres:
        return
    host = centres[0]
    h = layout.placed[host]
    deepest = max(layout.by_id[u.root].size[1] for u in stalls)
    widest = max(layout.by_id[u.root].size[0] for u in stalls)
    radius = max(h.w, h.d) / 2 + SQUARE_RING + deepest / 2
    # spread them over the back and the sides: the arc opposite the viewer, widened as needed
    arc = min(300.0, max(180.0, len(stalls) * math.degrees((widest + 0.8) / radius)))
    radius = max(radius, len(stalls) * (widest + 0.8) / math.radians(arc))
    for k, unit in enumerate(stalls):
        a = math.radians(90.0 - arc / 2 + arc * (k + 0.5) / len(stalls))
        x, y = h.x + radius * math.cos(a), h.y + radius * math.sin(a)
        layout.attach(unit, layout.unit_of[host], x, y, yaw_towards((x, y), (h.x, h.y)), (x - h.x, y - h.y))
    layout.unit_of[host].group = "square"


def street(layout: Layout) -> None:
    """Two or more stalls with no square: two rows facing each other across a walk that runs
    away from the viewer."""
    stalls = layout.free_units(roles.STALLS)
    if len(stalls) < 2:
        return
    first = stalls[0]
    pitch = max(layout.by_id[u.root].size[0] for u in stalls) + 0.6
    layout.turn(first, 90.0)
    for k, unit in enumerate(stalls[1:], start=1):
        side = -1 if k % 2 == 0 else 1
        size = layout.by_id[unit.root].size
        across = STREET + (size[1] + layout.by_id[first.root].size[1]) / 2
        x = layout.placed[first.root].x + (0.0 if side < 0 else across)
        y = layout.placed[first.root].y + pitch * (k // 2)
        layout.attach(unit, first, x, y, 90.0 if side < 0 else -90.0, (0.0, 1.0))
    first.group = "street"


def stock(layout: Layout) -> None:
    """Barrels, crates and the like beside the stalls, shared out one stall at a time, at the
    stalls' sides so their fronts stay open."""
    props = layout.free_units(roles.STALL_PROPS)
    stalls = layout.hosts(roles.STALLS)
    if not props or not stalls:
        return
    used = {s: 0 for s in stalls}
    while props:
        progress = False
        for host in stalls:
            if not props:
                break
            h = layout.placed[host]
            k = used[host]
            used[host] += 1
            if k >= 4:
                continue
            size = layout.by_id[props[0].root].size
            side = 1 if k % 2 == 0 else -1
            lx = side * (h.size[0] / 2 + 0.15 + size[0] / 2)
            ly = -h.size[1] / 2 + size[1] / 2 + (k // 2) * (size[1] + 0.1)
            x, y = h.local_to_world(lx, ly)
            if layout.attach(props[0], layout.unit_of[host], x, y, h.yaw, (x - h.x, y - h.y)):
                props.pop(0)
                progress = True
        if not progress:
            return


def park(layout: Layout, units: list[Unit]) -> None:
    """Vehicles nose to tail along the right edge of what is placed, beside a free road."""
    if not units:
        return
    x0, y0, x1, y1 = bbox(layout.placed[i] for u in layout.settled for i in u.ids)
    widest = max(layout.by_id[u.root].size[0] for u in units)
    x = x1 + ROAD + widest / 2
    y = y0
    for unit in units:
        layout.turn(unit, 0.0)
        p = layout.placed[unit.root]
        layout.move(unit, x - p.x, y + p.d / 2 - p.y)
        layout.settle(unit, (0.0, 1.0))
        y = layout.placed[unit.root].y + p.d / 2 + 1.0
    layout.keep_free.append((x1 + 0.3, min(y0, 0.0) - 30.0, x1 + ROAD - 0.2, max(y1, y) + 30.0))


def scatter(layout: Layout, units: list[Unit], rng: random.Random) -> None:
    """Natural things with Poisson-disc spacing (each at least its own and its neighbour's
    half extents plus :data:`SCATTER_GAP` from every other), around what is placed, clear of
    the kept-free ways; larger things first."""
    if not units:
        return
    units = sorted(units, key=lambda u: -max(layout.by_id[u.root].size[:2]))
    core = [layout.placed[i] for u in layout.settled for i in u.ids]
    area = sum(layout.by_id[u.root].size[0] * layout.by_id[u.root].size[1] for u in units)
    if core:
        x0, y0, x1, y1 = bbox(core)
        layout.keep_free.append(((x0 + x1) / 2 - WAY_IN, y0 - 1e3, (x0 + x1) / 2 + WAY_IN, y0))
    else:
        x0 = y0 = x1 = y1 = 0.0
    margin = max(2.0, math.sqrt(area * 1.5) / 2)
    done: list[tuple[float, float, float]] = []  # x, y, reach
    for unit in units:
        reach = max(layout.by_id[unit.root].size[:2]) / 2
        layout.turn(unit, rng.uniform(-180.0, 180.0) if layout.kind(unit.root) not in _UPRIGHT else 0.0)
        for _ in range(12):
            region = (x0 - margin, y0 - margin, x1 + margin, y1 + margin)
            spot = _dart(layout, unit, reach, done, region, (x0, y0, x1, y1) if core else None, rng)
            if spot is not None:
                break
            margin *= 1.3
        else:  # never reached in practice: past every margin, beyond the far right
            spot = (x1 + margin + reach, (y0 + y1) / 2)
        p = layout.placed[unit.root]
        layout.move(unit, spot[0] - p.x, spot[1] - p.y)
        layout.settle(unit, (1.0, 0.0))
        done.append((layout.placed[unit.root].x, layout.placed[unit.root].y, reach))


#: Natural things that grow upright and look the same from every side.
_UPRIGHT = frozenset({"tree", "pine_tree", "palm_tree", "cactus"})


def _dart(layout, unit, reach, done, region, core, rng):
    """One Bridson-style round: candidates in the ring 1–2 spacings around earlier things,
    else anywhere in the region; the first valid one."""
    rx0, ry0, rx1, ry1 = region
    cands = []
    for x, y, r in done:
        for _ in range(12):
            dist = (r + reach + SCATTER_GAP) * rng.uniform(1.0, 2.0)
            a = rng.uniform(0.0, 2 * math.pi)
            cands.append((x + dist * math.cos(a), y + dist * math.sin(a)))
    cands += [(rng.uniform(rx0, rx1), rng.uniform(ry0, ry1)) for _ in range(40)]
    rng.shuffle(cands)
    others = layout.settled_prints()
    p = layout.placed[unit.root]
    for cx, cy in cands:
        if not (rx0 <= cx <= rx1 and ry0 <= cy <= ry1):
            continue
        if any(math.hypot(cx - x, cy - y) < r + reach + SCATTER_GAP for x, y, r in done):
            continue
        if any(x0 - reach < cx < x1 + reach and y0 - reach < cy < y1 + reach for x0, y0, x1, y1 in layout.keep_free):
            continue
        if core is not None and core[0] - reach < cx < core[2] + reach and core[1] - reach < cy < core[3] + reach:
            continue
        layout.move(unit, cx - p.x, cy - p.y)
        if layout.is_clear(unit, others, margin=0.2):
            return cx, cy
    return None

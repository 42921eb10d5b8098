"""Tall storage along the edges of the scene, backs outward.

Bookshelves, wardrobes, cabinets, fridges and the like stand where walls would be: along
the back of what is set out, then down its left and right sides, fronts turned inward —
never in the open front, which is the viewer's. Two or fewer go side by side at the back;
more share the back with the sides (a U), so storage alone never forms a line. Where a bed's
headboard takes the back, the sides come first.
"""

from __future__ import annotations

import math

from scenewright.analysis.composition import roles
from scenewright.analysis.composition.footprint import GAP, bbox
from scenewright.analysis.composition.units import Layout, Unit

#: Room between the storage and what it stands behind.
CLEARANCE = 0.6
#: The yaw that turns a thing's front inward from each edge, and the outward direction.
EDGES = {"back": (0.0, (0.0, 1.0)), "left": (90.0, (-1.0, 0.0)), "right": (-90.0, (1.0, 0.0))}


#: Anchors the text gives that send a thing to the edges ("against the wall", "in the corner",
#: "at the back"); "at the back" keeps it on the back edge.
ANCHORED = frozenset({"wall", "corner", "back"})


#: How tall, or how wide a ground, a building or a landform tied to nothing is to stand at the
#: edges as a backdrop (an 8 m chalet among the skiers hides them; a 2 m shed does not).
BACKDROP_HEIGHT = 4.0
BACKDROP_AREA = 40.0


def backdrop(layout: Layout, unit: Unit) -> bool:
    """Whether the unit is a big building or landform (``roles.BACKDROPS``) that goes to the
    edges with the tall storage, behind the groups the text relates, not packed in front of them."""
    w, d, h = layout.by_id[unit.root].size
    return layout.kind(unit.root) in roles.BACKDROPS and (h >= BACKDROP_HEIGHT or w * d >= BACKDROP_AREA)


def share(count: int, back_free: bool = True) -> list[str]:
    """Which edge each of ``count`` storage pieces goes to, in order; when a bed's head takes
    the back, the sides come first."""
    back = (count if count <= 2 else max(2, math.ceil(count / 2))) if back_free else count // 3
    sides = ["left" if k % 2 == 0 else "right" for k in range(count - back)]
    return sides + ["back"] * back if not back_free else ["back"] * back + sides


def along_edges(layout: Layout, units: list[Unit], back_taken: bool = False) -> None:
    """Stand each storage unit along an edge of everything already placed; the sides first
    when a group the text puts against the back wall (``back_taken``) or a bed's head takes
    the back."""
    if not units:
        return
    x0, y0, x1, y1 = bbox(layout.placed[i] for u in layout.settled for i in u.ids)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    back = [u for u in units if layout.by_id[u.root].anchor == "back"]
    rest = [u for u in units if layout.by_id[u.root].anchor != "back"]
    units = back + rest
    edges = ["back"] * len(back) + share(
        len(rest), back_free=not back and not back_taken and not any(layout.kind(u.root) in roles.BEDS for u in layout.settled)
    )
    for edge in ("back", "left", "right"):
        row = [u for u, e in zip(units, edges) if e == edge]
        if not row:
            continue
        yaw, (ox, oy) = EDGES[edge]
        for u in row:
            layout.turn(u, yaw)
        widths = [layout.placed[u.root].w if edge == "back" else layout.placed[u.root].d for u in row]
        total = sum(widths) + GAP * (len(row) - 1)
        start = -total / 2
        for u, width in zip(row, widths):
            p = layout.placed[u.root]
            along = start + width / 2
            start += width + GAP
            if edge == "back":
                x, y = cx + along, y1 + CLEARANCE + p.d / 2
            else:
                x = (x0 - CLEARANCE - p.w / 2) if edge == "left" else (x1 + CLEARANCE + p.w / 2)
                y = cy - along
            layout.move(u, x - p.x, y - p.y)
            layout.settle(u, (ox, oy))


def in_front(layout: Layout, units: list[Unit]) -> None:
    """Things the text puts at the front: side by side before everything already placed, on the
    viewer's side."""
    if not units:
        return
    prints = [layout.placed[i] for u in layout.settled for i in u.ids]
    x0, y0, x1, _ = bbox(prints) if prints else (0.0, 0.0, 0.0, 0.0)
    widths = [layout.box(u)[2] - layout.box(u)[0] for u in units]
    start = (x0 + x1) / 2 - (sum(widths) + GAP * (len(units) - 1)) / 2
    for u, width in zip(units, widths):
        bx0, by0, bx1, by1 = layout.box(u)
        layout.move(u, start + width / 2 - (bx0 + bx1) / 2, y0 - CLEARANCE - (by1 - by0) / 2 - (by0 + by1) / 2)
        start += width + GAP
        layout.settle(u, (0.0, -1.0))

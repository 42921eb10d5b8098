"""Setting the units out on the ground: compact, two-dimensional, the viewer's side open.

Units go down largest first; each next one takes the clear spot beside those already down
that keeps the whole smallest and squarest, preferring the sides and the back to the front
(−Y, where the viewer stands). Repeated groups — four desks each with its chair, three
beds with their nightstands — first form a grid block, as in an office or a dormitory.
The same search finds a spot for a single object next to a group of related ones.
"""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np

from scenewright.analysis.composition.footprint import GAP, Footprint
from scenewright.analysis.composition.units import Layout, Unit

#: Room between units: a walkway.
AISLE = 0.9
#: Extra cost of a spot in front (toward the viewer) of what is already placed.
FRONT_COST = 0.35
#: Extra cost of a spot right behind something taller by :data:`HIDE_MARGIN` (m) or more, where
#: the viewer cannot see it (piglets set out behind the barn).
HIDDEN_COST = 1.0
HIDE_MARGIN = 1.5

Box = tuple[float, float, float, float]


def best_spot(size: tuple[float, float], boxes: list[Box], gap: float = AISLE,
              back: float | None = None, about_origin: bool = False,
              heights: tuple[float, list[float]] | None = None) -> tuple[float, float]:
    """The centre for a ``size`` (w, d) box beside ``boxes`` that keeps their union compact and
    square, sides and back before the front, and never reaching past ``back`` (y) when given;
    (0, 0) when there is nothing yet. ``about_origin``: compact as seen from the origin (the
    union's extent mirrored about it), for a layout whose middle must stay where it is (a
    table the text puts in the middle of the room, which is built centred on it). ``heights``
    (the box's own top, the tops of ``boxes``): a spot hidden behind a much taller box costs more."""
    if not boxes:
        return 0.0, 0.0
    w, d = size
    arr = np.array(boxes, dtype=float)
    cands = []
    for x0, y0, x1, y1 in boxes:
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        for y in (cy, y0 + d / 2, y1 - d / 2):
            cands += [(x1 + gap + w / 2, y), (x0 - gap - w / 2, y)]
        for x in (cx, x0 + w / 2, x1 - w / 2):
            cands += [(x, y1 + gap + d / 2), (x, y0 - gap - d / 2)]
    c = np.array(cands)
    lo = c - (w / 2, d / 2)
    hi = c + (w / 2, d / 2)
    margin = gap - 1e-6
    hit = (
        (lo[:, None, 0] < arr[None, :, 2] + margin)
        & (hi[:, None, 0] > arr[None, :, 0] - margin)
        & (lo[:, None, 1] < arr[None, :, 3] + margin)
        & (hi[:, None, 1] > arr[None, :, 1] - margin)
    ).any(axis=1)
    ux0, uy0 = np.minimum(lo[:, 0], arr[:, 0].min()), np.minimum(lo[:, 1], arr[:, 1].min())
    ux1, uy1 = np.maximum(hi[:, 0], arr[:, 2].max()), np.maximum(hi[:, 1], arr[:, 3].max())
    if about_origin:
        uw, ud = 2 * np.maximum(-ux0, ux1), 2 * np.maximum(-uy0, uy1)
    else:
        uw, ud = ux1 - ux0, uy1 - uy0
    area = uw * ud * (1.0 + 0.5 * np.abs(np.log(uw / ud)))
    front = c[:, 1] < (arr[:, 1].min() + arr[:, 3].max()) / 2 - 1e-6
    behind_all = lo[:, 1] >= arr[:, 1].min() - 1e-6
    cost = area * (1.0 + FRONT_COST * (front & ~behind_all)) + 1e-3 * np.hypot(c[:, 0], c[:, 1])
    if heights is not None:
        own, tops = heights
        taller = np.array(tops, dtype=float)[None, :] > own + HIDE_MARGIN
        across = (lo[:, None, 0] < arr[None, :, 2]) & (hi[:, None, 0] > arr[None, :, 0])
        behind = arr[None, :, 3] <= lo[:, None, 1] + 1e-6
        cost *= 1.0 + HIDDEN_COST * (taller & across & behind).any(axis=1)
    cost[hit] = np.inf
    if back is not None:
        cost[hi[:, 1] > back + 1e-6] = np.inf
    k = int(np.argmin(cost))
    if not np.isfinite(cost[k]):  # boxed in everywhere: beyond the far right
        return float(arr[:, 2].max() + gap + w / 2), float((arr[:, 1].min() + arr[:, 3].max()) / 2)
    return float(c[k, 0]), float(c[k, 1])


def free_spot(obj, placed: dict[str, Footprint]) -> Footprint:
    """A spot for an object the relations of its group leave unplaced, beside the group."""
    boxes = [(p.x - p.w / 2, p.y - p.d / 2, p.x + p.w / 2, p.y + p.d / 2) for p in placed.values()]
    x, y = best_spot((obj.size[0], obj.size[1]), boxes, gap=GAP)
    return Footprint(x, y, obj.size[2] / 2, 0.0, obj.size)


def _grid(layout: Layout, units: list[Unit]) -> None:
    """Repeated groups side by side in rows, like desks in an office, all facing one way."""
    boxes = [layout.box(u) for u in units]
    cw = max(b[2] - b[0] for b in boxes) + AISLE
    cd = max(b[3] - b[1] for b in boxes) + AISLE
    cols = math.ceil(math.sqrt(len(units)))
    rows = math.ceil(len(units) / cols)
    for k, (unit, b) in enumerate(zip(units, boxes)):
        r, c = divmod(k, cols)
        x, y = (c - (cols - 1) / 2) * cw, ((rows - 1) / 2 - r) * cd
        layout.move(unit, x - (b[0] + b[2]) / 2, y - (b[1] + b[3]) / 2)


def pack(layout: Layout, units: list[Unit], centred: int = 0, backed: frozenset[int] | set[int] = frozenset(),
         open_air: bool = False) -> None:
    """Set ``units`` out compactly around the origin (what is already placed stays); the first
    ``centred`` units (those the text puts in the middle) go down first, at the centre; then the
    units (by ``id``) ``backed`` against a wall ("a sofa at the back of the room"), and nothing
    goes down behind those: the room fit moves them back to their wall as they are. In the
    ``open_air`` nothing goes out of sight behind a barn or a tower if there is room elsewhere
    (in a room the tall things stand along the walls)."""
    centre = {id(u) for u in units[:centred]}
    by_group: dict[tuple[str, str], list[Unit]] = defaultdict(list)
    blocks: list[list[Unit]] = []
    for u in units:
        if u.group:
            by_group[(u.group, layout.kind(u.root))].append(u)
        else:
            blocks.append([u])
    for members in by_group.values():
        if len(members) > 1:
            _grid(layout, members)
            blocks.append(members)
        else:
            blocks.append(members[:1])
    order = {id(u): k for k, u in enumerate(units)}

    def weight(block: list[Unit]):
        x0, y0, x1, y1 = _union(layout, block)
        count = sum(len(u.ids) for u in block)
        middle = any(id(u) in centre for u in block)
        walled = any(id(u) in backed for u in block)
        return (not middle, not walled, -count, -(x1 - x0) * (y1 - y0), min(order[id(u)] for u in block))

    down: list[Box] = []
    tops: list[float] = []
    back: float | None = None
    for block in sorted(blocks, key=weight):
        x0, y0, x1, y1 = _union(layout, block)
        walled = any(id(u) in backed for u in block)
        top = max(layout.placed[i].z + layout.placed[i].h / 2 for u in block for i in u.ids)
        # the first stays in its own frame (its main object at the origin)
        x, y = (best_spot((x1 - x0, y1 - y0), down, back=None if walled else back, about_origin=bool(centre),
                          heights=(top, tops) if open_air else None)
                if down else ((x0 + x1) / 2, (y0 + y1) / 2))
        for u in block:
            layout.move(u, x - (x0 + x1) / 2, y - (y0 + y1) / 2)
            layout.settled.append(u)
        down.append(_union(layout, block))
        tops.append(top)
        if walled:
            back = max(back if back is not None else -np.inf, down[-1][3])


def _union(layout: Layout, block: list[Unit]) -> Box:
    boxes = [layout.box(u) for u in block]
    return min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes)

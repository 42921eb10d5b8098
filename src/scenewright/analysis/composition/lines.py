"""Never a line: when the ground objects' centres fall nearly on one line, units (and then
single objects with what rests on them) step sideways off it, as long as every relation
still holds and nothing overlaps, until the spread reaches :data:`spread.MIN_SPREAD`."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from scenewright.analysis.composition.footprint import clear
from scenewright.analysis.composition.spread import MIN_SPREAD, major_axis, spread
from scenewright.analysis.composition.units import Layout

#: Aim a little above the threshold, so round-off in the solver does not tip it back.
TARGET = MIN_SPREAD + 0.02
#: Sideways steps tried, as fractions of the standard deviation along the line.
STEPS = (0.25, 0.4, 0.6, 0.9, 1.3)


def unline(layout: Layout, holds: Callable[[set[str]], bool]) -> None:
    """Move things off the line; ``holds(ids)`` says whether the relations of the objects
    ``ids`` still hold where they now stand."""
    ground = [i for i in layout.placed if layout.on_ground(i)]
    if len(ground) < 3:
        return
    sets = [list(u.ids) for u in layout.top_units()]
    if len(sets) < 3:  # too few units to break the line with: single objects, with their load
        sets += [layout.with_load(i) for i in ground if layout.by_id[i].size[2] >= 0.1]
    for _ in range(4 * len(ground)):
        points = np.array([(layout.placed[i].x, layout.placed[i].y) for i in ground])
        now = spread(points)
        if now >= TARGET:
            return
        axis = major_axis(points)
        normal = np.array([-axis[1], axis[0]])
        scale = float(np.std(points @ axis))
        best = None
        for step in STEPS:
            for ids in sets:
                for sign in (1.0, -1.0):
                    dx, dy = normal * sign * step * max(scale, 0.5)
                    if not _try(layout, ids, dx, dy, holds):
                        continue
                    moved = np.array([(layout.placed[i].x, layout.placed[i].y) for i in ground])
                    score = spread(moved)
                    _shift(layout, ids, -dx, -dy)
                    if score > now + 1e-3 and (best is None or score > best[0]):
                        best = (score, ids, dx, dy)
            if best is not None:
                break
        if best is None:
            return
        _shift(layout, best[1], best[2], best[3])


def _shift(layout: Layout, ids: list[str], dx: float, dy: float) -> None:
    for i in ids:
        layout.placed[i].x += dx
        layout.placed[i].y += dy


def _try(layout: Layout, ids: list[str], dx: float, dy: float, holds) -> bool:
    """Shift ``ids``; keep the shift (True) only if clear and every relation holds."""
    _shift(layout, ids, dx, dy)
    mine = set(ids)
    others = layout.ground_prints(i for i in layout.placed if i not in mine)
    ok = all(clear(p, others) for p in layout.ground_prints(ids))
    if ok and not holds(mine):
        ok = False
    if not ok:
        _shift(layout, ids, -dx, -dy)
    return ok

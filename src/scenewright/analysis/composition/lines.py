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
    ``ids`` still hold where they now stand.

    Each pass walks the movable sets along the line and steps them to alternate sides (a
    zigzag), keeping each step that widens the spread, until the spread reaches the target.
    """
    ground = [i for i in layout.placed if layout.on_ground(i)]
    if len(ground) < 3:
        return
    sets = [list(u.ids) for u in layout.top_units()]
    if len(sets) < 3:  # too few units to break the line with: single objects, with their load
        sets += [layout.with_load(i) for i in ground if layout.by_id[i].size[2] >= 0.1]

    def points() -> np.ndarray:
        return np.array([(layout.placed[i].x, layout.placed[i].y) for i in ground])

    for _ in range(6):
        now = spread(points())
        if now >= TARGET:
            return
        axis = major_axis(points())
        normal = np.array([-axis[1], axis[0]])
        scale = max(float(np.std(points() @ axis)), 0.5)
        centre = {k: np.mean([(layout.placed[i].x, layout.placed[i].y) for i in ids], axis=0) @ axis
                  for k, ids in enumerate(sets)}  # fmt: skip
        improved = False
        for rank, k in enumerate(sorted(centre, key=centre.get)):
            side = 1.0 if rank % 2 == 0 else -1.0
            for step, sign in ((step, sign) for step in STEPS for sign in (side, -side)):
                dx, dy = normal * sign * step * scale
                if not _try(layout, sets[k], dx, dy, holds):
                    continue
                score = spread(points())
                if score > now + 1e-3:
                    now, improved = score, True
                    break
                _shift(layout, sets[k], -dx, -dy)
            if now >= TARGET:
                return
        if not improved:
            return


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

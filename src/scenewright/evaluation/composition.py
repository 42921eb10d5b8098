"""Composition: are the ground objects spread over the floor or set out in a line?

The spread is the ratio of the minor to the major standard deviation of the ground objects'
centres in plan (the square root of the ratio of the two principal-component variances): 1
for a round or square cloud, 0 for a line. A scene whose spread is below :data:`LINE` while it
has at least :data:`MIN_GROUND` ground objects reads as a row of unrelated things.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from scenewright.evaluation.stated import on_ground, supports
from scenewright.scene import Scene, SceneObject

#: Below this spread the ground objects stand (nearly) in a line.
LINE = 0.15
#: Fewer ground objects than this always lie on a line; no spread is reported for them.
MIN_GROUND = 3


def ground_objects(scene: Scene) -> list[SceneObject]:
    resting = supports(scene.objects)
    return [o for o in scene.objects if on_ground(*resting[o.id])]


def spread_of(points: Sequence[Sequence[float]]) -> float | None:
    """Minor/major standard deviation of plan points; ``None`` for fewer than :data:`MIN_GROUND`."""
    xy = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(xy) < MIN_GROUND:
        return None
    eigen = np.linalg.eigvalsh(np.cov(xy, rowvar=False))
    major = float(eigen[-1])
    if major <= 1e-12:  # all at one point: no direction at all, treat as a degenerate line
        return 0.0
    return round(float(np.sqrt(max(float(eigen[0]), 0.0) / major)), 4)


def spread(scene: Scene) -> tuple[float | None, int]:
    """The scene's spread and how many ground objects it was taken over."""
    ground = ground_objects(scene)
    return spread_of([(o.position.x, o.position.y) for o in ground]), len(ground)


def in_a_line(value: float | None) -> bool:
    return value is not None and value < LINE

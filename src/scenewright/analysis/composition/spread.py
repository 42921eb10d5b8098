"""How far a set of floor positions is from a line: a composition figure of docs/architecture.md, "Evaluation".

The spread is the ratio of the minor to the major standard deviation of the centres (the
square root of the ratio of their covariance's eigenvalues): 1 for a round or square cloud,
near 0 when everything stands in one row. A designer never sets unrelated things out in a
line, so the arranger keeps the spread of ground objects at or above :data:`MIN_SPREAD`.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np

from scenewright.scene import SceneObject

#: Below this the ground objects read as a line.
MIN_SPREAD = 0.15
#: Objects whose bottom is this close to z = 0 stand on the ground.
GROUND_TOLERANCE = 0.05


def spread(points: Iterable[Sequence[float]]) -> float:
    """Minor over major standard deviation of the (x, y) points; 1.0 for fewer than three
    points or when they all coincide (neither is a line)."""
    xy = np.array([(float(p[0]), float(p[1])) for p in points], dtype=float).reshape(-1, 2)
    if len(xy) < 3:
        return 1.0
    low, high = np.linalg.eigvalsh(np.cov(xy.T, bias=True))
    if high <= 1e-12:
        return 1.0
    return float(np.sqrt(max(low, 0.0) / high))


def major_axis(points: Iterable[Sequence[float]]) -> np.ndarray:
    """The unit direction along which the (x, y) points spread most."""
    xy = np.array([(float(p[0]), float(p[1])) for p in points], dtype=float).reshape(-1, 2)
    if len(xy) < 2:
        return np.array([1.0, 0.0])
    _, vectors = np.linalg.eigh(np.cov(xy.T, bias=True))
    return vectors[:, 1]


def ground_objects(objects: Sequence[SceneObject]) -> list[SceneObject]:
    """The objects standing on the ground (bottom at z ≈ 0), not on or above something."""
    return [o for o in objects if abs(o.position.z - o.size.z / 2) <= GROUND_TOLERANCE]


def scene_spread(objects: Sequence[SceneObject]) -> float:
    """The spread of the ground objects' centres of a laid-out scene."""
    return spread((o.position.x, o.position.y) for o in ground_objects(objects))

"""Physical plausibility: colliding pairs (the paper's CF and CN), out-of-bounds and unsupported objects.

Collisions are counted at mesh level by the layout engine's own check, so the solver and
the evaluation can never disagree about what a collision is; resting contact of ``on``
pairs is not a collision.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
import trimesh

from scenewright.geometry import world_box
from scenewright.layout import colliding_pairs
from scenewright.scene import Scene

#: How far (metres) a bottom may sit from the surface under it and still rest on it, and how
#: far an object may stick out of the scene's footprint.
TOLERANCE = 0.01


@dataclass
class Physical:
    collisions: list[tuple[str, str]] = field(default_factory=list)
    out_of_bounds: list[str] = field(default_factory=list)
    #: Objects neither on the ground nor on another object (hanging ``above`` sources excepted).
    floating: list[str] = field(default_factory=list)
    #: Objects whose bottom is under the ground.
    sunken: list[str] = field(default_factory=list)

    @property
    def collision_free(self) -> bool:
        return not self.collisions


def _footprints_overlap(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> bool:
    return bool(np.all(np.minimum(a[1][:2], b[1][:2]) - np.maximum(a[0][:2], b[0][:2]) > TOLERANCE))


def physical(scene: Scene, meshes: Mapping[str, trimesh.Trimesh] | None = None) -> Physical:
    objects = scene.objects
    boxes = {obj.id: world_box(obj) for obj in objects}
    hanging = {c.source for c in scene.constraints if c.relation == "above"}
    result = Physical(collisions=colliding_pairs(objects, meshes, scene.constraints))
    for obj in objects:
        low, high = boxes[obj.id]
        if scene.bounds is not None:
            half = np.array(scene.bounds) / 2.0
            if np.any(low[:2] < -half - TOLERANCE) or np.any(high[:2] > half + TOLERANCE):
                result.out_of_bounds.append(obj.id)
        if low[2] < -TOLERANCE:
            result.sunken.append(obj.id)
            continue
        on_ground = low[2] <= TOLERANCE
        on_object = any(
            other != obj.id and abs(box[1][2] - low[2]) <= TOLERANCE and _footprints_overlap(boxes[obj.id], box)
            for other, box in boxes.items()
        )
        if not (on_ground or on_object or obj.id in hanging):
            result.floating.append(obj.id)
    return result

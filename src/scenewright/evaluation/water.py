"""By water: do the floating things lie on the water and the rest on land?

For a scene whose text sets it by open water (:func:`~scenewright.analysis.parser.style.detect_water`),
the ground objects are split by what the text says of them
(:func:`~scenewright.analysis.composition.water.floats`): a floating thing is right when its
centre lies over the water (beyond the shore of ``scene.ground.water``), any other when it
lies on land. A scene with no water has every floating thing wrong and every other right.
"""

from __future__ import annotations

from dataclasses import dataclass

from scenewright.analysis.composition.water import floats
from scenewright.analysis.parser.style import detect_water
from scenewright.evaluation.composition import ground_objects
from scenewright.scene import Scene


@dataclass(frozen=True)
class ByWater:
    floating: int
    afloat: int
    grounded: int
    ashore: int


def by_water(scene: Scene) -> ByWater | None:
    """The counts for a scene by water; ``None`` for a scene on dry land or in a room."""
    if not detect_water(scene.text, scene.room is not None):
        return None
    shore = scene.ground.water.shore if scene.ground.water is not None else None
    floating = afloat = grounded = ashore = 0
    for obj in ground_objects(scene):
        wet = shore is not None and obj.position.y > shore
        if floats(obj.name, obj.category, scene.text):
            floating += 1
            afloat += wet
        else:
            grounded += 1
            ashore += not wet
    return ByWater(floating, afloat, grounded, ashore)

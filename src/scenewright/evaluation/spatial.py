"""Spatial consistency: the share of the scene's constraints that hold, by relation and by type.

Each relation is judged by :func:`scenewright.layout.check`, the definition the solver uses.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field

from scenewright.layout import check
from scenewright.scene import RELATION_TYPES, Scene


@dataclass
class Spatial:
    #: relation → [satisfied, total]
    by_relation: dict[str, list[int]] = field(default_factory=dict)
    violated: list[str] = field(default_factory=list)

    @property
    def satisfied(self) -> int:
        return sum(s for s, _ in self.by_relation.values())

    @property
    def total(self) -> int:
        return sum(t for _, t in self.by_relation.values())

    def by_type(self) -> dict[str, list[int]]:
        counts: dict[str, list[int]] = defaultdict(lambda: [0, 0])
        for relation, (satisfied, total) in self.by_relation.items():
            counts[RELATION_TYPES[relation]][0] += satisfied
            counts[RELATION_TYPES[relation]][1] += total
        return dict(counts)


def spatial(scene: Scene) -> Spatial:
    """Constraints naming an object no longer in the scene are not counted."""
    objects = {obj.id: obj for obj in scene.objects}
    result = Spatial()
    for c in scene.constraints:
        if c.source not in objects or c.target not in objects:
            continue
        counts = result.by_relation.setdefault(c.relation, [0, 0])
        counts[1] += 1
        if check(c.relation, objects[c.source], objects[c.target]):
            counts[0] += 1
        else:
            result.violated.append(str(c))
    return result

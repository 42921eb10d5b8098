"""How a layout sits in its room (docs/rooms.md): SceneEval's out-of-bounds, opening clearance
and navigability, and whether wall- and ceiling-mounted things are where they hang.

All measured by :mod:`scenewright.layout.room` and the room relations of
:mod:`scenewright.layout.relations`, the same definitions the solver works to, on the final
layout. Wall-mounted means a wall-thing category (mirror, picture, clock...) or the source of
an ``on wall`` constraint; ceiling-mounted likewise with ``on ceiling``.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np

from scenewright.analysis.parser.room import CEILING_THINGS, hangs_by_kind
from scenewright.layout.relations import Boxes, RoomTarget, holds
from scenewright.layout.room import FLOOR, SLACK, RoomShape, boxes_of
from scenewright.scene import Scene


@dataclass
class RoomMetrics:
    outside: list[str] = field(default_factory=list)
    #: objects whose top is above the ceiling (a thing stacked on a tall one, a hung thing 2 m "above")
    above_ceiling: list[str] = field(default_factory=list)
    #: "door 0 on wall_3: sofa_1, ..." for each opening whose clear strip something stands in
    blocked_openings: list[str] = field(default_factory=list)
    #: doors the agent cannot step in through (their index in room.openings)
    stuck_doors: list[int] = field(default_factory=list)
    unreachable: list[str] = field(default_factory=list)
    floor_objects: int = 0
    not_on_wall: list[str] = field(default_factory=list)
    not_on_ceiling: list[str] = field(default_factory=list)
    wall_mounted: int = 0
    ceiling_mounted: int = 0

    def to_dict(self) -> dict:
        return asdict(self)


def room_metrics(scene: Scene) -> RoomMetrics | None:
    """The room figures of ``scene``; None for a scene without a room."""
    room = scene.room
    if room is None:
        return None
    shape, out = RoomShape(room), RoomMetrics()
    objects = scene.objects
    if not objects:
        return out
    boxes = boxes_of(objects)
    out.outside = [o.id for o, by in zip(objects, shape.outside_by(boxes)) if by > SLACK]
    out.above_ceiling = [o.id for o, by in zip(objects, shape.above_ceiling(boxes)) if by > 0]
    out.blocked_openings = [f"{o.kind} {k} on wall_{o.wall}: {', '.join(ids)}" for k, o, ids in shape.blocked_openings(objects)]
    mounted = {c.source: c.relation for c in scene.constraints if c.relation in ("on wall", "on ceiling")}
    wall = [o for o in objects if mounted.get(o.id) == "on wall" or (o.id not in mounted and hangs_by_kind(o))]
    ceiling = [o for o in objects if mounted.get(o.id) == "on ceiling" or (o.id not in mounted and o.category in CEILING_THINGS)]
    target = RoomTarget.of(room)
    out.not_on_wall = [o.id for o in wall if not holds("on wall", Boxes.of(o), target)]
    out.not_on_ceiling = [o.id for o in ceiling if not holds("on ceiling", Boxes.of(o), target)]
    out.wall_mounted, out.ceiling_mounted = len(wall), len(ceiling)
    resting = {c.source for c in scene.constraints if c.relation in ("on", "above")}
    hung = {o.id for o in wall + ceiling}
    floor = {o.id for o, low in zip(objects, np.asarray(boxes.lo[:, 2]) < FLOOR) if low and o.id not in resting | hung}
    out.floor_objects = len(floor)
    out.unreachable, out.stuck_doors = shape.unreachable(objects, floor)
    return out

"""The room priors of analysis/composition/walls.py: what hangs, what is mounted, what stands against a wall."""

from __future__ import annotations

from scenewright.analysis.composition.walls import room_constraints
from scenewright.scene import Constraint, SceneObject, Vec3


def _o(oid: str, category: str, z: float) -> SceneObject:
    return SceneObject(id=oid, name=category, category=category, size=Vec3(x=0.5, y=0.5, z=z))


def test_a_thing_above_another_that_would_pass_the_ceiling_hangs_from_it_near_its_target():
    objects = [_o("lantern_1", "lantern", 0.4), _o("desk_1", "desk", 0.75), _o("mirror_1", "mirror", 0.8),
               _o("sink_1", "sink", 0.9), _o("lamp_1", "pendant_lamp", 0.3), _o("rug_1", "rug", 0.02),
               _o("drone_1", "drone", 0.2)]
    said = [Constraint(relation="above", source=s, target=t)
            for s, t in (("lantern_1", "desk_1"), ("mirror_1", "sink_1"), ("drone_1", "rug_1"))]
    got = {str(c) for c in room_constraints(objects, said, 2.7)}
    assert {"lantern_1 on ceiling ceiling", "lantern_1 near desk_1"} <= got
    assert "lantern_1 above desk_1" not in got
    assert {"mirror_1 near sink_1", "mirror_1 on wall room"} <= got  # mounted: the wall gives the height
    assert "drone_1 above rug_1" in got  # 0.02 + 2 + 0.2 m fits under 2.7 m
    assert "lantern_1 above desk_1" in {str(c) for c in room_constraints(objects, said, 4.0)}


def test_a_fireplace_and_a_tv_stand_stand_against_a_wall_even_with_a_seat_by_them():
    objects = [_o("fireplace_1", "fireplace", 1.2), _o("tv_stand_1", "tv_stand", 0.5), _o("armchair_1", "armchair", 0.9)]
    said = [Constraint(relation="near", source="armchair_1", target="fireplace_1")]
    got = {str(c) for c in room_constraints(objects, said, 2.7)}
    assert {"fireplace_1 against wall room", "tv_stand_1 against wall room"} <= got
    assert "armchair_1 against wall room" not in got

"""Room phrases in the offline edit planner (editing/parser.py) and the room priors every
backend's constraints get (analysis/composition/walls.py)."""

from __future__ import annotations

import pytest

from scenewright.analysis.composition.walls import room_constraints
from scenewright.editing.parser import plan_edit_offline
from scenewright.errors import InputError
from scenewright.scene import Constraint, Room, Scene, SceneObject, Vec3


def _obj(oid, category, size=(1.0, 1.0, 1.0)):
    return SceneObject(id=oid, name=category.replace("_", " "), category=category, size=Vec3.of(size),
                       position=Vec3(z=size[2] / 2))


def _scene(room: bool = True) -> Scene:
    objects = [_obj("bed_1", "bed", (1.6, 2.1, 1.0)), _obj("mirror_1", "mirror", (0.6, 0.04, 0.9)),
               _obj("wardrobe_1", "wardrobe", (1.2, 0.6, 2.0))]
    return Scene(text="a bedroom", objects=objects, room=Room.rectangle(4, 5) if room else None)


@pytest.mark.parametrize(
    "instruction, relation, target",
    [
        ("move the bed against the left wall", "against wall", "wall_3"),
        ("push the wardrobe into the corner", "in corner", "room"),
        ("hang the mirror on the back wall", "on wall", "wall_2"),
        ("put the bed against the wall", "against wall", "room"),
    ],
)
def test_room_phrases_place_against_the_named_wall(instruction, relation, target):
    plan = plan_edit_offline(_scene(), instruction)
    assert plan.operation == "move"
    assert [(c.relation, c.target) for c in plan.constraints] == [(relation, target)]


def test_an_added_thing_can_go_on_a_wall_and_beside_an_object():
    plan = plan_edit_offline(_scene(), "add a clock on the right wall near the bed")
    assert plan.operation == "add" and plan.new_object.category == "wall_clock"
    assert {(c.relation, c.target) for c in plan.constraints} == {("on wall", "wall_1"), ("near", "bed_1")}


def test_room_edits():
    resize = plan_edit_offline(_scene(), "make the room 5 by 6 metres")
    assert resize.operation == "room" and resize.room.size == (5.0, 6.0)
    window = plan_edit_offline(_scene(), "add a window on the back wall")
    assert window.operation == "room" and (window.room.opening, window.room.side) == ("window", "back")
    door = plan_edit_offline(_scene(), "add another door")
    assert (door.room.opening, door.room.side) == ("door", None)


def test_room_phrases_in_an_open_scene_are_refused():
    with pytest.raises(InputError, match="no room"):
        plan_edit_offline(_scene(room=False), "move the bed against the left wall")
    with pytest.raises(InputError, match="no room"):
        plan_edit_offline(_scene(room=False), "make the room 5 by 6 metres")


def test_room_priors_hang_mounted_things_and_put_storage_against_a_wall():
    objects = [_obj("mirror_1", "mirror"), _obj("fan_1", "ceiling_fan"), _obj("sink_1", "sink"),
               _obj("shelf_1", "bookshelf"), _obj("shelf_2", "bookshelf"), _obj("vase_1", "vase")]
    constraints = [Constraint(relation="above", source="mirror_1", target="sink_1"),
                   Constraint(relation="right of", source="shelf_2", target="sink_1"),
                   Constraint(relation="on", source="vase_1", target="shelf_1")]
    got = {str(c) for c in room_constraints(objects, constraints)}
    assert got == {
        "mirror_1 near sink_1", "mirror_1 on wall room", "fan_1 on ceiling ceiling", "sink_1 against wall room",
        "shelf_1 against wall room", "shelf_2 right of sink_1", "vase_1 on shelf_1",
        "shelf_2 against wall room",  # storage beside another thing stands at a wall all the same
    }

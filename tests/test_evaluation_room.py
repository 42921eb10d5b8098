"""Room figures in the evaluation (evaluation/room.py) and wall / ceiling supports in the
annotation scorer when the scene has a room."""

from __future__ import annotations

from scenewright.evaluation import evaluate_scene
from scenewright.evaluation.annotations import parse_prompt
from scenewright.evaluation.room import room_metrics
from scenewright.evaluation.stated import stated
from scenewright.scene import Opening, Room, Scene, SceneObject, Vec3


def _obj(oid, category, x, y, z, size, yaw=0.0):
    return SceneObject(id=oid, name=category, category=category, size=Vec3(x=size[0], y=size[1], z=size[2]),
                       position=Vec3(x=x, y=y, z=z), rotation=Vec3(z=yaw))


def _room() -> Room:
    room = Room.rectangle(4, 5)
    return Room.model_validate({**room.model_dump(), "openings": [Opening(kind="door", wall=3, offset=4.2, width=0.9, height=2.1)]})


def _scene(objects, constraints=()) -> Scene:
    return Scene(text="a bedroom", objects=objects, constraints=list(constraints), room=_room())


def test_a_good_room_layout_scores_clean():
    mirror = _obj("mirror_1", "mirror", 0.0, 2.5 - 0.021, 1.5, (0.6, 0.04, 0.9))
    fan = _obj("fan_1", "ceiling_fan", 0.0, 0.0, 2.7 - 0.201, (1.2, 1.2, 0.4))
    bed = _obj("bed_1", "bed", 0.0, 0.5, 0.5, (1.6, 2.0, 1.0))
    metrics = room_metrics(_scene([mirror, fan, bed]))
    assert metrics.outside == [] and metrics.blocked_openings == [] and metrics.unreachable == []
    assert metrics.not_on_wall == [] and metrics.not_on_ceiling == []
    assert (metrics.wall_mounted, metrics.ceiling_mounted, metrics.floor_objects) == (1, 1, 1)


def test_every_kind_of_room_fault_is_named():
    door_y = 2.5 - 4.2
    objects = [
        _obj("mirror_1", "mirror", 0.0, 0.0, 0.45, (0.6, 0.04, 0.9)),  # standing in the middle of the floor
        _obj("fan_1", "ceiling_fan", 0.0, 0.0, 1.2, (1.2, 1.2, 0.4)),  # floating half way up
        _obj("crate_1", "crate", -1.6, door_y, 0.4, (0.7, 0.7, 0.8)),  # in the door's way
        _obj("crate_2", "crate", 2.1, 0.0, 0.4, (0.6, 0.6, 0.8)),  # through the right wall
    ]
    metrics = room_metrics(_scene(objects))
    assert metrics.not_on_wall == ["mirror_1"] and metrics.not_on_ceiling == ["fan_1"]
    assert metrics.outside == ["crate_2"]
    assert metrics.blocked_openings == ["door 0 on wall_3: crate_1"]
    assert metrics.stuck_doors == [0]


def test_the_evaluation_report_carries_the_room_figures_only_for_a_room():
    bed = _obj("bed_1", "bed", 0.0, 0.5, 0.5, (1.6, 2.0, 1.0))
    with_room = evaluate_scene(_scene([bed]), name="a").to_dict()
    assert with_room["room"]["floor_objects"] == 1
    open_scene = Scene(text="a park", objects=[bed])
    assert evaluate_scene(open_scene, name="b").to_dict()["room"] is None


def test_wall_and_ceiling_supports_are_checked_in_a_room_and_air_is_not():
    prompt = parse_prompt({"id": "p", "domain": "indoor", "style": "realistic", "text": "a bedroom",
                           "objects": {"mirror": 1, "ceiling_fan": 1, "drone": 1}, "relations": [],
                           "supports": {"mirror": "wall", "ceiling_fan": "ceiling", "drone": "air"}})
    on_wall = _obj("mirror_1", "mirror", 0.0, 2.5 - 0.021, 1.5, (0.6, 0.04, 0.9))
    on_floor_fan = _obj("ceiling_fan_1", "ceiling_fan", 0.0, 0.0, 0.2, (1.2, 1.2, 0.4))
    drone = _obj("drone_1", "drone", 1.0, 1.0, 1.5, (0.6, 0.6, 0.2))
    result = stated(_scene([on_wall, on_floor_fan, drone]), prompt)
    assert (result.supports_right, result.supports_checked) == (1, 2)
    assert result.supports_skipped == {"air": 1}
    assert any(w.startswith("ceiling_fan_1: wants the ceiling") for w in result.wrong_supports)
    no_room = Scene(text="a bedroom", objects=[on_wall, on_floor_fan, drone])
    assert stated(no_room, prompt).supports_skipped == {"wall": 1, "ceiling": 1, "air": 1}

import json

import pytest
from pydantic import ValidationError

from scenewright.errors import InputError
from scenewright.scene import SCHEMA_VERSION, Constraint, Opening, Room, Scene, SceneObject, Vec3


def _obj(id_="table_1", **kw):
    return SceneObject(id=id_, name="Table", size=Vec3(x=1.2, y=0.8, z=0.75), **kw)


def test_constraint_type_follows_relation_even_when_mislabelled():
    c = Constraint(type="relative", relation="on", source="lamp_1", target="desk_1")
    assert c.type == "vertical"


def test_constraint_relation_is_normalised():
    c = Constraint(relation="  Left_Of ", source="a", target="b")
    assert c.relation == "left of" and c.type == "relative"


def test_unknown_relation_names_the_valid_ones():
    with pytest.raises(ValidationError) as exc:
        Constraint(relation="under", source="a", target="b")
    assert "under" in str(exc.value) and "face to" in str(exc.value)


@pytest.mark.parametrize("size", [(0, 1, 1), (1, -0.5, 1), (0.0005, 1, 1), (1, 1, 1001)])
def test_sizes_outside_a_millimetre_to_a_kilometre_are_rejected(size):
    with pytest.raises(ValidationError, match="between 0.001 and 1000 metres"):
        SceneObject(id="x", name="x", size=Vec3.of(size))


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -float("inf")])
def test_nan_and_infinity_are_refused_everywhere(value):
    with pytest.raises(ValidationError, match="finite"):
        Vec3(x=value)
    obj = SceneObject(id="x", name="x", size=Vec3.of((1, 1, 1)))
    with pytest.raises(ValidationError, match="finite"):  # an assignment is checked too
        obj.rotation = Vec3(z=value)
    with pytest.raises(ValidationError, match="finite"):
        Scene(text="t", bounds=(value, 5.0))


@pytest.mark.parametrize("position", [(1e308, 0, 0), (0, -10_000.5, 0), (0, 0, 2e4)])
def test_positions_beyond_ten_kilometres_are_rejected(position):
    with pytest.raises(ValidationError, match="within ±10000 m"):
        SceneObject(id="x", name="x", size=Vec3.of((1, 1, 1)), position=Vec3.of(position))


@pytest.mark.parametrize(
    "field, value, says",
    [
        ("position", {"x": "NaN"}, "finite"),
        ("position", {"x": 1e308}, "within ±10000 m"),
        ("rotation", {"z": "Infinity"}, "finite"),
        ("size", {"x": 1e308, "y": 1, "z": 1}, "between 0.001 and 1000 metres"),
    ],
)
def test_a_tampered_document_with_wild_numbers_is_bad_input_naming_the_field(tmp_path, field, value, says):
    scene = Scene(text="a room", objects=[SceneObject(id="x", name="x", size=Vec3.of((1, 1, 1)))])
    data = json.loads(scene.to_json())
    data["objects"][0][field] = value
    path = tmp_path / "scene.json"
    # NaN and Infinity are what json.dumps writes for them, and what a tampered file holds.
    path.write_text(json.dumps(data).replace('"NaN"', "NaN").replace('"Infinity"', "Infinity"))
    with pytest.raises(InputError, match=f"objects.0.{field}.*{says}"):
        Scene.load(path)


def test_ids_must_be_names_and_unique():
    with pytest.raises(ValidationError, match="must use only"):
        _obj("bad id!")
    with pytest.raises(ValidationError, match="used twice"):
        Scene(text="t", objects=[_obj("a"), _obj("a")])


def test_save_load_round_trip_is_byte_stable(tmp_path):
    scene = Scene(text="a table", objects=[_obj(position=Vec3(z=0.375))])
    scene.record("analysis", "parsed", objects=1)
    path = scene.save(tmp_path / "scene.json")
    again = Scene.load(path)
    assert again == scene
    again.save(tmp_path / "again.json")
    assert (tmp_path / "again.json").read_bytes() == path.read_bytes()
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_load_errors_name_the_file_and_field(tmp_path):
    bad = tmp_path / "scene.json"
    bad.write_text("{not json")
    with pytest.raises(InputError, match=r"scene\.json: not valid JSON"):
        Scene.load(bad)
    bad.write_text(json.dumps({"text": "x", "objects": [{"id": "a", "name": "a", "size": {"x": 1, "y": 1, "z": -1}}]}))
    with pytest.raises(InputError, match=r"objects\.0\.size"):
        Scene.load(bad)
    with pytest.raises(InputError, match="no such file"):
        Scene.load(tmp_path / "missing.json")


def test_newer_schema_version_asks_for_an_upgrade(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"text": "x", "schema_version": SCHEMA_VERSION + 1}))
    with pytest.raises(InputError, match="upgrade scenewright"):
        Scene.load(path)


def test_get_names_known_objects():
    scene = Scene(text="t", objects=[_obj("a"), _obj("b")])
    assert scene.get("b").id == "b"
    with pytest.raises(InputError, match="objects are: a, b"):
        scene.get("c")


def test_a_version_1_document_loads_as_an_open_scene(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"text": "a red chair", "schema_version": 1}))
    scene = Scene.load(path)
    assert scene.schema_version == SCHEMA_VERSION and scene.room is None


def test_a_rectangular_room_lists_its_walls_counter_clockwise():
    room = Room.rectangle(4, 5, 2.6, openings=[Opening(kind="door", wall=0, offset=1.0, width=0.9, height=2.1)])
    assert room.walls[0] == ((-2.0, -2.5), (2.0, -2.5)) and len(room.walls) == 4
    assert room.wall_length(1) == 5.0


def test_a_clockwise_floor_is_turned_round():
    room = Room(floor=[(0, 0), (0, 3), (4, 3), (4, 0)])
    assert room.floor == [(4, 0), (4, 3), (0, 3), (0, 0)]


@pytest.mark.parametrize(
    "fields, words",
    [
        ({"floor": [(0, 0), (4, 0), (0, 3), (4, 3)]}, "intersects itself"),
        ({"floor": [(0, 0), (4, 0)]}, "at least 3 corners"),
        ({"floor": [(0, 0), (0.2, 0), (0.2, 4), (0, 4)]}, "shorter than"),
        ({"floor": [(0, 0), (4, 0), (4, 3)], "height": 30}, "height"),
        ({"floor": [(0, 0), (4, 0), (4, 3)], "openings": [{"kind": "door", "wall": 0, "offset": 0.2, "width": 0.9, "height": 2}]}, "does not fit"),
        ({"floor": [(0, 0), (4, 0), (4, 3)], "openings": [{"kind": "window", "wall": 7, "offset": 1, "width": 0.9, "height": 1}]}, "walls 0..2"),
        ({"floor": [(0, 0), (4, 0), (4, 3)], "openings": [{"kind": "door", "wall": 0, "offset": 1, "width": 0.9, "height": 2, "sill": 0.5}]}, "sill 0"),
    ],
)
def test_a_bad_room_is_refused_naming_what_is_wrong(fields, words):
    with pytest.raises(ValidationError, match=words):
        Room(**fields)


def test_the_water_of_the_ground_round_trips_and_an_older_ground_loads_without_it(tmp_path):
    from scenewright.scene import Water

    scene = Scene(text="a rowing boat on a lake", objects=[_obj(position=Vec3(z=0.375))])
    scene.ground.water = Water(shore=2.5)
    again = Scene.load(scene.save(tmp_path / "scene.json"))
    assert again.ground.water == Water(shore=2.5) and again == scene
    old = tmp_path / "old.json"
    old.write_text(json.dumps({"text": "a bench", "schema_version": SCHEMA_VERSION,
                               "ground": {"kind": "grass", "texture": None, "description": ""}}))
    assert Scene.load(old).ground.water is None


@pytest.mark.parametrize("shore", [float("nan"), float("inf"), 1e9])
def test_a_shore_beyond_the_scene_s_reach_is_refused(shore):
    from scenewright.scene import Water

    with pytest.raises(ValidationError, match="shore"):
        Water(shore=shore)

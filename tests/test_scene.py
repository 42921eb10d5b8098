import json

import pytest
from pydantic import ValidationError

from scenewright.errors import InputError
from scenewright.scene import SCHEMA_VERSION, Constraint, Scene, SceneObject, Vec3


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


@pytest.mark.parametrize("size", [(0, 1, 1), (1, -0.5, 1)])
def test_non_positive_sizes_are_rejected(size):
    with pytest.raises(ValidationError, match="size must be > 0"):
        SceneObject(id="x", name="x", size=Vec3.of(size))


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

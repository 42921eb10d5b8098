"""Edit history: every previous document kept byte for byte, undo/redo exact, a new edit after
an undo drops the undone ones."""

from __future__ import annotations

import json

import pytest

from editing_scenes import BoxMeshes, NoImages, RulePlanner, build_folder
from scenewright.backends import Backends
from scenewright.editing import apply_edit, entries, redo, undo
from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.settings import Settings


def edit(folder, instruction):
    backends = Backends(vlm=RulePlanner(), images=NoImages(), meshes=BoxMeshes())
    return apply_edit(folder.load(), folder, instruction, backends=backends, settings=Settings(cache_dir=None))


def node_names(folder):
    data = folder.glb.read_bytes()
    length = int.from_bytes(data[12:16], "little")
    return {n.get("name") for n in json.loads(data[20:20 + length])["nodes"]}


def test_an_edit_keeps_the_previous_document_and_logs_what_changed(folder):
    original = folder.document.read_bytes()
    edit(folder, "move the floor lamp to the left of the bookshelf")
    assert (folder.history / "0001.json").read_bytes() == original
    [line] = (folder.history / "log.jsonl").read_text().splitlines()
    record = json.loads(line)
    assert record["instruction"] == "move the floor lamp to the left of the bookshelf"
    assert (record["operation"], record["focus"], record["number"]) == ("move", "floor_lamp_1", 1)
    assert any("floor_lamp_1 left of bookshelf_1" in change for change in record["changes"])
    assert record["time"]


def test_undo_restores_the_document_byte_for_byte_and_re_exports_the_glb(folder):
    original = folder.document.read_bytes()
    edit(folder, "remove the coffee table")
    assert "coffee_table_1" not in node_names(folder)
    scene, entry = undo(folder)
    assert folder.document.read_bytes() == original
    assert entry.operation == "delete"
    assert {"coffee_table_1", "vase_1"} <= node_names(folder)
    assert {o.id for o in scene.objects} == {o.id for o in folder.load().objects}


def test_undo_goes_further_back_and_redo_comes_forward_exactly(folder):
    versions = [folder.document.read_bytes()]
    for instruction in ("move the armchair next to the bookshelf", "paint the sofa green", "add a vase on the dining table"):
        edit(folder, instruction)
        versions.append(folder.document.read_bytes())
    for expected in reversed(versions[:-1]):
        undo(folder)
        assert folder.document.read_bytes() == expected
    with pytest.raises(InputError, match="nothing to undo"):
        undo(folder)
    redo(folder)
    redo(folder)
    assert folder.document.read_bytes() == versions[2]
    assert [e.active for e in entries(folder)] == [True, True, False]


def test_a_new_edit_after_undo_drops_the_redo_branch(folder):
    edit(folder, "move the armchair next to the bookshelf")
    edit(folder, "paint the sofa green")
    undo(folder)
    edit(folder, "remove the floor lamp")
    log = entries(folder)
    assert [e.instruction for e in log] == ["move the armchair next to the bookshelf", "remove the floor lamp"]
    assert all(e.active for e in log)
    assert not (folder.history / "0003.json").exists()
    with pytest.raises(InputError, match="nothing to redo"):
        redo(folder)


def test_history_of_a_folder_that_is_not_a_scene_is_refused(tmp_path):
    with pytest.raises(InputError, match="not a scene folder"):
        entries(SceneFolder(tmp_path))
    with pytest.raises(InputError, match="not a scene folder"):
        undo(SceneFolder(tmp_path))


@pytest.mark.parametrize(
    "name, content", [("log.jsonl", "{not json\n"), ("log.jsonl", "[1, 2]\n"), ("state.json", ""), ("state.json", '{"x": 1}')]
)
def test_a_damaged_history_file_is_bad_input_naming_it(tmp_path, name, content):
    folder = build_folder(tmp_path / "scene")
    folder.history.mkdir()
    (folder.history / "log.jsonl").write_text("")
    (folder.history / name).write_text(content)
    with pytest.raises(InputError, match=f"{name} is broken"):
        undo(folder)

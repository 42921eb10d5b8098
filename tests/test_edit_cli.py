"""``scenewright edit|undo|redo|history`` end to end, with the offline backends a new user gets."""

from __future__ import annotations

import importlib.util

import numpy as np
import pytest

from editing_scenes import snapshot
from scenewright.assets import load_meshes
from scenewright.cli import main
from scenewright.folder import SceneFolder
from scenewright.evaluation.physical import physical
from scenewright.layout import check
from scenewright.render import render, render_info


@pytest.fixture(autouse=True)
def private_cache(tmp_path, monkeypatch):
    """The CLI's default cache and config lookups stay inside the test's folder."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.chdir(tmp_path)


def pose(obj):
    return np.array([*obj.position.tuple(), obj.rotation.z])


def edit_and_check(folder, instruction, moved):
    """Run the edit through the CLI, check the result, undo it, and check the undo."""
    before_bytes = folder.document.read_bytes()
    before = folder.load()
    assert main(["edit", str(folder.root), instruction]) == 0
    after = folder.load()
    for obj in after.objects:
        if obj.id not in moved and obj.id in {o.id for o in before.objects}:
            assert np.allclose(pose(obj), pose(before.get(obj.id)), atol=1e-3), obj.id
    held = {c.key() for c in before.constraints if check(c.relation, before.get(c.source), before.get(c.target))}
    for c in after.constraints:  # the edit's constraints hold, and every one that held still does
        if c.key() in held or c.source in moved or c.source not in {o.id for o in before.objects}:
            assert check(c.relation, after.get(c.source), after.get(c.target)), str(c)
    physics = physical(after, load_meshes(after, folder))
    assert physics.collisions == [] and physics.floating == [] and physics.sunken == []
    assert main(["undo", str(folder.root)]) == 0
    assert folder.document.read_bytes() == before_bytes
    return before, after


def test_move(folder):
    _, after = edit_and_check(folder, "move the floor lamp to the left of the bookshelf", {"floor_lamp_1"})
    assert any(c.source == "floor_lamp_1" and c.relation == "left of" and c.target == "bookshelf_1"
               for c in after.constraints)


def test_turn(folder):
    _, after = edit_and_check(folder, "turn the armchair to face the dining table", {"armchair_1"})
    assert check("face to", after.get("armchair_1"), after.get("table_1"))


def test_delete(folder):
    before, after = edit_and_check(folder, "delete the coffee table", set())
    assert len(after.objects) == len(before.objects) - 2  # the vase rested only on it


def test_replace(folder):
    _, after = edit_and_check(folder, "swap the floor lamp for a lantern", {"floor_lamp_1"})
    assert after.get("floor_lamp_1").category == "lantern"


def test_a_replacement_of_another_height_stands_where_the_old_one_stood(folder):
    before, after = edit_and_check(folder, "replace the bookshelf with a small crate", {"bookshelf_1"})
    old, new = before.get("bookshelf_1"), after.get("bookshelf_1")
    assert new.size.z < old.size.z and new.position.z == pytest.approx(new.size.z / 2)


def test_restyle(folder):
    _, after = edit_and_check(folder, "paint the bookshelf white", {"bookshelf_1"})
    assert "white" in after.get("bookshelf_1").visual_description


def test_add(folder):
    _, after = edit_and_check(folder, "add a potted plant next to the sofa", set())
    plant = after.get("potted_plant_1")
    assert check("side of", plant, after.get("sofa_1"))


def test_history_undo_redo_commands(folder, capsys):
    assert main(["edit", str(folder.root), "move the armchair next to the bookshelf"]) == 0
    edited = folder.document.read_bytes()
    assert main(["undo", str(folder.root)]) == 0
    assert main(["history", str(folder.root)]) == 0
    out = capsys.readouterr().out
    assert "move the armchair next to the bookshelf" in out and "undone" in out
    assert main(["redo", str(folder.root)]) == 0
    assert folder.document.read_bytes() == edited


@pytest.mark.parametrize(
    ("instruction", "code", "says"),
    [
        ("move the piano next to the sofa", 2, "no piano"),
        ("move the chair next to the sofa", 2, "chair_4"),
        ("", 2, "empty"),
        ("   ", 2, "empty"),
        ("move the bookshelf far from the sofa", 3, "bookshelf_1"),
    ],
)
def test_bad_edits_exit_with_a_message_and_change_nothing(folder, capsys, instruction, code, says):
    scene = folder.load()
    scene.bounds = (12.0, 6.0)  # no room anywhere for "far from the sofa"
    folder.save(scene)
    files = snapshot(folder.root)
    assert main(["edit", str(folder.root), instruction]) == code
    assert says in " ".join(capsys.readouterr().err.split())
    assert snapshot(folder.root) == files


@pytest.mark.parametrize("command", [["edit", "{dir}", "move the sofa next to the lamp"], ["undo", "{dir}"],
                                     ["redo", "{dir}"], ["history", "{dir}"]])
def test_a_folder_that_is_not_a_scene_is_refused(tmp_path, capsys, command):
    (tmp_path / "notes.txt").write_text("not a scene")
    files = snapshot(tmp_path)
    assert main([part.format(dir=tmp_path) for part in command]) == 2
    assert "not a scene folder" in " ".join(capsys.readouterr().err.split())
    assert snapshot(tmp_path) == files


def test_nothing_to_undo(folder, capsys):
    assert main(["undo", str(folder.root)]) == 2
    assert "nothing to undo" in capsys.readouterr().err


GENERATED = (
    "A cosy living room. A grey fabric sofa stands against the back wall, and a low coffee table "
    "stands in front of the sofa. A brass floor lamp is to the right of the sofa, a tall bookshelf "
    "is to the left of the sofa, and a potted plant sits near the bookshelf."
)


def test_every_operation_on_a_generated_scene(tmp_path):
    from scenewright.backends import backends_from_settings
    from scenewright.pipeline import generate
    from scenewright.settings import Settings

    settings = Settings(cache_dir=tmp_path / "cache")
    folder = SceneFolder(tmp_path / "generated")
    # On open ground: in a room the bookshelf may stand at a wall with nothing to its left
    # (tests/test_room_cli.py edits scenes in rooms).
    generate(GENERATED, folder, backends=backends_from_settings(settings), settings=settings, render=False, room="none")
    scene = folder.load()
    by_category = {o.category: o.id for o in scene.objects}
    lamp, shelf = by_category["floor_lamp"], by_category["bookshelf"]
    edit_and_check(folder, "move the floor lamp to the left of the bookshelf", {lamp})
    edit_and_check(folder, "turn the sofa to face the bookshelf", {by_category["sofa"]})
    edit_and_check(folder, "add a red armchair next to the coffee table", set())
    edit_and_check(folder, "replace the floor lamp with a lantern", {lamp})
    edit_and_check(folder, "paint the bookshelf white", {shelf})
    before, after = edit_and_check(folder, "remove the potted plant", set())
    assert len(after.objects) == len(before.objects) - 1


@pytest.mark.blender
@pytest.mark.skipif(importlib.util.find_spec("bpy") is None, reason="needs the render extra (bpy)")
def test_previews_are_called_stale_after_an_edit_and_render_refreshes_them_as_they_were(folder, capsys):
    render(folder.load(), folder, draft=True)
    made = render_info(folder)
    assert main(["edit", str(folder.root), "move the floor lamp to the left of the bookshelf"]) == 0
    assert "renders/ show the scene before this edit" in capsys.readouterr().out
    assert main(["edit", str(folder.root), "move the armchair next to the bookshelf", "--render"]) == 0
    assert "rendered" in capsys.readouterr().out
    again = render_info(folder)
    assert again["resolution"] == made["resolution"] and again["draft"] and again["visible"] != made["visible"]

import pytest

from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.scene import Scene


def test_create_refuses_a_non_scene_folder_and_touches_nothing(tmp_path):
    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(InputError, match="holds no scene.json"):
        SceneFolder(tmp_path).create()
    assert [p.name for p in tmp_path.iterdir()] == ["notes.txt"]


def test_create_refuses_a_file_and_accepts_new_or_scene_folders(tmp_path):
    f = tmp_path / "file"
    f.write_text("x")
    with pytest.raises(InputError, match="not a folder"):
        SceneFolder(f).create()
    new = SceneFolder(tmp_path / "a" / "b")
    new.create()
    new.save(Scene(text="t"))
    new.create()  # an existing scene may be resumed
    assert new.load().text == "t"


def test_load_of_a_non_scene_says_how_to_make_one(tmp_path):
    with pytest.raises(InputError, match="scenewright generate"):
        SceneFolder(tmp_path).load()


def test_paths_are_relative_and_portable(tmp_path):
    folder = SceneFolder(tmp_path)
    assert folder.relative(folder.asset("sofa_1")) == "assets/sofa_1.glb"
    assert folder.resolve("images/objects/a.png") == folder.object_image("a")


def test_relative_accepts_absolute_paths_of_a_relatively_named_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    folder = SceneFolder("scene")
    absolute = (tmp_path / "scene" / "renders" / "front.png").resolve()
    assert folder.relative(absolute) == "renders/front.png"

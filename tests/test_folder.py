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


# --- confinement: every path a document names stays inside the folder -------------------------

from scenewright.scene import SceneObject, Vec3  # noqa: E402


def _obj(**fields) -> SceneObject:
    return SceneObject(id="chair_1", name="chair", size=Vec3(x=1, y=1, z=1), **fields)


@pytest.mark.parametrize(
    ("value", "problem"),
    [
        ("/etc/passwd.glb", "is an absolute path"),
        ("C:\\\\Windows\\\\x.glb", "is an absolute path"),
        ("~/x.glb", "is an absolute path"),
        ("../outside.glb", "leads outside the scene folder"),
        ("assets/../../outside.glb", "leads outside the scene folder"),
        ("assets/chair.txt", "is not a asset file"),
        ("", "is not a file name"),
        ("assets/a\x00.glb", "is not a usable path"),
    ],
)
def test_an_asset_path_outside_the_folder_is_refused_naming_the_field(tmp_path, value, problem):
    folder = SceneFolder(tmp_path)
    with pytest.raises(InputError, match=rf"scene.json objects\[chair_1\].asset .*{problem}"):
        folder.asset_of(_obj(asset=value))


def test_a_link_inside_the_folder_to_a_file_outside_is_refused(tmp_path):
    outside = tmp_path / "secret.png"
    outside.write_bytes(b"secret")
    folder = SceneFolder(tmp_path / "scene")
    (folder.object_images).mkdir(parents=True)
    (folder.object_images / "chair_1.png").symlink_to(outside)
    with pytest.raises(InputError, match=r"objects\[chair_1\].image .*leads outside"):
        folder.image_of(_obj(image="images/objects/chair_1.png"))
    (folder.root / "assets").mkdir()
    (folder.root / "assets" / "dir.glb").mkdir()
    with pytest.raises(InputError, match="is not a regular file"):
        folder.asset_of(_obj(asset="assets/dir.glb"))


def test_paths_inside_the_folder_are_accepted_missing_or_not(tmp_path):
    folder = SceneFolder(tmp_path)
    assert folder.asset_of(_obj(asset="assets/chair_1.glb")) == folder.asset("chair_1")
    assert folder.image_of(_obj()) is None
    scene = Scene(text="t")
    scene.ground.texture = "images/ground.png"
    assert folder.ground_texture(scene) == folder.ground_image
    scene.ground.texture = "/etc/hostname"
    with pytest.raises(InputError, match="ground.texture"):
        folder.ground_texture(scene)


@pytest.mark.parametrize("name", ["history", "renders", "assets", "images", "images/objects"])
def test_a_linked_sub_folder_is_refused_when_the_folder_is_opened(tmp_path, name):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    folder.save(Scene(text="t"))
    (folder.root / name).parent.mkdir(parents=True, exist_ok=True)
    (folder.root / name).symlink_to(elsewhere, target_is_directory=True)
    with pytest.raises(InputError, match=f"{name} is a symbolic link"):
        folder.load()
    with pytest.raises(InputError, match="symbolic link"):
        folder.create()


def test_a_fixed_file_linking_outside_is_refused(tmp_path):
    outside = tmp_path / "photo.png"
    outside.write_bytes(b"x")
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    folder.save(Scene(text="t"))
    folder.images.mkdir()
    folder.reference_image.symlink_to(outside)
    with pytest.raises(InputError, match="reference.png is a symbolic link to outside"):
        folder.load()
    with pytest.raises(InputError, match="symbolic link to outside"):
        folder.reference()


def test_read_image_decodes_and_refuses_what_is_not_an_image(tmp_path):
    from PIL import Image

    folder = SceneFolder(tmp_path)
    folder.object_images.mkdir(parents=True)
    path = folder.object_image("chair_1")
    path.write_bytes(b"root:x:0:0:root:/root:/bin/bash\n")
    with pytest.raises(InputError, match=r"objects\[chair_1\].image .* is not a readable image"):
        folder.read_image(path, "objects[chair_1].image")
    Image.new("RGB", (4, 4), "red").save(path, format="PNG")
    assert folder.read_image(path, "x") == path.read_bytes()
    Image.new("RGB", (4, 4), "red").save(path, format="GIF")
    with pytest.raises(InputError, match="is a GIF image"):
        folder.read_image(path, "x")

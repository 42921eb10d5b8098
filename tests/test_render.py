import importlib.util
import json

import numpy as np
import pytest
import trimesh

from scenewright.errors import InputError, MissingExtra
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.render import best_render, render, render_info, scene_bounds
from scenewright.render.views import VIEWS, best_view, camera_matrix, visibility
from scenewright.scene import Scene, SceneObject, Vec3

has_bpy = importlib.util.find_spec("bpy") is not None


def small_scene(tmp_path) -> tuple[Scene, SceneFolder]:
    """Three boxes and a ground node, exported the way the pipeline's scene.glb is laid out."""
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    scene = Scene(
        text="a table with a chair in front of it and a lamp to the right",
        objects=[
            SceneObject(id="table_1", name="table", position=Vec3(x=0, y=0, z=0.4), size=Vec3(x=1.4, y=0.8, z=0.8)),
            SceneObject(id="chair_1", name="chair", position=Vec3(x=-1.2, y=-1.0, z=0.45), size=Vec3(x=0.5, y=0.5, z=0.9)),
            SceneObject(
                id="lamp_1", name="lamp", position=Vec3(x=1.5, y=0.3, z=0.8), rotation=Vec3(z=30), size=Vec3(x=0.3, y=0.3, z=1.6)
            ),
        ],
    )
    glb = trimesh.Scene()
    for i, obj in enumerate(scene.objects):
        box = trimesh.creation.box(extents=obj.size.tuple())
        box.apply_translation([0, 0, obj.size.z / 2])
        box.apply_transform(SCENE_TO_GLTF)  # stored like an asset: glTF convention
        box.visual.face_colors = [[200, 80, 60, 255], [60, 120, 200, 255], [230, 200, 70, 255]][i]
        glb.add_geometry(box, node_name=obj.id, geom_name=obj.id, transform=SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE)
    ground = trimesh.creation.box(extents=(8, 8, 0.01))
    ground.apply_transform(SCENE_TO_GLTF)
    glb.add_geometry(ground, node_name="ground", geom_name="ground")
    folder.glb.write_bytes(glb.export(file_type="glb"))
    folder.save(scene)
    return scene, folder


def test_every_view_frames_every_corner_of_the_bounds():
    low, high = [-3.0, -2.0, 0.0], [5.0, 1.0, 2.5]
    for view in VIEWS:
        m = camera_matrix(view, low, high, 16 / 9)
        inverse = np.linalg.inv(m)
        for corner in [[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]:
            x, y, z = (inverse @ np.array([*corner, 1.0]))[:3]
            assert z < 0, view  # in front of the camera (it looks down −Z)
            assert abs(x / -z) <= 18 / 35 + 1e-9 and abs(y / -z) <= 18 / 35 * 9 / 16 + 1e-9, view


def test_visibility_decodes_indices_and_ignores_background():
    image = np.zeros((2, 3, 4), np.uint8)
    image[0, 0] = [1, 0, 0, 255]
    image[0, 1] = [1, 0, 0, 255]
    image[1, 2] = [2, 1, 0, 255]  # index 258
    image[1, 1] = [2, 0, 0, 0]  # transparent: background, not counted
    ids = [f"o{i}" for i in range(258)]
    counts = visibility(image, ids)
    assert counts["o0"] == 2 and counts["o257"] == 1 and counts["o1"] == 0


def test_best_view_prefers_more_objects_then_well_shown_ones_then_pixels_then_paper_order():
    assert best_view({"iso_left": {"a": 5, "b": 0}, "front": {"a": 1, "b": 1}}) == "front"
    assert best_view({"iso_left": {"a": 5, "b": 1}, "front": {"a": 9, "b": 1}}) == "front"
    assert best_view({"iso_left": {"a": 1}, "front": {"a": 1}, "right": {"a": 1}}) == "iso_left"
    # Same objects seen: the view where fewer are mostly hidden wins over the one with more pixels.
    assert best_view({"iso_left": {"a": 60, "b": 30}, "right": {"a": 200, "b": 5}}) == "iso_left"


def test_bounds_cover_objects_and_footprint():
    scene = Scene(
        text="x",
        bounds=(10.0, 4.0),
        objects=[SceneObject(id="a", name="a", position=Vec3(x=6, y=0, z=1), size=Vec3(x=2, y=2, z=2))],
    )
    low, high = scene_bounds(scene)
    assert low == [-5.0, -2.0, 0.0] and high == [7.0, 2.0, 2.0]


def test_render_refuses_unknown_views_and_missing_glb(tmp_path):
    scene, folder = small_scene(tmp_path)
    with pytest.raises(InputError, match="iso_left"):
        render(scene, folder, views=("top",))
    folder.glb.unlink()
    with pytest.raises(InputError, match="scene.glb"):
        render(scene, folder)


def test_missing_bpy_names_the_extra_before_starting_blender(tmp_path, monkeypatch):
    scene, folder = small_scene(tmp_path)
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "bpy" else real(name, *a))
    monkeypatch.setattr("subprocess.run", lambda *a, **k: pytest.fail("the worker must not start"))
    with pytest.raises(MissingExtra, match=r"scenewright\[render\]"):
        render(scene, folder, draft=True)


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_draft_render_shows_every_object_in_its_index_pass(tmp_path):
    scene, folder = small_scene(tmp_path)
    paths = render(scene, folder, draft=True, keep_all=True)
    assert paths[0].name == f"{render_info(folder)['best']}.png"
    assert sorted(p.name for p in paths) == sorted(f"{v}.png" for v in VIEWS)
    info = json.loads((folder.renders / "renders.json").read_text())
    assert info["missing"] == []
    best = info["visible"][info["best"]]
    assert set(best) == {o.id for o in scene.objects}
    assert all(pixels > 0 for pixels in best.values()), best
    from PIL import Image

    image = np.asarray(Image.open(best_render(folder)).convert("RGB"))
    assert image.shape == (144, 256, 3)
    assert image.std() > 5  # a picture, not a flat fill


@pytest.mark.blender
@pytest.mark.skipif(not has_bpy, reason="needs the render extra (bpy)")
def test_a_blender_failure_becomes_a_backend_error_with_its_stderr(tmp_path):
    from scenewright.errors import BackendError

    scene, folder = small_scene(tmp_path)
    folder.glb.write_bytes(b"not a glb")
    with pytest.raises(BackendError, match="Blender render failed") as info:
        render(scene, folder, draft=True)
    assert "Traceback" in str(info.value) or "Error" in str(info.value)

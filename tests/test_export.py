"""scene.glb: one node per object at the solved pose (in glTF frame), a textured ground, valid glTF."""

from __future__ import annotations

import io
import json
import struct

import numpy as np
import pytest
import trimesh
from PIL import Image

from gltf_validator import assert_valid
from scenewright.errors import InputError
from scenewright.export import assemble, node_matrix
from scenewright.export.ground import TILE_METRES, ground_extent
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, world_box
from scenewright.scene import Scene, SceneObject, Vec3


def _glb_json(data: bytes) -> dict:
    length = struct.unpack("<I", data[12:16])[0]
    return json.loads(data[20 : 20 + length])


def _asset(size: Vec3, colour=(200, 30, 30, 255)) -> bytes:
    """A box asset in the stored convention: glTF axes, footprint centred, bottom at y = 0."""
    box = trimesh.creation.box([size.x, size.z, size.y])
    box.apply_translation([0, size.z / 2, 0])
    box.visual = trimesh.visual.TextureVisuals(
        material=trimesh.visual.material.PBRMaterial(baseColorFactor=colour, metallicFactor=0.2, roughnessFactor=0.6)
    )
    return box.export(file_type="glb")


def _png(colour=(90, 140, 60)) -> bytes:
    buf = io.BytesIO()
    Image.new("RGB", (32, 32), colour).save(buf, "PNG")
    return buf.getvalue()


def _scene(tmp_path, objects: list[SceneObject]) -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    for obj in objects:
        folder.assets.mkdir(exist_ok=True)
        folder.asset(obj.id).write_bytes(_asset(obj.size))
        obj.asset = folder.relative(folder.asset(obj.id))
    folder.images.mkdir()
    folder.ground_image.write_bytes(_png())
    scene = Scene(text="test", objects=objects)
    scene.ground.texture = folder.relative(folder.ground_image)
    return scene, folder


def _objects() -> list[SceneObject]:
    return [
        SceneObject(id="sofa_1", name="sofa", size=Vec3(x=2.0, y=0.9, z=0.8),
                    position=Vec3(x=1.0, y=2.0, z=0.4), rotation=Vec3(z=90)),
        SceneObject(id="table_1", name="table", size=Vec3(x=1.2, y=0.7, z=0.75),
                    position=Vec3(x=-1.5, y=-0.5, z=0.375), rotation=Vec3(z=30)),
        SceneObject(id="lamp_1", name="lamp", size=Vec3(x=0.3, y=0.3, z=0.5),
                    position=Vec3(x=-1.5, y=-0.5, z=1.0), rotation=Vec3(z=-135)),
    ]


def _world_bounds_in_scene_frame(loaded: trimesh.Scene, object_id: str) -> np.ndarray:
    points = []
    for node in loaded.graph.nodes_geometry:
        if node.startswith(object_id + "/"):
            transform, name = loaded.graph[node]
            points.append(trimesh.transform_points(loaded.geometry[name].vertices, GLTF_TO_SCENE @ transform))
    points = np.vstack(points)
    return np.array([points.min(axis=0), points.max(axis=0)])


def test_each_object_is_one_named_node_at_its_pose(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    path = assemble(scene, folder)
    assert path == folder.glb
    loaded = trimesh.load_scene(path)
    for obj in scene.objects:
        assert obj.id in loaded.graph.nodes
        np.testing.assert_allclose(loaded.graph.get(obj.id)[0], node_matrix(obj), atol=1e-6)
        lo, hi = world_box(obj)
        np.testing.assert_allclose(_world_bounds_in_scene_frame(loaded, obj.id), [lo, hi], atol=1e-5)


def test_the_scene_root_holds_one_node_per_object_and_the_ground(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    tree = _glb_json(assemble(scene, folder).read_bytes())
    roots = [tree["nodes"][i] for i in tree["scenes"][tree["scene"]]["nodes"]]
    assert sorted(n["name"] for n in roots) == ["ground", "lamp_1", "sofa_1", "table_1"]
    sofa = next(n for n in roots if n["name"] == "sofa_1")
    assert sofa["extras"] == {"name": "sofa", "category": None}
    assert "mesh" not in sofa and sofa["children"]
    assert tree["asset"]["generator"].startswith("scenewright")


def test_asset_materials_survive_assembly(tmp_path):
    scene, folder = _scene(tmp_path, _objects()[:1])
    tree = _glb_json(assemble(scene, folder).read_bytes())
    factors = [m["pbrMetallicRoughness"].get("baseColorFactor") for m in tree["materials"]]
    assert any(f is not None and abs(f[0] - 200 / 255) < 0.01 and f[1] < 0.2 for f in factors)


def test_ground_is_an_upward_plane_covering_the_scene_with_tiled_texture(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    loaded = trimesh.load_scene(assemble(scene, folder))
    transform, name = loaded.graph.get("ground")
    ground = loaded.geometry[name].copy()
    ground.apply_transform(GLTF_TO_SCENE @ transform)
    assert np.allclose(ground.vertices[:, 2], 0.0)
    assert np.all(ground.face_normals[:, 2] > 0.99)
    (gx0, gy0), (gx1, gy1) = ground.vertices[:, :2].min(axis=0), ground.vertices[:, :2].max(axis=0)
    for obj in scene.objects:
        lo, hi = world_box(obj)
        assert gx0 < lo[0] and gy0 < lo[1] and gx1 > hi[0] and gy1 > hi[1]
    uv = ground.visual.uv
    span_uv = uv.max(axis=0) - uv.min(axis=0)
    np.testing.assert_allclose(span_uv, [(gx1 - gx0) / TILE_METRES, (gy1 - gy0) / TILE_METRES], rtol=1e-5)
    assert ground.visual.material.baseColorTexture is not None


def test_ground_extent_respects_bounds_and_empty_scenes():
    lo, hi = ground_extent([], (20.0, 10.0))
    assert lo[0] < -10 and hi[0] > 10 and lo[1] < -5 and hi[1] > 5
    lo, hi = ground_extent([], None)
    assert np.all(hi - lo > 0)


def test_missing_texture_gives_plain_ground_and_still_exports(tmp_path):
    scene, folder = _scene(tmp_path, _objects()[:1])
    folder.ground_image.unlink()
    tree = _glb_json(assemble(scene, folder).read_bytes())
    ground_material = next(m for m in tree["materials"] if m.get("name") == "ground")
    assert "baseColorTexture" not in ground_material["pbrMetallicRoughness"]


def test_missing_asset_is_named(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    folder.asset("table_1").unlink()
    with pytest.raises(InputError, match="table_1"):
        assemble(scene, folder)
    assert not folder.glb.exists()


def test_rewrite_replaces_the_file_and_leaves_no_temporary(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    first = assemble(scene, folder).read_bytes()
    scene.objects[0].position = Vec3(x=5.0, y=5.0, z=0.4)
    second = assemble(scene, folder).read_bytes()
    assert first != second
    assert sorted(p.name for p in folder.root.iterdir()) == ["assets", "images", "scene.glb"]


@pytest.mark.node
def test_assembled_scene_is_valid_gltf(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    report = assert_valid(assemble(scene, folder))
    assert report["info"]["totalVertexCount"] > 0
    # Not even a hint: buffer views say whether they hold vertices or indices.
    assert report["issues"]["messages"] == []


def test_broken_asset_is_named(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    folder.asset("sofa_1").write_bytes(b"not a glb at all")
    with pytest.raises(InputError, match="sofa_1.*broken"):
        assemble(scene, folder)


BLENDER_IMPORT = """
import json, sys
import bpy
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=sys.argv[1])
print(json.dumps({o.name: [list(o.matrix_world.translation), o.type] for o in bpy.data.objects}))
"""


@pytest.mark.blender
def test_blender_imports_one_object_per_id_in_the_scene_frame(tmp_path):
    import importlib.util
    import subprocess
    import sys

    if importlib.util.find_spec("bpy") is None:
        pytest.skip("bpy (the render extra) is not installed")
    scene, folder = _scene(tmp_path, _objects())
    path = assemble(scene, folder)
    proc = subprocess.run(
        [sys.executable, "-c", BLENDER_IMPORT, str(path)], capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    imported = json.loads(proc.stdout.strip().splitlines()[-1])
    assert "ground" in imported
    for obj in scene.objects:
        # Blender turns glTF's +Y up back into +Z up, so its frame is the scene frame.
        location, kind = imported[obj.id]
        bottom_centre = np.array(obj.position.tuple()) - [0.0, 0.0, obj.size.z / 2]
        np.testing.assert_allclose(location, bottom_centre, atol=1e-4)
        assert kind == "EMPTY"


def test_a_scene_by_water_gets_a_named_translucent_water_node_beyond_the_shore(tmp_path):
    from scenewright.scene import WATER_LEVEL, Water

    scene, folder = _scene(tmp_path, _objects())
    scene.ground.water = Water(shore=1.0)
    data = assemble(scene, folder).read_bytes()
    tree = _glb_json(data)
    roots = [tree["nodes"][i]["name"] for i in tree["scenes"][tree["scene"]]["nodes"]]
    assert "water" in roots and "ground" in roots
    material = next(m for m in tree["materials"] if m.get("name") == "water")
    assert material["alphaMode"] == "BLEND" and material["pbrMetallicRoughness"]["roughnessFactor"] < 0.2
    colour = material["pbrMetallicRoughness"]["baseColorFactor"]
    assert colour[2] > colour[0] and colour[3] < 1.0  # blue, and the ground shows through
    loaded = trimesh.load_scene(io.BytesIO(data), file_type="glb")
    transform, name = loaded.graph.get("water")
    water = loaded.geometry[name].copy()
    water.apply_transform(GLTF_TO_SCENE @ transform)
    assert np.allclose(water.vertices[:, 2], WATER_LEVEL)
    assert np.all(water.face_normals[:, 2] > 0.99)
    assert water.vertices[:, 1].min() == pytest.approx(1.0)  # from the shore back
    transform, name = loaded.graph.get("ground")
    ground = loaded.geometry[name].copy()
    ground.apply_transform(GLTF_TO_SCENE @ transform)
    assert water.vertices[:, 1].max() == pytest.approx(ground.vertices[:, 1].max())


def test_a_scene_on_dry_land_has_no_water_node(tmp_path):
    scene, folder = _scene(tmp_path, _objects())
    tree = _glb_json(assemble(scene, folder).read_bytes())
    assert all(n["name"] != "water" for n in tree["nodes"])


@pytest.mark.node
def test_a_scene_by_water_is_valid_gltf(tmp_path):
    from scenewright.scene import Water

    scene, folder = _scene(tmp_path, _objects())
    scene.ground.water = Water(shore=0.5)
    report = assert_valid(assemble(scene, folder))
    assert report["issues"]["messages"] == []

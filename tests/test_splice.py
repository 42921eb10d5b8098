"""scene.glb put together from the assets' own glTF: encoded textures and exact materials copied,
the room taken over from the recorded scene.glb while it stays the same, the same bytes either way."""

from __future__ import annotations

import io

import numpy as np
import pytest
import trimesh
from PIL import Image

from gltf_validator import assert_valid
from scenewright.cli import main
from scenewright.export import glb as export_glb
from scenewright.export.glb import assemble
from scenewright.export.splice import Glb, GlbWriter
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, world_box
from scenewright.integrity import assemble_recorded
from scenewright.scene import Opening, Room, Scene, SceneObject, Vec3


def _textured_asset(size: Vec3) -> bytes:
    """A box with a noise texture and a transmissive material, as a GLB in the stored convention."""
    box = trimesh.creation.box([size.x, size.z, size.y])
    box.apply_translation([0, size.z / 2, 0])
    pixels = (np.random.default_rng(3).random((16, 16, 3)) * 255).astype(np.uint8)
    uv = np.random.default_rng(4).random((len(box.vertices), 2))
    box.visual = trimesh.visual.TextureVisuals(uv=uv, material=trimesh.visual.material.PBRMaterial(
        baseColorTexture=Image.fromarray(pixels), metallicFactor=0.1, roughnessFactor=0.7))
    data = box.export(file_type="glb")
    # Add what trimesh itself would drop: an extension, and a second node holding the mesh, turned
    # and moved by TRS, under the first.
    glb = Glb.parse(data)
    tree = glb.tree
    tree["materials"][0].setdefault("extensions", {})["KHR_materials_transmission"] = {"transmissionFactor": 0.5}
    tree["extensionsUsed"] = ["KHR_materials_transmission"]
    out = GlbWriter("test")
    root = out.node("holder")
    out.splice(glb, glb.roots(), parent=root)
    return out.to_bytes()


def _objects() -> list[SceneObject]:
    return [
        SceneObject(id="crate_1", name="crate", size=Vec3(x=1.0, y=0.6, z=0.5),
                    position=Vec3(x=1.0, y=-1.0, z=0.25), rotation=Vec3(z=30)),
        SceneObject(id="crate_2", name="crate", size=Vec3(x=0.4, y=0.4, z=0.8),
                    position=Vec3(x=-1.0, y=1.0, z=0.4), rotation=Vec3(z=-90)),
    ]


def _folder(tmp_path, room: Room | None = None) -> tuple[Scene, SceneFolder]:
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    folder.assets.mkdir()
    scene = Scene(text="test", objects=_objects(), room=room)
    for obj in scene.objects:
        folder.asset(obj.id).write_bytes(_textured_asset(obj.size))
        obj.asset = folder.relative(folder.asset(obj.id))
    folder.images.mkdir()
    png = io.BytesIO()
    Image.new("RGB", (8, 8), (90, 140, 60)).save(png, "PNG")
    folder.ground_image.write_bytes(png.getvalue())
    scene.ground.texture = folder.relative(folder.ground_image)
    folder.save(scene)
    return scene, folder


def _image_bytes(glb: Glb) -> list[bytes]:
    views = glb.tree["bufferViews"]
    return [glb.binary[views[i["bufferView"]].get("byteOffset", 0):][: views[i["bufferView"]]["byteLength"]]
            for i in glb.tree.get("images", [])]


def test_assets_keep_their_encoded_images_materials_and_node_trees(tmp_path):
    scene, folder = _folder(tmp_path)
    out = Glb.parse(assemble(scene, folder).read_bytes())
    asset = Glb.parse(folder.asset("crate_1").read_bytes())
    assert _image_bytes(asset)[0] in _image_bytes(out), "the texture is copied, not encoded again"
    material = next(m for m in out.tree["materials"] if "extensions" in m)
    assert material["extensions"] == asset.tree["materials"][0]["extensions"]
    assert material["pbrMetallicRoughness"]["metallicFactor"] == asset.tree["materials"][0]["pbrMetallicRoughness"]["metallicFactor"]
    assert out.tree["extensionsUsed"] == ["KHR_materials_transmission"]
    holder = out.tree["nodes"][out.find("crate_1/holder")]
    children = [out.tree["nodes"][k] for k in holder["children"]]
    assert children and all(c["name"].startswith("crate_1/") and "mesh" in c for c in children)
    assert out.tree["nodes"][out.find("crate_1")]["children"] == [out.find("crate_1/holder")]
    loaded = trimesh.load_scene(folder.glb)
    for obj in scene.objects:
        points = np.vstack([trimesh.transform_points(loaded.geometry[g].vertices, GLTF_TO_SCENE @ loaded.graph[n][0])
                            for n in loaded.graph.nodes_geometry if n.startswith(obj.id + "/")
                            for g in [loaded.graph[n][1]]])
        lo, hi = world_box(obj)
        np.testing.assert_allclose([points.min(axis=0), points.max(axis=0)], [lo, hi], atol=1e-5)


@pytest.mark.node
def test_a_spliced_scene_is_valid_gltf(tmp_path):
    scene, folder = _folder(tmp_path)
    report = assert_valid(assemble(scene, folder))
    assert report["issues"]["messages"] == []


def _room() -> Room:
    return Room.rectangle(6.0, 5.0, openings=[Opening(kind="door", wall=0, offset=1.0, width=0.9, height=2.1)])


def test_the_room_is_taken_over_from_the_recorded_glb_and_gives_the_same_bytes(tmp_path, monkeypatch):
    scene, folder = _folder(tmp_path, _room())
    built = []
    real = export_glb.room_glb
    monkeypatch.setattr(export_glb, "room_glb", lambda s: built.append(1) or real(s))
    assemble_recorded(scene, folder)
    assert len(built) == 1
    scene.objects[0].position = Vec3(x=0.5, y=0.5, z=0.25)  # a move: the room is as it was
    taken_over = assemble(scene, folder).read_bytes()
    assert len(built) == 1, "the room was made again for a move"
    scene.glb_sha256 = None  # nothing recorded: made afresh
    assert assemble(scene, folder).read_bytes() == taken_over
    assert len(built) == 2


def test_a_changed_room_or_an_unrecorded_glb_makes_the_room_again(tmp_path, monkeypatch):
    scene, folder = _folder(tmp_path, _room())
    built = []
    real = export_glb.room_glb
    monkeypatch.setattr(export_glb, "room_glb", lambda s: built.append(1) or real(s))
    assemble_recorded(scene, folder)
    folder.glb.write_bytes(folder.glb.read_bytes() + b"    ")  # not the file the document records
    assemble_recorded(scene, folder)
    assert len(built) == 2
    scene.room = Room.rectangle(7.0, 5.0)
    path = assemble(scene, folder)
    assert len(built) == 3
    floor = [n for n in trimesh.load_scene(path).graph.nodes if n == "room/floor"]
    assert floor


def test_an_asset_referring_outside_itself_is_refused(tmp_path):
    scene, folder = _folder(tmp_path)
    glb = Glb.parse(folder.asset("crate_1").read_bytes())
    glb.tree["images"][0] = {"uri": "/etc/passwd"}
    with pytest.raises(ValueError, match="outside file"):
        GlbWriter("test").splice(glb, glb.roots())


def test_a_move_edit_encodes_no_image_and_builds_no_mesh(tmp_path, monkeypatch):
    out = tmp_path / "room"
    assert main(["generate", "a small bedroom with a bed, a nightstand and a lamp", "--out", str(out),
                 "--no-render"]) == 0
    folder = SceneFolder(out)
    scene = folder.load()
    assert scene.room is not None
    calls = {"encode": 0, "export": 0}
    save, export = Image.Image.save, trimesh.exchange.gltf.export_glb

    def counted_save(self, *args, **kwargs):
        calls["encode"] += 1
        return save(self, *args, **kwargs)

    def counted_export(*args, **kwargs):
        calls["export"] += 1
        return export(*args, **kwargs)

    monkeypatch.setattr(Image.Image, "save", counted_save)
    monkeypatch.setattr(trimesh.exchange.gltf, "export_glb", counted_export)
    lamp = next(o.id for o in scene.objects if o.category == "lamp" or "lamp" in o.id)
    before = folder.glb.read_bytes()
    assert main(["edit", str(out), f"move the {lamp} to the right of the bed"]) == 0
    assert calls == {"encode": 0, "export": 0}
    after = Glb.parse(folder.glb.read_bytes())
    assert folder.glb.read_bytes() != before
    assert _image_bytes(Glb.parse(before)) == _image_bytes(after), "textures are copied byte for byte"
    moved = folder.load()
    node = after.tree["nodes"][after.find(lamp)]
    expected = SCENE_TO_GLTF @ export_glb.object_matrix(next(o for o in moved.objects if o.id == lamp)) @ GLTF_TO_SCENE
    np.testing.assert_allclose(np.asarray(node["matrix"]).reshape(4, 4).T, expected, atol=1e-9)

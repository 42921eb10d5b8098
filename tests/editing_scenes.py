"""Hand-built scene folders and small local backends for the editing tests.

The scenes are complete folders (scene.json, one asset per object, scene.glb), built
without the text pipeline so the editing tests do not depend on what the text parser
makes of a description.
"""

from __future__ import annotations

import hashlib
import io
import shutil
from pathlib import Path

import pytest
import trimesh
from PIL import Image

from scenewright.assets import generate_assets
from scenewright.cache import RequestCache
from scenewright.core.protocols import Answer
from scenewright.editing.parser import plan_edit_offline
from scenewright.folder import SceneFolder
from scenewright.integrity import assemble_recorded
from scenewright.scene import Constraint, Scene, SceneObject, Vec3


class BoxMeshes:
    """A mesh backend answering a box of the requested size (glTF axes, bottom at y = 0)."""

    name = "boxes"
    params: dict = {}
    concurrency = 1

    def __init__(self) -> None:
        self.requests = []

    def cancel(self):
        """Boxes are made inside ``generate``; nothing runs to abandon."""

    def generate(self, requests, progress=None):
        out = {}
        for request in requests:
            self.requests.append(request)
            size = request.size
            box = trimesh.creation.box([size.x, size.z, size.y])
            box.apply_translation([0, size.z / 2, 0])
            out[request.id] = box.export(file_type="glb")
        return out


class NoImages:
    name = "none"

    def object_images(self, objects, style, reference, progress=None):
        return {}


class PictureImages(NoImages):
    """An image backend that draws one tiny PNG per object, coloured by its description
    (a real image: images are decoded before they go to a mesh server)."""

    name = "pictures"

    def object_images(self, objects, style, reference, progress=None):
        return {o.id: _swatch(hashlib.sha256(o.visual_description.encode()).digest()[:3]) for o in objects}


def _swatch(colour: bytes) -> bytes:
    out = io.BytesIO()
    Image.new("RGB", (4, 4), tuple(colour)).save(out, format="PNG")
    return out.getvalue()


class RulePlanner:
    name = "rules"

    def plan_edit(self, scene, instruction):
        return Answer(plan_edit_offline(scene, instruction))


def _obj(oid, category, name, size, x, y, z=None, yaw=0.0, description=""):
    size = Vec3.of(size)
    return SceneObject(
        id=oid, name=name, category=category, size=size,
        position=Vec3(x=x, y=y, z=size.z / 2 if z is None else z),
        rotation=Vec3(z=yaw), visual_description=description or name,
    )


def living_room() -> Scene:
    """A sofa corner and a dining table with four chairs; a vase stands on the coffee table."""
    objects = [
        _obj("sofa_1", "sofa", "sofa", (2.1, 0.9, 0.85), 0.0, 1.5),
        _obj("coffee_table_1", "coffee_table", "coffee table", (1.1, 0.6, 0.45), 0.0, 0.2),
        _obj("vase_1", "vase", "vase", (0.2, 0.2, 0.35), 0.0, 0.2, z=0.45 + 0.175),
        _obj("floor_lamp_1", "floor_lamp", "floor lamp", (0.45, 0.45, 1.7), 1.6, 1.5),
        _obj("bookshelf_1", "bookshelf", "bookshelf", (1.0, 0.35, 1.9), -1.8, 1.7),
        _obj("armchair_1", "armchair", "armchair", (0.85, 0.85, 0.95), -1.4, -1.0),
        _obj("table_1", "table", "dining table", (1.6, 0.9, 0.75), 5.0, 0.0),
        _obj("chair_1", "chair", "chair", (0.45, 0.5, 0.9), 3.8, 0.0, yaw=-90.0),
        _obj("chair_2", "chair", "chair", (0.45, 0.5, 0.9), 6.2, 0.0, yaw=90.0),
        _obj("chair_3", "chair", "chair", (0.45, 0.5, 0.9), 5.0, -0.9),
        _obj("chair_4", "chair", "chair", (0.45, 0.5, 0.9), 5.0, 0.9, yaw=180.0),
    ]
    constraints = [
        Constraint(relation="in front of", source="coffee_table_1", target="sofa_1"),
        Constraint(relation="on", source="vase_1", target="coffee_table_1"),
        Constraint(relation="right of", source="floor_lamp_1", target="sofa_1"),
        Constraint(relation="left of", source="bookshelf_1", target="sofa_1"),
        Constraint(relation="near", source="armchair_1", target="coffee_table_1"),
        Constraint(relation="left of", source="chair_1", target="table_1"),
        Constraint(relation="right of", source="chair_2", target="table_1"),
        Constraint(relation="in front of", source="chair_3", target="table_1"),
        Constraint(relation="behind", source="chair_4", target="table_1"),
    ]
    return Scene(text="a living room with a sofa corner and a dining table", objects=objects,
                 constraints=constraints, done=["analyze", "assets", "layout", "export"])


def build_folder(root: Path, scene: Scene | None = None) -> SceneFolder:
    """Write ``scene`` (default: :func:`living_room`) as a complete scene folder."""
    folder = SceneFolder(root)
    folder.create()
    scene = scene or living_room()
    generate_assets(scene, folder, BoxMeshes(), RequestCache(None))
    assemble_recorded(scene, folder)
    folder.save(scene)
    return folder


def snapshot(root: Path) -> dict[str, str]:
    """Every file under ``root`` by relative path → sha256, to prove nothing changed."""
    return {
        p.relative_to(root).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(Path(root).rglob("*")) if p.is_file()
    }


@pytest.fixture(scope="module")
def template(tmp_path_factory):
    """One built scene folder per test module; each test edits its own copy."""
    return build_folder(tmp_path_factory.mktemp("template") / "scene").root


@pytest.fixture
def folder(template, tmp_path):
    return SceneFolder(shutil.copytree(template, tmp_path / "scene"))

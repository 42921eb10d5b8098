"""Assemble ``scene.glb``: every object as its own named node, the ground or the room as another.

Each object's node is named by its id and carries the pose, so Blender, Godot and Unreal
show one selectable, movable object per id; the asset's nodes hang under it unchanged.
Assets are stored in glTF convention, so the pose (solved in the scene frame) is conjugated
into glTF frame: ``SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE``.

The file is put together at the glTF level (:mod:`scenewright.export.splice`): each asset's
meshes, exact materials and encoded textures are copied from its GLB, not decoded and encoded
again, so a move costs new node matrices and a copy of bytes. A room's meshes and its floor
texture take a mesh library and image encoding to make; they are made once and, while the
room and style stay as they were, taken over from the ``scene.glb`` the document records
(its ``room`` node carries the key of what it was made from).
"""

from __future__ import annotations

import hashlib
import io
import json
import logging
from pathlib import Path

import numpy as np

from scenewright.assets.load import AssetMeshes
from scenewright.errors import InputError
from scenewright.export.ground import PLAIN_COLOUR, WATER_COLOUR, ground_plane, water_plane
from scenewright.export.splice import Glb, GlbWriter
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.scene import Scene, SceneObject
from scenewright.version import __version__

log = logging.getLogger(__name__)

GROUND_NODE = "ground"
WATER_NODE = "water"
ROOM_NODE = "room"
#: Bumped when the room's meshes or materials are made differently, so a ``scene.glb`` written
#: before does not hand its room on.
ROOM_FORMAT = 1


def node_matrix(obj: SceneObject) -> np.ndarray:
    """The object's pose as a glTF node transform for its glTF-frame asset."""
    return SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE


def _asset_paths(scene: Scene, folder: SceneFolder) -> dict[str, Path]:
    paths, missing = {}, []
    for obj in scene.objects:
        path = folder.asset_of(obj)
        if path is None or not path.is_file():
            missing.append(obj.id)
        else:
            paths[obj.id] = path
    if missing:
        raise InputError(
            f"cannot assemble {folder.glb}: no asset file for {', '.join(missing)}; "
            f"resume the scene with `scenewright generate --resume {folder.root}` to build them"
        )
    return paths


def _add_object(out: GlbWriter, obj: SceneObject, path: Path, store: AssetMeshes) -> None:
    """Copy the asset's node trees under a new node for the object, named ``<id>/<node>``."""
    try:
        asset = Glb.parse(store.data(path))
        node = out.node(obj.id, matrix=node_matrix(obj), extras={"name": obj.name, "category": obj.category})
        out.splice(asset, asset.roots(), parent=node, prefix=obj.id)
    except ValueError as exc:
        raise InputError(f"cannot assemble object {obj.id!r}: its asset {path} is broken ({exc})") from None


def room_key(scene: Scene) -> str:
    """What the room's part of ``scene.glb`` is made from: the room, the style, the code."""
    made_from = {"room": scene.room.model_dump(mode="json") if scene.room else None, "style": scene.style,
                 "version": __version__, "format": ROOM_FORMAT}
    return hashlib.sha256(json.dumps(made_from, sort_keys=True).encode()).hexdigest()[:32]


def _recorded_room(scene: Scene, folder: SceneFolder, key: str) -> Glb | None:
    """The ``scene.glb`` on disk when it is the one the document records and its room was made
    from ``key``; ``None`` otherwise (first assembly, a changed room, a file that does not match)."""
    if scene.glb_sha256 is None:
        return None
    try:
        data = folder.glb.read_bytes()
    except OSError:
        return None
    if hashlib.sha256(data).hexdigest() != scene.glb_sha256:
        return None
    try:
        glb = Glb.parse(data)
    except ValueError:
        return None
    index = glb.find(ROOM_NODE)
    if index is None or glb.tree["nodes"][index].get("extras", {}).get("room") != key:
        return None
    return glb


def room_glb(scene: Scene) -> bytes:
    """The room's meshes as a GLB of their own: a ``room`` node, each mesh a node under it named
    as :func:`~scenewright.procedural.room.room_meshes` names it; a door's or window's parts hang
    under a node for the opening (``room/door_0``), so it selects as one thing. Written from
    the meshes' arrays, each with its exact material; the floor's texture as PNG."""
    from scenewright.procedural.room import room_geometry

    out = GlbWriter(f"scenewright {__version__}")
    groups = {ROOM_NODE: out.node(ROOM_NODE)}
    for name, mesh in room_geometry(scene.room, scene.style):
        parent = name.rsplit("/", 1)[0] if name.count("/") == 2 else ROOM_NODE
        if parent not in groups:
            groups[parent] = out.node(parent, groups[ROOM_NODE])
        material = dict(mesh.material)
        uv = None
        if mesh.image is not None:
            buffer = io.BytesIO()
            mesh.image.save(buffer, "PNG", compress_level=1)  # a fifth of the time of the default level
            texture = out.add("textures", {"source": out.image(buffer.getvalue(), "image/png")})
            material["pbrMetallicRoughness"] = {**material.get("pbrMetallicRoughness", {}),
                                                "baseColorTexture": {"index": texture}}
            uv = np.column_stack([mesh.uv[:, 0], 1.0 - mesh.uv[:, 1]])  # glTF's V runs down the image
        vertices = mesh.vertices @ SCENE_TO_GLTF[:3, :3].T
        out.mesh(name, vertices, mesh.faces, out.material(material), uv=uv, parent=groups[parent])
    return out.to_bytes()


def _add_room(out: GlbWriter, scene: Scene, folder: SceneFolder) -> None:
    key = room_key(scene)
    source = _recorded_room(scene, folder, key)
    if source is None:
        source = Glb.parse(room_glb(scene))
    else:
        log.info("room taken over from %s", folder.glb)
    [index] = out.splice(source, [source.find(ROOM_NODE)])
    out.tree["nodes"][index]["extras"] = {"room": key}


def _image(path: Path) -> tuple[bytes, str]:
    """The texture file's bytes as glTF takes them (PNG or JPEG as they are; WebP, which core
    glTF does not take, as PNG)."""
    data = path.read_bytes()
    if data.startswith(b"\x89PNG\r\n\x1a\n"):
        return data, "image/png"
    if data.startswith(b"\xff\xd8\xff"):
        return data, "image/jpeg"
    from PIL import Image

    buffer = io.BytesIO()
    with Image.open(io.BytesIO(data)) as image:
        image.save(buffer, "PNG")
    return buffer.getvalue(), "image/png"


def _add_ground(out: GlbWriter, scene: Scene, folder: SceneFolder) -> None:
    """The ground plane of :func:`~scenewright.export.ground.ground_plane`, its texture file
    embedded as it is (or a plain colour when the file is missing)."""
    vertices, faces, uv = ground_plane(scene.objects, scene.bounds)
    texture = folder.ground_texture(scene)
    pbr: dict = {}
    if texture is not None and texture.is_file():
        data, mime = _image(texture)
        image = out.image(data, mime)
        pbr["baseColorTexture"] = {"index": out.add("textures", {"source": image})}
    else:
        if texture is not None:
            log.warning("ground texture %s is missing; the ground gets a plain colour", texture)
        pbr["baseColorFactor"] = list(PLAIN_COLOUR)
    pbr.update(metallicFactor=0.0, roughnessFactor=0.9)
    material = out.add("materials", {"name": GROUND_NODE, "pbrMetallicRoughness": pbr, "doubleSided": False})
    flipped = np.column_stack([uv[:, 0], 1.0 - uv[:, 1]])  # glTF's V runs down the image
    out.mesh(GROUND_NODE, vertices, faces, material, normals=np.tile([0.0, 1.0, 0.0], (len(vertices), 1)), uv=flipped)


def _add_water(out: GlbWriter, scene: Scene) -> None:
    """The water beyond the shore (:func:`~scenewright.export.ground.water_plane`): one plane,
    blue, smooth and alpha-blended, so the ground's edge shows faintly through it."""
    assert scene.ground.water is not None
    vertices = water_plane(scene.objects, scene.bounds, scene.ground.water)
    pbr = {"baseColorFactor": list(WATER_COLOUR), "metallicFactor": 0.0, "roughnessFactor": 0.05}
    material = out.add("materials", {"name": WATER_NODE, "pbrMetallicRoughness": pbr, "alphaMode": "BLEND",
                                     "doubleSided": False})
    out.mesh(WATER_NODE, vertices, np.array([[0, 1, 2], [0, 2, 3]]), material,
             normals=np.tile([0.0, 1.0, 0.0], (len(vertices), 1)))


def scene_glb(scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None) -> GlbWriter:
    """The glTF of ``scene.glb`` (a node per object, named by id, and the ground with the water
    beyond its shore, or the room when the scene has one: its floor is the ground then), ready for more nodes or its bytes.
    ``meshes`` holds the asset files the caller has read already."""
    paths = _asset_paths(scene, folder)
    store = meshes if meshes is not None else AssetMeshes()
    out = GlbWriter(f"scenewright {__version__}")
    for obj in scene.objects:
        _add_object(out, obj, paths[obj.id], store)
    if scene.room is not None:
        _add_room(out, scene, folder)
    else:
        _add_ground(out, scene, folder)
        if scene.ground.water is not None:
            _add_water(out, scene)
    return out


def assemble(scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None) -> Path:
    """Write ``scene.glb`` (metres, +Y up) from the objects' assets and poses; return its path."""
    data = scene_glb(scene, folder, meshes).to_bytes()
    log.info("assembled %d objects into %s", len(scene.objects), folder.glb)
    return write_atomic(folder.glb, data)

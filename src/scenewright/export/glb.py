"""Assemble ``scene.glb``: every object as its own named node, the ground as another.

Each object's node is named by its id and carries the pose, so Blender, Godot and Unreal
show one selectable, movable object per id; the asset's meshes hang under it unchanged.
Assets are stored in glTF convention, so the pose (solved in the scene frame) is conjugated
into glTF frame: ``SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE``.
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np
import trimesh

from scenewright.assets.load import AssetMeshes
from scenewright.version import __version__
from scenewright.errors import InputError
from scenewright.export.ground import ground_mesh
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.gltf import keep_materials
from scenewright.scene import Scene, SceneObject

log = logging.getLogger(__name__)

GROUND_NODE = "ground"
ROOM_NODE = "room"
#: glTF bufferView targets: vertex attributes and triangle indices.
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


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


def _add_object(
    target: trimesh.Scene, obj: SceneObject, path: Path, materials: dict[str, dict], store: AssetMeshes
) -> None:
    """Hang the asset's meshes under the object's node; ``materials`` learns each new mesh's
    material as the asset file wrote it (trimesh's copy is rounded and loses extensions)."""
    try:
        parsed = store.parsed(path)
        asset, source = parsed.asset, parsed.materials()
    except ValueError as exc:
        raise InputError(f"cannot assemble object {obj.id!r}: its asset {path} is broken ({exc})") from None
    target.graph.update(frame_to=obj.id, frame_from=target.graph.base_frame, matrix=node_matrix(obj))
    for node in asset.graph.nodes_geometry:
        transform, geometry_name = asset.graph[node]
        name = f"{obj.id}/{node}"
        if geometry_name in source:
            materials[name] = source[geometry_name]
        target.add_geometry(
            asset.geometry[geometry_name],
            geom_name=name,
            node_name=name,
            parent_node_name=obj.id,
            transform=transform,
        )


def _add_room(target: trimesh.Scene, scene: Scene, materials: dict[str, dict]) -> None:
    """The room's meshes under a ``room`` node, each a node of its own named as
    :func:`~scenewright.procedural.room.room_meshes` names it; a door's or window's parts
    hang under a node for the opening (``room/door_0``), so it selects as one thing."""
    from scenewright.procedural.room import GLTF_MATERIAL, room_meshes  # only scenes with a room pay its import

    target.graph.update(frame_to=ROOM_NODE, frame_from=target.graph.base_frame, matrix=np.eye(4))
    for name, mesh in room_meshes(scene.room, scene.style):
        parent = ROOM_NODE
        if name.count("/") == 2:
            parent = name.rsplit("/", 1)[0]
            if parent not in target.graph.nodes:
                target.graph.update(frame_to=parent, frame_from=ROOM_NODE, matrix=np.eye(4))
        gltf = mesh.copy()
        gltf.apply_transform(SCENE_TO_GLTF)
        if GLTF_MATERIAL in mesh.metadata:
            materials[name] = mesh.metadata[GLTF_MATERIAL]
        target.add_geometry(gltf, geom_name=name, node_name=name, parent_node_name=parent)


def _mark_buffer_targets(tree: dict) -> None:
    """Say which buffer views hold vertices and which indices, as engines prefer to be told."""
    for mesh in tree.get("meshes", []):
        for primitive in mesh["primitives"]:
            for accessor in primitive["attributes"].values():
                tree["bufferViews"][tree["accessors"][accessor]["bufferView"]]["target"] = ARRAY_BUFFER
            if "indices" in primitive:
                view = tree["accessors"][primitive["indices"]]["bufferView"]
                tree["bufferViews"][view]["target"] = ELEMENT_ARRAY_BUFFER


def _describe_nodes(scene: Scene, materials: dict[str, dict]):
    """A glTF tree hook that names the generator, tags each object node with its record and
    gives each mesh its asset's exact material."""
    extras = {obj.id: {"name": obj.name, "category": obj.category} for obj in scene.objects}
    keep = keep_materials(materials)

    def postprocess(tree: dict) -> None:
        keep(tree)
        tree["asset"]["generator"] = f"scenewright {__version__}"
        for node in tree.get("nodes", []):
            if node.get("name") in extras:
                node["extras"] = extras[node["name"]]
        _mark_buffer_targets(tree)

    return postprocess


def build_scene(
    scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None
) -> tuple[trimesh.Scene, dict[str, dict]]:
    """The scene graph of ``scene.glb`` (a node per object, named by id, and the ground, or the
    room when the scene has one: its floor is the ground then) and the assets' exact glTF
    materials by mesh name, which trimesh's own export would round. ``meshes`` holds the
    assets the caller has parsed already."""
    paths = _asset_paths(scene, folder)
    store = meshes if meshes is not None else AssetMeshes()
    glb = trimesh.Scene()
    materials: dict[str, dict] = {}
    for obj in scene.objects:
        _add_object(glb, obj, paths[obj.id], materials, store)
    if scene.room is not None:
        _add_room(glb, scene, materials)
        return glb, materials
    texture = folder.ground_texture(scene)
    glb.add_geometry(
        ground_mesh(scene.objects, scene.bounds, texture), geom_name=GROUND_NODE, node_name=GROUND_NODE
    )
    return glb, materials


def glb_bytes(glb: trimesh.Scene, scene: Scene, materials: dict[str, dict]) -> bytes:
    """The binary glTF of a graph from :func:`build_scene`, its object nodes tagged."""
    return trimesh.exchange.gltf.export_glb(glb, tree_postprocessor=_describe_nodes(scene, materials))


def assemble(scene: Scene, folder: SceneFolder, meshes: AssetMeshes | None = None) -> Path:
    """Write ``scene.glb`` (metres, +Y up) from the objects' assets and poses; return its path."""
    glb, materials = build_scene(scene, folder, meshes)
    data = glb_bytes(glb, scene, materials)
    log.info("assembled %d objects into %s", len(scene.objects), folder.glb)
    return write_atomic(folder.glb, data)

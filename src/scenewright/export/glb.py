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

from scenewright import __version__
from scenewright.assets.normalise import parse_glb
from scenewright.errors import InputError
from scenewright.export.ground import ground_mesh
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE, SCENE_TO_GLTF, object_matrix
from scenewright.scene import Scene, SceneObject

log = logging.getLogger(__name__)

GROUND_NODE = "ground"
#: glTF bufferView targets: vertex attributes and triangle indices.
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963


def node_matrix(obj: SceneObject) -> np.ndarray:
    """The object's pose as a glTF node transform for its glTF-frame asset."""
    return SCENE_TO_GLTF @ object_matrix(obj) @ GLTF_TO_SCENE


def _asset_paths(scene: Scene, folder: SceneFolder) -> dict[str, Path]:
    paths, missing = {}, []
    for obj in scene.objects:
        path = folder.resolve(obj.asset) if obj.asset else None
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


def _add_object(target: trimesh.Scene, obj: SceneObject, path: Path) -> None:
    try:
        asset = parse_glb(path.read_bytes())
    except ValueError as exc:
        raise InputError(f"cannot assemble object {obj.id!r}: its asset {path} is broken ({exc})") from None
    target.graph.update(frame_to=obj.id, frame_from=target.graph.base_frame, matrix=node_matrix(obj))
    for node in asset.graph.nodes_geometry:
        transform, geometry_name = asset.graph[node]
        name = f"{obj.id}/{node}"
        target.add_geometry(
            asset.geometry[geometry_name],
            geom_name=name,
            node_name=name,
            parent_node_name=obj.id,
            transform=transform,
        )


def _mark_buffer_targets(tree: dict) -> None:
    """Say which buffer views hold vertices and which indices, as engines prefer to be told."""
    for mesh in tree.get("meshes", []):
        for primitive in mesh["primitives"]:
            for accessor in primitive["attributes"].values():
                tree["bufferViews"][tree["accessors"][accessor]["bufferView"]]["target"] = ARRAY_BUFFER
            if "indices" in primitive:
                view = tree["accessors"][primitive["indices"]]["bufferView"]
                tree["bufferViews"][view]["target"] = ELEMENT_ARRAY_BUFFER


def _describe_nodes(scene: Scene):
    """A glTF tree hook that names the generator and tags each object node with its record."""
    extras = {obj.id: {"name": obj.name, "category": obj.category} for obj in scene.objects}

    def postprocess(tree: dict) -> None:
        tree["asset"]["generator"] = f"scenewright {__version__}"
        for node in tree.get("nodes", []):
            if node.get("name") in extras:
                node["extras"] = extras[node["name"]]
        _mark_buffer_targets(tree)

    return postprocess


def build_scene(scene: Scene, folder: SceneFolder) -> trimesh.Scene:
    """The scene graph of ``scene.glb``: a node per object (named by id) and the ground."""
    paths = _asset_paths(scene, folder)
    glb = trimesh.Scene()
    for obj in scene.objects:
        _add_object(glb, obj, paths[obj.id])
    texture = folder.resolve(scene.ground.texture) if scene.ground.texture else None
    glb.add_geometry(
        ground_mesh(scene.objects, scene.bounds, texture), geom_name=GROUND_NODE, node_name=GROUND_NODE
    )
    return glb


def glb_bytes(glb: trimesh.Scene, scene: Scene) -> bytes:
    """The binary glTF of a graph from :func:`build_scene`, its object nodes tagged."""
    return trimesh.exchange.gltf.export_glb(glb, tree_postprocessor=_describe_nodes(scene))


def assemble(scene: Scene, folder: SceneFolder) -> Path:
    """Write ``scene.glb`` (metres, +Y up) from the objects' assets and poses; return its path."""
    data = glb_bytes(build_scene(scene, folder), scene)
    log.info("assembled %d objects into %s", len(scene.objects), folder.glb)
    return write_atomic(folder.glb, data)

"""An asset's look as the simulator exports need it: one mesh per material, in the scene frame.

USD and MJCF take meshes with a plain material (colour, metalness, roughness, glow); a
texture, where an asset has one, is reduced to its mean colour here (the GLB keeps it).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from scenewright.assets.normalise import parse_glb
from scenewright.geometry import GLTF_TO_SCENE

#: A material without a colour of its own shows this grey.
PLAIN = (0.7, 0.7, 0.7, 1.0)


@dataclass(frozen=True)
class Look:
    colour: tuple[float, float, float, float]
    metallic: float
    roughness: float
    emissive: tuple[float, float, float]


@dataclass
class Part:
    name: str
    mesh: trimesh.Trimesh
    look: Look


def _factor(value, default) -> np.ndarray:
    if value is None:
        return np.array(default, dtype=float)
    array = np.asarray(value, dtype=float)
    # trimesh reads colour factors as 0-255 integers.
    return array / 255.0 if array.max(initial=0.0) > 1.0 else array


def _look(mesh: trimesh.Trimesh) -> Look:
    material = getattr(mesh.visual, "material", None)
    if material is None:
        colours = getattr(mesh.visual, "vertex_colors", None)
        colour = tuple(np.asarray(colours, dtype=float).mean(axis=0) / 255.0) if colours is not None and len(colours) else PLAIN
        return Look(tuple(float(c) for c in colour), 0.0, 0.6, (0.0, 0.0, 0.0))
    if not hasattr(material, "baseColorFactor"):
        material = material.to_pbr()
    colour = _factor(material.baseColorFactor, PLAIN)
    texture = getattr(material, "baseColorTexture", None)
    if texture is not None:
        pixels = np.asarray(texture.convert("RGBA"), dtype=float).reshape(-1, 4) / 255.0
        colour = colour * pixels.mean(axis=0)
    emissive = _factor(getattr(material, "emissiveFactor", None), (0.0, 0.0, 0.0))
    metallic = getattr(material, "metallicFactor", None)
    roughness = getattr(material, "roughnessFactor", None)
    return Look(
        colour=tuple(float(c) for c in colour[:4]) if len(colour) >= 4 else (*map(float, colour[:3]), 1.0),
        metallic=float(0.0 if metallic is None else metallic),
        roughness=float(0.5 if roughness is None else roughness),
        emissive=tuple(float(c) for c in emissive[:3]),
    )


def size_box(size) -> trimesh.Trimesh:
    """The object's size box in the asset frame (bottom centre at the origin): what stands in
    for an object that has no asset, as in the solver and the evaluation."""
    box = trimesh.creation.box(extents=size.tuple())
    box.apply_translation((0.0, 0.0, size.z / 2.0))
    return box


def object_parts(obj, folder) -> list[Part]:
    """The object's visual parts: its asset's, else its size box in plain grey."""
    if obj.asset is None:
        return [Part(name="box", mesh=size_box(obj.size), look=Look(PLAIN, 0.0, 0.6, (0.0, 0.0, 0.0)))]
    return visual_parts(folder.resolve(obj.asset).read_bytes())


def room_parts(room, style: str) -> list[Part]:
    """The room's meshes (:func:`scenewright.procedural.room.room_meshes`) with their looks,
    in the scene frame; parts are named as the meshes are."""
    from scenewright.procedural.room import room_meshes

    return [Part(name=name, mesh=mesh, look=_look(mesh)) for name, mesh in room_meshes(room, style)]


def visual_parts(glb: bytes) -> list[Part]:
    """Each mesh of a normalised asset in the scene-frame asset frame, with its look."""
    scene = parse_glb(glb)
    parts = []
    for node in scene.graph.nodes_geometry:
        transform, name = scene.graph[node]
        source = scene.geometry[name]
        mesh = trimesh.Trimesh(source.vertices, source.faces, process=False)
        mesh.apply_transform(GLTF_TO_SCENE @ transform)
        parts.append(Part(name=str(node), mesh=mesh, look=_look(source)))
    return parts

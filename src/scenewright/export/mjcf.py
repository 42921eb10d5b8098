"""MJCF for MuJoCo: one body per object, a floor plane, collision by convex pieces.

Each object is a body named by its id at its pose (the asset frame's origin is the object's
bottom centre). A dynamic object has a free joint and its mass, centre of mass and inertia from
:mod:`scenewright.export.physics`; a static one is welded to the world. Visual geoms (group 2)
are the asset's meshes with their colours and never collide; collision geoms (group 3) are the
convex pieces, which MuJoCo collides as they are. A room's meshes are visual geoms of the
world, and its walls collide as static boxes (one per solid piece, so openings stay open).
Meshes go to ``meshes/`` as binary STL.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from scenewright.export.colliders import Collider
from scenewright.export.physics import inertia_matrix
from scenewright.export.visual import object_parts, room_parts
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.geometry import object_matrix
from scenewright.scene import Scene

#: Simulation step (s): MuJoCo's default, stable for resting contact of these masses.
TIMESTEP = 0.002
FLOOR_FRICTION = 0.8
MESH_DIR = "meshes"


@dataclass
class Mjcf:
    """The model's XML and the mesh files it names (relative to its folder)."""

    xml: str
    files: dict[str, bytes]

    def write(self, path: Path) -> Path:
        """``path`` (the XML) with its meshes beside it in ``meshes/``."""
        for name, data in self.files.items():
            write_atomic(path.parent / name, data)
        return write_atomic(path, self.xml)


def _numbers(values) -> str:
    return " ".join(f"{float(v):.6g}" for v in values)


def _pose(matrix: np.ndarray) -> tuple[str, str]:
    x, y, z, w = Rotation.from_matrix(matrix[:3, :3]).as_quat()
    return _numbers(matrix[:3, 3]), _numbers((w, x, y, z))


def _room(scene: Scene, world: ET.Element, assets: ET.Element, files: dict[str, bytes]) -> None:
    from scenewright.procedural.room import wall_boxes

    for part in room_parts(scene.room, scene.style):
        name = part.name
        files[f"{MESH_DIR}/{name.replace('/', '_')}.stl"] = part.mesh.export(file_type="stl")
        ET.SubElement(assets, "mesh", name=name, file=f"{name.replace('/', '_')}.stl", inertia="shell")
        ET.SubElement(world, "geom", {"class": "visual", "name": name, "mesh": name, "rgba": _numbers(part.look.colour)})
    for name, pose, extents in wall_boxes(scene.room):
        pos, quat = _pose(pose)
        ET.SubElement(world, "geom", {"class": "collision", "name": name, "type": "box", "size": _numbers(extents / 2.0),
                                      "pos": pos, "quat": quat, "friction": f"{FLOOR_FRICTION} 0.005 0.0001"})


def build_mjcf(scene: Scene, folder: SceneFolder, pieces: dict[str, Collider]) -> Mjcf:
    """The MJCF of ``scene``: every object needs its physics record (``ensure_physics``)."""
    root = ET.Element("mujoco", model="scenewright")
    ET.SubElement(root, "compiler", angle="radian", meshdir=MESH_DIR, autolimits="true", inertiafromgeom="false")
    ET.SubElement(root, "option", timestep=str(TIMESTEP), integrator="implicitfast")
    default = ET.SubElement(root, "default")
    visual = ET.SubElement(default, "default", {"class": "visual"})
    ET.SubElement(visual, "geom", type="mesh", contype="0", conaffinity="0", group="2")
    collision = ET.SubElement(default, "default", {"class": "collision"})
    ET.SubElement(collision, "geom", type="mesh", group="3", condim="3", rgba="0.4 0.6 0.9 0.4")
    assets = ET.SubElement(root, "asset")
    ET.SubElement(assets, "texture", name="grid", type="2d", builtin="checker", width="256", height="256",
                  rgb1="0.55 0.55 0.52", rgb2="0.45 0.45 0.42")
    ET.SubElement(assets, "material", name="floor", texture="grid", texrepeat="1 1", texuniform="true")
    world = ET.SubElement(root, "worldbody")
    ET.SubElement(world, "light", name="sun", directional="true", pos="0 0 20", dir="-0.3 0.2 -1")
    ET.SubElement(world, "geom", name="floor", type="plane", size="0 0 0.05", material="floor",
                  friction=f"{FLOOR_FRICTION} 0.005 0.0001")
    files: dict[str, bytes] = {}
    if scene.room is not None:
        _room(scene, world, assets, files)
    for obj in scene.objects:
        physics = obj.physics
        assert physics is not None, f"{obj.id} has no physics record; call ensure_physics first"
        pos, quat = _pose(object_matrix(obj))
        body = ET.SubElement(world, "body", name=obj.id, pos=pos, quat=quat)
        if not physics.static:
            ET.SubElement(body, "freejoint", name=obj.id)
        inertia = inertia_matrix(physics)
        ET.SubElement(body, "inertial", pos=_numbers(physics.center_of_mass.tuple()), mass=f"{physics.mass:.6g}",
                      fullinertia=_numbers([inertia[0, 0], inertia[1, 1], inertia[2, 2],
                                            inertia[0, 1], inertia[0, 2], inertia[1, 2]]))
        for k, part in enumerate(object_parts(obj, folder)):
            name = f"{obj.id}:visual{k}"
            files[f"{MESH_DIR}/{name}.stl"] = part.mesh.export(file_type="stl")
            ET.SubElement(assets, "mesh", name=name, file=f"{name}.stl", inertia="shell")
            ET.SubElement(body, "geom", {"class": "visual", "name": name, "mesh": name, "rgba": _numbers(part.look.colour)})
        for k, hull in enumerate(pieces[obj.id].hulls):
            name = f"{obj.id}:collision{k}"
            files[f"{MESH_DIR}/{name}.stl"] = hull.export(file_type="stl")
            ET.SubElement(assets, "mesh", name=name, file=f"{name}.stl")
            ET.SubElement(body, "geom", {"class": "collision", "name": name, "mesh": name,
                                         "friction": f"{physics.friction:.3g} 0.005 0.0001"})
    ET.indent(root)
    return Mjcf(xml=ET.tostring(root, encoding="unicode") + "\n", files=files)

"""``scene.glb`` with collision nodes that game engines turn into colliders on import.

Godot reads node-name suffixes: a mesh node ending in ``-convcolonly`` becomes a convex
collision shape and is not drawn (``-colonly`` for a concave one). Unreal reads ``UCX_<mesh>_NN``
meshes as the convex collision of the static mesh ``<mesh>`` (import the object's meshes
combined, so that the static mesh carries the object's id). The two naming schemes would
draw each other's colliders, so one file follows one engine. Each object's convex pieces
hang under its node, so they move with it; the ground gets a thin box, and a room's walls
one box per solid piece (openings stay open) under each wall's node.
"""

from __future__ import annotations

from pathlib import Path

import trimesh

from scenewright.export.colliders import Collider
from scenewright.export.glb import scene_glb
from scenewright.export.ground import ground_extent
from scenewright.export.splice import Glb, GlbWriter
from scenewright.files import write_atomic
from scenewright.folder import SceneFolder
from scenewright.geometry import SCENE_TO_GLTF
from scenewright.scene import Scene

ENGINES = ("godot", "unreal")
GROUND_COLLIDER = "ground_collider"
GROUND_THICKNESS = 0.1


def collider_name(engine: str, owner: str, k: int) -> str:
    if engine == "godot":
        return f"{owner}-hull{k}-convcolonly"
    return f"UCX_{owner}_{k:02d}"


def _add(out: GlbWriter, pieces: list[tuple[str, trimesh.Trimesh]], parent: str | None) -> None:
    """The collision meshes (scene-frame asset frame) as nodes under the node ``parent``."""
    if not pieces:
        return
    glb = trimesh.Scene()
    for name, mesh in pieces:
        gltf = mesh.copy()
        gltf.apply_transform(SCENE_TO_GLTF)
        gltf.visual = trimesh.visual.ColorVisuals(gltf)
        glb.add_geometry(gltf, geom_name=name, node_name=name)
    part = Glb.parse(trimesh.exchange.gltf.export_glb(glb))
    out.splice(part, part.roots(), parent=None if parent is None else _node(out, parent))


def _node(out: GlbWriter, name: str) -> int:
    return next(i for i, node in enumerate(out.tree["nodes"]) if node.get("name") == name)


def write_glb_physics(
    scene: Scene, folder: SceneFolder, pieces: dict[str, Collider], path: Path, engine: str = "godot"
) -> Path:
    out = scene_glb(scene, folder)
    for obj in scene.objects:
        _add(out, [(collider_name(engine, obj.id, k), hull) for k, hull in enumerate(pieces[obj.id].hulls)], obj.id)
    if scene.room is not None:
        from scenewright.procedural.room import wall_boxes

        walls: dict[str, list[tuple[str, trimesh.Trimesh]]] = {}
        for name, pose, extents in wall_boxes(scene.room):
            wall, box = name.rsplit("/", 1)
            owner = wall.replace("/", "_")
            walls.setdefault(wall, []).append((collider_name(engine, owner, int(box.removeprefix("box_"))),
                                               trimesh.creation.box(extents=extents, transform=pose)))
        for wall, boxes in walls.items():
            _add(out, boxes, wall)
    lo, hi = ground_extent(scene.objects, scene.bounds, scene.room)
    ground = trimesh.creation.box(extents=(*(hi - lo), GROUND_THICKNESS))
    ground.apply_translation((*((lo + hi) / 2.0), -GROUND_THICKNESS / 2.0))
    _add(out, [(collider_name(engine, GROUND_COLLIDER, 0), ground)], None)
    return write_atomic(path, out.to_bytes())

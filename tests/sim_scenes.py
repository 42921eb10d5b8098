"""Small hand-built scenes for the physics, stability and simulation-export tests."""

from __future__ import annotations

import trimesh

from scenewright.assets.normalise import to_glb
from scenewright.folder import SceneFolder
from scenewright.geometry import SCENE_TO_GLTF
from scenewright.scene import Scene, SceneObject, Vec3


def glb(mesh: trimesh.Trimesh) -> bytes:
    """A stored asset: glTF axes, bottom at y = 0."""
    gltf = mesh.copy()
    gltf.apply_transform(SCENE_TO_GLTF)
    return to_glb(trimesh.Scene(gltf))


def box(extents, centre=(0, 0, 0)) -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=extents)
    box.apply_translation(centre)
    return box


def scene_of(tmp_path, objects: dict, constraints=(), positions: dict | None = None) -> tuple[Scene, SceneFolder]:
    """A saved scene of ``{id: (category, mesh in the asset frame or None)}``: each object as big as
    its mesh (a 0.5 m cube without one), at ``positions[id]`` (its box centre) or in a row."""
    folder = SceneFolder(tmp_path / "scene")
    folder.create()
    scene = Scene(text="test", constraints=list(constraints))
    for k, (oid, (category, mesh)) in enumerate(objects.items()):
        size = Vec3.of(mesh.extents) if mesh is not None else Vec3(x=0.5, y=0.5, z=0.5)
        position = (positions or {}).get(oid, (2.0 * k, 0.0, size.z / 2.0))
        obj = SceneObject(id=oid, name=category, category=category, size=size, position=Vec3.of(position))
        if mesh is not None:
            folder.assets.mkdir(parents=True, exist_ok=True)
            folder.asset(oid).write_bytes(glb(mesh))
            obj.asset = folder.relative(folder.asset(oid))
        scene.objects.append(obj)
    folder.save(scene)
    return scene, folder

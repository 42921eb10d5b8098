"""Stored assets as meshes in the scene-frame asset frame, for the solver and evaluation."""

from __future__ import annotations

import trimesh

from scenewright.assets.normalise import parse_glb
from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE
from scenewright.scene import Scene


def asset_mesh(glb: bytes) -> trimesh.Trimesh:
    """One mesh, bottom at z = 0, front −Y, from a normalised GLB (``ValueError`` when unreadable)."""
    mesh = parse_glb(glb).to_mesh()
    mesh.apply_transform(GLTF_TO_SCENE)
    return mesh


def load_meshes(scene: Scene, folder: SceneFolder) -> dict[str, trimesh.Trimesh]:
    """Each object's asset by id; objects without an asset are left out (boxes stand in)."""
    meshes: dict[str, trimesh.Trimesh] = {}
    for obj in scene.objects:
        if obj.asset is None:
            continue
        path = folder.resolve(obj.asset)
        try:
            meshes[obj.id] = asset_mesh(path.read_bytes())
        except FileNotFoundError:
            raise InputError(
                f"object {obj.id!r}: its asset {obj.asset} is missing from {folder.root}; "
                f"re-run `scenewright generate --resume {folder.root}` to rebuild it"
            ) from None
        except ValueError as exc:
            raise InputError(f"object {obj.id!r}: its asset {path} is not a usable GLB: {exc}") from None
    return meshes

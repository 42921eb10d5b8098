"""Stored assets as meshes in the scene-frame asset frame, for the solver and evaluation."""

from __future__ import annotations

import trimesh

from scenewright.assets.normalise import parse_glb
from scenewright.errors import InputError
from scenewright.folder import SceneFolder
from scenewright.geometry import GLTF_TO_SCENE
from scenewright.scene import Scene, SceneObject


def asset_mesh(glb: bytes) -> trimesh.Trimesh:
    """One mesh, bottom at z = 0, front −Y, from a normalised GLB (``ValueError`` when unreadable)."""
    mesh = parse_glb(glb).to_mesh()
    mesh.apply_transform(GLTF_TO_SCENE)
    return mesh


def load_meshes(scene: Scene, folder: SceneFolder) -> dict[str, trimesh.Trimesh]:
    """Each object's asset by id; objects without an asset are left out (boxes stand in)."""
    meshes: dict[str, trimesh.Trimesh] = {}
    for obj in scene.objects:
        path = folder.asset_of(obj)
        if path is None:
            continue
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


#: Verdicts of :func:`asset_problem` by (path, mtime, size): a resume checks every asset, and an
#: asset file is never rewritten in place, so a verdict stays true while its key does.
_VERDICTS: dict[tuple[str, int, int], str | None] = {}


def asset_problem(obj: SceneObject, folder: SceneFolder) -> str | None:
    """Why ``obj``'s stored asset cannot be used (none, missing, empty, corrupt, no triangles),
    or ``None`` when it can; a path the document should not name is an InputError."""
    path = folder.asset_of(obj)
    if path is None:
        return "it has no asset"
    try:
        stat = path.stat()
    except FileNotFoundError:
        return f"its asset {obj.asset} is missing"
    key = (str(path.resolve()), stat.st_mtime_ns, stat.st_size)
    if key not in _VERDICTS:
        try:
            asset_mesh(path.read_bytes())
            _VERDICTS[key] = None
        except ValueError as exc:
            _VERDICTS[key] = f"its asset {obj.asset} is not a usable GLB ({exc})"
    return _VERDICTS[key]
